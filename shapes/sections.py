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
    """(u, v) (3,) each: an orthonormal basis of the plane of unit ``normal``
    with u x v = normal."""
    n = np.asarray(normal, float)
    n = n / np.linalg.norm(n)
    helper = np.eye(3)[int(np.argmin(np.abs(n)))]
    u = np.cross(helper, n)
    u /= np.linalg.norm(u)
    return u, np.cross(n, u)


def edges_of(triangles):
    """(E, 2) int, the unique edges of a closed triangle mesh (T, 3)."""
    t = np.asarray(triangles, np.int64)
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    return np.unique(np.sort(e, axis=1), axis=0)


def polyhedron_section(vertices, triangles, point, normal):
    """(K, 3) m: the section of the convex polyhedron (vertices (V, 3),
    closed triangle mesh (T, 3)) by the plane through ``point`` (3,) with
    unit ``normal`` (3,), its vertices in order around it (counter-clockwise
    about ``normal``); (0, 3) when the plane misses the grain or only touches
    it (fewer than three distinct points).

    The vertices are the points where the hull's edges cross the plane
    (linear interpolation between the edge's ends, from the end nearer the
    plane) and the hull's vertices that lie on it; being convex, the section
    is their convex hull, ordered here by angle about their centroid."""
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
    """(disc centre (3,), disc radius) where the plane through ``point``
    with unit ``normal`` cuts the sphere, or None when it misses it: radius
    sqrt(r^2 - h^2) at the signed distance h of the centre from the plane."""
    c = np.asarray(centre, float)
    n = np.asarray(normal, float)
    h = float((c - np.asarray(point, float)) @ n)
    if abs(h) >= radius:
        return None
    return c - h * n, float(np.sqrt(radius * radius - h * h))


def polygon_area(polygon, normal):
    """Signed area (m^2) of a planar polygon (K, 3) about unit ``normal``
    (positive when counter-clockwise about it)."""
    p = np.asarray(polygon, float)
    if len(p) < 3:
        return 0.0
    return 0.5 * float(np.cross(p, np.roll(p, -1, axis=0)).sum(axis=0) @ np.asarray(normal, float))
