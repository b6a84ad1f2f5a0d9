"""Coordination number, rattlers and the share of weak forces."""
from __future__ import annotations

import numpy as np

#: a contact bears force when |f| > FORCE_FLOOR * max |f| of the snapshot
FORCE_FLOOR = 1e-9


def force_bearing(force):
    """(C,) bool: contacts whose force magnitude exceeds FORCE_FLOOR times the
    largest one (relative, so it does not depend on the force unit).

    force : (C, 3) N.
    """
    mag = np.sqrt(np.einsum("ij,ij->i", force, force))
    top = mag.max() if len(mag) else 0.0
    return mag > FORCE_FLOOR * top if top > 0 else np.zeros(len(mag), bool)


def rattlers(i1, i2, bearing, n_particles, min_contacts=2):
    """(B,) bool: particles with fewer than ``min_contacts`` force-bearing
    contacts (walls count), removed iteratively: a particle that drops below
    the threshold once its rattling neighbours are discarded is a rattler too.

    i1, i2 : (C,) int, particle rows of the two sides (-1 for a wall).
    bearing : (C,) bool, force-bearing contacts.
    """
    i1 = np.asarray(i1)
    i2 = np.asarray(i2)
    active = np.asarray(bearing, bool).copy()
    rattler = np.zeros(n_particles, bool)
    while True:
        k = (np.bincount(i1[active & (i1 >= 0)], minlength=n_particles)
             + np.bincount(i2[active & (i2 >= 0)], minlength=n_particles))
        new = (k < min_contacts) & ~rattler
        if not new.any():
            return rattler
        rattler |= new
        gone = ((i1 >= 0) & rattler[np.maximum(i1, 0)]) | ((i2 >= 0) & rattler[np.maximum(i2, 0)])
        active &= ~gone


def coordination(i1, i2, force, n_particles):
    """Coordination numbers of the particle-particle contact network.

    z = 2 N_c / N_p with N_c the force-bearing particle-particle contacts.
    ``z`` counts only non-rattlers and the contacts between them (the usual
    definition); ``z_all`` counts every particle and contact.

    i1, i2 : (C,) int particle rows (-1 for walls); force : (C, 3) N.

    Returns dict with ``z``, ``z_all``, ``n_rattlers``, ``n_bearing``.
    """
    bearing = force_bearing(force)
    pp = (np.asarray(i1) >= 0) & (np.asarray(i2) >= 0)
    rat = rattlers(i1, i2, bearing, n_particles)
    ok = pp & bearing
    keep = ok & ~rat[np.maximum(i1, 0)] & ~rat[np.maximum(i2, 0)]
    n_live = n_particles - int(rat.sum())
    return {
        "z": 2.0 * keep.sum() / n_live if n_live > 0 else 0.0,
        "z_all": 2.0 * ok.sum() / n_particles if n_particles else np.nan,
        "n_rattlers": int(rat.sum()),
        "n_bearing": int(ok.sum()),
    }


def fraction_below_mean(normal_force):
    """Fraction of the given normal forces (N, any unit) below their mean."""
    fn = np.asarray(normal_force, float)
    return float(np.mean(fn < fn.mean())) if len(fn) else np.nan
