"""Convex polyhedra: hull, validity checks and normalisation.

A valid shape is a closed, outward-oriented, convex triangle mesh with
positive volume and none of the degenerate features that break contact
detection. Every tolerance is relative to the shape's size d (twice the
largest barycentre-to-vertex distance), so validity does not depend on units:

==================  =====================================================
``VERTEX_TOL``      0.02 d: two vertices closer than this are duplicates
``EDGE_TOL``        0.02 d: no (geometric) edge shorter than this
``HEIGHT_TOL``      0.01 d: no triangle with a smallest altitude below this
                    (a sliver face)
``VOLUME_TOL``      0.005 d^3: no polyhedron flatter than this (a sliver
                    or nearly coplanar body; a unit-d cube has 0.19 d^3)
``CONVEX_TOL``      1e-9 d: no vertex may stand further than this outside
                    the plane of any triangle
``COPLANAR_DEG``    1 deg: adjacent triangles whose normals differ by less
                    make one geometric face
``CREASE_DEG``      3 deg: a real edge bends by at least this much; an edge
                    bending by COPLANAR_DEG to CREASE_DEG is ambiguous (is
                    it a face or an edge?) and rejected, so that the
                    face/edge/vertex features of a contact are well defined
==================  =====================================================

The normalised frame: origin at the centre of mass (uniform density), axes
along the principal axes of inertia sorted by increasing principal moment
(x is the long axis), x and y pointing to the side of their furthest vertex,
z = x cross y, scaled to d = 1.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

VERTEX_TOL = 0.02
EDGE_TOL = 0.02
HEIGHT_TOL = 0.01
VOLUME_TOL = 0.005
CONVEX_TOL = 1e-9
COPLANAR_DEG = 1.0
CREASE_DEG = 3.0


class ShapeError(ValueError):
    """A point set or mesh that is not a valid convex polyhedron; the
    message names the defect and its size relative to d."""


@dataclass
class Polyhedron:
    """A convex polyhedron in its normalised frame (d = 1 unless scaled).

    vertices : (V, 3); triangles : (T, 3) int, counter-clockwise seen from
    outside; triangle_face : (T,) int, geometric face of each triangle;
    volume : float (d^3); inertia : (3, 3) inertia tensor about the centre of
    mass for unit density (d^5); dims : (3,) extents along the principal
    axes, sorted L >= I >= S; sphericity : Wadell's pi^(1/3) (6V)^(2/3) / A.
    """

    vertices: np.ndarray
    triangles: np.ndarray
    triangle_face: np.ndarray
    volume: float
    inertia: np.ndarray
    dims: np.ndarray
    area: float

    @property
    def n_vertices(self):
        return len(self.vertices)

    @property
    def n_faces(self):
        """Geometric faces (coplanar triangles merged)."""
        return int(self.triangle_face.max()) + 1 if len(self.triangle_face) else 0

    @property
    def n_edges(self):
        """Geometric edges: edges between two different geometric faces."""
        return len(_feature_edges(self.triangles, self.triangle_face))

    @property
    def sphericity(self):
        return float(np.pi ** (1 / 3) * (6 * self.volume) ** (2 / 3) / self.area)

    @property
    def size(self):
        """d = 2 x the largest centre-of-mass-to-vertex distance."""
        return 2.0 * float(np.max(np.linalg.norm(self.vertices, axis=1)))


def _edges(triangles):
    t = np.asarray(triangles)
    return np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])


def edge_triangles(triangles):
    """Undirected edges (E, 2) and the two triangles of each (E, 2) of a
    closed triangle mesh."""
    directed = _edges(triangles)
    tri = np.tile(np.arange(len(triangles)), 3)
    key = np.sort(directed, axis=1)
    order = np.lexsort((key[:, 1], key[:, 0]))
    key, tri = key[order], tri[order]
    return key[0::2], np.column_stack([tri[0::2], tri[1::2]])


def _feature_edges(triangles, triangle_face):
    edges, faces = edge_triangles(triangles)
    return edges[triangle_face[faces[:, 0]] != triangle_face[faces[:, 1]]]


def triangle_normals(vertices, triangles):
    """(T, 3) unit outward normals and (T,) areas of the triangles."""
    v = np.asarray(vertices, float)
    t = np.asarray(triangles)
    cr = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    area2 = np.linalg.norm(cr, axis=1)
    return cr / np.where(area2 > 0, area2, 1.0)[:, None], 0.5 * area2


def geometric_faces(vertices, triangles, tol_deg=COPLANAR_DEG):
    """(T,) face id per triangle: edge-adjacent triangles whose normals differ
    by less than ``tol_deg`` are merged (union-find over shared edges)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    n, _ = triangle_normals(vertices, triangles)
    _, pairs = edge_triangles(triangles)
    cos = np.einsum("ij,ij->i", n[pairs[:, 0]], n[pairs[:, 1]])
    same = pairs[cos > np.cos(np.radians(tol_deg))]
    T = len(triangles)
    g = coo_matrix((np.ones(len(same)), (same[:, 0], same[:, 1])), shape=(T, T))
    _, labels = connected_components(g, directed=False)
    # number faces in order of first appearance (stable across runs)
    _, first = np.unique(labels, return_index=True)
    rank = np.empty(len(first), int)
    rank[np.argsort(first)] = np.arange(len(first))
    return rank[labels]


def bend_angles(vertices, triangles):
    """Edges (E, 2), their two triangles (E, 2) and the angle (E,) in degrees
    between the two triangles' outward normals (0 = flat)."""
    n, _ = triangle_normals(vertices, triangles)
    edges, pairs = edge_triangles(triangles)
    cos = np.clip(np.einsum("ij,ij->i", n[pairs[:, 0]], n[pairs[:, 1]]), -1, 1)
    return edges, pairs, np.degrees(np.arccos(cos))


def check_polyhedron(vertices, triangles, triangle_face=None):
    """Raise ShapeError unless (vertices, triangles) is a valid convex
    polyhedron (closed, outward, convex, within the tolerances above).

    vertices : (V, 3); triangles : (T, 3) int. Any units: tolerances scale
    with d.
    """
    v = np.asarray(vertices, float)
    t = np.asarray(triangles)
    if v.ndim != 2 or v.shape[1] != 3 or len(v) < 4:
        raise ShapeError(f"need at least 4 vertices of 3 coordinates, got shape {v.shape}")
    if not np.isfinite(v).all():
        raise ShapeError("vertex coordinates are NaN or infinite")
    if t.ndim != 2 or t.shape[1] != 3 or len(t) < 4:
        raise ShapeError(f"need at least 4 triangles, got shape {t.shape}")
    if t.min() < 0 or t.max() >= len(v):
        raise ShapeError("triangle index out of range")
    used = np.zeros(len(v), bool)
    used[t.ravel()] = True
    if not used.all():
        raise ShapeError(f"vertex {int(np.flatnonzero(~used)[0])} belongs to no triangle")
    # closed and consistently oriented: each directed edge once, each
    # undirected edge in exactly two triangles
    directed = _edges(t)
    if len(np.unique(directed, axis=0)) != len(directed):
        raise ShapeError("mesh is not consistently oriented (a directed edge repeats)")
    _, counts = np.unique(np.sort(directed, axis=1), axis=0, return_counts=True)
    if np.any(counts != 2):
        raise ShapeError("mesh is not closed (an edge does not join exactly two triangles)")
    c = v.mean(axis=0)
    d = 2 * np.max(np.linalg.norm(v - c, axis=1))
    if d == 0:
        raise ShapeError("all vertices coincide")
    _check_vertex_spacing(v, d)
    n, area = triangle_normals(v, t)
    volume = np.sum(np.einsum("ij,ij->i", v[t[:, 0]] - c, np.cross(v[t[:, 1]] - c, v[t[:, 2]] - c))) / 6
    if volume <= 0:
        raise ShapeError(f"volume {volume:.3g} is not positive (inward-facing triangles?)")
    if volume < VOLUME_TOL * d ** 3:
        raise ShapeError(f"volume {volume / d**3:.2e} d^3 < {VOLUME_TOL} d^3: a sliver or "
                         "nearly coplanar polyhedron")
    out = np.einsum("tj,vtj->vt", n, v[:, None, :] - v[t[:, 0]][None, :, :])
    if out.max() > CONVEX_TOL * d:
        k = np.unravel_index(np.argmax(out), out.shape)
        raise ShapeError(f"not convex: vertex {k[0]} stands {out.max() / d:.2e} d outside "
                         f"triangle {k[1]}")
    _, pairs, bend = bend_angles(v, t)
    vague = (bend >= COPLANAR_DEG) & (bend < CREASE_DEG)
    if vague.any():
        k = int(np.flatnonzero(vague)[0])
        raise ShapeError(f"nearly flat edge: triangles {pairs[k, 0]} and {pairs[k, 1]} bend by "
                         f"{bend[k]:.2f} deg, between {COPLANAR_DEG} and {CREASE_DEG} deg")
    tf = geometric_faces(v, t) if triangle_face is None else np.asarray(triangle_face)
    feat = _feature_edges(t, tf)
    Lf = np.linalg.norm(v[feat[:, 0]] - v[feat[:, 1]], axis=1)
    if len(Lf) and Lf.min() < EDGE_TOL * d:
        raise ShapeError(f"degenerate edge: length {Lf.min() / d:.2e} d < {EDGE_TOL} d")
    longest = np.max(np.stack([np.linalg.norm(v[t[:, i]] - v[t[:, (i + 1) % 3]], axis=1)
                               for i in range(3)]), axis=0)
    height = 2 * area / longest
    own = np.bincount(tf, minlength=tf.max() + 1)[tf] == 1   # triangles that are whole faces
    if np.any(own) and height[own].min() < HEIGHT_TOL * d:
        k = int(np.flatnonzero(own)[np.argmin(height[own])])
        raise ShapeError(f"sliver face: triangle {k} has an altitude of "
                         f"{height[k] / d:.2e} d < {HEIGHT_TOL} d")


def _check_vertex_spacing(v, d):
    from scipy.spatial.distance import pdist

    dist = pdist(v)
    if dist.min() < VERTEX_TOL * d:
        k = int(np.argmin(dist))
        n = len(v)
        # index pair of condensed entry k
        i = int(n - 2 - np.floor(np.sqrt(-8 * k + 4 * n * (n - 1) - 7) / 2 - 0.5))
        j = int(k + i + 1 - n * (n - 1) // 2 + (n - i) * ((n - i) - 1) // 2)
        raise ShapeError(f"duplicate or near-duplicate vertices {i} and {j}: "
                         f"{dist.min() / d:.2e} d apart (< {VERTEX_TOL} d)")


def hull(points, allow_interior=False):
    """Convex hull of ``points`` (N, 3) as (vertices (V, 3), triangles (T, 3))
    with outward (counter-clockwise) triangles.

    Points inside the hull are dropped when ``allow_interior``, else they are
    an error (the input was meant to be a convex vertex set). Raises
    ShapeError for fewer than 4 points, non-finite values, coincident,
    duplicate or (nearly) coplanar points. Works at any scale: the points are
    centred and scaled to unit size before qhull sees them.
    """
    from scipy.spatial import ConvexHull, QhullError

    p = np.asarray(points, float)
    if p.ndim != 2 or p.shape[1] != 3 or len(p) < 4:
        raise ShapeError(f"need at least 4 points of 3 coordinates, got shape {p.shape}")
    if not np.isfinite(p).all():
        raise ShapeError("point coordinates are NaN or infinite")
    c = p.mean(axis=0)
    d = 2 * np.max(np.linalg.norm(p - c, axis=1))
    if d == 0:
        raise ShapeError("all points coincide")
    q = (p - c) / d
    _check_vertex_spacing(q, 2 * np.max(np.linalg.norm(q, axis=1)))
    try:
        h = ConvexHull(q)
    except QhullError:
        raise ShapeError("points are coplanar or nearly so: the hull has no volume") from None
    if h.volume < VOLUME_TOL * (2 * np.max(np.linalg.norm(q, axis=1))) ** 3:
        raise ShapeError(f"points are nearly coplanar: hull volume {h.volume:.2e} d^3 "
                         f"< {VOLUME_TOL} d^3")
    keep = np.sort(h.vertices)
    if len(keep) < len(p) and not allow_interior:
        k = int(np.setdiff1d(np.arange(len(p)), keep)[0])
        raise ShapeError(f"point {k} lies inside the hull of the others: not the vertex "
                         "set of a convex polyhedron")
    remap = np.full(len(p), -1)
    remap[keep] = np.arange(len(keep))
    tri = remap[h.simplices]
    v = p[keep]
    n, _ = triangle_normals(q[keep], tri)
    flip = np.einsum("ij,ij->i", n, h.equations[:, :3]) < 0
    tri[flip] = tri[flip][:, [0, 2, 1]]
    return v, tri


def normalise(vertices, triangles):
    """Move a valid convex mesh to its normalised frame (module docstring)
    and return a :class:`Polyhedron` with d = 1. Mass properties by trimesh
    (Eberly's surface integrals, uniform density 1)."""
    import trimesh

    v = np.asarray(vertices, float)
    t = np.asarray(triangles, np.int64)
    m = trimesh.Trimesh(v, t, process=False)
    w, R = np.linalg.eigh(m.moment_inertia)
    centred = v - m.center_mass
    # eigenvector signs are arbitrary: fix axes x and y so that the vertex
    # furthest along each lies on its positive side; z = x cross y
    for k in (0, 1):
        proj = centred @ R[:, k]
        if proj.max() < -proj.min():
            R[:, k] *= -1
    R[:, 2] = np.cross(R[:, 0], R[:, 1])
    local = centred @ R
    local /= 2 * np.max(np.linalg.norm(local, axis=1))
    m = trimesh.Trimesh(local, t, process=False)
    # re-centre on the exact centre of mass after scaling (round-off only)
    local = local - m.center_mass
    m = trimesh.Trimesh(local, t, process=False)
    ext = local.max(axis=0) - local.min(axis=0)
    return Polyhedron(vertices=local, triangles=t, triangle_face=geometric_faces(local, t),
                      volume=float(m.volume), inertia=np.asarray(m.moment_inertia),
                      dims=np.sort(ext)[::-1], area=float(m.area))


def polyhedron_from_points(points, allow_interior=False):
    """Hull, check and normalise: a valid :class:`Polyhedron` with d = 1 from
    a point set, or ShapeError naming the defect."""
    v, t = hull(points, allow_interior=allow_interior)
    check_polyhedron(v, t)
    return normalise(v, t)
