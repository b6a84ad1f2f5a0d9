"""Grains from meshes: scans (STL, OBJ, PLY, OFF) become library polyhedra.

A researcher's grains arrive as triangle meshes, from a laser scanner or a
segmented CT volume, with thousands to millions of triangles and some
concavities. Each grain (one file, or one connected piece of a file with
``components=True``) becomes a valid library polyhedron, like the generated
ones (:mod:`shapes.polyhedron`):

1. **Read** with trimesh's loaders (``.stl`` ASCII or binary, ``.obj``,
   ``.ply``, ``.off``), no processing; then our own checks, each refusal an
   :class:`ImportRefused` with a one-line reason: finite coordinates, at
   least 4 distinct vertices, exact duplicate vertices merged (STL stores
   each triangle's corners apart), triangles with a repeated corner after
   the merge dropped, one connected piece, closed (every edge in exactly two
   triangles), manifold, consistently oriented (every directed edge once),
   enclosed volume not zero. A wholly inside-out mesh (negative volume) is turned
   round.
2. **Hull**: the convex hull of the vertices (qhull), its volume V_hull, its
   centre of mass and its size d_hull = 2 x the largest distance from that
   centre to a hull vertex; the **convexity deficit** 1 - V_mesh / V_hull
   (0 for a convex mesh).
3. **Reduction** to a vertex budget (:func:`reduce_hull`): the hull's vertices
   are added greedily, each time the one furthest outside the hull of those
   already chosen (quickhull's order), starting from four extreme points,
   until the budget is met:

   * ``vertices=N``: N vertices (fewer when the hull has fewer);
   * ``max_error=E``: the fewest vertices whose hull is within E d_hull of
     the full hull (Hausdorff), at most ``max_vertices`` (default 37, the
     paper's largest grain).

   Points within ``ZERO_ERROR`` (1e-6 d_hull) of the chosen hull count as on
   it (a float32 STL rounds coordinates by 6e-8 d). Points within 0.02 d of a
   chosen vertex are never chosen (they could not be vertices of a valid
   grain). A chosen set whose hull fails the validity checks of
   :mod:`shapes.polyhedron` (two vertices closer than 0.02 d, an edge
   bending by 1-3 deg, a sliver triangle) is repaired by removing the vertex
   of the defect whose removal leaves the hull nearest to the points, and
   banning the points within ``BAN_RADIUS`` (0.005 d_hull) of it; the greedy
   then goes on. An error target can so be missed; the error is measured
   and reported all the same. Above ``MAX_CANDIDATES`` hull vertices the
   greedy runs on a grid-thinned subset (:func:`thin_points`).
4. **Error of the reduction**, measured exactly: the reduced hull lies inside
   the full hull (its vertices are hull vertices), so their Hausdorff
   distance is the largest distance from a full-hull vertex to the reduced
   polyhedron (:func:`distance_to_convex`, :func:`hausdorff_to_convex`),
   reported relative to d_hull;
   and the volume change V_reduced / V_hull - 1 (<= 0).
5. **Normalised** as the generated grains are
   (:func:`shapes.polyhedron.normalise`): centre of mass, principal frame,
   d = 1. The grain's size in the file's units (``source_d``) is kept.

Pure functions over arrays, and :func:`import_paths` for files and folders
(what ``python -m shapes import`` runs). Units: any (the mesh's); every
relative quantity is scale-free.
"""
from __future__ import annotations

import os
import time
from dataclasses import dataclass, field

import numpy as np

from .polyhedron import (COPLANAR_DEG, CREASE_DEG, HEIGHT_TOL, VERTEX_TOL, Polyhedron, ShapeError,
                         bend_angles, check_polyhedron, geometric_faces, normalise, triangle_normals)

#: file extensions read, and trimesh's name for each format
FORMATS = {".stl": "stl", ".obj": "obj", ".ply": "ply", ".off": "off"}
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


class ImportRefused(ValueError):
    """A mesh that cannot become a grain; the message is one line naming the
    reason (the caller adds the file name)."""


@dataclass
class Budget:
    """The vertex budget of the reduction: ``vertices`` (exactly N, fewer
    only when the hull has fewer) or ``max_error`` (relative to d_hull, with
    at most ``max_vertices``). Exactly one of ``vertices`` and ``max_error``
    is set."""

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
        return self.vertices if self.vertices is not None else self.max_vertices

    def as_dict(self):
        return {"vertices": self.vertices, "max_error": self.max_error,
                "max_vertices": None if self.vertices is not None else self.max_vertices}


@dataclass
class ImportedGrain:
    """One imported grain: the library polyhedron (d = 1) and what the import
    measured. Lengths in the mesh's units unless relative.

    source : name (file, ``file#k`` for the k-th piece); mesh_triangles,
    mesh_vertices : counts after the merge; mesh_volume, hull_volume : units^3;
    hull_vertices : vertex count of the full hull; d_hull : 2 x largest
    centre-of-mass-to-vertex distance of the full hull; source_d : d of the
    reduced grain; convexity_deficit : 1 - V_mesh / V_hull;
    reduction_hausdorff : Hausdorff distance reduced-full hull / d_hull;
    reduction_volume_change : V_reduced / V_hull - 1; target_met : False when
    an error target could not be met within max_vertices; seconds : timings.
    """

    polyhedron: Polyhedron
    source: str
    mesh_triangles: int
    mesh_vertices: int
    mesh_volume: float
    hull_volume: float
    hull_vertices: int
    d_hull: float
    source_d: float
    convexity_deficit: float
    reduction_hausdorff: float
    reduction_volume_change: float
    target_met: bool = True
    seconds: dict = field(default_factory=dict)


# ---------------------------------------------------------------- reading

def read_mesh(path):
    """(vertices (V, 3) float64, triangles (T, 3) int64) of a mesh file, as
    stored (no merge, no repair). Raises ImportRefused for an unknown format,
    an unreadable file or one without triangles."""
    import trimesh

    ext = os.path.splitext(path)[1].lower()
    if ext not in FORMATS:
        raise ImportRefused(f"unknown format '{ext or '(no extension)'}' (reads "
                            f"{', '.join(sorted(FORMATS))})")
    try:
        m = trimesh.load(path, file_type=FORMATS[ext], process=False)
        if isinstance(m, trimesh.Scene):          # several objects: one mesh, transforms applied
            m = m.dump(concatenate=True) if m.geometry else None
    except Exception as exc:          # any failure of a foreign parser is one line
        msg = str(exc).strip().splitlines()[0] if str(exc).strip() else exc.__class__.__name__
        raise ImportRefused(f"unreadable {FORMATS[ext].upper()} file ({msg[:120]})") from None
    faces = getattr(m, "faces", None)
    verts = getattr(m, "vertices", None)
    if faces is None or verts is None or len(faces) == 0:
        raise ImportRefused("no triangles in the file (empty, or a point cloud)")
    v = np.asarray(verts, np.float64)
    t = np.asarray(faces, np.int64)
    if t.ndim != 2 or t.shape[1] != 3:
        raise ImportRefused(f"faces are not triangles (shape {t.shape})")
    return v, t


def _mix64(x):
    """splitmix64's finaliser on a uint64 array (a bijection that spreads
    every input bit over the output)."""
    x = x ^ (x >> np.uint64(30))
    x = x * np.uint64(0xBF58476D1CE4E5B9)
    x = x ^ (x >> np.uint64(27))
    x = x * np.uint64(0x94D049BB133111EB)
    return x ^ (x >> np.uint64(31))


def merge_vertices(vertices, triangles):
    """Merge vertices with exactly equal coordinates and drop triangles left
    with a repeated corner (and vertices no triangle uses). Returns
    (vertices (V', 3), triangles (T', 3)); the merged vertices come in an
    order fixed by their coordinates.

    A 64-bit hash of the coordinates' bits groups the rows (one sort of V
    keys rather than of V x 3 floats); every row is then compared with its
    group's representative, and a hash collision falls back to numpy's exact
    row unique, so the result is exact either way.
    """
    v = np.asarray(vertices, np.float64) + 0.0               # a contiguous copy; -0.0 -> 0.0
    t = np.asarray(triangles, np.int64)
    with np.errstate(over="ignore"):
        bits = v.view(np.uint64)
        h = _mix64(_mix64(_mix64(bits[:, 0]) ^ bits[:, 1]) ^ bits[:, 2])
    order = np.argsort(h)
    hs = h[order]
    start = np.empty(len(hs), bool)
    start[:1] = True
    np.not_equal(hs[1:], hs[:-1], out=start[1:])
    first = order[start]
    inv = np.empty(len(v), np.int64)
    inv[order] = np.cumsum(start) - 1
    if not (bits[first[inv]] == bits).all():          # bitwise: NaN rows compare too
        _, first, inv = np.unique(v, axis=0, return_index=True, return_inverse=True)
        inv = inv.ravel()
    t = inv[t]
    keep = (t[:, 0] != t[:, 1]) & (t[:, 1] != t[:, 2]) & (t[:, 2] != t[:, 0])
    if not keep.all():
        t = t[keep]
    used = np.zeros(len(first), bool)
    used[t.ravel()] = True
    if used.all():
        return v[first], t
    new = np.cumsum(used) - 1
    return v[first[used]], new[t]


def components(vertices, triangles):
    """Connected pieces of a mesh (triangles sharing a vertex): a list of
    (vertices, triangles), largest first (by triangle count)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    n = len(vertices)
    t = np.asarray(triangles)
    a, b = np.concatenate([t[:, 0], t[:, 1]]), np.concatenate([t[:, 1], t[:, 2]])
    k, labels = connected_components(coo_matrix((np.ones(len(a)), (a, b)), shape=(n, n)), directed=False)
    if k == 1:
        return [(vertices, t)]
    tl = labels[t[:, 0]]
    out = []
    for c in np.argsort(-np.bincount(tl, minlength=k), kind="stable"):
        sub = t[tl == c]
        used, local = np.unique(sub, return_inverse=True)
        out.append((vertices[used], local.reshape(-1, 3)))
    return out


def mesh_volume(vertices, triangles):
    """Signed enclosed volume (units^3) of a closed triangle mesh, positive
    for outward (counter-clockwise from outside) triangles: the divergence
    theorem, sum of a . (b x c) / 6 over the triangles, about the vertices'
    mean for round-off."""
    v = np.asarray(vertices, float)
    v = v - v.mean(axis=0)
    t = np.asarray(triangles)
    a, b, c = v[t[:, 0]].T, v[t[:, 1]].T, v[t[:, 2]].T     # (3, T) each: columns are cheap
    det = a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0])
    return float(det.sum() / 6.0)


def check_closed(vertices, triangles):
    """Raise ImportRefused unless the mesh is finite, closed, manifold,
    consistently oriented and in one piece, with a non-zero volume; returns
    its signed volume (units^3, positive for outward triangles).

    vertices : (V, 3) merged (:func:`merge_vertices`); triangles : (T, 3).
    One sort of the 3T directed edges, keyed (smaller index, larger index,
    direction), decides the edge conditions: every undirected edge must
    occur exactly twice, once in each direction. Its edges then give the
    connected pieces.
    """
    v, t = vertices, triangles
    if not np.isfinite(v).all():
        raise ImportRefused(f"{int((~np.isfinite(v).all(axis=1)).sum())} vertices have NaN or "
                            "infinite coordinates")
    if len(v) < 4 or len(t) < 4:
        raise ImportRefused(f"degenerate: {len(v)} distinct vertices and {len(t)} proper triangles "
                            "(a closed solid needs at least 4 of each)")
    n = np.int64(len(v))
    i = t.T.ravel()
    j = t[:, [1, 2, 0]].T.ravel()
    key = np.sort((np.minimum(i, j) * n + np.maximum(i, j)) * 2 + (i < j))
    und = key >> 1
    cut = np.flatnonzero(und[1:] != und[:-1]) + 1
    counts = np.diff(np.concatenate([[0], cut, [len(und)]]))
    if np.any(counts == 1):
        raise ImportRefused(f"open mesh: {int((counts == 1).sum())} boundary edges (each in one "
                            "triangle); a grain must be a closed surface")
    if np.any(counts > 2):
        raise ImportRefused(f"non-manifold: {int((counts > 2).sum())} edges are shared by more "
                            "than two triangles")
    rep = int(np.count_nonzero((key[0::2] & 1) == (key[1::2] & 1)))
    if rep:
        raise ImportRefused(f"inconsistently oriented: {rep} edges run the same way in both their "
                            "triangles (some triangles face inwards)")
    pieces = _count_pieces(und[0::2], n)
    if pieces > 1:
        raise ImportRefused(f"{pieces} separate pieces in one mesh (import each as a grain with "
                            "--components)")
    vol = mesh_volume(v, t)
    ext = np.ptp(v, axis=0).max()
    # |V| within the round-off of the summed triple products: no volume at all
    if not np.isfinite(vol) or abs(vol) <= 1e-12 * ext ** 3 * max(1.0, len(t) ** 0.5):
        raise ImportRefused(f"no volume: the closed surface encloses {vol:.3g} (units^3), "
                            "a flat or collapsed mesh")
    return vol


def _count_pieces(edge_keys, n):
    """Connected components of the graph on n vertices whose edges are the
    sorted keys a * n + b (a < b): the keys sorted by a are a CSR matrix as
    they stand."""
    from scipy.sparse import csr_matrix
    from scipy.sparse.csgraph import connected_components

    a = edge_keys // n
    indptr = np.concatenate([[0], np.cumsum(np.bincount(a, minlength=n))])
    g = csr_matrix((np.ones(len(edge_keys), np.int8), edge_keys % n, indptr), shape=(n, n))
    return connected_components(g, directed=False)[0]


# ---------------------------------------------------------------- geometry

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
    """Exact Euclidean distances (N,) from ``points`` (N, 3) to the convex
    polyhedron (vertices (V, 3), outward triangles (T, 3)); 0 inside.

    For a point outside, the distance is at least its largest signed plane
    distance h_max, with equality when its projection on that plane lies in
    the triangle (the first pass, one matrix product). Otherwise the nearest
    point lies on an edge or in a coplanar neighbour: the distance is the
    least of the point-segment distances to every edge and of h over the
    triangles that contain the point's projection (each is the distance to a
    point of the polyhedron, and the nearest point is among them).
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
    (m, 3), outward triangles), each as the local indices of the vertices
    involved: two vertices closer than VERTEX_TOL d; the two triangles'
    four vertices at an edge bending by COPLANAR_DEG to CREASE_DEG; a
    sliver triangle's three. Empty when there are none."""
    from scipy.spatial.distance import pdist, squareform

    out = []
    d = 2 * np.max(np.linalg.norm(vq - vq.mean(axis=0), axis=1))
    dist = squareform(pdist(vq))
    np.fill_diagonal(dist, np.inf)
    i, j = np.nonzero(np.triu(dist < VERTEX_TOL * d))
    out += [(int(a), int(b)) for a, b in zip(i, j)]
    edges, pairs, bend = bend_angles(vq, tri)
    for k in np.flatnonzero((bend >= COPLANAR_DEG) & (bend < CREASE_DEG)):
        out.append(tuple(int(x) for x in np.unique(np.concatenate([tri[pairs[k, 0]], tri[pairs[k, 1]]]))))
    tf = geometric_faces(vq, tri)
    own = np.bincount(tf, minlength=tf.max() + 1)[tf] == 1
    _, area = triangle_normals(vq, tri)
    longest = np.max(np.stack([np.linalg.norm(vq[tri[:, a]] - vq[tri[:, (a + 1) % 3]], axis=1)
                               for a in range(3)]), axis=0)
    out += [tuple(int(x) for x in tri[k]) for k in np.flatnonzero(own & (2 * area / longest < HEIGHT_TOL * d))]
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
    """The largest distance from ``points`` (N, 3) to the convex polyhedron
    (vertices, outward triangles), and the index of the point attaining it
    (-1 when every point is inside): max of :func:`distance_to_convex`, with
    the exact distance computed only where it can matter.

    Each point has a lower bound L (its largest signed plane distance) and
    an upper bound U (its distance to where the segment from it to the
    vertices' mean enters the polyhedron, a point of the polyhedron). Points
    are taken by decreasing U, exact distances computed chunk by chunk,
    until the next U is below the best exact distance found.
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
    """Indices of at most ``max_points`` of the points q (N, 3) (unit size
    d = 1), spread over them: one point per occupied cell of a cubic grid
    whose spacing starts at sqrt(pi / max_points) (a convex surface of size
    1 has an area of at most pi) and grows by 1.5 until few enough cells are
    occupied. All indices when N <= max_points."""
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


def _cheapest_removal(q, sub, chosen, involved):
    """Of the chosen points at local indices ``involved``, the one (index
    into q) whose removal leaves the hull of the rest nearest to the points
    q[sub] (Hausdorff distance)."""
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


def reduce_hull(points, budget, d=None, max_steps=None, max_candidates=None):
    """Choose the reduced grain's vertices among ``points`` (N, 3), the full
    hull's vertices (any units), by greedy furthest-point insertion (module
    docstring, step 3).

    budget : :class:`Budget`; d : the full hull's size (default: twice the
    largest distance from the points' mean). Above ``max_candidates`` points
    (default MAX_CANDIDATES) the greedy runs on a thinned subset
    (:func:`thin_points`) and the error is still measured on every point; an
    error target is then met by adding the worst points themselves.

    Returns (indices (k,) into points, their hull's outward triangles (T, 3)
    as indices into the returned vertex list, the exact Hausdorff distance
    to the full hull in units of d, target_met: False when an error target
    was not reached, at ``budget.max_vertices`` or because the validity
    repairs forbade the nearer choices). Raises ShapeError when no valid
    polyhedron is found.
    """
    p = np.asarray(points, float)
    c = p.mean(axis=0)
    d = d or 2 * np.max(np.linalg.norm(p - c, axis=1))
    q = (p - c) / d                     # unit-size coordinates: tolerances are absolute
    cap = min(budget.cap, len(q))
    stop = max(budget.max_error if budget.max_error is not None else 0.0, ZERO_ERROR)
    if len(q) <= cap and (budget.vertices is not None or stop <= ZERO_ERROR):
        # the whole hull fits the budget: it is the answer when it is a valid grain
        hq = _hull_of(q)
        if hq is not None and len(hq[0]) == len(q) and not _defects(q[hq[0]], hq[1]):
            return hq[0], hq[1], 0.0, True
    sub = thin_points(q, max_candidates or MAX_CANDIDATES)
    first = _initial_simplex(q)
    if first is None:
        raise ShapeError("all points on a line or a plane: no volume")
    sub = np.union1d(sub, first)
    chosen = list(first)                # indices into q
    banned = np.zeros(len(q), bool)
    greedy = _Greedy(q[sub])
    pos = {int(k): i for i, k in enumerate(sub)}
    max_steps = max_steps or 20 * cap + 100

    def hull_of_chosen():
        hq = _hull_of(q[chosen])
        if hq is None:
            raise ShapeError("the chosen points are coplanar: no volume")
        return [chosen[k] for k in hq[0]], hq[1]      # qhull drops points on a face

    def crowded(pts):
        """Points within VERTEX_TOL d of a chosen vertex (d as the checks
        take it): they cannot be vertices of a valid grain."""
        cq = q[chosen]
        r = VERTEX_TOL * 2 * np.max(np.linalg.norm(cq - cq.mean(axis=0), axis=1))
        near = np.zeros(len(pts), bool)
        for x in cq:
            near |= np.einsum("ij,ij->i", pts - x, pts - x) < r * r
        return near

    for _ in range(max_steps):
        chosen, tri = hull_of_chosen()
        h = greedy.update([pos[k] for k in chosen], tri)
        live = sub[greedy.live]
        cand = np.flatnonzero(~banned[live])
        cand = cand[~crowded(q[live[cand]])]
        grow = None
        if len(chosen) < cap and len(cand) and h[cand].max() > stop:
            grow = int(live[cand[np.argmax(h[cand])]])
        elif len(chosen) < cap:
            # the planes say done: the exact distances of every eligible point decide
            idx = live if len(sub) == len(q) else np.arange(len(q))
            idx = idx[~banned[idx]]
            idx = idx[~crowded(q[idx])]
            err, k = hausdorff_to_convex(q[idx], q[chosen], tri)
            if err > stop:
                grow = int(idx[k])
                if grow not in pos:     # a point the thinning left out: the greedy takes it in
                    sub = np.union1d(sub, [grow])
                    pos = {int(x): i for i, x in enumerate(sub)}
                    greedy = _Greedy(q[sub])
        if grow is not None:
            chosen.append(grow)
            continue
        bad = _defects(q[chosen], tri)
        if not bad:
            err, _ = hausdorff_to_convex(q, q[chosen], tri)
            return np.array(chosen), tri, err, budget.vertices is not None or err <= stop
        # repair the first defect: drop the vertex involved whose loss costs least (the error
        # over the greedy's points), and ban the points within BAN_RADIUS of it
        drop = _cheapest_removal(q, sub, chosen, bad[0])
        banned |= np.linalg.norm(q - q[drop], axis=1) < BAN_RADIUS
        chosen = [k for k in chosen if k != drop]
        greedy.reset()                  # the hull shrank: points inside may be outside again
        if len(chosen) < 4:
            raise ShapeError("no valid polyhedron: repairs left fewer than 4 vertices")
    # out of steps: remove defects without adding until the hull is valid
    while len(chosen) >= 4:
        chosen, tri = hull_of_chosen()
        bad = _defects(q[chosen], tri)
        if not bad:
            err, _ = hausdorff_to_convex(q, q[chosen], tri)
            return np.array(chosen), tri, err, budget.vertices is not None or err <= stop
        drop = _cheapest_removal(q, sub, chosen, bad[0])
        chosen = [k for k in chosen if k != drop]
    raise ShapeError(f"no valid polyhedron within {max_steps} greedy steps")


# ---------------------------------------------------------------- one grain

def import_mesh(vertices, triangles, budget=None, source=""):
    """One closed mesh (vertices (V, 3), triangles (T, 3), any units) to an
    :class:`ImportedGrain`. Raises ImportRefused with a one-line reason."""
    budget = budget or Budget()
    sec = {}
    t0, p0 = time.perf_counter(), time.process_time()
    v, t = merge_vertices(vertices, triangles)
    if not np.isfinite(v).all():
        raise ImportRefused(f"{int((~np.isfinite(v).all(axis=1)).sum())} vertices have NaN or "
                            "infinite coordinates")
    vol = check_closed(v, t)
    if vol < 0:                                    # inside-out as a whole: turn round
        t = t[:, [0, 2, 1]]
        vol = -vol
    sec["check"], sec["check_cpu"] = time.perf_counter() - t0, time.process_time() - p0
    t0, p0 = time.perf_counter(), time.process_time()
    c0 = v.mean(axis=0)
    scale = float(np.ptp(v, axis=0).max())
    hq = _hull_of((v - c0) / scale)
    if hq is None:
        raise ImportRefused("degenerate: all vertices on a plane or a line (the hull has no "
                            "volume)")
    hv = v[hq[0]]
    hull_volume, com = _volume_and_centre(hv, hq[1])
    d_hull = 2 * float(np.max(np.linalg.norm(hv - com, axis=1)))
    sec["hull"], sec["hull_cpu"] = time.perf_counter() - t0, time.process_time() - p0
    t0, p0 = time.perf_counter(), time.process_time()
    try:
        idx, rt, err, met = reduce_hull(hv, budget, d=d_hull)
        rv = hv[idx]
        check_polyhedron(rv, rt)
        poly = normalise(rv - rv.mean(axis=0), rt)      # centred first: no cancellation far from the origin
    except ShapeError as exc:
        raise ImportRefused(f"no valid library polyhedron: {exc}") from None
    sec["reduce"], sec["reduce_cpu"] = time.perf_counter() - t0, time.process_time() - p0
    reduced_volume, rcom = _volume_and_centre(rv, rt)
    return ImportedGrain(polyhedron=poly, source=source, mesh_triangles=len(t), mesh_vertices=len(v),
                         mesh_volume=vol, hull_volume=hull_volume, hull_vertices=len(hv), d_hull=d_hull,
                         source_d=2 * float(np.max(np.linalg.norm(rv - rcom, axis=1))),
                         convexity_deficit=max(0.0, 1 - vol / hull_volume),
                         reduction_hausdorff=err, reduction_volume_change=reduced_volume / hull_volume - 1,
                         target_met=bool(met), seconds=sec)


def _volume_and_centre(v, t):
    """Volume (units^3) and centre of mass (3,) of a closed outward mesh of
    uniform density (signed tetrahedra from the vertices' mean)."""
    c = v.mean(axis=0)
    a, b, e = v[t[:, 0]] - c, v[t[:, 1]] - c, v[t[:, 2]] - c
    w = np.einsum("ij,ij->i", a, np.cross(b, e)) / 6.0
    vol = float(w.sum())
    return vol, c + (w[:, None] * (a + b + e)).sum(axis=0) / (4.0 * vol)


# ---------------------------------------------------------------- files

def mesh_files(path):
    """The mesh files a command-line argument names: the file itself, or a
    folder's files with a known extension (sorted, not recursive). Returns
    (files, ignored_count); raises ImportRefused for a missing path or a
    folder without mesh files."""
    if os.path.isdir(path):
        names = sorted(os.listdir(path))
        files = [os.path.join(path, n) for n in names
                 if os.path.splitext(n)[1].lower() in FORMATS and os.path.isfile(os.path.join(path, n))]
        if not files:
            raise ImportRefused(f"no {', '.join(sorted(FORMATS))} file in this folder"
                                + (f" ({len(names)} other entries)" if names else " (empty)"))
        return files, len(names) - len(files)
    if not os.path.exists(path):
        raise ImportRefused("no such file or folder")
    return [path], 0


def import_paths(paths, budget=None, split=False, log=None):
    """Import every mesh named by ``paths`` (files and folders).

    Returns (grains: list of ImportedGrain, refused: list of (name, reason),
    ignored: count of non-mesh files in folders). ``split``: each connected
    piece of a file is a grain (``file#k``, largest first). ``log(name,
    reason)`` is called at each refusal as it happens. Nothing raises for a
    bad file: it is refused and the others go on.
    """
    budget = budget or Budget()
    grains, refused, ignored = [], [], 0

    def refuse(name, reason):
        refused.append((name, reason))
        if log:
            log(name, reason)

    for arg in paths:
        try:
            files, n_ignored = mesh_files(arg)
            ignored += n_ignored
        except ImportRefused as exc:
            refuse(arg, str(exc))
            continue
        for f in files:
            t0 = time.perf_counter()
            try:
                v, t = read_mesh(f)
            except ImportRefused as exc:
                refuse(f, str(exc))
                continue
            load = time.perf_counter() - t0
            if split:
                try:
                    mv, mt = merge_vertices(v, t)
                    if not np.isfinite(mv).all():
                        raise ImportRefused(f"{int((~np.isfinite(mv).all(axis=1)).sum())} vertices have "
                                            "NaN or infinite coordinates")
                    pieces = components(mv, mt)
                except ImportRefused as exc:
                    refuse(f, str(exc))
                    continue
                named = [(f"{f}#{k}", pv, pt) for k, (pv, pt) in enumerate(pieces)]
            else:
                named = [(f, v, t)]
            for name, pv, pt in named:
                try:
                    g = import_mesh(pv, pt, budget, source=name)
                except ImportRefused as exc:
                    refuse(name, str(exc))
                    continue
                g.seconds["load"] = load / len(named)
                grains.append(g)
    return grains, refused, ignored
