"""Does the scatter of claim 6's leanings fall as N^(-1/2)? Block averaging
inside the packings of one or more studies.

    postproc investigate leaning-blocks STUDY [STUDY ...] [--types points lmgc90] \
        [--grids 1 2 3 4] [--min-grains 25] [--out runs/leaning-blocks]

(:func:`write_blocks`; ``make size-front`` runs it on its three studies.)

A few seeds per size cannot say how the seed-to-seed scatter of a leaning
scales with the number of grains N (the size front's F-intervals span two
decades). Blocks can: each packing's box is cut into g x g x g blocks, and a
leaning measured block by block scatters like that of many small packings.
If a packing's leaning is the mean of independent local parts, the blocks'
scatter goes as n^(-1/2) with their number of grains n, the blocks of one
packing share no common part, and the whole packing's leaning scatters
between seeds as N^(-1/2): one 5000-grain seed is then worth five 1000-grain
seeds.

For every complete S1 run of each STUDY (a ``make study`` folder) and each
count (``--types``: the study's point count, ``points``, and LMGC90's,
``lmgc90``, whichever the study analysed), the snapshots of the claim's
steady window (:func:`postproc.statistics.steady_indices` on that count's
``summary.csv``) are classified again with the count and its tolerance as
recorded there. Each force-bearing particle-particle contact goes to the
block holding the midpoint of its two centres (the range of the centres
along each axis cut into g equal parts). A block's leaning of type k (VF,
EE) is, as for the whole packing (:func:`postproc.pertype.class_statistics`,
``fabric_a``), the mean of (5/4)(3 u^2 - 1) over its k contacts in a
snapshot (u the cosine of the branch vector with the compression axis z),
then averaged over the window's snapshots. At g = 1 this is the study's own
seed leaning, which :func:`window_contacts` checks snapshot by snapshot (to
1e-9) before using anything else.

Per count, type, size and grid with at least 2 seeds and ``--min-grains``
grains per block, :func:`postproc.statistics.block_components` splits the
blocks' values into a local part (sd ``local``, with its 95 % interval), a
part shared by a packing's blocks (``packing``, with the F-test's p) and the
blocks' places by the walls (``position``). ``local x sqrt(n)`` is constant
when the local part scales as n^(-1/2); the slope of log(local) on log(n)
over every (size, grid) is fitted by weighted least squares (weights the
degrees of freedom: var(log s) = 1 / (2 dof)) with its 95 % interval.
``whole`` = sqrt(packing^2 + local^2 / B) is the predicted seed-to-seed sd
of the whole packing's leaning (which weights its blocks by their contacts,
nearly equal), beside the one the seeds show (g = 1), and
with the present mean it gives the seeds the leaning needs to be told from
0 (:func:`postproc.statistics.seeds_needed`).

Writes OUT/blocks.csv (one row per count, type, size and grid), OUT/blocks.md
(the tables) and caches each run's contacts of the window in
OUT/cache/*.npz (block midpoints as fractions of the centres' range, type,
(5/4)(3 u^2 - 1), snapshot), so a second call with other grids reclassifies
nothing.
"""
from __future__ import annotations

import os
import sys

import numpy as np
import pandas as pd
from scipy.stats import t as student

from ..classify import classifier_for
from ..contactset import resolve
from ..coordination import force_bearing
from ..errors import InputError
from ..pertype import axial_leaning, class_statistics
from ..pipeline import open_source
from ..statistics import block_components, seeds_needed, steady_indices
from .report import discover

TYPES = ("VF", "EE")
AXIS = 2                       # the compression axis, z, as in the study's analyses


def summaries_of(run):
    """The summaries of one study run, by contact count.

    Parameters
    ----------
    run : dict
        One run of :func:`postproc.study.report.discover` (its ``analysis``
        folder and its ``counts``: {count: folder}).

    Returns
    -------
    dict
        {count (str, the summary's ``ct_method``): path of its summary.csv}:
        the primary analysis under its own count and every other count the
        run has; a folder without a summary.csv is left out.
    """
    out = {}
    for folder in [run.get("analysis"), *(run.get("counts") or {}).values()]:
        path = os.path.join(folder, "summary.csv") if folder else None
        if path and os.path.exists(path):
            method = pd.read_csv(path, usecols=["ct_method"])["ct_method"].iloc[0]
            out.setdefault(str(method), path)
    return out


def window_contacts(dump, summary_path, cache):
    """The force-bearing particle-particle contacts of the steady window of
    one run under one count.

    Checks each snapshot's VF and EE leaning against the summary's
    ``ct_fabric_*`` (to 1e-9). The cache is used only while the summary's
    window (its steps and leanings) is the one it was made from.

    Parameters
    ----------
    dump : str
        The run's RUN.h5 dump.
    summary_path : str
        summary.csv of that dump's analysis under one count (its
        ``ct_method`` and ``ct_threshold`` are the count and tolerance used).
    cache : str
        .npz file written after a classification and read instead of one.

    Returns
    -------
    dict
        Arrays over the window's C contacts: ``frac`` (C, 3) the contact's
        place in [0, 1]^3 (the midpoint of the two centres over the range of
        the centres, dimensionless), ``label`` (C,) type, ``g`` (C,)
        (5/4)(3 u^2 - 1), ``snap`` (C,) the snapshot's index in the window;
        and ``n_particles`` (0-d), ``steps`` (S,) and ``lean`` (S, 2) the
        window's steps and the summary's VF and EE leanings.

    Raises
    ------
    InputError
        A snapshot cannot be read, a leaning differs from the summary's, or
        a snapshot of the window is not in the dump.
    """
    df = pd.read_csv(summary_path, dtype={"snapshot": str})
    rows = df.iloc[steady_indices(df["eps_q"], df["stage"])]
    want = {int(s): i for i, s in enumerate(rows["step"])}
    lean = rows[[f"ct_fabric_{t}" for t in TYPES]].to_numpy(float)
    if os.path.exists(cache):
        with np.load(cache) as z:
            kept = {k: z[k] for k in z.files}
        if np.array_equal(kept["steps"], rows["step"].to_numpy(int)) and np.array_equal(kept["lean"], lean,
                                                                                         equal_nan=True):
            return kept                      # the same window of the same analysis
    method, tol = str(rows["ct_method"].iloc[0]), float(rows["ct_threshold"].iloc[0])
    count, snaps, close, shapes = open_source(dump)
    parts = {"frac": [], "label": [], "g": [], "snap": []}
    seen = set()
    try:
        classifier = classifier_for(shapes, method, tolerance=tol)
        for snap in snaps:
            if isinstance(snap, Exception):
                raise InputError(f"{dump}: {snap}")
            k = want.get(int(snap.step))
            if k is None or snap.stage != "shear":
                continue
            labels = classifier.classify(snap, variants=False).labels
            cs = resolve(snap)
            sel = cs.pp & force_bearing(cs.force)
            branch = cs.arm[sel]
            st = class_statistics(labels[sel], cs.normal_force[sel], branch, AXIS)
            for t in TYPES:
                ref = float(rows[f"ct_fabric_{t}"].iloc[k])
                got = st[t]["fabric_a"] if t in st else np.nan
                if not (np.isclose(got, ref, rtol=0, atol=1e-9) or (np.isnan(got) and np.isnan(ref))):
                    raise InputError(f"{dump} step {snap.step}: {method} {t} leaning {got:.12g} "
                                     f"against the summary's {ref:.12g}: not the analysis the study made")
            centres = snap.positions
            lo, hi = centres.min(axis=0), centres.max(axis=0)
            mid = centres[cs.i1[sel]] + 0.5 * branch
            parts["frac"].append((mid - lo) / (hi - lo))
            parts["label"].append(labels[sel].astype("U8"))
            parts["g"].append(axial_leaning(branch, AXIS))
            parts["snap"].append(np.full(int(sel.sum()), k))
            seen.add(k)
    finally:
        close()
    if len(seen) != len(want):
        raise InputError(f"{dump}: {len(want) - len(seen)} of the {len(want)} steady-window "
                         f"snapshots of {summary_path} are not in the dump")
    out = {k: np.concatenate(v) for k, v in parts.items()}
    out["n_particles"] = np.array(len(centres))
    out["steps"], out["lean"] = rows["step"].to_numpy(int), lean
    os.makedirs(os.path.dirname(cache), exist_ok=True)
    np.savez_compressed(cache, **out)
    return out


def block_values(c, g):
    """Each type's leaning per block of a g x g x g grid.

    Parameters
    ----------
    c : dict
        The contacts of :func:`window_contacts` (``frac``, ``label``, ``g``,
        ``snap``, ``n_particles``).
    g : int
        Blocks per axis (1: the whole packing).

    Returns
    -------
    values : ndarray, shape (len(TYPES), g**3)
        The window's mean of the per-snapshot block means of
        (5/4)(3 u^2 - 1); NaN where a block never holds the type.
    grains : float
        The mean number of grains per block, n_particles / g^3.
    """
    cell = np.clip((c["frac"] * g).astype(int), 0, g - 1)
    block = (cell[:, 0] * g + cell[:, 1]) * g + cell[:, 2]
    S, B = int(c["snap"].max()) + 1, g ** 3
    out = np.full((len(TYPES), B), np.nan)
    for j, t in enumerate(TYPES):
        m = c["label"] == t
        key = c["snap"][m] * B + block[m]
        tot = np.bincount(key, weights=c["g"][m], minlength=S * B).reshape(S, B)
        num = np.bincount(key, minlength=S * B).reshape(S, B)
        with np.errstate(invalid="ignore"):
            per_snap = np.where(num > 0, tot / np.maximum(num, 1), np.nan)
        ok = np.isfinite(per_snap).any(axis=0)
        out[j, ok] = np.nanmean(per_snap[:, ok], axis=0)
    return out, float(c["n_particles"]) / B


def slope(points):
    """Weighted least squares of log(local) on log(n).

    Parameters
    ----------
    points : list of (float, float, float)
        (grains per block n, local sd, its degrees of freedom), one per
        (size, grid); each weighted by 1 / var(log sd) = 2 dof.

    Returns
    -------
    tuple of float
        (slope, lo, hi): the slope and its 95 % Student's t interval, the
        standard error scaled by the misfit when it exceeds 1; NaN for
        fewer than 3 points.
    """
    x = np.log([p[0] for p in points])
    y = np.log([p[1] for p in points])
    w = 2.0 * np.array([p[2] for p in points], float)        # 1 / var(log s) = 2 dof
    if len(x) < 3:
        return np.nan, np.nan, np.nan
    X = np.column_stack([np.ones_like(x), x])
    cov = np.linalg.inv(X.T @ (w[:, None] * X))
    beta = cov @ X.T @ (w * y)
    chi = float(w @ (y - X @ beta) ** 2) / (len(x) - 2)      # scale by the misfit when it exceeds 1
    se = np.sqrt(cov[1, 1] * max(1.0, chi))
    h = student.ppf(0.975, len(x) - 2) * se
    return float(beta[1]), float(beta[1] - h), float(beta[1] + h)


def _fmt(x, d=3):
    """x to d decimals, or a dash when missing or not finite."""
    return "–" if x is None or not np.isfinite(x) else f"{x:.{d}f}"


#: the counts whose analyses the block leanings read by default
DEFAULT_COUNTS = ("points", "lmgc90")


def write_blocks(studies, out="runs/leaning-blocks", types=DEFAULT_COUNTS, grids=(1, 2, 3, 4),
                 min_grains=25.0):
    """The block leanings of one or more studies, tabulated (see the module
    docstring): writes OUT/blocks.csv, OUT/blocks.md and ``OUT/cache/*.npz``.

    Parameters
    ----------
    studies : list of str
        ``make study`` folders (each with its manifest.json), any numbers of
        grains.
    out : str
        Output folder.
    types : sequence of str
        The counts to use (``points``, ``lmgc90``): each run's analysis
        under that count; a run without it is left out (said on stderr).
    grids : sequence of int
        Blocks per axis g (positive, 1 included: the whole packing).
    min_grains : float
        A grid g > 1 is used only with at least this many grains per block.

    Returns
    -------
    str
        The text of blocks.md: one row per count, type, size and grid, then
        the slope of log(local sd) on log(grains per block) per count and
        type.

    Raises
    ------
    InputError
        Bad grids, a study without a complete S1 run, no run with the
        counts asked for, or a dump that is not the study's analysis.
    """
    if any(g < 1 for g in grids) or 1 not in grids:
        raise InputError("--grids must be positive integers and include 1 (the whole packing)")
    runs = []                      # (N, count, seed label, contacts)
    for study in studies:
        try:
            found = discover(study)
        except (OSError, ValueError) as exc:
            raise InputError(f"{study}: {exc}")
        ok = [r for r in found.get("polyhedra", []) if r.get("status") == "ok"]
        if not ok:
            raise InputError(f"{study}: no complete S1 run")
        for r in ok:
            have = summaries_of(r)
            for count in types:
                if count not in have:
                    print(f"leaning-blocks: {study} {r['label']}: no {count} analysis, left out", file=sys.stderr)
                    continue
                name = f"{os.path.basename(os.path.normpath(study))}-{r['label'].replace(' ', '')}-{count}"
                print(f"leaning-blocks: {study} {r['label']} ({count})", file=sys.stderr, flush=True)
                c = window_contacts(r["dump"], have[count], os.path.join(out, "cache", name + ".npz"))
                runs.append((int(c["n_particles"]), count, f"{study}:{r['label']}", c))
    if not runs:
        raise InputError("no run with the counts asked for")
    rows = []
    for count in types:
        for N in sorted({n for n, k, _, _ in runs if k == count}):
            group = [c for n, k, _, c in runs if k == count and n == N]
            for g in sorted(grids):
                vals = [block_values(c, g) for c in group]
                n_grains = float(np.mean([v[1] for v in vals]))
                if g > 1 and n_grains < min_grains:
                    continue
                for j, t in enumerate(TYPES):
                    V = np.array([v[0][j] for v in vals])
                    row = {"count": count, "type": t, "N": N, "seeds": len(group), "grid": g, "blocks": g ** 3,
                           "grains_per_block": n_grains, "mean": float(np.nanmean(V))}
                    if g == 1:
                        row["seed_sd"] = float(np.nanstd(V[:, 0], ddof=1)) if len(group) > 1 else np.nan
                    else:
                        bc = block_components(V)
                        row.update({"blocks_used": bc.blocks, "local": bc.local, "local_lo": bc.local_ci[0],
                                    "local_hi": bc.local_ci[1], "local_dof": bc.local_dof,
                                    "local_sqrt_n": bc.local * np.sqrt(n_grains), "packing": bc.packing,
                                    "packing_p": bc.packing_p, "position": bc.position,
                                    "position_p": bc.position_p, "whole": bc.whole})
                    rows.append(row)
    tab = pd.DataFrame(rows)
    os.makedirs(out, exist_ok=True)
    tab.to_csv(os.path.join(out, "blocks.csv"), index=False)
    lines = ["| count | type | N | seeds | g | grains per block | local sd [95 %] | local × √n | packing sd (p) | "
             "position sd (p) | predicted whole sd | seeds' sd | mean | seeds needed |", "|" + "---|" * 14]
    fits = ["", "| count | type | slope of log(local) on log(n) [95 %] | points |", "|---|---|---|---|"]
    for (count, t), sub in tab.groupby(["count", "type"], sort=False):
        pts = []
        for N, s in sub.groupby("N"):
            whole = s[s["grid"] == 1].iloc[0]
            for _, r in s[s["grid"] > 1].iterrows():
                if np.isfinite(r["local"]) and r["local"] > 0:
                    pts.append((r["grains_per_block"], r["local"], r["local_dof"]))
                need = seeds_needed(whole["mean"], r["whole"]) if np.isfinite(r["whole"]) and whole["mean"] else None
                lines.append(f"| {count} | {t} | {N} | {int(r['seeds'])} | {int(r['grid'])} | "
                             f"{r['grains_per_block']:.0f} | {_fmt(r['local'])} [{_fmt(r['local_lo'])}, "
                             f"{_fmt(r['local_hi'])}] | {_fmt(r['local_sqrt_n'], 2)} | {_fmt(r['packing'])} "
                             f"({_fmt(r['packing_p'], 2)}) | {_fmt(r['position'])} ({_fmt(r['position_p'], 2)}) | "
                             f"{_fmt(r['whole'])} | {_fmt(whole['seed_sd'])} | {whole['mean']:+.3f} | "
                             f"{need if need else '–'} |")
        b, lo, hi = slope(pts)
        fits.append(f"| {count} | {t} | {_fmt(b, 2)} [{_fmt(lo, 2)}, {_fmt(hi, 2)}] | {len(pts)} |")
    text = "\n".join(lines + fits) + "\n"
    with open(os.path.join(out, "blocks.md"), "w") as fh:
        fh.write(text)
    return text
