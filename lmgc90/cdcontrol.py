"""The CD cell's walls: the box they bound, their stresses, the forces that
hold sigma0, and when the isotropic state is reached. Pure numpy.

Walls in the dump's order x-, x+, y-, y+, z-, z+ (``postproc.schema.WALL_ORDER``);
compression positive.
"""
from __future__ import annotations

import numpy as np

from .cdmodel import WALL_AXES


def box_from_walls(centres, half_thickness):
    """The box bounded by the walls' inner faces.

    Parameters
    ----------
    centres : array_like, shape (6, 3)
        m, the walls' centres, dump order x-, x+, y-, y+, z-, z+.
    half_thickness : float
        m.

    Returns
    -------
    lo, hi : ndarray, shape (3,)
        m.

    Examples
    --------
    >>> import numpy as np
    >>> from lmgc90.cdcontrol import box_from_walls
    >>> c = np.array([[-.1, .5, 1], [1.1, .5, 1], [.5, -.1, 1], [.5, 1.1, 1], [.5, .5, -.1], [.5, .5, 2.1]])
    >>> lo, hi = box_from_walls(c, 0.1)
    >>> print(lo, hi)
    [0. 0. 0.] [1. 1. 2.]
    """
    c = np.asarray(centres, float).reshape(6, 3)
    lo = np.array([c[0, 0], c[2, 1], c[4, 2]]) + half_thickness
    hi = np.array([c[1, 0], c[3, 1], c[5, 2]]) - half_thickness
    return lo, hi


def wall_areas(L):
    """Each wall's loaded area.

    Parameters
    ----------
    L : array_like, shape (3,)
        m, the box's lengths.

    Returns
    -------
    ndarray, shape (6,)
        m^2, dump order x-, x+, y-, y+, z-, z+.

    Examples
    --------
    >>> from lmgc90.cdcontrol import wall_areas
    >>> print(wall_areas([1.0, 2.0, 3.0]))
    [6. 6. 3. 3. 2. 2.]
    """
    L = np.asarray(L, float)
    a = np.array([L[1] * L[2], L[0] * L[2], L[0] * L[1]])
    return np.repeat(a, 2)


def wall_stresses(forces, L):
    """The normal stress on each wall, compression positive.

    Parameters
    ----------
    forces : array_like, shape (6, 3)
        N, the force on each wall by the grains.
    L : array_like, shape (3,)
        m, the box's lengths.

    Returns
    -------
    ndarray, shape (6,)
        Pa: the outward normal component of the force over the wall's area.

    Examples
    --------
    >>> import numpy as np
    >>> from lmgc90.cdcontrol import wall_stresses
    >>> F = np.zeros((6, 3)); F[0, 0], F[1, 0] = -2.0, 2.0; F[5, 2] = 4.0
    >>> print(wall_stresses(F, [1.0, 1.0, 2.0]) + 0.0)
    [1. 1. 0. 0. 0. 4.]
    """
    F = np.asarray(forces, float).reshape(6, 3)
    out = np.empty(6)
    A = wall_areas(L)
    for k, (axis, side) in enumerate(WALL_AXES):
        out[k] = side * F[k, axis] / A[k]
    return out


def pressing_forces(sigma, L, walls):
    """The external forces that press ``walls`` on the grains with a stress ``sigma``.

    Parameters
    ----------
    sigma : float
        Pa, > 0.
    L : array_like, shape (3,)
        m, the box's lengths now (the force follows the wall's area).
    walls : iterable of int
        Wall slots (0..5, dump order).

    Returns
    -------
    dict
        slot -> (6,) force and moment (N, N m): ``sigma * area`` along the
        inward normal, no moment.

    Examples
    --------
    >>> from lmgc90.cdcontrol import pressing_forces
    >>> print(pressing_forces(10.0, [1.0, 2.0, 3.0], [1])[1])
    [-60.   0.   0.   0.   0.   0.]
    """
    A = wall_areas(L)
    out = {}
    for k in walls:
        axis, side = WALL_AXES[k]
        f = np.zeros(6)
        f[axis] = -side * sigma * A[k]
        out[k] = f
    return out


class StressWindow:
    """The wall stresses of the last ``n`` steps: their means and spreads.

    CD's wall reactions vary from step to step; the isotropic state is
    judged on the mean over a window.

    Attributes
    ----------
    n : int
        The window's length, steps.
    rows : list of ndarray, shape (6,)
        Pa, the stresses of the last ``n`` steps, oldest first.

    Examples
    --------
    >>> from lmgc90.cdcontrol import StressWindow
    >>> w = StressWindow(2)
    >>> for s in ([1.0] * 6, [3.0] * 6, [5.0] * 6):
    ...     w.add(s)
    >>> print(w.full, w.mean()[0])
    True 4.0
    """

    def __init__(self, n):
        self.n = int(n)
        self.rows = []

    def add(self, sigma):
        """Append one step's wall stresses (6,) Pa, dropping the oldest beyond ``n``.

        Returns
        -------
        None
        """
        self.rows.append(np.asarray(sigma, float).copy())
        if len(self.rows) > self.n:
            self.rows.pop(0)

    @property
    def full(self):
        """True once the window holds ``n`` steps."""
        return len(self.rows) == self.n

    def mean(self):
        """The mean over the window.

        Returns
        -------
        ndarray, shape (6,)
            Pa.
        """
        return np.mean(self.rows, axis=0)

    def std(self):
        """The standard deviation over the window.

        Returns
        -------
        ndarray, shape (6,)
            Pa.
        """
        return np.std(self.rows, axis=0)


def isotropic_reached(mean_stress, sigma0, tolerance, volume_change, volume_tolerance):
    """True when the packing holds sigma0 at rest.

    Parameters
    ----------
    mean_stress : array_like, shape (6,)
        Pa, the walls' stresses averaged over the window.
    sigma0 : float
        Pa.
    tolerance : float
        |mean - sigma0| < tolerance * sigma0 on every wall.
    volume_change : float
        The box's relative volume change over the window.
    volume_tolerance : float
        ... below this.

    Returns
    -------
    bool

    Examples
    --------
    >>> from lmgc90.cdcontrol import isotropic_reached
    >>> print(isotropic_reached([1.0, 1.0, 1.0, 0.995, 1.0, 1.0], 1.0, 0.01, 1e-6, 1e-5))
    True
    """
    s = np.asarray(mean_stress, float)
    return bool(np.all(np.abs(s - sigma0) < tolerance * sigma0) and abs(volume_change) < volume_tolerance)
