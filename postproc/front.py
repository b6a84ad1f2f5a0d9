"""Speed against error (issue 7): the simulation front of a sweep, and the
accuracy and cost of the analysis estimators on synthetic sets.

Simulation front. A sweep folder holds ``<sample>/<sample>-<desc>.h5``
dumps (with their ``.info.json``) and ``<sample>/analysis-<sample>-<desc>/
summary.csv``. For every run: wall time, steps and contact-steps, the
plateau (steady shear, :func:`postproc.statistics.steady_indices`) of
q/p, a, a_n, a_t, their batch-means standard errors (the noise of one seed),
and the error |plateau - reference plateau| against the sample's reference
run: the one whose description starts with ``ref`` (the sweep puts the
stiffest, slowest run there), else the run with the largest kappa and the
smallest inertial number. ``err_max`` is the largest of the four errors.

Analysis front. Contact sets drawn from the seed's harmonic forms with known
anisotropies (:func:`postproc.synthetic.harmonic_contacts`); the tensor
estimators (:func:`postproc.fabric.anisotropies`) and the harmonic fits at
several bin counts (:func:`postproc.angular.fit_harmonics`) are timed and
their RMS error against the truth is measured over repetitions, for several
sample sizes.
"""
from __future__ import annotations

import glob
import json
import os
import time

import numpy as np

from .statistics import plateau_estimate, steady_indices

QUANTITIES = ("q_over_p", "a", "a_n", "a_t")


def collect_runs(folder):
    """DataFrame, one row per analysed run of the sweep folder."""
    import pandas as pd

    from .schema import DumpReader

    rows = []
    for summary in sorted(glob.glob(os.path.join(folder, "*", "analysis-*", "summary.csv"))):
        ana = os.path.dirname(summary)
        sample_dir = os.path.dirname(ana)
        name = os.path.basename(ana)[len("analysis-"):]
        dump = os.path.join(sample_dir, name + ".h5")
        info_path = os.path.join(sample_dir, name + ".info.json")
        if not (os.path.exists(dump) and os.path.exists(info_path)):
            continue
        with DumpReader(dump) as r:
            par = r.parameters
            sample = r.sample_kind
        with open(info_path) as fh:
            info = json.load(fh)
        df = pd.read_csv(summary)
        idx = steady_indices(df["eps_q"], df["stage"])
        row = {"sample": sample, "run": name.split("-", 1)[1] if "-" in name else name,
               "kappa": par.get("kappa"), "inertial_number": par.get("inertial_number"),
               "n_particles": par.get("n_particles"), "library": par.get("library", ""),
               "steps": info.get("steps"), "wall_seconds": info.get("wall_seconds"),
               "contact_steps": info.get("contact_steps"),
               "n_steady": len(idx)}
        for q in QUANTITIES:
            e = plateau_estimate([df[q].to_numpy(float)[idx]])
            row[q] = e.mean
            row[q + "_se"] = e.se
        rows.append(row)
    return pd.DataFrame(rows)


def add_errors(runs):
    """Add ``ref`` (bool), ``err_<q>`` and ``err_max`` columns, per sample."""
    runs = runs.copy()
    runs["ref"] = False
    for s, g in runs.groupby("sample"):
        named = g[g["run"].str.startswith("ref")]
        if len(named):
            r = named.index[0]
        else:
            r = g.sort_values(["kappa", "inertial_number", "n_particles"],
                              ascending=[False, True, False]).index[0]
        runs.loc[r, "ref"] = True
        for q in QUANTITIES:
            runs.loc[g.index, "err_" + q] = (g[q] - g.loc[r, q]).abs()
    runs["err_max"] = runs[["err_" + q for q in QUANTITIES]].max(axis=1)
    return runs


def pareto(cost, error):
    """(n,) bool: points no other point beats in both cost and error."""
    cost, error = np.asarray(cost, float), np.asarray(error, float)
    keep = np.ones(len(cost), bool)
    for i in range(len(cost)):
        better = (cost <= cost[i]) & (error <= error[i]) & ((cost < cost[i]) | (error < error[i]))
        keep[i] = not better.any()
    return keep


def write_front(folder):
    """Write ``front.csv`` and ``front.png`` into the sweep folder; returns
    the table."""
    from .errors import InputError
    from .plots import plot_front

    runs = collect_runs(folder)
    if runs.empty:
        raise InputError(f"{folder}: no analysed runs to build a front from")
    runs = add_errors(runs)
    runs["pareto"] = False
    for s, g in runs.groupby("sample"):
        runs.loc[g.index, "pareto"] = pareto(g["wall_seconds"], g["err_max"])
    runs.to_csv(os.path.join(folder, "front.csv"), index=False)
    plot_front(runs, os.path.join(folder, "front.png"))
    return runs


def analysis_front(sizes=(100, 300, 1000, 3000, 10000), bins=(6, 9, 18, 36), reps=40,
                   truth=(0.3, 0.1, 0.5, 0.2), seed=0):
    """RMS error against the truth and time per set of the tensor estimators
    and the harmonic fits (per bin count), for each sample size.

    Returns a DataFrame with columns estimator ("tensors" or "fit-<bins>"),
    n (contacts), seconds (mean per set), rms_<q> for q in a, a_l, a_n, a_t,
    and rms_max.
    """
    import pandas as pd

    from .angular import angular_functions, fit_harmonics
    from .fabric import anisotropies
    from .synthetic import harmonic_contacts

    rng = np.random.default_rng(seed)
    keys = ("a", "a_l", "a_n", "a_t")
    true = dict(zip(keys, truth))
    rows = []
    for n in sizes:
        sets = [harmonic_contacts(n, *truth, seed=rng) for _ in range(reps)]
        ests = {"tensors": lambda c: anisotropies(c.branch, c.force, 2, errors=False)}
        for b in bins:
            ests[f"fit-{b}"] = (lambda c, b=b: {k: v for k, v in fit_harmonics(
                angular_functions(c.branch, c.force, 2, nbins=b)).items()})
        for name, f in ests.items():
            err = {k: [] for k in keys}
            t0 = time.perf_counter()
            for c in sets:
                out = f(c)
                for k in keys:
                    err[k].append(out[k if name == "tensors" else k + "_fit"] - true[k])
            dt = (time.perf_counter() - t0) / reps
            row = {"estimator": name, "n": n, "seconds": dt}
            for k in keys:
                row["rms_" + k] = float(np.sqrt(np.mean(np.square(err[k]))))
                row["bias_" + k] = float(np.mean(err[k]))
            row["rms_max"] = max(row["rms_" + k] for k in keys)
            rows.append(row)
    return pd.DataFrame(rows)
