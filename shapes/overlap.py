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
    """Many shapes packed for the kernel: concatenated float64 vertices and
    int32 triangles, with offsets into them.

    Parameters
    ----------
    shapes : list of (vertices, triangles)
        Per shape, vertices (V, 3) m in its local frame (origin at the
        centre of mass) and triangles (T, 3) int, counter-clockwise seen
        from outside; V >= 4 finite vertices, T >= 4 triangles. A bad shape
        raises :class:`OverlapError` naming it.

    Attributes
    ----------
    n : int
        The number of shapes S.
    voff, toff : (S+1,) int32
        Shape s owns ``vertices[voff[s]:voff[s+1]]`` and
        ``triangles[toff[s]:toff[s+1]]``.
    vertices : (sum V, 3) float64
        m, every shape's vertices.
    triangles : (sum T, 3) int32
        Every shape's triangles, indices local to the shape.

    Examples
    --------
    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((-0.5, 0.5), repeat=3))))     # a unit cube
    >>> table = ShapeTable([(v, t), (2 * v, t)])
    >>> table.n, table.voff.tolist(), table.toff.tolist(), table.vertices.shape
    (2, [0, 8, 16], [0, 12, 24], (16, 3))
    >>> sub = table.subset([1])                         # the larger cube alone
    >>> sub.n, sub.voff.tolist(), float(sub.vertices.max())
    (1, [0, 8], 1.0)
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
    """The exact overlap of P pairs of convex polyhedra A and B (module
    docstring), computed by the compiled kernel.

    Parameters
    ----------
    table : ShapeTable
        The shapes.
    shape_a, shape_b : (P,) int
        Rows of ``table``: the shapes of A and B.
    pos_a, pos_b : (P, 3) float
        m, the positions of A's and B's local origins (centres of mass).
    quat_a, quat_b : (P, 4) float
        Unit quaternions (w, x, y, z) turning each local frame into the
        global one (a quaternion of zero norm is refused).
    threads : int
        OpenMP threads (0: all cores). The results do not depend on it.

    Returns
    -------
    dict
        ``volume`` (P,) m^3, ``centroid`` (P, 3) m (the contact point),
        ``normal`` (P, 3) unit, from A to B, ``footprint`` (P, 2) m,
        ``area`` (P,) m^2 and ``status`` (P,) int, as defined in the module
        docstring. The volumetric normal force on B is then k_V V n, along
        +n (repulsive). Pairs apart: volume 0, centroid and normal NaN.

    Raises
    ------
    OverlapError
        Indices, poses or quaternions of the wrong shape, out of range or
        not finite; a pair that overflowed the clipping workspace.

    Examples
    --------
    Two pairs of cubes, the second B twice as large, overlapping by 1 cm
    and 5 cm along x:

    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((-0.5, 0.5), repeat=3))))     # a unit cube
    >>> table = ShapeTable([(v, t), (2 * v, t)])
    >>> one = [[1.0, 0, 0, 0]] * 2                      # no rotation
    >>> r = batch_overlap(table, [0, 0], [[0, 0, 0]] * 2, one, [0, 1], [[0.99, 0, 0], [1.45, 0, 0]], one)
    >>> r["volume"].round(12), r["centroid"][:, 0].round(12), r["normal"].round(12) + 0.0
    (array([0.01, 0.05]), array([0.495, 0.475]), array([[1., 0., 0.],
           [1., 0., 0.]]))
    >>> r["footprint"], r["area"], r["status"]
    (array([[1., 1.],
           [1., 1.]]), array([1., 1.]), array([0, 0], dtype=int32))
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
    """The exact overlap of P convex polyhedra with walls (half-spaces).

    A wall is the plane through ``plane_point`` with normal m pointing to
    the side where the polyhedron belongs (into the box). The overlap is
    the part of the polyhedron with (x - point) . m < 0; its normal is m
    (from the wall to the polyhedron: the wall is A).

    Parameters
    ----------
    table : ShapeTable
        The shapes.
    shape : (P,) int
        Rows of ``table``.
    pos : (P, 3) float
        m, the polyhedra's positions (local origins).
    quat : (P, 4) float
        Unit quaternions (w, x, y, z), local -> global.
    plane_point : (P, 3) float
        m, a point of each wall's plane.
    plane_normal : (P, 3) float
        Each wall's normal, into the box (normalised here; not zero).
    threads : int
        OpenMP threads (0: all cores).

    Returns
    -------
    dict
        The arrays of :func:`batch_overlap`, ``normal`` being the wall's
        unit normal m wherever the polyhedron crosses the plane.

    Raises
    ------
    OverlapError
        As :func:`batch_overlap`, and for wall planes with non-finite
        points or zero normals.

    Examples
    --------
    A floor z = 0; the unit cube sinks 5 cm into it, the cube of side 2
    10 cm:

    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((-0.5, 0.5), repeat=3))))     # a unit cube
    >>> table = ShapeTable([(v, t), (2 * v, t)])
    >>> r = batch_wall(table, [0, 1], [[0, 0, 0.45], [0, 0, 0.9]], [[1.0, 0, 0, 0]] * 2,
    ...                plane_point=[[0, 0, 0]] * 2, plane_normal=[[0, 0, 1]] * 2)
    >>> r["volume"].round(12), r["centroid"][:, 2].round(12), r["area"].round(12)
    (array([0.05, 0.4 ]), array([-0.025, -0.05 ]), array([1., 4.]))
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
    """The exact overlap of convex polyhedron A and convex polyhedron B
    (one pair; module docstring).

    Parameters
    ----------
    verts_a, verts_b : (V, 3) float
        m, each shape's vertices in its local frame (origin at the centre
        of mass).
    faces_a, faces_b : (T, 3) int
        Each shape's triangles, counter-clockwise seen from outside.
    pos_a, pos_b : (3,) float
        m, the positions of the local origins.
    quat_a, quat_b : (4,) float
        Unit quaternions (w, x, y, z), local -> global.

    Returns
    -------
    dict
        ``volume`` (float, m^3), ``centroid`` (3,) m (the contact point),
        ``normal`` (3,) unit from A to B, ``footprint`` (2,) m largest
        first, ``area`` (float, m^2, of the overlap's shadow on the contact
        plane) and ``status`` (int): 0, or 1 when S_A vanishes (one grain
        inside the other) and the normal is the line of centres, or +z when
        the centres coincide. Apart: volume 0, centroid and normal NaN.

    Examples
    --------
    Two unit cubes, B 0.99 m along x from A: a slab 1 cm thick.

    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((-0.5, 0.5), repeat=3))))     # a unit cube
    >>> r = pair_overlap(v, t, [0, 0, 0], [1, 0, 0, 0], v, t, [0.99, 0, 0], [1, 0, 0, 0])
    >>> round(r["volume"], 12), r["centroid"].round(12) + 0.0, r["normal"] + 0.0, r["footprint"], r["area"]
    (0.01, array([0.495, 0.   , 0.   ]), array([1., 0., 0.]), array([1., 1.]), 1.0)
    >>> pair_overlap(v, t, [0, 0, 0], [1, 0, 0, 0], v, t, [1.5, 0, 0], [1, 0, 0, 0])["volume"]   # apart
    0.0
    """
    table = ShapeTable([(verts_a, faces_a), (verts_b, faces_b)])
    r = batch_overlap(table, [0], np.reshape(pos_a, (1, 3)), np.reshape(quat_a, (1, 4)),
                      [1], np.reshape(pos_b, (1, 3)), np.reshape(quat_b, (1, 4)), threads=1)
    return _single(r)


def wall_overlap(verts, faces, pos, quat, plane_point, plane_normal):
    """The exact overlap of one convex polyhedron with a wall (half-space;
    see :func:`batch_wall`).

    Parameters
    ----------
    verts : (V, 3) float
        m, the shape's vertices in its local frame.
    faces : (T, 3) int
        Its triangles, counter-clockwise seen from outside.
    pos : (3,) float
        m, the position of its local origin.
    quat : (4,) float
        Unit quaternion (w, x, y, z), local -> global.
    plane_point : (3,) float
        m, a point of the wall's plane.
    plane_normal : (3,) float
        The wall's normal, pointing to the polyhedron's side (into the
        box).

    Returns
    -------
    dict
        As :func:`pair_overlap`, the wall being A: the normal is the wall's
        (from the wall to the polyhedron).

    Examples
    --------
    A unit cube sunk 5 cm into the floor z = 0:

    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((-0.5, 0.5), repeat=3))))     # a unit cube
    >>> r = wall_overlap(v, t, [0, 0, 0.45], [1, 0, 0, 0], [0, 0, 0], [0, 0, 1])
    >>> round(r["volume"], 12), r["centroid"].round(12) + 0.0, r["normal"] + 0.0
    (0.05, array([ 0.   ,  0.   , -0.025]), array([0., 0., 1.]))
    """
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
    """The rotation matrices of quaternions.

    Parameters
    ----------
    quat : (n, 4) float
        Quaternions (w, x, y, z), normalised here (not zero).

    Returns
    -------
    (n, 3, 3) float
        The rotations, local -> global: ``R @ local = global``.

    Examples
    --------
    A quarter turn about z takes x to y:

    >>> R = rotation_matrices([[np.cos(np.pi / 4), 0, 0, np.sin(np.pi / 4)]])
    >>> (R[0] @ [1, 0, 0]).round(12) + 0.0
    array([0., 1., 0.])
    >>> rotation_matrices([[2, 0, 0, 0]])[0]                # normalised first
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    """
    q = np.asarray(quat, float)
    w, x, y, z = (q / np.linalg.norm(q, axis=1)[:, None]).T
    return np.stack([np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
                     np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
                     np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1)], -2)


class OrientedGrains:
    """Grains of fixed shapes and orientations whose centres are still to be
    chosen (placing a sample): :meth:`overlaps` tells which candidate
    positions would overlap.

    Parameters
    ----------
    shapes : list of (vertices, triangles)
        Grain k has vertices ``shapes[k][0]`` (V_k, 3) m in its local frame
        (origin at the centre of mass) and triangles ``shapes[k][1]``
        (T_k, 3), counter-clockwise seen from outside.
    quat : (K, 4) float
        Grain k's orientation, a quaternion (w, x, y, z), local -> global.

    Attributes
    ----------
    table : ShapeTable
        The grains' shapes, row k for grain k.
    quat : (K, 4) float64
        The orientations.
    posed : (K, max V_k, 3) float
        m, each grain's vertices turned into the global frame, relative to
        its centre (padded by repeating its first vertex).

    Examples
    --------
    A unit cube and one turned by 45 deg about z (half-diagonal 0.707 m
    along x): side by side along x, they touch at 0.5 + 0.707 m.

    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((-0.5, 0.5), repeat=3))))     # a unit cube
    >>> turned = [np.cos(np.pi / 8), 0, 0, np.sin(np.pi / 8)]
    >>> grains = OrientedGrains([(v, t), (v, t)], [[1, 0, 0, 0], turned])
    >>> grains.overlaps(0, np.zeros((2, 3)), np.array([1, 1]), np.array([[1.15, 0, 0], [1.25, 0, 0]]))
    array([ True, False])
    """

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
        """Whether grain k centred at X[i] overlaps grain J[i] centred at
        Y[i], for each i.

        Exact: a pair is apart when the plane normal to its line of centres
        separates the support functions, h_k(u) + h_J(-u) < |Y - X| with
        u = (Y - X) / |Y - X| (most pairs whose bounding spheres meet),
        else when the kernel finds no overlap volume.

        Parameters
        ----------
        k : int
            The grain to place.
        X : (m, 3) float
            m, candidate centres of grain k.
        J : (m,) int
            The grains already placed.
        Y : (m, 3) float
            m, their centres.

        Returns
        -------
        (m,) bool
            True where the pair overlaps (a positive overlap volume).
        """
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
