"""Speed against error: the simulation front of a sweep, and the
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
import pandas as pd

from .report import REFERENCE, comparison_table
from ..angular import angular_functions, fit_harmonics
from ..errors import InputError, read_json_object
from ..fabric import anisotropies
from ..plots import plot_analysis_front, plot_front, plot_front_trends
from ..schema import DumpReader
from ..statistics import difference, Estimate, plateau_estimate, plateau_estimate as pe, steady_indices
from ..synthetic import harmonic_contacts

QUANTITIES = ("q_over_p", "a", "a_n", "a_t")

# The quantities of the study's comparison table (postproc.study.report.
# comparison_table), one value per run: column -> row name of that table.
# phi_iso, the solid fraction after compaction, comes from the dump.
COMPARISON = {
    "qp_plateau": "q/p plateau", "qp_peak": "q/p peak",
    "psi_peak_deg": "dilatancy angle at the peak (deg)",
    "a_al": "a + a_l", "an_at": "a_n + a_t",
    "a": "a", "a_l": "a_l", "a_n": "a_n", "a_t": "a_t", "sff": "(2/5)(a+a_l+a_n+a_t)",
    "z": "z (a pair counts once)", "frac_below_mean": "fraction of forces below the mean",
    "ct_simple": "proportion of simple contacts", "ct_double": "proportion of double contacts",
    "ct_triple": "proportion of triple contacts",
    "fr_simple": "mean f_n of simple contacts / mean", "fr_double": "mean f_n of double contacts / mean",
    "fr_triple": "mean f_n of triple contacts / mean",
}
FRONT_QUANTITIES = tuple(COMPARISON) + ("phi_iso",)
# The front's reference point: the fit's units (kappa_d / kappa and I / I_d),
# so that its two slopes are the two effects there. It is the point the front
# was measured around (the default preset of that time, kappa = 300,
# I = 2e-2), fixed here rather than read from the presets: moving the default
# must not change what the measured front says.
# A sweep around another point names it per sample in its plan
# (``front-plan.json``: "reference": {sample: [kappa_d, I_d]}).
FRONT_KAPPA = 300.0
FRONT_I = 2e-2


def reference_point(reference, sample, kappa_d=FRONT_KAPPA, inertial_d=FRONT_I):
    """(kappa_d, I_d) of one sample: ``reference[sample]`` when the mapping
    names it, else (kappa_d, inertial_d)."""
    if reference and sample in reference:
        k, i = reference[sample]
        return float(k), float(i)
    return float(kappa_d), float(inertial_d)


def _run_values(df, sample, reference):
    """{column: value} of one run's summary table: its comparison-table row
    values (each the run's steady plateau or value at the peak)."""

    rows = comparison_table({sample: [df.copy()]}, reference)     # copy: one consolidated block
    by_name = {name: est for name, smp, est, _ in rows if smp == sample}
    return {col: (float(by_name[name].mean) if by_name.get(name) is not None else np.nan)
            for col, name in COMPARISON.items()}


def collect_runs(folder):
    """DataFrame, one row per analysed run of the sweep folder: its
    parameters (kappa, inertial_number, n_particles, library, seed, safety), its cost
    (wall_seconds, steps, compaction_steps, shear_steps, contact_steps, and
    for the polyhedra kernel touch_steps, the exact touching contact-steps),
    the plateau of q/p, a, a_n, a_t with one-seed batch-means s.e., and every
    quantity of FRONT_QUANTITIES."""

    with open(REFERENCE) as fh:
        reference = json.load(fh)
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
        info = read_json_object(info_path, "run info file")
        df = pd.read_csv(summary, dtype={"snapshot": str})
        idx = steady_indices(df["eps_q"], df["stage"])
        shear0 = info.get("shear_start_step")
        row = {"sample": sample, "run": name.split("-", 1)[1] if "-" in name else name,
               "kappa": par.get("kappa"), "inertial_number": par.get("inertial_number"),
               "n_particles": par.get("n_particles"), "library": par.get("library", ""),
               "seed": par.get("seed"), "final_strain": par.get("final_strain"), "safety": par.get("safety"),
               "steps": info.get("steps"), "wall_seconds": info.get("wall_seconds"),
               "compaction_steps": shear0,
               "shear_steps": (info["steps"] - shear0) if shear0 is not None else np.nan,
               "compaction_wall_seconds": info.get("shear_start_wall_seconds"),
               "contact_steps": info.get("contact_steps"),
               "touch_steps": (info.get("kernel") or {}).get("touch_steps", np.nan),
               "n_steady": len(idx), "phi_iso": par.get("solid_fraction_isotropic", np.nan)}
        for q in QUANTITIES:
            e = plateau_estimate([df[q].to_numpy(float)[idx]])
            row[q] = e.mean
            row[q + "_se"] = e.se
        row.update(_run_values(df, sample, reference))
        rows.append(row)
    return pd.DataFrame(rows)


def add_errors(runs):
    """Add ``ref`` (bool), ``err_<q>`` and ``err_max`` columns, per sample:
    each run's |plateau - reference plateau| for q in QUANTITIES. The
    reference is the first run whose name starts with ``ref``, else the
    stiffest, slowest, largest run."""
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


POINT = ["sample", "kappa", "inertial_number", "n_particles", "library"]


def point_table(runs, quantities=FRONT_QUANTITIES):
    """One row per point (sample, kappa, I, N, library): ``n_seeds``, the
    mean over seeds of each quantity ``<q>`` with the 95 % Student's-t
    half-width ``<q>_ci`` (nan with one seed), and the medians of the cost
    columns (wall_seconds, steps, compaction_steps, shear_steps)."""

    rows = []
    for key, g in runs.groupby(POINT, sort=True):
        row = dict(zip(POINT, key))
        row["n_seeds"] = int(g["seed"].nunique()) if "seed" in g else len(g)
        for q in quantities:
            v = g[q].to_numpy(float) if q in g else np.array([])
            e = plateau_estimate([[x] for x in v])       # one value per seed: t over seeds
            lo, hi = e.ci()
            row[q], row[q + "_ci"] = e.mean, (hi - lo) / 2
        for c in ("wall_seconds", "steps", "compaction_steps", "shear_steps"):
            row[c] = float(np.nanmedian(g[c].to_numpy(float))) if c in g and g[c].notna().any() else np.nan
        rows.append(row)
    return pd.DataFrame(rows)


def fit_rigid_quasistatic(runs, q, kappa_d=FRONT_KAPPA, inertial_d=FRONT_I, alpha=1.0, beta=1.0):
    """Least-squares fit of one quantity over the runs of one sample at one
    size, with one offset per seed (the seeds are paired: the same seed at
    every point starts from the same grains and positions):

        X(kappa, I, seed) = X0 + A (kappa_d / kappa)^alpha + B (I / I_d)^beta + c_seed,
        sum c = 0.

    alpha = 1: effects of the contact deflection, delta/d ~ 1/kappa, on
    stresses (linear contact law; Agnolin & Roux 2007); alpha = 1/2: the
    jamming scaling of contact numbers, z - z_c ~ (delta/d)^(1/2) (O'Hern et
    al. 2003). beta = 1: the quasistatic limit of mu(I) = mu_0 + b I (GDR
    MiDi 2004, da Cruz et al. 2005); beta = 1/2 the empirical alternative
    (:func:`fit_table` picks the form the data fit best). X0 is the rigid,
    quasistatic limit kappa -> inf, I -> 0; A and B are the stiffness and the
    rate effects at the default (kappa_d, I_d), so the default's bias is
    A + B. Returns a dict with X0, A, B, bias = A + B, their standard errors
    (``se_<name>``), 95 % half-widths (``ci_<name>``), the residual
    standard deviation ``resid_sd``, ``dof`` and ``n`` runs; nans when the
    fit has no degrees of freedom left.
    """
    g = runs[np.isfinite(runs[q].to_numpy(float))]
    y = g[q].to_numpy(float)
    x1 = (kappa_d / g["kappa"].to_numpy(float)) ** alpha
    x2 = (g["inertial_number"].to_numpy(float) / inertial_d) ** beta
    seeds = sorted(g["seed"].unique()) if "seed" in g else [None]
    cols = [np.ones_like(y), x1, x2]
    sv = g["seed"].to_numpy() if "seed" in g else np.zeros(len(y))
    for s in seeds[1:]:                        # sum-to-zero seed offsets
        cols.append((sv == s).astype(float) - (sv == seeds[0]).astype(float))
    X = np.column_stack(cols)
    n, k = X.shape
    out = {"n": n, "dof": n - k, "alpha": alpha, "beta": beta}
    names = ("X0", "A", "B")
    if n <= k or np.linalg.matrix_rank(X) < k:
        out.update({nm: np.nan for nm in names + ("bias", "resid_sd")})
        out.update({f"{p}_{nm}": np.nan for p in ("se", "ci") for nm in names + ("bias",)})
        return out
    coef, *_ = np.linalg.lstsq(X, y, rcond=None)
    resid = y - X @ coef
    s2 = float(resid @ resid) / (n - k)
    cov = s2 * np.linalg.inv(X.T @ X)
    # the bias A + B as the combination (0, 1, 1, 0...) of the coefficients
    combos = {"X0": [0], "A": [1], "B": [2], "bias": [1, 2]}
    for nm, idx in combos.items():
        e = Estimate(float(coef[idx].sum()), float(np.sqrt(cov[np.ix_(idx, idx)].sum())), n - k, n, "fit")
        lo, hi = e.ci()
        out[nm], out["se_" + nm], out["ci_" + nm] = e.mean, e.se, (hi - lo) / 2
    out["resid_sd"] = float(np.sqrt(s2))
    return out


def monotone(points, q, axis, fixed):
    """Whether the point means of ``q`` change in one direction along one
    sweep. axis "kappa" (at I = fixed) or "inertial_number" (at kappa =
    fixed); points of one sample and size. Returns (+1 increasing, -1
    decreasing, 0 not monotone or fewer than 3 points) in the axis's own
    order (kappa increasing, I increasing)."""
    other = "inertial_number" if axis == "kappa" else "kappa"
    g = points[np.isclose(points[other].to_numpy(float), fixed)].sort_values(axis)
    v = g[q].to_numpy(float)
    v = v[np.isfinite(v)]
    if len(v) < 3:
        return 0
    d = np.diff(v)
    return 1 if np.all(d > 0) else (-1 if np.all(d < 0) else 0)


def size_effect(runs, q, n_small, n_large, kappa_d=FRONT_KAPPA, inertial_d=FRONT_I):
    """Mean over seeds of q at (kappa_d, I_d) for N = n_large minus N =
    n_small (independent samples: Welch's t). Returns (difference, 95 %
    half-width) or (nan, nan)."""

    at = runs[np.isclose(runs["kappa"], kappa_d) & np.isclose(runs["inertial_number"], inertial_d)]
    a = at.loc[at["n_particles"] == n_large, q].to_numpy(float)
    b = at.loc[at["n_particles"] == n_small, q].to_numpy(float)
    a, b = a[np.isfinite(a)], b[np.isfinite(b)]
    if len(a) < 2 or len(b) < 2:
        return np.nan, np.nan
    e = difference(pe([[v] for v in a]), pe([[v] for v in b]))
    lo, hi = e.ci()
    return float(e.mean), float((hi - lo) / 2)


FORMS = ((1.0, 1.0), (0.5, 1.0), (1.0, 0.5), (0.5, 0.5))


def fit_table(runs, quantities=FRONT_QUANTITIES, kappa_d=FRONT_KAPPA, inertial_d=FRONT_I, forms=FORMS,
              reference=None):
    """Per sample (at its most common N and library) and quantity: the fit of
    :func:`fit_rigid_quasistatic` in the form (alpha, beta) of ``forms`` with
    the smallest residual (all forms have the same number of parameters),
    the range of X0 over all forms (``X0_min``, ``X0_max``: how much the
    extrapolation depends on the form), whether the kappa and I sweeps are
    monotone, the seed-to-seed standard deviation at the default point
    (``seed_sd``), the size effect (largest N minus the base N at the
    default) and the prediction error of the corner points (stiff and slow
    at once), which tests that the two effects add. The default point is
    (kappa_d, inertial_d), or per sample ``reference`` ({sample: (kappa_d,
    I_d)}); each row names it (columns ``kappa_d``, ``inertial_d``)."""

    rows = []
    k_all, i_all = kappa_d, inertial_d
    for s, gs in runs.groupby("sample"):
        kappa_d, inertial_d = reference_point(reference, s, k_all, i_all)
        base_n = gs["n_particles"].mode().iloc[0]
        base_lib = gs["library"].mode().iloc[0]
        g = gs[(gs["n_particles"] == base_n) & (gs["library"] == base_lib)]
        pts = point_table(g, quantities)
        sizes = sorted(set(gs["n_particles"]) - {base_n})
        for q in quantities:
            if q not in g or not np.isfinite(g[q].to_numpy(float)).any():
                continue
            fits = [fit_rigid_quasistatic(g, q, kappa_d, inertial_d, a, b) for a, b in forms]
            ok = [f for f in fits if np.isfinite(f["resid_sd"])]
            f = min(ok, key=lambda f: f["resid_sd"]) if ok else fits[0]
            at = g[np.isclose(g["kappa"], kappa_d) & np.isclose(g["inertial_number"], inertial_d)][q]
            corner = g[~np.isclose(g["kappa"], kappa_d) & ~np.isclose(g["inertial_number"], inertial_d)]
            row = {"sample": s, "quantity": q, "n_particles": int(base_n), "kappa_d": kappa_d,
                   "inertial_d": inertial_d, **f,
                   "X0_min": min((x["X0"] for x in ok), default=np.nan),
                   "X0_max": max((x["X0"] for x in ok), default=np.nan),
                   "monotone_kappa": monotone(pts, q, "kappa", inertial_d),
                   "monotone_I": monotone(pts, q, "inertial_number", kappa_d),
                   "default_mean": float(at.mean()) if len(at) else np.nan,
                   "seed_sd": float(at.std(ddof=1)) if at.notna().sum() > 1 else np.nan}
            if len(corner) and np.isfinite(f["X0"]):
                pred = (f["X0"] + f["A"] * (kappa_d / corner["kappa"].to_numpy(float)) ** f["alpha"]
                        + f["B"] * (corner["inertial_number"].to_numpy(float) / inertial_d) ** f["beta"])
                c = corner[q].to_numpy(float)
                # seed offsets cancel in the mean over the corner's seeds
                row["corner_residual"] = float(np.nanmean(c - pred))
            else:
                row["corner_residual"] = np.nan
            if sizes:
                row["size_n"] = int(sizes[-1])
                row["size_effect"], row["size_effect_ci"] = size_effect(gs, q, base_n, sizes[-1],
                                                                        kappa_d, inertial_d)
            rows.append(row)
    return pd.DataFrame(rows)


def cost_model(runs, kappa_d=FRONT_KAPPA, inertial_d=FRONT_I, strain=0.3, reference=None):
    """Per sample, the cost constants measured on the sweep's runs, as the
    medians over runs:

    * ``compaction_steps_ref``: steps to the isotropic state, scaled to
      kappa_d (the time step goes as kappa^-1/2: steps x sqrt(kappa_d/kappa));
    * ``shear_steps_ref``: shear steps to eps_1 = ``strain`` at (kappa_d,
      I_d): shear steps x sqrt(kappa_d/kappa) x (I/I_d) x strain/final_strain
      (the strain rate goes as I);
    * ``contacts_per_grain``: touching contacts per grain and step
      (kernel touch_steps / steps / N; else the logged contact-steps);
    * ``us_per_contact_step``: wall time per touching contact-step (µs), for
      the run's own threads;
    * ``us_per_grain_step``: wall time per grain-step (µs);

    with the relative spread (``*_rsd``, sd / median) of each scaled step
    count, which says how well the kappa^-1/2 and I^-1 laws hold.
    ``reference`` ({sample: (kappa_d, I_d)}) sets the point per sample.
    Returns a DataFrame, one row per sample and particle count, with its
    ``kappa_d`` and ``inertial_d``.
    """

    rows = []
    k_all, i_all = kappa_d, inertial_d
    for (s, n), g in runs.groupby(["sample", "n_particles"]):
        kappa_d, inertial_d = reference_point(reference, s, k_all, i_all)
        scale = np.sqrt(kappa_d / g["kappa"].to_numpy(float))
        comp = g["compaction_steps"].to_numpy(float) * scale
        shear = (g["shear_steps"].to_numpy(float) * scale * g["inertial_number"].to_numpy(float)
                 / inertial_d * strain / g["final_strain"].to_numpy(float))
        touch = g["touch_steps"].to_numpy(float)
        touch = np.where(np.isfinite(touch), touch, g["contact_steps"].to_numpy(float))
        steps = g["steps"].to_numpy(float)
        wall = g["wall_seconds"].to_numpy(float)
        row = {"sample": s, "n_particles": int(n), "runs": len(g), "kappa_d": kappa_d, "inertial_d": inertial_d}
        for name, v in (("compaction_steps_ref", comp), ("shear_steps_ref", shear)):
            v = v[np.isfinite(v)]
            row[name] = float(np.median(v)) if len(v) else np.nan
            row[name + "_rsd"] = float(v.std(ddof=1) / np.median(v)) if len(v) > 1 else np.nan
        row["contacts_per_grain"] = float(np.nanmedian(touch / steps / n))
        row["us_per_contact_step"] = float(np.nanmedian(wall / touch * 1e6))
        row["us_per_grain_step"] = float(np.nanmedian(wall / steps / n * 1e6))
        rows.append(row)
    return pd.DataFrame(rows)


def _f(x, d=3):
    return f"{x:.{d}f}" if np.isfinite(x) else "n/a"


def front_markdown(fits, cost):
    """The front as markdown: per sample, the extrapolated limit X0 (95 %
    interval, and its range over the fit forms), the default's bias A + B
    with its interval, the stiffness and rate parts, the form, whether
    both sweeps are monotone, the corner's residual and the seed-to-seed
    sd at the default point; then the cost model."""
    out = []
    for s, g in fits.groupby("sample"):
        at = (f"; default κ = {g['kappa_d'].iloc[0]:g}, I = {g['inertial_d'].iloc[0]:g}"
              if "kappa_d" in g else "")
        out += [f"### {s} ({int(g['n_particles'].iloc[0])} particles{at})", "",
                "| quantity | default (mean) | κ→∞, I→0 | range over forms | bias of the default | "
                "κ part A | I part B | form (α, β) | monotone κ / I | corner residual | seed sd |",
                "|---|---|---|---|---|---|---|---|---|---|---|"]
        for _, r in g.iterrows():
            mono = "/".join({1: "↑", -1: "↓", 0: "no"}[int(m)] for m in (r["monotone_kappa"], r["monotone_I"]))
            out.append(f"| {r['quantity']} | {_f(r['default_mean'])} | {_f(r['X0'])} ± {_f(r['ci_X0'])} | "
                       f"{_f(r['X0_min'])}–{_f(r['X0_max'])} | {_f(r['bias'])} ± {_f(r['ci_bias'])} | "
                       f"{_f(r['A'])} ± {_f(r['ci_A'])} | {_f(r['B'])} ± {_f(r['ci_B'])} | "
                       f"({r['alpha']:g}, {r['beta']:g}) | {mono} | {_f(r['corner_residual'])} | "
                       f"{_f(r['seed_sd'])} |")
        out.append("")
    out += ["### cost (steps scaled to the sample's default κ, I)", "",
            "| sample | N | runs | default κ, I | compaction steps | shear steps to ε1 = 0.3 | "
            "contacts per grain | µs per contact-step | µs per grain-step |", "|---|---|---|---|---|---|---|---|---|"]
    for _, r in cost.iterrows():
        kd = f"{r['kappa_d']:g}, {r['inertial_d']:g}" if "kappa_d" in r else "n/a"
        out.append(f"| {r['sample']} | {int(r['n_particles'])} | {int(r['runs'])} | {kd} | "
                   f"{r['compaction_steps_ref']:.0f} (± {100 * r['compaction_steps_ref_rsd']:.0f} %) | "
                   f"{r['shear_steps_ref']:.0f} (± {100 * r['shear_steps_ref_rsd']:.0f} %) | "
                   f"{r['contacts_per_grain']:.2f} | {r['us_per_contact_step']:.2f} | {r['us_per_grain_step']:.2f} |")
    return "\n".join(out) + "\n"


def write_front(folder, reference=None):
    """Write into the sweep folder: ``front.csv`` (one row per run),
    ``front-points.csv`` (means over seeds per point), ``front-fit.csv``
    (the extrapolation and the default's bias per quantity),
    ``front-cost.csv`` (the cost model), ``front.md`` (the fit and the cost
    as markdown tables), ``front.png`` and ``front-trends.png``. The default
    point of each sample (the fit's units) is ``reference`` ({sample:
    (kappa_d, I_d)}), else the plan's (``front-plan.json``, key
    "reference"), else (FRONT_KAPPA, FRONT_I). Returns the run table."""

    if reference is None:
        plan = os.path.join(folder, "front-plan.json")
        if os.path.exists(plan):
            try:
                with open(plan) as fh:
                    reference = json.load(fh).get("reference")
            except (OSError, ValueError) as exc:
                raise InputError(f"{plan}: not a readable plan ({exc})") from None
    runs = collect_runs(folder)
    if runs.empty:
        raise InputError(f"{folder}: no analysed runs to build a front from")
    runs = add_errors(runs)
    runs["pareto"] = False
    for s, g in runs.groupby("sample"):
        runs.loc[g.index, "pareto"] = pareto(g["wall_seconds"], g["err_max"])
    runs.to_csv(os.path.join(folder, "front.csv"), index=False)
    points = point_table(runs)
    points.to_csv(os.path.join(folder, "front-points.csv"), index=False)
    fits = fit_table(runs, reference=reference)
    fits.to_csv(os.path.join(folder, "front-fit.csv"), index=False)
    cost = cost_model(runs, reference=reference)
    cost.to_csv(os.path.join(folder, "front-cost.csv"), index=False)
    with open(os.path.join(folder, "front.md"), "w") as fh:
        fh.write(front_markdown(fits, cost))
    plot_front(runs, os.path.join(folder, "front.png"))
    plot_front_trends(points, fits, os.path.join(folder, "front-trends.png"), FRONT_KAPPA, FRONT_I)
    return runs


def analysis_front(sizes=(100, 300, 1000, 3000, 10000), bins=(6, 9, 18, 36), reps=40,
                   truth=(0.3, 0.1, 0.5, 0.2), seed=0):
    """RMS error against the truth and time per set of the tensor estimators
    and the harmonic fits (per bin count), for each sample size.

    Returns a DataFrame with columns estimator ("tensors" or "fit-<bins>"),
    n (contacts), seconds (mean per set), rms_<q> for q in a, a_l, a_n, a_t,
    and rms_max.
    """

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


#: the columns of the analysis front that ``postproc investigate analysis-front`` prints
ANALYSIS_FRONT_COLUMNS = ("estimator", "n", "seconds", "rms_a", "rms_a_l", "rms_a_n", "rms_a_t", "rms_max",
                          "bias_a_n", "bias_a_t")


def write_analysis_front(out="runs/front-analysis", reps=40):
    """The analysis front (:func:`analysis_front`, its default sizes, bins
    and truth (a, a_l, a_n, a_t) = (0.3, 0.1, 0.5, 0.2)) written to a
    folder: ``analysis_front.csv`` (every column) and ``analysis_front.png``
    (:func:`postproc.plots.plot_analysis_front`). ``make front`` runs it as
    ``postproc investigate analysis-front``.

    Parameters
    ----------
    out : str
        Output folder (made if missing).
    reps : int
        Synthetic sets per sample size.

    Returns
    -------
    pandas.DataFrame
        The table of :func:`analysis_front`: per estimator and number of
        contacts n, the seconds per set and the RMS error and bias of each
        anisotropy (dimensionless).
    """
    os.makedirs(out, exist_ok=True)
    table = analysis_front(reps=reps)
    table.to_csv(os.path.join(out, "analysis_front.csv"), index=False)
    plot_analysis_front(table, os.path.join(out, "analysis_front.png"))
    return table
