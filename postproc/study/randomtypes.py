"""The geometric chance of each contact type: random pairs of library
grains, with random orientations and contact normals, classified by the
angular criterion (:func:`postproc.contacttypes.classify_contacts`) at
theta / 2, theta and 2 theta. Nothing selects their contacts, so a
packing's proportions against these show what its contact mechanics
selects (docs/contact-types.md: a packing's face-face share at 5 degrees is
about 40 times the chance).

    postproc investigate random-types [--library runs/shapes/library.h5] [--pairs 100000]

(:func:`random_type_fractions`.) The draws are those of the angular
criterion's throughput benchmark (``benchmarks/bench_contact_types.py``),
so the proportions are those measured beside it: with generator seed 0,
``draws`` shape pairs (uniform over the library), then their unit
quaternions (normalised Gaussians, by the classifier) and their normals
(uniform on the sphere), of which the first ``pairs`` are classified.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from ..contacttypes import DEFAULT_THETA_DEG, PAIR_TYPES, classify_contacts, shape_tables


def random_pairs(n_shapes, draws, seed=0):
    """Random contacts between shapes of a library.

    Parameters
    ----------
    n_shapes : int
        Shapes in the library.
    draws : int
        Contacts drawn.
    seed : int
        Seed of :func:`numpy.random.default_rng`.

    Returns
    -------
    tuple of ndarray
        (s1, s2, q1, q2, n): shape rows (draws,) of each side, quaternions
        (draws, 4) (not normalised: Gaussian, the classifier normalises
        them) and unit normals (draws, 3).
    """
    rng = np.random.default_rng(seed)
    s1, s2 = rng.integers(n_shapes, size=draws), rng.integers(n_shapes, size=draws)
    q1, q2 = rng.normal(size=(draws, 4)), rng.normal(size=(draws, 4))
    n = rng.normal(size=(draws, 3))
    n /= np.linalg.norm(n, axis=1)[:, None]
    return s1, s2, q1, q2, n


def random_type_fractions(library, pairs=100_000, draws=1_000_000, seed=0, thetas=None):
    """The pair-type proportions of random contacts between a library's
    grains.

    Parameters
    ----------
    library : shapes.library.ShapeLibrary
        The grains.
    pairs : int
        Contacts classified (the first of the draws).
    draws : int
        Contacts drawn (at least ``pairs``; the draws of the benchmark).
    seed : int
        Seed of the draws.
    thetas : sequence of float, optional
        Angular tolerances in degrees (default theta / 2, theta and 2 theta
        of the default, 5 degrees).

    Returns
    -------
    pandas.DataFrame
        One row per tolerance: ``theta_deg`` and the share of each pair type
        of :data:`postproc.contacttypes.PAIR_TYPES` (VV ... FF, summing
        to 1).
    """
    if thetas is None:
        thetas = (DEFAULT_THETA_DEG / 2, DEFAULT_THETA_DEG, 2 * DEFAULT_THETA_DEG)
    tables = shape_tables(*zip(*[library[s] for s in range(len(library))]))
    s1, s2, q1, q2, n = random_pairs(len(library), max(draws, pairs), seed)
    rows = []
    for theta in thetas:
        _, _, pair = classify_contacts(tables, s1[:pairs], s2[:pairs], q1[:pairs], q2[:pairs], n[:pairs], theta)
        frac = np.bincount(pair, minlength=len(PAIR_TYPES)) / len(pair)
        rows.append({"theta_deg": float(theta), **dict(zip(PAIR_TYPES, frac.tolist()))})
    return pd.DataFrame(rows)


def lines(table):
    """The printed form of :func:`random_type_fractions`' table.

    Parameters
    ----------
    table : pandas.DataFrame
        Its rows.

    Returns
    -------
    list of str
        One line per tolerance: "theta 5.0 deg (random orientations): VV
        0.xxxx, ...".
    """
    return [f"theta {r['theta_deg']:4.1f} deg (random orientations): "
            + ", ".join(f"{t} {r[t]:.4f}" for t in PAIR_TYPES) for _, r in table.iterrows()]
