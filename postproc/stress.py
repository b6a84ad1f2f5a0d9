"""Stress tensors of a granular packing and their invariants.

Convention: compression positive; forces are forces on id2 by id1; the
compression axis is the major principal direction in triaxial compression.
"""
from __future__ import annotations

import numpy as np

from .axes import axis_vector
from .schema import WALL_ORDER


def contact_stress(force, vector, volume):
    """sigma = (1/V) sum_c f^c (x) v^c (seed eq. 2), compression positive.

    Parameters
    ----------
    force : (C, 3) N, contact force on id2 by id1.
    vector : (C, 3) m. With the branch vectors l = x2 - x1 of
        particle-particle contacts this is the branch-vector form; with the
        lever arms of :class:`~postproc.contactset.ContactSet` (wall contacts
        included) it is the sum of the particles' internal moments
        M^i = sum_c f^c (x) (x^c - x^i) (seed eq. 1), with the sign flipped
        to make compression positive.
    volume : float, m^3.

    Returns
    -------
    (3, 3) Pa, ``sigma[a, b] = sum_c f_a v_b / V``; not symmetrised.
    """
    force = np.asarray(force, float)
    vector = np.asarray(vector, float)
    return force.T @ vector / float(volume)


def wall_stress(wall_forces, box_lengths):
    """Stress from the forces on the six walls of a rectangular box.

    sigma[a, b] = (F^{b+}_a - F^{b-}_a) / (2 A_b) with A_b the area of the
    walls normal to axis b, i.e. the mean traction on the two opposite walls.
    Compression positive.

    Parameters
    ----------
    wall_forces : (6, 3) N, force on each wall by the particles, walls in the
        order x-, x+, y-, y+, z-, z+ (``schema.WALL_ORDER``).
    box_lengths : (3,) m.

    Returns
    -------
    (3, 3) Pa.
    """
    F = np.asarray(wall_forces, float).reshape(len(WALL_ORDER), 3)
    L = np.asarray(box_lengths, float)
    area = np.array([L[1] * L[2], L[0] * L[2], L[0] * L[1]])
    sigma = np.empty((3, 3))
    for b in range(3):
        sigma[:, b] = (F[2 * b + 1] - F[2 * b]) / (2.0 * area[b])
    return sigma


def invariants(sigma, axis=2):
    """Principal stresses and the triaxial invariants of the seed paper.

    Parameters
    ----------
    sigma : (3, 3) Pa, compression positive (symmetrised here).
    axis : int or (3,) unit vector, the compression axis.

    Returns
    -------
    dict with
      ``principal`` (3,) Pa, sigma_1 >= sigma_2 >= sigma_3;
      ``directions`` (3, 3), column k is the direction of sigma_k;
      ``p`` = (s1 + s2 + s3)/3 and ``q`` = (s1 - s3)/3 (Pa; the factor 1/3 is
      the seed's convention, which makes q/p = (2/5) sum of anisotropies);
      ``q_over_p``; ``q_axial`` = (sigma_aa - mean lateral)/3 along the given
      axis, signed (negative in extension); ``angle_1`` (deg) between the
      major principal direction and the axis; ``antisymmetry`` =
      |skew(sigma)| / |sigma| (Frobenius norms).
    """
    sigma = np.asarray(sigma, float)
    sym = 0.5 * (sigma + sigma.T)
    w, v = np.linalg.eigh(sym)
    order = np.argsort(w)[::-1]
    w, v = w[order], v[:, order]
    e = axis_vector(axis)
    p = w.sum() / 3.0
    q = (w[0] - w[2]) / 3.0
    s_aa = e @ sym @ e
    q_axial = (s_aa - (np.trace(sym) - s_aa) / 2.0) / 3.0
    norm = np.linalg.norm(sigma)
    skew = np.linalg.norm(0.5 * (sigma - sigma.T))
    cosang = min(1.0, abs(float(v[:, 0] @ e)))
    return {
        "principal": w, "directions": v, "p": p, "q": q,
        "q_over_p": q / p if p != 0 else np.nan,
        "q_axial": q_axial,
        "angle_1": float(np.degrees(np.arccos(cosang))),
        "antisymmetry": skew / norm if norm > 0 else 0.0,
    }


def relative_difference(sigma, reference):
    """|sigma - reference| / |reference| (Frobenius norms); NaN if either is
    not finite."""
    sigma = np.asarray(sigma, float)
    reference = np.asarray(reference, float)
    if not (np.isfinite(sigma).all() and np.isfinite(reference).all()):
        return np.nan
    nref = np.linalg.norm(reference)
    return np.linalg.norm(sigma - reference) / nref if nref > 0 else np.nan
