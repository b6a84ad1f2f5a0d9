"""Stress tensors of a granular packing and their invariants.

Convention: compression positive; forces are forces on id2 by id1; the
compression axis is the major principal direction in triaxial compression.
"""
from __future__ import annotations

import numpy as np

from .axes import axis_vector
from .schema import WALL_ORDER


def contact_stress(force, vector, volume):
    """The stress tensor of a set of contacts, sigma = (1/V) sum_c f^c (x) v^c
    (seed eq. 2), compression positive.

    Parameters
    ----------
    force : array_like, shape (C, 3)
        N, the force of each contact on its particle id2 by id1.
    vector : array_like, shape (C, 3)
        m. With the branch vectors l = x2 - x1 of particle-particle contacts
        this is the branch-vector form; with the lever arms of
        :class:`~postproc.contactset.ContactSet` (wall contacts included) it
        is the sum of the particles' internal moments
        M^i = sum_c f^c (x) (x^c - x^i) (seed eq. 1), with the sign flipped to
        make compression positive.
    volume : float
        m^3, the volume of the packing.

    Returns
    -------
    sigma : ndarray, shape (3, 3)
        Pa, ``sigma[a, b] = sum_c f_a v_b / V``; compression positive; not
        symmetrised (its antisymmetric part measures the imbalance of
        moments).

    Examples
    --------
    Two contacts of a 1 litre packing, 10 N along z and 4 N along x, each
    pushing particle id2 away from id1 (compression):

    >>> import numpy as np
    >>> from postproc.stress import contact_stress
    >>> force = np.array([[0.0, 0.0, 10.0], [4.0, 0.0, 0.0]])
    >>> branch = np.array([[0.0, 0.0, 0.05], [0.05, 0.0, 0.0]])
    >>> print(contact_stress(force, branch, 1e-3))
    [[200.   0.   0.]
     [  0.   0.   0.]
     [  0.   0. 500.]]
    """
    force = np.asarray(force, float)
    vector = np.asarray(vector, float)
    return force.T @ vector / float(volume)


def wall_stress(wall_forces, box_lengths):
    """Stress from the forces on the six walls of a rectangular box.

    sigma[a, b] = (F^{b+}_a - F^{b-}_a) / (2 A_b) with A_b the area of the
    walls normal to axis b: the mean traction on the two opposite walls,
    compression positive.

    Parameters
    ----------
    wall_forces : array_like, shape (6, 3)
        N, the force on each wall by the particles, walls in the order x-,
        x+, y-, y+, z-, z+ (``schema.WALL_ORDER``). Particles pressing
        outward push the x- wall along -x and the x+ wall along +x.
    box_lengths : array_like, shape (3,)
        m, the box's lengths along x, y, z.

    Returns
    -------
    sigma : ndarray, shape (3, 3)
        Pa, compression positive.

    Examples
    --------
    A 0.1 x 0.1 x 0.2 m box whose particles press 5 N on each z wall and
    2 N on each lateral wall:

    >>> import numpy as np
    >>> from postproc.stress import wall_stress
    >>> walls = np.zeros((6, 3))
    >>> walls[0, 0], walls[1, 0], walls[2, 1], walls[3, 1] = -2.0, 2.0, -2.0, 2.0
    >>> walls[4, 2], walls[5, 2] = -5.0, 5.0
    >>> print(wall_stress(walls, [0.1, 0.1, 0.2]))
    [[100.   0.   0.]
     [  0. 100.   0.]
     [  0.   0. 500.]]
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
    sigma : array_like, shape (3, 3)
        Pa, compression positive (symmetrised here).
    axis : int, str or array_like of shape (3,), optional
        The compression axis: 0, 1, 2, 'x', 'y', 'z' or a unit vector
        (default 2, z).

    Returns
    -------
    dict
        ``principal`` : ndarray (3,), Pa, sigma_1 >= sigma_2 >= sigma_3;
        ``directions`` : ndarray (3, 3), column k the direction of sigma_k;
        ``p`` = (s1 + s2 + s3)/3 and ``q`` = (s1 - s3)/3, Pa (the factor 1/3
        is the seed's convention, which makes q/p = (2/5) sum of
        anisotropies, eq. 10); ``q_over_p``; ``q_axial`` = (sigma_aa - mean
        lateral)/3 along ``axis``, Pa, signed (negative in extension);
        ``angle_1``, degrees between the major principal direction and the
        axis; ``antisymmetry`` = |skew(sigma)| / |sigma| (Frobenius norms).

    Examples
    --------
    >>> import numpy as np
    >>> from postproc.stress import invariants
    >>> inv = invariants(np.diag([100.0, 100.0, 300.0]), axis="z")
    >>> print(round(inv["p"], 3), round(inv["q"], 3), round(inv["q_over_p"], 3), inv["angle_1"])
    166.667 66.667 0.4 0.0
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
    """The relative difference of two stress tensors.

    Parameters
    ----------
    sigma, reference : array_like, shape (3, 3)
        Pa, any common unit.

    Returns
    -------
    float
        |sigma - reference| / |reference| (Frobenius norms), dimensionless;
        NaN when either is not finite or the reference is zero.

    Examples
    --------
    >>> import numpy as np
    >>> from postproc.stress import relative_difference
    >>> print(round(relative_difference(np.diag([1.0, 1.0, 1.1]), np.eye(3)), 4))
    0.0577
    """
    sigma = np.asarray(sigma, float)
    reference = np.asarray(reference, float)
    if not (np.isfinite(sigma).all() and np.isfinite(reference).all()):
        return np.nan
    nref = np.linalg.norm(reference)
    return np.linalg.norm(sigma - reference) / nref if nref > 0 else np.nan
