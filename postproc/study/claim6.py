"""Claim 6 (face-face contacts strong and axial, vertex-face and edge-edge
weak and lateral) on one study, decided with each contact-type criterion.

    postproc investigate claim6-criteria STUDY [--types points commonplane] [--tolerance T ...]

(:func:`write_claim6`.)

STUDY is a ``make study`` folder (its ``manifest.json``). Each usable S1
dump is analysed with every criterion that its study analysis did not use
(``postproc analyze --types T`` through :func:`postproc.pipeline.analyze_path`,
into STUDY/claim6/<run>-<T>/, or <run>-<T>-tol<X>/ with ``--tolerance X``, the
criterion's tolerance: alpha of "points", tau of "commonplane"; several
values give one row each, and the criterion's own tolerance is then added
as the nominal row, read from the analyses already made); the claims are evaluated
(:func:`postproc.study.claims.evaluate`) with those S1 summaries and the
study's S2 ones, and claim 6's numbers and verdict are printed per criterion
and written to STUDY/claim6/claim6.md, with the number of contacts behind
the VF and EE leanings (the steady window of every seed). For each
criterion it also gives every seed's leanings beside its solid fraction
after compaction, how their scatter splits into window noise and a
persistent per-sample part (:func:`postproc.statistics.seed_scatter`),
how many seeds would exclude 0 at the present mean and scatter
(:func:`postproc.statistics.seeds_needed`), and the least-squares slope of
the seeds' leanings on their solid fractions with its 95 % interval
(Student's t, n - 2 degrees of freedom).

With ``--tolerance``, the stability test of the leanings: each tolerance's
VF and EE leanings beside the nominal ones, their paired shift over seeds
with its 95 % interval, and whether the shift is inside the +-0.03 the
contact-type proportions are held to (STABLE, its interval inside; MOVES,
its interval outside; else undecided), in claim6.md, and the figure
STUDY/claim6/<criterion>-tolerance.png
(:func:`postproc.plots.plot_leanings_by_tolerance`).
"""
from __future__ import annotations

import json
import os

import numpy as np
import pandas as pd
from scipy.stats import linregress, t

from ..classify import CRITERIA
from ..errors import InputError
from ..pipeline import AnalysisOptions, analyze_path
from ..plots import plot_leanings_by_tolerance
from ..statistics import plateau_estimate, seed_scatter, seeds_needed, steady_indices
from .claims import evaluate
from .report import run_summaries, usable_runs, discover

#: the criteria claim 6 is decided with by default
DEFAULT_CRITERIA = ("points", "commonplane")
STABLE = 0.03   # the band the contact-type proportions must stay in at half and double the tolerance
LEANINGS = ("ct_fabric_VF", "ct_fabric_EE")


def write_claim6(study, criteria=DEFAULT_CRITERIA, tolerances=(None,)):
    """Claim 6 decided with each criterion on one study (see the module
    docstring): analyses into STUDY/claim6/ (numbers only: no figures), the tables in
    STUDY/claim6/claim6.md and, with tolerances, the figures
    STUDY/claim6/<criterion>-tolerance.png. Prints each criterion's verdict
    as it is reached.

    Parameters
    ----------
    study : str
        A ``make study`` folder (its manifest.json).
    criteria : sequence of str
        The criteria (``postproc analyze --types``), one row each.
    tolerances : sequence of float or None
        The criterion's tolerance (points: alpha, units of V/area;
        commonplane: tau, units of the centre-to-extreme-vertex distance);
        ``(None,)``: each criterion's own. Several values: one row each,
        beside the criterion's own as the nominal row.

    Returns
    -------
    str
        The stability tables (with tolerances) and the per-seed leanings and
        their scatter per criterion, as printed at the end (claim6.md also
        holds the table of verdicts first).

    Raises
    ------
    InputError
        A criterion or tolerance ``postproc analyze`` refuses, or no usable
        S1 run in the study.
    """
    tolerances = list(tolerances)
    for types in criteria:
        for tol in tolerances:
            AnalysisOptions(types=types, tolerance=tol).check()
    runs = discover(study)
    s1, s2 = usable_runs(runs, "polyhedra"), usable_runs(runs, "spheres")
    if not s1:
        raise InputError(f"no usable S1 run in {study}")
    s2_frames = run_summaries({"spheres": s2}).get("spheres", [])
    out = os.path.join(study, "claim6")
    os.makedirs(out, exist_ok=True)
    lines = ["| criterion | S1 seeds | contacts (steady window) | verdict | numbers |", "|---|---|---|---|---|"]
    scatter = []
    own = [pd.read_csv(os.path.join(r["analysis"], "summary.csv")) for r in s1]
    band = []
    for types in criteria:
        rows = []
        for tol in _tolerances(types, tolerances):
            name = types if tol is None else f"{types}-tol{tol:g}"
            frames = []
            for r, summary in zip(s1, own):
                if tol is None and summary["ct_method"].iloc[0] == types:
                    frames.append(summary)
                    continue
                folder = os.path.join(out, f"{r['label'].replace(' ', '')}-{name}")
                if not os.path.exists(os.path.join(folder, "summary.csv")):
                    analyze_path(r["dump"], folder, AnalysisOptions(types=types, tolerance=tol, figures=False),
                                 progress=False)
                frames.append(pd.read_csv(os.path.join(folder, "summary.csv")))
            c6 = evaluate({"polyhedra": frames, "spheres": s2_frames})[5]
            n = sum(int(df["n_contacts_pp"].to_numpy()[steady_indices(df["eps_q"], df["stage"])].sum())
                    for df in frames)
            lines.append(f"| {name} | {len(frames)} | {n} | {c6['verdict']} | {c6['numbers']} |")
            print(f"{name}: {c6['verdict']}: {c6['numbers']}", flush=True)
            series = _steady_leanings(frames)
            means = {c: np.array([np.nanmean(x) for x in series[c]]) for c in LEANINGS}
            scatter += _scatter_lines(name, s1, series, means)
            rows.append((_nominal(types) if tol is None else tol, means))
        if len(rows) > 1:
            band += _band_lines(types, rows)
            if all(x is not None for x, _ in rows):
                order = np.argsort([x for x, _ in rows])
                plot_leanings_by_tolerance(
                    [rows[k][0] for k in order],
                    {c[-2:]: np.array([rows[k][1][c] for k in order]) for c in LEANINGS},
                    os.path.join(out, f"{types}-tolerance.png"), criterion=CRITERIA[types].label,
                    unit=CRITERIA[types].unit)
    with open(os.path.join(out, "claim6.md"), "w") as fh:
        fh.write("\n".join(lines + band + scatter) + "\n")
    return "\n".join(band + scatter)


def _nominal(types):
    """The criterion's own --tolerance (the registry's default), or None when
    its parameter is set by another option (footprint, angular)."""
    c = CRITERIA[types]
    return c.default if c.option == "--tolerance" else None


def _tolerances(types, asked):
    """The tolerances of one criterion's rows: None alone without
    ``--tolerance``; else None (the criterion's own, nominal) first, then
    the asked values other than the nominal one."""
    if asked == [None]:
        return [None]
    nominal = _nominal(types)
    return [None] + [x for x in asked if x is not None and not (nominal is not None and np.isclose(x, nominal))]


def _steady_leanings(frames):
    """{column: one (K_s,) array per seed}: the VF and EE leanings of each
    seed's steady-window snapshots."""
    return {c: [df[c].to_numpy(float)[steady_indices(df["eps_q"], df["stage"])] for df in frames]
            for c in LEANINGS}


def _band_lines(types, rows):
    """Markdown: the stability test, each tolerance's leanings and their
    paired shift from the nominal row (the first), over seeds."""
    nominal_tol, nominal = rows[0]
    out = ["", f"Stability of the leanings ({types}; shift from the nominal tolerance "
               f"{nominal_tol if nominal_tol is not None else 'own'}, paired over seeds, 95 %; "
               f"stable when inside +-{STABLE})", "",
           "| tolerance | VF | VF shift | EE | EE shift |", "|---|---|---|---|---|"]
    for k, (tol, lean) in enumerate(rows):
        cells = []
        for c in LEANINGS:
            level = plateau_estimate([[v] for v in lean[c]])
            cells.append(level.text(3))
            if k == 0:
                cells.append("nominal")
                continue
            shift = plateau_estimate([[v] for v in lean[c] - nominal[c]])
            lo, hi = shift.ci()
            word = ("STABLE" if -STABLE < lo and hi < STABLE else
                    "MOVES" if lo > STABLE or hi < -STABLE else "undecided")
            cells.append(f"{shift.text(3)} {word}")
        label = "own" if tol is None else f"{tol:g}"
        out.append(f"| {label} | " + " | ".join(cells) + " |")
    return out


def _solid_fraction(run):
    """The run's solid fraction after compaction (its info file), or NaN."""
    try:
        with open(run["info"]) as fh:
            return float(json.load(fh)["solid_fraction_isotropic"])
    except (OSError, KeyError, TypeError, ValueError):
        return float("nan")


def _scatter_lines(types, runs, series, seed_means):
    """Markdown: each seed's VF and EE leanings (``seed_means``, the
    steady-window means of ``series`` from :func:`_steady_leanings`) beside
    its solid fraction, then the scatter split and the seeds needed."""
    cols = LEANINGS
    phi = np.array([_solid_fraction(r) for r in runs])
    out = ["", f"Leanings per seed ({types}; negative is lateral)", "",
           "| seed | solid fraction | VF | EE |", "|---|---|---|---|"]
    for k, r in enumerate(runs):
        out.append(f"| {r['label']} | {phi[k]:.4f} | " + " | ".join(f"{seed_means[c][k]:+.3f}" for c in cols) + " |")
    out += ["", "| leaning | mean | sd over seeds | window noise | persistent | seeds to exclude 0 "
                "| slope on solid fraction [95 %] |", "|---|---|---|---|---|---|---|"]
    for c in cols:
        sc = seed_scatter(series[c])
        means = seed_means[c]
        need = seeds_needed(means.mean(), sc.between) if np.isfinite(sc.between) else None
        ok = np.isfinite(phi) & np.isfinite(means)
        slope = "n/a"
        if ok.sum() >= 3 and np.ptp(phi[ok]) > 0:
            fit = linregress(phi[ok], means[ok])
            h = t.ppf(0.975, ok.sum() - 2) * fit.stderr
            slope = f"{fit.slope:+.1f} [{fit.slope - h:+.1f}, {fit.slope + h:+.1f}] (r {fit.rvalue:+.2f})"
        out.append(f"| {c[-2:]} | {means.mean():+.3f} | {sc.between:.3f} | {sc.within:.3f} | "
                   f"{sc.persistent:.3f} | {need if need else 'n/a'} | {slope} |")
    return out
