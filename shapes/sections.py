"""Plane sections of grains: the convex polygon where a plane cuts a convex
polyhedron, and the disc where it cuts a sphere (numpy only).

Used by the analysis to draw slabs through a packing (``postproc.slab``).
A plane is given by a point on it and its unit normal; a polygon comes back
as its vertices (K, 3) in order around it (counter-clockwise seen from the
side the normal points to), in the same units as the input.
"""
from __future__ import annotations

import numpy as np


def plane_basis(normal):
    """An orthonormal basis of the plane normal to a vector, right-handed
    about it.

    Parameters
    ----------
    normal : (3,) float
        The plane's normal (normalised here; not zero).

    Returns
    -------
    u, v : (3,) float
        Unit vectors in the plane, orthogonal, with u x v = normal /
        |normal|.

    Examples
    --------
    >>> u, v = plane_basis([0, 0, 2])
    >>> u + 0.0, v + 0.0, np.cross(u, v) + 0.0
    (array([ 0., -1.,  0.]), array([1., 0., 0.]), array([0., 0., 1.]))
    """
    n = np.asarray(normal, float)
    n = n / np.linalg.norm(n)
    helper = np.eye(3)[int(np.argmin(np.abs(n)))]
    u = np.cross(helper, n)
    u /= np.linalg.norm(u)
    return u, np.cross(n, u)


def edges_of(triangles):
    """The edges of a triangle mesh, each once.

    Parameters
    ----------
    triangles : (T, 3) int
        Vertex indices of the triangles.

    Returns
    -------
    (E, 2) int
        Vertex indices of each edge, smaller first, sorted (E = 3T / 2 for
        a closed mesh).

    Examples
    --------
    >>> edges_of([[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]]).tolist()     # a tetrahedron
    [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]]
    """
    t = np.asarray(triangles, np.int64)
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    return np.unique(np.sort(e, axis=1), axis=0)


def polyhedron_section(vertices, triangles, point, normal):
    """The convex polygon where a plane cuts a convex polyhedron.

    The polygon's points are where the mesh's edges cross the plane
    (linear interpolation between the edge's two ends) and the mesh's
    vertices that lie on it, ordered by angle about their centroid. Every
    triangle edge counts, so where the plane crosses an edge between two
    coplanar triangles (a face's diagonal) the polygon has an extra point
    on one of its sides; the polygon, and its area, are the same.

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions of the polyhedron (m, or any unit), in the same
        frame as the plane.
    triangles : (T, 3) int
        Its closed triangle mesh.
    point : (3,) float
        A point of the plane.
    normal : (3,) float
        The plane's unit normal.

    Returns
    -------
    (K, 3) float
        The polygon's points in order around it, counter-clockwise about
        ``normal``, in the vertices' units; a plane through a face gives
        that face. (0, 3) when the plane misses the polyhedron or touches
        it at a vertex or an edge only (fewer than three distinct points).

    Examples
    --------
    A unit cube cut across by z = 0.1, and through its centre normal to
    a diagonal (a regular hexagon of side sqrt(2) / 2):

    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((-0.5, 0.5), repeat=3))))
    >>> square = polyhedron_section(v, t, [0, 0, 0.1], [0, 0, 1])
    >>> bool(np.allclose(square[:, 2], 0.1)), polygon_area(square, [0, 0, 1])
    (True, 1.0)
    >>> n = np.ones(3) / np.sqrt(3)
    >>> round(polygon_area(polyhedron_section(v, t, [0, 0, 0], n), n), 6), round(3 * 3 ** 0.5 / 4, 6)
    (1.299038, 1.299038)
    >>> polyhedron_section(v, t, [0, 0, 2], [0, 0, 1]).shape      # misses it
    (0, 3)
    """
    V = np.asarray(vertices, float)
    n = np.asarray(normal, float)
    d = (V - np.asarray(point, float)) @ n
    e = edges_of(triangles)
    da, db = d[e[:, 0]], d[e[:, 1]]
    cross = ((da < 0) & (db > 0)) | ((da > 0) & (db < 0))
    a, b = e[cross, 0], e[cross, 1]
    t = (d[a] / (d[a] - d[b]))[:, None]
    pts = np.concatenate([V[a] + t * (V[b] - V[a]), V[d == 0]])
    if len(pts) < 3:
        return np.zeros((0, 3))
    u, v = plane_basis(n)
    c = pts.mean(axis=0)
    ang = np.arctan2((pts - c) @ v, (pts - c) @ u)
    pts = pts[np.argsort(ang)]
    size = np.abs(V - V.mean(axis=0)).max()
    keep = np.linalg.norm(pts - np.roll(pts, 1, axis=0), axis=1) > 1e-12 * size
    pts = pts[keep]
    return pts if len(pts) >= 3 else np.zeros((0, 3))


def sphere_section(centre, radius, point, normal):
    """The disc where a plane cuts a sphere.

    Parameters
    ----------
    centre : (3,) float
        The sphere's centre (m, or any unit).
    radius : float
        Its radius, same unit.
    point : (3,) float
        A point of the plane.
    normal : (3,) float
        The plane's unit normal.

    Returns
    -------
    (disc_centre, disc_radius) or None
        The disc's centre (3,), the projection of ``centre`` on the plane,
        and its radius sqrt(radius^2 - h^2), h the signed distance of the
        centre from the plane; None when |h| >= radius (the plane misses
        the sphere or touches it at one point).

    Examples
    --------
    >>> sphere_section([0, 0, 0], 0.5, [0, 0, 0.3], [0, 0, 1])
    (array([0. , 0. , 0.3]), 0.4)
    >>> sphere_section([0, 0, 0], 0.5, [0, 0, 0.5], [0, 0, 1]) is None
    True
    """
    c = np.asarray(centre, float)
    n = np.asarray(normal, float)
    h = float((c - np.asarray(point, float)) @ n)
    if abs(h) >= radius:
        return None
    return c - h * n, float(np.sqrt(radius * radius - h * h))


def polygon_area(polygon, normal):
    """The signed area of a planar polygon in space.

    Parameters
    ----------
    polygon : (K, 3) float
        The polygon's vertices in order (m, or any unit).
    normal : (3,) float
        The unit normal of its plane.

    Returns
    -------
    float
        The area (m^2, the unit squared): positive when the vertices run
        counter-clockwise about ``normal``, negative when clockwise, 0 for
        fewer than three vertices.

    Examples
    --------
    >>> square = [[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0]]
    >>> polygon_area(square, [0, 0, 1]), polygon_area(square[::-1], [0, 0, 1])
    (2.0, -2.0)
    """
    p = np.asarray(polygon, float)
    if len(p) < 3:
        return 0.0
    return 0.5 * float(np.cross(p, np.roll(p, -1, axis=0)).sum(axis=0) @ np.asarray(normal, float))
