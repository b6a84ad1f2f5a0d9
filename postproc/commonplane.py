"""Contact points of a pair of convex polyhedra on a common plane: two counts.

* :func:`lmgc90_points` (``--types lmgc90`` and ``lmgc90-planplan``) is
  LMGC90's own count: a step-by-step port of its CpCundall detection (shadow
  overlap, Cundall's plane as LMGC90 iterates it, its face topology, and
  either today's point stage or the older planplan one); it gives LMGC90's
  compiled count on 99 % of the grain pairs of our packings
  (docs/lmgc90-contacts.md, tests/test_lmgc90_fixtures.py). Its third route,
  ``--types lmgc90-2009``, is planplan with the length-tolerant intersection
  LMGC90 used before Clipper2 (:func:`tolerant_intersection`, written from
  its description; no compiled LMGC90 of that age was run to check it).
* :func:`contact_points` (``--types commonplane``) is the earlier band count
  described below: the band idea of LMGC90's older route with our own
  geometry, kept for the study's earlier numbers; it is not LMGC90's count
  (it agrees with it on about 7 pairs in 10).

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

import math
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

DEFAULT_NEIGHBOR = 0.1        # LMGC90 cundall_neighbor (mod_PRPRx.f90)
DEFAULT_ITERATIONS = 100      # LMGC90 cundall_iter default; scripts pass 100-300
THETA_MAX = 0.087             # cundall_theta_max, rad (5 deg)
THETA_MIN = 0.0017            # cundall_theta_min, rad (0.1 deg)
GAP_TOL = 1e-6                # cundall_gap, relative to the smaller body radius
VISIBLE_TOL = 1e-3            # tol_normales of compute_shadow_overlap
MERGE = 1e-2                  # coincident projected points, in units of ref
MAX_POINTS = 4
REFERENCES = ("vertex", "normal")
_NB_ROT = 8
_BLOCK = 1 << 10
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
    phis = 2 * np.pi * np.arange(1, _NB_ROT + 1) / _NB_ROT
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


def _cross2(u, v):
    """z component of the cross product of two 2-D vectors."""
    return u[0] * v[1] - u[1] * v[0]


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
    is :func:`lmgc90_points`).

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
    for a0 in range(0, C, _BLOCK):
        sl = slice(a0, min(a0 + _BLOCK, C))
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


# ============================================================================
# LMGC90's own count: its CpCundall detection, point stage and all
# ============================================================================
#
# The functions below port, step by step, what LMGC90's
# ``wcp_compute_contact_PRPRx`` does for one pair of convex POLYR bodies
# (``DETECTION_COMMON_PLANE`` of ``mod_PRPRx.f90``, with the geometry of
# ``mod_DiscreteGeometry.f90`` and the face topology of ``mod_POLYR.f90``),
# so that the count is LMGC90's, not a count of the same idea. Three routes:
# ``"lmgc90"`` (today's default point stage, ``new_ccpm = .true.``),
# ``"lmgc90-planplan"`` (the older route, ``use_old_ccpm_PRPRx``) and
# ``"lmgc90-2009"`` (the older route with the length-tolerant intersection
# planplan used before Clipper2, :func:`tolerant_intersection`; presumably
# the paper's, not checked against a 2009 LMGC90).

LMGC90_ROUTES = ("lmgc90", "lmgc90-planplan", "lmgc90-2009")
DEFAULT_ALERT = 0.1           # alert distance, in units of the smallest grain radius (LMGC90's examples)
LMGC90_ITERATIONS = 200       # cundall_iter: the compas_lmgc90 glue's value (LMGC90's module default: 100)
TOPO_ANGLE = 5.0              # deg, POLYR topo_angle: adjacent triangles closer than this form one face
F2F_TOL = 1e-3                # f2f_tol: a face is "seen" when 1 - cos(face, plane) <= this (2.6 deg)
TOL_ANGLE = 1e-2              # tol_angle: a point is kept when 1 - cos(its normal, plane) <= this (8.1 deg)
CLIP_EPS = 1e-8               # Clipper2 precision of polytopes_intersection_wc (8 decimals of the length unit)
TOL_2009 = 1e-2               # lmgc90-2009: the intersection's length tolerance, in units of the band's ref
_TOL_NORMALES = 1e-3          # compute_shadow_overlap
# LMGC90 writes these as default-real (single precision) literals in
# double-precision variables: their values are the float32 roundings
_F32 = lambda x: float(np.float32(x))
_LMGC_THETA_MAX = _F32(0.087)         # cundall_theta_max = 0.087
_LMGC_THETA_MIN = _F32(0.0017)        # cundall_theta_min = 0.0017
_LMGC_F2F_TOL = _F32(F2F_TOL)         # f2f_tol = 1e-3
_LMGC_PARALLEL = _F32(1e-6)           # edgetoedge_distance's tol = 1e-6
_LMGC_PI = _F32(math.pi)              # PI_g = 3.14159265358979323846 (mod_overall)


@dataclass
class LmgcShape:
    """One shape as LMGC90's POLYR sees it (local frame, origin at the
    centre of mass). vertices (V, 3) m; triangles (T, 3) outward;
    normals (T, 3) unit outward triangle normals; faces: list of (k,)
    triangle indices, the topological faces (adjacent triangles within
    TOPO_ANGLE, merged); face_normal (F, 3) the normal of each face's first
    triangle; contour: list of (m,) the corner vertices (``sommet``) along
    each face's contour, counter-clockwise seen from outside; corner (V,)
    bool the vertices shared by 3+ faces (``f2f_sommet``); edges (E, 2) the
    topological edges (pairs of consecutive corners along a contour, lower
    index first, ``f2f_edge``); radius m the largest centre-vertex
    distance; min_radius_face m the smallest triangle circumradius.

    Attributes
    ----------
    vertices : ndarray, shape (V, 3)
        m, local frame, origin at the centre of mass.
    triangles : ndarray of int64, shape (T, 3)
        Vertex indices, each oriented so that its normal points away from
        the centre (as POLYR fixes it).
    normals : ndarray, shape (T, 3)
        Unit outward triangle normals, (s2 - s3) x (s2 - s1) normalised
        (LMGC90's ``compute_info_triangle``).
    faces : list of ndarray of int
        The triangle indices of each of the F topological faces.
    face_normal : ndarray, shape (F, 3)
        The unit normal of each face's first triangle.
    contour : list of ndarray of int
        The corner vertices along each face's contour (``sommet``).
    corner : ndarray of bool, shape (V,)
        True for a vertex on the contours of 3 or more faces (``f2f_sommet``).
    edges : ndarray of int64, shape (E, 2)
        The topological edges, lower index first (``f2f_edge``).
    edge_set : set of tuple
        The same edges as (i, j) pairs, i < j, for lookup.
    radius : float
        m, the largest centre-vertex distance.
    min_radius_face : float
        m, the smallest triangle outer radius (half the longest side of an
        obtuse or flat triangle, else the circumradius).
    """

    vertices: np.ndarray
    triangles: np.ndarray
    normals: np.ndarray
    faces: list
    face_normal: np.ndarray
    contour: list
    corner: np.ndarray
    edges: np.ndarray
    edge_set: set
    radius: float
    min_radius_face: float


def _triangle_normals(S1, S2, S3):
    """LMGC90's compute_info_triangle normals: (s2 - s3) x (s2 - s1), unit;
    (T, 3) from the corners (T, 3) each."""
    n = np.cross(S2 - S3, S2 - S1)
    return n / np.linalg.norm(n, axis=1)[:, None]


def _circumradii(S1, S2, S3):
    """compute_info_triangle's outer radius of each triangle (T,): half the
    longest side for an obtuse triangle, else the circumradius."""
    v1, v2, v3 = S2 - S3, S1 - S3, S2 - S1
    l = np.stack([np.linalg.norm(v1, axis=1), np.linalg.norm(v2, axis=1), np.linalg.norm(v3, axis=1)], 1)
    hp = 0.5 * l.sum(axis=1)
    surf = np.sqrt(np.maximum(hp * (hp - l[:, 0]) * (hp - l[:, 1]) * (hp - l[:, 2]), 0.0))
    c = np.stack([np.einsum("ij,ij->i", -v2, v3), np.einsum("ij,ij->i", -v3, -v1),
                  np.einsum("ij,ij->i", v1, v2)], 1)
    obtuse = (c.min(axis=1) < 0) | (surf == 0)
    return np.where(obtuse, 0.5 * l.max(axis=1), l.prod(axis=1) / (4 * np.where(surf == 0, 1.0, surf)))


def lmgc90_shape(vertices, triangles):
    """:class:`LmgcShape` of one polyhedron: vertices (V, 3) m in the local
    frame (origin at the centre of mass), triangles (T, 3) outward
    counter-clockwise. The topology is LMGC90's ``build_topology_surface_T3``
    (topo angle 5 deg).

    It does not check the surface: an open or otherwise bad surface gives a
    meaningless topology, no error (:func:`lmgc90_tables` runs the checks
    of :func:`postproc.contactpoints.point_tables` first, which do not test
    closedness either).

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        m, the vertices in the local frame, origin at the centre of mass.
    triangles : array_like of int, shape (T, 3)
        Vertex indices of a closed triangulated surface (triangles whose
        normal points towards the centre are turned over).

    Returns
    -------
    LmgcShape
        The shape with its triangle normals, topological faces, contours,
        corners and edges.
    """
    V = np.asarray(vertices, float)
    T = np.asarray(triangles, np.int64)
    nT = len(T)
    normals = _triangle_normals(V[T[:, 0]], V[T[:, 1]], V[T[:, 2]])
    # orientation as POLYR fixes it: outward with respect to the centre
    flip = np.einsum("ij,ij->i", V[T[:, 0]], normals) <= 0
    if flip.any():
        T = T.copy()
        T[flip] = T[flip][:, [0, 2, 1]]
        normals[flip] = -normals[flip]
    # the neighbour across each edge (edge ic joins corners ic and ic + 1)
    TL = T.tolist()
    owner = {}
    for ie, t in enumerate(TL):
        for ic in range(3):
            owner.setdefault((t[ic], t[(ic + 1) % 3]), []).append(ie)
    adj = []
    for ie, t in enumerate(TL):
        row = []
        for ic in range(3):
            a, b = t[ic], t[(ic + 1) % 3]
            other = [je for je in owner.get((b, a), []) + owner.get((a, b), []) if je != ie]
            if other:
                row.append(min(other))
        adj.append(row)
    tol_topo = np.cos(np.radians(TOPO_ANGLE))
    dots = normals @ normals.T
    belong = np.arange(nT)
    skip = np.zeros(nT, bool)
    for ie in range(nT - 1):
        if skip[ie]:
            continue
        skip[ie] = True
        todo = [ie]
        while todo:
            nxt = []
            for je in todo:
                for ke in adj[je]:
                    if skip[ke] or ke in nxt:
                        continue
                    if dots[je, ke] > tol_topo:
                        nxt.append(ke)
                        skip[ke] = True
                        belong[ke] = ie
            todo = nxt
    faces = [np.flatnonzero(belong == ie) for ie in range(nT) if belong[ie] == ie]
    nface = len(faces)
    starts = np.zeros(len(V), np.int64)
    contours = []
    for f in faces:
        fs = set(f.tolist())
        border = []
        for ie in f.tolist():
            for je in adj[ie]:
                if je in fs:
                    continue
                t, tj = TL[ie], TL[je]
                for ic in range(3):
                    a, b = t[ic], t[(ic + 1) % 3]
                    if a in tj and b in tj:
                        border.append([a, b])
                        starts[a] += 1
                        break
        # chain the border edges into a loop, in LMGC90's order
        for j in range(len(border) - 1):
            for k in range(j + 1, len(border)):
                if border[j][1] == border[k][0]:
                    if k > j + 1:
                        border[j + 1], border[k] = border[k], border[j + 1]
                    break
        contours.append(border)
    corner = starts > 2
    edges, seen = [], set()
    for border in contours:
        n = len(border)
        j_first, look, ibeg = None, False, None
        for jj in range(2 * n):
            j = jj % n
            if j == j_first:
                break
            if not look:
                ibeg = border[j][0]
                if corner[ibeg]:
                    if j_first is None:
                        j_first = j
                    look = True
            if look:
                iend = border[j][1]
                if corner[iend]:
                    key = (min(ibeg, iend), max(ibeg, iend))
                    if key not in seen:
                        seen.add(key)
                        edges.append(key)
                    look = False
    contour = [np.array([e[0] for e in border if corner[e[0]]], np.int64) for border in contours]
    face_normal = np.array([normals[f[0]] for f in faces]).reshape(nface, 3)
    rmf = float(np.min(_circumradii(V[T[:, 0]], V[T[:, 1]], V[T[:, 2]])))
    return LmgcShape(V, T, normals, faces, face_normal, contour, corner,
                     np.array(edges, np.int64).reshape(-1, 2), seen,
                     float(np.max(np.linalg.norm(V, axis=1))), float(rmf))


def lmgc90_tables(vertices, triangles):
    """:class:`LmgcTables`: the :class:`LmgcShape` of each shape (a dump's ``/shapes``).
    Raises InputError (one line) for bad shapes.

    Parameters
    ----------
    vertices : sequence of array_like, each of shape (V_s, 3)
        m, each shape's vertices in its local frame (origin at the centre of
        mass).
    triangles : sequence of array_like of int, each of shape (T_s, 3)
        Each shape's outward triangles.

    Returns
    -------
    LmgcTables
        One :class:`LmgcShape` per shape, with the padded arrays.

    Raises
    ------
    InputError
        The checks of :func:`postproc.contactpoints.point_tables`.
    """
    point_tables(vertices, triangles)                       # the shared checks, one-line errors
    return LmgcTables([lmgc90_shape(v, t) for v, t in zip(vertices, triangles)])


class _Body:
    """One posed POLYR: world vertices X (V, 3), triangle normals N (T, 3),
    face normals FN (F, 3), centre c (3,), support values (T,)."""

    __slots__ = ("shape", "X", "N", "FN", "c", "support")

    def __init__(self, shape, R, x):
        self.shape = shape
        self.X = shape.vertices @ R.T + x
        self.N = shape.normals @ R.T
        self.FN = shape.face_normal @ R.T
        self.c = np.asarray(x, float)
        self.support = np.einsum("ij,ij->i", self.X[shape.triangles[:, 0]], self.N)


def _shadow_overlap(cd, an, adist, sep):
    """compute_shadow_overlap: (ok, sep, gap, cd_vis, an_vis)."""
    gap = np.min(cd.X @ sep) - np.max(an.X @ sep)
    if gap > adist:
        return False, sep, gap, None, None
    an_vis = np.zeros(len(an.X), np.int64)
    cd_vis = np.zeros(len(cd.X), np.int64)
    gap_an, e_an = gap, -1
    for i in np.flatnonzero(an.N @ sep >= -_TOL_NORMALES):
        d = np.min(cd.X @ an.N[i]) - an.support[i]
        if d > adist:
            return False, sep, gap, None, None
        an_vis[an.shape.triangles[i]] = 1
        if d > gap_an:
            gap_an, e_an = d, i
    gap_cd, e_cd = gap, -1
    for i in np.flatnonzero(cd.N @ sep <= _TOL_NORMALES):
        d = np.min(an.X @ cd.N[i]) - cd.support[i]
        if d > adist:
            return False, sep, gap, None, None
        if d > gap_cd:
            gap_cd, e_cd = d, i
        cd_vis[cd.shape.triangles[i]] = 1
    if e_cd >= 0 and e_an >= 0:
        s = (an.N[e_an] - cd.N[e_cd]) * 0.5
        sep, gap = s / np.linalg.norm(s), (gap_cd + gap_an) * 0.5
    elif e_cd >= 0:
        sep, gap = -cd.N[e_cd], gap_cd
    elif e_an >= 0:
        sep, gap = an.N[e_an], gap_an
    return True, sep, gap, cd_vis, an_vis


def _comp_rep(n):
    """LMGC90's comp_rep: (t, s) completing the unit normal n."""
    if abs(n[0]) < 1e-15:
        t = np.array([n[0], -n[2], n[1]])
    elif abs(n[1]) < 1e-15:
        t = np.array([-n[2], n[1], n[0]])
    elif abs(n[2]) < 1e-15:
        t = np.array([-n[1], n[0], n[2]])
    else:
        s = np.cross([1.0, 0.0, 0.0], n)
        t = s / np.linalg.norm(s)
        return t, np.cross(t, n)
    t = t / np.linalg.norm(t)
    return t, np.cross(t, n)


def _cundall(cd, an, cd_vis, an_vis, center, normal, iterations, ref_size):
    """compute_cundall_common_plane, as LMGC90 iterates it: returns
    (normal, t, s, gap, jmin, imax, centre of the plane)."""
    Xc, Xa = cd.X - center, an.X - center
    jc, ia = np.flatnonzero(cd_vis), np.flatnonzero(an_vis)
    dc, da = Xc[jc] @ normal, Xa[ia] @ normal
    jmin, imax = jc[np.argmin(dc)], ia[np.argmax(da)]
    p1 = an.X[imax] - cd.X[jmin]
    t = p1 - (p1 @ normal) * normal
    nt = np.sqrt(t @ t)
    if nt < 1e-6 * ref_size:
        t, s = _comp_rep(normal)
    else:
        t = t / nt
        s = np.cross(t, normal)
    gap = dc.min() - da.max()
    angle = _LMGC_THETA_MAX
    cr, sr = math.cos(2 * _LMGC_PI / _NB_ROT), math.sin(2 * _LMGC_PI / _NB_ROT)
    # the 3-vectors as Python floats: eight trial normals per round, built
    # one from the other as LMGC90 does (t is not re-orthogonalised)
    nx, ny, nz = (float(v) for v in normal)
    tx, ty, tz = (float(v) for v in t)
    sx, sy, sz = (float(v) for v in s)
    XcT, XaT = Xc[jc].T, Xa[ia].T
    n_ite, t_ite = np.empty((_NB_ROT, 3)), np.empty((_NB_ROT, 3))
    for _ in range(iterations):
        co, si = math.cos(angle), math.sin(angle)
        for k in range(_NB_ROT):
            tx, ty, tz = cr * tx + sr * sx, cr * ty + sr * sy, cr * tz + sr * sz
            L = math.sqrt(tx * tx + ty * ty + tz * tz)
            tx, ty, tz = tx / L, ty / L, tz / L
            t_ite[k] = tx, ty, tz
            sx, sy, sz = ty * nz - tz * ny, tz * nx - tx * nz, tx * ny - ty * nx
            ax, ay, az = co * nx + si * tx, co * ny + si * ty, co * nz + si * tz
            L = math.sqrt(ax * ax + ay * ay + az * az)
            n_ite[k] = ax / L, ay / L, az / L
        Dc = n_ite @ XcT                                           # (8, nc)
        Da = n_ite @ XaT
        gk = Dc.min(axis=1) - Da.max(axis=1)
        gap_ini, kk = gap, -1
        for k in range(_NB_ROT):
            if gap < gk[k]:
                gap, kk = gk[k], k
        if kk >= 0:
            jmin, imax = jc[np.argmin(Dc[kk])], ia[np.argmax(Da[kk])]
            if (gap - gap_ini) / ref_size < GAP_TOL:
                kk = -1
        if kk >= 0:
            nx, ny, nz = n_ite[kk]
            tx, ty, tz = t_ite[kk]
            sx, sy, sz = ty * nz - tz * ny, tz * nx - tx * nz, tx * ny - ty * nx
        elif angle >= _LMGC_THETA_MIN:
            angle *= 0.5
        else:
            break
    normal = np.array([nx, ny, nz])
    normal = normal / np.sqrt(normal @ normal)
    t, s = _comp_rep(normal)
    gap = (cd.X[jmin] - center) @ normal - (an.X[imax] - center) @ normal
    return normal, t, s, gap, jmin, imax, (an.X[imax] + cd.X[jmin]) * 0.5


def _mark_band(cd, an, cd_vis, an_vis, jmin, imax, center, normal, gap, neighbor):
    """The band of compute_cundall_common_plane: 2 for the extreme
    vertices, 1 within d1 of the plane on the body's side, -1 beyond."""
    ref = min(abs(normal @ (an.X[imax] - an.c)), abs(normal @ (cd.X[jmin] - cd.c)))
    d1 = max(0.0, gap * 0.5) + neighbor * ref
    cd_vis = cd_vis.copy()
    an_vis = an_vis.copy()
    hc = (cd.X - center) @ normal
    ha = (an.X - center) @ normal
    out_c = (cd_vis != 0) & (hc > d1)
    out_a = (an_vis != 0) & (ha < -d1)
    cd_vis[out_c] = -cd_vis[out_c]
    an_vis[out_a] = -an_vis[out_a]
    cd_vis[jmin], an_vis[imax] = 2, 2
    return cd_vis, an_vis, ref, hc, ha


def _hull2(P):
    """Convex hull (counter-clockwise, no collinear vertices) of 2-D points
    P (k, 2), exact (Andrew's monotone chain); (m, 2), m may be < 3.

    The points are sorted by x, then y, and repeated points dropped, as
    ``np.unique(P, axis=0)`` does them at many times the cost on a few
    points (of two points equal but for the sign of a zero coordinate, the
    first in the input is kept, where np.unique keeps either); the chain
    runs on Python floats, whose arithmetic is that of float64. The hull
    is float64 whatever the input's type."""
    P = np.asarray(P, dtype=float).reshape(-1, 2)
    if len(P) > 1:
        P = P[np.lexsort((P[:, 1], P[:, 0]))]
        new = np.empty(len(P), bool)
        new[0] = True
        np.any(P[1:] != P[:-1], axis=1, out=new[1:])
        P = P[new]
    if len(P) < 3:
        return P

    def half(pts):
        h = []
        for p in pts:
            while len(h) >= 2:
                (ax, ay), (bx, by) = h[-2], h[-1]
                if (bx - ax) * (p[1] - ay) - (by - ay) * (p[0] - ax) > 0:
                    break
                h.pop()
            h.append(p)
        return h
    pts = P.tolist()
    lo, hi = half(pts), half(pts[::-1])
    return np.array(lo[:-1] + hi[:-1])


def _clip_convex(poly, clipper):
    """Sutherland-Hodgman: convex polygon ``poly`` clipped by the convex
    counter-clockwise polygon ``clipper``, no tolerance."""
    out = poly
    m = len(clipper)
    for i in range(m):
        if not len(out):
            break
        a, b = clipper[i], clipper[(i + 1) % m]
        e = b - a
        side = e[0] * (out[:, 1] - a[1]) - e[1] * (out[:, 0] - a[0])
        res = []
        k = len(out)
        for j in range(k):
            p, q, sp, sq = out[j], out[(j + 1) % k], side[j], side[(j + 1) % k]
            if sp >= 0:
                res.append(p)
            if (sp >= 0) != (sq >= 0):
                res.append(p + sp / (sp - sq) * (q - p))
        out = np.array(res).reshape(-1, 2)
    return out


def _simplify(P, eps):
    """Clipper2's SimplifyPaths on a closed path: drop vertices closer than
    eps to the line through their neighbours (and repeated vertices),
    until none is; fewer than 3 vertices left means no polygon."""
    P = [p for p in P]
    changed = True
    while changed and len(P) >= 3:
        changed = False
        m = len(P)
        for i in range(m):
            a, b, c = P[i - 1], P[i], P[(i + 1) % m]
            ac = c - a
            L = np.hypot(*ac)
            d = np.hypot(*(b - a)) if L == 0 else abs(_cross2(ac, b - a)) / L
            if d < eps or np.hypot(*(b - a)) < eps:
                del P[i]
                changed = True
                break
    return np.array(P).reshape(-1, 2)


def _planplan(cd, an, cd_vis, an_vis, center, t, normal, s, clip_eps):
    """LMGC90's planplan: the kept vertices of each side projected on the
    common plane, their hulls intersected (Clipper2), at most 4 of the
    intersection's corners. Returns (k, 3) contact points (k = 0, 3 or 4)."""
    B2 = np.stack([s, t], 1)                                     # LMGC90's (s, t) coordinates

    def proj(X, keep):
        r = X[keep > 0] - center
        r = r - np.outer(r @ normal, normal)
        return r @ B2
    Pa, Pc = _hull2(proj(an.X, an_vis)), _hull2(proj(cd.X, cd_vis))
    if len(Pa) < 3 or len(Pc) < 3:
        return np.zeros((0, 3))
    # Clipper2 works on a grid of 10^-8 of the length unit
    q = 1.0 / clip_eps
    Pa, Pc = np.round(Pa * q) / q, np.round(Pc * q) / q
    I = _clip_convex(Pc, Pa)
    if len(I) < 3:
        return np.zeros((0, 3))
    I = np.round(I * q) / q
    I = _simplify(I, clip_eps)
    if len(I) < 3 or _area2(I) <= 0:
        return np.zeros((0, 3))
    if len(I) > MAX_POINTS:
        I = _sharpest_corners(I)
    return center + I[:, :1] * s + I[:, 1:2] * t


def _sharpest_corners(I, k=MAX_POINTS):
    """planplan's reduction of a polygon with more than k corners: the k
    corners (m, 2) -> (k, 2), in their order along the contour, with the
    sharpest turns (the smallest cosine between the incoming and outgoing
    edge; the first on a tie)."""
    m = len(I)
    cosang = np.empty(m)
    for i in range(m):
        v1, v2 = I[i] - I[i - 1], I[(i + 1) % m] - I[i]
        cosang[i] = (v1 @ v2) / (np.hypot(*v1) * np.hypot(*v2))
    return I[np.sort(np.argsort(cosang, kind="stable")[:k])]


def _area2(P):
    x, y = P[:, 0], P[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


# ---------------------------------------------------------------------------
# The 2009 route: planplan with a length-tolerant convex intersection
# ---------------------------------------------------------------------------
#
# Before Clipper2, LMGC90's planplan intersected the two projected hulls with
# ``polytopes_intersection``, which works with a length tolerance, so that a
# side whose kept vertices project to a point or a segment still gives points
# (docs/lmgc90-contacts.md). Its code is not reproduced here; the functions
# below implement the intersection from that description.


def _points_2d(P, name):
    """P as a float (k, 2) array, k >= 1, finite; InputError (one line) otherwise."""
    try:
        A = np.asarray(P, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be an array of 2-D points, got {type(P).__name__}") from None
    if A.ndim != 2 or A.shape[1] != 2 or len(A) < 1:
        raise InputError(f"{name} must have shape (k, 2) with k >= 1, got {A.shape}")
    if not np.isfinite(A).all():
        raise InputError(f"{name} must be finite")
    return A


def _length_tolerance(tol):
    """tol as a float; InputError (one line) unless finite and >= 0."""
    try:
        a = float(tol)
    except (TypeError, ValueError):
        raise InputError(f"the length tolerance must be a number, got {tol!r}") from None
    if not (np.isfinite(a) and a >= 0):
        raise InputError(f"the length tolerance must be finite and >= 0, got {tol!r}")
    return a


def convex_set_2d(P, tol):
    """The convex set spanned by 2-D points, with its dimension decided
    within a length tolerance: a point, a segment or a polygon.

    Parameters
    ----------
    P : array_like, shape (k, 2), k >= 1
        Points (m), e.g. the kept vertices of one side projected on the
        common plane.
    tol : float
        Length tolerance (m), >= 0.

    Returns
    -------
    ndarray, shape (m, 2)
        m = 1: a point (the mean of the hull's corners), when the points
        lie within tol of each other (the hull's diameter is <= tol);
        m = 2: a segment, its two ends (the hull's diameter pair, exact
        input points), when every point lies within tol of the line
        through them; m >= 3: a polygon, its corners counter-clockwise
        (exact input points), the hull's corners closer than tol to the
        line through their neighbours, or to a neighbour, dropped.

    Raises
    ------
    InputError
        P not (k, 2) with k >= 1, not finite, or tol not finite and >= 0.

    Examples
    --------
    >>> convex_set_2d([[0, 0], [1, 0], [2, 1e-9]], 1e-6).tolist()
    [[0.0, 0.0], [2.0, 1e-09]]
    >>> len(convex_set_2d([[0, 0], [1, 0], [0, 1]], 1e-6))
    3
    """
    P = _points_2d(P, "P")
    tol = _length_tolerance(tol)
    H = _hull2(P)
    if len(H) == 1:
        return H
    D = np.sqrt(((H[:, None, :] - H[None, :, :]) ** 2).sum(axis=2))
    i, j = np.unravel_index(int(np.argmax(D)), D.shape)
    i, j = min(i, j), max(i, j)
    if D[i, j] <= tol:
        return H.mean(axis=0, keepdims=True)
    if len(H) == 2:
        return H
    p, q = H[i], H[j]
    u = (q - p) / D[i, j]
    off = np.abs(u[0] * (H[:, 1] - p[1]) - u[1] * (H[:, 0] - p[0]))
    if off.max() <= tol:
        return np.array([p, q])
    S = _simplify(H, tol)
    return S if len(S) >= 3 else np.array([p, q])


def _clip_tolerant(X, closed, a, b, tol):
    """The part of the chain X (k, 2) (closed: a convex polygon; else a
    point or a segment) on the left of the directed line a -> b, a vertex
    kept when it lies at most tol on the right. Where an edge leaves the
    kept side from a vertex strictly on the left, the exact crossing with
    the line is added (so an overlap's corners are exact); from a vertex
    within tol on the right, that vertex is the end."""
    e = b - a
    side = (e[0] * (X[:, 1] - a[1]) - e[1] * (X[:, 0] - a[0])) / np.hypot(*e)
    keep = side >= -tol
    m = len(X)
    if m == 1:
        return X if keep[0] else X[:0]
    out = []
    if not closed and keep[0]:
        out.append(X[0])
    for i in range(m if closed else m - 1):
        j = (i + 1) % m
        if closed and keep[i]:
            out.append(X[i])
        if keep[i] != keep[j]:
            s_in = side[i] if keep[i] else side[j]
            if s_in > 0:
                out.append(X[i] + side[i] / (side[i] - side[j]) * (X[j] - X[i]))
        if not closed and keep[j]:
            out.append(X[j])
    return np.array(out).reshape(-1, 2)


def _segment_segment(A, B, tol):
    """Two segments (2, 2): the ends of their overlap when they lie on one
    line within tol, else their crossing (within tol of both), else an
    end within tol of the other segment; (k, 2), k = 0, 1 or 2."""
    if np.hypot(*(A[1] - A[0])) < np.hypot(*(B[1] - B[0])):
        A, B = B, A
    p, L = A[0], np.hypot(*(A[1] - A[0]))
    u = (A[1] - A[0]) / L
    X = np.concatenate([A, B])
    h = u[0] * (X[:, 1] - p[1]) - u[1] * (X[:, 0] - p[0])
    if np.all(np.abs(h) <= tol):                                  # one line: the overlap
        s = (X - p) @ u
        lo_a, lo_b = (0, 1) if s[0] <= s[1] else (1, 0)
        lo_c, lo_d = (2, 3) if s[2] <= s[3] else (3, 2)
        lo = lo_a if s[lo_a] >= s[lo_c] else lo_c               # the later start
        hi = lo_b if s[lo_b] <= s[lo_d] else lo_d                # the earlier end
        if s[hi] < s[lo] - tol:
            return np.zeros((0, 2))
        if s[hi] - s[lo] <= tol:
            return (0.5 * (X[lo] + X[hi]))[None]
        return X[[lo, hi]]
    a, b, c, d = X
    r, w = b - a, d - c
    den = _cross2(r, w)
    if den != 0:
        t = _cross2(c - a, w) / den
        v = _cross2(c - a, r) / den
        La, Lb = np.hypot(*r), np.hypot(*w)
        if -tol <= t * La <= La + tol and -tol <= v * Lb <= Lb + tol:
            return (a + t * r)[None]
    # no crossing: an end within tol of the other segment (nearly parallel, touching)
    best, where = np.inf, None
    for P, (q0, q1) in ((a, (c, d)), (b, (c, d)), (c, (a, b)), (d, (a, b))):
        e = q1 - q0
        z = np.clip((P - q0) @ e / (e @ e), 0.0, 1.0)
        dist = np.hypot(*(P - q0 - z * e))
        if dist < best:
            best, where = dist, P
    return where[None] if best <= tol else np.zeros((0, 2))


def tolerant_intersection(P, Q, tol, max_points=MAX_POINTS):
    """Contact points of two projected sides as the 2009 planplan route
    finds them: the intersection of their convex sets in the plane with a
    length tolerance, so that a point or a segment gives points too.

    Each side's points make a point, a segment or a polygon
    (:func:`convex_set_2d`, within tol). Then:

    * polygon and polygon: the corners of their intersection polygon
      (the exact crossings of the two contours and the corners of either
      inside the other), its own dimension decided within tol again, so a
      sliver of width <= tol gives the 2 ends of a segment;
    * segment and polygon: the two ends of the segment clipped by the
      polygon (exact crossings with its edges), 1 point when they are
      within tol of each other;
    * segment and segment: on one line within tol (every end within tol of
      the longer one's line), the ends of their overlap (input points; 1
      point, their midpoint, when the overlap is <= tol long); else their
      crossing when it lies within tol of both;
    * point and anything: the point when within tol of the other set
      (two points: their midpoint).

    "Within tol" of a polygon is on the inner side of every edge line or
    at most tol outside it (a vertex that far out is kept as it is).
    More than ``max_points`` corners are reduced as planplan reduces them:
    the ``max_points`` sharpest corners (smallest cosine of the turn).

    Parameters
    ----------
    P, Q : array_like, shape (k, 2), k >= 1
        The two sides' points (m), in the same plane coordinates.
    tol : float
        Length tolerance (m), >= 0. The route uses :data:`TOL_2009` times
        the band's reference length (:func:`lmgc90_pair`).
    max_points : int
        At most this many points (planplan: 4).

    Returns
    -------
    ndarray, shape (n, 2)
        The points, n = 0 (no contact) to ``max_points``.

    Raises
    ------
    InputError
        Points not (k, 2) with k >= 1 or not finite; tol not finite and
        >= 0; max_points not an integer >= 1.

    Examples
    --------
    A segment lying across a unit square gives its two clipped ends:

    >>> square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    >>> tolerant_intersection([[-1, 0.5], [2, 0.5]], square, 1e-3).tolist()
    [[0.0, 0.5], [1.0, 0.5]]
    >>> len(tolerant_intersection([[0.5, 1.01]], square, 1e-3))
    0
    """
    A, B = convex_set_2d(_points_2d(P, "P"), tol), convex_set_2d(_points_2d(Q, "Q"), tol)
    tol = float(tol)
    if not (isinstance(max_points, (int, np.integer)) and max_points >= 1):
        raise InputError(f"max_points must be an integer >= 1, got {max_points!r}")
    if len(A) > len(B):
        A, B = B, A
    if len(B) >= 3:                                              # B a polygon: clip A by its edges
        R = A
        m = len(B)
        for i in range(m):
            R = _clip_tolerant(R, len(R) >= 3, B[i], B[(i + 1) % m], tol)
            if not len(R):
                return np.zeros((0, 2))
        if len(A) == 1:
            I = R
        elif len(A) == 2:
            I = R[[0, -1]] if np.hypot(*(R[-1] - R[0])) > tol else (0.5 * (R[0] + R[-1]))[None]
        else:
            I = convex_set_2d(R, tol)
    elif len(A) == 2:                                            # two segments
        I = _segment_segment(A, B, tol)
    elif len(B) == 2:                                            # a point and a segment
        e = B[1] - B[0]
        z = np.clip((A[0] - B[0]) @ e / (e @ e), 0.0, 1.0)
        I = A if np.hypot(*(A[0] - B[0] - z * e)) <= tol else np.zeros((0, 2))
    else:                                                        # two points
        I = (0.5 * (A + B)) if np.hypot(*(A[0] - B[0])) <= tol else np.zeros((0, 2))
    if len(I) > max_points:
        I = _sharpest_corners(I, max_points)
    return I


def _planplan_2009(cd, an, cd_vis, an_vis, center, t, normal, s, tol):
    """planplan with the length-tolerant intersection (the 2009 route): the
    kept vertices of each side projected on the common plane (LMGC90's
    (s, t) coordinates), :func:`tolerant_intersection` with tol (m).
    Returns (k, 3) contact points, k = 0 to 4."""
    B2 = np.stack([s, t], 1)

    def proj(X, keep):
        r = X[keep > 0] - center
        r = r - np.outer(r @ normal, normal)
        return r @ B2
    Pa, Pc = proj(an.X, an_vis), proj(cd.X, cd_vis)
    if not (len(Pa) and len(Pc)):
        return np.zeros((0, 3))
    I = tolerant_intersection(Pc, Pa, tol)
    return center + I[:, :1] * s + I[:, 1:2] * t


def _node_node(x1, x2, ntr):
    ptc = 0.5 * (x1 + x2)
    n = x1 - x2
    d = np.sqrt(n @ n)
    if d != 0:
        n = n / d
        if n @ ntr < 0:
            n, d = -n, -d
    else:
        n = ntr
    return ptc, n, d


def _node_edge(x1, b, e, ntr):
    """nodetoedge_distance: (ptc, normal, dist)."""
    e2 = e - b
    l2 = np.sqrt(e2 @ e2)
    e2 = e2 / l2
    x = (x1 - b) @ e2
    if x > l2:
        return _node_node(x1, e, ntr)
    if x >= 0:
        w = x / l2
        p = (1 - w) * b + w * e
        ptc, n, d = _node_node(x1, p, ntr)
        return ptc, n, d
    return _node_node(x1, b, ntr)


def _node_face(x1, C, ntr):
    """nodetoface_distance on the contour corners C (m, 3): (ptc, normal,
    dist), or None where LMGC90 raises an error."""
    m = len(C)
    e = np.roll(C, -1, axis=0) - C
    l = np.linalg.norm(e, axis=1)
    e = e / l[:, None]
    dist = (x1 - C[0]) @ ntr
    ptc = x1 - dist * ntr
    normal = ntr
    signe = np.array([int(np.cross(ntr, e[i]) @ (ptc - C[i]) < 0) for i in range(m)])
    status = int(signe.sum())
    if status > 1 and m > 3:
        xprev, x1st = -1.0, 1.0
        for ie in range(m):
            if signe[ie] == 0:
                xprev = -1.0
                continue
            x = (ptc - C[ie]) @ e[ie]
            if ie == 0:
                x1st = x
            if 0 <= x <= l[ie]:
                signe[:] = 0
                signe[ie] = 1
                status = 1
                break
            elif x > l[ie]:
                xprev = x
                if ie == m - 1 and x1st < 0:
                    signe[:] = 0
                    signe[m - 1] = signe[0] = 1
                    status = 2
                    break
            elif x < 0 and xprev > 0:
                signe[:] = 0
                signe[ie - 1] = signe[ie] = 1
                status = 2
                break
    if status == 0:
        return ptc, normal, dist
    if status == 1:
        for ie in range(m - 1):                       # LMGC90 stops at the last but one edge
            if signe[ie]:
                return _node_edge(x1, C[ie], C[(ie + 1) % m], ntr)
        return ptc, normal, dist
    if status == 2:
        for ie in range(m):
            if signe[ie]:
                if ie == 0 and signe[1] == 0:
                    return _node_node(x1, C[0], ntr)
                return _node_node(x1, C[(ie + 1) % m], ntr)
    return None


def _edge_edge(c1b, c1e, c2b, c2e, ntr):
    """edgetoedge_distance: list of (ptc, normal, dist), 1 or 2 entries
    (LMGC90's branches, including its pairing of the antiparallel case)."""
    e1 = c1e - c1b
    l1 = np.sqrt(e1 @ e1)
    e1 = e1 / l1
    e2 = c2e - c2b
    l2 = np.sqrt(e2 @ e2)
    e2 = e2 / l2
    P1 = lambda w: (1 - w) * c1b + w * c1e
    P2 = lambda w: (1 - w) * c2b + w * c2e
    nn = lambda a, b: _node_node(a, b, ntr)
    c = e1 @ e2
    if abs(c) > 1 - _LMGC_PARALLEL:
        x1, x2 = (c1b - c2b) @ e2, (c1e - c2b) @ e2
        if c > 0:
            if x1 > l2:
                return [nn(c1b, c2e)]
            if 0 <= x1 <= l2 and x2 > l2:
                return [nn(c1b, P2(x1 / l2)), nn(P1(((c2e - c1b) @ e1) / l1), c2e)]
            if 0 <= x1 <= l2 and 0 <= x2 <= l2:
                return [nn(c1b, P2(x1 / l2)), nn(c1e, P2(x2 / l2))]
            if x1 < 0 and x2 > l2:
                return [nn(P1(((c2b - c1b) @ e1) / l1), c2b), nn(P1(((c2e - c1b) @ e1) / l1), c2e)]
            if x1 < 0 and 0 <= x2 <= l2:
                return [nn(P1(((c2b - c1b) @ e1) / l1), c2b), nn(c1e, P2(x2 / l2))]
            if x2 < 0:
                return [nn(c1e, c2b)]
            return []
        if x2 > l2:
            return [nn(c1e, c2e)]
        if 0 <= x2 <= l2 and x1 > l2:
            return [nn(c1e, P2(x2 / l2)), nn(P1(((c2e - c1b) @ e1) / l1), c2e)]
        if 0 <= x2 <= l2 and 0 <= x1 <= l2:
            return [nn(c1e, P2(x2 / l2)), nn(c1e, P2(x1 / l2))]          # sic: LMGC90 pairs c1e twice
        if x2 < 0 and x1 > l2:
            return [nn(P1(((c2e - c1b) @ e1) / l1), c2e), nn(P1(((c2b - c1b) @ e1) / l1), c2b)]
        if x2 < 0 and 0 <= x1 <= l2:
            return [nn(P1(((c2e - c1b) @ e1) / l1), c2e), nn(c1e, P2(x2 / l2))]   # sic
        if x1 < 0:
            return [nn(c1b, c2b)]
        return []
    tmp = c1b - c2b
    b1, b2, a12 = e1 @ tmp, -(e2 @ tmp), -c
    delta = 1 - a12 * a12
    x1 = (a12 * b2 - b1) / delta
    x2 = (a12 * b1 - b2) / delta
    w1 = 0.0 if x1 < 0 else (1.0 if x1 > l1 else x1 / l1)
    w2 = 0.0 if x2 < 0 else (1.0 if x2 > l2 else x2 / l2)
    return [nn(P1(w1), P2(w2))]


def _orient(a, b, c, d):
    """Shewchuk's orient3d sign convention: det[a - d, b - d, c - d]
    (floating point, not exact: they differ only on exact degeneracies)."""
    ax, ay, az = a[0] - d[0], a[1] - d[1], a[2] - d[2]
    bx, by, bz = b[0] - d[0], b[1] - d[1], b[2] - d[2]
    cx, cy, cz = c[0] - d[0], c[1] - d[1], c[2] - d[2]
    return float(ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx))


def _edge_face(c1b, c1e, C, ntr):
    """edgetoface_distance_wp: list of (ptc, normal, dist), 0 to 2 entries,
    or None where LMGC90 raises an error."""
    m = len(C)
    d1b = (c1b - C[0]) @ ntr
    p1b = c1b - d1b * ntr
    d1e = (c1e - C[0]) @ ntr
    p1e = c1e - d1e * ntr
    b_in = e_in = True
    cross = []
    para = -1
    for ie in range(m):
        a, b = C[ie], C[(ie + 1) % m]
        tmp = a - ntr
        bc, ec = _orient(a, tmp, b, p1b), _orient(a, tmp, b, p1e)
        if bc < 0:
            b_in = False
        if ec < 0:
            e_in = False
        if (bc < 0) != (ec < 0):
            tmp2 = p1b - ntr
            b2, e2 = _orient(p1b, tmp2, p1e, a), _orient(p1b, tmp2, p1e, b)
            if (b2 < 0) != (e2 < 0):
                r = _edge_edge(c1b, c1e, a, b, ntr)
                if not r:
                    return None
                pick = min(r, key=lambda z: z[2]) if len(r) == 2 else r[0]
                keep = True
                if len(cross) == 1:
                    ref = 0.5 * (r[0][0] + r[1][0]) if len(r) == 2 else r[0][0]
                    if np.linalg.norm(cross[0][0] - ref) < 1e-14:
                        keep = False
                elif len(cross) == 2:
                    keep = False
                if keep:
                    cross.append(pick)
        if bc == 0 and ec == 0:
            para = ie
            break
    if para >= 0:
        r = _edge_edge(c1b, c1e, C[para], C[(para + 1) % m], ntr)
        if len(r) != 2:
            return None
        out = r
    elif len(cross) == 2:
        out = cross
    elif len(cross) == 1:
        if b_in:
            out = [cross[0], (p1b, ntr, d1b)]
        elif e_in:
            out = [cross[0], (p1e, ntr, d1e)]
        else:
            out = cross
    else:
        out = []
    if b_in and e_in:
        out = [(p1b, ntr, d1b), (p1e, ntr, d1e)]
    return out


def _accept(pts, adist, mid, sign):
    """LMGC90's per-point test of the point stage: drop a point whose gap
    exceeds the alert distance or whose normal is more than tol_angle off
    the common plane's (sign: +1 when the normal is oriented like the
    plane's, -1 when opposite)."""
    return [p for p in pts if not (p[2] > adist or sign * (p[1] @ mid) < 1 - TOL_ANGLE)]


def _seen_face(body, normal, sign):
    """The face LMGC90 takes for a side with 3+ kept vertices: the first
    whose normal is within f2f_tol of the plane's (sign * n . normal), else
    the best aligned."""
    c = sign * (body.FN @ normal)
    ok = np.flatnonzero(c >= 1 - _LMGC_F2F_TOL)
    if len(ok):
        return int(ok[0])
    best, k = 0.0, -1
    for i, v in enumerate(c):
        if v > best:
            best, k = v, i
    return k


def _side(body, vis, jext, normal, sign):
    """(status, geo) of a side: 3 face, 2 edge, 1 vertex, as LMGC90's
    contact-type stage decides it from the kept vertices."""
    kept = np.flatnonzero(vis > 0)
    js = len(kept)
    if js > 2:
        return 3, _seen_face(body, normal, sign)
    if js == 2:
        key = (int(kept[0]), int(kept[1]))
        if key in body.shape.edge_set:
            return 2, key
    return 1, int(jext)


def lmgc90_pair(cd, an, adist, route="lmgc90", neighbor=DEFAULT_NEIGHBOR, iterations=LMGC90_ITERATIONS,
                min_radius=None, sep=None, clip_eps=CLIP_EPS):
    """LMGC90's detection of one pair (``DETECTION_COMMON_PLANE``): cd the
    candidate, an the antagonist (:class:`_Body`), adist the alert
    distance (m). Returns a dict: ``points`` (k, 3) m, ``gaps`` (k,) m,
    ``normal`` (3,) the common plane's (from an to cd), ``gap`` the plane's
    gap, ``stage`` the contact-type code (cd 1/2/3 + an 10/20/30, -1 when the
    shadow overlap separates the pair; the planplan and 2009 routes report
    the same code though they do not use it). route: one of
    :data:`LMGC90_ROUTES` (:func:`lmgc90_points`).

    Parameters
    ----------
    cd, an : _Body
        The posed candidate and antagonist (world vertices X (V, 3) m,
        triangle and face normals, centre c (3,) m).
    adist : float
        m, the alert distance.
    route : str, optional
        One of ``LMGC90_ROUTES`` (default "lmgc90").
    neighbor : float, optional
        LMGC90's cundall_neighbor, the band in units of ref (default 0.1).
    iterations : int, optional
        cundall_iter (default ``LMGC90_ITERATIONS`` = 200).
    min_radius : float or None, optional
        m, the convergence scale of Cundall's search (None: the smaller of
        the two shapes' radii).
    sep : array_like of shape (3,) or None, optional
        The start direction (None: from an's centre to cd's, normalised).
    clip_eps : float, optional
        m, the Clipper2 grid (default ``CLIP_EPS`` = 1e-8).

    Returns
    -------
    dict
        ``points`` ndarray (k, 3) m, k = 0..4 (no point: (0, 3));
        ``gaps`` ndarray (k,) m; ``normal`` ndarray (3,) unit, from an to
        cd; ``gap`` float m (positive: apart); ``stage`` int, the code as
        said above, also -1 when a side has no visible corner.
    """
    if sep is None:
        sep = cd.c - an.c
        sep = sep / np.linalg.norm(sep)
    ok, sep, gap, cd_vis, an_vis = _shadow_overlap(cd, an, adist, np.asarray(sep, float))
    empty = {"points": np.zeros((0, 3)), "gaps": np.zeros(0), "normal": sep, "gap": gap, "stage": -1}
    if not ok:
        return empty
    cd_vis = np.where(cd.shape.corner, cd_vis, 0)
    an_vis = np.where(an.shape.corner, an_vis, 0)
    if not (cd_vis.any() and an_vis.any()):
        return empty
    ref_size = min(cd.shape.radius, an.shape.radius) if min_radius is None else float(min_radius)
    mid_P = 0.5 * (an.c + cd.c)
    normal, t, s, gap, jmin, imax, center = _cundall(cd, an, cd_vis, an_vis, mid_P, sep, iterations, ref_size)
    cd_k, an_k, ref, hc, ha = _mark_band(cd, an, cd_vis, an_vis, jmin, imax, center, normal, gap, neighbor)
    return _point_stage(cd, an, [adist], route, neighbor, clip_eps, normal, t, s, gap, jmin, imax, center,
                        cd_k, an_k, ref, hc, ha)[0]


def _point_stage(cd, an, adists, route, neighbor, clip_eps, normal, t, s, gap, jmin, imax, center,
                 cd_k, an_k, ref, hc, ha):
    """The contact-type and point stages of DETECTION_COMMON_PLANE after
    the band (see :func:`lmgc90_pair`), at each alert distance of
    ``adists`` (m): a list of results, one per alert distance. What does
    not depend on the alert distance (the types, the geometric points,
    planplan, the wider band's planplan) is computed once."""
    cs, cg = _side(cd, cd_k, jmin, normal, -1.0)
    as_, ag = _side(an, an_k, imax, normal, +1.0)
    code = cs + 10 * as_
    res = {"normal": normal, "gap": gap, "stage": code}
    if route in ("lmgc90-planplan", "lmgc90-2009"):
        if route == "lmgc90-planplan":
            P = _planplan(cd, an, cd_k, an_k, center, t, normal, s, clip_eps)
        else:
            P = _planplan_2009(cd, an, cd_k, an_k, center, t, normal, s, TOL_2009 * ref)
        return [{**res, "points": P.copy() if k else P, "gaps": np.full(len(P), gap)} for k in range(len(adists))]
    X, A = cd.X, an.X
    cand, sign, fixed = [], 1, None          # the points before LMGC90's per-point test (_accept)
    if code == 11:
        cand = [_node_node(X[cg], A[ag], normal)]
    elif code == 12:
        cand, sign = [_node_edge(A[ag], X[cg[0]], X[cg[1]], -normal)], -1
    elif code == 13:
        r = _node_face(A[ag], X[cd.shape.contour[cg]], cd.FN[cg])
        cand, sign = ([] if r is None else [r]), -1
    elif code == 21:
        cand = [_node_edge(X[cg], A[ag[0]], A[ag[1]], normal)]
    elif code == 22:
        cand = _edge_edge(X[cg[0]], X[cg[1]], A[ag[0]], A[ag[1]], normal)
    elif code == 23:
        r = _edge_face(A[ag[0]], A[ag[1]], X[cd.shape.contour[cg]], cd.FN[cg])
        cand, sign = ([] if r is None else r), -1
    elif code == 31:
        r = _node_face(X[cg], A[an.shape.contour[ag]], normal)
        cand = [] if r is None else [r]
    elif code == 32:
        r = _edge_face(X[cg[0]], X[cg[1]], A[an.shape.contour[ag]], an.FN[ag])
        cand = [] if r is None else r
    else:                                                         # 33: face on face, no per-point test
        P = _planplan(cd, an, cd_k, an_k, center, t, normal, s, clip_eps)
        fixed = [(p, normal, gap) for p in P]
    out, wide = [], None
    for adist in adists:
        pts = fixed if fixed is not None else _accept(cand, adist, normal, sign)
        if not pts and gap < adist:
            # no point: the band ten times wider, and planplan
            if wide is None:
                d1 = max(0.0, gap * 0.5) + 10 * neighbor * ref
                cd_w, an_w = cd_k.copy(), an_k.copy()
                m = (cd_w != 0) & (np.arange(len(cd_w)) != jmin)
                cd_w[m & (hc > d1)] = 0
                cd_w = np.abs(cd_w)
                m = (an_w != 0) & (np.arange(len(an_w)) != imax)
                an_w[m & (ha < -d1)] = 0
                an_w = np.abs(an_w)
                P = _planplan(cd, an, cd_w, an_w, center, t, normal, s, clip_eps)
                wide = [(p, normal, gap) for p in P]
            pts = wide
        if not pts:
            out.append({**res, "points": np.zeros((0, 3)), "gaps": np.zeros(0)})
        else:
            out.append({**res, "points": np.array([p[0] for p in pts]),
                        "gaps": np.array([p[2] for p in pts], float)})
    return out


def check_alert(alert, what="the alert distance"):
    """alert as a float; InputError (one line) unless finite and > 0.

    Parameters
    ----------
    alert : object
        The alert distance (m, or in units the caller states): a number or
        a string of one.
    what : str, optional
        Its name in the message.

    Returns
    -------
    float
        alert, finite and > 0.

    Raises
    ------
    InputError
        Not a number, not finite, or <= 0.
    """
    return positive_tolerance(alert, what)


def check_route(route):
    """route unchanged; InputError (one line) unless one of LMGC90_ROUTES.

    Parameters
    ----------
    route : str
        "lmgc90", "lmgc90-planplan" or "lmgc90-2009".

    Returns
    -------
    str
        ``route``, one of ``LMGC90_ROUTES``.

    Raises
    ------
    InputError
        Any other value.
    """
    if route not in LMGC90_ROUTES:
        raise InputError(f"LMGC90 count: route must be one of {', '.join(LMGC90_ROUTES)}, got {route!r}")
    return route


def lmgc90_points(tables, shape_cd, pos_cd, quat_cd, shape_an, pos_an, quat_an, alert,
                  route="lmgc90", neighbor=DEFAULT_NEIGHBOR, iterations=LMGC90_ITERATIONS, min_radius=None,
                  clip_eps=CLIP_EPS):
    """LMGC90's contact points of each polyhedra pair, as its CpCundall
    detection finds them at a first detection (module section above).

    tables : list of :class:`LmgcShape` (:func:`lmgc90_tables`). shape_cd,
    shape_an (C,) int shape rows of the candidate and the antagonist (in
    LMGC90 the candidate is the body with the lower number); pos (C, 3) m
    centres of mass; quat (C, 4) (w, x, y, z) local -> global. alert : the
    alert distance (m; pairs whose gap exceeds it have no point, and with
    route "lmgc90" so has every point whose own gap exceeds it). route :
    "lmgc90" (today's default point stage), "lmgc90-planplan" (the older
    route: planplan, the hulls intersected by Clipper2, so 3 or 4 points or
    none) or "lmgc90-2009" (the older route with the intersection planplan
    used before Clipper2, which has a length tolerance:
    :func:`tolerant_intersection`, so a point or a segment gives 1 or 2
    points). The 2009 route's tolerance is ``TOL_2009 * ref`` = 1e-2 ref,
    ref the band's reference length (the smaller distance, along the
    plane's normal, from a body's centre to its extreme vertex; 0.4-1.3 cm
    on 90 % of the default study's contacts, so tol is 4e-5 to 1.3e-4 m):
    the distance below which LMGC90's older ``polytopes_intersection``
    called two points one (its squared distances below 1e-4 of its
    reference length squared), the length scale of that intersection
    relative to the grain size, as planplan's Clipper grid (1e-8 m) is
    today's. It is far above round-off and Clipper's grid (about 1e-6 ref)
    and a tenth of the band (0.1 ref), so it decides only the degenerate
    meetings: a point or a segment on a contour, segments on one line,
    slivers (at tol/10 the group changes on 0.4 % of a packing's contacts;
    docs/lmgc90-contacts.md). Which reference length planplan passed to
    ``polytopes_intersection`` is not in the source found; ref is the
    length the band is made of. neighbor : LMGC90's cundall_neighbor (the
    band, 0.1). iterations : cundall_iter. min_radius : m, the smallest grain radius of the sample
    (LMGC90's convergence scale; default the smallest shape of ``tables``).
    clip_eps : m, the Clipper2 precision (1e-8 of LMGC90's length unit: the
    default assumes metres).

    The search starts, as LMGC90's does at a first detection, from the
    direction from the antagonist's centre to the candidate's.

    Returns a dict of (C,) arrays: ``points`` int (0..4), ``group`` int8
    (SIMPLE, DOUBLE, TRIPLE; 0 or 1 point is simple), ``pair`` int8 index
    into contacttypes.PAIR_TYPES agreeing with the group, ``feature_cd``,
    ``feature_an`` int8 (VERTEX, EDGE, FACE: 1, 2, 3+ vertices kept in the
    band), ``gap`` m (the common plane's; negative: interpenetration),
    ``normal`` (C, 3) the common plane's unit normal from the antagonist to
    the candidate, ``stage`` int the contact-type code (cd 1/2/3 + an
    10/20/30; -1 when the shadow overlap separates the pair), and the lists
    ``xyz`` (each (k, 3) m, the points) and ``gaps`` (each (k,) m).
    Raises InputError (one line) for bad indices or non-finite input.

    Parameters
    ----------
    tables : LmgcTables or list of LmgcShape
        The shapes (:func:`lmgc90_tables`).
    shape_cd, shape_an : array_like of int, shape (C,)
        The shape rows of the candidate and the antagonist.
    pos_cd, pos_an : array_like, shape (C, 3)
        m, their centres of mass (never equal).
    quat_cd, quat_an : array_like, shape (C, 4)
        Their orientations (w, x, y, z), local -> global.
    alert : float
        m, the alert distance, finite and > 0.
    route : str, optional
        One of ``LMGC90_ROUTES`` (default "lmgc90").
    neighbor : float, optional
        cundall_neighbor, > 0 (default ``DEFAULT_NEIGHBOR`` = 0.1).
    iterations : int, optional
        cundall_iter (default ``LMGC90_ITERATIONS`` = 200).
    min_radius : float or None, optional
        m, the sample's smallest grain radius (None: the smallest shape
        radius of ``tables``).
    clip_eps : float, optional
        m, the Clipper2 grid (default ``CLIP_EPS`` = 1e-8).

    Returns
    -------
    dict
        As said above. A pair with no contact (separated by the shadow
        overlap, or a gap above the alert distance) has 0 points, stage -1,
        VERTEX features and the shadow overlap's gap and direction. The
        features ``feature_cd`` and ``feature_an`` come from the stage
        code: a side with 2 kept corners not joined by a topological edge
        is a VERTEX.

    Raises
    ------
    InputError
        As said above, coinciding centres, an unknown route or a bad alert
        distance or neighbor.
    """
    return lmgc90_points_alerts(tables, shape_cd, pos_cd, quat_cd, shape_an, pos_an, quat_an, [alert],
                                route=route, neighbor=neighbor, iterations=iterations, min_radius=min_radius,
                                clip_eps=clip_eps)[0]


def lmgc90_points_alerts(tables, shape_cd, pos_cd, quat_cd, shape_an, pos_an, quat_an, alerts,
                         route="lmgc90", neighbor=DEFAULT_NEIGHBOR, iterations=LMGC90_ITERATIONS, min_radius=None,
                         clip_eps=CLIP_EPS):
    """:func:`lmgc90_points` at several alert distances at once, as a
    band test asks (the alert distance halved, as given, doubled).

    The alert distance decides only which pairs the shadow overlap keeps
    and, on the ``lmgc90`` route, the per-point test and the wider band's
    fallback; the rest of the detection (the shadow overlap's plane,
    Cundall's search, the band, the contact types, planplan) is made once
    per pair, at the largest alert distance, and the results are those of
    :func:`lmgc90_points` called at each alert distance, value for value.

    Parameters
    ----------
    tables, shape_cd, pos_cd, quat_cd, shape_an, pos_an, quat_an
        As :func:`lmgc90_points`: the shape tables, (C,) shape rows,
        (C, 3) centres of mass (m) and (C, 4) quaternions (w, x, y, z) of
        the candidates and the antagonists.
    alerts : sequence of float
        The alert distances (m), each finite and > 0.
    route, neighbor, iterations, min_radius, clip_eps
        As :func:`lmgc90_points`.

    Returns
    -------
    list of dict
        One dict of :func:`lmgc90_points` per alert distance, in the
        order of ``alerts``, each with arrays of its own.

    Raises
    ------
    InputError
        One line: bad indices, non-finite input, coinciding centres, an
        unknown route or a bad alert distance.
    """
    check_route(route)
    if isinstance(alerts, (str, bytes, dict)) or np.ndim(alerts) != 1:
        raise InputError(f"LMGC90 count: alerts must be a sequence of distances, got {alerts!r}")
    alerts = [check_alert(a) for a in alerts]
    if not alerts:
        raise InputError("LMGC90 count: no alert distance given")
    check_neighbor(neighbor)
    C = len(np.asarray(shape_cd))
    s_cd, s_an, p_cd, p_an, q_cd, q_an = check_pose_arrays("LMGC90 count", len(tables), (
        ("shape_cd", shape_cd, (C,)), ("shape_an", shape_an, (C,)), ("pos_cd", pos_cd, (C, 3)),
        ("pos_an", pos_an, (C, 3)), ("quat_cd", quat_cd, (C, 4)), ("quat_an", quat_an, (C, 4))))
    same = np.all(p_cd == p_an, axis=1)
    if same.any():
        raise InputError(f"LMGC90 count: contact {int(np.flatnonzero(same)[0])}: the two centres coincide")
    if not isinstance(tables, LmgcTables):
        tables = LmgcTables(tables)
    if min_radius is None:
        min_radius = tables.rmin
    R_cd, R_an = rotation_matrices(q_cd.astype(float)), rotation_matrices(q_an.astype(float))
    outs = [{"points": np.zeros(C, np.int64), "gap": np.zeros(C), "normal": np.zeros((C, 3)),
             "stage": np.zeros(C, np.int64), "feature_cd": np.zeros(C, np.int8),
             "feature_an": np.zeros(C, np.int8), "xyz": [], "gaps": []} for _ in alerts]
    feat = {1: VERTEX, 2: EDGE, 3: FACE}
    amax = max(alerts)
    for b0 in range(0, C, _BLOCK):
        sl = slice(b0, min(b0 + _BLOCK, C))
        sc, sa = s_cd[sl], s_an[sl]
        D = _detect_block(tables, sc, R_cd[sl], p_cd[sl].astype(float), sa, R_an[sl], p_an[sl].astype(float),
                          amax, iterations, float(min_radius), neighbor)
        at = {int(k): i for i, k in enumerate(D.get("a", []))}
        for j in range(sl.stop - b0):
            k = b0 + j
            i = at.get(j)
            # a contact at an alert distance: visible faces and a reach within it
            kept = [i is not None and D["reach"][j] <= a for a in alerts]
            rs = iter(())
            if any(kept):
                cd = _Posed(tables[sc[j]], D["XC"][j], R_cd[k], p_cd[k])
                an = _Posed(tables[sa[j]], D["XA"][j], R_an[k], p_an[k])
                nc, na = len(cd.X), len(an.X)
                rs = iter(_point_stage(cd, an, [a for a, y in zip(alerts, kept) if y], route, neighbor, clip_eps,
                                       D["normal"][i], D["t"][i], D["s"][i], D["plane_gap"][i], D["jmin"][i],
                                       D["imax"][i], D["center"][i], D["kC"][i, :nc], D["kA"][i, :na],
                                       D["ref"][i], D["hc"][i, :nc], D["ha"][i, :na]))
            for out, y in zip(outs, kept):
                if not y:                          # no contact: no visible pair of faces, or a gap above the alert
                    out["gap"][k], out["normal"][k], out["stage"][k] = D["gap"][j], D["sep"][j], -1
                    out["feature_cd"][k] = out["feature_an"][k] = VERTEX
                    out["xyz"].append(np.zeros((0, 3)))
                    out["gaps"].append(np.zeros(0))
                    continue
                r = next(rs)
                out["points"][k] = len(r["points"])
                out["gap"][k], out["normal"][k], out["stage"][k] = r["gap"], r["normal"], r["stage"]
                st = r["stage"]
                out["feature_cd"][k], out["feature_an"][k] = feat[st % 10], feat[st // 10]
                out["xyz"].append(r["points"])
                out["gaps"].append(r["gaps"])
    for out in outs:
        out["group"], out["pair"] = groups_and_pairs(out["points"], out["feature_cd"], out["feature_an"])
    return outs


class LmgcTables(list):
    """A list of :class:`LmgcShape` (one per shape) with the shapes padded
    to common sizes for the vectorised detection: ``V`` (S, Vmax, 3)
    vertices, ``vmask`` (S, Vmax), ``corner`` (S, Vmax), ``N`` (S, Tmax, 3)
    triangle normals, ``tmask`` (S, Tmax), ``tri`` (S, Tmax, 3) and ``rmin``
    the smallest shape radius.

    Parameters
    ----------
    shapes : iterable of LmgcShape
        The shapes, in shape-row order (at least one).

    Attributes
    ----------
    V : ndarray, shape (S, Vmax, 3)
        m, local vertices, padded with 0.
    vmask : ndarray of bool, shape (S, Vmax)
        True for a vertex.
    corner : ndarray of bool, shape (S, Vmax)
        True for a topological corner (:attr:`LmgcShape.corner`).
    N : ndarray, shape (S, Tmax, 3)
        Unit outward triangle normals, padded with 0.
    tmask : ndarray of bool, shape (S, Tmax)
        True for a triangle.
    tri : ndarray of int64, shape (S, Tmax, 3)
        Triangles (vertex indices), padded with each shape's first.
    rmin : float
        m, the smallest shape radius (largest centre-vertex distance), the
        smallest grain radius d/2 of the shapes.
    """

    def __init__(self, shapes):
        super().__init__(shapes)
        S = len(self)
        Vm = max(len(x.vertices) for x in self)
        Tm = max(len(x.triangles) for x in self)
        self.V = np.zeros((S, Vm, 3))
        self.vmask = np.zeros((S, Vm), bool)
        self.corner = np.zeros((S, Vm), bool)
        self.N = np.zeros((S, Tm, 3))
        self.tmask = np.zeros((S, Tm), bool)
        self.tri = np.zeros((S, Tm, 3), np.int64)
        for k, x in enumerate(self):
            nv, nt = len(x.vertices), len(x.triangles)
            self.V[k, :nv], self.vmask[k, :nv], self.corner[k, :nv] = x.vertices, True, x.corner
            self.N[k, :nt], self.tmask[k, :nt], self.tri[k, :nt] = x.normals, True, x.triangles
            self.tri[k, nt:] = x.triangles[0]
        self.rmin = min(x.radius for x in self) if S else 0.0


def _cross_rows(a, b):
    """Row-wise cross products of (n, 3) arrays."""
    return np.stack([a[:, 1] * b[:, 2] - a[:, 2] * b[:, 1], a[:, 2] * b[:, 0] - a[:, 0] * b[:, 2],
                     a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]], 1)


def _unit_rows(a):
    return a / np.sqrt(np.einsum("ij,ij->i", a, a))[:, None]


def _comp_rep_rows(n):
    """comp_rep for each row of n (n, 3): (t, s)."""
    t = np.empty_like(n)
    a0, a1, a2 = np.abs(n[:, 0]) < 1e-15, np.abs(n[:, 1]) < 1e-15, np.abs(n[:, 2]) < 1e-15
    c0 = a0
    c1 = ~a0 & a1
    c2 = ~a0 & ~a1 & a2
    c3 = ~(a0 | a1 | a2)
    t[c0] = np.stack([n[c0, 0], -n[c0, 2], n[c0, 1]], 1)
    t[c1] = np.stack([-n[c1, 2], n[c1, 1], n[c1, 0]], 1)
    t[c2] = np.stack([-n[c2, 1], n[c2, 0], n[c2, 2]], 1)
    x = np.zeros_like(n[c3])
    x[:, 0] = 1.0
    t[c3] = _cross_rows(x, n[c3])
    t = _unit_rows(t)
    return t, _cross_rows(t, n)


def _detect_block(T, s_cd, R_cd, p_cd, s_an, R_an, p_an, adist, iterations, ref_size, neighbor):
    """Shadow overlap, Cundall's plane and the band for a block of pairs,
    vectorised (the same steps as :func:`lmgc90_pair`). Returns a dict of
    arrays; ``ok`` (B,) False where the pair is no contact at ``adist``;
    ``reach`` (B,) m the smallest alert distance at which the shadow
    overlap keeps the pair (``ok`` at an alert distance a <= adist is
    ``ok & (reach <= a)``: nothing else of the detection depends on it)."""
    B = len(s_cd)
    XC = np.einsum("bij,bvj->bvi", R_cd, T.V[s_cd]) + p_cd[:, None, :]
    XA = np.einsum("bij,bvj->bvi", R_an, T.V[s_an]) + p_an[:, None, :]
    NC = np.einsum("bij,btj->bti", R_cd, T.N[s_cd])
    NA = np.einsum("bij,btj->bti", R_an, T.N[s_an])
    mC, mA = T.vmask[s_cd], T.vmask[s_an]
    tC, tA = T.tmask[s_cd], T.tmask[s_an]
    triC, triA = T.tri[s_cd], T.tri[s_an]
    rows = np.arange(B)
    supC = np.einsum("btk,btk->bt", XC[rows[:, None], triC[:, :, 0]], NC)
    supA = np.einsum("btk,btk->bt", XA[rows[:, None], triA[:, :, 0]], NA)
    sep = _unit_rows(p_cd - p_an)
    gap = (np.where(mC, np.einsum("bvk,bk->bv", XC, sep), np.inf).min(axis=1)
           - np.where(mA, np.einsum("bvk,bk->bv", XA, sep), -np.inf).max(axis=1))
    ok = gap <= adist
    # antagonist faces turned to the candidate, against every candidate vertex
    va = (np.einsum("btk,bk->bt", NA, sep) >= -_TOL_NORMALES) & tA
    DA = np.where(mC[:, :, None], np.einsum("bvk,btk->bvt", XC, NA), np.inf).min(axis=1) - supA
    vc = (np.einsum("btk,bk->bt", NC, sep) <= _TOL_NORMALES) & tC
    DC = np.where(mA[:, :, None], np.einsum("bvk,btk->bvt", XA, NC), np.inf).min(axis=1) - supC
    ok &= ~np.any(va & (DA > adist), axis=1) & ~np.any(vc & (DC > adist), axis=1)
    DAm = np.where(va, DA, -np.inf)
    DCm = np.where(vc, DC, -np.inf)
    reach = np.maximum(gap, np.maximum(DAm.max(axis=1), DCm.max(axis=1)))
    e_an, e_cd = DAm.argmax(axis=1), DCm.argmax(axis=1)
    g_an, g_cd = DAm[rows, e_an], DCm[rows, e_cd]
    has_an, has_cd = g_an > gap, g_cd > gap
    n_an, n_cd = NA[rows, e_an], NC[rows, e_cd]
    both = has_an & has_cd
    new_sep = sep.copy()
    new_gap = gap.copy()
    if both.any():
        new_sep[both] = _unit_rows((n_an[both] - n_cd[both]) * 0.5)
        new_gap[both] = (g_cd[both] + g_an[both]) * 0.5
    only_cd = has_cd & ~has_an
    new_sep[only_cd], new_gap[only_cd] = -n_cd[only_cd], g_cd[only_cd]
    only_an = has_an & ~has_cd
    new_sep[only_an], new_gap[only_an] = n_an[only_an], g_an[only_an]
    # visible vertices: those of the turned faces, corners only
    visC = np.zeros((B, XC.shape[1]), bool)
    visA = np.zeros((B, XA.shape[1]), bool)
    r3 = np.broadcast_to(rows[:, None, None], triC.shape)
    visC[r3[vc], triC[vc]] = True
    r3 = np.broadcast_to(rows[:, None, None], triA.shape)
    visA[r3[va], triA[va]] = True
    visC &= T.corner[s_cd]
    visA &= T.corner[s_an]
    ok &= visC.any(axis=1) & visA.any(axis=1)
    out = {"ok": ok, "reach": reach, "XC": XC, "XA": XA, "NC": NC, "NA": NA, "sep": new_sep, "gap": new_gap}
    a = np.flatnonzero(ok)
    if not len(a):
        return out
    # Cundall's common plane, every pair of the block in step
    center = 0.5 * (p_an[a] + p_cd[a])
    Xc, Xa = XC[a] - center[:, None, :], XA[a] - center[:, None, :]
    vC, vA = visC[a], visA[a]
    n = new_sep[a].copy()
    dC = np.where(vC, np.einsum("bvk,bk->bv", Xc, n), np.inf)
    dA = np.where(vA, np.einsum("bvk,bk->bv", Xa, n), -np.inf)
    jmin, imax = dC.argmin(axis=1), dA.argmax(axis=1)
    ra = np.arange(len(a))
    p1 = XA[a][ra, imax] - XC[a][ra, jmin]
    t = p1 - np.einsum("bk,bk->b", p1, n)[:, None] * n
    nt = np.sqrt(np.einsum("bk,bk->b", t, t))
    small = nt < 1e-6 * ref_size
    t0, s0 = _comp_rep_rows(n)
    t = np.where(small[:, None], t0, t / np.where(small, 1.0, nt)[:, None])
    s = np.where(small[:, None], s0, _cross_rows(t, n))
    g = dC[ra, jmin] - dA[ra, imax]
    angle = np.full(len(a), _LMGC_THETA_MAX)
    live = np.ones(len(a), bool)
    cr, sr = math.cos(2 * _LMGC_PI / _NB_ROT), math.sin(2 * _LMGC_PI / _NB_ROT)
    for _ in range(iterations):
        L = np.flatnonzero(live)
        if not len(L):
            break
        nL, tL, sL = n[L], t[L], s[L]
        co, si = np.cos(angle[L])[:, None], np.sin(angle[L])[:, None]
        n_ite = np.empty((len(L), _NB_ROT, 3))
        t_ite = np.empty((len(L), _NB_ROT, 3))
        for k in range(_NB_ROT):
            tL = _unit_rows(cr * tL + sr * sL)
            t_ite[:, k] = tL
            sL = _cross_rows(tL, nL)
            n_ite[:, k] = _unit_rows(co * nL + si * tL)
        t[L], s[L] = tL, sL                        # LMGC90 carries the turned tangent over
        DcL = np.where(vC[L][:, None, :], np.einsum("bkj,bvj->bkv", n_ite, Xc[L]), np.inf)
        DaL = np.where(vA[L][:, None, :], np.einsum("bkj,bvj->bkv", n_ite, Xa[L]), -np.inf)
        gk = DcL.min(axis=2) - DaL.max(axis=2)                     # (L, 8)
        best = gk.argmax(axis=1)
        rl = np.arange(len(L))
        gbest = gk[rl, best]
        better = gbest > g[L]
        gap_ini = g[L]
        Lb = L[better]
        g[Lb] = gbest[better]
        jmin[Lb] = DcL[rl[better], best[better]].argmin(axis=1)
        imax[Lb] = DaL[rl[better], best[better]].argmax(axis=1)
        accept = better & ((gbest - gap_ini) / ref_size >= GAP_TOL)
        La = L[accept]
        n[La] = n_ite[rl[accept], best[accept]]
        t[La] = t_ite[rl[accept], best[accept]]
        s[La] = _cross_rows(t[La], n[La])
        Lr = L[~accept]
        halve = angle[Lr] >= _LMGC_THETA_MIN
        angle[Lr[halve]] *= 0.5
        live[Lr[~halve]] = False
    n = _unit_rows(n)
    t, s = _comp_rep_rows(n)
    xc, xa = XC[a][ra, jmin], XA[a][ra, imax]
    g = np.einsum("bk,bk->b", xc - center, n) - np.einsum("bk,bk->b", xa - center, n)
    cpt = 0.5 * (xa + xc)
    # the band
    ref = np.minimum(np.abs(np.einsum("bk,bk->b", xa - p_an[a], n)), np.abs(np.einsum("bk,bk->b", xc - p_cd[a], n)))
    d1 = np.maximum(0.0, g * 0.5) + neighbor * ref
    hc = np.einsum("bvk,bk->bv", XC[a] - cpt[:, None, :], n)
    ha = np.einsum("bvk,bk->bv", XA[a] - cpt[:, None, :], n)
    kC = np.where(vC, np.where(hc > d1[:, None], -1, 1), 0)
    kA = np.where(vA, np.where(ha < -d1[:, None], -1, 1), 0)
    kC[ra, jmin] = 2
    kA[ra, imax] = 2
    out.update({"a": a, "normal": n, "t": t, "s": s, "plane_gap": g, "jmin": jmin, "imax": imax, "center": cpt,
                "kC": kC, "kA": kA, "ref": ref, "hc": hc, "ha": ha})
    return out


class _Posed:
    """A posed body for the point stage, from the block's arrays."""

    __slots__ = ("shape", "X", "N", "FN", "c", "support")

    def __init__(self, shape, X, R, x):
        self.shape = shape
        self.X = X[:len(shape.vertices)]
        self.FN = shape.face_normal @ R.T
        self.c = x
