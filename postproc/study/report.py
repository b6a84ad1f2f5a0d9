"""The study report: ``postproc report STUDY_DIR`` → ``STUDY_DIR/report/``.

Reads what the study wrote (no simulation here): for each sample the runs
listed in ``STUDY_DIR/manifest.json`` (written by ``yade_scripts.campaign.study``:
label, dump, analysis folder and status of every run), or, without a
manifest, ``STUDY_DIR/<sample>/run.h5`` and its ``analysis/``. Writes

* ``report.md`` and ``report.html`` (rendered from it, figures embedded by
  relative links);
* the paper's figures for S1 and S2 side by side (``fig_*.png``), the
  contact-type figures of S1, the force networks of both samples in a slab, coloured by
  normal force;
* ``comparison.csv`` (our values beside the published ones) and
  ``claims.csv`` (the six claims, their numbers and verdicts).

A failed or missing run is listed in the report and left out of the
numbers; the rest of the report still builds. A partial run (status
"partial": failed after the start of the steady state, see
``yade_scripts.campaign.study.partial_progress``) is marked PARTIAL with the strain it
reached, and its steady snapshots are used.
"""
from __future__ import annotations

import datetime
import json
import os
import shutil

import numpy as np
import pandas as pd

from .claims import BAND, BAND_STABLE, band_test, claim6, evaluate, plateau
from .dilatancy import peak_summary
from .manifest import read_manifest
from .. import plots
from ..analysis import analyze_snapshot, group_labels_of
from ..angular import angular_functions
from ..classify import classifier_for, snapshot_classes
from ..contactset import resolve
from ..contacttypes import GROUP_OF
from ..coordination import force_bearing
from ..errors import InputError, read_json_object
from ..schema import DumpReader
from ..slab import slab
from ..statistics import plateau_estimate

SAMPLES = ("polyhedra", "spheres")
LABEL = {"polyhedra": "S1 polyhedra", "spheres": "S2 spheres"}
HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.path.join(os.path.dirname(os.path.dirname(HERE)), "reference_data", "paper_values.json")


def discover(study):
    """{sample: [run dict]} with keys label, dump, analysis, status
    ("ok" or the reason it failed), info (run.info.json path or None)."""
    path = os.path.join(study, "manifest.json")
    if os.path.exists(path):
        runs = read_manifest(path)
        for sample in runs:
            for r in runs[sample]:
                for k in ("dump", "analysis", "info"):
                    if r.get(k) and not os.path.isabs(r[k]):
                        r[k] = os.path.join(study, r[k])
                r["counts"] = {c: f if os.path.isabs(f) else os.path.join(study, f)
                               for c, f in (r.get("counts") or {}).items()}
        return runs
    runs = {}
    for s in SAMPLES:
        folder = os.path.join(study, s)
        if not os.path.isdir(folder):
            continue
        ok = os.path.exists(os.path.join(folder, "analysis", "summary.csv"))
        runs[s] = [{"label": "seed 1", "dump": os.path.join(folder, "run.h5"),
                    "analysis": os.path.join(folder, "analysis"),
                    "info": os.path.join(folder, "run.info.json"),
                    "status": "ok" if ok else "no analysis (run failed or unfinished)"}]
    return runs


def usable_runs(runs, sample):
    """The runs of ``sample`` whose numbers are used: complete ("ok") first,
    then partial ones (failed after the start of the steady state)."""
    rs = [r for r in runs.get(sample, []) if r.get("status") in ("ok", "partial")]
    return sorted(rs, key=lambda r: r.get("status") != "ok")


def figure_runs(runs, sample):
    """:func:`usable_runs` of ``sample`` with those whose dump is on this
    host first (a run taken from an archive of analysed runs,
    :mod:`yade_scripts.campaign.archive`, has none): the runs the figures that read
    a dump, or copy an analysis's figures, start from."""
    return sorted(usable_runs(runs, sample), key=lambda r: not os.path.exists(r.get("dump") or ""))


def run_summaries(runs):
    """{sample: [summary DataFrame per usable run]}. The shear snapshots of a
    partial run before the start of the steady state of a complete run
    (eps_1 < partial["steady_from_eps_1"]) are relabelled stage "transient",
    so that its steady window is the complete runs' one, not half of the
    strain it happened to reach."""

    out = {}
    for s in runs:
        frames = []
        for r in usable_runs(runs, s):
            p = os.path.join(r["analysis"], "summary.csv") if r.get("analysis") else None
            if p and os.path.exists(p):
                df = pd.read_csv(p, dtype={"snapshot": str}).copy()
                part = r.get("partial")
                if r.get("status") == "partial" and part and "eps_1" in df and "stage" in df:
                    early = (df["stage"] == "shear") & (df["eps_1"] < part["steady_from_eps_1"] - 1e-9)
                    df.loc[early, "stage"] = "transient"
                frames.append(df)
        out[s] = frames
    return out


def count_summaries(runs, summaries):
    """{count: [summary DataFrame per usable S1 run]}: the primary
    analysis under its own count (its ``ct_method``), then each other count
    the study analysed (:mod:`postproc.study.counts`), for the runs that
    have it. Partial runs' early shear rows are relabelled as in
    :func:`run_summaries`."""
    s1 = summaries.get("polyhedra", [])
    out = {}
    if s1 and "ct_method" in s1[0]:
        out[str(s1[0]["ct_method"].iloc[0])] = s1
    for r in usable_runs(runs, "polyhedra"):
        for count, folder in (r.get("counts") or {}).items():
            p = os.path.join(folder, "summary.csv")
            if count in out and out[count] is s1 or not os.path.exists(p):
                continue
            other = run_summaries({"polyhedra": [{**r, "analysis": folder, "counts": {}}]})["polyhedra"]
            out.setdefault(count, []).extend(other)
    return out


def claim6_rows(counts):
    """Claim 6 per count and per band: a list of dicts (count, seeds,
    factor of the count's parameter, verdict, VF and EE leanings,
    their band-test shifts and words, numbers), from
    :func:`postproc.study.claims.claim6` and :func:`~postproc.study.claims.band_test`."""
    rows = []
    for count, frames in counts.items():
        band = {b["tag"]: b for b in band_test(frames)}
        for tag in ("lo", "", "hi"):
            c6, b = claim6(frames, tag), band[tag]
            rows.append({"count": count, "seeds": len(frames), "factor": BAND.get(tag, 1.0),
                         "verdict": c6["verdict"], "VF": b["VF"].text(3), "EE": b["EE"].text(3),
                         "VF_shift": b.get("VF_shift").text(3) + " " + b["VF_word"] if tag else "",
                         "EE_shift": b.get("EE_shift").text(3) + " " + b["EE_word"] if tag else "",
                         "numbers": c6["numbers"]})
    return rows


def comparison_table(summaries, reference):
    """Rows (quantity, sample, ours (Estimate), published value or None)."""
    res = reference["results"]
    rows = []

    def add(name, sample, col, pub, combine=None):
        frames = summaries.get(sample, [])
        if combine:
            frames = [df.assign(**{col: combine(df)}) for df in frames]
        rows.append((name, sample, plateau(frames, col) if frames else None, pub))

    def add_peak(name, sample, item, pub):
        """A per-run value at the peak of q/p, one value per seed."""
        vals = [peak_summary(df)[item] for df in summaries.get(sample, [])]
        rows.append((name, sample, plateau_estimate([[v] for v in vals]) if vals else None, pub))

    for s in SAMPLES:
        add("q/p plateau", s, "q_over_p", res["q_over_p_plateau"].get(s))
        add_peak("q/p peak", s, 0, None)
        add_peak("dilatancy angle at the peak (deg)", s, 2, res.get("dilatancy_angle_at_peak_deg", {}).get(s))
        add("a + a_l", s, "a_al", res["a_plus_a_l"].get(s), lambda d: d["a"] + d["a_l"])
        add("a_n + a_t", s, "an_at", res["a_n_plus_a_t"].get(s), lambda d: d["a_n"] + d["a_t"])
        for k in ("a", "a_l", "a_n", "a_t"):
            add(k, s, k, res.get(k, {}).get(s))
        add("(2/5)(a+a_l+a_n+a_t)", s, "sff", res["sff_vs_q_over_p"].get(s, [None])[0])
        add("z (a pair counts once)", s, "z", res["coordination_z"].get(s))
        add("fraction of forces below the mean", s, "frac_below_mean",
            res["fraction_forces_below_mean"].get(s))
    types = res["contact_types_simple_double_triple"]["polyhedra"]
    ratios = res["mean_normal_force_by_type_relative"]["polyhedra"]
    for g, pub, rpub in zip(("simple", "double", "triple"), types,
                            (ratios["simple"], ratios["double"], ratios["triple"])):
        add(f"proportion of {g} contacts", "polyhedra", f"ct_frac_{g}", pub)
        add(f"mean f_n of {g} contacts / mean", "polyhedra", f"ct_fratio_{g}", rpub)
    return rows


def _read_listed(path, what, problems):
    """The JSON object in ``path``, or None with the reason appended to
    ``problems`` when it cannot be read (the report goes on without it)."""
    try:
        return read_json_object(path, what)
    except InputError as exc:
        problems.append(str(exc))
        return None


def _lines_or_problem(make, problems, what):
    """``make()``, the lines of a report section built from files of the
    study's own (run info, schedule); [] with ``what`` and the error
    appended to ``problems`` when the files are not of the shape the section
    reads (the report goes on without it)."""
    try:
        return make()
    except (AttributeError, KeyError, TypeError, ValueError) as exc:
        problems.append(f"{what} ({exc.__class__.__name__}: {exc})")
        return []


def _run_infos(runs, problems):
    """[(sample, run label, its run.info.json as a dict)] of the runs that
    wrote one; an unreadable one is named in ``problems``."""
    out = []
    for s, rs in runs.items():
        for r in rs:
            info = r.get("info")
            if info and os.path.exists(info):
                d = _read_listed(info, "run info file", problems)
                if d is not None:
                    out.append((s, r["label"], d))
    return out


def _cost_rows(infos):
    rows = []
    for s, label, d in infos:
        eng = sum(d.get("engine_seconds", {}).values())
        cs = d.get("contact_steps") or 0
        rows.append((LABEL.get(s, s), label, d.get("steps"), d.get("shear_start_step"),
                     d.get("wall_seconds"), 1e6 * eng / cs if cs else np.nan,
                     d.get("solid_fraction_isotropic")))
    return rows


def host_lines(infos):
    """Lines naming the hosts the runs ran on (the ``host`` of each
    run.info.json, :mod:`yade_scripts.runs.host`), one per distinct host with
    the runs it ran; [] when no run recorded one. A run repeats step for
    step only on hosts whose CPUs make glibc's maths library pick the same
    code (docs/scenes.md, "Preparation"), so this says which per-seed
    numbers a rerun can match."""
    hosts = {}
    for s, label, d in infos:
        h = d.get("host")
        if not h:
            continue
        key = (h.get("cpu") or "unknown CPU", "/".join(h.get("cpu_flags") or []) or "no vector flags read",
               h.get("libc") or "unknown libc", h.get("numpy") or "?")
        hosts.setdefault(key, []).append(f"{LABEL.get(s, s)} {label}")
    return [f"Host: {cpu}, {flags}, {libc}, numpy {npv} in YADE's Python ({', '.join(names)})."
            for (cpu, flags, libc, npv), names in hosts.items()]


def _schedule_lines(study, problems):
    """Lines on the schedule of the study's runs (``schedule.json``,
    :mod:`yade_scripts.launch.pool`): makespan, busy and idle core-time; an
    unreadable schedule is named in ``problems``."""
    path = os.path.join(study, "schedule.json")
    if not os.path.exists(path):
        return []
    s = _read_listed(path, "schedule", problems)
    m = (s or {}).get("summary", {})
    if not isinstance(m, dict):
        problems.append(f"{path}: the schedule's summary is not an object")
        return []
    if not m.get("makespan_s"):
        return []
    return _lines_or_problem(lambda: _schedule_line(m, s.get("attempts", [])), problems,
                             f"{path}: not a schedule of the pool's shape")


def _schedule_line(m, att):
    """The schedule's lines from its summary ``m`` and its attempts ``att``."""
    runs = [a for a in att if a.get("kind") != "after"]
    after = [a for a in att if a.get("kind") == "after"]
    widened = sum(1 for a in runs if a.get("widening"))
    return ["", f"Schedule (`schedule.json`): {len(runs)} attempt(s) of runs"
                + (f" and {len(after)} analyses of finished runs on free cores "
                   f"({sum(a['end'] - a['start'] for a in after) / 60:.1f} core-min)" if after else "")
                + f" on {m['cores']} cores in "
                f"{m['makespan_s'] / 60:.1f} min; busy {m['busy_core_s'] / 60:.1f} core-min, idle "
                f"{m['idle_core_s'] / 60:.1f} core-min ({100 * m['idle_share']:.1f} %); "
                f"{widened} run(s) stopped to resume on more threads."]


def _polar_data(run, target=0.3):
    """(af, fits, caption) at the snapshot nearest eps_q = target (or the
    last one) of a run's dump."""

    df = pd.read_csv(os.path.join(run["analysis"], "summary.csv"), dtype={"snapshot": str})
    eq = df["eps_q"].to_numpy(float)
    k = int(np.nanargmin(np.abs(eq - target))) if np.isfinite(eq).any() else len(df) - 1
    if np.nanmax(eq) < target:
        k = len(df) - 1
    name = str(df["snapshot"].iloc[k]).zfill(6)
    with DumpReader(run["dump"]) as reader:
        i = reader.names.index(name) if name in reader.names else len(reader) - 1
        snap = reader.read(i)
    res = analyze_snapshot(snap, errors=False)
    return res.angular, res.fits, f"snapshot {snap.name}, eps_q = {eq[k]:.3f}"


def group_branch_polar(run, target=0.3, nbins=9):
    """({group: AngularFunctions}, caption): the branch-vector densities
    P_Omega(theta) of the simple and triple contacts (force-bearing
    polyhedra pairs, default contact types) at the snapshot nearest
    eps_q = ``target`` (or the last one) of a run's dump: the paper's
    claim-6 figure. theta from the compression axis (z)."""

    df = pd.read_csv(os.path.join(run["analysis"], "summary.csv"), dtype={"snapshot": str})
    eq = df["eps_q"].to_numpy(float)
    k = len(df) - 1
    if np.isfinite(eq).any() and np.nanmax(eq) >= target:
        k = int(np.nanargmin(np.abs(eq - target)))
    name = str(df["snapshot"].iloc[k]).zfill(6)
    with DumpReader(run["dump"]) as reader:
        shapes = reader.shapes()
        snap = reader.read(reader.names.index(name) if name in reader.names else len(reader) - 1)
    classifier = _run_classifier(run, shapes)
    if classifier is None:
        raise ValueError("the dump has no polyhedra shapes")
    groups = group_labels_of(classifier.classify(snap, variants=False).labels)
    cs = resolve(snap)
    sel = cs.pp & force_bearing(cs.force)
    out = {}
    for g in ("simple", "triple"):
        m = sel & (groups == g)
        if m.sum() >= 2:
            out[g] = angular_functions(cs.arm[m], cs.force[m], 2, nbins)
    if not out:
        raise ValueError("no simple or triple contacts")
    counts = ", ".join(f"{g} {int(a.count.sum())}" for g, a in out.items())
    return out, f"snapshot {snap.name}, eps_q = {eq[k]:.3f} ({counts} contacts)"


def _run_classifier(run, shapes):
    """The contact-type classifier the run's analysis used, as recorded in
    its summary.csv (ct_method, ct_threshold, ct_theta_deg), so that the
    report's figures classify with the same criterion as its numbers; the
    defaults when the summary records none."""

    p = os.path.join(run["analysis"], "summary.csv") if run.get("analysis") else None
    if p is None or not os.path.exists(p):
        return classifier_for(shapes)
    row = pd.read_csv(p, nrows=1)
    if "ct_method" not in row or not len(row):
        return classifier_for(shapes)
    method = str(row["ct_method"].iloc[0])
    threshold = float(row["ct_threshold"].iloc[0])
    theta = float(row["ct_theta_deg"].iloc[0])
    if method == "points":
        return classifier_for(shapes, "points", theta_deg=theta, tolerance=threshold)
    if method == "footprint":
        return classifier_for(shapes, "footprint", threshold=threshold, theta_deg=theta)
    return classifier_for(shapes, method, theta_deg=theta)


def _slab_snapshots(runs):
    """{sample: (run, snapshot name, eps_q)}: for the first usable run of each
    sample, the snapshot nearest the largest strain both samples reached
    (from the run's summary.csv; the last snapshot without one)."""

    chosen, eq = {}, {}
    for s in SAMPLES:
        ok = figure_runs(runs, s)
        if not ok:
            continue
        p = os.path.join(ok[0]["analysis"], "summary.csv") if ok[0].get("analysis") else None
        df = pd.read_csv(p, dtype={"snapshot": str}) if p and os.path.exists(p) else None
        chosen[s], eq[s] = ok[0], df
    known = [df["eps_q"].max() for df in eq.values() if df is not None and len(df)]
    target = min(known) if known else None
    out = {}
    for s, run in chosen.items():
        df = eq[s]
        if df is None or not len(df) or target is None:
            out[s] = (run, None, float("nan"))
        else:
            k = int(np.argmin(np.abs(df["eps_q"].to_numpy() - target)))
            out[s] = (run, str(df["snapshot"].iloc[k]), float(df["eps_q"].iloc[k]))
    return out


def _slab_of(run, name):
    """(slab dict, snapshot name) of a run's snapshot (the last when name is
    None), contacts labelled by the group (simple, double, triple) of the
    analysis's contact-type criterion."""

    with DumpReader(run["dump"]) as reader:
        shapes = reader.shapes()
        if name is not None and name not in reader.names:
            raise ValueError(f"{run['dump']}: no snapshot {name!r} (summary.csv and dump disagree)")
        snap = reader.read(len(reader) - 1 if name is None else reader.names.index(name))
    labels = None
    if shapes is not None:

        labels = np.array([GROUP_OF.get(str(x), str(x)) for x in snapshot_classes(snap, _run_classifier(run, shapes))])
    return slab(snap, shapes, labels=labels), snap.name


def _slab_pictures(picked, colour, path):

    panels = []
    for s, (run, name, eq) in picked.items():
        sl, snap_name = _slab_of(run, name)
        strain = f"εq = {eq:.3f}" if np.isfinite(eq) else "last snapshot"
        panels.append((f"{LABEL[s]}, snapshot {snap_name}, {strain}", sl))
    plots.plot_slabs(panels, path, colour=colour)


#: the figures of the report (:func:`build_report`), removed when it is written without them
REPORT_FIGURES = ("fig_qp.png", "fig_anisotropies.png", "fig_sff.png", "fig_polar.png", "fig_types_polar.png",
                  "s1_contact_types.png", "s1_footprint.png", "s1_force_pdf.png", "s1_networks.png",
                  "packing_slab.png", "s1_slab_types.png", "library_descriptors.png")


def _report_figures(out, runs, summaries, pub, problems):
    """Draw the report's figures into ``out`` (those of
    :data:`REPORT_FIGURES` the study's runs allow) and copy S1's analysis
    figures there; returns [(file name, caption)] of those written. A
    figure that cannot be drawn is named in ``problems`` (appended to), not
    fatal. ``pub``: the published results of the reference."""
    figures = []

    def figure(name, fn, *args, caption=""):
        try:
            fn(*args, os.path.join(out, name))
            figures.append((name, caption))
        except Exception as exc:       # a figure that cannot be drawn is reported, not fatal
            problems.append(f"figure {name} not drawn: {exc.__class__.__name__}: {exc}")

    figure("fig_qp.png", plots.plot_report_qp, summaries,
           {s: pub["q_over_p_plateau"].get(s) for s in SAMPLES},
           caption="q/p against εq (each seed; dashed: published plateau), seed fig. 3")
    figure("fig_anisotropies.png", plots.plot_report_anisotropies, summaries,
           caption="a, a_l, a_n, a_t against εq (mean over seeds), seed figs. 6–7")
    figure("fig_sff.png", plots.plot_report_sff, summaries,
           caption="q/p (signed, axial) against (2/5)(a+a_l+a_n+a_t), every shear snapshot, seed fig. 8")
    polar = {}
    for s in SAMPLES:
        ok = figure_runs(runs, s)
        if ok:
            try:
                polar[s] = _polar_data(ok[0])
            except Exception as exc:
                problems.append(f"polar data of {LABEL[s]}: {exc.__class__.__name__}: {exc}")
    if polar:
        figure("fig_polar.png", plots.plot_report_polar, polar,
               caption="P_Ω(θ) and ⟨ℓ⟩(θ) with their harmonic fits at εq ≈ 0.3 (or the last "
                       "snapshot), first seed with its dump, seed figs. 5 and 7")
    s1 = figure_runs(runs, "polyhedra")
    if s1:
        try:
            gp = group_branch_polar(s1[0])
            figure("fig_types_polar.png", plots.plot_group_polar, *gp,
                   caption="branch-vector directions P_Ω(θ) of simple and triple contacts of S1 "
                           "(the analysis's contact-type criterion) at εq ≈ 0.3 or the last snapshot, first seed "
                           "with its dump: the paper's claim-6 figure")
        except Exception as exc:
            problems.append(f"figure fig_types_polar.png not drawn: {exc.__class__.__name__}: {exc}")
        for name, cap in (("contact_types.png", "contact types of S1 against εq: proportions "
                           "(bands: the criterion's threshold halved and doubled), force ratios, "
                           "signed fabric, q/p shares (first seed with its dump)"),
                          ("footprint.png", "footprint extents L1/d and L2/d of S1's polyhedra contacts "
                           "(steady shear, first seed with its dump) with the threshold t, t/2 and 2t: where the "
                           "simple, double and triple groups overlap"),
                          ("force_pdf.png", "densities of f_n/⟨f_n⟩ by contact type, S1, steady shear"),
                          ("networks.png", "strong and weak networks of S1")):
            src = os.path.join(s1[0]["analysis"], name)
            if os.path.exists(src):
                shutil.copyfile(src, os.path.join(out, "s1_" + name))
                figures.append(("s1_" + name, cap))
        if not os.path.exists(os.path.join(s1[0]["analysis"], "qp_sff.png")):
            problems.append(f"S1's analysis figures not in the report: {s1[0]['analysis']} was analysed "
                            f"without figures (postproc analyze without --no-figures draws them)")
    picked = _slab_snapshots(runs)
    if picked:
        figure("packing_slab.png", _slab_pictures, picked, "force",
               caption="force networks in a slab 1.5 mean diameters thick through the middle of the sample "
                       "(normal to y; z is the compression axis), both samples at the same strain (the snapshot "
                       "of each nearest the largest εq both reached, first seed with its dump): grains cut by "
                       "the mid-plane, contacts between centres, width and colour by f_n/⟨f_n⟩. "
                       "3-D: postproc export-vtk")
    if "polyhedra" in picked:
        figure("s1_slab_types.png", _slab_pictures, {"polyhedra": picked["polyhedra"]}, "type",
               caption="the same slab of S1, contacts coloured by type (the analysis's criterion), width by "
                       "f_n/⟨f_n⟩")
    return figures


def build_report(study, out=None, reference=REFERENCE, figures=True):
    """Write the report of the study folder ``study``; returns the path of
    report.md. Raises nothing for failed runs: they are listed.
    ``figures=False``: the same tables and text without the figures (the
    report says so)."""

    out = out or os.path.join(study, "report")
    os.makedirs(out, exist_ok=True)
    with open(reference) as fh:
        ref = json.load(fh)
    runs = discover(study)
    summaries = run_summaries(runs)
    problems = []
    for s in SAMPLES:
        for r in runs.get(s, []):
            if r.get("status") == "partial":
                problems.append(f"{LABEL[s]} {r['label']}: PARTIAL run, used: {r.get('note', '')}")
            elif r.get("status") != "ok":
                problems.append(f"{LABEL[s]} {r['label']}: {r['status']}")
        if not summaries.get(s):
            problems.append(f"{LABEL[s]}: no analysed run; its numbers are missing below")
    if figures:
        drawn = _report_figures(out, runs, summaries, ref["results"], problems)
    else:                              # numbers only: no figure of an earlier report stays beside them
        drawn = None
        for name in REPORT_FIGURES:
            if os.path.exists(os.path.join(out, name)):
                os.remove(os.path.join(out, name))

    rows = comparison_table(summaries, ref)
    comp = pd.DataFrame([{"quantity": q, "sample": s,
                          "ours": e.mean if e else np.nan,
                          "ci_low": e.ci()[0] if e else np.nan, "ci_high": e.ci()[1] if e else np.nan,
                          "interval": e.method if e else "no run", "published": p}
                         for q, s, e, p in rows])
    comp.to_csv(os.path.join(out, "comparison.csv"), index=False)
    claims = evaluate(summaries)
    pd.DataFrame(claims).to_csv(os.path.join(out, "claims.csv"), index=False)
    by_count = claim6_rows(count_summaries(runs, summaries))
    pd.DataFrame(by_count).to_csv(os.path.join(out, "claim6.csv"), index=False)

    md = _markdown(study, runs, summaries, ref, rows, claims, drawn, problems, by_count)
    md += "\n".join(_library_section(runs, out, figures))
    with open(os.path.join(out, "report.md"), "w") as fh:
        fh.write(md)
    _html(md, os.path.join(out, "report.html"))
    return os.path.join(out, "report.md")


def _library_section(runs, out, figures=True):
    """The section on S1's grains (:func:`shapes.report.study_section`): the
    library the first polyhedra run used (its run folder's copy, named in
    its params.json), its name and descriptors beside the published ranges
    (and their figure, unless ``figures`` is False)."""
    from shapes.report import study_section

    for r in runs.get("polyhedra", []):
        folder = os.path.dirname(r.get("dump") or "")
        pj = os.path.join(folder, "params.json")
        if os.path.exists(pj):
            try:
                params = read_json_object(pj, "run parameters file")
            except InputError as exc:
                return ["", f"S1's grains are not described: {exc}"]
            return study_section(os.path.join(folder, params.get("library", "shapes.h5")), out,
                                 **({} if figures else {"figure": None}))
    return []


def _fmt(x, digits=2):
    return "–" if x is None or not np.isfinite(x) else f"{x:.{digits}f}"


def _markdown(study, runs, summaries, ref, rows, claims, figures, problems, by_count=()):
    n = {s: len(summaries.get(s, [])) for s in SAMPLES}
    lines = [f"# Study report: {os.path.basename(os.path.abspath(study))}", "",
             f"Generated {datetime.datetime.now().isoformat(timespec='seconds')} from `{study}`. "
             f"Published values: {ref['citation']}", ""]
    lines += ["## Runs", "", "| sample | run | status | preset / parameters |", "|---|---|---|---|"]
    for s in SAMPLES:
        for r in runs.get(s, []):
            params = ""
            pj = os.path.join(os.path.dirname(r.get("dump") or ""), "params.json")
            p = _read_listed(pj, "run parameters file", problems) if os.path.exists(pj) else None
            if p is not None:
                params = (f"{p.get('preset')}: N = {p.get('n_particles')}, κ = {p.get('kappa')}, "
                          f"I = {p.get('inertial_number')}, ε1 final = {p.get('final_strain')}")
            status = r["status"].upper() if r["status"] == "partial" else r["status"]
            if r.get("note"):
                status += f" ({r['note']})"
            lines.append(f"| {LABEL[s]} | {r['label']} | {status} | {params} |")
    infos = _run_infos(runs, problems)
    cost = _lines_or_problem(lambda: _cost_rows(infos), problems,
                             "the runs' info files are not of the study's shape, no cost table")
    if cost:
        lines += ["", "| sample | run | steps | of which compaction | wall time (s) | µs per contact-step | "
                  "solid fraction after compression |", "|---|---|---|---|---|---|---|"]
        lines += [f"| {a} | {b} | {c} | {cc} | {_fmt(d, 0)} | {_fmt(e, 1)} | {_fmt(f, 3)} |"
                  for a, b, c, cc, d, e, f in cost]
    hosts = _lines_or_problem(lambda: host_lines(infos), problems,
                              "the runs' info files are not of the study's shape, no host lines")
    if hosts:
        lines += [""] + hosts
    lines += _schedule_lines(study, problems)
    if problems:
        lines += ["", "**Problems** (the rest of the report is built without them):", ""]
        lines += [f"* {p}" for p in problems]
    basis = ("over seeds (Student's t)" if min(n.values()) >= 2 else
             "batch means of one seed's steady snapshots (4 batches, Student's t): an indication, "
             "not an ensemble interval; run `make study ENSEMBLE=n` for intervals over seeds")
    lines += ["", "## Our values beside the published ones", "",
              f"Steady shear: snapshots with εq ≥ half the final εq. Intervals are 95 % {basis}.", "",
              "| quantity | sample | ours [95 % interval] | published |", "|---|---|---|---|"]
    for q, s, e, p in rows:
        lines.append(f"| {q} | {LABEL[s]} | {e.text() if e else '–'} | {_fmt(p) if p is not None else '–'} |")
    lines += ["", "## The six claims", "",
              "Thresholds and rules: `postproc/study/claims.py` (reproduced: every condition holds with its "
              "interval; not reproduced: one is contradicted with its interval; else inconclusive).", "",
              "| # | claim | verdict | numbers |", "|---|---|---|---|"]
    for c in claims:
        numbers = c["numbers"].replace("|", "\\|")
        lines.append(f"| {c['id']} | {c['claim']} | **{c['verdict']}** | {numbers} "
                     f"(intervals: {c['basis']}) |")
    if by_count:
        lines += ["", "## Claim 6 by contact count", "",
                  "Claim 6 rests on how contacts are typed. Each count types the S1 contacts of the steady "
                  "window on its own (`postproc/study/counts.py`), with its parameter halved, as is and doubled "
                  "(the band test): a leaning is *stable* when its shift from the nominal one, paired over "
                  f"seeds, stays inside ±{BAND_STABLE} with its 95 % interval, *moves* when it lies outside.", "",
                  "| count | seeds | parameter | verdict | VF leaning | EE leaning | VF shift | EE shift |",
                  "|---|---|---|---|---|---|---|---|"]
        for r in by_count:
            lines.append(f"| {r['count']} | {r['seeds']} | × {r['factor']:g} | **{r['verdict']}** | {r['VF']} | "
                         f"{r['EE']} | {r['VF_shift'] or 'nominal'} | {r['EE_shift'] or 'nominal'} |")
        lines += ["", "Numbers at each count's own parameter:", ""]
        lines += [f"* {r['count']}: {r['numbers']}" for r in by_count if r["factor"] == 1.0]
    lines += ["", "## Figures", ""]
    if figures is None:
        lines += ["Not drawn: the report was written with `--no-figures` (numbers only).", ""]
    for name, cap in figures or ():
        lines += [f"![{cap}]({name})", "", f"*{cap}*", ""]
    return "\n".join(lines) + "\n"


def _html(md, path):
    import markdown  # only the HTML rendering needs it

    body = markdown.markdown(md, extensions=["tables"])
    style = ("body{font-family:sans-serif;max-width:1100px;margin:2em auto;line-height:1.4}"
             "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:3px 6px;"
             "font-size:90%}img{max-width:100%}")
    with open(path, "w") as fh:
        fh.write(f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>Study report</title>"
                 f"<style>{style}</style></head><body>{body}</body></html>\n")
