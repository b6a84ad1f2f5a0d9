"""Steady-state averages and their 95 % confidence intervals.

A quantity's *plateau* is its mean over the shear snapshots with
eps_q >= 0.5 max eps_q (the steady part of shear). Successive snapshots of
one run are correlated, so their spread is not an error bar:

* with two or more seeds (an ensemble), each seed gives one plateau mean
  and the interval is Student's t over the seeds (n - 1 degrees of freedom);
* with one seed, the plateau is cut into 4 consecutive batches and the
  interval is Student's t over the batch means (3 degrees of freedom), the
  batch-means method for correlated series. It is an indication, not an
  ensemble interval, and is labelled so.

Differences of independent estimates use Welch's t (Welch-Satterthwaite
degrees of freedom). How the seeds scatter (:func:`seed_scatter`: the part a
longer steady window would average away and the part it would not) and how
many seeds an interval needs to exclude 0 (:func:`seeds_needed`) say what
more computing would buy.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.stats import t

STEADY_START = 0.5
N_BATCHES = 4


def steady_indices(eps_q, stage, start=STEADY_START):
    """(K,) int rows of the steady part of shear: stage "shear" and
    eps_q >= start * max eps_q over the shear rows. Falls back to the last
    row alone when strains are unknown or fewer than 2 rows qualify.

    eps_q (S,) strain (compression positive); stage (S,) str.
    """
    eq = np.asarray(eps_q, float)
    stage = np.asarray(stage).astype(str)
    shear = stage == "shear"
    if shear.any() and np.isfinite(eq[shear]).any():
        top = np.nanmax(eq[shear])
        idx = np.flatnonzero(shear & (eq >= start * top))
        if top > 0 and len(idx) > 1:
            return idx
    return np.array([len(eq) - 1])


@dataclass
class Estimate:
    """A mean with its standard error and degrees of freedom."""

    mean: float
    se: float
    dof: float
    n: int              # seeds, or batches for one seed
    method: str         # "seeds", "batch means (one seed)" or "one value"

    def ci(self, level=0.95):
        """(low, high) Student's t interval; (nan, nan) without an error."""
        if not (np.isfinite(self.se) and self.dof >= 1):
            return (np.nan, np.nan)

        h = t.ppf(0.5 + level / 2, self.dof) * self.se
        return (self.mean - h, self.mean + h)

    def text(self, digits=2):
        lo, hi = self.ci()
        if np.isfinite(lo):
            return f"{self.mean:.{digits}f} [{lo:.{digits}f}, {hi:.{digits}f}]"
        return f"{self.mean:.{digits}f}" if np.isfinite(self.mean) else "n/a"


def plateau_estimate(series):
    """Estimate of the plateau mean from a list with one (K_s,) array of
    steady-state values per seed (NaNs dropped).

    Two or more seeds with values: t over the per-seed means. One seed:
    batch means over N_BATCHES consecutive batches (fewer when K < 8, at
    least 2 values per batch); a single value gives no interval.
    """
    series = [np.asarray(s, float) for s in series]
    series = [s[np.isfinite(s)] for s in series]
    series = [s for s in series if len(s)]
    if not series:
        return Estimate(np.nan, np.nan, 0, 0, "no values")
    if len(series) >= 2:
        m = np.array([s.mean() for s in series])
        return Estimate(float(m.mean()), float(m.std(ddof=1) / np.sqrt(len(m))), len(m) - 1,
                        len(m), "seeds")
    s = series[0]
    b = min(N_BATCHES, len(s) // 2)
    if b < 2:
        return Estimate(float(s.mean()), np.nan, 0, 1, "one value")
    m = np.array([c.mean() for c in np.array_split(s, b)])
    return Estimate(float(s.mean()), float(m.std(ddof=1) / np.sqrt(b)), b - 1, b,
                    "batch means (one seed)")


def difference(e1, e2):
    """Estimate of e1 - e2 for independent estimates (Welch)."""
    se = np.hypot(e1.se, e2.se)
    if not np.isfinite(se) or se == 0:
        dof = 0
    else:
        dof = se ** 4 / (e1.se ** 4 / max(e1.dof, 1) + e2.se ** 4 / max(e2.dof, 1))
    method = e1.method if e1.method == e2.method else f"{e1.method} / {e2.method}"
    return Estimate(e1.mean - e2.mean, float(se), float(dof), min(e1.n, e2.n), method)


@dataclass
class SeedScatter:
    """How the plateau means of an ensemble scatter, in the quantity's units.

    ``between``: standard deviation of the per-seed plateau means (ddof 1);
    ``within``: root mean square over seeds of each seed's batch-means
    standard error (the noise of a plateau mean from its own window);
    ``persistent``: sqrt(max(between² - within², 0)), the part of a seed's
    plateau set by its sample, which a longer window would not remove;
    ``n``: seeds with values."""

    between: float
    within: float
    persistent: float
    n: int


def seed_scatter(series):
    """Split the scatter of per-seed plateau means into window noise and a
    persistent, per-sample part (one-way random effects, method of moments:
    var(seed means) = persistent² + mean of the seeds' squared standard errors).

    series: list with one (K_s,) array of steady-state values per seed (NaNs
    dropped); each seed's standard error is the batch-means one of
    :func:`plateau_estimate` (N_BATCHES batches), which underestimates the
    noise when the series is correlated over more than a batch, so
    ``persistent`` is an upper bound in that case. Needs 2 seeds with at
    least 4 values each; otherwise every field is NaN.
    """
    series = [np.asarray(s, float) for s in series]
    series = [s[np.isfinite(s)] for s in series]
    series = [s for s in series if len(s) >= 4]
    if len(series) < 2:
        return SeedScatter(np.nan, np.nan, np.nan, len(series))
    means = np.array([s.mean() for s in series])
    se = np.array([plateau_estimate([s]).se for s in series])
    between = float(means.std(ddof=1))
    within = float(np.sqrt(np.mean(se ** 2)))
    return SeedScatter(between, within, float(np.sqrt(max(between ** 2 - within ** 2, 0.0))), len(series))


def seeds_needed(mean, sd, level=0.95, n_max=100000):
    """Smallest number of seeds n >= 2 whose Student's t interval,
    mean ± t_{n-1} sd / sqrt(n), excludes 0, for an ensemble whose seed
    means have this ``mean`` and standard deviation ``sd`` (same units).
    A planning figure: the next seeds move both. Returns None when
    mean == 0 or n would exceed n_max; 1 is never returned (one seed gives
    no interval over seeds)."""
    mean, sd = abs(float(mean)), float(sd)
    if not (np.isfinite(mean) and np.isfinite(sd)) or sd < 0:
        raise ValueError(f"seeds_needed: mean and sd must be finite and sd >= 0, got {mean}, {sd}")
    if sd == 0:
        return 2 if mean > 0 else None
    if mean == 0:
        return None
    half = lambda n: t.ppf(0.5 + level / 2, n - 1) * sd / np.sqrt(n)  # noqa: E731
    lo = 2
    if half(lo) < mean:
        return lo
    if half(n_max) >= mean:
        return None
    hi = n_max                                  # half(n) falls with n: bisect
    while hi - lo > 1:
        mid = (lo + hi) // 2
        lo, hi = (lo, mid) if half(mid) < mean else (mid, hi)
    return hi
