"""The shape front: the study's quantities on two grain libraries.

What does grain shape change? Two studies (``make study``) that differ only
in S1's grains (``make study SHAPES=LIB.h5``, e.g. the real stones of
``reference_data/stonepacking-3d.h5``, against the default's generated
grains), at the same number of grains, kappa, I and preparation. For each
study, the values of :func:`postproc.study.sizefront.study_values`: per seed,
the plateau of q/p, a, a_l, a_n, a_t (eqs. a1-a3), (2/5)Σa, z, the fraction
of forces below the mean, the solid fraction after compaction, and for S1
per contact count (the primary analysis and each other count) the
proportions of simple, double and triple contacts and claim 6's force
ratios, leanings and FF shares. Then per quantity and sample: each study's
mean over seeds with its 95 % interval (Student's t), the difference
second - first with its 95 % interval (Welch), the paper's value where it
states one, and whether the second study's value is nearer to it
(:func:`direction`). Also each study's verdicts (the six claims by its primary count,
claim 6 by each count) and its grains' descriptors (:mod:`shapes.descriptors`,
mean over the library's grains).

::

    postproc investigate shape-front GENERATED_STUDY REAL_STUDY --out DIR
"""
from __future__ import annotations

import json
import os

import numpy as np
import pandas as pd

from .claims import claim6, evaluate
from .report import REFERENCE, count_summaries, discover, run_summaries
from .sizefront import _estimate, _f, _label, study_values
from ..errors import InputError
from ..statistics import difference

#: (quantity, sample) -> the key of paper_values.json's results and the index in it
PAPER = {("q_over_p", "polyhedra"): ("q_over_p_plateau", "polyhedra"),
         ("q_over_p", "spheres"): ("q_over_p_plateau", "spheres"),
         ("a", "polyhedra"): ("a", "polyhedra"), ("a", "spheres"): ("a", "spheres"),
         ("a_l", "polyhedra"): ("a_l", "polyhedra"), ("a_l", "spheres"): ("a_l", "spheres"),
         ("a_n", "spheres"): ("a_n", "spheres"), ("a_t", "spheres"): ("a_t", "spheres"),
         ("z", "polyhedra"): ("coordination_z", "polyhedra"), ("z", "spheres"): ("coordination_z", "spheres"),
         ("frac_below_mean", "polyhedra"): ("fraction_forces_below_mean", "polyhedra"),
         ("frac_below_mean", "spheres"): ("fraction_forces_below_mean", "spheres")}
TYPE_FRACTIONS = ("ct_frac_simple", "ct_frac_double", "ct_frac_triple")
#: the descriptors shown per library (shapes.descriptors.NAMES), with their labels
DESCRIPTORS = {"n_vertices": "vertices", "n_faces": "faces", "elongation": "elongation I/L",
               "flatness": "flatness S/I", "sphericity": "Wadell sphericity", "angularity_deg": "angularity (°)", "sharpest_edge_deg": "sharpest edge (°)",
               "convexity_deficit": "convexity deficit", "reduction_hausdorff": "reduction error (d)",
               "reduction_volume_change": "volume change of the reduction"}


def paper_value(quantity, sample, reference=REFERENCE):
    """The paper's value of ``quantity`` for ``sample`` (float), or NaN when
    it states none. S1's contact-type proportions (``<count>:ct_frac_*``)
    are the published 0.70 / 0.15 / 0.15 whatever the count.

    Examples
    --------
    >>> paper_value("a_l", "polyhedra"), paper_value("lmgc90:ct_frac_double", "polyhedra")
    (0.12, 0.15)
    >>> bool(np.isnan(paper_value("a_n", "polyhedra")))    # only a_n + a_t is stated
    True
    """
    with open(reference) as fh:
        res = json.load(fh)["results"]
    col = quantity.split(":")[-1]
    if sample == "polyhedra" and col in TYPE_FRACTIONS:
        return float(res["contact_types_simple_double_triple"]["polyhedra"][TYPE_FRACTIONS.index(col)])
    if ":" in quantity or (quantity, sample) not in PAPER:
        return np.nan
    key, s = PAPER[(quantity, sample)]
    return float(res[key][s])


def direction(first, diff_low, diff_high, paper):
    """Whether the second study is nearer the paper's value than the first,
    from the difference's interval [diff_low, diff_high] (second - first).

    With g = paper - first, the second value is nearer the paper exactly
    when the difference lies strictly between 0 and 2g. "toward": the
    whole interval lies there; "away": it lies wholly outside [0, 2g]
    (the other way, or past the paper by more than the first was short of
    it); "no change": it holds 0; "undecided": it straddles 2g. "" when
    there is no paper value or no interval. The first study's own
    uncertainty is not counted.

    Examples
    --------
    >>> direction(0.0, 0.01, 0.05, 0.12), direction(0.0, -0.05, -0.01, 0.12), direction(0.0, -0.01, 0.02, 0.12)
    ('toward', 'away', 'no change')
    >>> direction(0.709, -0.175, -0.109, 0.70), direction(0.0, 0.2, 0.3, 0.12)   # far past it; 2g = 0.24 inside
    ('away', 'undecided')
    """
    if not (np.isfinite(paper) and np.isfinite(diff_low) and np.isfinite(diff_high)):
        return ""
    if diff_low <= 0 <= diff_high:
        return "no change"
    lo, hi = sorted((0.0, 2 * (paper - first)))
    if lo < diff_low and diff_high < hi:
        return "toward"
    if diff_high < lo or diff_low > hi:
        return "away"
    return "undecided"


def shape_table(values, labels):
    """Long DataFrame, one row per quantity and sample: for each study
    label, ``mean:<label>``, ``low:<label>``, ``high:<label>``, ``seeds:<label>``;
    the difference last - first (``diff``, ``diff_low``, ``diff_high``),
    ``paper`` and ``toward`` (:func:`direction`). ``values``: rows of
    :func:`study_values` with a ``label`` column."""
    rows = []
    quantities = [q for q in values.columns if q not in ("study", "sample", "n_particles", "run", "label")]
    for sample in ("polyhedra", "spheres"):
        g = values[values["sample"] == sample]
        for q in quantities:
            if not np.isfinite(g[q].to_numpy(float)).any():
                continue
            row = {"quantity": q, "sample": sample}
            est = {}
            for lab in labels:
                v = g[g["label"] == lab][q].to_numpy(float)
                v = v[np.isfinite(v)]
                e = est[lab] = _estimate(v)
                lo, hi = e.ci()
                row.update({f"mean:{lab}": e.mean, f"low:{lab}": lo, f"high:{lab}": hi, f"seeds:{lab}": len(v)})
            d = difference(est[labels[-1]], est[labels[0]])
            row["diff"], (row["diff_low"], row["diff_high"]) = d.mean, d.ci()
            row["paper"] = paper_value(q, sample)
            row["toward"] = direction(est[labels[0]].mean, row["diff_low"], row["diff_high"], row["paper"])
            rows.append(row)
    return pd.DataFrame(rows)


def study_verdicts(study):
    """{claim key: verdict} of one study: "1".."6" by its primary count and
    "6 (<count>)" for claim 6 by each count, with its interval text."""
    runs = discover(study)
    summaries = run_summaries(runs)
    out = {}
    for c in evaluate(summaries):
        out[str(c["id"])] = c["verdict"]
    for count, frames in count_summaries(runs, summaries).items():
        out[f"6 ({count})"] = claim6(frames)["verdict"]
    return out


def library_of(study):
    """The S1 library file a study ran on (its polyhedra folder's copy,
    ``shapes.h5``), or None."""
    for sub in ("polyhedra-ensemble", "polyhedra"):
        path = os.path.join(study, sub, "shapes.h5")
        if os.path.exists(path):
            return path
    return None


def descriptor_means(study):
    """{descriptor: (mean, min, max)} over the grains of the study's S1
    library (:data:`DESCRIPTORS`), with ``name`` -> the library's name; an
    empty dict when the study has no library copy."""
    from shapes.descriptors import library_descriptors
    from shapes.library import LibraryError, ShapeLibrary

    path = library_of(study)
    if path is None:
        return {}
    try:
        lib = ShapeLibrary(path)
    except LibraryError:
        return {}
    desc = library_descriptors(lib)
    out = {k: (float(np.mean(desc[k])), float(np.min(desc[k])), float(np.max(desc[k])))
           for k in DESCRIPTORS if k in desc}
    out["name"] = lib.name
    out["grains"] = len(lib)
    return out


def shape_markdown(table, labels, verdicts, descriptors):
    """The shape front as markdown: the grains' descriptors, the table of
    means and differences with the paper's value, and the verdicts."""
    out = []
    if all(descriptors.get(lab) for lab in labels):
        out += ["| grains' descriptor (mean [min, max]) | " + " | ".join(
                    f"{lab}: {descriptors[lab]['name']} ({descriptors[lab]['grains']} grains)" for lab in labels) + " |",
                "|---|" + "---|" * len(labels)]
        for k, name in DESCRIPTORS.items():
            cells = [f"{_f(descriptors[lab][k][0])} [{_f(descriptors[lab][k][1])}, {_f(descriptors[lab][k][2])}]"
                     if k in descriptors[lab] else "–" for lab in labels]
            out.append(f"| {name} | " + " | ".join(cells) + " |")
        out.append("")
    out += ["| quantity | sample | " + " | ".join(labels) + f" | {labels[-1]} − {labels[0]} | paper | "
            "toward the paper? |", "|---|---|" + "---|" * (len(labels) + 3)]
    for _, r in table.iterrows():
        cells = [f"{_f(r[f'mean:{lab}'])} [{_f(r[f'low:{lab}'])}, {_f(r[f'high:{lab}'])}]" for lab in labels]
        mark = "**" if (r["diff_low"] > 0 or r["diff_high"] < 0) else ""
        diff = (f"{mark}{r['diff']:+.3f} [{r['diff_low']:+.3f}, {r['diff_high']:+.3f}]{mark}"
                if np.isfinite(r["diff_low"]) else _f(r["diff"]))
        out.append(f"| {_label(r['quantity'])} | {r['sample']} | " + " | ".join(cells) + f" | {diff} | "
                   f"{_f(r['paper'], 2) if np.isfinite(r['paper']) else ''} | {r['toward']} |")
    out += ["", "Means over seeds with their 95 % intervals (Student's t); the difference's interval is "
            "Welch's. Bold: it excludes 0. \"toward\": the second study's value is nearer the paper's, the "
            "whole interval of the difference agreeing; \"away\": farther (the other way, or past it by more than "
            "the first fell short); \"undecided\": either.", ""]
    keys = list(dict.fromkeys(k for lab in labels for k in verdicts[lab]))
    out += ["| claim | " + " | ".join(labels) + " |", "|---|" + "---|" * len(labels)]
    for k in keys:
        out.append(f"| {k} | " + " | ".join(verdicts[lab].get(k, "–") for lab in labels) + " |")
    return "\n".join(out) + "\n"


def write_shape_front(studies, out, labels=None):
    """Write the shape front of two or more study folders into ``out``:
    values.csv (one row per run), shape.csv (:func:`shape_table`),
    verdicts.csv, shape.md and shape-front.png. ``labels`` name the studies
    (default: their S1 libraries' names). Returns the path of shape.md.
    Raises InputError (one line) for a folder without a usable study, or
    fewer than two studies."""
    from ..plots import plot_shape_front

    if len(studies) < 2:
        raise InputError("the shape front needs two studies or more (the first is the reference)")
    descriptors = {}
    frames = []
    names = []
    for k, s in enumerate(studies):
        v = study_values(s)
        d = descriptor_means(s)
        name = labels[k] if labels else (d.get("name") or os.path.basename(os.path.normpath(s)))
        if name in names:
            name = f"{name} ({os.path.basename(os.path.normpath(s))})"
        names.append(name)
        descriptors[name] = d
        frames.append(v.assign(label=name))
    ns = {int(f["n_particles"].iloc[0]) for f in frames if len(f)}
    if len(ns) > 1:
        raise InputError(f"the studies have different numbers of grains ({sorted(ns)}): compare shapes at one size "
                         "(postproc investigate size-front compares sizes)")
    values = pd.concat(frames, ignore_index=True)
    table = shape_table(values, names)
    verdicts = {name: study_verdicts(s) for name, s in zip(names, studies)}
    os.makedirs(out, exist_ok=True)
    values.to_csv(os.path.join(out, "values.csv"), index=False)
    table.to_csv(os.path.join(out, "shape.csv"), index=False)
    pd.DataFrame([{"study": n, "claim": k, "verdict": v} for n in names for k, v in verdicts[n].items()]).to_csv(
        os.path.join(out, "verdicts.csv"), index=False)
    path = os.path.join(out, "shape.md")
    with open(path, "w") as fh:
        fh.write(shape_markdown(table, names, verdicts, descriptors))
    plot_shape_front(table, names, os.path.join(out, "shape-front.png"))
    return path
