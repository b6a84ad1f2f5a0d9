"""The six claims of the seed paper (``reference_data/paper_values.json``),
tested on our summaries, each with its numbers and a plain verdict.

Input: for each sample ("polyhedra", "spheres") a list of ``summary.csv``
DataFrames, one per seed. Plateau values and 95 % intervals come from
:mod:`postproc.statistics` (over seeds when there are several, else batch
means of one seed, labelled so). A verdict is

* ``reproduced`` when every condition holds with its interval on the
  claimed side,
* ``not reproduced`` when a condition is contradicted with its interval on
  the other side,
* ``inconclusive`` otherwise (intervals straddle the threshold, or data are
  missing). Verdicts are never forced: the thresholds are stated here.

Thresholds: a_l is "negligible" when |a_l| < NEGLIGIBLE (0.05, a fifth of
the paper's a + a_l); the 2/5 relation "holds" when the relative residual
(q_axial/p - sff)/(q_axial/p) lies within +-SFF_TOLERANCE (0.15; the paper
shows 0.43 vs 0.46, 7 %); "throughout shear" means at least THROUGHOUT (90 %)
of a common eps_q grid past the first 10 % of the shear.
"""
from __future__ import annotations

import numpy as np

from ..classify import CRITERIA
from ..statistics import (Estimate, difference, leaning_words, plateau_estimate, seed_scatter, seeds_needed,
                          seeds_to_decide, steady_indices)

NEGLIGIBLE = 0.05
SFF_TOLERANCE = 0.15
THROUGHOUT = 0.9
EARLY = 0.1        # the first 10 % of eps_q is left out of "all along the shear"
BAND_STABLE = 0.03  # claim 6's band test: a leaning is stable when its shift stays inside +-0.03
LEANINGS = ("VF", "EE")
#: claim 6's equivalence margin: a VF or EE leaning whose 95 % interval lies
#: inside +-NO_LEANING leans nowhere ("none"), which contradicts the claim's
#: lateral leaning. 0.03 on the (5/2)(F_33 - F_11) scale of the leaning is
#: the band the band test holds a leaning's shift to, under a third of the
#: whole packing's fabric anisotropy a (0.08 published for S1, 0.10 ours)
#: and about a twentieth of the face-face leaning (+0.5): a type's directions
#: that close to isotropic do not lean toward the minor principal direction.
#: Fixed before the 5000-grain seeds that decide claim 6 were run.
NO_LEANING = 0.03
BAND = {"lo": 0.5, "hi": 2.0}   # the criterion's parameter halved, doubled (summary columns *_lo, *_hi)

#: the six claims: (the claim as the paper states it, its short form in the
#: README's claims table, the comparison-table quantities that table quotes;
#: claim 6 quotes its leanings instead); results.py builds the table from it
TABLE = (
    ("q/p of polyhedra is higher than that of spheres throughout shear.",
     "q/p of polyhedra above that of spheres throughout shear", ("q/p plateau",)),
    ("Branch-vector fabric anisotropy a is lower for polyhedra than for spheres.",
     "branch-vector anisotropy a lower for polyhedra", ("a",)),
    ("a_l is negligible for spheres, not for polyhedra.",
     "a_l negligible for spheres, not for polyhedra", ("a_l",)),
    ("a_n and, much more, a_t are higher for polyhedra.",
     "a_n and, much more, a_t higher for polyhedra", ("a_n + a_t", "a_t")),
    ("q/p ~ (2/5)(a + a_l + a_n + a_t) for both, all along the shear.",
     "q/p ≈ (2/5)(a + a_l + a_n + a_t) for both, all along the shear", ("(2/5)(a+a_l+a_n+a_t)", "q/p plateau")),
    ("Face-face contacts sit in strong chains along the major principal stress; "
     "vertex-face and edge-edge contacts carry weak forces and lean toward the minor "
     "principal direction.",
     "face–face contacts strong and axial; vertex–face and edge–edge weak and lateral", ()),
)
#: the claims as the paper states them, claim k at k - 1
CLAIMS = tuple(sentence for sentence, _, _ in TABLE)


def plateau(frames, column):
    """Estimate of ``column`` over the steady part of shear of each seed."""
    series = []
    for df in frames:
        if column not in df:
            continue
        idx = steady_indices(df["eps_q"], df["stage"])
        series.append(df[column].to_numpy(float)[idx])
    return plateau_estimate(series)


def _side(est, threshold=0.0):
    """+1 if the interval lies above threshold, -1 below, 0 straddling."""
    lo, hi = est.ci()
    if not np.isfinite(lo):
        return 0
    return 1 if lo > threshold else (-1 if hi < threshold else 0)


def _seeds_hint(est, threshold):
    """For an interval over seeds that straddles ``threshold``: ", about N
    seeds would tell it from T" (N from :func:`seeds_needed` at the present
    mean and seed-to-seed standard deviation, se x sqrt(n)); else ""."""
    if est.method != "seeds" or _side(est, threshold) != 0 or not np.isfinite(est.se):
        return ""
    n = seeds_needed(est.mean - threshold, est.se * np.sqrt(est.n))
    return f", about {n} seeds would tell it from {threshold:g}" if n else ""


def _decide_hint(est, margin=None):
    """For an undecided leaning over seeds: ", about N seeds would decide it
    (WORD)" (:func:`postproc.statistics.seeds_to_decide` at the present
    mean and seed-to-seed standard deviation, se x sqrt(n)); else ""."""
    margin = NO_LEANING if margin is None else margin
    if est.method != "seeds" or not (np.isfinite(est.se) and np.isfinite(est.mean)):
        return ""
    got = seeds_to_decide(est.mean, est.se * np.sqrt(est.n), margin)
    return f", about {got[0]} seeds would decide it ({got[1]})" if got else ""


def leaning_decision(est, margin=NO_LEANING):
    """Claim 6's decision on one leaning (the signed branch anisotropy of a
    contact type; negative: lateral).

    Parameters
    ----------
    est : Estimate
        The leaning over seeds (or one seed's batch means).
    margin : float
        The equivalence margin (:data:`NO_LEANING`).

    Returns
    -------
    str
        "none" when the 95 % interval lies inside (-margin, +margin) (an
        equivalence test, each side at 2.5 %: a leaning of size ``margin``
        or more is called "none" at most 2.5 % of the time), else "lateral"
        when it lies below 0, "axial" when above 0, else "undecided". A
        leaning told from 0 but inside the margin is "none": too small to
        call a lean.

    Examples
    --------
    >>> from postproc.statistics import Estimate
    >>> [leaning_decision(Estimate(m, 0.005, 4, 5, "seeds")) for m in (-0.05, 0.0, 0.05)]
    ['lateral', 'none', 'axial']
    >>> leaning_decision(Estimate(0.02, 0.015, 4, 5, "seeds"))          # [-0.022, 0.062]
    'undecided'
    >>> leaning_decision(Estimate(0.0, 0.015, 4, 5, "seeds"))           # [-0.042, 0.042]: not inside 0.03
    'undecided'
    """
    return str(leaning_words(*est.ci(), margin))


#: a leaning's decision as claim 6's condition (it claims "lateral")
LEANING_CONDITION = {"lateral": 1, "axial": -1, "none": -1, "undecided": 0}


def _verdict(conditions):
    """conditions: list of +1 (holds), -1 (contradicted), 0 (unclear)."""
    if any(c < 0 for c in conditions):
        return "not reproduced"
    if conditions and all(c > 0 for c in conditions):
        return "reproduced"
    return "inconclusive"


def _mean_curve(frames, column, grid):
    curves = []
    for df in frames:
        sh = df[df["stage"] == "shear"]
        x, y = sh["eps_q"].to_numpy(float), sh[column].to_numpy(float)
        ok = np.isfinite(x) & np.isfinite(y)
        if ok.sum() >= 2:
            order = np.argsort(x[ok])
            curves.append(np.interp(grid, x[ok][order], y[ok][order], left=np.nan, right=np.nan))
    if not curves:
        return np.full(len(grid), np.nan)
    curves = np.array(curves)
    n = np.isfinite(curves).sum(axis=0)
    return np.where(n > 0, np.nansum(curves, axis=0) / np.maximum(n, 1), np.nan)


def _grid(s1, s2):
    tops = [np.nanmax(df.loc[df["stage"] == "shear", "eps_q"]) for df in s1 + s2
            if (df["stage"] == "shear").any()]
    top = np.nanmin(tops) if tops else np.nan
    if not np.isfinite(top) or top <= 0:
        return np.array([])
    return np.linspace(EARLY * top, top, 50)


def evaluate(samples):
    """The six claims on ``samples`` = {"polyhedra": [df, ...], "spheres":
    [df, ...]}. Returns a list of 6 dicts: ``id``, ``claim``, ``numbers``
    (text), ``verdict``, ``basis`` (how the interval was obtained)."""
    s1, s2 = samples.get("polyhedra", []), samples.get("spheres", [])
    out = []

    def add(k, numbers, conds, basis):
        out.append({"id": k, "claim": CLAIMS[k - 1], "numbers": numbers,
                    "verdict": _verdict(conds) if s1 and (s2 or k == 6) else "inconclusive",
                    "basis": basis})

    def est(frames, col):
        return plateau(frames, col) if frames else Estimate(np.nan, np.nan, 0, 0, "no run")

    # 1. q/p higher for polyhedra throughout shear
    q1, q2 = est(s1, "q_over_p"), est(s2, "q_over_p")
    d = difference(q1, q2)
    grid = _grid(s1, s2)
    if len(grid) and s1 and s2:
        c1, c2 = _mean_curve(s1, "q_over_p", grid), _mean_curve(s2, "q_over_p", grid)
        ok = np.isfinite(c1) & np.isfinite(c2)
        frac = float(np.mean(c1[ok] > c2[ok])) if ok.any() else np.nan
    else:
        frac = np.nan
    # the curves are single (or few) noisy realisations: "throughout" can
    # confirm the claim, only the plateau interval can contradict it
    throughout = 1 if frac >= THROUGHOUT else 0
    add(1, f"plateau q/p: polyhedra {q1.text()}, spheres {q2.text()}, difference {d.text()}; "
           f"polyhedra above spheres on "
           f"{f'{frac:.0%}' if np.isfinite(frac) else 'n/a'} of the shear (eps_q grid past its first 10 %)",
        [_side(d), throughout if np.isfinite(frac) else 0], d.method)

    # 2. a lower for polyhedra
    a1, a2 = est(s1, "a"), est(s2, "a")
    d = difference(a1, a2)
    add(2, f"plateau a: polyhedra {a1.text()}, spheres {a2.text()}, difference {d.text()}",
        [-_side(d)], d.method)

    # 3. a_l negligible for spheres, not for polyhedra
    l1, l2 = est(s1, "a_l"), est(s2, "a_l")
    lo2, hi2 = l2.ci()
    sph = 1 if (np.isfinite(lo2) and -NEGLIGIBLE < lo2 and hi2 < NEGLIGIBLE) else \
        (-1 if np.isfinite(lo2) and (lo2 > NEGLIGIBLE or hi2 < -NEGLIGIBLE) else 0)
    lo1, hi1 = l1.ci()
    poly = 1 if (np.isfinite(lo1) and (lo1 > NEGLIGIBLE or hi1 < -NEGLIGIBLE)) else \
        (-1 if np.isfinite(lo1) and -NEGLIGIBLE < lo1 and hi1 < NEGLIGIBLE else 0)
    add(3, f"plateau a_l: polyhedra {l1.text()}, spheres {l2.text()} "
           f"(negligible: |a_l| < {NEGLIGIBLE})", [sph, poly], l1.method)

    # 4. a_n and, much more, a_t higher for polyhedra
    n1, n2, t1, t2 = est(s1, "a_n"), est(s2, "a_n"), est(s1, "a_t"), est(s2, "a_t")
    dn, dt = difference(n1, n2), difference(t1, t2)
    rn = n1.mean / n2.mean if n2.mean else np.nan
    rt = t1.mean / t2.mean if t2.mean else np.nan
    much = 1 if (np.isfinite(rt) and np.isfinite(rn) and rt > rn) else (-1 if rt <= rn else 0)
    add(4, f"plateau a_n: polyhedra {n1.text()}, spheres {n2.text()} (difference {dn.text()}, "
           f"ratio {rn:.2f}); a_t: polyhedra {t1.text()}, spheres {t2.text()} "
           f"(difference {dt.text()}, ratio {rt:.2f})", [_side(dn), _side(dt), much], dn.method)

    # 5. the 2/5 relation for both samples, all along the shear
    parts, conds = [], []
    for name, frames in (("polyhedra", s1), ("spheres", s2)):
        if not frames:
            conds.append(0)
            continue
        # a copy first: the analysis frames are built column by column, and
        # pandas warns when one more is inserted into such a fragmented frame
        frames = [df.copy().assign(sff_relative_residual=(df["q_axial_over_p"] - df["sff"])
                                   / df["q_axial_over_p"]) for df in frames]
        r = est(frames, "sff_relative_residual")
        worst = []
        for df in frames:
            sh = df[(df["stage"] == "shear")]
            top = sh["eps_q"].max()
            late = sh[sh["eps_q"] >= EARLY * top]
            worst.append(np.nanmax(np.abs(late["sff_relative_residual"])) if len(late) else np.nan)
        qp, sff = est(frames, "q_axial_over_p"), est(frames, "sff")
        lo, hi = r.ci()
        c = 1 if (np.isfinite(lo) and -SFF_TOLERANCE < lo and hi < SFF_TOLERANCE) else \
            (-1 if np.isfinite(lo) and (lo > SFF_TOLERANCE or hi < -SFF_TOLERANCE) else 0)
        conds.append(c)
        parts.append(f"{name}: q_axial/p {qp.text()} vs (2/5)Σa {sff.text()}, relative residual "
                     f"{r.text()}, largest |residual| past the first 10 % of shear "
                     f"{np.nanmax(worst):.2f}")
    add(5, "; ".join(parts) + f" (holds: residual within ±{SFF_TOLERANCE})", conds, q1.method)

    # 6. face-face strong and along the axis; vertex-face, edge-edge weak and lateral
    c6 = claim6(s1)
    add(6, c6["numbers"], c6["conditions"], c6["basis"])
    return out


def _column(tag, name):
    """The summary column of claim 6's quantity ``name`` with the contact
    criterion's parameter at its own value (tag "") or halved/doubled
    ("lo"/"hi", see :func:`postproc.analysis.contact_type_columns`)."""
    return f"{name}_{tag}" if tag else name


def _criterion_text(df, tag=""):
    """How the contacts of a summary were typed, with the parameter used."""
    method = df["ct_method"].iloc[0] if "ct_method" in df else None
    factor = BAND.get(tag, 1.0)
    c = CRITERIA.get(method)
    if c is not None:
        value = df["ct_theta_deg" if c.option == "--theta" else "ct_threshold"].iloc[0]
        return c.reading.format(factor * value)
    if "ct_theta_deg" in df:
        return f"angular criterion, tolerance {factor * df['ct_theta_deg'].iloc[0]:g} deg"
    return None


def claim6(s1, tag=""):
    """Claim 6 on the S1 summaries ``s1`` (one DataFrame per seed, typed by
    one contact criterion): face-face contacts carry more than the mean
    force and lean along the compression axis, and their share of the
    strong network exceeds that of the weak; vertex-face and edge-edge
    contacts carry less than the mean force and lean toward the lateral
    (minor principal) directions. Leaning: the signed branch-vector
    anisotropy of a type, (5/2)(F_33 - F_11) of its fabric tensor,
    negative when lateral (:func:`postproc.pertype.class_statistics`).

    ``tag``: "" for the criterion's own parameter, "lo"/"hi" for it halved
    or doubled (the band test; the ``*_lo``/``*_hi`` columns).
    Returns {"numbers": text, "conditions": [+1/-1/0 per condition],
    "verdict", "basis", "estimates": {name: Estimate}}."""
    def est(col):
        return plateau(s1, _column(tag, col)) if s1 else Estimate(np.nan, np.nan, 0, 0, "no run")

    checks, conds, estimates = [], [], {}
    for col, sign, thr, what in (
            ("ct_fratio_FF", 1, 1.0, "FF mean force / mean"),
            ("ct_fabric_FF", 1, 0.0, "FF signed branch anisotropy"),
            ("ct_fratio_VF", -1, 1.0, "VF mean force / mean"),
            ("ct_fratio_EE", -1, 1.0, "EE mean force / mean"),
            ("ct_fabric_VF", -1, 0.0, "VF signed branch anisotropy"),
            ("ct_fabric_EE", -1, 0.0, "EE signed branch anisotropy")):
        e = estimates[col] = est(col)
        if col.startswith("ct_fabric_") and col != "ct_fabric_FF":
            word = leaning_decision(e)
            conds.append(LEANING_CONDITION[word])
            hint = _decide_hint(e) if word == "undecided" else ""
            checks.append(f"{what} {e.text()} (< 0{hint}; leaning {word}, none inside ±{NO_LEANING:g})")
            continue
        conds.append(sign * _side(e, thr))
        checks.append(f"{what} {e.text()} ({'>' if sign > 0 else '<'} {thr:g}{_seeds_hint(e, thr)})")
    fs, fw = est("strong_frac_FF"), est("weak_frac_FF")
    estimates["strong_frac_FF"], estimates["weak_frac_FF"] = fs, fw
    conds.append(_side(difference(fs, fw)))
    checks.append(f"FF share of the strong network {fs.text()} vs weak {fw.text()}")
    criterion = _criterion_text(s1[0], tag) if s1 else None
    if criterion:
        checks.append(criterion)
    typed = bool(s1) and _column(tag, "ct_fratio_FF") in s1[0]
    conds = conds if typed else [0]
    return {"numbers": "; ".join(checks), "conditions": conds, "verdict": _verdict(conds) if typed else "inconclusive",
            "basis": est("ct_fratio_FF").method, "estimates": estimates}


def seed_leanings(s1, tag=""):
    """{"VF": (n_seeds,), "EE": (n_seeds,)}: each seed's steady-window mean
    of the type's signed branch anisotropy (claim 6's leaning; negative is
    lateral), with the criterion's parameter as ``tag`` says."""
    out = {}
    for k in LEANINGS:
        col = _column(tag, f"ct_fabric_{k}")
        out[k] = np.array([np.nanmean(df[col].to_numpy(float)[steady_indices(df["eps_q"], df["stage"])])
                           if col in df else np.nan for df in s1])
    return out


def leaning_scatter(s1):
    """{"VF": SeedScatter, "EE": SeedScatter}: how the seeds' leanings
    scatter (:func:`postproc.statistics.seed_scatter`: between seeds, the
    window noise of one seed, and the persistent per-sample part)."""
    return {k: seed_scatter([df[f"ct_fabric_{k}"].to_numpy(float)[steady_indices(df["eps_q"], df["stage"])]
                             for df in s1 if f"ct_fabric_{k}" in df]) for k in LEANINGS}


def band_test(s1):
    """The band test of claim 6's leanings: with the contact criterion's
    parameter halved ("lo") and doubled ("hi"), each leaning's level over
    seeds and its shift from the nominal one, paired seed by seed (95 %,
    Student's t over seeds), and a word: "stable" when the shift's interval
    lies inside +-BAND_STABLE (the band the contact-type proportions are
    held to), "moves" when it lies outside, else "undecided".

    Returns a list of dicts, one per tag ("", "lo", "hi") with "tag",
    "factor" and for each leaning k: k (Estimate of the level), and for
    "lo"/"hi" f"{k}_shift" (Estimate) and f"{k}_word"."""
    nominal = seed_leanings(s1)
    rows = []
    for tag in ("", "lo", "hi"):
        lean = seed_leanings(s1, tag)
        row = {"tag": tag, "factor": BAND.get(tag, 1.0)}
        for k in LEANINGS:
            row[k] = plateau_estimate([[v] for v in lean[k]])
            if tag:
                shift = plateau_estimate([[v] for v in lean[k] - nominal[k]])
                lo, hi = shift.ci()
                row[f"{k}_shift"] = shift
                row[f"{k}_word"] = ("stable" if -BAND_STABLE < lo and hi < BAND_STABLE else
                                    "moves" if lo > BAND_STABLE or hi < -BAND_STABLE else "undecided")
        rows.append(row)
    return rows



def claim6_groups(s1, prefix):
    """Claim 6 read off a count by groups only (simple, double, triple):
    triple contacts (face-face) carry more than the mean force and lean
    along the axis, their share of the strong network exceeding that of the
    weak; simple contacts (vertex-face and edge-edge, one point each) carry
    less than the mean force and lean laterally. The leaning is the signed
    branch anisotropy (5/2)(F_33 - F_11) of the group's fabric tensor
    (the paper's Eq. 6), decided as :func:`leaning_decision` decides VF's.

    The CD counts of a CD dump (``prefix`` ``"cd_alert_"``: every point
    within the alert distance; ``"cd_force_"``: the force-carrying points)
    have only these groups, so this is how claim 6 is decided by them; the
    conditions are those of :func:`claim6` with FF read as triple and VF, EE
    (one condition each in :func:`claim6`) as the one simple group.

    Parameters
    ----------
    s1 : list of DataFrame
        The S1 summaries, one per seed.
    prefix : str
        The count's column prefix: ``{prefix}fratio_triple``,
        ``{prefix}fabric_simple``, ``{prefix}strong_frac_triple``, ...

    Returns
    -------
    dict
        As :func:`claim6`: "numbers", "conditions", "verdict", "basis",
        "estimates"; "inconclusive" with one condition 0 when the count's
        columns are absent.
    """
    def est(col):
        return plateau(s1, prefix + col) if s1 else Estimate(np.nan, np.nan, 0, 0, "no run")

    checks, conds, estimates = [], [], {}
    for col, sign, thr, what in (("fratio_triple", 1, 1.0, "triple mean force / mean"),
                                 ("fabric_triple", 1, 0.0, "triple signed branch anisotropy"),
                                 ("fratio_simple", -1, 1.0, "simple mean force / mean"),
                                 ("fabric_simple", -1, 0.0, "simple signed branch anisotropy")):
        e = estimates[prefix + col] = est(col)
        if col == "fabric_simple":
            word = leaning_decision(e)
            conds.append(LEANING_CONDITION[word])
            checks.append(f"{what} {e.text()} (< 0; leaning {word}, none inside ±{NO_LEANING:g})")
            continue
        conds.append(sign * _side(e, thr))
        checks.append(f"{what} {e.text()} ({'>' if sign > 0 else '<'} {thr:g})")
    fs, fw = est("strong_frac_triple"), est("weak_frac_triple")
    estimates[prefix + "strong_frac_triple"], estimates[prefix + "weak_frac_triple"] = fs, fw
    conds.append(_side(difference(fs, fw)))
    checks.append(f"triple share of the strong network {fs.text()} vs weak {fw.text()}")
    typed = bool(s1) and prefix + "fratio_triple" in s1[0]
    conds = conds if typed else [0]
    return {"numbers": "; ".join(checks), "conditions": conds,
            "verdict": _verdict(conds) if typed else "inconclusive",
            "basis": est("fratio_triple").method, "estimates": estimates}
