"""The study by method: the six claims decided on a YADE (soft-contact DEM)
study and on a Contact Dynamics (LMGC90) study of the same grains, side by
side, and the contact types by every count each method has.

    postproc compare-methods YADE_STUDY CD_STUDY --out DIR [--json FILE --readme README.md]

Both studies are folders with a ``manifest.json``
(:mod:`postproc.study.manifest`), their runs' ``analysis/summary.csv``
read as the report reads them (:func:`postproc.study.report.run_summaries`:
a partial run's shear before the steady state of the complete ones is left
out). The claims are those of :func:`postproc.study.claims.evaluate`, the
same code for both methods, so a verdict that differs is the method's, not
the test's.

The contact-type block gives, for each method and each count it has, the
simple / double / triple proportions of the force-bearing pairs over the
steady window (95 % interval, :func:`postproc.statistics.plateau_estimate`)
against the paper's 0.70 / 0.15 / 0.15, and claim 6 decided by that count:

* ``ours``: our count of the study's primary analysis (``ct_frac_<g>``,
  criterion ``ct_method``), claim 6 by :func:`postproc.study.claims.claim6`;
  any other count the study analysed (:mod:`postproc.study.counts`) one row
  more;
* ``cd-alert``: the CD contact points, every point within the alert distance
  (``cd_alert_frac_<g>``), claim 6 by :func:`postproc.study.claims.claim6_groups`;
* ``cd-force``: the CD points carrying a force (``cd_force_frac_<g>``), the same.

A count a study lacks (a YADE dump has no CD points, so no ``cd_*``) gives
"–" and the reason. Nothing is computed here that the claims code does not
compute; the functions below other than :func:`read_study` and
:func:`write_methods` do no I/O.

methods.json (``FORMAT`` 1)::

    {"format": 1,
     "studies": {"YADE"|"CD": {"path": str, "samples": {sample: {"runs": int, "usable": int,
                                 "partial": int}}, "note": str,
                                 "grains": int|null, "nlgs_tol": float|null}},   # run_settings
     "claims": [{"id": int, "claim": str, "paper": str,
                 "YADE"|"CD": {"verdict": str, "numbers": str, "basis": str}}],   # 6 rows
     "types": [{"method": "YADE"|"CD", "count": str, "label": str, "seeds": int,
                "simple"|"double"|"triple": {"mean": float|null, "lo": float|null, "hi": float|null}|null,
                "claim6": str|null, "claim6_numbers": str|null, "reason": str|null}],
     "paper_types": [0.70, 0.15, 0.15]}

A row of "types" without the count has null proportions and claim 6, and
its "reason".
"""
from __future__ import annotations

import json
import os

from ..columns import GROUPS
from ..errors import InputError, read_json_object
from .claims import claim6, claim6_groups, evaluate, plateau
from .report import count_summaries, discover, run_summaries, usable_runs
from .results import ROOT, _clean

FORMAT = 1
METHODS = ("YADE", "CD")
#: the CD counts: (name, column prefix, what it counts)
CD_COUNTS = (("cd-alert", "cd_alert_", "CD contact points, every point within the alert distance"),
             ("cd-force", "cd_force_", "CD contact points carrying a force"))
PAPER = os.path.join(ROOT, "reference_data", "paper_values.json")


def read_study(study):
    """The runs ({sample: [run]}) and summaries ({sample: [DataFrame]}) of a
    study folder; InputError in one line when it is not one."""
    if not os.path.isfile(os.path.join(study, "manifest.json")):
        raise InputError(f"{study}: not a study folder (no manifest.json)")
    runs = discover(study)
    return runs, run_summaries(runs)


def run_settings(runs):
    """What the S1 runs' folders say of their setting, read beside each dump:
    the number of grains (a YADE ensemble's ``params.json``, ``n_particles``)
    and NLGS's tolerance (a CD run's ``run.params.json``, ``nlgs_tol``).

    Returns
    -------
    dict
        {"grains": int or None, "nlgs_tol": float or None}: one value when
        the runs agree, the largest tolerance when they do not, None when
        no folder records it.
    """
    grains, tols = set(), set()
    for r in runs.get("polyhedra", []):
        folder = os.path.dirname(r.get("dump") or "")
        for name, key, into in (("params.json", "n_particles", grains), ("run.params.json", "nlgs_tol", tols)):
            path = os.path.join(folder, name)
            if folder and os.path.isfile(path):
                try:
                    value = read_json_object(path, "run parameters").get(key)
                except InputError:
                    continue
                if isinstance(value, (int, float)) and value > 0:
                    into.add(value)
    return {"grains": int(max(grains)) if len(grains) == 1 else None,
            "nlgs_tol": float(max(tols)) if tols else None}


def study_facts(runs, summaries):
    """{"samples": {sample: {"runs", "usable", "partial"}}, "note": text}:
    how much of a study the numbers rest on; the note names a sample with
    no usable run and partial runs (so a partial CD study says so)."""
    samples, notes = {}, []
    for s in ("polyhedra", "spheres"):
        rs = runs.get(s, [])
        use = usable_runs(runs, s)
        part = sum(r["status"] == "partial" for r in use)
        samples[s] = {"runs": len(rs), "usable": len(summaries.get(s, [])), "partial": part}
        if not summaries.get(s):
            notes.append(f"no usable {'S1' if s == 'polyhedra' else 'S2'} run")
        elif part:
            notes.append(f"{'S1' if s == 'polyhedra' else 'S2'}: {part} of {len(use)} runs partial "
                         "(stopped short; their steady window is the complete runs')")
    return {"samples": samples, "note": "; ".join(notes) if notes else "complete"}


def paper_text(reference, k):
    """The paper's values claim ``k`` (1-6) rests on, as one line, from
    ``reference`` (``reference_data/paper_values.json``)."""
    r = reference["results"]

    def pair(key):
        v = r[key]
        return f"S1 {v['polyhedra']:g}, S2 {v['spheres']:g}"
    if k == 1:
        return f"q/p plateau {pair('q_over_p_plateau')}"
    if k == 2:
        return f"a {pair('a')}"
    if k == 3:
        return f"a_l {pair('a_l')}"
    if k == 4:
        return f"a_n + a_t {pair('a_n_plus_a_t')}; S2 a_n {r['a_n']['spheres']:g}, a_t {r['a_t']['spheres']:g}"
    if k == 5:
        s1, s2 = r["sff_vs_q_over_p"]["polyhedra"], r["sff_vs_q_over_p"]["spheres"]
        return f"(2/5)Σa vs q/p: S1 {s1[0]:g} vs {s1[1]:g}, S2 {s2[0]:g} vs {s2[1]:g}"
    f = r["mean_normal_force_by_type_relative"]["polyhedra"]
    t = r["contact_types_simple_double_triple"]["polyhedra"]
    return (f"simple/double/triple {'/'.join(f'{x:.2f}' for x in t)}; f/<f> simple {f['simple']:g}, "
            f"double {f['double']:g}, triple {f['triple']:g}")


def _interval(est):
    lo, hi = est.ci()
    return {"mean": _clean(est.mean), "lo": _clean(lo), "hi": _clean(hi)}


#: NLGS tolerance (LMGC90's QM/16) at or below which the force-carrying
#: count is converged: on the front's branch, 1e-3 and 3e-4 give the same
#: proportions, 1e-2 and 3e-3 others (docs/front.md, "The CD time step and tolerance")
FORCE_COUNT_TOL = 1e-3


def type_rows(method, runs, summaries, nlgs_tol=None):
    """The contact-type rows of one method: each count it has (and the CD
    counts, with a reason when absent), the simple/double/triple
    proportions over the S1 seeds and claim 6 decided by that count. The
    force-carrying CD count decides nothing when the runs' NLGS tolerance
    ``nlgs_tol`` is above :data:`FORCE_COUNT_TOL` (its proportions are
    shown, with the reason)."""
    s1 = summaries.get("polyhedra", [])
    rows = []
    if not s1:
        for name, label in (("ours", "our contact-point count"),) + tuple((n, w) for n, _, w in CD_COUNTS):
            rows.append(_row(method, name, label, [], None, None, "no usable S1 run"))
        return rows
    for count, frames in count_summaries(runs, summaries).items():
        c6 = claim6(frames)
        rows.append(_row(method, f"ours ({count})", f"our {count} count", frames, "ct_frac_", c6, None))
    if not any(r["count"].startswith("ours") for r in rows):
        rows.append(_row(method, "ours", "our contact-point count", s1, "ct_frac_", claim6(s1), None))
    for name, prefix, label in CD_COUNTS:
        col = f"{prefix}frac_simple"
        loose = name == "cd-force" and nlgs_tol is not None and nlgs_tol > FORCE_COUNT_TOL * (1 + 1e-9)
        if col in s1[0]:
            why = (f"not decided: NLGS tolerance {nlgs_tol:g}, above the {FORCE_COUNT_TOL:g} at which this count "
                   "converges (docs/front.md)") if loose else None
            rows.append(_row(method, name, label, s1, prefix + "frac_", None if loose else claim6_groups(s1, prefix),
                             why))
        else:
            why = ("no cd_* columns: not a CD dump (no CD contact points)"
                   if not any(c.startswith("cd_") for c in s1[0].columns) else f"no column {col}")
            rows.append(_row(method, name, label, s1, None, None, why))
    return rows


def _row(method, count, label, frames, prefix, c6, reason):
    row = {"method": method, "count": count, "label": label, "seeds": len(frames)}
    for g in GROUPS:
        if prefix is not None and f"{prefix}{g}" not in frames[0]:
            reason, prefix = f"no column {prefix}{g}", None
    for g in GROUPS:
        row[g] = _interval(plateau(frames, f"{prefix}{g}")) if prefix is not None else None
    row["claim6"] = c6["verdict"] if c6 and prefix is not None else None
    row["claim6_numbers"] = c6["numbers"] if c6 and prefix is not None else None
    row["reason"] = reason
    return row


def compare_methods(studies, reference, paths=None, settings=None):
    """The comparison, as methods.json holds it (see the module docstring).

    Parameters
    ----------
    studies : dict
        {"YADE": (runs, summaries), "CD": (runs, summaries)}, as
        :func:`read_study` returns them.
    reference : dict
        The paper's values (``reference_data/paper_values.json``).
    paths : dict, optional
        {method: study folder}, recorded.
    settings : dict, optional
        {method: :func:`run_settings`}: the grains and NLGS tolerance,
        recorded with each study (the CD tolerance decides whether the
        force-carrying count decides claim 6).

    Returns
    -------
    dict
        The methods.json object.
    """
    missing = [m for m in METHODS if m not in studies]
    if missing:
        raise InputError(f"compare-methods: no {', '.join(missing)} study")
    paths, settings = paths or {}, settings or {}
    claims = {m: evaluate(summaries) for m, (_, summaries) in studies.items()}
    out = {"format": FORMAT,
           "studies": {m: {"path": paths.get(m), **study_facts(*studies[m]),
                           **settings.get(m, {"grains": None, "nlgs_tol": None})} for m in METHODS},
           "claims": [], "types": [],
           "paper_types": [float(x) for x in reference["results"]["contact_types_simple_double_triple"]["polyhedra"]]}
    for k in range(6):
        row = {"id": k + 1, "claim": claims["YADE"][k]["claim"], "paper": paper_text(reference, k + 1)}
        for m in METHODS:
            c = claims[m][k]
            row[m] = {"verdict": c["verdict"], "numbers": c["numbers"], "basis": c["basis"]}
        out["claims"].append(row)
    for m in METHODS:
        out["types"] += type_rows(m, *studies[m], nlgs_tol=out["studies"][m]["nlgs_tol"])
    return out


def _cell(iv):
    if iv is None or iv["mean"] is None:
        return "–"
    if iv["lo"] is None:
        return f"{iv['mean']:.2f}"
    return f"{iv['mean']:.2f} [{iv['lo']:.2f}, {iv['hi']:.2f}]"


def methods_markdown(result):
    """methods.md: the studies, the claims side by side, the contact types."""
    lines = ["# The study by method: YADE (soft-contact DEM) and Contact Dynamics (LMGC90)", ""]
    for m in METHODS:
        st = result["studies"][m]
        seeds = ", ".join(f"{'S1' if s == 'polyhedra' else 'S2'} {v['usable']} of {v['runs']} runs"
                          for s, v in st["samples"].items())
        setting = "".join(f"; {k} {st[k]:g}" for k in ("grains", "nlgs_tol") if st.get(k) is not None)
        lines.append(f"* {m}: {st['path'] or '(no path)'}: {seeds}; {st['note']}{setting}")
    lines += ["", "## The six claims", "",
              "| claim | paper | YADE | CD | YADE numbers | CD numbers |", "|---|---|---|---|---|---|"]
    for c in result["claims"]:
        lines.append(f"| {c['id']}. {c['claim']} | {c['paper']} | {c['YADE']['verdict']} | {c['CD']['verdict']} "
                     f"| {c['YADE']['numbers']} ({c['YADE']['basis']}) | {c['CD']['numbers']} ({c['CD']['basis']}) |")
    paper = "/".join(f"{x:.2f}" for x in result["paper_types"])
    lines += ["", f"## Contact types (simple / double / triple; the paper: {paper})", "",
              "| method | count | seeds | simple | double | triple | claim 6 | note |",
              "|---|---|---|---|---|---|---|---|"]
    for r in result["types"]:
        lines.append(f"| {r['method']} | {r['count']}: {r['label']} | {r['seeds']} | "
                     + " | ".join(_cell(r[g]) for g in GROUPS)
                     + f" | {r['claim6'] or '–'} | {r['reason'] or r['claim6_numbers'] or ''} |")
    return "\n".join(lines) + "\n"


def write_methods(yade_study, cd_study, out, reference=PAPER):
    """Read both studies, write OUT/methods.md and OUT/methods.json, return
    the comparison (:func:`compare_methods`)."""
    studies = {"YADE": read_study(yade_study), "CD": read_study(cd_study)}
    result = compare_methods(studies, read_json_object(reference, "paper values"),
                             {"YADE": yade_study, "CD": cd_study},
                             {m: run_settings(runs) for m, (runs, _) in studies.items()})
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "methods.json"), "w") as fh:
        json.dump(result, fh, indent=1, ensure_ascii=False)
        fh.write("\n")
    with open(os.path.join(out, "methods.md"), "w") as fh:
        fh.write(methods_markdown(result))
    return result

