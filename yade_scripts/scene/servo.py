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
    """The stress the walls carry along each axis: the mean of the normal
    forces on the two walls of the axis over their area,

        sigma_a = (F_{a+, a} - F_{a-, a}) / 2 / (L_b L_c),

    with b, c the two other axes. This is the boundary stress the servo
    holds at sigma0; the stress of the paper's analysis, (1/V) sum over
    contacts of f_alpha l_beta (Azema, Radjai & Saussine 2009, "Shear
    strength"), is computed from the contacts by :mod:`postproc.stress`.

    Parameters
    ----------
    wall_forces : array_like, shape (6, 3)
        N, the force on each wall by the particles, walls in
        :data:`WALL_ORDER` (x-, x+, y-, y+, z-, z+).
    lengths : array_like, shape (3,)
        m, the box's lengths along x, y, z.

    Returns
    -------
    numpy.ndarray, shape (3,)
        Pa, compression positive: particles pushing the walls apart give
        positive stresses.

    Examples
    --------
    >>> F = np.zeros((6, 3))
    >>> F[0, 0], F[1, 0] = -100.0, 100.0      # 100 N pushing the x walls outwards
    >>> F[4, 2], F[5, 2] = -200.0, 200.0      # 200 N on the z walls
    >>> wall_stresses(F, [0.1, 0.1, 0.2])     # the x walls are 0.1 x 0.2 m, the z walls 0.1 x 0.1 m
    array([ 5000.,     0., 20000.])
    """
    F = np.asarray(wall_forces, float)
    L = np.asarray(lengths, float)
    area = np.array([L[1] * L[2], L[0] * L[2], L[0] * L[1]])
    push = np.array([(F[2 * a + 1, a] - F[2 * a, a]) / 2 for a in range(3)])
    return push / area


def servo_rates(stress, target, max_rate, gain, integral=None, dt=0.0, tau=np.inf):
    """The wall servo's strain rates for the three axes: a
    proportional-integral controller,

        rate_a = max_rate clip(gain e_a + J_a, -1, 1),   e_a = (target - sigma_a) / target,
        J_a += gain e_a dt / tau.

    The integral term removes the steady error a proportional servo keeps
    while the walls must move (the lateral walls follow the dilatancy
    during shear); it integrates only while |e_a| < 0.2 and stays in
    [-1, 1] (anti-windup). Without ``integral``, or with ``dt = 0`` or an
    infinite ``tau``, the servo is proportional only. The arithmetic is on
    plain floats (the controller runs every step; numpy's calls on
    3-arrays cost more than the arithmetic), in numpy's order of
    operations.

    Parameters
    ----------
    stress : array_like, shape (3,)
        Pa, the wall stresses (:func:`wall_stresses`), compression positive.
    target : float
        Pa, the stress to reach on every axis (sigma0).
    max_rate : float
        1/s, the fastest strain rate of an axis.
    gain : float
        Dimensionless proportional gain (the scene lowers it so that one
        step changes the stress by at most a fifth of the error:
        :meth:`yade_scripts.scene.loading.TriaxialLoading.stable_gain`).
    integral : numpy.ndarray, shape (3,), optional
        The integral term J, updated in place.
    dt : float
        s, the time step (the integral's increment).
    tau : float
        s, the integral time.

    Returns
    -------
    numpy.ndarray, shape (3,)
        1/s, compression positive: a stress below the target gives a
        positive rate, which closes the walls (:func:`wall_velocities`).

    Examples
    --------
    >>> servo_rates([5000.0, 9900.0, 12000.0], 1e4, max_rate=0.5, gain=10.0)
    array([ 0.5 ,  0.05, -0.5 ])
    >>> J = np.zeros(3)
    >>> servo_rates([9900.0, 1e4, 1e4], 1e4, 0.5, 10.0, J, dt=1e-3, tau=1.0), J
    (array([0.05005, 0.     , 0.     ]), array([0.0001, 0.    , 0.    ]))
    """
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
    """The velocities of the six walls that strain the box at ``rates``:
    each wall of axis a moves inwards at rate_a L_a / 2, so the box's
    length along a changes at -rate_a L_a.

    Parameters
    ----------
    rates : array_like, shape (3,)
        1/s, strain rates of x, y, z, compression positive.
    lengths : array_like, shape (3,)
        m, the box's lengths.

    Returns
    -------
    numpy.ndarray, shape (6, 3)
        m/s, the velocity of each wall in :data:`WALL_ORDER` (x-, x+, y-,
        y+, z-, z+), along its own axis only.

    Examples
    --------
    >>> wall_velocities([0.1, 0.0, -0.1], [0.1, 0.1, 0.2])[[0, 1, 4, 5]]
    array([[ 0.005,  0.   ,  0.   ],
           [-0.005,  0.   ,  0.   ],
           [ 0.   ,  0.   , -0.01 ],
           [ 0.   ,  0.   ,  0.01 ]])
    """
    v = np.zeros((6, 3))
    for a in range(3):
        s = rates[a] * lengths[a] / 2
        v[2 * a, a] = s          # the minus wall moves towards +a
        v[2 * a + 1, a] = -s
    return v
