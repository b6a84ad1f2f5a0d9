"""Coordination number, rattlers and the share of weak forces."""
from __future__ import annotations

import numpy as np
from scipy.sparse import coo_matrix

#: a contact bears force when |f| > FORCE_FLOOR * max |f| of the snapshot
FORCE_FLOOR = 1e-9

#: whole-array peeling passes before the queue takes over (a constant, so
#: the total stays O(particles + contacts)); more passes measured slower on a
#: 1e6-contact packing (benchmarks/bench_rattlers.py)
_SCAN_LAYERS = 1


def force_bearing(force):
    """The force-bearing contacts.

    Parameters
    ----------
    force : array_like, shape (C, 3)
        N (any unit), the contact forces.

    Returns
    -------
    ndarray of bool, shape (C,)
        True where |f| exceeds FORCE_FLOOR (1e-9) times the largest |f| of
        the set (relative, so it does not depend on the force unit); all
        False when every force is zero.

    Examples
    --------
    Particles 0, 1, 2 in a triangle, 0 and 1 also on a wall (the wall
    contact of 1 unloaded), particle 3 hanging on 2 alone:

    >>> import numpy as np
    >>> from postproc.coordination import coordination, force_bearing, rattlers
    >>> i1 = np.array([0, 1, 2, 3, 0, 1])
    >>> i2 = np.array([1, 2, 0, 2, -1, -1])
    >>> force = np.array([[1.0, 0.0, 0.0]] * 5 + [[0.0, 0.0, 0.0]])
    >>> print(force_bearing(force))
    [ True  True  True  True  True False]
    """
    mag = np.sqrt(np.einsum("ij,ij->i", force, force))
    top = mag.max() if len(mag) else 0.0
    return mag > FORCE_FLOOR * top if top > 0 else np.zeros(len(mag), bool)


def rattlers(i1, i2, bearing, n_particles, min_contacts=2):
    """The rattlers: particles with fewer than ``min_contacts``
    force-bearing contacts (walls count), removed iteratively.

    A particle that drops below the threshold once its rattling neighbours
    are discarded is a rattler too: the non-rattlers are the
    ``min_contacts``-core of the contact graph (every particle in it keeps
    at least ``min_contacts`` bearing contacts with other core particles or
    walls); the core is unique, so the order of removal does not matter.
    O(B + C): ``_SCAN_LAYERS`` whole-array peeling pass, then a queue over
    the adjacency of what is left, in which each contact is seen once from
    each side.

    Parameters
    ----------
    i1, i2 : array_like of int, shape (C,)
        The particle rows (0 .. B-1) of the two sides of each contact; -1
        for a wall.
    bearing : array_like of bool, shape (C,)
        The force-bearing contacts (:func:`force_bearing`).
    n_particles : int
        B, the number of particles.
    min_contacts : int, optional
        k of the k-core (default 2).

    Returns
    -------
    ndarray of bool, shape (B,)
        True for the rattlers.

    Examples
    --------
    Particles 0, 1, 2 in a triangle, 0 and 1 also on a wall (the wall
    contact of 1 unloaded), particle 3 hanging on 2 alone:

    >>> import numpy as np
    >>> from postproc.coordination import coordination, force_bearing, rattlers
    >>> i1 = np.array([0, 1, 2, 3, 0, 1])
    >>> i2 = np.array([1, 2, 0, 2, -1, -1])
    >>> force = np.array([[1.0, 0.0, 0.0]] * 5 + [[0.0, 0.0, 0.0]])
    >>> print(rattlers(i1, i2, force_bearing(force), 4))
    [False False False  True]
    """
    i1 = np.asarray(i1, np.int64)
    i2 = np.asarray(i2, np.int64)
    active = np.asarray(bearing, bool)
    a, b = i1[active], i2[active]
    removed = np.zeros(n_particles, bool)
    for _ in range(_SCAN_LAYERS):
        deg = (np.bincount(a[a >= 0], minlength=n_particles)
               + np.bincount(b[b >= 0], minlength=n_particles))
        new = (deg < min_contacts) & ~removed
        if not new.any():
            return removed
        removed |= new
        keep = ((a < 0) | ~removed[np.maximum(a, 0)]) & ((b < 0) | ~removed[np.maximum(b, 0)])
        a, b = a[keep], b[keep]
    # Deep peeling (chains, dangling arms): a queue. deg counts the contacts
    # left (all between live particles or with walls); the adjacency holds
    # the live particle-particle ones, a repeated pair once with its count.

    deg = (np.bincount(a[a >= 0], minlength=n_particles)
           + np.bincount(b[b >= 0], minlength=n_particles)).astype(np.int64)
    pp = (a >= 0) & (b >= 0)
    ends = np.concatenate([a[pp], b[pp]])
    other = np.concatenate([b[pp], a[pp]])
    adj = coo_matrix((np.ones(len(ends), np.int64), (ends, other)),
                     shape=(n_particles, n_particles)).tocsr()
    ptr, nbr, mult = (memoryview(np.ascontiguousarray(x, np.int64))
                      for x in (adj.indptr, adj.indices, adj.data))
    degv = memoryview(deg)
    front = np.flatnonzero((deg < min_contacts) & ~removed)
    removed[front] = True
    gone = memoryview(removed)
    queue = front.tolist()
    while queue:
        u = queue.pop()
        for j in range(ptr[u], ptr[u + 1]):
            v = nbr[j]
            if not gone[v]:
                d = degv[v] - mult[j]
                degv[v] = d
                if d < min_contacts:
                    gone[v] = True
                    queue.append(v)
    return removed


def coordination(i1, i2, force, n_particles):
    """Coordination numbers of the particle-particle contact network.

    z = 2 N_c / N_p with N_c the force-bearing particle-particle contacts:
    ``z`` counts only non-rattlers and the contacts between them (the usual
    definition), ``z_all`` every particle and contact. Every contact counts
    once, so a face-face pair dumped as one contact counts once.

    Parameters
    ----------
    i1, i2 : array_like of int, shape (C,)
        The particle rows of the two sides (-1 for a wall).
    force : array_like, shape (C, 3)
        N, the contact forces.
    n_particles : int
        The number of particles.

    Returns
    -------
    dict
        ``z`` and ``z_all`` (float), ``n_rattlers`` (int, :func:`rattlers`),
        ``n_bearing`` (int, force-bearing particle-particle contacts).

    Examples
    --------
    Particles 0, 1, 2 in a triangle, 0 and 1 also on a wall (the wall
    contact of 1 unloaded), particle 3 hanging on 2 alone:

    >>> import numpy as np
    >>> from postproc.coordination import coordination, force_bearing, rattlers
    >>> i1 = np.array([0, 1, 2, 3, 0, 1])
    >>> i2 = np.array([1, 2, 0, 2, -1, -1])
    >>> force = np.array([[1.0, 0.0, 0.0]] * 5 + [[0.0, 0.0, 0.0]])
    >>> r = coordination(i1, i2, force, 4)
    >>> print(float(r["z"]), float(r["z_all"]), r["n_rattlers"], r["n_bearing"])
    2.0 2.0 1 4
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
    """The fraction of the given normal forces below their mean.

    Parameters
    ----------
    normal_force : array_like, shape (C,)
        N (any unit), normal forces, compression positive.

    Returns
    -------
    float
        The fraction of the values strictly below their mean; NaN for none.

    Examples
    --------
    >>> from postproc.coordination import fraction_below_mean
    >>> print(round(fraction_below_mean([1.0, 1.0, 4.0]), 4))
    0.6667
    """
    fn = np.asarray(normal_force, float)
    return float(np.mean(fn < fn.mean())) if len(fn) else np.nan
