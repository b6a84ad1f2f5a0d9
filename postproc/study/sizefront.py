"""The size front: the study's quantities at several numbers of grains.

Every conclusion of the study rests on packings far smaller than the
paper's (36 933 polyhedra, 19 998 spheres). The size front measures, for
every quantity the claims use, how it moves with the number of grains N:
the same study (``make study`` at the default's kappa, I and preparation)
run at several N (the presets ``small``, ``default`` and ``intermediate``:
200, 1000 and 5000 grains per sample).

For each study folder (its ``manifest.json``, :mod:`postproc.study.report`)
and each usable run, one value per seed: the plateau (mean over the steady
window, :func:`postproc.statistics.steady_indices`) of q/p, a, a_l, a_n,
a_t, (2/5)(a + a_l + a_n + a_t), the relative residual of the 2/5 relation,
z, the fraction of forces below the mean; the solid fraction after
compaction (the run's info file); and for S1, per contact count (the
primary analysis and each other count of :mod:`postproc.study.counts`),
the proportions of simple, double and triple contacts and claim 6's force
ratios, leanings and FF shares of the strong and weak networks. Then per
quantity, sample and N the mean over seeds with its 95 % interval
(Student's t over seeds); between consecutive N the difference with its
interval (Welch); and the trend with N: a straight line in x = N^(-1/3)
(walls and other boundary effects scale as the surface over the volume,
N^(2/3) / N), fitted by weighted least squares through the means
(weights 1 / se^2), whose intercept is the value extrapolated to N -> inf
(interval: Welch-Satterthwaite degrees of freedom of the linear
combination of the means). The per-seed scatter of the claim-6 leanings is
compared across N: if it falls as N^(-1/2), the ratio of standard
deviations sd(N1)/sd(N2) is sqrt(N2/N1); its 95 % interval comes from the
F distribution of the variance ratio. And the verdicts of the six claims,
and of claim 6 by each count, at each N.
"""
from __future__ import annotations

import json
import os

import numpy as np
import pandas as pd
from scipy.stats import f as f_dist

from .claims import claim6, evaluate
from .report import REFERENCE, run_summaries, usable_runs, count_summaries, discover
from ..columns import GROUPS, label
from ..errors import InputError, read_json_object
from ..statistics import Estimate, difference, plateau_estimate, steady_indices

SAMPLES = ("polyhedra", "spheres")
#: quantity -> (summary column or None for a derived one, label)
QUANTITIES = {
    "q_over_p": ("q_over_p", f"{label('q_over_p')} plateau"),
    **{k: (k, label(k)) for k in ("a", "a_l", "a_n", "a_t", "sff")},
    "sff_rel_residual": (None, "(q/p − (2/5)Σa) / (q/p)"),
    **{k: (k, label(k)) for k in ("z", "frac_below_mean")},
    "phi_iso": (None, "solid fraction after compaction"),
}
#: claim 6 and contact-type quantities of S1, per count
COUNT_QUANTITIES = {
    **{f"ct_frac_{g}": g for g in GROUPS},
    **{k: label(k) for k in ("ct_fratio_FF", "ct_fratio_VF", "ct_fratio_EE", "ct_fabric_FF", "ct_fabric_VF",
                             "ct_fabric_EE", "strong_frac_FF", "weak_frac_FF")},
}
LEANINGS = ("ct_fabric_VF", "ct_fabric_EE")


def _steady_mean(df, col):
    if col not in df:
        return np.nan
    v = df[col].to_numpy(float)[steady_indices(df["eps_q"], df["stage"])]
    v = v[np.isfinite(v)]
    return float(v.mean()) if len(v) else np.nan


def _n_particles(run):
    """N of a run: its run folder's params.json, else its dump's parameters."""
    pj = os.path.join(os.path.dirname(run.get("dump") or ""), "params.json")
    if os.path.exists(pj):
        n = read_json_object(pj, "run parameters file").get("n_particles")
        whole = isinstance(n, int) or (isinstance(n, float) and n.is_integer())
        if isinstance(n, bool) or not whole or n < 1 or n > 10 ** 12:
            raise InputError(f"{pj}: n_particles {n!r} is not a number of grains (a whole number from 1 to 1e12)")
        return int(n)
    from ..schema import DumpReader

    with DumpReader(run["dump"]) as r:
        return int(r.parameters["n_particles"])


def _phi(run):
    try:
        with open(run["info"]) as fh:
            return float(json.load(fh)["solid_fraction_isotropic"])
    except (OSError, KeyError, TypeError, ValueError):
        return np.nan


def study_values(study):
    """DataFrame, one row per usable run of the study folder: study, sample,
    n_particles, run label, and one column per quantity (the seed's
    plateau), S1's count quantities named ``<count>:<column>``. Raises
    InputError (one line) when the folder has no manifest or no usable run."""
    if not os.path.exists(os.path.join(study, "manifest.json")):
        raise InputError(f"{study}: no manifest.json (run make study there first)")
    runs = discover(study)
    rows = []
    for sample in SAMPLES:
        for run in usable_runs(runs, sample):
            frames = run_summaries({sample: [run]})[sample]
            if not frames:
                continue
            df = frames[0]
            row = {"study": study, "sample": sample, "n_particles": _n_particles(run), "run": run["label"]}
            for q, (col, _) in QUANTITIES.items():
                if col:
                    row[q] = _steady_mean(df, col)
            if "q_axial_over_p" in df and "sff" in df:
                qa = df["q_axial_over_p"].to_numpy(float)
                row["sff_rel_residual"] = _steady_mean(df.assign(_r=(qa - df["sff"].to_numpy(float)) / qa), "_r")
            else:
                row["sff_rel_residual"] = np.nan
            row["phi_iso"] = _phi(run)
            if sample == "polyhedra":
                for count, cdf in _count_frames(run, df).items():
                    for col in COUNT_QUANTITIES:
                        row[f"{count}:{col}"] = _steady_mean(cdf, col)
            rows.append(row)
    if not rows:
        raise InputError(f"{study}: no usable run in its manifest")
    return pd.DataFrame(rows)


def _count_frames(run, primary):
    """{count: summary DataFrame} of an S1 run: the primary analysis under
    its own count (``ct_method``), then each other count the study analysed
    (:mod:`postproc.study.counts`)."""
    out = {}
    if "ct_method" in primary:
        out[str(primary["ct_method"].iloc[0])] = primary
    for count, folder in (run.get("counts") or {}).items():
        if count in out or not os.path.exists(os.path.join(folder, "summary.csv")):
            continue
        sub = run_summaries({"polyhedra": [{**run, "analysis": folder}]})["polyhedra"]
        if sub:
            out[count] = sub[0]
    return out


def _estimate(values):
    v = np.asarray(values, float)
    return plateau_estimate([[x] for x in v[np.isfinite(v)]])


def _trend(points):
    """Weighted least squares y = y_inf + c x, x = N^(-1/3), through the
    means of ``points`` [(N, Estimate)] (weights 1/se^2). Returns
    (y_inf Estimate, c Estimate); NaN Estimates with fewer than 3 points with
    finite standard errors > 0. The intervals use the Welch-Satterthwaite
    degrees of freedom of each coefficient as a linear combination of the
    means."""
    pts = [(n, e) for n, e in points if np.isfinite(e.mean) and np.isfinite(e.se) and e.se > 0 and e.dof >= 1]
    nan = Estimate(np.nan, np.nan, 0, 0, "no trend")
    if len(pts) < 3:
        return nan, nan
    x = np.array([n ** (-1 / 3) for n, _ in pts])
    y = np.array([e.mean for _, e in pts])
    se = np.array([e.se for _, e in pts])
    dof = np.array([e.dof for _, e in pts], float)
    X = np.column_stack([np.ones_like(x), x])
    W = np.diag(1 / se ** 2)
    A = np.linalg.solve(X.T @ W @ X, X.T @ W)          # coefficients = A @ y
    out = []
    for row in A:
        var_terms = row ** 2 * se ** 2
        var = var_terms.sum()
        nu = var ** 2 / np.sum(var_terms ** 2 / dof)
        out.append(Estimate(float(row @ y), float(np.sqrt(var)), float(nu), len(pts), "seeds (trend in N^-1/3)"))
    return out[0], out[1]


def size_table(values):
    """Long DataFrame: per quantity, sample and N, the mean over seeds with
    its 95 % interval, the seeds' sd and count; per quantity and sample the
    difference from the next smaller N (Welch, 95 %), the extrapolation to
    N -> inf and the slope in N^(-1/3) (:func:`_trend`)."""
    rows = []
    quantities = [q for q in values.columns if q not in ("study", "sample", "n_particles", "run")]
    for (sample, q), _ in values.melt(id_vars=["sample"], value_vars=quantities).groupby(["sample", "variable"]):
        g = values[values["sample"] == sample]
        if not np.isfinite(g[q].to_numpy(float)).any():
            continue
        points, prev = [], None
        for n, gn in g.groupby("n_particles"):
            e = _estimate(gn[q])
            vals = gn[q].to_numpy(float)
            vals = vals[np.isfinite(vals)]
            lo, hi = e.ci()
            row = {"quantity": q, "sample": sample, "n_particles": int(n), "mean": e.mean, "ci_low": lo,
                   "ci_high": hi, "sd": float(vals.std(ddof=1)) if len(vals) > 1 else np.nan, "seeds": len(vals)}
            if prev is not None:
                d = difference(e, prev)
                dlo, dhi = d.ci()
                row.update(diff_from=int(points[-1][0]), diff=d.mean, diff_low=dlo, diff_high=dhi)
            rows.append(row)
            points.append((int(n), e))
            prev = e
        y_inf, slope = _trend(points)
        for r in rows:
            if r["quantity"] == q and r["sample"] == sample:
                r["extrapolated"], (r["extrapolated_low"], r["extrapolated_high"]) = y_inf.mean, y_inf.ci()
                r["slope"], (r["slope_low"], r["slope_high"]) = slope.mean, slope.ci()
    return pd.DataFrame(rows)


def scatter_table(values):
    """The per-seed scatter of claim 6's leanings at each N, per count:
    rows (count, leaning, n_particles, seeds, sd) and, against the next
    smaller N, the ratio sd(smaller)/sd(this), its 95 % interval from the
    F distribution (variance ratio, seeds - 1 degrees of freedom each) and
    sqrt(N / N_smaller), the ratio if the scatter falls as N^(-1/2)."""
    s1 = values[values["sample"] == "polyhedra"]
    rows = []
    for col in [c for c in s1.columns if c.split(":")[-1] in LEANINGS]:
        prev = None
        for n, g in s1.groupby("n_particles"):
            v = g[col].to_numpy(float)
            v = v[np.isfinite(v)]
            row = {"count": col.split(":")[0], "leaning": col.split(":")[-1][-2:], "n_particles": int(n),
                   "seeds": len(v), "sd": float(v.std(ddof=1)) if len(v) > 1 else np.nan}
            if prev is not None and len(v) > 1 and prev["seeds"] > 1 and row["sd"] > 0:
                r = prev["sd"] / row["sd"]
                d1, d2 = prev["seeds"] - 1, len(v) - 1
                row.update(ratio=r, ratio_low=r / np.sqrt(f_dist.ppf(0.975, d1, d2)),
                           ratio_high=r / np.sqrt(f_dist.ppf(0.025, d1, d2)),
                           expected=float(np.sqrt(n / prev["n_particles"])), from_n=prev["n_particles"])
            rows.append(row)
            prev = row
    return pd.DataFrame(rows)


def verdict_table(studies):
    """Per study (its N): the six claims' verdicts of its report's primary
    count, and claim 6's verdict with each count at its own parameter.
    Rows (n_particles, claim, count, verdict)."""
    rows = []
    for study in studies:
        runs = discover(study)
        summaries = run_summaries(runs)
        n = _n_particles(usable_runs(runs, "polyhedra")[0]) if usable_runs(runs, "polyhedra") else np.nan
        for c in evaluate(summaries):
            rows.append({"n_particles": n, "claim": c["id"], "count": "primary", "verdict": c["verdict"]})
        for count, frames in count_summaries(runs, summaries).items():
            rows.append({"n_particles": n, "claim": 6, "count": count, "verdict": claim6(frames)["verdict"]})
    return pd.DataFrame(rows)


def _label(q):
    if ":" in q:
        count, col = q.split(":")
        return f"{COUNT_QUANTITIES.get(col, col)} ({count})"
    return QUANTITIES.get(q, (None, q))[1]


def _f(x, d=3):
    return "–" if x is None or not np.isfinite(x) else f"{x:.{d}f}"


def size_markdown(table, scatter, verdicts):
    """The size front as markdown: the table of means per N, the
    differences and the extrapolation, the leanings' scatter and the
    verdicts per N."""
    ns = sorted(table["n_particles"].unique())
    out = ["| quantity | sample | " + " | ".join(f"N = {n}" for n in ns) + " | " +
           " | ".join(f"Δ {a}→{b}" for a, b in zip(ns, ns[1:])) + " | N → ∞ (fit in N^-1/3) |",
           "|---|---|" + "---|" * (2 * len(ns))]
    counts = sorted({q.split(":")[0] for q in table["quantity"] if ":" in q})
    order = list(QUANTITIES) + [f"{c}:{col}" for c in counts for col in COUNT_QUANTITIES]
    rank = {q: k for k, q in enumerate(order)}
    table = table.assign(_rank=table["quantity"].map(lambda q: rank.get(q, len(rank))),
                         _s=table["sample"].map({"polyhedra": 0, "spheres": 1}))
    for (_, _, sample, q), g in table.groupby(["_s", "_rank", "sample", "quantity"]):
        by_n = {int(r["n_particles"]): r for _, r in g.iterrows()}
        cells = [f"{_f(by_n[n]['mean'])} [{_f(by_n[n]['ci_low'])}, {_f(by_n[n]['ci_high'])}]" if n in by_n else "–"
                 for n in ns]
        diffs = []
        for a, b in zip(ns, ns[1:]):
            r = by_n.get(b)
            if r is not None and r.get("diff_from") == a and np.isfinite(r.get("diff", np.nan)):
                mark = "**" if (r["diff_low"] > 0 or r["diff_high"] < 0) else ""
                ci = f" [{r['diff_low']:+.3f}, {r['diff_high']:+.3f}]" if np.isfinite(r["diff_low"]) else ""
                diffs.append(f"{mark}{r['diff']:+.3f}{ci}{mark}")
            else:
                diffs.append("–")
        r0 = g.iloc[0]
        ext = (f"{_f(r0['extrapolated'])} [{_f(r0['extrapolated_low'])}, {_f(r0['extrapolated_high'])}]"
               if np.isfinite(r0.get("extrapolated", np.nan)) else "–")
        out.append(f"| {_label(q)} | {sample} | " + " | ".join(cells) + " | " + " | ".join(diffs) + f" | {ext} |")
    out += ["", "Bold: the interval of the difference excludes 0.", ""]
    if len(scatter):
        out += ["| count | leaning | N | seeds | sd over seeds | sd ratio to the smaller N [95 %] | "
                "expected if ∝ N^-1/2 |", "|---|---|---|---|---|---|---|"]
        for _, r in scatter.iterrows():
            ratio = (f"{r['ratio']:.2f} [{r['ratio_low']:.2f}, {r['ratio_high']:.2f}]"
                     if np.isfinite(r.get("ratio", np.nan)) else "–")
            exp = f"{r['expected']:.2f}" if np.isfinite(r.get("expected", np.nan)) else "–"
            out.append(f"| {r['count']} | {r['leaning']} | {int(r['n_particles'])} | {int(r['seeds'])} | "
                       f"{_f(r['sd'])} | {ratio} | {exp} |")
        out.append("")
    if len(verdicts):
        piv = verdicts.assign(key=verdicts["claim"].astype(str) + " (" + verdicts["count"] + ")")
        keys = list(dict.fromkeys(piv["key"]))
        out += ["| claim | " + " | ".join(f"N = {n}" for n in ns) + " |", "|---|" + "---|" * len(ns)]
        for k in keys:
            cells = []
            for n in ns:
                v = piv[(piv["key"] == k) & (piv["n_particles"] == n)]["verdict"]
                cells.append(v.iloc[0] if len(v) else "–")
            out.append(f"| {k} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


def write_size_front(studies, out):
    """Write the size front of the study folders ``studies`` (one per N)
    into ``out``: values.csv (one row per run), size.csv
    (:func:`size_table`), scatter.csv (:func:`scatter_table`),
    verdicts.csv (:func:`verdict_table`), size.md and size-front.png.
    Returns the path of size.md. Raises InputError (one line) for a folder
    without a usable study."""
    from ..plots import plot_size_front

    values = pd.concat([study_values(s) for s in studies], ignore_index=True)
    if values["n_particles"].nunique() < 2:
        raise InputError("the size front needs studies at two numbers of grains or more")
    os.makedirs(out, exist_ok=True)
    values.to_csv(os.path.join(out, "values.csv"), index=False)
    table = size_table(values)
    table.to_csv(os.path.join(out, "size.csv"), index=False)
    scatter = scatter_table(values)
    scatter.to_csv(os.path.join(out, "scatter.csv"), index=False)
    verdicts = verdict_table(studies)
    verdicts.to_csv(os.path.join(out, "verdicts.csv"), index=False)
    with open(REFERENCE) as fh:
        pub = json.load(fh)["results"]
    published = {("polyhedra", "q_over_p"): pub["q_over_p_plateau"].get("polyhedra"),
                 ("spheres", "q_over_p"): pub["q_over_p_plateau"].get("spheres")}
    for k in ("a", "a_l", "a_n", "a_t"):
        for s in SAMPLES:
            published[(s, k)] = pub.get(k, {}).get(s)
    for s in SAMPLES:
        published[(s, "z")] = pub["coordination_z"].get(s)
    published[("polyhedra", "ct_frac_triple")] = pub["contact_types_simple_double_triple"]["polyhedra"][2]
    plot_size_front(table, os.path.join(out, "size-front.png"), published=published)
    path = os.path.join(out, "size.md")
    with open(path, "w") as fh:
        fh.write(size_markdown(table, scatter, verdicts))
    return path
