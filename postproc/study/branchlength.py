"""Branch-length anisotropy a_l of contact subsets, and the grain geometry
that could produce it.

The seed paper (eq. a2) fits the mean branch length per direction,

    <l>(theta) = l0 [1 + a_l (3 cos^2 theta - 1)],

theta the angle between the branch direction n' and the compression axis,
and :mod:`postproc.fabric` estimates a_l from the tensor
H^l = int <l>(Omega) n (x) n dOmega, a_l = (5/2)(H^l_3 - H^l_1) / tr H^l,
inverting the density weighting of the contact sums exactly for the
harmonic forms. This module reuses that estimator on subsets of contacts
(selected by a boolean mask: a contact type, an elongation class, ...)
and on other per-contact lengths (for instance l / d_pair, which takes the
size distribution out), and adds the geometry needed to predict a_l from
the grains' shapes and orientations:

* :func:`subset_anisotropy`: a and a_l (with delta-method standard errors)
  of the contacts selected by a mask;
* :func:`length_profile`: <l>(theta) in bins of theta, the direct form of
  eq. a2;
* :func:`principal_extents`: a convex polyhedron's extents L >= I >= S
  along the principal axes of its (uniform-density) inertia, and those
  axes, as the shape library defines elongation I/L and flatness S/I;
* :func:`radial_distance`: the distance from a convex polyhedron's centre
  of mass to its surface along given directions, so that
  rho_1(n) + rho_2(n) is the branch length of two grains touching on their
  line of centres (a model of l).

All functions are pure, take numpy arrays in SI units and never import
yade.
"""
from __future__ import annotations

import numpy as np

from ..axes import axis_vector
from ..fabric import anisotropies


def subset_anisotropy(branch, mask=None, axis=2, length=None):
    """Fabric anisotropy a and branch-length anisotropy a_l of a subset of
    contacts, with delta-method standard errors (contacts independent).

    Parameters
    ----------
    branch : (N, 3) m, branch vectors l = x2 - x1 (sign irrelevant).
    mask : (N,) bool or None, the contacts to use (None: all).
    axis : compression axis ("3"): 0/1/2, 'x'/'y'/'z' or a 3-vector.
    length : (N,) or None, the per-contact length whose directional mean
        is fitted (default |l|, m; e.g. |l| / d_pair for a dimensionless
        branch length). Must be finite and > 0 on the subset.

    Returns
    -------
    dict with ``a``, ``a_se``, ``a_l``, ``a_l_se`` (dimensionless; a_l as in
    seed eq. a2 and the tensor definition a_l = (5/2)(H^l_3 - H^l_1)/tr H^l,
    estimated by :func:`postproc.fabric.anisotropies`), ``l0`` (the sphere
    mean of <length>, units of ``length``), ``mean`` (the plain contact mean
    of ``length``) and ``n`` (contacts used). With fewer than 2 contacts
    the values are NaN.

    Positive a_l: branches are longer along the compression axis.
    """
    b = np.asarray(branch, float)
    if b.ndim != 2 or b.shape[1] != 3:
        raise ValueError(f"branch must be (N, 3), got {b.shape}")
    sel = np.ones(len(b), bool) if mask is None else np.asarray(mask, bool)
    if sel.shape != (len(b),):
        raise ValueError(f"mask must be ({len(b)},), got {sel.shape}")
    b = b[sel]
    nan = {"a": np.nan, "a_se": np.nan, "a_l": np.nan, "a_l_se": np.nan,
           "l0": np.nan, "mean": np.nan, "n": int(len(b))}
    if len(b) < 2:
        return nan
    norm = np.linalg.norm(b, axis=1)
    if not np.all(np.isfinite(norm) & (norm > 0)):
        raise ValueError("branch vectors of zero length or not finite")
    unit = b / norm[:, None]
    if length is not None:
        lam = np.asarray(length, float)
        if lam.shape != sel.shape:
            raise ValueError(f"length must be ({len(sel)},), got {lam.shape}")
        lam = lam[sel]
        if not np.all(np.isfinite(lam) & (lam > 0)):
            raise ValueError("lengths must be finite and > 0")
        b = unit * lam[:, None]
    else:
        lam = norm
    # a unit radial force on every contact: the force part of the estimator
    # is then exactly isotropic and only a, a_l (and their errors) are used
    r = anisotropies(b, unit, axis, errors=True)
    return {"a": float(r["a"]), "a_se": float(r["a_se"]), "a_l": float(r["a_l"]),
            "a_l_se": float(r["a_l_se"]), "l0": float(r["l0"]), "mean": float(lam.mean()),
            "n": int(len(b))}


def length_profile(branch, length=None, axis=2, edges_deg=(0, 15, 30, 45, 60, 75, 90)):
    """<length>(theta): the mean per-contact length in bins of the angle
    theta (deg, 0..90) between the branch direction and the compression
    axis, the direct form of seed eq. a2.

    branch : (N, 3) m; length : (N,) or None (|l|); axis as in
    :func:`subset_anisotropy`; edges_deg : increasing bin edges in [0, 90].

    Returns dict of arrays over the K bins: ``lo``, ``hi`` (deg), ``n``
    (contacts), ``frac`` (share of the contacts), ``mean``, ``sd`` and
    ``se`` of the length (NaN in empty bins).
    """
    b = np.asarray(branch, float)
    norm = np.linalg.norm(b, axis=1)
    lam = norm if length is None else np.asarray(length, float)
    c = np.abs(b @ axis_vector(axis)) / norm
    theta = np.degrees(np.arccos(np.clip(c, 0, 1)))
    e = np.asarray(edges_deg, float)
    k = np.clip(np.searchsorted(e, theta, side="right") - 1, 0, len(e) - 2)
    out = {"lo": e[:-1], "hi": e[1:], "n": np.zeros(len(e) - 1, int)}
    for name in ("mean", "sd", "se"):
        out[name] = np.full(len(e) - 1, np.nan)
    for j in range(len(e) - 1):
        x = lam[k == j]
        out["n"][j] = len(x)
        if len(x):
            out["mean"][j] = x.mean()
        if len(x) > 1:
            out["sd"][j] = x.std(ddof=1)
            out["se"][j] = out["sd"][j] / np.sqrt(len(x))
    out["frac"] = out["n"] / max(len(lam), 1)
    return out


def solid_moments(vertices, triangles):
    """Volume, centroid (3,) and second moment about the centroid (3, 3) of
    a closed, outward-oriented triangle mesh (tetrahedra from the origin:
    int x x^T over a tetrahedron (0, a, b, c) = det/120 [a a^T + b b^T +
    c c^T + s s^T], s = a + b + c, det = a . (b x c))."""
    v = np.asarray(vertices, float)
    t = np.asarray(triangles, np.int64)
    ref = v.mean(axis=0)
    a, b, c = v[t[:, 0]] - ref, v[t[:, 1]] - ref, v[t[:, 2]] - ref
    det = np.einsum("ij,ij->i", a, np.cross(b, c))
    vol = det.sum() / 6
    s = a + b + c
    cen = (det[:, None] * s).sum(axis=0) / 24 / vol
    M = (np.einsum("i,ij,ik->jk", det, a, a) + np.einsum("i,ij,ik->jk", det, b, b)
         + np.einsum("i,ij,ik->jk", det, c, c) + np.einsum("i,ij,ik->jk", det, s, s)) / 120
    M -= vol * np.outer(cen, cen)
    return vol, cen + ref, M


def principal_extents(vertices, triangles):
    """Extents of a convex polyhedron along its principal axes of inertia.

    vertices : (V, 3) m; triangles : (T, 3) int, outward oriented.

    Returns (dims, axes): dims (3,) m, the extents L >= I >= S of the vertex
    cloud along the principal axes (as ``dims`` in the shape library, so
    I/L is the elongation and S/I the flatness); axes (3, 3), column k the
    unit principal axis of dims[k] in the frame of ``vertices`` (column 0
    the long axis: smallest moment of inertia, largest second moment).
    """
    v = np.asarray(vertices, float)
    vol, cen, M = solid_moments(v, triangles)
    if not (np.isfinite(vol) and vol > 0):
        raise ValueError("mesh with zero or negative volume (not closed or inward oriented)")
    w, R = np.linalg.eigh(M)
    R = R[:, ::-1]                          # largest second moment first
    proj = (v - cen) @ R
    ext = proj.max(axis=0) - proj.min(axis=0)
    order = np.argsort(ext)[::-1]
    return ext[order], R[:, order]


def radial_distance(vertices, triangles, directions, centre=None):
    """Distance from the centre to the surface of a convex polyhedron along
    each direction: rho(u) = min over the faces with n_f . u > 0 of
    h_f / (n_f . u), h_f the face plane's distance from the centre.

    vertices : (V, 3) m; triangles : (T, 3) int, outward oriented;
    directions : (K, 3) unit vectors in the frame of ``vertices``;
    centre : (3,) m, a point inside (default the centre of mass).

    Returns (K,) m.
    """
    v = np.asarray(vertices, float)
    t = np.asarray(triangles, np.int64)
    if centre is None:
        _, centre, _ = solid_moments(v, t)
    p = v - np.asarray(centre, float)
    n = np.cross(p[t[:, 1]] - p[t[:, 0]], p[t[:, 2]] - p[t[:, 0]])
    n /= np.linalg.norm(n, axis=1)[:, None]
    h = np.einsum("ij,ij->i", n, p[t[:, 0]])
    u = np.asarray(directions, float)
    dots = u @ n.T                                      # (K, T)
    with np.errstate(divide="ignore", invalid="ignore"):
        r = np.where(dots > 1e-12, h[None, :] / dots, np.inf)
    return r.min(axis=1)
