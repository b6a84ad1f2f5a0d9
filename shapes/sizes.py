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
    """Integer counts per class summing to ``n``, closest to n * fractions
    (largest remainders; ties go to the first classes)."""
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
    """Diameters d (m) of ``n`` particles, in random order.

    exact=True: the class counts are the nearest integers to n * fractions
    (what the seed's sample has); exact=False: each particle draws its class
    independently (multinomial). Reproducible from ``seed`` (int or
    numpy Generator).

    Returns (n,) float array, m.
    """
    rng = seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)
    d = np.asarray(diameters, float)
    if exact:
        out = np.repeat(d, class_counts(n, fractions))
        rng.shuffle(out)
        return out
    return d[rng.choice(len(d), size=n, p=np.asarray(fractions, float))]
