"""The size distribution of the seed study, for both samples.

Number fractions 50 % of d = 2.5 cm, 34 % of 3.75 cm, 16 % of 5 cm, where d is
twice the largest distance from the barycentre to a vertex (polyhedra) or the
diameter (spheres). numpy only (importable from YADE's system Python).
"""
from __future__ import annotations

import numpy as np

CLASS_DIAMETERS = (0.025, 0.0375, 0.05)   # m
CLASS_FRACTIONS = (0.50, 0.34, 0.16)      # by number


def class_counts(n, fractions=CLASS_FRACTIONS):
    """Integer counts per size class, summing to ``n``, closest to
    n x fractions (the method of largest remainders).

    Parameters
    ----------
    n : int
        The number of particles (>= 0).
    fractions : sequence of float
        Number fractions per class, >= 0, summing to 1 (default: the study's
        50 / 34 / 16 %, Azema, Radjai & Saussine 2009, section 2,
        "Numerical procedures").

    Returns
    -------
    (K,) int
        The counts: floor(n x fraction) per class, then one more for each
        of the classes with the largest remainders until they sum to ``n``
        (ties to the first classes).

    Raises
    ------
    ValueError
        A negative ``n``, a negative fraction, or fractions whose sum is
        not 1.

    Examples
    --------
    >>> class_counts(10).tolist(), class_counts(100).tolist(), class_counts(3).tolist()
    ([5, 3, 2], [50, 34, 16], [2, 1, 0])
    """
    f = np.asarray(fractions, float)
    if n < 0 or np.any(f < 0) or not np.isclose(f.sum(), 1.0):
        raise ValueError(f"need n >= 0 and fractions >= 0 summing to 1, got {n}, {fractions}")
    raw = n * f
    counts = np.floor(raw).astype(int)
    short = n - counts.sum()
    order = np.argsort(-(raw - counts), kind="stable")
    counts[order[:short]] += 1
    return counts


def sample_diameters(n, seed=0, exact=True, diameters=CLASS_DIAMETERS,
                     fractions=CLASS_FRACTIONS):
    """The sizes d of ``n`` particles drawn from the study's size classes,
    in random order.

    d is the size of Azema, Radjai & Saussine (2009), section 2
    ("Numerical procedures"): twice the largest distance from the
    barycentre to a vertex for a polyhedron, the diameter for a sphere.

    Parameters
    ----------
    n : int
        The number of particles.
    seed : int or numpy.random.Generator
        The source of the order (and of the classes when not exact): the
        same seed gives the same diameters.
    exact : bool
        True (default): the class counts are :func:`class_counts` (what the
        seed study's samples have), shuffled; False: each particle draws
        its class independently (multinomial).
    diameters : sequence of float
        m, the classes' d (default 2.5, 3.75 and 5 cm).
    fractions : sequence of float
        Their number fractions (default 50, 34 and 16 %).

    Returns
    -------
    (n,) float
        m, each particle's d.

    Examples
    --------
    >>> d = sample_diameters(10, seed=0)
    >>> d.shape, sorted(d.tolist())
    ((10,), [0.025, 0.025, 0.025, 0.025, 0.025, 0.0375, 0.0375, 0.0375, 0.05, 0.05])
    >>> bool(np.array_equal(d, sample_diameters(10, seed=0)))
    True
    """
    rng = seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)
    d = np.asarray(diameters, float)
    if exact:
        out = np.repeat(d, class_counts(n, fractions))
        rng.shuffle(out)
        return out
    return d[rng.choice(len(d), size=n, p=np.asarray(fractions, float))]
