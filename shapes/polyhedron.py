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

    Made by :func:`normalise` (or :func:`polyhedron_from_points`), which
    fill every field; lengths are in units of the grain's size d (module
    docstring), so a grain of size d metres has vertices ``d * vertices``
    (m), volume ``d**3 * volume`` (m^3) and, at density rho (kg/m^3),
    inertia ``rho * d**5 * inertia`` (kg m^2).

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions in the normalised frame: centre of mass at the
        origin, x along the long principal axis.
    triangles : (T, 3) int
        Vertex indices of each triangle, counter-clockwise seen from
        outside (outward normals).
    triangle_face : (T,) int
        The geometric face of each triangle (:func:`geometric_faces`:
        coplanar neighbours share one), numbered from 0.
    volume : float
        d^3, the enclosed volume.
    inertia : (3, 3) float
        d^5, the inertia tensor about the centre of mass for unit density
        (diagonal in the normalised frame).
    dims : (3,) float
        d, the extents along the principal axes, sorted L >= I >= S.
    area : float
        d^2, the surface area.

    Attributes
    ----------
    vertices, triangles, triangle_face, volume, inertia, dims, area
        The parameters, as given.
    n_vertices : int
        The number of vertices V.
    n_faces, n_edges : int
        Geometric faces (coplanar triangles merged) and geometric edges
        (edges between two different geometric faces).
    sphericity : float
        Wadell's sphericity pi^(1/3) (6 volume)^(2/3) / area: 1 for a
        ball, 0.806 for a cube.
    size : float
        d, twice the largest distance from the origin (the centre of mass)
        to a vertex: the particle size of Azema, Radjai & Saussine (2009),
        section 2, "Numerical procedures" (1 in the normalised frame).

    Examples
    --------
    A 1 x 1 x 2 box, moved to its normalised frame:

    >>> import itertools
    >>> box = polyhedron_from_points(np.array(list(itertools.product((0, 1), (0, 1), (0, 2))), float))
    >>> box.n_vertices, len(box.triangles), box.n_faces, box.n_edges
    (8, 12, 6, 12)
    >>> round(box.size, 12), box.dims.round(4)          # d = 1; L = 2 / sqrt(6) along x
    (1.0, array([0.8165, 0.4082, 0.4082]))
    >>> round(box.volume, 4), round(box.sphericity, 4)  # 2 / 6^1.5 d^3
    (0.1361, 0.7677)
    >>> bool(np.allclose(box.vertices.mean(axis=0), 0))  # centred (a box's centre of mass is its vertices' mean)
    True
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
        """The number of vertices V (int)."""
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
        """Wadell's sphericity pi^(1/3) (6 volume)^(2/3) / area (float):
        the surface area of the ball of the same volume over the grain's
        own; 1 for a ball, 0.806 for a cube, 0.671 for a regular
        tetrahedron."""
        return float(np.pi ** (1 / 3) * (6 * self.volume) ** (2 / 3) / self.area)

    @property
    def size(self):
        """d = 2 x the largest distance from the origin to a vertex (float,
        the vertices' units): the particle size of Azema, Radjai & Saussine
        (2009), section 2, "Numerical procedures", when the origin is the
        centre of mass (as in the normalised frame)."""
        return 2.0 * float(np.max(np.linalg.norm(self.vertices, axis=1)))


def _edges(triangles):
    t = np.asarray(triangles)
    return np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])


def edge_triangles(triangles):
    """The undirected edges of a closed triangle mesh and the two triangles
    that share each.

    Parameters
    ----------
    triangles : (T, 3) int
        A closed mesh: every edge in exactly two triangles (not checked
        here; :func:`check_polyhedron` does).

    Returns
    -------
    edges : (E, 2) int
        Vertex indices of each edge, smaller first, sorted; E = 3T / 2.
    pairs : (E, 2) int
        The two triangles of each edge.

    Examples
    --------
    >>> edges, pairs = edge_triangles([[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]])   # a tetrahedron
    >>> edges.tolist()
    [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]]
    >>> sorted(pairs[0].tolist())          # edge 0-1 is in triangles 0 and 1
    [0, 1]
    """
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
    """Unit normals and areas of the triangles of a mesh.

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions, any units.
    triangles : (T, 3) int
        Vertex indices; the normal follows the right-hand rule (outward for
        triangles counter-clockwise seen from outside).

    Returns
    -------
    normals : (T, 3) float
        Unit normals (0 for a triangle of zero area).
    areas : (T,) float
        Areas, in the vertices' units squared.

    Examples
    --------
    >>> n, a = triangle_normals([[0, 0, 0], [2, 0, 0], [0, 1, 0]], [[0, 1, 2], [0, 2, 1]])
    >>> n.tolist(), a.tolist()
    ([[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]], [1.0, 1.0])
    """
    v = np.asarray(vertices, float)
    t = np.asarray(triangles)
    cr = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    area2 = np.linalg.norm(cr, axis=1)
    return cr / np.where(area2 > 0, area2, 1.0)[:, None], 0.5 * area2


def geometric_faces(vertices, triangles, tol_deg=COPLANAR_DEG):
    """The geometric face of each triangle: edge-adjacent triangles whose
    normals differ by less than ``tol_deg`` are one face (connected
    components over the shared edges).

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions, any units.
    triangles : (T, 3) int
        A closed mesh, triangles counter-clockwise seen from outside.
    tol_deg : float
        deg, the largest angle between the normals of two triangles of one
        face (default ``COPLANAR_DEG``, 1 deg).

    Returns
    -------
    (T,) int
        The face of each triangle, numbered 0, 1, ... in the order of the
        faces' first triangles.

    Examples
    --------
    The 12 triangles of a cube make its 6 faces:

    >>> import itertools
    >>> v, t = hull(np.array(list(itertools.product((0, 1), repeat=3)), float))
    >>> faces = geometric_faces(v, t)
    >>> int(faces.max()) + 1, np.bincount(faces).tolist()
    (6, [2, 2, 2, 2, 2, 2])
    """
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
    """How much a closed mesh bends at each edge: the angle between the
    outward normals of the edge's two triangles.

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions, any units.
    triangles : (T, 3) int
        A closed mesh, triangles counter-clockwise seen from outside.

    Returns
    -------
    edges : (E, 2) int
        The edges, as :func:`edge_triangles` gives them.
    pairs : (E, 2) int
        The two triangles of each edge.
    angles : (E,) float
        deg, the angle between the two triangles' outward normals: 0 where
        they are coplanar, 90 at a cube's edge (the exterior dihedral
        angle; the interior one is 180 - this).

    Examples
    --------
    >>> import itertools
    >>> v, t = hull(np.array(list(itertools.product((0, 1), repeat=3)), float))
    >>> edges, pairs, angles = bend_angles(v, t)
    >>> len(edges), np.unique(angles.round(6)).tolist()    # 6 face diagonals, 12 cube edges
    (18, [0.0, 90.0])
    """
    n, _ = triangle_normals(vertices, triangles)
    edges, pairs = edge_triangles(triangles)
    cos = np.clip(np.einsum("ij,ij->i", n[pairs[:, 0]], n[pairs[:, 1]]), -1, 1)
    return edges, pairs, np.degrees(np.arccos(cos))


def check_polyhedron(vertices, triangles, triangle_face=None):
    """Raise ShapeError unless (vertices, triangles) is a valid convex
    polyhedron: closed, outward, convex and within the tolerances of the
    module docstring.

    The checks, in order: at least 4 finite vertices and 4 triangles, every
    vertex in a triangle, every directed edge once and every edge in two
    triangles (closed, consistently oriented), vertices at least
    ``VERTEX_TOL`` d apart, a positive volume of at least ``VOLUME_TOL``
    d^3, no vertex more than ``CONVEX_TOL`` d outside a triangle's plane,
    no edge bending by ``COPLANAR_DEG`` to ``CREASE_DEG``, no geometric edge
    shorter than ``EDGE_TOL`` d, no single-triangle face with an altitude
    below ``HEIGHT_TOL`` d. Here d is twice the largest distance from the
    vertices' mean to a vertex.

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions, any units (the tolerances scale with d).
    triangles : (T, 3) int
        Vertex indices, counter-clockwise seen from outside.
    triangle_face : (T,) int, optional
        The geometric face of each triangle (default: computed with
        :func:`geometric_faces`).

    Returns
    -------
    None
        Nothing when the polyhedron is valid; otherwise ShapeError, whose
        message names the first defect found.

    Examples
    --------
    >>> import itertools
    >>> v, t = hull(np.array(list(itertools.product((-0.5, 0.5), repeat=3))))
    >>> check_polyhedron(v, t)                      # a cube: valid
    >>> flipped = t.copy()
    >>> flipped[0] = flipped[0, ::-1]               # one triangle turned inwards
    >>> check_polyhedron(v, flipped)
    Traceback (most recent call last):
    ...
    shapes.polyhedron.ShapeError: mesh is not consistently oriented (a directed edge repeats)
    >>> dented = v.copy()
    >>> dented[0] *= 0.9                            # a corner pushed inwards
    >>> check_polyhedron(dented, t)
    Traceback (most recent call last):
    ...
    shapes.polyhedron.ShapeError: not convex: vertex ... stands 3.02e-02 d outside triangle ...
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
    """The convex hull of a point set, with outward triangles (qhull).

    Works at any scale: the points are centred and scaled to unit size
    before qhull sees them.

    Parameters
    ----------
    points : (N, 3) float
        At least 4 points, any units.
    allow_interior : bool
        Drop the points inside the hull (or on it but not its vertices).
        False (the default): such a point is an error, the input being
        meant as the vertex set of a convex polyhedron.

    Returns
    -------
    vertices : (V, 3) float
        The hull's vertices, in the order of the input.
    triangles : (T, 3) int
        Indices into ``vertices``, counter-clockwise seen from outside.

    Raises
    ------
    ShapeError
        Fewer than 4 points, non-finite values, coincident points, two
        points closer than ``VERTEX_TOL`` d, (nearly) coplanar points (hull
        volume below ``VOLUME_TOL`` d^3), or, without ``allow_interior``, a
        point that is not a vertex of the hull.

    Examples
    --------
    >>> import itertools
    >>> cube = np.array(list(itertools.product((-0.5, 0.5), repeat=3)))
    >>> v, t = hull(cube)
    >>> v.shape, t.shape
    ((8, 3), (12, 3))
    >>> v, t = hull(np.vstack([cube, [[0, 0, 0]]]), allow_interior=True)   # the centre is dropped
    >>> len(v)
    8
    >>> hull(np.vstack([cube, [[0, 0, 0]]]))
    Traceback (most recent call last):
    ...
    shapes.polyhedron.ShapeError: point 8 lies inside the hull of the others: not the vertex set of a convex polyhedron
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
    and measure it: a :class:`Polyhedron` with d = 1.

    The frame: origin at the centre of mass (uniform density), axes along
    the principal axes of inertia by increasing principal moment (x long),
    x and y each towards its furthest vertex, z = x cross y, lengths divided
    by d = 2 x the largest centre-to-vertex distance. Mass properties by
    trimesh (Eberly's surface integrals, uniform density 1). The mesh is
    not checked here (:func:`check_polyhedron` does).

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions, any units and position.
    triangles : (T, 3) int
        A closed convex mesh, triangles counter-clockwise seen from outside.

    Returns
    -------
    Polyhedron
        The same triangles, the vertices in the normalised frame, and the
        volume, inertia, extents, area and geometric faces measured there.

    Examples
    --------
    A 1 x 1 x 2 box standing along z, away from the origin, comes back
    centred, long along x, with d = 1:

    >>> import itertools
    >>> v, t = hull(np.array(list(itertools.product((0, 1), (0, 1), (0, 2))), float) + 10)
    >>> box = normalise(v, t)
    >>> box.vertices.max(axis=0).round(4), box.dims.round(4)
    (array([0.4082, 0.2041, 0.2041]), array([0.8165, 0.4082, 0.4082]))
    >>> np.diag(box.inertia).round(5)           # the smallest moment about x
    array([0.00378, 0.00945, 0.00945])
    """
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
    """A valid :class:`Polyhedron` with d = 1 from a point set: its hull
    (:func:`hull`), checked (:func:`check_polyhedron`) and normalised
    (:func:`normalise`).

    Parameters
    ----------
    points : (N, 3) float
        At least 4 points, any units.
    allow_interior : bool
        Drop the points that are not vertices of the hull (default False:
        such a point is an error).

    Returns
    -------
    Polyhedron
        In the normalised frame, d = 1.

    Raises
    ------
    ShapeError
        Naming the defect (:func:`hull`, :func:`check_polyhedron`).

    Examples
    --------
    A regular tetrahedron:

    >>> tet = polyhedron_from_points(np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], float))
    >>> tet.n_vertices, tet.n_faces, tet.n_edges, round(tet.sphericity, 3)
    (4, 4, 6, 0.671)
    >>> round(tet.volume, 5)                    # edge a = sqrt(2/3) d, volume a^3 / (6 sqrt(2))
    0.06415
    """
    v, t = hull(points, allow_interior=allow_interior)
    check_polyhedron(v, t)
    return normalise(v, t)
