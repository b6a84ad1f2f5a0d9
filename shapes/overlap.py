"""Exact overlap of two convex polyhedra, and of a polyhedron with a wall.

The geometry of YADE's volumetric contact model (Polyhedra), computed
exactly (to round-off) by the compiled kernel ``polycontact.c``:

``volume``     V (m^3), the volume of the overlap polyhedron A n B; 0 when
               apart (or exactly touching).
``centroid``   (3,) m, its centroid: the contact point.
``normal``     (3,) unit, n = S_A / |S_A| from A to B, where S_A is the sum
               over the overlap's faces lying on A's surface of (face area x
               A's outward unit normal). S_A = -dV/dx_B: moving B along n
               reduces V fastest, so F = k_V V n derives from the overlap
               geometry alone (Feng's energy-conserving choice).
``footprint``  (2,) m, the principal extents of the overlap's shadow on the
               contact plane (normal to n), largest first. The shadow is the
               convex polygon onto which the overlap projects; its principal
               axes are those of its second moment of area, and an extent is
               the shadow's width (max - min) along that axis.
``area``       m^2, the area of that shadow.
``status``     0, or 1 when S_A vanishes (one grain inside the other,
               identical poses): the normal is then the line of centres
               (A to B), or +z when the centres coincide.

When apart: volume 0, area 0, footprint (0, 0), centroid and normal NaN.

Shapes are as the library stores them: vertices (V, 3) in the body's local
frame (origin at the centre of mass), triangles (T, 3) int, counter-clockwise
seen from outside; a pose is a position (3,) m and a unit quaternion
(w, x, y, z) turning the local frame into the global one. The shapes must be
convex: the overlap is computed by clipping A's faces by B's face planes.

This module imports only numpy and the kernel loader, so YADE's Python can
use it too.
"""
from __future__ import annotations

import numpy as np

from . import ckernel


class OverlapError(ValueError):
    """Shapes or poses the kernel cannot take; the message names the problem."""


class ShapeTable:
    """Many shapes packed for the kernel.

    shapes : list of (vertices (V, 3), triangles (T, 3)) pairs in each
    shape's local frame. Stored as concatenated float64 vertices and int32
    triangles with offsets (S+1,) into them.
    """

    def __init__(self, shapes):
        verts, tris = [], []
        for k, (v, t) in enumerate(shapes):
            v = np.asarray(v, float)
            t = np.asarray(t)
            if v.ndim != 2 or v.shape[1] != 3 or len(v) < 4:
                raise OverlapError(f"shape {k}: vertices must be (V >= 4, 3), got {v.shape}")
            if t.ndim != 2 or t.shape[1] != 3 or len(t) < 4:
                raise OverlapError(f"shape {k}: triangles must be (T >= 4, 3), got {t.shape}")
            if not np.all(np.isfinite(v)):
                raise OverlapError(f"shape {k}: vertices are not finite")
            if t.min() < 0 or t.max() >= len(v):
                raise OverlapError(f"shape {k}: triangle index out of range 0..{len(v) - 1}")
            verts.append(v)
            tris.append(t.astype(np.int32))
        if not verts:
            raise OverlapError("no shapes")
        self.n = len(verts)
        self.voff = ckernel.i32(np.concatenate([[0], np.cumsum([len(v) for v in verts])]))
        self.toff = ckernel.i32(np.concatenate([[0], np.cumsum([len(t) for t in tris])]))
        self.vertices = ckernel.f64(np.concatenate(verts))
        self.triangles = ckernel.i32(np.concatenate(tris))

    def subset(self, rows):
        """The table of the shapes ``rows`` (K,) only, in that order (row k
        of the result is row rows[k] here): the same numbers, so the kernel
        computes the same overlaps from it, and a call that needs a few
        shapes of a large table does not pay for the rest (the kernel
        prepares every shape of the table it is given)."""
        rows = np.asarray(rows, np.int64)
        sub = ShapeTable.__new__(ShapeTable)
        sub.n = len(rows)
        for name, data, off in (("vertices", self.vertices, self.voff), ("triangles", self.triangles, self.toff)):
            lo, hi = off[rows].astype(np.int64), off[rows + 1].astype(np.int64)
            lengths = hi - lo
            start = np.repeat(lo - np.concatenate([[0], np.cumsum(lengths)[:-1]]), lengths)
            idx = start + np.arange(lengths.sum())
            setattr(sub, name, np.ascontiguousarray(data[idx]))
            setattr(sub, "voff" if name == "vertices" else "toff",
                    ckernel.i32(np.concatenate([[0], np.cumsum(lengths)])))
        return sub

    def args(self):
        """The leading arguments of the kernel's geometry functions."""
        return (self.n, ckernel.iptr(self.voff), ckernel.dptr(self.vertices), ckernel.iptr(self.toff),
                ckernel.iptr(self.triangles))


def _poses(pos, quat, n, what):
    pos = ckernel.f64(pos)
    quat = ckernel.f64(quat)
    if pos.shape != (n, 3):
        raise OverlapError(f"{what} positions must be ({n}, 3), got {pos.shape}")
    if quat.shape != (n, 4):
        raise OverlapError(f"{what} quaternions must be ({n}, 4) (w, x, y, z), got {quat.shape}")
    if not (np.all(np.isfinite(pos)) and np.all(np.isfinite(quat))):
        raise OverlapError(f"{what} poses are not finite")
    if np.any(np.linalg.norm(quat, axis=1) == 0):
        raise OverlapError(f"{what} quaternion of zero norm")
    return pos, quat


def _index(idx, n, nshapes, what):
    idx = np.asarray(idx)
    if idx.shape != (n,):
        raise OverlapError(f"{what} shape indices must be ({n},), got {idx.shape}")
    if n and (idx.min() < 0 or idx.max() >= nshapes):
        raise OverlapError(f"{what} shape index out of range 0..{nshapes - 1}")
    return ckernel.i32(idx)


def batch_overlap(table, shape_a, pos_a, quat_a, shape_b, pos_b, quat_b, threads=0):
    """Overlap of P pairs of polyhedra (see the module docstring).

    table : ShapeTable; shape_a, shape_b : (P,) rows of the table;
    pos_a, pos_b : (P, 3) m; quat_a, quat_b : (P, 4) (w, x, y, z).
    threads : OpenMP threads (0: all cores).
    Returns a dict of arrays: volume (P,), centroid (P, 3), normal (P, 3),
    footprint (P, 2), area (P,), status (P,).
    """
    n = len(np.asarray(shape_a))
    sa = _index(shape_a, n, table.n, "A")
    sb = _index(shape_b, n, table.n, "B")
    pa, qa = _poses(pos_a, quat_a, n, "A")
    pb, qb = _poses(pos_b, quat_b, n, "B")
    out = _outputs(n)
    lib = ckernel.load()
    err = lib.pc_batch_overlap(*table.args(), n, ckernel.iptr(sa), ckernel.dptr(pa), ckernel.dptr(qa),
                               ckernel.iptr(sb), ckernel.dptr(pb), ckernel.dptr(qb), *_out_ptrs(out), int(threads))
    if err:
        raise MemoryError("contact kernel: could not allocate its workspace")
    _check_status(out)
    return out


def batch_wall(table, shape, pos, quat, plane_point, plane_normal, threads=0):
    """Overlap of P polyhedra with walls (half-spaces).

    A wall is the plane through ``plane_point`` (P, 3) m with unit normal
    ``plane_normal`` (P, 3) pointing to the side where the polyhedron belongs
    (into the box). The overlap is the part of the polyhedron with
    (x - point) . m < 0; its normal is m (from the wall to the polyhedron).
    Returns the same dict as :func:`batch_overlap`.
    """
    n = len(np.asarray(shape))
    s = _index(shape, n, table.n, "polyhedron")
    p, q = _poses(pos, quat, n, "polyhedron")
    wp = ckernel.f64(plane_point).reshape(n, 3)
    wm = ckernel.f64(plane_normal).reshape(n, 3)
    norm = np.linalg.norm(wm, axis=1)
    if not np.all(np.isfinite(wp)) or not np.all(norm > 0):
        raise OverlapError("wall planes must have finite points and non-zero normals")
    wm = ckernel.f64(wm / norm[:, None])
    out = _outputs(n)
    lib = ckernel.load()
    err = lib.pc_batch_wall(*table.args(), n, ckernel.iptr(s), ckernel.dptr(p), ckernel.dptr(q),
                            ckernel.dptr(wp), ckernel.dptr(wm), *_out_ptrs(out), int(threads))
    if err:
        raise MemoryError("contact kernel: could not allocate its workspace")
    _check_status(out)
    return out


def pair_overlap(verts_a, faces_a, pos_a, quat_a, verts_b, faces_b, pos_b, quat_b):
    """Overlap of polyhedron A and polyhedron B (one pair).

    verts (V, 3) m in the local frame, faces (T, 3) int outward triangles,
    pos (3,) m, quat (4,) (w, x, y, z) local -> global. Returns a dict with
    ``volume`` (m^3), ``centroid`` (3,) m, ``normal`` (3,) unit from A to B,
    ``footprint`` (2,) m largest first, ``area`` (m^2), ``status``.
    """
    table = ShapeTable([(verts_a, faces_a), (verts_b, faces_b)])
    r = batch_overlap(table, [0], np.reshape(pos_a, (1, 3)), np.reshape(quat_a, (1, 4)),
                      [1], np.reshape(pos_b, (1, 3)), np.reshape(quat_b, (1, 4)), threads=1)
    return _single(r)


def wall_overlap(verts, faces, pos, quat, plane_point, plane_normal):
    """Overlap of one polyhedron with the wall through ``plane_point`` (3,)
    whose unit normal ``plane_normal`` (3,) points to the polyhedron's side:
    see :func:`batch_wall`. Returns the dict of :func:`pair_overlap`."""
    table = ShapeTable([(verts, faces)])
    r = batch_wall(table, [0], np.reshape(pos, (1, 3)), np.reshape(quat, (1, 4)),
                   np.reshape(plane_point, (1, 3)), np.reshape(plane_normal, (1, 3)), threads=1)
    return _single(r)


def _outputs(n):
    return {"volume": np.zeros(n), "centroid": np.zeros((n, 3)), "normal": np.zeros((n, 3)),
            "footprint": np.zeros((n, 2)), "area": np.zeros(n), "status": np.zeros(n, np.int32)}


def _out_ptrs(out):
    return (ckernel.dptr(out["volume"]), ckernel.dptr(out["centroid"]), ckernel.dptr(out["normal"]),
            ckernel.dptr(out["footprint"]), ckernel.dptr(out["area"]), ckernel.iptr(out["status"]))


def _check_status(out):
    if np.any(out["status"] == 2):
        k = int(np.argmax(out["status"] == 2))
        raise OverlapError(f"pair {k}: the clipping workspace overflowed (are the shapes convex?)")


def _single(r):
    return {"volume": float(r["volume"][0]), "centroid": r["centroid"][0], "normal": r["normal"][0],
            "footprint": r["footprint"][0], "area": float(r["area"][0]), "status": int(r["status"][0])}


def rotation_matrices(quat):
    """(n, 3, 3) rotation matrices (local -> global: R @ local = global) of
    quaternions (n, 4) (w, x, y, z), normalised here."""
    q = np.asarray(quat, float)
    w, x, y, z = (q / np.linalg.norm(q, axis=1)[:, None]).T
    return np.stack([np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
                     np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
                     np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1)], -2)


class OrientedGrains:
    """Grains of fixed shapes and orientations whose centres are still to be
    chosen (placing a sample): grain k has vertices ``shapes[k][0]`` (V_k,
    3) m in its local frame, triangles ``shapes[k][1]``, and orientation
    ``quat[k]`` (w, x, y, z)."""

    def __init__(self, shapes, quat):
        self.table = ShapeTable(shapes)
        self.quat = ckernel.f64(quat)
        if self.quat.shape != (self.table.n, 4):
            raise OverlapError(f"quaternions must be ({self.table.n}, 4), got {self.quat.shape}")
        rot = rotation_matrices(self.quat)
        vmax = max(len(v) for v, _ in shapes)
        self.posed = np.zeros((self.table.n, vmax, 3))      # global-frame vertices about the centre
        for k, (v, _) in enumerate(shapes):
            g = np.asarray(v, float) @ rot[k].T
            self.posed[k] = np.concatenate([g, np.repeat(g[:1], vmax - len(g), axis=0)])   # pad: no new support

    def overlaps(self, k, X, J, Y):
        """(m,) bool: grain k centred at X[i] (m, 3) overlaps grain J[i]
        centred at Y[i] (m, 3). Exact: a pair is apart when the plane normal
        to its line of centres separates the support functions, h_k(u) +
        h_J(-u) < |Y - X| with u = (Y - X)/|Y - X| (most pairs whose bounding
        spheres meet), else when the kernel finds no overlap volume."""
        X, Y, J = np.asarray(X, float), np.asarray(Y, float), np.asarray(J)
        u = Y - X
        dist = np.linalg.norm(u, axis=1)
        u = u / np.where(dist > 0, dist, 1.0)[:, None]
        h_k = (self.posed[k] @ u.T).max(axis=0)
        h_j = -np.einsum("mvc,mc->mv", self.posed[J], u).min(axis=1)
        out = np.zeros(len(J), bool)
        test = np.flatnonzero(h_k + h_j >= dist)
        if len(test):
            # only the shapes of these pairs go to the kernel (it prepares every shape of its table)
            rows, local = np.unique(np.concatenate([[k], J[test]]), return_inverse=True)
            res = batch_overlap(self.table.subset(rows), np.full(len(test), local[0]), X[test],
                                np.repeat(self.quat[k][None], len(test), 0), local[1:], Y[test], self.quat[J[test]],
                                threads=1)
            out[test] = res["volume"] > 0
        return out
