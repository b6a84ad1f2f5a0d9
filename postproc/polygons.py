"""Convex sets of 2-D points on a common plane, for the point stages of
LMGC90's count (:mod:`postproc.lmgc90count`): the exact convex hull, the
Sutherland-Hodgman clip and the simplification of planplan's Clipper2
route, the reduction of a polygon to its :data:`MAX_POINTS` sharpest
corners, and the length-tolerant intersection of the 2009 route
(:func:`convex_set_2d`, :func:`tolerant_intersection`).

Pure functions over (k, 2) arrays of coordinates in the plane (m); no
file I/O. The helpers with a leading underscore are shared with
:mod:`postproc.lmgc90count` and :mod:`postproc.commonplane` only.
"""
from __future__ import annotations

import numpy as np

from .errors import InputError

MAX_POINTS = 4                # LMGC90 keeps at most 4 contact points of a pair


def _cross2(u, v):
    """z component of the cross product of two 2-D vectors."""
    return u[0] * v[1] - u[1] * v[0]


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
        Length tolerance (m), >= 0. The route uses :data:`postproc.lmgc90count.TOL_2009` times
        the band's reference length (:func:`postproc.lmgc90count.lmgc90_pair`).
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
