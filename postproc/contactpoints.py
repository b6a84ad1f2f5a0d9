"""Contact points of a pair of convex polyhedra: 1, 2 or 3+ (simple, double, triple).

The seed paper's contact-dynamics code (LMGC90) counts the contact points of
a polyhedra pair by its common-plane method: on each body it takes the
vertices that lie within a distance tolerance of the contact plane, projects
them on the plane and intersects the two convex hulls; the contact points
are the vertices of that intersection. One point for vertex-face,
vertex-edge and crossed edges, two for an edge on a face, three or more for
face on face. We count the same from the poses, the contact normal and the
overlap of a soft-contact (volumetric) run.

Definition. For a contact between polyhedra A (id1) and B (id2) and a unit
direction u from A to B, the heights of A's vertices are s = x . u and those
of B's are -x . u; each body's support height is its largest; the
*penetration along u* is g_u = max_A (x . u) - min_B (x . u) (m; the
overlap's extent along u). A vertex *touches along u* when its height is
within g_u + delta of its body's support height,

    support - s(v) <= g_u + delta,        delta = alpha * h,

i.e. it lies in the overlap slab (as far as the height along u tells) or at
most delta short of it; h (m) is the overlap's mean thickness V / area (the
overlap volume over the area of its shadow on the contact plane, both
dumped by kernel runs, recomputed with shapes.overlap otherwise) and alpha
the tolerance (``DEFAULT_ALPHA``). The count of a side is the larger of
its counts along two directions: the contact normal n, and the normal of
the *partner's* face closest to the contact plane (the triangle plane of B
whose outward normal is closest to -n, for A; of A closest to +n, for B).
The second direction is the plane a face-on-face contact sits in: where a
face overlap spills over an edge of the partner, the kernel's normal
(S_A / |S_A|) tilts by about h / s (s the overlap's width), which lifts the
far corners of a face resting flat by about its length times that, more
than the slab. A side's touching feature is its VERTEX (1 touching vertex),
EDGE (2) or FACE (3 or more: a face, or an edge with a third vertex as
close to the plane). The pair type is VV .. FF from the two features and
the number of contact points, LMGC90's, is

    1 if a side is a vertex, or both are edges (crossed edges: one point),
    2 for an edge on a face (EF),
    3 or more for face on face (FF; we return the smaller of the two
      touching counts, a lower bound of the intersection's),

grouped as simple (1), double (2), triple (3+). Parallel edges lying on each
other (two points in LMGC90) count as EE, one point: they need an angular
tolerance of their own and are rare between these grains.

Tolerance. A face or edge of length L counts when it lies flat to about
(g + delta) / L; delta adds a margin alpha h to the slab. The counts
converge as alpha -> 0 (the slab alone); the default alpha = 0.1 keeps
faces that lie flush (to round-off) and is where halving and doubling alpha
moves each group by less than 0.03 on the S1 runs (docs/contact-types.md:
at alpha = 1 they move by 0.09-0.11). The slab itself grows with the
overlap, i.e. with the contact stiffness and the force: the groups are not
independent of kappa (docs/contact-types.md).

Pure functions over arrays; no file I/O; vectorised in blocks of contacts.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from shapes.overlap import rotation_matrices

from .contacttypes import EDGE, FACE, PAIR_TYPES, VERTEX, pair_types
from .errors import InputError

DEFAULT_ALPHA = 0.1       # delta = alpha * h, h = V / area (the overlap's mean thickness); see docs/contact-types.md
SIMPLE, DOUBLE, TRIPLE = 0, 1, 2
_BLOCK = 1 << 11


@dataclass
class PointTables:
    """Per-shape local geometry padded to the largest shape.

    Built by :func:`point_tables` (S shapes, at most Vmax vertices and Tmax
    triangles).

    Attributes
    ----------
    vertices : ndarray of float64, shape (S, Vmax, 3)
        m, the vertices in each shape's local frame (origin at the body's
        position, its centre of mass), padded with 0.
    mask : ndarray of bool, shape (S, Vmax)
        True for a vertex, False for padding.
    plane_normals : ndarray of float64, shape (S, Tmax, 3)
        Unit outward normals of the triangles, padded with copies of the
        first triangle's.
    plane_offsets : ndarray of float64, shape (S, Tmax)
        m, the offset of each triangle's plane: a point x of the shape has
        n . x <= offset for every plane; padded with copies of the first
        plane's.
    radius : ndarray of float64, shape (S,)
        m, the largest distance from the local origin to a vertex (None
        when the tables are made without it).
    """

    vertices: np.ndarray
    mask: np.ndarray
    plane_normals: np.ndarray
    plane_offsets: np.ndarray
    radius: np.ndarray = None


def point_tables(vertices, triangles):
    """:class:`PointTables` from per-shape vertex arrays (V_s, 3) m in the
    local frames and outward (counter-clockwise) triangles (T_s, 3), as in
    a dump's ``/shapes``. Raises InputError (one line) for a shape with
    fewer than 4 or non-finite vertices, bad or degenerate triangles.

    Parameters
    ----------
    vertices : sequence of array_like, each of shape (V_s, 3)
        m, each shape's vertices in its local frame, V_s >= 4, finite.
    triangles : sequence of array_like of int, each of shape (T_s, 3)
        Each shape's triangles as vertex indices (0..V_s - 1), T_s >= 4,
        counter-clockwise seen from outside (outward normals).

    Returns
    -------
    PointTables
        The padded tables of the S shapes, ``radius`` included.

    Raises
    ------
    InputError
        No shapes, unequal numbers of vertex and triangle sets, or a shape
        as listed above (one line naming the shape).
    """
    if vertices is None or len(vertices) == 0:
        raise InputError("contact points: no shapes")
    if len(triangles) != len(vertices):
        raise InputError(f"contact points: {len(vertices)} vertex sets but {len(triangles)} triangle sets")
    vs, ns, os_ = [], [], []
    for s, (v, t) in enumerate(zip(vertices, triangles)):
        v = np.asarray(v, float)
        t = np.asarray(t)
        if v.ndim != 2 or v.shape[1] != 3 or len(v) < 4:
            raise InputError(f"contact points: shape {s}: vertices must be (V >= 4, 3), got {v.shape}")
        if not np.isfinite(v).all():
            raise InputError(f"contact points: shape {s}: vertices are not finite")
        if t.ndim != 2 or t.shape[1] != 3 or len(t) < 4 or not np.issubdtype(t.dtype, np.integer) \
                or t.min() < 0 or t.max() >= len(v):
            raise InputError(f"contact points: shape {s}: triangles must be (T >= 4, 3) vertex indices")
        c = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
        norm = np.linalg.norm(c, axis=1)
        if np.any(norm == 0):
            raise InputError(f"contact points: shape {s}: a triangle has zero area")
        c /= norm[:, None]
        vs.append(v)
        ns.append(c)
        os_.append(np.einsum("ij,ij->i", c, v[t[:, 0]]))
    S, vmax, tmax = len(vs), max(len(v) for v in vs), max(len(n) for n in ns)
    V = np.zeros((S, vmax, 3))
    M = np.zeros((S, vmax), bool)
    N = np.zeros((S, tmax, 3))
    O = np.zeros((S, tmax))
    for s in range(S):
        V[s, :len(vs[s])] = vs[s]
        M[s, :len(vs[s])] = True
        k = len(ns[s])
        N[s, :k], O[s, :k] = ns[s], os_[s]
        N[s, k:], O[s, k:] = ns[s][0], os_[s][0]
    return PointTables(V, M, N, O, np.linalg.norm(V, axis=2).max(axis=1))


def _posed(tables, shape, pos, quat):
    """Global vertices (C, V, 3), plane normals (C, T, 3) and offsets (C, T)."""
    R = rotation_matrices(quat)
    X = np.einsum("cij,cvj->cvi", R, tables.vertices[shape]) + pos[:, None, :]
    N = np.einsum("cij,ctj->cti", R, tables.plane_normals[shape])
    O = tables.plane_offsets[shape] + np.einsum("ctk,ck->ct", N, pos)
    return X, N, O


def check_pose_arrays(where, n_shapes, arrays):
    """The per-contact arrays of a batch of polyhedra pairs, checked alike
    for every count (this module's, and both of :mod:`postproc.commonplane`).

    where : the message prefix ("contact points", "common plane", ...).
    n_shapes : the number of shape rows. arrays : [(name, value, shape)],
    each value's required shape. Names starting "shape" must be integer
    shape rows in 0..n_shapes-1; every other array finite per contact;
    those starting "quat" of non-zero norm; "normal" unit vectors.
    Returns the arrays in order, shape rows as int64 and the others as
    float. Raises InputError (one line naming the array and the first bad
    contact).

    Parameters
    ----------
    where : str
        The message prefix ("contact points", "common plane", ...).
    n_shapes : int
        The number of shape rows S.
    arrays : sequence of (str, array_like, tuple)
        (name, value, required shape) of each array, e.g. ("shape1",
        shape1, (C,)), ("pos1", pos1, (C, 3)) m, ("quat1", quat1, (C, 4)),
        ("normal", normal, (C, 3)).

    Returns
    -------
    list of ndarray
        The arrays in the order given: shape rows as int64, the others as
        float64, shapes unchanged.

    Raises
    ------
    InputError
        A value of another shape, shape rows not integer or outside
        0..n_shapes - 1, a non-finite value, a quaternion of zero norm or a
        normal whose norm is not within 1e-6 of 1.
    """
    given = []
    for name, a, shp in arrays:
        a = np.asarray(a)
        if a.shape != shp:
            raise InputError(f"{where}: {name} must have shape {shp}, got {a.shape}")
        given.append((name, a))
    out = {}
    for name, a in given:
        if name.startswith("shape"):
            if not np.issubdtype(a.dtype, np.integer):
                raise InputError(f"{where}: {name} must be integer shape rows")
            bad = (a < 0) | (a >= n_shapes)
            if bad.any():
                k = int(np.flatnonzero(bad)[0])
                raise InputError(f"{where}: contact {k}: {name} {int(a[k])} out of range 0..{n_shapes - 1}")
            out[name] = a.astype(np.int64)
    for name, a in given:
        if not name.startswith("shape"):
            a = out[name] = a.astype(float)
            finite = np.isfinite(a) if a.ndim == 1 else np.isfinite(a).all(axis=tuple(range(1, a.ndim)))
            if not finite.all():
                raise InputError(f"{where}: contact {int(np.flatnonzero(~finite)[0])}: {name} is not finite")
    for name, a in out.items():
        if name.startswith("quat"):
            bad = np.linalg.norm(a, axis=1) == 0
            if bad.any():
                raise InputError(f"{where}: contact {int(np.flatnonzero(bad)[0])}: {name} has zero norm")
    if "normal" in out:
        bad = ~(np.abs(np.linalg.norm(out["normal"], axis=1) - 1) < 1e-6)
        if bad.any():
            raise InputError(f"{where}: contact {int(np.flatnonzero(bad)[0])}: normal is not a unit vector")
    return [out[name] for name, _ in given]


def _check(tables, shape1, pos1, quat1, shape2, pos2, quat2, normal, h, alpha):
    C = len(np.asarray(shape1))
    s1, s2, p1, p2, q1, q2, n, h = check_pose_arrays("contact points", tables.vertices.shape[0], (
        ("shape1", shape1, (C,)), ("shape2", shape2, (C,)), ("pos1", pos1, (C, 3)), ("pos2", pos2, (C, 3)),
        ("quat1", quat1, (C, 4)), ("quat2", quat2, (C, 4)), ("normal", normal, (C, 3)), ("h", h, (C,))))
    bad = h < 0
    if bad.any():
        raise InputError(f"contact points: contact {int(np.flatnonzero(bad)[0])}: overlap thickness h < 0")
    a = float(alpha)
    if not (np.isfinite(a) and a >= 0):
        raise InputError(f"contact points: the tolerance alpha must be finite and >= 0, got {alpha!r}")
    return s1, s2, p1, p2, q1, q2, n, h


def touching_counts(tables, shape1, pos1, quat1, shape2, pos2, quat2, normal, h,
                    alpha=DEFAULT_ALPHA):
    """Touching-vertex counts of the two sides of each contact (module
    docstring).

    tables :class:`PointTables`; shape1, shape2 (C,) int shape rows of A = id1
    and B = id2; pos (C, 3) m centre-of-mass positions (the shapes' local
    origins); quat (C, 4) (w, x, y, z) local -> global, need not be
    normalised; normal (C, 3) unit, from A to B; h (C,) m >= 0 the overlap's
    mean thickness V / area; alpha >= 0, delta = alpha h.

    Returns (k1 (C,) int, k2 (C,) int, g (C,) m): the number of A's and B's
    touching vertices (the larger of the counts along n and along the
    partner's face normal closest to n; >= 1 while g + delta >= 0) and the
    penetration g along n (negative when the bodies are apart along n). Raises InputError (one line)
    for bad shapes, indices or non-finite input.

    Parameters
    ----------
    tables : PointTables
        The shapes (:func:`point_tables`).
    shape1, shape2 : array_like of int, shape (C,)
        The shape rows of A = id1 and B = id2.
    pos1, pos2 : array_like, shape (C, 3)
        m, their centre-of-mass positions (the shapes' local origins).
    quat1, quat2 : array_like, shape (C, 4)
        Their orientations (w, x, y, z), local -> global, need not be
        normalised.
    normal : array_like, shape (C, 3)
        Unit contact normals n, from A to B.
    h : array_like, shape (C,)
        m, >= 0, the overlap's mean thickness V / area (overlap volume over
        the area of its shadow on the contact plane).
    alpha : float, optional
        The tolerance alpha >= 0, dimensionless: delta = alpha h (default
        ``DEFAULT_ALPHA`` = 0.1).

    Returns
    -------
    k1, k2 : ndarray of int64, shape (C,)
        The touching-vertex counts of A and B: the vertices within
        g_u + delta of their body's support height along u, the larger
        count of u = n and u = the partner's face normal closest to n.
        delta carries a round-off margin of 1e-9 (max|pos1| + max|pos2| +
        the two radii), so that exactly flush faces count.
    g : ndarray of float64, shape (C,)
        m, the penetration along n, g = max_A (x . n) - min_B (x . n):
        positive for an overlap, negative when the bodies are apart along n.

    Raises
    ------
    InputError
        Bad arrays (:func:`check_pose_arrays`), h < 0, or alpha not finite
        and >= 0; one line.
    """
    s1, s2, p1, p2, q1, q2, n, h = _check(tables, shape1, pos1, quat1, shape2, pos2, quat2, normal, h, alpha)
    C = len(s1)
    k1 = np.empty(C, np.int64)
    k2 = np.empty(C, np.int64)
    g = np.empty(C)
    for a in range(0, C, _BLOCK):
        sl = slice(a, min(a + _BLOCK, C))
        nn, delta = n[sl], alpha * h[sl]
        X1, N1, _ = _posed(tables, s1[sl], p1[sl], q1[sl])
        X2, N2, _ = _posed(tables, s2[sl], p2[sl], q2[sl])
        m1, m2 = tables.mask[s1[sl]], tables.mask[s2[sl]]
        rows = np.arange(len(nn))
        # the face plane of each side closest to the contact plane (no tolerance)
        f1 = N1[rows, np.argmax(np.einsum("ctk,ck->ct", N1, nn), axis=1)]       # A's, along ~ +n
        f2 = -N2[rows, np.argmax(np.einsum("ctk,ck->ct", N2, -nn), axis=1)]     # B's, turned to ~ +n
        # round-off margin (relative to the positions): exactly flush faces count
        eps = 1e-9 * (np.abs(p1[sl]).max(axis=1) + np.abs(p2[sl]).max(axis=1) + tables.radius[s1[sl]]
                      + tables.radius[s2[sl]])
        c1n, c2n, gg = _slab_counts(X1, m1, X2, m2, nn, delta + eps)
        c1f, _, _ = _slab_counts(X1, m1, X2, m2, f2, delta + eps)                # A on B's face
        _, c2f, _ = _slab_counts(X1, m1, X2, m2, f1, delta + eps)                # B on A's face
        k1[sl] = np.maximum(c1n, c1f)
        k2[sl] = np.maximum(c2n, c2f)
        g[sl] = gg
    return k1, k2, g


def _slab_counts(X1, m1, X2, m2, u, tol):
    """Touching counts of A (X1 (C, V, 3), mask m1) and B along the unit
    direction u (C, 3) from A to B: the vertices within g_u + tol (C,) of
    their support planes, g_u the penetration along u. Returns (c1, c2, g_u)."""
    h1 = np.where(m1, np.einsum("cvk,ck->cv", X1, u), -np.inf)
    h2 = np.where(m2, -np.einsum("cvk,ck->cv", X2, u), -np.inf)
    t1, t2 = h1.max(axis=1), h2.max(axis=1)
    gu = t1 + t2
    band = (gu + tol)[:, None]
    return np.sum(t1[:, None] - h1 <= band, axis=1), np.sum(t2[:, None] - h2 <= band, axis=1), gu


def features_of(count):
    """(C,) int8 feature code (contacttypes VERTEX, EDGE, FACE) from a
    touching-vertex count (C,): 1 vertex, 2 edge, 3 or more face.

    Parameters
    ----------
    count : array_like of int, shape (C,)
        Touching-vertex counts (:func:`touching_counts`).

    Returns
    -------
    ndarray of int8, shape (C,)
        VERTEX (0) for a count of 1 (and of 0), EDGE (1) for 2, FACE (2)
        for 3 or more.
    """
    c = np.asarray(count)
    return np.where(c >= 3, FACE, np.where(c == 2, EDGE, VERTEX)).astype(np.int8)


def contact_points(tables, shape1, pos1, quat1, shape2, pos2, quat2, normal, h,
                   alpha=DEFAULT_ALPHA):
    """Contact points of each polyhedra pair, counted from the overlap (module docstring).

    Arguments as :func:`touching_counts`. Returns a dict of (C,) arrays:
    ``points`` int (1; 2; 3 or more: the smaller touching count of a
    face-face pair), ``group`` int8 (SIMPLE, DOUBLE, TRIPLE = 0, 1, 2),
    ``pair`` int8 index into contacttypes.PAIR_TYPES (VV .. FF),
    ``feature1``, ``feature2`` int8 (VERTEX, EDGE, FACE), ``k1``, ``k2``
    the touching-vertex counts and ``g`` m the penetration along n.

    Parameters
    ----------
    tables, shape1, pos1, quat1, shape2, pos2, quat2, normal, h, alpha
        As :func:`touching_counts`: the shapes, (C,) shape rows, (C, 3)
        centres of mass (m), (C, 4) quaternions (w, x, y, z) of A = id1
        and B = id2, (C, 3) unit normals from A to B, (C,) V/area (m) and
        alpha.

    Returns
    -------
    dict of ndarray, each of shape (C,)
        ``points`` int64: LMGC90's number of contact points, 1 for a simple
        pair (a side a vertex, or both edges), 2 for EF, and for FF the
        smaller of the two touching counts (>= 3, a lower bound of the
        intersection's); ``group`` int8: SIMPLE 0, DOUBLE 1 (EF), TRIPLE
        2 (FF); ``pair`` int8: index into contacttypes.PAIR_TYPES;
        ``feature1``, ``feature2`` int8: VERTEX 0, EDGE 1, FACE 2
        (:func:`features_of`); ``k1``, ``k2`` int64: the touching counts;
        ``g`` float64, m: the penetration along n (positive: overlap).

    Raises
    ------
    InputError
        As :func:`touching_counts`.
    """
    k1, k2, g = touching_counts(tables, shape1, pos1, quat1, shape2, pos2, quat2, normal, h, alpha)
    f1, f2 = features_of(k1), features_of(k2)
    pair = pair_types(f1, f2)
    group = np.where(pair == PAIR_TYPES.index("FF"), TRIPLE,
                     np.where(pair == PAIR_TYPES.index("EF"), DOUBLE, SIMPLE)).astype(np.int8)
    points = np.where(group == TRIPLE, np.minimum(k1, k2), group + 1)
    return {"points": points, "group": group, "pair": pair, "feature1": f1, "feature2": f2,
            "k1": k1, "k2": k2, "g": g}


def positive_tolerance(value, what, meaning=""):
    """``value`` as a float; InputError naming ``what`` (and, in brackets,
    ``meaning``) unless it is a finite number > 0.

    Parameters
    ----------
    value : object
        The value to check: a number or anything ``float`` reads (a string
        of a number).
    what : str
        Its name in the message (e.g. "--tolerance").
    meaning : str, optional
        What it means, added in brackets to the message of a value that is
        not finite and > 0 (default: nothing added).

    Returns
    -------
    float
        ``value`` as a float, finite and > 0.

    Raises
    ------
    InputError
        Not a number, not finite (an integer beyond float's range
        included), or <= 0.
    """
    try:
        a = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{what} must be a number, got {value!r}") from None
    except OverflowError:                      # an integer beyond float's range
        raise InputError(f"{what} must be finite and > 0, got {value!r}") from None
    if not (np.isfinite(a) and a > 0):
        raise InputError(f"{what} must be finite and > 0{f' ({meaning})' if meaning else ''}, got {value!r}")
    return a


def check_alpha(alpha, what="--tolerance"):
    """alpha as a float; InputError unless finite and > 0.

    Parameters
    ----------
    alpha : object
        The tolerance alpha (dimensionless, delta = alpha V/area): a number
        or a string of one.
    what : str, optional
        The option's name in the message (default "--tolerance").

    Returns
    -------
    float
        alpha, finite and > 0 (:func:`touching_counts` itself also takes 0).

    Raises
    ------
    InputError
        Not a number, not finite, or <= 0 (:func:`positive_tolerance`).
    """
    return positive_tolerance(alpha, what, "delta = alpha * V/area")
