"""The reduction of a grain's hull to a vertex budget, and its error:
steps 3 and 4 of a mesh's import (:mod:`shapes.meshimport`, whose module
docstring says what they do).

:class:`Budget` is the budget (a vertex count, or an error target with a
cap); :func:`reduce_hull` chooses the reduced grain's vertices among the
hull's along one sequence of valid sets (:func:`thin_points` thins a hull
of more than ``MAX_CANDIDATES`` vertices first); :func:`distance_to_convex`
and :func:`hausdorff_to_convex` measure, exactly, how far points lie from a
convex polyhedron and so the reduction's Hausdorff error. Pure functions
over arrays; lengths in the mesh's units, errors relative to d_hull.
"""
from __future__ import annotations

from collections import Counter
from dataclasses import dataclass

import numpy as np

from .polyhedron import (COPLANAR_DEG, CREASE_DEG, HEIGHT_TOL, VERTEX_TOL, ShapeError, bend_angles, geometric_faces,
                         triangle_normals)

#: points within this distance (relative to d_hull) of a hull count as on it
ZERO_ERROR = 1e-6
#: default error target of ``python -m shapes import`` (relative to d_hull):
#: see docs/shapes-import.md for how it was chosen
DEFAULT_MAX_ERROR = 0.02
DEFAULT_MAX_VERTICES = 37
#: above this many hull vertices the greedy runs on a thinned subset
MAX_CANDIDATES = 30000
#: a vertex removed by a repair bans the points this near it (units of d_hull)
BAN_RADIUS = 0.005


@dataclass
class Budget:
    """The vertex budget of the reduction (:func:`reduce_hull`): a vertex
    count, or an error target with a cap on the count.

    Exactly one of ``vertices`` and ``max_error`` is set; as ``max_error``
    defaults to ``DEFAULT_MAX_ERROR``, a vertex count is asked for with
    ``Budget(vertices=N, max_error=None)``. Invalid values raise
    ValueError.

    Parameters
    ----------
    vertices : int or None
        Reduce to exactly this many vertices (at least 4; fewer only when
        the hull has fewer).
    max_error : float or None
        The error target, relative to d_hull, in [0, 1): the first valid
        set of :func:`reduce_hull`'s sequence whose hull is within
        max_error x d_hull of the full hull (Hausdorff distance), or else
        the valid set of least error. Default ``DEFAULT_MAX_ERROR``
        (0.02).
    max_vertices : int
        At most this many vertices with ``max_error`` (at least 4; default
        ``DEFAULT_MAX_VERTICES``, 37, the published library's largest
        count).

    Attributes
    ----------
    vertices, max_error, max_vertices
        The parameters, as given.
    cap : int
        The most vertices the reduction may keep.

    Examples
    --------
    >>> Budget(), Budget().cap
    (Budget(vertices=None, max_error=0.02, max_vertices=37), 37)
    >>> Budget(vertices=12, max_error=None).as_dict()
    {'vertices': 12, 'max_error': None, 'max_vertices': None}
    >>> Budget(vertices=12)
    Traceback (most recent call last):
    ...
    ValueError: set exactly one of vertices and max_error
    """

    vertices: int | None = None
    max_error: float | None = DEFAULT_MAX_ERROR
    max_vertices: int = DEFAULT_MAX_VERTICES

    def __post_init__(self):
        if (self.vertices is None) == (self.max_error is None):
            raise ValueError("set exactly one of vertices and max_error")
        if self.vertices is not None and self.vertices < 4:
            raise ValueError(f"the vertex budget must be at least 4, got {self.vertices}")
        if self.max_error is not None and not (0 <= self.max_error < 1):
            raise ValueError(f"max_error is relative to d and must be in [0, 1), got {self.max_error}")
        if self.max_vertices < 4:
            raise ValueError(f"max_vertices must be at least 4, got {self.max_vertices}")

    @property
    def cap(self):
        """The most vertices the reduction may keep (int): ``vertices``
        when set, else ``max_vertices``."""
        return self.vertices if self.vertices is not None else self.max_vertices

    def as_dict(self):
        """The budget as stored in an imported library's recipe.

        Returns
        -------
        dict
            ``vertices``, ``max_error`` and ``max_vertices`` (None when a
            vertex count is set, as it does not apply).
        """
        return {"vertices": self.vertices, "max_error": self.max_error,
                "max_vertices": None if self.vertices is not None else self.max_vertices}


def _planes(vertices, triangles):
    n, _ = triangle_normals(vertices, triangles)
    off = -np.einsum("ij,ij->i", n, vertices[triangles[:, 0]])
    return n, off


def _segment_distance(p, a, b):
    """Distances (N, E) from points p (N, 3) to segments a-b (E, 3)."""
    ab = b - a                                            # (E, 3)
    ap = p[:, None, :] - a[None, :, :]                    # (N, E, 3)
    den = np.einsum("ij,ij->i", ab, ab)
    s = np.clip(np.einsum("nej,ej->ne", ap, ab) / np.where(den > 0, den, 1.0), 0.0, 1.0)
    diff = ap - s[..., None] * ab[None, :, :]
    return np.sqrt(np.einsum("nej,nej->ne", diff, diff))


def _inside_triangles(p, vertices, triangles, n):
    """(N, T) bool: the projection of p onto each triangle's plane falls in it."""
    a = vertices[triangles[:, 0]]
    b = vertices[triangles[:, 1]]
    c = vertices[triangles[:, 2]]
    inside = np.ones((len(p), len(triangles)), bool)
    for x, y in ((a, b), (b, c), (c, a)):
        # the projection is on the inner side of edge x->y: (y-x) x (p-x) . n >= 0
        e = np.cross(y - x, n)                             # points outward of the edge, in plane
        inside &= np.einsum("nej,ej->ne", p[:, None, :] - x[None, :, :], e) <= 0
    return inside


def distance_to_convex(points, vertices, triangles, chunk=4096):
    """Exact Euclidean distances from points to a convex polyhedron.

    For a point outside, the distance is at least its largest signed plane
    distance h_max, with equality when its projection on that plane lies in
    the triangle (the first pass, one matrix product). Otherwise the nearest
    point lies on an edge or in a coplanar neighbour: the distance is the
    least of the point-segment distances to every edge and of h over the
    triangles that contain the point's projection (each is the distance to a
    point of the polyhedron, and the nearest point is among them).

    Parameters
    ----------
    points : (N, 3) float
        The points, any units.
    vertices : (V, 3) float
        The polyhedron's vertices, same units.
    triangles : (T, 3) int
        Its triangles, counter-clockwise seen from outside (outward).
    chunk : int
        Points handled at a time (it bounds the size of the intermediate
        arrays).

    Returns
    -------
    (N,) float
        The distances, same units; 0 for points inside or on the surface.

    Examples
    --------
    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((0, 1), repeat=3)), float))    # unit cube
    >>> distance_to_convex([[0.5, 0.5, 0.5], [2, 0.5, 0.5], [2, 2, 0.5], [2, 2, 2]], v, t).round(6)
    array([0.      , 1.      , 1.414214, 1.732051])
    """
    p = np.asarray(points, float)
    v = np.asarray(vertices, float)
    t = np.asarray(triangles)
    n, off = _planes(v, t)
    edges = np.unique(np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1), axis=0)
    out = np.zeros(len(p))
    for s in range(0, len(p), chunk):
        q = p[s:s + chunk]
        h = (n @ np.ascontiguousarray(q.T) + off[:, None]).T
        k = np.argmax(h, axis=1)
        hmax = h[np.arange(len(q)), k]
        outside = np.flatnonzero(hmax > 0)
        if not len(outside):
            continue
        qo = q[outside]
        tk = t[k[outside]]
        proj = qo - hmax[outside, None] * n[k[outside]]
        ok = np.ones(len(outside), bool)
        for x, y in ((0, 1), (1, 2), (2, 0)):
            e = np.cross(v[tk[:, y]] - v[tk[:, x]], n[k[outside]])
            ok &= np.einsum("ij,ij->i", proj - v[tk[:, x]], e) <= 0
        d = hmax[outside].copy()
        hard = np.flatnonzero(~ok)
        if len(hard):
            qh = qo[hard]
            seg = _segment_distance(qh, v[edges[:, 0]], v[edges[:, 1]]).min(axis=1)
            hh = h[outside[hard]]
            face = np.where(_inside_triangles(qh, v, t, n) & (hh >= 0), hh, np.inf).min(axis=1)
            d[hard] = np.minimum(seg, face)
        out[s + outside] = d
    return out


def _hull_of(q):
    """Hull of points q (k, 3) in scaled coordinates: (vertex positions in
    q (m,), outward triangles (T, 3) as indices into those, plane normals,
    offsets), or None when flat."""
    from scipy.spatial import ConvexHull, QhullError

    try:
        h = ConvexHull(q)
    except QhullError:
        return None
    verts = np.sort(h.vertices)
    remap = np.full(len(q), -1)
    remap[verts] = np.arange(len(verts))
    tri = remap[h.simplices]
    n, _ = triangle_normals(q[verts], tri)
    flip = np.einsum("ij,ij->i", n, h.equations[:, :3]) < 0
    tri[flip] = tri[flip][:, [0, 2, 1]]
    return verts, tri


def _defects(vq, tri):
    """The defects that would fail the validity checks of a chosen hull (vq
    (m, 3), outward triangles), each as (kind, the local indices of the
    vertices involved): two vertices closer than VERTEX_TOL d; the two triangles'
    four vertices at an edge bending by COPLANAR_DEG to CREASE_DEG; a
    sliver triangle's three. Empty when there are none."""
    from scipy.spatial.distance import pdist, squareform

    out = []
    d = 2 * np.max(np.linalg.norm(vq - vq.mean(axis=0), axis=1))
    dist = squareform(pdist(vq))
    np.fill_diagonal(dist, np.inf)
    i, j = np.nonzero(np.triu(dist < VERTEX_TOL * d))
    out += [("close vertices", (int(a), int(b))) for a, b in zip(i, j)]
    edges, pairs, bend = bend_angles(vq, tri)
    for k in np.flatnonzero((bend >= COPLANAR_DEG) & (bend < CREASE_DEG)):
        out.append(("nearly flat edge",
                    tuple(int(x) for x in np.unique(np.concatenate([tri[pairs[k, 0]], tri[pairs[k, 1]]])))))
    tf = geometric_faces(vq, tri)
    own = np.bincount(tf, minlength=tf.max() + 1)[tf] == 1
    _, area = triangle_normals(vq, tri)
    longest = np.max(np.stack([np.linalg.norm(vq[tri[:, a]] - vq[tri[:, (a + 1) % 3]], axis=1)
                               for a in range(3)]), axis=0)
    out += [("sliver triangle", tuple(int(x) for x in tri[k]))
            for k in np.flatnonzero(own & (2 * area / longest < HEIGHT_TOL * d))]
    return out


def _initial_simplex(q):
    """Indices of four extreme, non-coplanar points of q (N, 3), or None."""
    i0 = int(np.argmax(np.einsum("ij,ij->i", q - q.mean(axis=0), q - q.mean(axis=0))))
    i1 = int(np.argmax(np.linalg.norm(q - q[i0], axis=1)))
    u = q[i1] - q[i0]
    if not np.linalg.norm(u):
        return None
    u /= np.linalg.norm(u)
    r = q - q[i0]
    i2 = int(np.argmax(np.linalg.norm(r - np.outer(r @ u, u), axis=1)))
    nrm = np.cross(u, q[i2] - q[i0])
    if not np.linalg.norm(nrm):
        return None
    i3 = int(np.argmax(np.abs(r @ nrm)))
    out = [i0, i1, i2, i3]
    return out if len(set(out)) == 4 else None


def hausdorff_to_convex(points, vertices, triangles, chunk=4096):
    """The largest distance from points to a convex polyhedron, and which
    point attains it: the maximum of :func:`distance_to_convex`, with the
    exact distance computed only where it can matter. For points whose
    convex hull contains the polyhedron (a full hull and a reduced one), it
    is their Hausdorff distance.

    Each point has a lower bound L (its largest signed plane distance) and
    an upper bound U (its distance to where the segment from it to the
    vertices' mean enters the polyhedron, a point of the polyhedron). Points
    are taken by decreasing U, exact distances computed chunk by chunk,
    until the next U is below the best exact distance found.

    Parameters
    ----------
    points : (N, 3) float
        The points, any units.
    vertices : (V, 3) float
        The polyhedron's vertices, same units.
    triangles : (T, 3) int
        Its triangles, counter-clockwise seen from outside.
    chunk : int
        Points whose exact distance is computed at a time.

    Returns
    -------
    distance : float
        The largest distance, same units (0 when every point is inside or
        on the surface).
    index : int
        The point attaining it, -1 when every point is inside or on the
        surface.

    Examples
    --------
    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((0, 1), repeat=3)), float))    # unit cube
    >>> hausdorff_to_convex([[0.5, 0.5, 0.5], [2, 0.5, 0.5], [2, 2, 0.5]], v, t)
    (1.414213562373095..., 2)
    >>> hausdorff_to_convex([[0.5, 0.5, 0.5]], v, t)
    (0.0, -1)
    """
    p = np.asarray(points, float)
    v = np.asarray(vertices, float)
    t = np.asarray(triangles)
    if not len(p):
        return 0.0, -1
    n, off = _planes(v, t)
    c = v.mean(axis=0)
    g = n @ c + off                                     # (T,) < 0: the mean is inside
    lo = np.empty(len(p))
    hi = np.empty(len(p))
    for s in range(0, len(p), 65536):
        qt = np.ascontiguousarray(p[s:s + 65536].T)
        h = n @ qt + off[:, None]                       # (T, chunk)
        lo[s:s + 65536] = h.max(axis=0)
        # the ray c + tau (x - c) leaves the polyhedron at the least tau_f over faces it approaches
        rise = h - g[:, None]
        with np.errstate(divide="ignore"):
            tau = np.where(rise > 0, -g[:, None] / rise, np.inf).min(axis=0)
        hi[s:s + 65536] = np.clip(1.0 - tau, 0.0, None) * np.linalg.norm(qt - c[:, None], axis=0)
    out = lo > 0
    if not out.any():
        return 0.0, -1
    idx = np.flatnonzero(out)
    idx = idx[np.argsort(-hi[idx])]
    best, arg = float(lo[idx].max()), int(idx[np.argmax(lo[idx])])
    for s in range(0, len(idx), chunk):
        part = idx[s:s + chunk]
        if hi[part[0]] <= best:
            break
        d = distance_to_convex(p[part], v, t, chunk=chunk)
        k = int(np.argmax(d))
        if d[k] > best:
            best, arg = float(d[k]), int(part[k])
    return best, arg


class _Greedy:
    """The state of the greedy insertion over candidate points q (N, 3):
    for each live point its largest signed distance to the chosen hull's
    planes and that plane's id, updated face by face as the hull grows (only
    new faces are tested, and the points of removed faces re-tested): the
    bookkeeping of quickhull. Points inside the hull are dropped for good
    while the hull only grows; a repair (a removed vertex) resets it. The
    live points are kept transposed (3, L), the layout in which numpy's
    (k, 3) @ (3, L) products are fast."""

    def __init__(self, q):
        self.q = q
        self.reset()

    def reset(self):
        self.live = np.arange(len(self.q))
        self.qt = np.ascontiguousarray(self.q.T)
        self.h = None
        self.arg = None
        self.faces = {}
        self.next_id = 0

    def update(self, chosen, tri):
        """Planes of the hull of q[chosen] (outward triangles ``tri``); returns
        the largest signed plane distance (L,) of each live point."""
        keys = [tuple(sorted(x)) for x in np.asarray(chosen)[tri].tolist()]
        n, off = _planes(self.q[chosen], tri)
        fid = np.empty(len(keys), np.int64)
        fresh = []
        for k, key in enumerate(keys):
            if key in self.faces:
                fid[k] = self.faces[key]
            else:
                fid[k] = self.next_id
                self.next_id += 1
                fresh.append(k)
        if self.h is None:
            H = n @ self.qt + off[:, None]
            self.h = H.max(axis=0)
            self.arg = fid[H.argmax(axis=0)]
        else:
            now = set(keys)
            gone = np.array(sorted(f for key, f in self.faces.items() if key not in now), np.int64)
            if fresh:
                Hn = n[fresh] @ self.qt + off[fresh, None]
                m = Hn.max(axis=0)
                up = m > self.h
                self.h[up] = m[up]
                self.arg[up] = fid[fresh][Hn[:, up].argmax(axis=0)]
            if len(gone):
                redo = np.flatnonzero(np.isin(self.arg, gone))
                if len(redo):
                    H = n @ self.qt[:, redo] + off[:, None]
                    self.h[redo] = H.max(axis=0)
                    self.arg[redo] = fid[H.argmax(axis=0)]
        self.faces = dict(zip(keys, fid.tolist()))
        keep = self.h > 0
        keep[np.isin(self.live, chosen)] = False
        if not keep.all():
            self.live, self.h, self.arg = self.live[keep], self.h[keep], self.arg[keep]
            self.qt = np.ascontiguousarray(self.qt[:, keep])
        return self.h


def thin_points(q, max_points=MAX_CANDIDATES):
    """At most ``max_points`` of a point set, spread over it: one point per
    occupied cell of a cubic grid whose spacing starts at sqrt(pi /
    max_points) (a convex surface of size 1 has an area of at most pi) and
    grows by 1.5 until few enough cells are occupied.

    Parameters
    ----------
    q : (N, 3) float
        The points, at unit size (d = 1).
    max_points : int
        The most points kept (default ``MAX_CANDIDATES``).

    Returns
    -------
    (K,) int
        Sorted indices into ``q``, K <= max_points; all of them when N <=
        max_points.

    Examples
    --------
    >>> rng = np.random.default_rng(0)
    >>> q = rng.normal(size=(5000, 3))
    >>> q /= 2 * np.linalg.norm(q, axis=1)[:, None]            # on a sphere of d = 1
    >>> keep = thin_points(q, 500)
    >>> bool(100 < len(keep) <= 500), bool(np.all(np.diff(keep) > 0))
    (True, True)
    >>> thin_points(q[:10], 500).tolist()
    [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]
    """
    if len(q) <= max_points:
        return np.arange(len(q))
    delta = np.sqrt(np.pi / max_points)
    lo = q.min(axis=0)
    while True:
        cell = np.floor((q - lo) / delta).astype(np.int64)
        span = cell.max(axis=0) + 1
        key = (cell[:, 0] * span[1] + cell[:, 1]) * span[2] + cell[:, 2]
        _, first = np.unique(key, return_index=True)
        if len(first) <= max_points:
            return np.sort(first)
        delta *= 1.5


def _cheapest_removal(q, sub, chosen, involved, max_points=4000):
    """Of the chosen points at local indices ``involved``, the one (index
    into q) whose removal leaves the hull of the rest nearest to the points
    q[sub] (Hausdorff distance; over at most ``max_points`` of them, spread
    by :func:`thin_points`, as this only ranks the choices)."""
    if len(sub) > max_points:
        sub = sub[thin_points(q[sub], max_points)]
    best, arg = np.inf, chosen[involved[0]]
    for i in involved:
        rest = [k for j, k in enumerate(chosen) if j != i]
        hq = _hull_of(q[rest]) if len(rest) >= 4 else None
        if hq is None:
            continue
        err, _ = hausdorff_to_convex(q[sub], q[rest][hq[0]], hq[1])
        if err < best:
            best, arg = err, chosen[i]
    return arg


def reduce_hull(points, budget, d=None, max_steps=None, max_candidates=None, details=None):
    """Choose the reduced grain's vertices among the full hull's vertices,
    by greedy furthest-point insertion with validity repairs (module
    docstring, step 3).

    The search is one sequence of chosen sets, the same whatever the error
    target, in two passes from four extreme points. In the first, a valid
    set (one that passes the validity checks) grows by the point furthest
    outside its hull, until ``budget.cap`` vertices or until every point is
    on the hull, and a set that fails the checks is repaired at once (the
    vertex of its first defect whose loss costs least is removed, and the
    points within ``BAN_RADIUS`` of it are banned). The second pass starts
    again and grows through invalid sets, repairing only when it can grow
    no further (at the cap). Each pass has ``max_steps`` steps. The answer
    is the first valid set of the sequence that meets the budget (the
    error target, or the vertex count); when none does, the valid set of
    the least error seen. So a stricter target never gives a larger error:
    it stops later on the same sequence, or takes its best set (exact for
    hulls of up to ``max_candidates`` vertices; above, the sets are
    compared by their error on the thinned points).

    Above ``max_candidates`` points the greedy runs on a thinned subset
    (:func:`thin_points`) and the error is still measured on every point;
    once the thinned points are all on the hull, the worst of all points is
    added.

    Parameters
    ----------
    points : (N, 3) float
        The full hull's vertices, any units.
    budget : Budget
        A vertex count, or an error target with a cap.
    d : float, optional
        The full hull's size, in the points' units (default: twice the
        largest distance from the points' mean to a point); tolerances and
        errors are relative to it.
    max_steps : int, optional
        Steps (an addition or a repair) of each pass (default 20 x cap +
        100).
    max_candidates : int, optional
        Default ``MAX_CANDIDATES``.
    details : dict, optional
        Filled with what the search did: ``steps`` (int), ``repairs`` (a
        dict, defect kind -> count: ``close vertices``, ``nearly flat
        edge``, ``sliver triangle``), ``valid_sets`` (valid sets seen),
        ``reached_cap`` (whether a valid set had ``budget.cap`` vertices)
        and ``why`` (None when the budget is met, else one line: the
        vertex cap, or the validity checks that forbade the nearer
        choices, with the repairs).

    Returns
    -------
    indices : (k,) int
        The chosen points, indices into ``points``.
    triangles : (T, 3) int
        Their hull's outward triangles, as indices into ``indices`` (so
        ``points[indices][triangles]`` are the triangles' corners).
    error : float
        The exact Hausdorff distance between the chosen hull and the full
        one, in units of d.
    target_met : bool
        False when an error target was not reached: at
        ``budget.max_vertices``, or because the validity repairs forbade
        the nearer choices (for a vertex count: False when no valid set of
        that many vertices was found).

    Raises
    ------
    ShapeError
        When no valid polyhedron is found.

    Examples
    --------
    The 162 vertices of a geodesic sphere (d = 2), to 12 vertices, and to
    the fewest within 0.05 d:

    >>> import trimesh
    >>> ball = trimesh.creation.icosphere(subdivisions=2).vertices
    >>> idx, tri, err, met = reduce_hull(ball, Budget(vertices=12, max_error=None))
    >>> len(idx), tri.shape, round(err, 3), met
    (12, (20, 3), 0.202, True)
    >>> idx, tri, err, met = reduce_hull(ball, Budget(max_error=0.05))
    >>> len(idx), bool(err <= 0.05), met
    (35, True, True)

    A target the cap cannot reach: the best set found, and why.

    >>> info = {}
    >>> idx, tri, err, met = reduce_hull(ball, Budget(max_error=0.01, max_vertices=20), details=info)
    >>> len(idx), met
    (20, False)
    >>> print(info["why"])
    at the 20-vertex cap (--max-vertices): no valid set of up to 20 vertices met it (repairs of the
    validity checks: nearly flat edge 2)
    """
    p = np.asarray(points, float)
    c = p.mean(axis=0)
    d = d or 2 * np.max(np.linalg.norm(p - c, axis=1))
    q = (p - c) / d                     # unit-size coordinates: tolerances are absolute
    cap = min(budget.cap, len(q))
    stop = max(budget.max_error if budget.max_error is not None else 0.0, ZERO_ERROR)
    info = details if details is not None else {}
    repairs = Counter()
    info.update(steps=0, repairs=repairs, valid_sets=0, reached_cap=False, why=None)
    if len(q) <= cap and (budget.vertices is not None or stop <= ZERO_ERROR):
        # the whole hull fits the budget: it is the answer when it is a valid grain
        hq = _hull_of(q)
        if hq is not None and len(hq[0]) == len(q) and not _defects(q[hq[0]], hq[1]):
            info["valid_sets"], info["reached_cap"] = 1, True
            return hq[0], hq[1], 0.0, True
    sub0 = thin_points(q, max_candidates or MAX_CANDIDATES)
    first = _initial_simplex(q)
    if first is None:
        raise ShapeError("all points on a line or a plane: no volume")
    sub0 = np.union1d(sub0, first)
    thinned = len(sub0) < len(q)
    max_steps = max_steps or 20 * cap + 100
    valid = []                          # (error or a lower bound, vertices, chosen, tri, exact?) of valid sets

    def met(n, err):
        return n == cap or err <= ZERO_ERROR if budget.vertices is not None else err <= stop

    def walk(eager):
        """One pass of the sequence: the first valid set that meets the
        budget, or None (``valid`` then holds the valid sets seen)."""
        sub = sub0
        chosen = list(first)            # indices into q
        banned = np.zeros(len(q), bool)
        greedy = _Greedy(q[sub])
        pos = {int(k): i for i, k in enumerate(sub)}

        def crowded(pts):
            """Points within VERTEX_TOL d of a chosen vertex (d as the checks
            take it): they cannot be vertices of a valid grain."""
            from scipy.spatial import cKDTree

            cq = q[chosen]
            r = VERTEX_TOL * 2 * np.max(np.linalg.norm(cq - cq.mean(axis=0), axis=1))
            if not len(pts):
                return np.zeros(0, bool)
            dist, _ = cKDTree(cq).query(pts, distance_upper_bound=r)
            return dist < r

        for _ in range(max_steps):
            info["steps"] += 1
            hq = _hull_of(q[chosen])
            if hq is None:
                raise ShapeError("the chosen points are coplanar: no volume")
            chosen, tri = [chosen[k] for k in hq[0]], hq[1]      # qhull drops points on a face
            h = greedy.update([pos[k] for k in chosen], tri)
            bad = _defects(q[chosen], tri)
            if not bad:
                info["valid_sets"] += 1
                info["reached_cap"] |= len(chosen) >= cap
                lower = float(h.max()) if len(h) else 0.0       # a plane distance: at most the error
                if met(len(chosen), lower):
                    err, _ = hausdorff_to_convex(q[sub], q[chosen], tri)
                    full = hausdorff_to_convex(q, q[chosen], tri)[0] if thinned and met(len(chosen), err) else err
                    if met(len(chosen), full):
                        return np.array(chosen), tri, float(full), True
                    # compared later by the error on the first thinned points
                    valid.append((lower, len(chosen), list(chosen), tri, False) if thinned else
                                 (err, len(chosen), list(chosen), tri, True))
                else:                   # its error is needed only if it may be the best: later
                    valid.append((lower, len(chosen), list(chosen), tri, False))
            grow = None
            if len(chosen) < cap and not (eager and bad):
                live = sub[greedy.live]
                cand = np.flatnonzero(~banned[live])
                cand = cand[~crowded(q[live[cand]])]
                if len(cand) and h[cand].max() > ZERO_ERROR:
                    grow = int(live[cand[np.argmax(h[cand])]])
                else:
                    # the planes say done: the exact distances of every eligible point decide
                    idx = live if not thinned else np.arange(len(q))
                    idx = idx[~banned[idx]]
                    idx = idx[~crowded(q[idx])]
                    err, k = hausdorff_to_convex(q[idx], q[chosen], tri)
                    if err > ZERO_ERROR:
                        grow = int(idx[k])
                        if grow not in pos:     # a point the thinning left out: the greedy takes it in
                            sub = np.union1d(sub, [grow])
                            pos = {int(x): i for i, x in enumerate(sub)}
                            greedy = _Greedy(q[sub])
            if grow is not None:
                chosen.append(grow)
                continue
            if not bad:
                return None             # valid, and nothing left to add: the pass ends
            # repair the first defect: drop the vertex involved whose loss costs least (the error
            # over the greedy's points), and ban the points within BAN_RADIUS of it
            kind, involved = bad[0]
            repairs[kind] += 1
            drop = _cheapest_removal(q, sub, chosen, involved)
            banned |= np.linalg.norm(q - q[drop], axis=1) < BAN_RADIUS
            chosen = [k for k in chosen if k != drop]
            greedy.reset()              # the hull shrank: points inside may be outside again
            if len(chosen) < 4:
                return None
        return None

    for eager in (True, False):         # repairs at once, then (a second pass) only at the cap
        found = walk(eager)
        if found is not None:
            return found
    if not valid:
        raise ShapeError(f"no valid polyhedron in {info['steps']} steps ({_kinds(repairs)})")
    # the valid set of least error (then fewest vertices): exact errors by increasing lower bound,
    # until the next bound exceeds the best error found (on the thinned points above max_candidates)
    best = None
    for bound, n, chosen, tri, exact in sorted(valid, key=lambda s: s[:2]):
        if best is not None and bound > best[0]:
            break
        err = bound if exact else hausdorff_to_convex(q[sub0], q[chosen], tri)[0]
        if best is None or (err, n) < best[:2]:
            best = (err, n, chosen, tri)
    err, n, chosen, tri = best
    if thinned:
        err, _ = hausdorff_to_convex(q, q[chosen], tri)
    if budget.vertices is not None:
        info["why"] = (f"no valid set of {cap} vertices in {info['steps']} steps: the validity checks "
                       f"forbade the nearer choices ({_kinds(repairs)}); {n} vertices kept")
    elif info["reached_cap"]:
        info["why"] = (f"at the {cap}-vertex cap (--max-vertices): no valid set of up to {cap} vertices met it"
                       + (f" (repairs of the validity checks: {_kinds(repairs)})" if repairs else ""))
    else:
        info["why"] = (f"every nearer choice failed the validity checks ({_kinds(repairs)}; "
                       f"{info['steps']} steps)")
    return np.array(chosen), tri, float(err), False


def _kinds(counter):
    """'nearly flat edge 12, close vertices 3' from a Counter of repairs."""
    return ", ".join(f"{k} {n}" for k, n in counter.most_common()) or "no repairs"
