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
    """Exterior dihedral angles (E,) in degrees (angle between the outward
    normals of the two faces; 0 = flat, interior angle = 180 - this) and
    lengths (E,) of the geometric edges of a convex polyhedron.

    vertices : (V, 3); triangles : (T, 3) outward; triangle_face : (T,)
    geometric face per triangle (computed when None).
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
    """(3,) extents L >= I >= S of a closed polyhedron along its principal
    axes of inertia (uniform density), in the vertices' units."""
    import trimesh

    v = np.asarray(vertices, float)
    v = v - v.mean(axis=0)                   # about an inner point: no cancellation far from the origin
    m = trimesh.Trimesh(v, np.asarray(triangles), process=False)
    _, R = np.linalg.eigh(m.moment_inertia)
    local = (v - m.center_mass) @ R
    return np.sort(local.max(axis=0) - local.min(axis=0))[::-1]


def grain_descriptors(vertices, triangles, triangle_face=None, dims=None):
    """dict of the descriptors of one convex polyhedron (module docstring),
    without the import-only ones. vertices (V, 3) any units; triangles (T, 3)
    outward; dims (3,) principal extents if known (else computed)."""
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
    """dict name -> (S,) array of every descriptor of a
    :class:`shapes.library.ShapeLibrary`; the import-only ones are the
    library's own datasets when it has them, else 0."""
    rows = [grain_descriptors(*lib[s], dims=lib.dims[s]) for s in range(len(lib))]
    out = {k: np.array([r[k] for r in rows]) for k in rows[0]}
    for k in IMPORT_ONLY:
        out[k] = np.asarray(lib.data[k], float) if k in lib.data else np.zeros(len(lib))
    return {k: out[k] for k in NAMES}


def library_edge_angles(lib):
    """Every geometric edge of a library: (exterior angles (E,) deg, lengths
    (E,) in units of each grain's d)."""
    ang, length = [], []
    for s in range(len(lib)):
        a, l_ = dihedral_angles(*lib[s])
        ang.append(a)
        length.append(l_)
    return np.concatenate(ang), np.concatenate(length)


def compare(a, b, names=NAMES):
    """Distances between two descriptor tables (dicts of arrays, e.g. from
    :func:`library_descriptors`): per name the two-sample Kolmogorov-Smirnov
    statistic D and its p-value (scipy; for integer counts the p-value is
    conservative), its 95 % critical value 1.358 sqrt((n+m)/(n m)), the
    medians and the differences of the 10th, 50th and 90th percentiles
    (b - a). Names constant in both (e.g. zeros) get D = 0, p = 1."""
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
