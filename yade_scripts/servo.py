"""Wall servo-control (numpy only): the strain rates that bring the wall
stresses to their targets.

YADE's TriaxialStressController needs Box walls, which Polyhedra cannot
touch, so the walls are YADE ``Wall`` bodies moved kinematically by this
proportional controller: along each controlled axis a,

    rate_a = max_rate * clip(gain * (target - sigma_a) / target, -1, 1)

(compression positive: a stress below target closes the walls). With a
packing of bulk stiffness K ~ kappa sigma0 the stress relaxes with time
constant 1 / (kappa * max_rate * gain); the caller keeps it well above dt.
"""
from __future__ import annotations

import numpy as np

#: wall order of the dump schema: x-, x+, y-, y+, z-, z+
WALL_ORDER = ("x-", "x+", "y-", "y+", "z-", "z+")


def wall_stresses(wall_forces, lengths):
    """(3,) Pa, compression positive: mean normal force of the two walls of
    each axis over their area. wall_forces (6, 3) N on the walls by the
    particles; lengths (3,) m."""
    F = np.asarray(wall_forces, float)
    L = np.asarray(lengths, float)
    area = np.array([L[1] * L[2], L[0] * L[2], L[0] * L[1]])
    push = np.array([(F[2 * a + 1, a] - F[2 * a, a]) / 2 for a in range(3)])
    return push / area


def servo_rates(stress, target, max_rate, gain):
    """(3,) 1/s strain rates (compression positive) for the three axes."""
    err = (target - np.asarray(stress, float)) / target
    return max_rate * np.clip(gain * err, -1.0, 1.0)


def wall_velocities(rates, lengths):
    """(6, 3) m/s velocities of the six walls for axis strain rates (3,)
    (compression positive): each wall of axis a moves inwards at
    rate_a * L_a / 2."""
    v = np.zeros((6, 3))
    for a in range(3):
        s = rates[a] * lengths[a] / 2
        v[2 * a, a] = s          # the minus wall moves towards +a
        v[2 * a + 1, a] = -s
    return v
