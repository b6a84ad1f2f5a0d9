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
more computing would buy, and how often a study extended by that figure
decides each way (:func:`two_stage_rates`); how a value measured on blocks
of several packings splits into a local part, a packing part and the
blocks' places (:func:`block_components`) says how its scatter scales with the packing's size.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.stats import chi2, t
from scipy.stats import f as f_dist

STEADY_START = 0.5
N_BATCHES = 4


def steady_indices(eps_q, stage, start=STEADY_START):
    """The rows of the steady part of shear.

    Parameters
    ----------
    eps_q : array_like, shape (S,)
        The deviatoric strain of each snapshot (compression positive).
    stage : array_like of str, shape (S,)
        The stage of each snapshot ("isotropic", "shear", ...).
    start : float, optional
        The steady part starts at ``start`` x the largest eps_q of shear
        (default STEADY_START, 0.5).

    Returns
    -------
    ndarray of int, shape (K,)
        The rows of stage "shear" with eps_q >= start x max eps_q over the
        shear rows; the last row alone when strains are unknown or fewer
        than 2 rows qualify.

    Examples
    --------
    >>> from postproc.statistics import steady_indices
    >>> print(steady_indices([0, 0.05, 0.1, 0.2, 0.3], ["isotropic"] + ["shear"] * 4))
    [3 4]
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
    """A mean with its standard error and degrees of freedom.

    Attributes
    ----------
    mean : float
        The estimate, in the quantity's units.
    se : float
        Its standard error (NaN when there is none).
    dof : float
        The degrees of freedom of its Student's t interval.
    n : int
        The seeds, or the batches of one seed, behind it.
    method : str
        "seeds", "batch means (one seed)", "one value" or "no values"
        (differences of two methods join them with " / ").
    """

    mean: float
    se: float
    dof: float
    n: int              # seeds, or batches for one seed
    method: str         # "seeds", "batch means (one seed)" or "one value"

    def ci(self, level=0.95):
        """The Student's t confidence interval.

        Parameters
        ----------
        level : float, optional
            The confidence level (default 0.95).

        Returns
        -------
        tuple of float
            (low, high), mean -+ t_dof x se; (nan, nan) without an error.
        """
        if not (np.isfinite(self.se) and self.dof >= 1):
            return (np.nan, np.nan)

        h = t.ppf(0.5 + level / 2, self.dof) * self.se
        return (self.mean - h, self.mean + h)

    def text(self, digits=2):
        """The estimate as the tables print it.

        Parameters
        ----------
        digits : int, optional
            Decimals (default 2).

        Returns
        -------
        str
            "mean [low, high]" with its 95 % interval, the mean alone
            without an interval, "n/a" without a value.
        """
        lo, hi = self.ci()
        if np.isfinite(lo):
            return f"{self.mean:.{digits}f} [{lo:.{digits}f}, {hi:.{digits}f}]"
        return f"{self.mean:.{digits}f}" if np.isfinite(self.mean) else "n/a"


def plateau_estimate(series):
    """The plateau mean with its 95 % interval, over seeds or batches.

    Parameters
    ----------
    series : list of array_like
        One (K_s,) array of steady-state values per seed (NaNs dropped).

    Returns
    -------
    Estimate
        Two or more seeds with values: the mean of the per-seed means, with
        Student's t over them (n - 1 degrees of freedom), method "seeds".
        One seed: batch means over N_BATCHES consecutive batches (fewer when
        K < 8, at least 2 values per batch), method "batch means (one
        seed)"; a single value gives no interval ("one value").

    Examples
    --------
    >>> from postproc.statistics import plateau_estimate
    >>> e = plateau_estimate([[0.42, 0.44], [0.45, 0.47], [0.40, 0.42]])
    >>> print(e.text(), e.method, e.n)
    0.43 [0.37, 0.50] seeds 3
    >>> print(plateau_estimate([[0.40, 0.42, 0.44, 0.46, 0.41, 0.43, 0.45, 0.47]]).text())
    0.43 [0.40, 0.47]
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
    """The difference of two independent estimates (Welch).

    Parameters
    ----------
    e1, e2 : Estimate
        Independent estimates of quantities in the same unit.

    Returns
    -------
    Estimate
        e1 - e2 with the standard error sqrt(se1^2 + se2^2) and the
        Welch-Satterthwaite degrees of freedom.

    Examples
    --------
    >>> from postproc.statistics import difference, plateau_estimate
    >>> s1 = plateau_estimate([[0.42, 0.44], [0.45, 0.47], [0.40, 0.42]])
    >>> s2 = plateau_estimate([[0.25], [0.26], [0.24]])
    >>> print(difference(s1, s2).text())
    0.18 [0.13, 0.24]
    """
    se = np.hypot(e1.se, e2.se)
    if not np.isfinite(se) or se == 0:
        dof = 0
    else:
        dof = se ** 4 / (e1.se ** 4 / max(e1.dof, 1) + e2.se ** 4 / max(e2.dof, 1))
    method = e1.method if e1.method == e2.method else f"{e1.method} / {e2.method}"
    return Estimate(e1.mean - e2.mean, float(se), float(dof), min(e1.n, e2.n), method)


@dataclass
class SeedScatter:
    """How the plateau means of an ensemble scatter, in the quantity's units
    (:func:`seed_scatter`).

    Attributes
    ----------
    between : float
        The standard deviation of the per-seed plateau means (ddof 1).
    within : float
        The root mean square over seeds of each seed's batch-means standard
        error: the noise of a plateau mean from its own window.
    persistent : float
        sqrt(max(between^2 - within^2, 0)), the part of a seed's plateau set
        by its sample, which a longer window would not remove.
    n : int
        The seeds with values.
    """

    between: float
    within: float
    persistent: float
    n: int


def seed_scatter(series):
    """Split the scatter of per-seed plateau means into window noise and a
    persistent, per-sample part.

    One-way random effects, method of moments: var(seed means) =
    persistent^2 + the mean of the seeds' squared standard errors. Each
    seed's standard error is the batch-means one of :func:`plateau_estimate`
    (N_BATCHES batches), which underestimates the noise when the series is
    correlated over more than a batch, so ``persistent`` is an upper bound
    in that case.

    Parameters
    ----------
    series : list of array_like
        One (K_s,) array of steady-state values per seed (NaNs dropped).

    Returns
    -------
    SeedScatter
        Every field NaN unless 2 seeds have at least 4 values each.

    Examples
    --------
    Three seeds whose plateaus differ by far more than their windows' noise:

    >>> import numpy as np
    >>> from postproc.statistics import seed_scatter
    >>> base = np.array([0.0, 0.02, 0.01, 0.03])
    >>> sc = seed_scatter([0.1 + base, 0.2 + base, 0.15 + base])
    >>> print(round(sc.between, 4), round(sc.within, 4), round(sc.persistent, 4), sc.n)
    0.05 0.005 0.0497 3
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
    """How many seeds an interval needs to exclude 0: a planning figure.

    Parameters
    ----------
    mean : float
        The mean of the seed means (any unit; its sign does not matter).
    sd : float
        Their standard deviation (same unit, >= 0).
    level : float, optional
        The confidence level (default 0.95).
    n_max : int, optional
        The largest number of seeds considered (default 100 000).

    Returns
    -------
    int or None
        The smallest n >= 2 whose Student's t interval, mean -+ t_{n-1} sd /
        sqrt(n), excludes 0 (the next seeds move both mean and sd); None
        when mean == 0 or n would exceed n_max. 1 is never returned: one
        seed gives no interval over seeds.

    Raises
    ------
    ValueError
        When mean or sd is not finite, or sd < 0.

    Examples
    --------
    >>> from postproc.statistics import seeds_needed
    >>> print(seeds_needed(0.04, 0.066), seeds_needed(0.2, 0.05), seeds_needed(0.0, 0.1))
    13 3 None
    """
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


def seeds_to_decide(mean, sd, margin, level=0.95, n_max=100000):
    """How many seeds would decide an undecided leaning under the leaning
    rule (:func:`postproc.study.claims.leaning_decision`), at the present
    mean and seed-to-seed scatter: a planning figure.

    The rule calls a leaning "none" when its interval mean -+ h(n),
    h(n) = t_{n-1} sd / sqrt(n), lies inside (-margin, margin), and else
    "lateral" or "axial" when it excludes 0 on that side. "none" needs
    |mean| + h(n) < margin (only possible when |mean| < margin), a side
    needs h(n) < |mean| (:func:`seeds_needed`); the first n to meet
    either decides, "none" first as in the rule.

    Parameters
    ----------
    mean : float
        The mean of the seeds' leanings (negative: lateral).
    sd : float
        Their standard deviation (>= 0, same unit).
    margin : float
        The rule's equivalence margin (> 0, same unit).
    level : float, optional
        The confidence level (default 0.95).
    n_max : int, optional
        The largest number of seeds considered.

    Returns
    -------
    (int, str) or None
        The smallest n >= 2 and the decision then ("none", "lateral" or
        "axial"); None when neither comes within n_max seeds (a mean of
        exactly margin, say).

    Raises
    ------
    ValueError
        When mean, sd or margin is not finite, sd < 0 or margin <= 0.

    Examples
    --------
    >>> from postproc.statistics import seeds_to_decide
    >>> seeds_to_decide(0.006, 0.015, 0.03)         # t_3 x 0.015 / 2 = 0.0239 < 0.03 - 0.006
    (4, 'none')
    >>> seeds_to_decide(-0.06, 0.05, 0.03)
    (6, 'lateral')
    """
    mean, sd, margin = float(mean), float(sd), float(margin)
    if not (np.isfinite(mean) and np.isfinite(sd) and np.isfinite(margin)) or sd < 0 or margin <= 0:
        raise ValueError(f"seeds_to_decide: mean, sd and margin must be finite, sd >= 0 and margin > 0, "
                         f"got {mean}, {sd}, {margin}")
    side = seeds_needed(mean, sd, level, n_max)
    none = seeds_needed(margin - abs(mean), sd, level, n_max) if abs(mean) < margin else None
    if none is not None and (side is None or none <= side):
        return none, "none"
    if side is not None:
        return side, "lateral" if mean < 0 else "axial"
    return None


def leaning_words(lo, hi, margin):
    """Claim 6's leaning rule on intervals, over arrays: the one place its
    comparisons are written (:func:`postproc.study.claims.leaning_decision`
    for one estimate, :func:`two_stage_rates` for many).

    Parameters
    ----------
    lo, hi : array_like, shape (R,) or scalars
        The 95 % intervals' ends, in the leaning's units (negative:
        lateral).
    margin : float
        The equivalence margin (> 0, same unit).

    Returns
    -------
    ndarray of str, shape (R,) or ()
        "none" when the interval lies inside (-margin, margin), else
        "lateral" when it lies below 0, "axial" when above 0, else (or when
        an end is not finite) "undecided".

    Examples
    --------
    >>> from postproc.statistics import leaning_words
    >>> print(leaning_words([-0.02, -0.08, 0.01, -0.01], [0.02, -0.01, 0.05, 0.04], 0.03))
    ['none' 'lateral' 'axial' 'undecided']
    """
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    ok = np.isfinite(lo) & np.isfinite(hi)
    return np.where(ok & (-margin < lo) & (hi < margin), "none",
                    np.where(ok & (hi < 0), "lateral", np.where(ok & (lo > 0), "axial", "undecided")))


def _seeds_leaning_words(x, margin, level):
    """:func:`leaning_words` for studies of seeds ``x`` (shape (R, n)) by
    the Student's t interval of each row's mean; with the rows' means and
    standard deviations (shape (R,))."""
    n = x.shape[1]
    m, s = x.mean(axis=1), x.std(axis=1, ddof=1)
    h = t.ppf(0.5 + level / 2, n - 1) * s / np.sqrt(n)
    return leaning_words(m - h, m + h, margin), m, s


def two_stage_rates(mu, sigma, n1, n_cap, margin, reps=20000, level=0.95, rng=None):
    """How often a leaning decided in two stages gets each decision, for
    seeds whose leanings are normal, N(mu, sigma^2): a Monte Carlo of the
    design a study extends by (docs/measurements.md, the 5000-grain study's
    extension rule).

    Stage one: ``n1`` seeds, decided by the leaning rule
    (:func:`postproc.study.claims.leaning_decision`: "none" when the 95 %
    interval lies inside +-margin, else "lateral" below 0, "axial" above 0,
    else "undecided"). An undecided leaning is extended once to the M seeds
    :func:`seeds_to_decide` gives at stage one's mean and standard
    deviation, when M <= ``n_cap`` (else it stays undecided), and decided
    on all M seeds by the same rule. Because M depends on stage one's
    numbers, the two-stage decision does not keep the fixed design's rates
    (a leaning of the margin's size called "none" at most 2.5 % of the
    time); this says what it keeps.

    Parameters
    ----------
    mu, sigma : float
        The seeds' true mean leaning (negative: lateral) and its seed-to-seed
        standard deviation (> 0), in the leaning's units.
    n1 : int
        Seeds of stage one (>= 2).
    n_cap : int
        The most seeds an extension may reach (>= n1; n1: no extension).
    margin : float
        The rule's equivalence margin (> 0; claim 6's 0.03).
    reps : int, optional
        Simulated studies (default 20 000; a share p is then known to
        about sqrt(p (1 - p) / reps)).
    level : float, optional
        The intervals' confidence level (default 0.95).
    rng : numpy.random.Generator or int, optional
        The random source, or its seed.

    Returns
    -------
    dict
        "none", "lateral", "axial", "undecided": the share of studies
        ending with each decision (they sum to 1); "extended": the share
        extended; "mean_seeds": the mean number of seeds run.

    Raises
    ------
    ValueError
        Non-finite mu, sigma or margin, sigma <= 0, margin <= 0, n1 < 2,
        n_cap < n1 or reps < 1.

    Examples
    --------
    >>> from postproc.statistics import two_stage_rates
    >>> r = two_stage_rates(0.0, 0.02, 6, 6, 0.03, reps=2000, rng=1)   # no extension
    >>> r["extended"], r["mean_seeds"]
    (0.0, 6.0)
    """
    mu, sigma, margin = float(mu), float(sigma), float(margin)
    if not (np.isfinite(mu) and np.isfinite(sigma) and np.isfinite(margin)) or sigma <= 0 or margin <= 0:
        raise ValueError(f"two_stage_rates: mu, sigma and margin must be finite, sigma > 0 and margin > 0, "
                         f"got {mu}, {sigma}, {margin}")
    if int(n1) < 2 or int(n_cap) < int(n1) or int(reps) < 1:
        raise ValueError(f"two_stage_rates: need n1 >= 2, n_cap >= n1 and reps >= 1, got {n1}, {n_cap}, {reps}")
    n1, n_cap, reps = int(n1), int(n_cap), int(reps)
    rng = np.random.default_rng(rng)
    x = rng.normal(mu, sigma, size=(reps, n1))
    words, m, s = _seeds_leaning_words(x, margin, level)
    plan = np.zeros(reps, int)                  # the extension's size, 0: none
    for i in np.flatnonzero(words == "undecided"):
        p = seeds_to_decide(m[i], s[i], margin, level, n_max=n_cap)
        plan[i] = p[0] if p is not None and p[0] > n1 else 0
    for size in np.unique(plan[plan > 0]):
        rows = np.flatnonzero(plan == size)
        more = rng.normal(mu, sigma, size=(len(rows), size - n1))
        words[rows] = _seeds_leaning_words(np.concatenate([x[rows], more], axis=1), margin, level)[0]
    out = {w: float(np.mean(words == w)) for w in ("none", "lateral", "axial", "undecided")}
    out["extended"] = float(np.mean(plan > 0))
    out["mean_seeds"] = float(np.where(plan > 0, plan, n1).mean())
    return out


@dataclass
class BlockComponents:
    """How a per-block value scatters inside packings and between them
    (:func:`block_components`), in the value's units.

    Attributes
    ----------
    local : float
        The standard deviation of one block about its packing's and its
        position's means (sqrt of the residual mean square).
    local_ci : tuple of float
        Its 95 % interval (chi-square on ``local_dof`` degrees of freedom).
    local_dof : int
        (S - 1)(B - 1).
    packing : float
        The standard deviation of the part every block of one packing
        shares (0 when the method of moments gives less).
    packing_p : float
        The F-test's p-value of "no packing part".
    position : float
        The standard deviation of the blocks' fixed position effects (blocks
        by a wall against inner ones; 0 when not seen).
    position_p : float
        The F-test's p-value of "no position effect".
    whole : float
        sqrt(packing^2 + local^2 / B): the predicted standard deviation
        between packings of the mean of a packing's B blocks.
    seeds : int
        S, the packings.
    blocks : int
        B, the blocks used (those without a NaN).
    """

    local: float
    local_ci: tuple
    local_dof: int
    packing: float
    packing_p: float
    position: float
    position_p: float
    whole: float
    seeds: int
    blocks: int


def block_components(values):
    """Split the scatter of a quantity measured on B blocks of S packings
    into a local part, a packing part and fixed position effects.

    The two-way model without interaction, value[s, b] = mu + alpha_s +
    beta_b + e[s, b]: alpha_s a packing's own part (random, sd ``packing``),
    beta_b the block's place in the box (fixed: blocks by a wall differ from
    inner ones in every packing), e the local part (independent, sd
    ``local``). Method of moments on the mean squares: MS_res estimates
    local^2, MS_seed = local^2 + B packing^2, MS_pos = local^2 + S var(beta).
    The mean of a packing's B blocks then scatters between packings with sd
    sqrt(packing^2 + local^2 / B) (``whole``): if ``packing`` is 0 the
    whole-packing value scatters as local / sqrt(B), i.e. as N^(-1/2) when
    the blocks have a fixed number of grains.

    Parameters
    ----------
    values : array_like, shape (S, B)
        One value per packing (row) and block (column), same block layout in
        every packing. Blocks (columns) with a NaN in any packing are dropped.

    Returns
    -------
    BlockComponents
        The standard deviations and p-values are NaN (``local_dof`` 0) unless
        S >= 2 and B >= 2 blocks remain.

    Examples
    --------
    Values that are the sum of a packing part and a position part only have
    no local part:

    >>> import numpy as np
    >>> from postproc.statistics import block_components
    >>> v = np.array([[0.0], [1.0], [2.0]]) + np.array([[0.0, 0.5, 0.25, 0.75]])
    >>> c = block_components(v)
    >>> print(round(c.local, 12), round(c.packing, 6), c.seeds, c.blocks)
    0.0 1.0 3 4
    """
    v = np.asarray(values, float)
    if v.ndim != 2:
        raise ValueError(f"block_components: values must be (packings, blocks), got shape {v.shape}")
    v = v[:, np.isfinite(v).all(axis=0)]
    S, B = v.shape
    nan = float("nan")
    if S < 2 or B < 2:
        return BlockComponents(nan, (nan, nan), 0, nan, nan, nan, nan, nan, S, B)
    grand = v.mean()
    rows, cols = v.mean(axis=1), v.mean(axis=0)
    dof = (S - 1) * (B - 1)
    ms_res = float(((v - rows[:, None] - cols[None, :] + grand) ** 2).sum() / dof)
    ms_seed = float(B * ((rows - grand) ** 2).sum() / (S - 1))
    ms_pos = float(S * ((cols - grand) ** 2).sum() / (B - 1))
    packing2 = max(0.0, (ms_seed - ms_res) / B)
    position2 = max(0.0, (ms_pos - ms_res) / S)
    if ms_res > 0:
        p_seed = float(f_dist.sf(ms_seed / ms_res, S - 1, dof))
        p_pos = float(f_dist.sf(ms_pos / ms_res, B - 1, dof))
    else:
        p_seed = p_pos = nan
    ci = (float(np.sqrt(dof * ms_res / chi2.ppf(0.975, dof))), float(np.sqrt(dof * ms_res / chi2.ppf(0.025, dof))))
    return BlockComponents(float(np.sqrt(ms_res)), ci, dof, float(np.sqrt(packing2)), p_seed,
                           float(np.sqrt(position2)), p_pos, float(np.sqrt(packing2 + ms_res / B)), S, B)
