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
    """Strain rate (1/s) for inertial number I = rate d sqrt(rho / p)."""
    return inertial_number / (d_mean * np.sqrt(density / pressure))


def rotational_mass(volume, inertia, vertices):
    """min(V, min_k I_k / r_k^2) for a grain at d = 1 and unit density, in
    its principal frame: I_k (3,) principal moments, r_k the largest distance
    of a vertex from axis k. Multiplied by rho d^3 it is the effective mass
    of the fastest rigid-body mode under a contact at the worst lever."""
    v = np.asarray(vertices, float)
    r2 = np.array([np.max(v[:, 1] ** 2 + v[:, 2] ** 2), np.max(v[:, 0] ** 2 + v[:, 2] ** 2),
                   np.max(v[:, 0] ** 2 + v[:, 1] ** 2)])
    return float(min(volume, np.min(np.asarray(inertia, float) / r2)))


def critical_time_step(effective_mass, stiffness):
    """min over particles of sqrt(m_eff / k), in s.

    effective_mass (n,) kg: the smaller of the mass and I_k / r_k^2 (see
    :func:`rotational_mass`); stiffness (n,) N/m: the stiffest contact each
    particle can have."""
    m = np.asarray(effective_mass, float)
    k = np.asarray(stiffness, float)
    return float(np.sqrt(np.min(m / k)))
