"""LMGC90's common-plane contact count with its two measures of ``ref``: the
band tau ref measured from the centre to the extreme vertex (``vertex``, the
older routine, our default) or along the common plane's normal (``normal``,
LMGC90's current routine), each at tau, tau/2 and 2 tau.

    postproc investigate commonplane-reference OUT DUMP.h5 [DUMP.h5 ...] [--from-eps1 0.1] [--every 2] [--tau 0.1]

(:func:`write_reference`.)

For each S1 dump, the shear snapshots with eps_1 >= --from-eps1 (every
--every-th of them) are classified (:class:`postproc.classify.Classifier`,
method "commonplane", through :func:`postproc.analysis.analyze_snapshot`
as ``postproc analyze`` does); OUT/commonplane_reference.csv and .md give,
per dump and reference, the contacts classified, the simple / double /
triple proportions (mean over the snapshots) at tau, tau/2 and 2 tau, and
the largest move of a group between them (the stability target is 0.03).
"""
from __future__ import annotations

import os

import numpy as np
import pandas as pd

from .typeskappa import GROUPS, proportions as type_proportions, shear_snapshots
from ..analysis import analyze_snapshot
from ..classify import Classifier
from ..commonplane import REFERENCES
from ..errors import InputError
from ..pipeline import open_source


def by_reference(dump, tau, from_eps1, every):
    """One dump's contact groups under each reference of the common plane.

    Parameters
    ----------
    dump : str
        An S1 dump.
    tau : float
        The band, in units of ``ref`` (dimensionless).
    from_eps1 : float
        The least eps_1 of the shear snapshots classified.
    every : int
        Every ``every``-th of those snapshots (the first included).

    Returns
    -------
    dict
        {reference ("vertex", "normal"): row}: dump, reference, tau,
        snapshots and contacts classified, the mean proportions at tau (no
        suffix), tau/2 (_lo) and 2 tau (_hi), and the largest move
        (:func:`postproc.study.typeskappa.proportions`).

    Raises
    ------
    InputError
        No shear snapshot with eps_1 >= from_eps1, or one that cannot be
        read.
    """
    count, snaps, close, shapes = open_source(dump)
    try:
        clfs = {r: Classifier(shapes, "commonplane", tolerance=tau, reference=r) for r in REFERENCES}
        rows = {r: [] for r in REFERENCES}
        k = 0
        for snap, _ in shear_snapshots(dump, snaps, from_eps1):
            k += 1
            if (k - 1) % every:
                continue
            for r, clf in clfs.items():
                rows[r].append(analyze_snapshot(snap, tables=clf).row)
    finally:
        close()
    out = {}
    for r, rr in rows.items():
        if not rr:
            raise InputError(f"{dump}: no shear snapshot with eps_1 >= {from_eps1}")
        df = pd.DataFrame(rr)
        out[r] = {"dump": os.path.basename(dump), "reference": r, "tau": tau, "snapshots": len(df),
                  "contacts": int(df["n_contacts_pp"].sum()), **type_proportions(df)}
    return out


def write_reference(out, dumps, from_eps1=0.1, every=1, tau=0.1):
    """Both references on every dump, tabulated: writes
    OUT/commonplane_reference.csv (one row per dump and reference) and
    OUT/commonplane_reference.md (per reference, over the dumps), printing
    each dump's proportions as they come.

    Parameters
    ----------
    out : str
        Output folder.
    dumps : list of str
        S1 dumps.
    from_eps1 : float
        The least eps_1 of the shear snapshots classified.
    every : int
        Every ``every``-th of those snapshots (>= 1).
    tau : float
        The band, in units of ``ref``.

    Returns
    -------
    str
        The text of commonplane_reference.md.

    Raises
    ------
    InputError
        ``every`` < 1, or a dump without shear snapshots to classify.
    """
    if every < 1:
        raise InputError(f"--every must be >= 1, got {every}")
    os.makedirs(out, exist_ok=True)
    table = []
    for dump in dumps:
        for r, row in by_reference(dump, tau, from_eps1, every).items():
            table.append(row)
            print(f"{row['dump']} {r}: {row['simple']:.3f} / {row['double']:.3f} / {row['triple']:.3f}, "
                  f"tau/2 {row['simple_lo']:.3f} / {row['double_lo']:.3f} / {row['triple_lo']:.3f}, "
                  f"2 tau {row['simple_hi']:.3f} / {row['double_hi']:.3f} / {row['triple_hi']:.3f}, "
                  f"move {row['move']:.3f} ({row['contacts']} contacts)", flush=True)
    df = pd.DataFrame(table)
    df.to_csv(os.path.join(out, "commonplane_reference.csv"), index=False)

    def trio(g, s):
        return " / ".join(f"{g[f'{x}{s}'].mean():.2f}" for x in GROUPS)

    lines = ["| reference | dumps | contacts | simple / double / triple | at tau/2 | at 2 tau | largest move |",
             "|---|---|---|---|---|---|---|"]
    for r, g in df.groupby("reference", sort=False):
        lines.append(f"| {r} | {len(g)} | {int(g['contacts'].sum())} | {trio(g, '')} | {trio(g, '_lo')} | "
                     f"{trio(g, '_hi')} | {float(np.max(g['move'])):.2f} |")
    with open(os.path.join(out, "commonplane_reference.md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    return "\n".join(lines)
