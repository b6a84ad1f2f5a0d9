"""Shape descriptors of grains and libraries, generated and imported alike.

Per grain (a convex polyhedron, any size; all descriptors are scale-free):

======================  ==================================================
``n_vertices``          vertices
``n_faces``             geometric faces (coplanar triangles merged, as in
                        :func:`shapes.polyhedron.geometric_faces`)
``n_edges``             geometric edges (between two different faces)
``elongation``          I/L, the extents along the principal axes of
                        inertia sorted L >= I >= S (Zingg's ratios)
``flatness``            S/I
``s_over_l``            S/L
``sphericity``          Wadell's pi^(1/3) (6 V)^(2/3) / A (1 for a ball,
                        0.806 for a cube, 0.671 for a regular tetrahedron)
``angularity_deg``      the edge-length weighted mean of the exterior
                        dihedral angle (the angle between the outward
                        normals of the two faces) over the geometric edges,
                        degrees: 90 for a cube, 109.47 for a regular
                        tetrahedron, -> 0 for ever finer polyhedra of a
                        smooth body. For a convex polyhedron
                        sum(L_e theta_e) = 2 pi b, with b its mean width,
                        so this is 2 pi b / (total edge length)
``sharpest_edge_deg``   the smallest interior dihedral angle (180 - the
                        largest exterior angle), degrees
``convexity_deficit``   1 - V_mesh / V_hull of the grain as scanned (0 for
                        generated grains, which are convex by construction)
``reduction_hausdorff`` Hausdorff distance between the reduced grain and
                        the full hull, relative to d (0 for generated ones)
``reduction_volume_change``  V_reduced / V_hull - 1 (0 for generated ones)
======================  ==================================================

:func:`dihedral_angles` gives the per-edge distribution (the angularity
histogram of the report). Everything here is numpy (+ scipy through
:mod:`shapes.polyhedron`).
"""
from __future__ import annotations

import numpy as np

from .polyhedron import edge_triangles, geometric_faces, triangle_normals

#: descriptors of one grain, in table order
NAMES = ("n_vertices", "n_faces", "n_edges", "elongation", "flatness", "s_over_l", "sphericity",
         "angularity_deg", "sharpest_edge_deg", "convexity_deficit", "reduction_hausdorff",
         "reduction_volume_change")
#: the descriptors ``build --like`` matches
MATCHED = ("elongation", "flatness", "n_vertices")
#: what the import measured; zero for generated grains
IMPORT_ONLY = ("convexity_deficit", "reduction_hausdorff", "reduction_volume_change")


def dihedral_angles(vertices, triangles, triangle_face=None):
    """The exterior dihedral angle and the length of every geometric edge
    of a convex polyhedron (the edges between two different geometric
    faces; the diagonals inside a face are left out).

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions, any units.
    triangles : (T, 3) int
        Closed mesh, triangles counter-clockwise seen from outside.
    triangle_face : (T,) int, optional
        The geometric face of each triangle (default: computed with
        :func:`shapes.polyhedron.geometric_faces`).

    Returns
    -------
    angles : (E,) float
        deg, the angle between the outward normals of the edge's two faces
        (0 = flat; the interior dihedral angle is 180 - this).
    lengths : (E,) float
        The edges' lengths, in the vertices' units.

    Examples
    --------
    A 1 x 1 x 2 box: 12 edges at 90 deg, four of them 2 long:

    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((0, 1), (0, 1), (0, 2))), float))
    >>> angles, lengths = dihedral_angles(v, t)
    >>> np.unique(angles.round(6)).tolist(), sorted(lengths.tolist())
    ([90.0], [1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 2.0])
    """
    v = np.asarray(vertices, float)
    t = np.asarray(triangles)
    tf = geometric_faces(v, t) if triangle_face is None else np.asarray(triangle_face)
    edges, pairs = edge_triangles(t)
    feat = tf[pairs[:, 0]] != tf[pairs[:, 1]]
    n, _ = triangle_normals(v, t)
    cos = np.clip(np.einsum("ij,ij->i", n[pairs[feat, 0]], n[pairs[feat, 1]]), -1.0, 1.0)
    e = edges[feat]
    return np.degrees(np.arccos(cos)), np.linalg.norm(v[e[:, 0]] - v[e[:, 1]], axis=1)


def principal_extents(vertices, triangles):
    """The extents of a closed polyhedron along its principal axes of
    inertia (uniform density): the L, I, S of Zingg's ratios.

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions, any units and position.
    triangles : (T, 3) int
        Closed mesh, triangles counter-clockwise seen from outside.

    Returns
    -------
    (3,) float
        The extents (max - min of the vertices along each principal axis),
        sorted L >= I >= S, in the vertices' units.

    Examples
    --------
    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((0, 1), (0, 1), (0, 2))), float))
    >>> principal_extents(v, t).round(12), principal_extents(3 * v + 100, t).round(12)
    (array([2., 1., 1.]), array([6., 3., 3.]))
    """
    import trimesh

    v = np.asarray(vertices, float)
    v = v - v.mean(axis=0)                   # about an inner point: no cancellation far from the origin
    m = trimesh.Trimesh(v, np.asarray(triangles), process=False)
    _, R = np.linalg.eigh(m.moment_inertia)
    local = (v - m.center_mass) @ R
    return np.sort(local.max(axis=0) - local.min(axis=0))[::-1]


def grain_descriptors(vertices, triangles, triangle_face=None, dims=None):
    """The descriptors of one convex polyhedron (module docstring), all but
    the import-only ones (``IMPORT_ONLY``).

    Parameters
    ----------
    vertices : (V, 3) float
        Vertex positions, any units (every descriptor is scale-free).
    triangles : (T, 3) int
        Closed convex mesh, triangles counter-clockwise seen from outside.
    triangle_face : (T,) int, optional
        The geometric face of each triangle (default: computed with
        :func:`shapes.polyhedron.geometric_faces`).
    dims : (3,) float, optional
        The principal extents L >= I >= S when known (a library's
        ``dims``); default: :func:`principal_extents`.

    Returns
    -------
    dict
        ``n_vertices``, ``n_faces``, ``n_edges`` (int), ``elongation``
        (I/L), ``flatness`` (S/I), ``s_over_l``, ``sphericity`` (Wadell's),
        ``angularity_deg`` (length-weighted mean exterior dihedral angle,
        deg) and ``sharpest_edge_deg`` (smallest interior dihedral angle,
        deg).

    Examples
    --------
    A 1 x 1 x 2 box and a regular tetrahedron:

    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> box = hull(np.array(list(itertools.product((0, 1), (0, 1), (0, 2))), float))
    >>> d = grain_descriptors(*box)
    >>> d["n_vertices"], d["n_faces"], d["n_edges"], float(d["elongation"]), float(d["flatness"])
    (8, 6, 12, 0.5, 1.0)
    >>> tet = hull(np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], float))
    >>> d = grain_descriptors(*tet)
    >>> round(d["sphericity"], 4), round(d["angularity_deg"], 2), round(d["sharpest_edge_deg"], 2)
    (0.6711, 109.47, 70.53)
    """
    v = np.asarray(vertices, float)
    t = np.asarray(triangles)
    tf = geometric_faces(v, t) if triangle_face is None else np.asarray(triangle_face)
    L, I, S = principal_extents(v, t) if dims is None else np.asarray(dims, float)
    _, area = triangle_normals(v, t)
    c = v.mean(axis=0)
    vol = np.einsum("ij,ij->i", v[t[:, 0]] - c, np.cross(v[t[:, 1]] - c, v[t[:, 2]] - c)).sum() / 6
    ang, length = dihedral_angles(v, t, tf)
    n_faces = int(tf.max()) + 1
    return {"n_vertices": len(v), "n_faces": n_faces, "n_edges": len(ang),
            "elongation": I / L, "flatness": S / I, "s_over_l": S / L,
            "sphericity": float(np.pi ** (1 / 3) * (6 * vol) ** (2 / 3) / area.sum()),
            "angularity_deg": float(np.sum(ang * length) / np.sum(length)),
            "sharpest_edge_deg": float(180.0 - ang.max())}


def library_descriptors(lib):
    """Every descriptor (``NAMES``, module docstring) of every grain of a
    library.

    Parameters
    ----------
    lib : shapes.library.ShapeLibrary
        The library (its ``dims`` give the principal extents).

    Returns
    -------
    dict
        name -> (S,) array, one row per grain, in the order of ``NAMES``.
        The import-only descriptors are the library's own datasets when it
        has them (an imported library), else 0.

    Examples
    --------
    >>> import os, tempfile
    >>> from shapes.generate import generate_library
    >>> from shapes.library import ShapeLibrary, write_library
    >>> path = os.path.join(tempfile.mkdtemp(), "lib.h5")
    >>> write_library(path, generate_library(3, seed=0)[0], seed=0, recipe={}, tolerances={})
    >>> desc = library_descriptors(ShapeLibrary(path))
    >>> list(desc) == list(NAMES), desc["elongation"].shape
    (True, (3,))
    >>> bool(np.all(desc["n_faces"] == 2 * desc["n_vertices"] - 4)), desc["convexity_deficit"].tolist()
    (True, [0.0, 0.0, 0.0])
    """
    rows = [grain_descriptors(*lib[s], dims=lib.dims[s]) for s in range(len(lib))]
    out = {k: np.array([r[k] for r in rows]) for k in rows[0]}
    for k in IMPORT_ONLY:
        out[k] = np.asarray(lib.data[k], float) if k in lib.data else np.zeros(len(lib))
    return {k: out[k] for k in NAMES}


def library_edge_angles(lib):
    """The exterior dihedral angle and the length of every geometric edge
    of every grain of a library (:func:`dihedral_angles`, grain after
    grain): the distribution of the report's edge histogram.

    Parameters
    ----------
    lib : shapes.library.ShapeLibrary
        The library.

    Returns
    -------
    angles : (E,) float
        deg, the exterior dihedral angles, E the library's total of
        geometric edges (the sum of ``lib.n_edges``).
    lengths : (E,) float
        The edges' lengths, in units of each grain's d.

    Examples
    --------
    >>> import os, tempfile
    >>> from shapes.generate import generate_library
    >>> from shapes.library import ShapeLibrary, write_library
    >>> path = os.path.join(tempfile.mkdtemp(), "lib.h5")
    >>> write_library(path, generate_library(3, seed=0)[0], seed=0, recipe={}, tolerances={})
    >>> lib = ShapeLibrary(path)
    >>> angles, lengths = library_edge_angles(lib)
    >>> len(angles) == int(lib.n_edges.sum()), bool(np.all((angles >= 3) & (angles < 180)))
    (True, True)
    """
    ang, length = [], []
    for s in range(len(lib)):
        a, l_ = dihedral_angles(*lib[s])
        ang.append(a)
        length.append(l_)
    return np.concatenate(ang), np.concatenate(length)


def compare(a, b, names=NAMES):
    """How far apart two descriptor tables are, descriptor by descriptor:
    the two-sample Kolmogorov-Smirnov test and quantile differences.

    Parameters
    ----------
    a, b : dict
        Descriptor tables, name -> (n,) and (m,) arrays (e.g. from
        :func:`library_descriptors`).
    names : sequence of str
        The descriptors to compare (default ``NAMES``); each must be in
        both tables.

    Returns
    -------
    dict
        name -> dict with ``ks_D`` (the KS statistic: the largest distance
        between the two empirical distribution functions), ``ks_p`` (its
        p-value, scipy's ``ks_2samp``: exact when n m <= 10 000, else
        asymptotic; conservative for integer counts), ``ks_D_crit95`` (the
        95 % critical value 1.358 sqrt((n + m) / (n m))), ``n_a``, ``n_b``,
        ``mean_a``, ``mean_b`` and ``dq10``, ``dq50``, ``dq90`` (the
        differences b - a of the 10th, 50th and 90th percentiles). A
        descriptor constant over both tables (e.g. zeros) gets D = 0 and
        p = 1.

    Examples
    --------
    >>> a = {"elongation": np.linspace(0.5, 0.9, 50)}
    >>> b = {"elongation": np.linspace(0.6, 1.0, 50)}
    >>> st = compare(a, b, names=("elongation",))["elongation"]
    >>> round(st["ks_D"], 2), round(float(st["ks_D_crit95"]), 3), round(st["dq50"], 6)
    (0.26, 0.272, 0.1)
    >>> compare(a, a, names=("elongation",))["elongation"]["ks_D"]
    0.0
    """
    from scipy.stats import ks_2samp

    out = {}
    for k in names:
        x, y = np.asarray(a[k], float), np.asarray(b[k], float)
        n, m = len(x), len(y)
        if np.ptp(np.concatenate([x, y])) == 0:
            D, p = 0.0, 1.0
        else:
            # exact p-values for small samples, the asymptotic form beyond (scipy's exact one
            # gives up on large samples with ties, e.g. vertex counts)
            r = ks_2samp(x, y, method="exact" if n * m <= 10_000 else "asymp")
            D, p = float(r.statistic), float(r.pvalue)
        qa, qb = np.percentile(x, [10, 50, 90]), np.percentile(y, [10, 50, 90])
        out[k] = {"ks_D": D, "ks_p": p, "ks_D_crit95": 1.358 * np.sqrt((n + m) / (n * m)),
                  "n_a": n, "n_b": m, "mean_a": float(x.mean()), "mean_b": float(y.mean()),
                  "dq10": float(qb[0] - qa[0]), "dq50": float(qb[1] - qa[1]), "dq90": float(qb[2] - qa[2])}
    return out
