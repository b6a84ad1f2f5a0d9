"""A convex polyhedron as LMGC90's POLYR sees it: its triangles oriented
outward, its topological faces (adjacent triangles within
:data:`TOPO_ANGLE`, merged), their contours and corners and the
topological edges (``mod_POLYR.f90``), one :class:`LmgcShape` per shape,
and :class:`LmgcTables`, the shapes padded to common sizes for the
vectorised detection of :mod:`postproc.lmgc90count`.

Pure functions over arrays; no file I/O.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .contactpoints import point_tables

TOPO_ANGLE = 5.0              # deg, POLYR topo_angle: adjacent triangles closer than this form one face


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
