"""Contact types between convex polyhedra: vertex, edge or face on each side.

YADE stores one contact point and one normal per polyhedra pair and no
contact type. We classify each particle-particle contact from the shapes
(local vertices and triangles), each body's orientation and the contact
normal n (unit, from id1 towards id2).

Criterion (one angular tolerance ``theta``, default 5 deg). For body A the
outward direction towards its partner is u = +n (A = id1) or -n (A = id2),
written in A's local frame. The feature of A that touches is its support
feature in direction u, taken as parallel to the contact plane within theta:

* FACE   if a geometric face of A that contains its support vertex (the
         vertex furthest along u) has its outward normal within theta of u
         (the face lies flat on the contact plane; a face that does not hold
         the most advanced vertex is not where the bodies touch);
* EDGE   else, if the two vertices of A furthest along u are the ends of an
         edge of A and that edge is parallel to the plane within theta:
         (s_1 - s_2) <= sin(theta) |v_1 - v_2|, s = v . u;
* VERTEX otherwise.

A tolerance in angle is a tolerance in distance relative to the feature's
size: a face or edge of length l counts as touching when its far end is
within l sin(theta) of the contact plane. The pair types are
VV, VE, VF, EE, EF, FF (unordered), grouped as in the paper into simple
(one contact point: VF, EE, and the rare VE, VV), double (EF) and triple
(FF). Everything is vectorised over contacts, in blocks.
"""
from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import numpy as np

from .contactset import lookup
from .errors import InputError

VERTEX, EDGE, FACE = 0, 1, 2
FEATURES = ("vertex", "edge", "face")
PAIR_TYPES = ("VV", "VE", "VF", "EE", "EF", "FF")
GROUP_OF = {"VV": "simple", "VE": "simple", "VF": "simple", "EE": "simple",
            "EF": "double", "FF": "triple"}
DEFAULT_THETA_DEG = 5.0
_BLOCK = 1 << 13
_THREADS = min(4, os.cpu_count() or 1)


@dataclass
class ShapeTables:
    """Per-shape arrays padded to the largest shape (S shapes, at most Vmax
    vertices, at most Dmax geometric faces at a vertex).

    Built by :func:`shape_tables` from a dump's ``/shapes``; read by the
    angular criterion (:func:`touching_features`).

    Attributes
    ----------
    vertices : ndarray of float32, shape (S, Vmax, 3)
        m, the vertices in each shape's local frame (as in ``/shapes``),
        padded with 0.
    pad : ndarray of float32, shape (S, Vmax)
        0 for a vertex and -inf for padding (added to the heights along a
        direction, so that padding is never a support vertex).
    vertex_normals : ndarray of float32, shape (S, Vmax, Dmax, 3)
        Unit outward normals (of the area-weighted sum of each face's
        triangle normals) of the geometric faces that contain each vertex,
        padded with 0.
    edge_length : ndarray of float32, shape (S, Vmax, Vmax)
        m, the length of the geometric edge between two vertices, 0 when
        they are not the ends of an edge (the diagonals between two
        triangles of one geometric face are not edges).
    vertex_face_size : ndarray of float32, shape (S, Vmax, Dmax)
        m, the diameter (largest distance between two of its vertices) of
        each of those faces, 0 for padding.
    """

    vertices: np.ndarray
    pad: np.ndarray
    vertex_normals: np.ndarray
    edge_length: np.ndarray
    vertex_face_size: np.ndarray


def shape_tables(vertices, triangles, triangle_faces):
    """Build :class:`ShapeTables` from per-shape lists (as stored in a dump's
    ``/shapes``): vertices (V_s, 3), triangles (T_s, 3) outward, and the
    geometric face of each triangle (T_s,).

    Parameters
    ----------
    vertices : sequence of array_like, each of shape (V_s, 3)
        m, the vertices of each shape s in its local frame.
    triangles : sequence of array_like of int, each of shape (T_s, 3)
        Vertex indices of each shape's triangles, ordered so that
        (v1 - v0) x (v2 - v0) points outward (counter-clockwise seen from
        outside).
    triangle_faces : sequence of array_like of int, each of shape (T_s,)
        The geometric face (0..F_s - 1) each triangle belongs to: the
        triangles of one planar polygonal face share a number.

    Returns
    -------
    ShapeTables
        The padded tables of the S shapes, in float32.

    Raises
    ------
    InputError
        No shapes, or a geometric face of zero area.
    """
    S = len(vertices)
    if S == 0:
        raise InputError("no shapes to classify contacts with")
    vmax = max(len(v) for v in vertices)
    fmax = max(int(np.max(f)) + 1 for f in triangle_faces)
    V = np.full((S, vmax, 3), np.nan)
    N = np.zeros((S, fmax + 1, 3))
    D = np.zeros((S, fmax + 1))
    A = np.zeros((S, vmax, vmax), bool)
    incident = []
    for s, (v, t, f) in enumerate(zip(vertices, triangles, triangle_faces)):
        v = np.asarray(v, float)
        t = np.asarray(t, np.int64)
        f = np.asarray(f, np.int64)
        V[s, :len(v)] = v
        cr = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
        nf = np.zeros((f.max() + 1, 3))
        np.add.at(nf, f, cr)                        # area-weighted face normal
        norm = np.linalg.norm(nf, axis=1)
        if np.any(norm == 0):
            raise InputError(f"shape {s}: a face has zero area")
        N[s, :len(nf)] = nf / norm[:, None]
        member = np.zeros((len(nf), len(v)), bool)  # face diameters: the largest vertex distance in each face
        member[np.repeat(f, 3), t.ravel()] = True
        dist = np.linalg.norm(v[:, None] - v[None], axis=-1)
        D[s, :len(nf)] = np.where(member[:, :, None] & member[:, None, :], dist, 0.0).max(axis=(1, 2))
        for a, b in ((0, 1), (1, 2), (2, 0)):       # edges between two different faces
            e1, e2 = t[:, a], t[:, b]
            A[s, e1, e2] = True
            A[s, e2, e1] = True
        # edges inside a geometric face (between its own triangles) are not edges
        inner = _inner_edges(t, f)
        A[s, inner[:, 0], inner[:, 1]] = False
        A[s, inner[:, 1], inner[:, 0]] = False
        incident.append([sorted(set(f[(t == k).any(axis=1)].tolist())) for k in range(len(v))])
    dmax = max(len(x) for inc in incident for x in inc)
    VN = np.zeros((S, vmax, dmax, 3))
    VD = np.zeros((S, vmax, dmax))
    for s, inc in enumerate(incident):
        for k, faces in enumerate(inc):
            VN[s, k, :len(faces)] = N[s, faces]
            VD[s, k, :len(faces)] = D[s, faces]
    pad = np.where(np.isnan(V[:, :, 0]), -np.inf, 0.0).astype(np.float32)
    V = np.nan_to_num(V)
    EL = np.where(A, np.linalg.norm(V[:, :, None, :] - V[:, None, :, :], axis=-1), 0.0)
    return ShapeTables(V.astype(np.float32), pad, VN.astype(np.float32), EL.astype(np.float32),
                       VD.astype(np.float32))


def _inner_edges(t, f):
    directed = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    face = np.tile(f, 3)
    key = np.sort(directed, axis=1)
    order = np.lexsort((key[:, 1], key[:, 0]))
    key, face = key[order], face[order]
    same = (key[0::2] == key[1::2]).all(axis=1) & (face[0::2] == face[1::2])
    return key[0::2][same]


def to_local(quaternion, vectors):
    """(C, 3) float32 global vectors expressed in the local frames of bodies
    with orientations (C, 4) (w, x, y, z), local -> global, not necessarily
    normalised: v' = R(q)^T v, computed component-wise (the transpose of
    the unit quaternion's rotation matrix applied to each vector).

    Parameters
    ----------
    quaternion : array_like, shape (C, 4)
        Orientations (w, x, y, z) of the bodies, local -> global, of any
        non-zero norm (cast to float32).
    vectors : array_like, shape (C, 3)
        One global vector per body (any unit; unit directions here), cast
        to float32.

    Returns
    -------
    ndarray of float32, shape (C, 3)
        R(q)^T v of each row: the vector in its body's local frame, in the
        unit of ``vectors``.
    """
    q = np.asarray(quaternion, np.float32)
    v = np.asarray(vectors, np.float32)
    w, x, y, z = q.T
    n2 = w * w + x * x + y * y + z * z
    k = 2 / n2
    vx, vy, vz = v.T
    out = np.empty((len(q), 3), np.float32)
    xx, yy, zz = x * x * k, y * y * k, z * z * k
    xy, xz, yz = x * y * k, x * z * k, y * z * k
    wx, wy, wz = w * x * k, w * y * k, w * z * k
    out[:, 0] = (1 - yy - zz) * vx + (xy + wz) * vy + (xz - wy) * vz
    out[:, 1] = (xy - wz) * vx + (1 - xx - zz) * vy + (yz + wx) * vz
    out[:, 2] = (xz + wy) * vx + (yz - wx) * vy + (1 - xx - yy) * vz
    return out


def touching_features(tables, shape, quaternion, direction, theta_deg=DEFAULT_THETA_DEG):
    """Feature code (VERTEX, EDGE or FACE) of each body at its contact.

    tables : ShapeTables; shape (C,) int row of each body's shape;
    quaternion (C, 4) orientations (w, x, y, z), local -> global;
    direction (C, 3) unit vector from the body towards its partner (global).
    Returns (C,) int8.

    Parameters
    ----------
    tables : ShapeTables
        The shapes (:func:`shape_tables`).
    shape : array_like of int, shape (C,)
        The row of each body's shape in ``tables``.
    quaternion : array_like, shape (C, 4)
        Orientations (w, x, y, z), local -> global, of any non-zero norm.
    direction : array_like, shape (C, 3)
        Unit vector u from the body towards its partner, global frame: +n
        for id1 and -n for id2, n the contact normal from id1 to id2.
    theta_deg : float, optional
        The angular tolerance theta, degrees (default
        ``DEFAULT_THETA_DEG`` = 5).

    Returns
    -------
    ndarray of int8, shape (C,)
        The touching feature of each body (module docstring, computed in
        float32): FACE (2) when a geometric face containing the support
        vertex has its outward normal within theta of u; else EDGE (1) when
        the two vertices furthest along u are the ends of an edge with
        s_1 - s_2 <= sin(theta) |v_1 - v_2|; else VERTEX (0).
    """
    shape = np.asarray(shape, np.int64)
    C = len(shape)
    out = np.empty(C, np.int8)
    cos_t = np.float32(np.cos(np.radians(theta_deg)))
    sin_t = np.float32(np.sin(np.radians(theta_deg)))
    local = to_local(quaternion, direction)

    def block(s0):
        sl = slice(s0, min(s0 + _BLOCK, C))
        sh = shape[sl]
        u = local[sl][:, :, None]
        s = (tables.vertices[sh] @ u)[:, :, 0]         # heights along u
        s += tables.pad[sh]                            # padding at -inf
        rows = np.arange(len(sh))
        i1 = np.argmax(s, axis=1)                      # support vertex
        sa = s[rows, i1]
        s[rows, i1] = -np.inf
        i2 = np.argmax(s, axis=1)                      # the next one
        length = tables.edge_length[sh, i1, i2]        # 0 unless (i1, i2) is an edge
        edge = (length > 0) & (sa - s[rows, i2] <= sin_t * length)
        face = (tables.vertex_normals[sh, i1] @ u)[:, :, 0].max(axis=1) >= cos_t
        out[sl] = np.where(face, FACE, np.where(edge, EDGE, VERTEX))

    starts = range(0, C, _BLOCK)
    if C > 2 * _BLOCK:       # numpy releases the GIL in these kernels: blocks in threads
        with ThreadPoolExecutor(_THREADS) as pool:
            list(pool.map(block, starts))
    else:
        for s0 in starts:
            block(s0)
    return out


def pair_types(f1, f2):
    """(C,) int index into PAIR_TYPES of the unordered feature pairs.

    Parameters
    ----------
    f1, f2 : array_like of int, shape (C,)
        The feature codes of the two sides (VERTEX 0, EDGE 1, FACE 2), in
        either order.

    Returns
    -------
    ndarray of int8, shape (C,)
        The index into PAIR_TYPES of each unordered pair: 0 VV, 1 VE, 2 VF,
        3 EE, 4 EF, 5 FF. ``GROUP_OF`` maps these to the paper's groups:
        simple (VV, VE, VF, EE: one contact point), double (EF: two),
        triple (FF: three or more).
    """
    lo, hi = np.minimum(f1, f2), np.maximum(f1, f2)
    # VV VE VF EE EF FF  <->  (0,0) (0,1) (0,2) (1,1) (1,2) (2,2)
    table = np.array([[0, 1, 2], [1, 3, 4], [2, 4, 5]], np.int8)
    return table[lo, hi]


def first_degenerate_normal(normal):
    """Index of the first normal that is not a finite unit vector, else -1.

    Parameters
    ----------
    normal : array_like, shape (C, 3)
        Contact normals (dimensionless).

    Returns
    -------
    int
        The row of the first normal whose norm is not within 1e-6 of 1
        (NaN and infinite rows included), or -1 when all are unit vectors.
    """
    norm = np.linalg.norm(np.asarray(normal, float), axis=1)
    bad = ~(np.abs(norm - 1) < 1e-6)
    return int(np.flatnonzero(bad)[0]) if bad.any() else -1


def classify_contacts(tables, shape1, shape2, q1, q2, normal, theta_deg=DEFAULT_THETA_DEG):
    """Pair type of each polyhedra contact.

    shape1, shape2 (C,) shape rows of id1 and id2; q1, q2 (C, 4) their
    orientations (w, x, y, z); normal (C, 3) unit, from id1 to id2.
    Returns (feature1, feature2, pair) as (C,) int arrays; ``pair`` indexes
    PAIR_TYPES. Raises InputError for a degenerate normal.

    Parameters
    ----------
    tables : ShapeTables
        The shapes (:func:`shape_tables`).
    shape1, shape2 : array_like of int, shape (C,)
        The shape rows of id1 and id2 in ``tables``.
    q1, q2 : array_like, shape (C, 4)
        Their orientations (w, x, y, z), local -> global.
    normal : array_like, shape (C, 3)
        Unit contact normals n from id1 to id2: id1 touches along +n, id2
        along -n.
    theta_deg : float, optional
        The angular tolerance, degrees (default 5).

    Returns
    -------
    feature1, feature2 : ndarray of int8, shape (C,)
        The touching features of id1 and id2 (VERTEX 0, EDGE 1, FACE 2;
        :func:`touching_features`).
    pair : ndarray of int8, shape (C,)
        The index into PAIR_TYPES of the unordered pair (:func:`pair_types`).

    Raises
    ------
    InputError
        A normal whose norm is not within 1e-6 of 1
        (:func:`first_degenerate_normal`).
    """
    n = np.asarray(normal, float)
    k = first_degenerate_normal(n)
    if k >= 0:
        raise InputError(f"contact {k}: degenerate contact normal {n[k].tolist()} (not a unit vector)")
    f1 = touching_features(tables, shape1, q1, n, theta_deg)
    f2 = touching_features(tables, shape2, q2, -n, theta_deg)
    return f1, f2, pair_types(f1, f2)


def classify_snapshot(snap, tables, theta_deg=DEFAULT_THETA_DEG, features=False):
    """Contact classes of a :class:`~postproc.schema.Snapshot`.

    Returns (C,) array of strings: a pair type of PAIR_TYPES for contacts
    between two polyhedra, ``"sphere"`` for contacts involving a sphere,
    ``"wall"`` for contacts with a wall. Raises InputError for a polyhedron
    without a shape, a shape index out of range or a degenerate normal.
    With ``features``, returns (labels, poly (C,) bool the polyhedra pairs,
    feature1 (P,), feature2 (P,), pair (P,)) for those P pairs.

    Parameters
    ----------
    snap : postproc.schema.Snapshot
        A dump's snapshot: contact normals (from id1 to id2), body kinds
        (0 sphere, 1 polyhedron), shape indices and orientations.
    tables : ShapeTables
        The dump's shapes (:func:`shape_tables`).
    theta_deg : float, optional
        The angular tolerance, degrees (default 5).
    features : bool, optional
        Also return the features and pair indices of the polyhedra pairs
        (default False).

    Returns
    -------
    labels : ndarray of str, shape (C,)
        "VV".."FF" (PAIR_TYPES) for a contact between two polyhedra,
        "sphere" for a particle pair with a sphere on either side, "wall"
        for a contact with a wall (a particle pair of any other body kind
        keeps "wall" too).
    poly : ndarray of bool, shape (C,)
        With ``features`` only: True for the P polyhedra pairs.
    feature1, feature2 : ndarray of int8, shape (P,)
        With ``features`` only: the touching features of id1 and id2 of
        those pairs (VERTEX 0, EDGE 1, FACE 2).
    pair : ndarray of int8, shape (P,)
        With ``features`` only: their index into PAIR_TYPES.

    Raises
    ------
    InputError
        A snapshot without normals, body kinds or shape indices (a flat
        table), a polyhedron without a shape or with a shape index out of
        range, or a degenerate normal; one line naming the snapshot.
    """
    where = f"snapshot {snap.name} (step {snap.step})"

    if snap.normal is None or snap.body_kind is None or snap.shape_index is None:
        raise InputError(f"{where}: contact types need normals, body kinds and shapes (a dump, not a table)")
    i1, i2 = lookup(snap.id1, snap.body_ids), lookup(snap.id2, snap.body_ids)
    out = np.full(len(snap.id1), "wall", dtype="<U6")
    pp = (i1 >= 0) & (i2 >= 0)
    kind1 = np.where(i1 >= 0, snap.body_kind[np.maximum(i1, 0)], -1)
    kind2 = np.where(i2 >= 0, snap.body_kind[np.maximum(i2, 0)], -1)
    sphere = pp & ((kind1 == 0) | (kind2 == 0))
    out[sphere] = "sphere"
    poly = pp & (kind1 == 1) & (kind2 == 1)
    if not poly.any():
        empty = np.zeros(0, np.int8)
        return (out, poly, empty, empty, empty) if features else out
    S = tables.vertices.shape[0]
    for side, rows in (("id1", i1), ("id2", i2)):
        sidx = snap.shape_index[rows[poly]]
        bad = (sidx < 0) | (sidx >= S)
        if bad.any():
            j = int(np.flatnonzero(bad)[0])
            k = int(np.flatnonzero(poly)[j])
            body = int((snap.id1 if side == "id1" else snap.id2)[k])
            what = "has no shape" if sidx[j] < 0 else \
                f"has shape index {int(sidx[j])} out of range (0..{S - 1})"
            raise InputError(f"{where}: polyhedron {body} of contact {k} {what}")
    k = first_degenerate_normal(snap.normal[poly])
    if k >= 0:
        c = int(np.flatnonzero(poly)[k])
        raise InputError(f"{where}: contact {c} has a degenerate normal {snap.normal[c].tolist()}")
    f1, f2, pair = classify_contacts(
        tables, snap.shape_index[i1[poly]], snap.shape_index[i2[poly]],
        snap.orientations[i1[poly]], snap.orientations[i2[poly]], snap.normal[poly], theta_deg)
    out[poly] = np.array(PAIR_TYPES)[pair]
    return (out, poly, f1, f2, pair) if features else out


def contact_classes(snap, tables, theta_deg=DEFAULT_THETA_DEG):
    """Class of every contact of ``snap``: :func:`classify_snapshot` when the
    dump has shapes (``tables`` not None), else "sphere" for particle-particle
    contacts and "wall" for wall contacts. Returns (C,) str.

    Parameters
    ----------
    snap : postproc.schema.Snapshot
        The snapshot (with normals, body kinds, shape indices and
        orientations when ``tables`` is given).
    tables : ShapeTables or None
        The dump's shapes, or None (spheres, flat contact tables).
    theta_deg : float, optional
        The angular tolerance, degrees (default 5).

    Returns
    -------
    ndarray of str, shape (C,)
        The class of each contact: with ``tables``, "VV".."FF", "sphere" or
        "wall" (:func:`classify_snapshot`); without, "sphere" when both ids
        are bodies of the snapshot and "wall" otherwise.

    Raises
    ------
    InputError
        As :func:`classify_snapshot`, when ``tables`` is given.
    """
    if tables is not None:
        return classify_snapshot(snap, tables, theta_deg)

    both = (lookup(snap.id1, snap.body_ids) >= 0) & (lookup(snap.id2, snap.body_ids) >= 0)
    return np.where(both, "sphere", "wall")
