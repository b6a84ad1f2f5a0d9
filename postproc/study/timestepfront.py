"""Speed against error along the time step: S1 at the default kappa and I
with dt = safety x the critical step, safety 0.3 (the default), 0.45, 0.6, 0.9.

    python -m yade_scripts.campaign.timestep_sweep [--out runs/timestep] [--jobs 2]
    postproc investigate timestep-front OUT

The first runs the ``timestep`` plan of :mod:`yade_scripts.campaign.sweeps` (200
polyhedra, the default preset, 3 seeds; finished runs are not run again)
and analyses each dump, then tabulates the front as the second does on a
folder it left (:func:`write_timestep_front`): OUT/timestep.csv and
OUT/timestep.md give, per safety, the
median steps and wall time, the steps over those of safety 0.3 (paired by
seed), and for each quantity of the study's comparison table and the solid
fraction after compaction, its mean over seeds and the paired difference
from safety 0.3 (mean over seeds with its 95 % Student's-t interval). The
same seed starts from the same grains and positions at every safety, so a
difference whose interval holds 0 is a time-step error below what 3 seeds
resolve; its width is printed beside the seed-to-seed standard deviation at
0.3 for scale. A run that fails (e.g. blows up) is listed with its exit
status.

The number of steps of a run goes as 1/safety (the rates are set by I), so
the cost of a study, and the paper preset's core-hours, go the same way.
"""
from __future__ import annotations

import json
import os

import numpy as np
import pandas as pd

from ..errors import InputError
from ..statistics import plateau_estimate
from .front import COMPARISON, collect_runs

#: the safety the others are compared with: the default, the first of the
#: plan's (``yade_scripts.campaign.sweeps.TIMESTEP_SAFETIES``)
REFERENCE_SAFETY = 0.3
QUANTITIES = tuple(COMPARISON) + ("phi_iso",)


def _paired(runs, reference):
    """Per safety s: (s, its runs indexed by seed, the reference runs indexed
    by seed, the seeds both have)."""
    ref = runs[runs["safety"] == reference].set_index("seed")
    for s, g in runs.groupby("safety"):
        g = g.set_index("seed")
        yield s, g, ref, g.index.intersection(ref.index)


def paired_table(runs, quantities=QUANTITIES, reference=REFERENCE_SAFETY):
    """Each quantity at each safety against the reference safety, paired by
    seed.

    Parameters
    ----------
    runs : pandas.DataFrame
        One row per run (:func:`postproc.study.front.collect_runs`): its
        ``safety``, ``seed`` and quantities.
    quantities : sequence of str
        Columns of ``runs`` to compare.
    reference : float
        The safety the others are compared with.

    Returns
    -------
    pandas.DataFrame
        One row per (safety, quantity): ``mean`` over seeds, ``diff`` the
        mean over seeds of (value - value at ``reference``, same seed),
        ``lo``/``hi`` its 95 % interval (t over seeds), ``sd_ref`` the
        seed-to-seed standard deviation at the reference, ``n`` the seeds
        paired.
    """
    rows = []
    for s, g, ref, common in _paired(runs, reference):
        for q in quantities:
            v = g[q].to_numpy(float)
            d = (g.loc[common, q] - ref.loc[common, q]).to_numpy(float)
            e = plateau_estimate([[x] for x in d[np.isfinite(d)]])
            lo, hi = e.ci()
            rows.append({"safety": s, "quantity": q, "mean": float(np.nanmean(v)) if len(v) else np.nan,
                         "diff": e.mean, "lo": lo, "hi": hi, "n": int(np.isfinite(d).sum()),
                         "sd_ref": float(np.nanstd(ref[q].to_numpy(float), ddof=1)) if len(ref) > 1 else np.nan})
    return pd.DataFrame(rows)


def cost_table(runs, reference=REFERENCE_SAFETY):
    """The cost of each safety.

    Parameters
    ----------
    runs : pandas.DataFrame
        One row per run (:func:`postproc.study.front.collect_runs`).
    reference : float
        The safety the steps are compared with.

    Returns
    -------
    pandas.DataFrame
        One row per safety: runs, median steps, compaction and shear steps,
        wall seconds, and the median over seeds of steps / steps at the
        reference (same seed).
    """
    rows = []
    for s, g, ref, common in _paired(runs, reference):
        ratio = (g.loc[common, "steps"] / ref.loc[common, "steps"]).to_numpy(float)
        rows.append({"safety": s, "runs": len(g), "steps": float(g["steps"].median()),
                     "compaction_steps": float(g["compaction_steps"].median()),
                     "shear_steps": float(g["shear_steps"].median()),
                     "wall_seconds": float(g["wall_seconds"].median()),
                     "steps_ratio": float(np.median(ratio)) if len(ratio) else np.nan})
    return pd.DataFrame(rows)


def markdown(cost, paired, failed, reference=REFERENCE_SAFETY):
    """The text of timestep.md.

    Parameters
    ----------
    cost : pandas.DataFrame
        :func:`cost_table`'s rows.
    paired : pandas.DataFrame
        :func:`paired_table`'s rows.
    failed : list of (str, int)
        (run, exit status) of the runs that failed, listed last.
    reference : float
        The reference safety of both tables.

    Returns
    -------
    str
        Markdown: the cost per safety, then each quantity at the reference
        (its seed-to-seed sd) and every other safety's paired difference
        with its 95 % interval.
    """
    out = [f"| safety | runs | steps | compaction | shear | wall s | steps / steps at {reference:g} |",
           "|---|---|---|---|---|---|---|"]
    for _, r in cost.iterrows():
        out.append(f"| {r['safety']:g} | {int(r['runs'])} | {r['steps']:.0f} | {r['compaction_steps']:.0f} | "
                   f"{r['shear_steps']:.0f} | {r['wall_seconds']:.0f} | {r['steps_ratio']:.2f} |")
    safeties = sorted(paired["safety"].unique())
    others = [s for s in safeties if s != reference]
    out += ["", f"| quantity | at {reference:g} (sd over seeds) | "
            + " | ".join(f"{s:g} − {reference:g}" for s in others) + " |",
            "|---|---|" + "---|" * len(others)]
    for q in QUANTITIES:
        ref = paired[(paired["safety"] == reference) & (paired["quantity"] == q)]
        if ref.empty:
            continue
        cells = [f"{ref['mean'].iloc[0]:.3f} ({ref['sd_ref'].iloc[0]:.3f})"]
        for s in others:
            r = paired[(paired["safety"] == s) & (paired["quantity"] == q)].iloc[0]
            cells.append(f"{r['diff']:+.3f} [{r['lo']:+.3f}, {r['hi']:+.3f}]" if np.isfinite(r["lo"])
                         else f"{r['diff']:+.3f}")
        out.append(f"| {COMPARISON.get(q, q)} | " + " | ".join(cells) + " |")
    if failed:
        out += ["", "Failed runs: " + ", ".join(f"{d} (exit {c})" for d, c in failed)]
    return "\n".join(out) + "\n"


def plan_runs(folder):
    """The polyhedra runs of the plan a front folder was run with.

    Parameters
    ----------
    folder : str
        A folder of :func:`yade_scripts.campaign.sweeps.run_front` (its
        front-plan.json).

    Returns
    -------
    list of str
        The plan's polyhedra run descriptions (``dt0.3-s1``, ...).

    Raises
    ------
    InputError
        No readable front-plan.json.
    """
    path = os.path.join(folder, "front-plan.json")
    try:
        with open(path) as fh:
            return [desc for desc, _ in json.load(fh).get("polyhedra", [])]
    except (OSError, ValueError, TypeError) as exc:
        raise InputError(f"{path}: not a readable plan ({exc})") from None


def write_timestep_front(out, runs_of_plan=None, failed=(), reference=REFERENCE_SAFETY):
    """The time-step front of a folder's analysed runs: writes
    OUT/timestep-runs.csv (one row per run), OUT/timestep.csv
    (:func:`paired_table`) and OUT/timestep.md (:func:`markdown`).

    Parameters
    ----------
    out : str
        The front's folder (its runs analysed).
    runs_of_plan : list of str, optional
        The run descriptions to use (default the folder's plan,
        :func:`plan_runs`).
    failed : sequence of (str, int)
        (run, exit status) of failed runs, listed in timestep.md.
    reference : float
        The safety the others are compared with.

    Returns
    -------
    str
        The text of timestep.md.

    Raises
    ------
    InputError
        No analysed run of the plan in the folder.
    """
    if runs_of_plan is None:
        runs_of_plan = plan_runs(out)
    runs = collect_runs(out)
    runs = runs[runs["run"].isin(list(runs_of_plan))] if not runs.empty else runs
    if runs.empty:
        raise InputError(f"{out}: no analysed runs")
    cost, paired = cost_table(runs, reference), paired_table(runs, reference=reference)
    runs.to_csv(os.path.join(out, "timestep-runs.csv"), index=False)
    paired.to_csv(os.path.join(out, "timestep.csv"), index=False)
    text = markdown(cost, paired, list(failed), reference)
    with open(os.path.join(out, "timestep.md"), "w") as fh:
        fh.write(text)
    return text
