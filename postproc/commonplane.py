"""Contact points of a pair of convex polyhedra on a common plane: the band count.

:func:`contact_points` (``--types commonplane``) is our earlier band count
described below: the band idea of LMGC90's older route with our own
geometry, kept for the study's earlier numbers; it is not LMGC90's count
(it agrees with it on about 7 pairs in 10). LMGC90's own count, a port of
its CpCundall detection with its three routes, is
:mod:`postproc.lmgc90count`; it shares this module's band tolerance
(:data:`DEFAULT_NEIGHBOR`, :func:`check_neighbor`), Cundall's search
constants and the rule from points to groups and pair types
(:func:`groups_and_pairs`).

The band count. It redoes, from the poses, the steps LMGC90
(``mod_PRPRx.f90``, ``PRPRx_UseCpCundallDetection``) applies to two convex
polyhedra (docs/lmgc90-contacts.md has the source lines). For A (id1,
LMGC90's antagonist) and B (id2, the candidate) and a start direction n
from A to B (the contact normal):

1. Visible vertices (``compute_shadow_overlap``): the vertices of A's
   triangles whose outward normal m has m . n >= -1e-3, and of B's with
   m . n <= 1e-3 (the faces turned towards the partner, to 90.06 deg).
2. Common plane (``compute_cundall_common_plane``, Cundall's iteration): n is
   turned so as to maximise the gap g(n) = min_B (x . n) - max_A (x . n)
   over the visible vertices: eight trial normals cos(theta) n + sin(theta)
   t_k (t_k every 45 deg in the plane), the best one kept while it raises
   the gap by at least 1e-6 of the smaller body radius; theta halves from
   0.087 rad (5 deg) until it is below 0.0017 rad; at most ``iterations``
   rounds (LMGC90's default 100). For overlapping convex bodies the common
   plane is the direction of least penetration. Its point c is the
   midpoint of the two extreme vertices (A's highest, B's lowest along n).
3. The band (the ``cundall_neighbor`` test): a vertex of A is kept when
   (x - c) . n >= -d1, one of B when (x - c) . n <= d1, with

       d1 = max(0, g / 2) + tau * ref,       tau = 0.1 (``DEFAULT_NEIGHBOR``),

   ref the smaller of the two bodies' distances from their centre of mass
   to their extreme vertex (``reference="vertex"``, the form of the older
   ``compute_cundall_common_plane_old``; ``"normal"``: the same distances
   measured along n, today's routine). Measured from a body's own support
   plane the band is tau ref + max(0, -g) / 2: a fixed fraction of the
   particle size (ref <= d / 2, d = 2 x the largest centre-vertex distance),
   plus half the interpenetration, which is nil in contact dynamics.
4. Contact points (``planplan``): the kept vertices of each side are
   projected on the common plane, their convex hulls (a point, a segment or
   a polygon) are intersected, and the vertices of the intersection are
   the contact points, at most 4 (LMGC90 keeps 4 of a larger polygon).
   Points closer than ``MERGE`` * ref are one point (the older
   ``polytopes_intersection``: squared distances below 1e-4 ref^2).

So 1 point for a vertex on a face and crossed edges, 2 for an edge on a
face (or two parallel edges lying on each other), 3 or 4 for face on face;
a vertex on a vertex or on an edge gives a point only when the projections
meet within the merge distance, else 0 (LMGC90 then makes no contact).
The group is the paper's: simple (0 or 1 point), double (2), triple (3+).
The features follow today's LMGC90 labels (``DETECTION_COMMON_PLANE``, the
``cd_status`` / ``an_status`` stage): 1 kept vertex = vertex, 2 joined by an
edge = edge (else vertex), 3 or more = face; the pair type (VV .. FF) is
made to agree with the group as in :func:`postproc.classify.reconcile`:
triple -> FF, double -> EF, simple -> VF when a side is a face, else the
features' type.

Pure functions over arrays; no file I/O. Blocks of contacts are vectorised
for steps 1-3; step 4 loops over contacts (a few polygons each).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from shapes.overlap import rotation_matrices

from .contactpoints import (
    DOUBLE,
    SIMPLE,
    TRIPLE,
    check_pose_arrays,
    point_tables,
    positive_tolerance,
)
from .contacttypes import EDGE, FACE, PAIR_TYPES, VERTEX, pair_types
from .errors import InputError
from .polygons import MAX_POINTS, _cross2

DEFAULT_NEIGHBOR = 0.1        # LMGC90 cundall_neighbor (mod_PRPRx.f90)
DEFAULT_ITERATIONS = 100      # LMGC90 cundall_iter default; scripts pass 100-300
THETA_MAX = 0.087             # cundall_theta_max, rad (5 deg)
THETA_MIN = 0.0017            # cundall_theta_min, rad (0.1 deg)
GAP_TOL = 1e-6                # cundall_gap, relative to the smaller body radius
VISIBLE_TOL = 1e-3            # tol_normales of compute_shadow_overlap
MERGE = 1e-2                  # coincident projected points, in units of ref
REFERENCES = ("vertex", "normal")
NB_ROT = 8                    # cundall: trial normals per round (LMGC90's nb_rot)
BLOCK = 1 << 10               # contacts per vectorised block
_FF, _EF, _VF = PAIR_TYPES.index("FF"), PAIR_TYPES.index("EF"), PAIR_TYPES.index("VF")


@dataclass
class PlaneTables:
    """Per-shape geometry for the common-plane count, padded to the largest
    shape. vertices (S, V, 3) m local frame (origin = centre of mass);
    mask (S, V) bool; tri (S, T, 3) int vertex indices (padded with the
    first triangle); tri_normals (S, T, 3) unit outward; tri_mask (S, T)
    bool; adjacent (S, V, V) bool, True where two vertices share a triangle
    edge; radius (S,) m the largest vertex distance.

    Attributes
    ----------
    vertices : ndarray of float64, shape (S, V, 3)
        m, local frame (origin at the centre of mass), padded with 0.
    mask : ndarray of bool, shape (S, V)
        True for a vertex, False for padding.
    tri : ndarray of int64, shape (S, T, 3)
        Each shape's triangles (vertex indices), padded with its first.
    tri_normals : ndarray of float64, shape (S, T, 3)
        Unit outward triangle normals (padding: the first triangle's).
    tri_mask : ndarray of bool, shape (S, T)
        True for a triangle, False for padding.
    adjacent : ndarray of bool, shape (S, V, V)
        True where two vertices share a triangle edge (the diagonals inside
        a polygonal face included).
    radius : ndarray of float64, shape (S,)
        m, the largest centre-to-vertex distance of each shape.
    """

    vertices: np.ndarray
    mask: np.ndarray
    tri: np.ndarray
    tri_normals: np.ndarray
    tri_mask: np.ndarray
    adjacent: np.ndarray
    radius: np.ndarray


def plane_tables(vertices, triangles):
    """:class:`PlaneTables` from per-shape vertices (V_s, 3) m and outward
    triangles (T_s, 3), as in a dump's ``/shapes``. Raises InputError (one
    line) for bad shapes (the checks of
    :func:`postproc.contactpoints.point_tables`).

    Parameters
    ----------
    vertices : sequence of array_like, each of shape (V_s, 3)
        m, each shape's vertices in its local frame.
    triangles : sequence of array_like of int, each of shape (T_s, 3)
        Each shape's outward (counter-clockwise seen from outside)
        triangles.

    Returns
    -------
    PlaneTables
        The padded tables of the S shapes.

    Raises
    ------
    InputError
        Bad shapes, as said above.
    """
    pt = point_tables(vertices, triangles)
    S, V = pt.mask.shape
    T = max(len(t) for t in triangles)
    tri = np.zeros((S, T, 3), np.int64)
    tmask = np.zeros((S, T), bool)
    adj = np.zeros((S, V, V), bool)
    for s, t in enumerate(triangles):
        t = np.asarray(t, np.int64)
        tri[s, :len(t)], tri[s, len(t):] = t, t[0]
        tmask[s, :len(t)] = True
        for a, b in ((0, 1), (1, 2), (2, 0)):
            adj[s, t[:, a], t[:, b]] = adj[s, t[:, b], t[:, a]] = True
    return PlaneTables(pt.vertices, pt.mask, tri, pt.plane_normals, tmask, adj, pt.radius)


def _check(tables, shape1, pos1, quat1, shape2, pos2, quat2, normal, neighbor, reference, iterations, alert):
    C = len(np.asarray(shape1))
    checked = check_pose_arrays("common plane", tables.vertices.shape[0], (
        ("shape1", shape1, (C,)), ("shape2", shape2, (C,)), ("pos1", pos1, (C, 3)), ("pos2", pos2, (C, 3)),
        ("quat1", quat1, (C, 4)), ("quat2", quat2, (C, 4)), ("normal", normal, (C, 3))))
    check_neighbor(neighbor)
    check_reference(reference)
    if not (isinstance(iterations, (int, np.integer)) and iterations >= 0):
        raise InputError(f"common plane: iterations must be an integer >= 0, got {iterations!r}")
    if alert is not None and not np.isfinite(float(alert)):
        raise InputError(f"common plane: the alert distance must be finite, got {alert!r}")
    return tuple(checked)


def check_neighbor(tau, what="common plane: the band tolerance tau"):
    """tau as a float; InputError unless finite and > 0.

    Parameters
    ----------
    tau : object
        The band tolerance tau (dimensionless, in units of ref; LMGC90's
        ``cundall_neighbor``): a number or a string of one.
    what : str, optional
        Its name in the message.

    Returns
    -------
    float
        tau, finite and > 0.

    Raises
    ------
    InputError
        Not a number, not finite, or <= 0.
    """
    return positive_tolerance(tau, what)


def check_reference(reference):
    """reference unchanged; InputError (one line) unless one of REFERENCES.

    Parameters
    ----------
    reference : str
        How the band's ref is measured: "vertex" (centre to extreme vertex)
        or "normal" (that distance along the common plane's normal).

    Returns
    -------
    str
        ``reference``, one of ``REFERENCES``.

    Raises
    ------
    InputError
        Any other value.
    """
    if reference not in REFERENCES:
        raise InputError(f"common plane: reference must be one of {', '.join(REFERENCES)}, got {reference!r}")
    return reference


def _perpendicular(n):
    """(C, 3) unit vectors perpendicular to the unit rows of n."""
    a = np.where((np.abs(n[:, 0]) < 0.9)[:, None], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    t = a - np.sum(a * n, axis=1)[:, None] * n
    return t / np.linalg.norm(t, axis=1)[:, None]


def _extremes(XA, vA, XB, vB, n):
    """A's highest and B's lowest visible vertex along n (C, 3) and the gap."""
    hA = np.where(vA, np.einsum("cvk,ck->cv", XA, n), -np.inf)
    hB = np.where(vB, np.einsum("cvk,ck->cv", XB, n), np.inf)
    return hA.argmax(axis=1), hB.argmin(axis=1), hB.min(axis=1) - hA.max(axis=1)


def cundall_plane(XA, vA, XB, vB, n0, rsize, iterations=DEFAULT_ITERATIONS):
    """Cundall's common plane (module docstring, step 2).

    XA (C, V, 3), XB global vertices m; vA, vB (C, V) bool the visible
    ones; n0 (C, 3) unit start normals from A to B; rsize (C,) m the
    smaller body radius (the convergence scale). Returns (n (C, 3) unit,
    gap (C,) m, iA (C,) A's highest vertex, iB (C,) B's lowest).

    Parameters
    ----------
    XA, XB : ndarray, shape (C, V, 3)
        m, the global vertices of A (id1) and B (id2), padded to V.
    vA, vB : ndarray of bool, shape (C, V)
        Their visible vertices (padding False).
    n0 : ndarray, shape (C, 3)
        The unit start normals, from A to B.
    rsize : ndarray, shape (C,)
        m, the smaller body radius of each pair: a trial is accepted when
        it raises the gap by at least ``GAP_TOL`` * rsize.
    iterations : int, optional
        The most rounds of eight trials (default ``DEFAULT_ITERATIONS`` =
        100); 0 keeps n0.

    Returns
    -------
    n : ndarray, shape (C, 3)
        The common plane's unit normal, from A to B.
    gap : ndarray, shape (C,)
        m, g(n) = min_B (x . n) - max_A (x . n) over the visible vertices:
        positive when the bodies are apart, negative for an
        interpenetration.
    iA, iB : ndarray of int, shape (C,)
        The vertex indices (into V) of A's highest and B's lowest visible
        vertex along n.
    """
    n = n0.copy()
    C = len(n)
    rows = np.arange(C)
    iA, iB, gap = _extremes(XA, vA, XB, vB, n)
    # the first tangent: from B's lowest to A's highest vertex, in the plane
    p = XA[rows, iA] - XB[rows, iB]
    t = p - np.sum(p * n, axis=1)[:, None] * n
    tn = np.linalg.norm(t, axis=1)
    small = tn < 1e-6 * rsize
    t = np.where(small[:, None], _perpendicular(n), t / np.where(small, 1.0, tn)[:, None])
    theta = np.full(C, THETA_MAX)
    active = np.ones(C, bool)
    phis = 2 * np.pi * np.arange(1, NB_ROT + 1) / NB_ROT
    for _ in range(iterations):
        if not active.any():
            break
        a = np.flatnonzero(active)
        na, ta = n[a], t[a]
        sa = np.cross(ta, na)
        tk = np.cos(phis)[None, :, None] * ta[:, None, :] + np.sin(phis)[None, :, None] * sa[:, None, :]
        nk = np.cos(theta[a])[:, None, None] * na[:, None, :] + np.sin(theta[a])[:, None, None] * tk
        nk /= np.linalg.norm(nk, axis=2)[:, :, None]
        hA = np.where(vA[a][:, :, None], np.einsum("cvj,ckj->cvk", XA[a], nk), -np.inf).max(axis=1)
        hB = np.where(vB[a][:, :, None], np.einsum("cvj,ckj->cvk", XB[a], nk), np.inf).min(axis=1)
        gk = hB - hA                                               # (A, 8)
        best = gk.argmax(axis=1)
        gbest = gk[np.arange(len(a)), best]
        accept = (gbest > gap[a]) & ((gbest - gap[a]) / rsize[a] >= GAP_TOL)
        acc = a[accept]
        n[acc] = nk[accept, best[accept]]
        tt = tk[accept, best[accept]]
        tt -= np.sum(tt * n[acc], axis=1)[:, None] * n[acc]
        t[acc] = tt / np.linalg.norm(tt, axis=1)[:, None]
        gap[acc] = gbest[accept]
        rej = a[~accept]
        done = theta[rej] < THETA_MIN
        theta[rej] *= 0.5
        active[rej[done]] = False
    iA, iB, gap = _extremes(XA, vA, XB, vB, n)
    return n, gap, iA, iB


def _posed(tables, shape, pos, quat):
    R = rotation_matrices(quat)
    X = np.einsum("cij,cvj->cvi", R, tables.vertices[shape]) + pos[:, None, :]
    N = np.einsum("cij,ctj->cti", R, tables.tri_normals[shape])
    return X, N


def _visible(tables, shape, N, n, sign):
    """(C, V) bool: vertices of the triangles turned to the partner
    (sign * m . n >= -VISIBLE_TOL)."""
    ok = (sign * np.einsum("ctk,ck->ct", N, n) >= -VISIBLE_TOL) & tables.tri_mask[shape]
    C, V = len(shape), tables.mask.shape[1]
    vis = np.zeros((C, V), bool)
    tri = tables.tri[shape]                                        # (C, T, 3)
    rows = np.broadcast_to(np.arange(C)[:, None, None], tri.shape)
    vis[rows[ok], tri[ok]] = True
    return vis & tables.mask[shape]


def _hull(P, tol):
    """Convex hull of 2-D points P (k, 2), as a point (1, 2), a segment
    (2, 2) or a counter-clockwise polygon (m >= 3, 2) without vertices
    closer than tol or within tol of the line of their neighbours."""
    P = np.unique(np.round(P, 15), axis=0)
    if len(P) > 2:
        def half(pts):
            h = []
            for p in pts:
                while len(h) >= 2 and _cross2(h[-1] - h[-2], p - h[-2]) <= 0:
                    h.pop()
                h.append(p)
            return h
        lo, hi = half(P), half(P[::-1])
        P = np.array(lo[:-1] + hi[:-1])
    # drop near-duplicates and near-collinear vertices (distance < tol)
    changed = True
    while changed and len(P) > 2:
        changed = False
        m = len(P)
        for i in range(m):
            a, b, c = P[i - 1], P[i], P[(i + 1) % m]
            ac = c - a
            L = np.linalg.norm(ac)
            if np.linalg.norm(b - a) < tol or (L > 0 and abs(_cross2(ac, b - a)) / L < tol):
                P = np.delete(P, i, axis=0)
                changed = True
                break
    if len(P) == 2 and np.linalg.norm(P[1] - P[0]) < tol:
        P = P[:1]
    if len(P) > 2 and max(np.linalg.norm(P - P[0], axis=1)) < tol:
        P = P[:1]
    return P


def _clip(poly, a, b, tol):
    """Sutherland-Hodgman: the part of the convex polygon / segment / point
    ``poly`` (k, 2) on the left of the directed line a -> b, within tol."""
    e = b - a
    L = np.linalg.norm(e)
    side = (e[0] * (poly[:, 1] - a[1]) - e[1] * (poly[:, 0] - a[0])) / L     # > 0 left
    if len(poly) == 1:
        return poly if side[0] >= -tol else poly[:0]
    out = []
    m = len(poly)
    closed = m > 2
    for i in range(m if closed else 1):
        j = (i + 1) % m
        p, q, sp, sq = poly[i], poly[j], side[i], side[j]
        if sp >= -tol:
            out.append(p)
        if (sp >= -tol) != (sq >= -tol):
            s = sp / (sp - sq)
            out.append(p + s * (q - p))
        if not closed and sq >= -tol:
            out.append(q)
    return np.array(out).reshape(-1, 2)


def _intersection_points(HA, HB, tol):
    """Number of distinct vertices of the intersection of two convex hulls
    (points, segments or polygons from :func:`_hull`), merged within tol."""
    if len(HA) < len(HB):
        HA, HB = HB, HA
    if len(HA) >= 3:
        R = HB
        m = len(HA)
        for i in range(m):
            R = _clip(R, HA[i], HA[(i + 1) % m], tol)
            if not len(R):
                return 0
        return len(_hull(R, tol))
    if len(HA) == 1:                                               # point and point
        return int(np.linalg.norm(HA[0] - HB[0]) <= tol)
    a, b = HA
    e = b - a
    L = np.linalg.norm(e)
    u = e / L
    if len(HB) == 1:                                               # segment and point
        w = HB[0] - a
        s = w @ u
        return int(abs(u[0] * w[1] - u[1] * w[0]) <= tol and -tol <= s <= L + tol)
    c, d = HB                                                      # segment and segment
    dc, dd = c - a, d - a
    hc, hd = u[0] * dc[1] - u[1] * dc[0], u[0] * dd[1] - u[1] * dd[0]
    if abs(hc) <= tol and abs(hd) <= tol:                          # on one line: the overlap
        lo, hi = max(0.0, min(dc @ u, dd @ u)), min(L, max(dc @ u, dd @ u))
        if hi < lo - tol:
            return 0
        return 1 if hi - lo < tol else 2
    if (hc > tol and hd > tol) or (hc < -tol and hd < -tol):
        return 0
    s = hc / (hc - hd) if hc != hd else 0.0
    x = c + s * (d - c)
    return int(-tol <= (x - a) @ u <= L + tol)


def contact_points(tables, shape1, pos1, quat1, shape2, pos2, quat2, normal,
                   neighbor=DEFAULT_NEIGHBOR, reference="vertex", iterations=DEFAULT_ITERATIONS,
                   alert=None):
    """Common-plane contact points of each polyhedra pair by the band count
    (module docstring; LMGC90's kind of detection, not its own count, which
    is :func:`postproc.lmgc90count.lmgc90_points`).

    tables :class:`PlaneTables`; shape1, shape2 (C,) int shape rows of A =
    id1 and B = id2; pos (C, 3) m centre-of-mass positions (the shapes'
    local origins); quat (C, 4) (w, x, y, z) local -> global, need not be
    normalised; normal (C, 3) unit, from A to B, the start of Cundall's
    search (``iterations=0`` keeps it as the common plane); neighbor tau > 0
    (the band is tau * ref); reference "vertex" or "normal" (how ref is
    measured); alert: LMGC90's alert distance (m), pairs whose gap exceeds
    it get 0 points (None: no test).

    Returns a dict of (C,) arrays: ``points`` int (0..4, the band count),
    ``group`` int8 (SIMPLE, DOUBLE, TRIPLE = 0, 1, 2; 0 or 1 point is
    simple), ``pair`` int8 index into contacttypes.PAIR_TYPES, agreeing
    with the group, ``feature1``, ``feature2`` int8 (VERTEX, EDGE, FACE),
    ``k1``, ``k2`` the kept vertices of A and B, ``gap`` m (negative:
    interpenetration), ``band`` m (d1 - max(0, g/2) = tau ref), and
    ``normal`` (C, 3) the common plane's normal. Raises InputError (one
    line) for bad shapes, indices or non-finite input.

    Parameters
    ----------
    tables : PlaneTables
        The shapes (:func:`plane_tables`).
    shape1, shape2 : array_like of int, shape (C,)
        The shape rows of A = id1 and B = id2.
    pos1, pos2 : array_like, shape (C, 3)
        m, their centre-of-mass positions.
    quat1, quat2 : array_like, shape (C, 4)
        Their orientations (w, x, y, z), local -> global.
    normal : array_like, shape (C, 3)
        Unit contact normals, from A to B (the search's start).
    neighbor : float, optional
        tau > 0, dimensionless (default ``DEFAULT_NEIGHBOR`` = 0.1).
    reference : {"vertex", "normal"}, optional
        How ref is measured (default "vertex").
    iterations : int, optional
        Rounds of Cundall's search, >= 0 (default 100).
    alert : float or None, optional
        m, the alert distance (default None: no test).

    Returns
    -------
    dict
        (C,) arrays ``points`` int64 (0..4), ``group`` int8 (SIMPLE 0,
        DOUBLE 1, TRIPLE 2), ``pair`` int8, ``feature1``, ``feature2`` int8
        (1 kept vertex VERTEX, 2 joined by a triangle edge EDGE, else
        VERTEX, 3+ FACE), ``k1``, ``k2`` int64, ``gap`` float64 m (positive:
        apart), ``band`` float64 m (tau ref), and ``normal`` (C, 3) unit,
        from A to B. A pair over the alert distance keeps its features,
        counts, gap and normal, with 0 points.

    Raises
    ------
    InputError
        As said above, a bad tau or reference, iterations not an integer
        >= 0, or a non-finite alert distance.
    """
    s1, s2, p1, p2, q1, q2, n0 = _check(tables, shape1, pos1, quat1, shape2, pos2, quat2, normal,
                                        neighbor, reference, iterations, alert)
    tau = float(neighbor)
    C = len(s1)
    res = {k: np.zeros(C, np.int64) for k in ("points", "k1", "k2")}
    res.update({"gap": np.zeros(C), "band": np.zeros(C), "normal": np.zeros((C, 3)),
                "feature1": np.zeros(C, np.int8), "feature2": np.zeros(C, np.int8)})
    for a0 in range(0, C, BLOCK):
        sl = slice(a0, min(a0 + BLOCK, C))
        XA, NA = _posed(tables, s1[sl], p1[sl], q1[sl])
        XB, NB = _posed(tables, s2[sl], p2[sl], q2[sl])
        nn = n0[sl] / np.linalg.norm(n0[sl], axis=1)[:, None]
        vA = _visible(tables, s1[sl], NA, nn, +1.0)
        vB = _visible(tables, s2[sl], NB, nn, -1.0)
        rsize = np.minimum(tables.radius[s1[sl]], tables.radius[s2[sl]])
        n, gap, iA, iB = cundall_plane(XA, vA, XB, vB, nn, rsize, iterations)
        rows = np.arange(len(n))
        xa, xb = XA[rows, iA], XB[rows, iB]
        c = 0.5 * (xa + xb)
        if reference == "vertex":
            ref = np.minimum(np.linalg.norm(xa - p1[sl], axis=1), np.linalg.norm(xb - p2[sl], axis=1))
        else:
            ref = np.minimum(np.abs(np.sum((xa - p1[sl]) * n, axis=1)),
                             np.abs(np.sum((xb - p2[sl]) * n, axis=1)))
        d1 = np.maximum(0.0, 0.5 * gap) + tau * ref
        hA = np.einsum("cvk,ck->cv", XA - c[:, None, :], n)
        hB = np.einsum("cvk,ck->cv", XB - c[:, None, :], n)
        kA = vA & (hA >= -d1[:, None])
        kB = vB & (hB <= d1[:, None])
        kA[rows, iA] = True
        kB[rows, iB] = True
        e1 = _perpendicular(n)
        e2 = np.cross(n, e1)
        for i in range(len(n)):
            ci = a0 + i
            fa, fb = np.flatnonzero(kA[i]), np.flatnonzero(kB[i])
            res["k1"][ci], res["k2"][ci] = len(fa), len(fb)
            res["feature1"][ci] = _feature(tables.adjacent[s1[ci]], fa)
            res["feature2"][ci] = _feature(tables.adjacent[s2[ci]], fb)
            if alert is not None and gap[i] > float(alert):
                continue
            tol = MERGE * ref[i]
            B2 = np.stack([e1[i], e2[i]], 1)
            HA = _hull((XA[i, fa] - c[i]) @ B2, tol)
            HB = _hull((XB[i, fb] - c[i]) @ B2, tol)
            res["points"][ci] = min(MAX_POINTS, _intersection_points(HA, HB, tol))
        res["gap"][sl], res["band"][sl], res["normal"][sl] = gap, tau * ref, n
    res["group"], res["pair"] = groups_and_pairs(res["points"], res["feature1"], res["feature2"])
    return res


def groups_and_pairs(points, f1, f2):
    """(group, pair) from the number of contact points (C,) and the two
    sides' features (C,): the group (SIMPLE for 0 or 1 point, DOUBLE for 2,
    TRIPLE for 3+, int8) and the pair type (int8 index into PAIR_TYPES)
    made to agree with it: triple -> FF, double -> EF, simple -> VF when a
    side is a face, else the features' type.

    Parameters
    ----------
    points : array_like of int, shape (C,)
        The number of contact points of each pair.
    f1, f2 : array_like of int, shape (C,)
        The two sides' features (VERTEX 0, EDGE 1, FACE 2).

    Returns
    -------
    group : ndarray of int8, shape (C,)
        The paper's group: SIMPLE 0 (0 or 1 point), DOUBLE 1 (2), TRIPLE 2
        (3 or more).
    pair : ndarray of int8, shape (C,)
        The index into PAIR_TYPES of the pair type agreeing with the group
        (as :func:`postproc.classify.reconcile`).
    """
    pts = np.asarray(points)
    group = np.where(pts >= 3, TRIPLE, np.where(pts == 2, DOUBLE, SIMPLE)).astype(np.int8)
    pair = pair_types(f1, f2).astype(np.int8)
    face = (np.asarray(f1) == FACE) | (np.asarray(f2) == FACE)
    pair[group == TRIPLE] = _FF
    pair[group == DOUBLE] = _EF
    pair[(group == SIMPLE) & face] = _VF
    return group, pair


def _feature(adjacent, idx):
    """VERTEX, EDGE (two kept vertices joined by an edge) or FACE (3+)."""
    if len(idx) >= 3:
        return FACE
    if len(idx) == 2 and adjacent[idx[0], idx[1]]:
        return EDGE
    return VERTEX
