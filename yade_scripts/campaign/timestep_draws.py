"""How the polyhedra's time step shrinks with the number of grains: the
sample's most limiting grain, drawn from the library.

    python -m yade_scripts.campaign.timestep_draws [--library runs/shapes/library.h5] \
        [--n 200 1000 5000 36933] [--seeds 1 2 3]

The scene (``yade_scripts/scene/triaxial.py``) sets dt = safety x min over its
grains of sqrt(m_eff / k) (:mod:`yade_scripts.scene.timestep`): for shape s at
diameter d, m_eff = rho d^3 rot_mass(s) and k = k_V max(max face area(s),
tangential_ratio x mean face area) d^2, so 1/dt goes as sqrt(k / m_eff) =
x(s, d) x a constant. N grains draw their shapes uniformly from the
library's L shapes and their sizes by the exact class counts
(:func:`shapes.sizes.class_counts`), so the largest x of a sample has an
exact distribution: P(max <= x) = prod over classes of (the fraction of
shapes with x(s, d_c) <= x)^(n_c) (:func:`expected_rate`). The command prints, for each N, the
expected 1/dt relative to that at 1000 grains (the shear's steps go as
1/dt at a fixed strain rate), the library's limit (every sample holding
the most limiting shape in the smallest class) and the chance that N grains
draw it; and, for each N and seed of ``--seeds``, whether the scene's own
draw (the same generator calls as the scene) holds that shape, which is
when a run's dt is the library's smallest.
"""
from __future__ import annotations

import argparse
import sys

import numpy as np

from shapes import sizes
from shapes.library import ShapeLibrary
from yade_scripts.scene import timestep
from yade_scripts.scene.parameters import PARAMETERS


def shape_rates(lib, tangential_ratio):
    """Each library shape's rate x(s, d = 1) = sqrt(k / m_eff), up to a
    common constant, as the scene computes k and m_eff.

    Parameters
    ----------
    lib : shapes.library.ShapeLibrary
        The L shapes (at d = 1, unit density).
    tangential_ratio : float
        The scene's ``tangential_ratio``: k is the largest face area, or
        this times the library's mean face area when that is larger.

    Returns
    -------
    ndarray, shape (L,)
        x(s, 1); at diameter d the rate is x(s, 1) / sqrt(d), and 1/dt is
        proportional to the sample's largest rate.
    """
    faces = []
    for s in range(len(lib)):
        v, t, _ = lib[s]
        faces.append(0.5 * np.linalg.norm(np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]]), axis=1))
    a_face = float(np.mean(np.concatenate(faces)))
    k = np.maximum(np.array([a.max() for a in faces]), tangential_ratio * a_face)
    m = np.array([timestep.rotational_mass(lib.volume[s], np.diag(lib.inertia[s]), lib[s][0]) for s in range(len(lib))])
    return np.sqrt(k / m)


def expected_rate(x1, n):
    """The expected largest rate of n grains: exact order statistics over
    the class counts of n grains, each grain's shape drawn uniformly.

    Parameters
    ----------
    x1 : ndarray, shape (L,)
        Each shape's rate at d = 1 (:func:`shape_rates`); x(s, d) =
        x1(s) / sqrt(d).
    n : int
        Grains in the sample (sizes by :func:`shapes.sizes.class_counts`).

    Returns
    -------
    float
        E[max x over the n grains], in the units of ``x1``.
    """
    per_class = [(np.sort(x1 / np.sqrt(d)), c) for d, c in zip(sizes.CLASS_DIAMETERS, sizes.class_counts(n))]
    grid = np.unique(np.concatenate([x for x, _ in per_class]))
    cdf = np.ones_like(grid)
    for x, c in per_class:
        cdf *= (np.searchsorted(x, grid, side="right") / len(x1)) ** c
    return float(np.diff(np.concatenate([[0.0], cdf])) @ grid)


def main(argv=None):
    """The command: the table of expected 1/dt against N and the seeds'
    draws, printed.

    Parameters
    ----------
    argv : list of str, optional
        Arguments (default ``sys.argv[1:]``).

    Returns
    -------
    int
        0, or 2 when the library cannot be read.
    """
    ap = argparse.ArgumentParser(prog="python -m yade_scripts.campaign.timestep_draws", description=__doc__.splitlines()[0])
    ap.add_argument("--library", default="runs/shapes/library.h5")
    ap.add_argument("--n", nargs="+", type=int, default=[200, 1000, 5000, 36933])
    ap.add_argument("--seeds", nargs="*", type=int, default=[1, 2, 3])
    args = ap.parse_args(argv)
    try:
        lib = ShapeLibrary(args.library)
    except (OSError, ValueError, KeyError) as exc:
        print(f"timestep_draws: error: {args.library}: {exc}", file=sys.stderr)
        return 2
    ratio = next(p.default for p in PARAMETERS if p.name == "tangential_ratio")
    x1 = shape_rates(lib, ratio)
    small = np.sqrt(sizes.CLASS_DIAMETERS[0])
    best = int(np.argmax(x1))
    ref = expected_rate(x1, 1000)
    f_small = sizes.CLASS_FRACTIONS[0]
    print(f"library {args.library}: {len(lib)} shapes, the most limiting is shape {best}; "
          f"its limit is {x1[best] / small / ref:.4f} x the expected 1/dt at 1000 grains")
    print("| N | expected 1/dt vs 1000 grains | chance of the most limiting shape in the smallest class |")
    print("|---|---|---|")
    for n in args.n:
        print(f"| {n} | {expected_rate(x1, n) / ref:.4f} | {1 - (1 - f_small / len(lib)) ** n:.3f} |")
    for n in args.n:
        for seed in args.seeds:
            rng = np.random.default_rng(seed)                 # the scene's draws, in its order
            d = sizes.sample_diameters(n, rng)
            shape_of = rng.integers(len(lib), size=n)
            holds = bool(np.any((shape_of == best) & (d == sizes.CLASS_DIAMETERS[0])))
            print(f"N {n} seed {seed}: {'holds' if holds else 'does not hold'} the most limiting shape")
    return 0


if __name__ == "__main__":
    sys.exit(main())
