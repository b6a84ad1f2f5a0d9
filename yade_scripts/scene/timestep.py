"""Stiffness scaling and the critical time step (numpy only).

Stiffness level kappa (dimensionless) and inertial number I set the physics:

* spheres, linear law (YADE Law2_ScGeom_FrictPhys_CundallStrack, kn = E R
  for equal radii): kappa = kn / (sigma0 d) with d the mean diameter, so
  E = 2 kappa sigma0 and a contact overlap is delta/d ~ 1/kappa;
* polyhedra, volumetric law (F_n = k_V V_overlap): a face contact of area A
  has a linear stiffness k_V A. With a_f the library's mean face area at
  d = 1, the typical face contact of a mean grain has k = k_V a_f d^2, and
  kappa = k / (sigma0 d) gives k_V = kappa sigma0 / (a_f d). The tangential
  stiffness of a pair is k_t = ratio_t * k_V a_f d_pair^2.

The critical time step of a mass-spring system is 2 sqrt(m/k); for rigid
bodies a rotational mode is faster when the radius of gyration about an
axis is small compared with the lever arm of a contact about that axis:
per particle dt_c = sqrt(min(m, min_k I_k / r_k^2) / k) with k the stiffest
contact that particle can have, and the run uses dt = safety * min dt_c
(the scene parameter ``safety``: 0.45 for the polyhedra, the parameter's
default, and 0.3 for the spheres and in the ``tiny`` and ``soft`` presets),
the margin covering several contacts per particle.
"""
from __future__ import annotations

import numpy as np


def inertial_strain_rate(inertial_number, d_mean, density, pressure):
    """The strain rate of an inertial number: I = rate d sqrt(rho / p), so
    rate = I / (d sqrt(rho / p)).

    The scene shears at the rate of ``inertial_number`` (the top wall at
    rate x the height of the isotropic state) and compresses at most at
    that of ``compaction_inertial_number``. The paper moved its top wall at
    a constant 1 cm/s instead (Azema, Radjai & Saussine 2009, "Numerical
    procedures"); its contact dynamics has no stiffness, and here I and
    kappa set the rate and the stiffness in units of the packing
    (docs/scenes.md).

    Parameters
    ----------
    inertial_number : float
        I, dimensionless.
    d_mean : float
        m, the mean particle diameter.
    density : float
        kg/m^3, the particles' density.
    pressure : float
        Pa, the confining stress (sigma0).

    Returns
    -------
    numpy.float64 or numpy.ndarray
        1/s, the strain rate (an array when an input is one).

    Examples
    --------
    >>> round(float(inertial_strain_rate(5e-3, 0.03325, 2700.0, 1e4)), 4)   # the default S1: d = 3.325 cm, 10 kPa
    0.2894
    """
    return inertial_number / (d_mean * np.sqrt(density / pressure))


def rotational_mass(volume, inertia, vertices):
    """The effective mass of a grain's fastest rigid-body mode,
    min(V, min_k I_k / r_k^2), for a grain at d = 1 and unit density.

    A contact at distance r_k from the principal axis k drives the
    rotation about it with the effective mass I_k / r_k^2; when that is
    below the mass, rotation is the fastest mode (a flat grain touched at
    its rim).

    Parameters
    ----------
    volume : float
        The grain's volume at d = 1 (its mass at unit density).
    inertia : array_like, shape (3,)
        Its principal moments of inertia at d = 1 and unit density.
    vertices : array_like, shape (n, 3)
        Its vertices in its principal frame (centre of mass at the
        origin); r_k is the largest distance of a vertex from axis k.

    Returns
    -------
    float
        min(V, min_k I_k / r_k^2); multiplied by rho d^3 (kg/m^3, m) it is
        the effective mass in kg of a grain of diameter d.

    Examples
    --------
    >>> cube = [[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]
    >>> round(rotational_mass(1.0, [1 / 6, 1 / 6, 1 / 6], cube), 4)   # a unit cube: I / r^2 = (1/6) / 0.5
    0.3333
    """
    v = np.asarray(vertices, float)
    r2 = np.array([np.max(v[:, 1] ** 2 + v[:, 2] ** 2), np.max(v[:, 0] ** 2 + v[:, 2] ** 2),
                   np.max(v[:, 0] ** 2 + v[:, 1] ** 2)])
    return float(min(volume, np.min(np.asarray(inertia, float) / r2)))


def critical_time_step(effective_mass, stiffness):
    """The critical time step of the sample: min over particles of
    sqrt(m_eff / k) (the scene steps at ``safety`` times it).

    Parameters
    ----------
    effective_mass : array_like, shape (n,)
        kg, each particle's effective mass: for a polyhedron the smaller of
        its mass and min_k I_k / r_k^2 (:func:`rotational_mass`), for a
        sphere 0.4 m (I / R^2).
    stiffness : array_like, shape (n,)
        N/m, the stiffest contact each particle can have.

    Returns
    -------
    float
        s.

    Examples
    --------
    >>> critical_time_step([1.0, 2.0], [100.0, 800.0])    # sqrt(2 / 800)
    0.05
    """
    m = np.asarray(effective_mass, float)
    k = np.asarray(stiffness, float)
    return float(np.sqrt(np.min(m / k)))
