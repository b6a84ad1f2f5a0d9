"""Wall servo-control (numpy only): the strain rates that bring the wall
stresses to their targets.

YADE's TriaxialStressController needs Box walls, which Polyhedra cannot
touch, so the walls are YADE ``Wall`` bodies moved kinematically by this
proportional-integral controller: along each controlled axis a,

    rate_a = max_rate * clip(gain * e_a + J_a, -1, 1),  e_a = (target - sigma_a) / target,
    J_a   += gain * e_a * dt / tau

(compression positive: a stress below target closes the walls). With a
packing of bulk stiffness K ~ kappa sigma0 the proportional part relaxes the
stress with time constant 1 / (kappa * max_rate * gain), kept well above dt;
the integral part (time tau, much longer) removes the steady error that a
purely proportional servo keeps while the walls have to move.
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


def servo_rates(stress, target, max_rate, gain, integral=None, dt=0.0, tau=np.inf):
    """(3,) 1/s strain rates (compression positive) for the three axes.

    Proportional-integral control: rate = max_rate * clip(gain e + J, -1, 1)
    with e = (target - stress)/target and J += gain e dt / tau, updated in
    place in ``integral`` (3,) when given. The integral term removes the
    steady error a proportional servo keeps while the walls must move (the
    lateral walls follow the dilatancy during shear); it integrates only
    while |e| < 0.2 and stays in [-1, 1] (anti-windup). Three numbers, so
    plain floats (the controller runs every step; numpy's calls on 3-arrays
    cost more than the arithmetic), in numpy's order of operations."""
    err = [(target - x) / target for x in np.asarray(stress, float).tolist()]
    if integral is not None and dt > 0 and np.isfinite(tau):
        J = integral.tolist()
        for a in range(3):
            if abs(err[a]) < 0.2:
                J[a] = J[a] + gain * err[a] * dt / tau
            J[a] = min(max(J[a], -1.0), 1.0)
        integral[:] = J
        return np.array([max_rate * min(max(gain * e + j, -1.0), 1.0) for e, j in zip(err, J)])
    return np.array([max_rate * min(max(gain * e, -1.0), 1.0) for e in err])


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
