"""The study's quantities at several numbers of grains, compared at the same
axial strain: for runs that have not reached their steady state yet (a
5000-grain study under way), or to see where along the shear two sizes part.

    postproc investigate size-at-strain FOLDER [FOLDER ...] [--sample polyhedra] \
        [--bins 0.04 0.075 0.105 0.145] [--out runs/size-at-strain]

(:func:`write_size_at_strain`.)

Each FOLDER is searched (recursively) for the per-seed analyses of one
sample: folders named ``...<sample>-seed<K>`` (a study's
``analysis-polyhedra-seed1``, or ``postproc analyze RUN.h5 --out DIR``'s
``DIR/polyhedra-seed1``) holding a ``summary.csv`` (one row per snapshot;
the point count's contact types; LMGC90's count, ``...-lmgc90``, is left
out). A partial dump (a run still going) is analysed like any other: copy
``RUN.h5`` and ``RUN.h5.parts`` aside first, then ``postproc analyze``.

Per seed, the shear snapshots with eps_1 in each bin [lo, hi) are averaged;
per number of grains (the summary's ``n_particles``) the table gives the
mean over seeds with the seeds' standard deviation and their number, and
between consecutive numbers of grains the difference with its 95 % Welch
interval (each seed's bin mean one sample; two seeds or more a side). The
bins are of eps_1 (axial strain, compression positive), not eps_q. Writes
OUT/size-at-strain.csv (one row per seed and bin) and OUT/size-at-strain.md
(one table per quantity: rows N, columns the bins).
"""
from __future__ import annotations

import glob
import os
import re

import numpy as np
import pandas as pd

from ..errors import InputError
from ..statistics import difference, plateau_estimate

QUANTITIES = ("q_over_p", "a", "a_l", "a_n", "a_t", "sff_residual", "z", "ct_frac_VF", "ct_frac_EE",
              "ct_frac_FF", "ct_frac_simple", "ct_frac_double")


def per_seed_bins(paths, bins, quantities=QUANTITIES):
    """Each seed's mean of each quantity over its shear snapshots in each
    bin of eps_1.

    Parameters
    ----------
    paths : list of str
        summary.csv files of ``postproc analyze``, one per seed.
    bins : ndarray, shape (B + 1,)
        Increasing edges of eps_1 (axial strain, compression positive,
        dimensionless); bin [lo, hi).
    quantities : sequence of str
        Summary columns to average.

    Returns
    -------
    pandas.DataFrame
        One row per (summary.csv, bin) holding a shear snapshot: ``N`` (the
        summary's n_particles), ``seed`` (the summary's folder name),
        ``bin`` ("lo-hi"), ``snapshots``, and the mean of each quantity.

    Raises
    ------
    ValueError
        A summary lacks a column (not a ``postproc analyze`` summary).
    """
    rows = []
    for path in paths:
        d = pd.read_csv(path)
        missing = [c for c in ("stage", "eps_1", "n_particles", *quantities) if c not in d.columns]
        if missing:
            raise ValueError(f"{path}: no column {', '.join(missing)} (not a postproc analyze summary)")
        d = d[d["stage"] == "shear"]
        for lo, hi in zip(bins[:-1], bins[1:]):
            m = d[(d["eps_1"] >= lo) & (d["eps_1"] < hi)]
            if len(m):
                rows.append({"N": int(m["n_particles"].iloc[0]), "seed": os.path.basename(os.path.dirname(path)),
                             "bin": f"{lo:g}-{hi:g}", "snapshots": len(m),
                             **{q: float(m[q].mean()) for q in quantities}})
    return pd.DataFrame(rows)


def differences(per_seed, q):
    """Between consecutive numbers of grains, the difference of one
    quantity's seed means per bin.

    Parameters
    ----------
    per_seed : pandas.DataFrame
        The rows of :func:`per_seed_bins`.
    q : str
        The quantity (a column of ``per_seed``).

    Returns
    -------
    dict
        {(N1, N2, bin): :class:`postproc.statistics.Estimate` of N2's mean
        minus N1's}, Welch's 95 % interval over the seeds' bin means, for
        consecutive N with two seeds or more each.
    """
    ns = sorted(per_seed["N"].unique())
    out = {}
    for n1, n2 in zip(ns[:-1], ns[1:]):
        for b in per_seed["bin"].unique():
            v1, v2 = ([[x] for x in per_seed[(per_seed["N"] == n) & (per_seed["bin"] == b)][q]] for n in (n1, n2))
            if len(v1) >= 2 and len(v2) >= 2:
                out[n1, n2, b] = difference(plateau_estimate(v2), plateau_estimate(v1))
    return out


def tables(per_seed, quantities=QUANTITIES):
    """The tables of size-at-strain.md.

    Parameters
    ----------
    per_seed : pandas.DataFrame
        The rows of :func:`per_seed_bins`.
    quantities : sequence of str
        One table each.

    Returns
    -------
    str
        Markdown: per quantity, rows N, columns the bins, 'mean ± sd (n)'
        over seeds; then a row per pair of consecutive N (two seeds or more
        each): the difference with its 95 % Welch interval.
    """
    out = []
    for q in quantities:
        cell = per_seed.groupby(["N", "bin"])[q].agg(
            lambda x: f"{x.mean():.3f} ± {x.std(ddof=1):.3f} ({len(x)})" if len(x) > 1 else f"{x.mean():.3f} (1)")
        t = cell.unstack("bin")
        diff = differences(per_seed, q)
        pairs = sorted({(n1, n2) for n1, n2, _ in diff})
        out.append(f"### {q}\n\n| N | " + " | ".join(f"eps_1 {b}" for b in t.columns) + " |\n|---|"
                   + "---|" * len(t.columns) + "\n"
                   + "".join(f"| {n} | " + " | ".join(str(v) if isinstance(v, str) else "" for v in t.loc[n])
                             + " |\n" for n in t.index)
                   + "".join(f"| {n2} − {n1} | " + " | ".join(diff[n1, n2, b].text(3) if (n1, n2, b) in diff else ""
                                                            for b in t.columns) + " |\n" for n1, n2 in pairs))
    return "\n".join(out)


def find_summaries(folder, sample):
    """The per-seed summaries of one sample under a folder.

    Parameters
    ----------
    folder : str
        Searched recursively.
    sample : str
        ``polyhedra`` or ``spheres``.

    Returns
    -------
    list of str
        Sorted paths of every ``.../<sample>-seed<K>/summary.csv`` (another
        count's analysis, ``...-seed<K>-lmgc90``, is left out).
    """
    pat = re.compile(rf"{sample}-seed\d+$")
    return sorted(p for p in glob.glob(os.path.join(folder, "**", "summary.csv"), recursive=True)
                  if pat.search(os.path.basename(os.path.dirname(p))))


def write_size_at_strain(folders, out="runs/size-at-strain", sample="polyhedra",
                         bins=(0.04, 0.075, 0.105, 0.145)):
    """The quantities of one sample by number of grains and bin of eps_1:
    writes OUT/size-at-strain.csv (:func:`per_seed_bins`) and
    OUT/size-at-strain.md (:func:`tables`).

    Parameters
    ----------
    folders : list of str
        Each searched for per-seed analyses (:func:`find_summaries`).
    out : str
        Output folder.
    sample : str
        ``polyhedra`` or ``spheres``.
    bins : sequence of float
        Two or more increasing edges of eps_1.

    Returns
    -------
    str
        The tables (size-at-strain.md without its title).

    Raises
    ------
    InputError
        Bad bins, a folder without summaries, a summary that is not one of
        ``postproc analyze``, or no shear snapshot in the bins.
    """
    bins = np.asarray(bins, float)
    if len(bins) < 2 or np.any(np.diff(bins) <= 0):
        raise InputError("--bins must be two or more increasing strains")
    paths = []
    for f in folders:
        found = find_summaries(f, sample)
        if not found:
            raise InputError(f"{f}: no {sample}-seed<K>/summary.csv under it")
        paths += found
    try:
        per_seed = per_seed_bins(paths, bins)
    except (ValueError, OSError, pd.errors.ParserError) as exc:
        raise InputError(str(exc)) from None
    if per_seed.empty:
        raise InputError("no shear snapshot falls in the bins")
    os.makedirs(out, exist_ok=True)
    per_seed.to_csv(os.path.join(out, "size-at-strain.csv"), index=False)
    text = tables(per_seed)
    with open(os.path.join(out, "size-at-strain.md"), "w") as fh:
        fh.write(f"# {sample}: the quantities at the same eps_1, by number of grains\n\n{text}")
    return text
