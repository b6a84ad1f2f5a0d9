"""LMGC90's own count of contact points: its CpCundall detection, point
stage and all.

:func:`lmgc90_points` (``--types lmgc90``, ``lmgc90-planplan`` and
``lmgc90-2009``) ports, step by step, what LMGC90's
``wcp_compute_contact_PRPRx`` does for one pair of convex POLYR bodies
(``DETECTION_COMMON_PLANE`` of ``mod_PRPRx.f90``, with the geometry of
``mod_DiscreteGeometry.f90`` and the face topology of ``mod_POLYR.f90``,
:mod:`postproc.lmgc90shape`): shadow overlap, Cundall's plane as LMGC90
iterates it, the band, the contact-type stage and a point stage, so that
the count is LMGC90's, not a count of the same idea. It gives LMGC90's
compiled count on 99 % of the grain pairs of our packings
(docs/lmgc90-contacts.md, tests/test_lmgc90_fixtures.py). Three routes
(:data:`LMGC90_ROUTES`): ``"lmgc90"`` (today's default point stage,
``new_ccpm = .true.``), ``"lmgc90-planplan"`` (the older route,
``use_old_ccpm_PRPRx``: planplan, the hulls intersected by Clipper2) and
``"lmgc90-2009"`` (the older route with the length-tolerant intersection
planplan used before Clipper2,
:func:`postproc.polygons.tolerant_intersection`, written from its
description; presumably the paper's, not checked against a 2009 LMGC90).

The band tolerance, Cundall's search constants and the rule from points to
groups and pair types are those of the band count
(:mod:`postproc.commonplane`). Pure functions over arrays; no file I/O;
blocks of pairs are vectorised up to the band, the point stage loops over
pairs.
"""
from __future__ import annotations

import math

import numpy as np

from shapes.overlap import rotation_matrices

from .commonplane import BLOCK, DEFAULT_NEIGHBOR, GAP_TOL, NB_ROT, check_neighbor, groups_and_pairs
from .contactpoints import check_pose_arrays, positive_tolerance
from .contacttypes import EDGE, FACE, VERTEX
from .errors import InputError
from .lmgc90shape import LmgcTables
from .polygons import MAX_POINTS, _area2, _clip_convex, _hull2, _sharpest_corners, _simplify, tolerant_intersection

LMGC90_ROUTES = ("lmgc90", "lmgc90-planplan", "lmgc90-2009")
DEFAULT_ALERT = 0.1           # alert distance, in units of the smallest grain radius (LMGC90's examples)
LMGC90_ITERATIONS = 200       # cundall_iter: the compas_lmgc90 glue's value (LMGC90's module default: 100)
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
    cr, sr = math.cos(2 * _LMGC_PI / NB_ROT), math.sin(2 * _LMGC_PI / NB_ROT)
    # the 3-vectors as Python floats: eight trial normals per round, built
    # one from the other as LMGC90 does (t is not re-orthogonalised)
    nx, ny, nz = (float(v) for v in normal)
    tx, ty, tz = (float(v) for v in t)
    sx, sy, sz = (float(v) for v in s)
    XcT, XaT = Xc[jc].T, Xa[ia].T
    n_ite, t_ite = np.empty((NB_ROT, 3)), np.empty((NB_ROT, 3))
    for _ in range(iterations):
        co, si = math.cos(angle), math.sin(angle)
        for k in range(NB_ROT):
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
        for k in range(NB_ROT):
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


def _planplan_2009(cd, an, cd_vis, an_vis, center, t, normal, s, tol):
    """planplan with the length-tolerant intersection (the 2009 route): the
    kept vertices of each side projected on the common plane (LMGC90's
    (s, t) coordinates), :func:`postproc.polygons.tolerant_intersection` with tol (m).
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

    tables : list of :class:`postproc.lmgc90shape.LmgcShape` (:func:`postproc.lmgc90shape.lmgc90_tables`). shape_cd,
    shape_an (C,) int shape rows of the candidate and the antagonist (in
    LMGC90 the candidate is the body with the lower number); pos (C, 3) m
    centres of mass; quat (C, 4) (w, x, y, z) local -> global. alert : the
    alert distance (m; pairs whose gap exceeds it have no point, and with
    route "lmgc90" so has every point whose own gap exceeds it). route :
    "lmgc90" (today's default point stage), "lmgc90-planplan" (the older
    route: planplan, the hulls intersected by Clipper2, so 3 or 4 points or
    none) or "lmgc90-2009" (the older route with the intersection planplan
    used before Clipper2, which has a length tolerance:
    :func:`postproc.polygons.tolerant_intersection`, so a point or a segment gives 1 or 2
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
        The shapes (:func:`postproc.lmgc90shape.lmgc90_tables`).
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
    for b0 in range(0, C, BLOCK):
        sl = slice(b0, min(b0 + BLOCK, C))
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
    cr, sr = math.cos(2 * _LMGC_PI / NB_ROT), math.sin(2 * _LMGC_PI / NB_ROT)
    for _ in range(iterations):
        L = np.flatnonzero(live)
        if not len(L):
            break
        nL, tL, sL = n[L], t[L], s[L]
        co, si = np.cos(angle[L])[:, None], np.sin(angle[L])[:, None]
        n_ite = np.empty((len(L), NB_ROT, 3))
        t_ite = np.empty((len(L), NB_ROT, 3))
        for k in range(NB_ROT):
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
