"""Claim 6 counted more than one way: the study's extra analyses of each S1
dump, one per contact count beside the primary one.

The paper's claim 6 rests on how contacts are typed (simple, double,
triple; VV ... FF), and two counts disagree on it (docs/lmgc90-contacts.md):
our contact-point count from the overlap (``types="points"``, the analysis
default, which the study's primary analysis uses) and LMGC90's own count,
its CpCundall detection and today's default point stage
(``types="lmgc90"``, alert distance 0.1 x the smallest grain radius; equal
to the compiled LMGC90's count on 99 % of the grain pairs of the default's
packings). The study therefore analyses every usable
S1 dump once more per count of :data:`EXTRA_COUNTS`, on the snapshots claim
6 reads only: the steady window of the primary analysis (shear snapshots with
eps_q >= half its final value, :func:`postproc.statistics.steady_indices`)
and the isotropic snapshot the strains start from. The steady window of such a
summary is the primary one (same final eps_q, same snapshots above half
of it), so the counts are compared on the same snapshots. Each analysis
also carries claim 6's quantities with the count's parameter halved and
doubled (the ``*_lo``/``*_hi`` columns of
:func:`postproc.analysis.contact_type_columns`), from which
:func:`postproc.study.claims.band_test` decides the band test.

Outputs go next to the primary analysis: ``<analysis>-<count>/summary.csv``.
A study can be given other counts (``python -m yade_scripts.campaign.study --counts
lmgc90 lmgc90-2009``, ``make study COUNTS="lmgc90 lmgc90-2009"``,
:func:`check_counts`); on a finished study only the missing analyses are
made, and its report then reads claim 6 by each.
"""
from __future__ import annotations

import os

import numpy as np
import pandas as pd

from ..errors import InputError
from ..classify import CRITERIA, DEFAULT_METHOD
from ..pipeline import BAD_INPUT, AnalysisOptions, analyze_path
from ..provenance import is_current
from ..schema import DumpReader
from ..statistics import steady_indices

#: the counts analysed beside the primary one (the analysis default, "points")
EXTRA_COUNTS = ("lmgc90",)


def check_counts(counts):
    """The study's other contact counts, checked before anything runs.

    Parameters
    ----------
    counts : sequence of str
        Contact-type criteria of ``postproc analyze --types``
        (:data:`postproc.classify.CRITERIA`) other than the primary one
        ("points"), e.g. ``("lmgc90", "lmgc90-2009")``; an empty sequence
        means the primary count only.

    Returns
    -------
    tuple of str
        The counts in their order, each once.

    Raises
    ------
    InputError
        One line naming an unknown count, or the primary one.

    Examples
    --------
    >>> check_counts(["lmgc90", "lmgc90-2009", "lmgc90"])
    ('lmgc90', 'lmgc90-2009')
    >>> check_counts(["points"])
    Traceback (most recent call last):
    ...
    postproc.errors.InputError: --counts: points is the primary count, always analysed; give the others (lmgc90, ...)
    """
    out = []
    for c in counts:
        if c == DEFAULT_METHOD:
            raise InputError(f"--counts: {c} is the primary count, always analysed; give the others (lmgc90, ...)")
        if c not in CRITERIA:
            others = ", ".join(m for m in CRITERIA if m != DEFAULT_METHOD)
            raise InputError(f"--counts: unknown count {c!r}; one of {others}")
        if c not in out:
            out.append(c)
    return tuple(out)


def count_folder(analysis, count):
    """The folder of a run's analysis with ``count``, beside its primary
    analysis folder ``analysis``."""
    return f"{analysis.rstrip(os.sep)}-{count}"


def claim6_snapshots(summary, names):
    """Indices (into the dump's snapshot ``names``) that claim 6 reads: the
    isotropic snapshots (the strains' reference) and the steady window of
    the primary ``summary`` (a DataFrame with columns snapshot, eps_q,
    stage). Raises InputError when a summary snapshot is not in the dump."""
    keep = set(steady_indices(summary["eps_q"], summary["stage"]).tolist())
    keep |= set(np.flatnonzero(summary["stage"].astype(str).to_numpy() == "isotropic").tolist())
    out = []
    for k in sorted(keep):
        name = str(summary["snapshot"].iloc[k]).zfill(6)
        if name not in names:
            raise InputError(f"snapshot {name} of the summary is not in the dump (summary and dump disagree)")
        out.append(names.index(name))
    return tuple(sorted(out))


def analyse_counts(dump, analysis, counts=None, progress=False, figures=False):
    """Analyse the S1 ``dump`` with each contact count of ``counts`` (None:
    :data:`EXTRA_COUNTS`), on the
    snapshots of :func:`claim6_snapshots` of its primary analysis (folder
    ``analysis``, with its summary.csv). An analysis made from the same dump
    files, snapshots and options by the same code
    (:func:`postproc.provenance.is_current`) is kept. Returns {count: folder}
    of the analyses that exist, and a list of one-line problems (a count
    that failed is left out and named there; the others go on).
    ``figures``: draw each analysis's figures (default False: numbers
    only, which is what claim 6 reads)."""
    primary = os.path.join(analysis, "summary.csv")
    done, problems = {}, []
    if not os.path.exists(primary):
        return done, [f"{dump}: no primary analysis ({primary}), so no other count"]
    chosen = None
    for count in EXTRA_COUNTS if counts is None else counts:
        folder = count_folder(analysis, count)
        try:
            if chosen is None:
                summary = pd.read_csv(primary, dtype={"snapshot": str})
                with DumpReader(dump) as reader:
                    names = list(reader.names)
                chosen = claim6_snapshots(summary, names)
            options = AnalysisOptions(types=count, snapshots=chosen, figures=figures)
            if not is_current(dump, folder, options):
                analyze_path(dump, folder, options, progress=progress)
            done[count] = folder
        except BAD_INPUT as exc:
            problems.append(f"{dump}: the {count} count failed: {exc}")
    return done, problems
