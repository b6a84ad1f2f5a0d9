"""Speed against error along the time step: S1 at the default kappa and I
with dt = safety x the critical step, safety 0.3 (the default), 0.45, 0.6, 0.9.

    python benchmarks/timestep_front.py [--out runs/timestep] [--jobs 2]

Runs the ``timestep`` plan of :mod:`yade_scripts.front` (200 polyhedra, the
default preset, 3 seeds; finished runs are not run again), analyses each
dump, then writes OUT/timestep.csv and OUT/timestep.md: per safety, the
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

import argparse
import os
import sys

import numpy as np
import pandas as pd

from postproc.statistics import plateau_estimate
from postproc.study.front import COMPARISON, collect_runs
from yade_scripts.front import PLANS, TIMESTEP_SAFETIES, run_front

REFERENCE_SAFETY = TIMESTEP_SAFETIES[0]
QUANTITIES = tuple(COMPARISON) + ("phi_iso",)


def _paired(runs, reference):
    """Per safety s: (s, its runs indexed by seed, the reference runs indexed
    by seed, the seeds both have)."""
    ref = runs[runs["safety"] == reference].set_index("seed")
    for s, g in runs.groupby("safety"):
        g = g.set_index("seed")
        yield s, g, ref, g.index.intersection(ref.index)


def paired_table(runs, quantities=QUANTITIES, reference=REFERENCE_SAFETY):
    """One row per (safety, quantity): ``mean`` over seeds, ``diff`` the mean
    over seeds of (value - value at ``reference``, same seed), ``lo``/``hi``
    its 95 % interval (t over seeds), ``sd_ref`` the seed-to-seed standard
    deviation at the reference, ``n`` the seeds paired."""
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
    """One row per safety: runs, median steps, compaction and shear steps,
    wall seconds, and the median over seeds of steps / steps at the
    reference (same seed)."""
    rows = []
    for s, g, ref, common in _paired(runs, reference):
        ratio = (g.loc[common, "steps"] / ref.loc[common, "steps"]).to_numpy(float)
        rows.append({"safety": s, "runs": len(g), "steps": float(g["steps"].median()),
                     "compaction_steps": float(g["compaction_steps"].median()),
                     "shear_steps": float(g["shear_steps"].median()),
                     "wall_seconds": float(g["wall_seconds"].median()),
                     "steps_ratio": float(np.median(ratio)) if len(ratio) else np.nan})
    return pd.DataFrame(rows)


def markdown(cost, paired, failed):
    out = [f"| safety | runs | steps | compaction | shear | wall s | steps / steps at {REFERENCE_SAFETY:g} |",
           "|---|---|---|---|---|---|---|"]
    for _, r in cost.iterrows():
        out.append(f"| {r['safety']:g} | {int(r['runs'])} | {r['steps']:.0f} | {r['compaction_steps']:.0f} | "
                   f"{r['shear_steps']:.0f} | {r['wall_seconds']:.0f} | {r['steps_ratio']:.2f} |")
    safeties = sorted(paired["safety"].unique())
    others = [s for s in safeties if s != REFERENCE_SAFETY]
    out += ["", f"| quantity | at {REFERENCE_SAFETY:g} (sd over seeds) | "
            + " | ".join(f"{s:g} − {REFERENCE_SAFETY:g}" for s in others) + " |",
            "|---|---|" + "---|" * len(others)]
    for q in QUANTITIES:
        ref = paired[(paired["safety"] == REFERENCE_SAFETY) & (paired["quantity"] == q)]
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


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="runs/timestep")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args(argv)
    status = run_front(args.out, "timestep", jobs=args.jobs, samples=("polyhedra",))
    failed = [(d, c) for d, c in status["polyhedra"].items() if c != 0]
    runs = collect_runs(args.out)
    runs = runs[runs["run"].isin([d for d, _ in PLANS["timestep"]["polyhedra"]])]
    if runs.empty:
        print("timestep_front: no analysed runs", file=sys.stderr)
        return 1
    cost, paired = cost_table(runs), paired_table(runs)
    runs.to_csv(os.path.join(args.out, "timestep-runs.csv"), index=False)
    paired.to_csv(os.path.join(args.out, "timestep.csv"), index=False)
    text = markdown(cost, paired, failed)
    with open(os.path.join(args.out, "timestep.md"), "w") as fh:
        fh.write(text)
    print(text)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
