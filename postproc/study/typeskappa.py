"""Contact types against the contact stiffness: the overlap-based point count
(``--types points``) and LMGC90's common-plane count (``--types
commonplane``) on the same dumps.

    postproc investigate contact-types-kappa OUT DUMP.h5 [DUMP.h5 ...] [--from-eps1 0.1]

(:func:`write_types_kappa`.)

Each kernel S1 dump is analysed with both criteria (``postproc analyze``
through :func:`postproc.pipeline.analyze_path`, into OUT/<dump>-<types>/),
then OUT/contact_types_kappa.csv and .md list, per dump and criterion, its
kappa and I, the number of contacts in the window, and the simple / double /
triple proportions (mean over the shear snapshots with eps_1 >= --from-eps1)
at the criterion's tolerance, half and double it, the largest move of a
group between them, and the mean normal force of each group over the mean.
A criterion whose proportions stop changing as kappa grows measures the
rigid grains of contact dynamics; one that is also stable under its
tolerance (moves <= 0.03) gives the paper's claim-6 counts a meaning.
With several seeds per (kappa, I) (a front's dumps, e.g.
``runs/front-default/polyhedra/*.h5``), OUT/contact_types_points.csv and
the second table of the .md give, per criterion and point, the means over
seeds with 95 % Student's t half-widths.
"""
from __future__ import annotations

import os

import numpy as np
import pandas as pd

from ..errors import InputError
from ..pipeline import AnalysisOptions, analyze_path
from ..schema import DumpReader
from ..statistics import plateau_estimate
from ..strain import box_strains

GROUPS = ("simple", "double", "triple")


def shear_snapshots(dump, snaps, from_eps1):
    """The shear snapshots of a dump from a given axial strain on.

    Parameters
    ----------
    dump : str
        The dump's path (for the error message).
    snaps : iterator
        The snapshots of an :func:`postproc.pipeline.open_source` of
        ``dump`` (a snapshot that could not be read is an exception).
    from_eps1 : float
        The least eps_1 (axial strain, compression positive,
        dimensionless), measured from the last isotropic snapshot (zero
        strain).

    Yields
    ------
    tuple
        (snapshot, eps_1) for each shear snapshot with eps_1 >= from_eps1.

    Raises
    ------
    InputError
        A snapshot could not be read (its one-line error).
    """
    ref_box = None
    for snap in snaps:
        if isinstance(snap, Exception):
            raise InputError(f"{dump}: {snap}")
        if snap.stage == "isotropic":
            ref_box = snap.box_lengths
        if snap.stage != "shear" or ref_box is None:
            continue
        eps1 = float(box_strains(snap.box_lengths, ref_box)["eps_1"][0])
        if eps1 >= from_eps1:
            yield snap, eps1


def dump_row(dump, out, types, from_eps1):
    """One dump under one criterion: its analysis (made into
    OUT/<dump>-<types>/ unless there, numbers only: no figures) summed up over the shear snapshots
    with eps_1 >= from_eps1.

    Parameters
    ----------
    dump : str
        A kernel S1 dump (its parameters hold kappa, inertial_number,
        n_particles and seed).
    out : str
        The output folder.
    types : str
        The criterion (``postproc analyze --types``).
    from_eps1 : float
        The least eps_1 of the snapshots used.

    Returns
    -------
    dict
        dump, criterion, kappa, I, seed, n_grains, snapshots, contacts (the
        particle-particle contacts summed over the snapshots), the
        :func:`proportions` and fratio_<group> (each group's mean normal
        force over the mean, averaged over the snapshots).
    """
    folder = os.path.join(out, f"{os.path.splitext(os.path.basename(dump))[0]}-{types}")
    if not os.path.exists(os.path.join(folder, "summary.csv")):
        analyze_path(dump, folder, AnalysisOptions(types=types, figures=False), progress=False)
    df = pd.read_csv(os.path.join(folder, "summary.csv"))
    sh = df[(df["stage"] == "shear") & (df["eps_1"] >= from_eps1)]
    with DumpReader(dump) as r:
        p = r.parameters
    row = {"dump": os.path.basename(dump), "criterion": types, "kappa": p["kappa"], "I": p["inertial_number"],
           "seed": p.get("seed"),
           "n_grains": p["n_particles"], "snapshots": len(sh), "contacts": int(sh["n_contacts_pp"].sum())}
    row.update(proportions(sh))
    for g in GROUPS:
        row[f"fratio_{g}"] = sh[f"ct_fratio_{g}"].mean()
    return row


def proportions(frame):
    """The simple / double / triple proportions of summary rows.

    Parameters
    ----------
    frame : pandas.DataFrame
        Rows of a ``postproc analyze`` summary (its ``ct_frac_<group>``,
        ``_lo`` and ``_hi`` columns).

    Returns
    -------
    dict
        The mean over the rows at the criterion's tolerance (``simple``...),
        half it (``simple_lo``...) and double it (``simple_hi``...), and
        ``move``, the largest change of a group between them.
    """
    row = {f"{g}{s}": float(frame[f"ct_frac_{g}{s}"].mean()) for g in GROUPS for s in ("", "_lo", "_hi")}
    row["move"] = max(abs(row[f"{g}{s}"] - row[g]) for g in GROUPS for s in ("_lo", "_hi"))
    return row


def point_means(table):
    """Means over seeds per criterion and (kappa, I).

    Parameters
    ----------
    table : pandas.DataFrame
        Rows of :func:`dump_row`.

    Returns
    -------
    pandas.DataFrame
        Per criterion and (kappa, I): ``seeds``, ``contacts``, the mean over
        seeds of each group's proportion at the tolerance, of ``move`` and
        of the force ratios, with 95 % Student's t half-widths over seeds
        (``<col>_ci``, nan with one seed).
    """
    cols = list(GROUPS) + ["move"] + [f"fratio_{g}" for g in GROUPS]
    rows = []
    for (c, k, i), g in table.groupby(["criterion", "kappa", "I"], sort=True):
        row = {"criterion": c, "kappa": k, "I": i, "seeds": len(g), "contacts": int(g["contacts"].sum())}
        for col in cols:
            e = plateau_estimate([[v] for v in g[col].to_numpy(float)])
            lo, hi = e.ci()
            row[col], row[col + "_ci"] = e.mean, (hi - lo) / 2
        rows.append(row)
    return pd.DataFrame(rows)


def write_types_kappa(out, dumps, from_eps1=0.1):
    """Both criteria on every dump, tabulated (see the module docstring):
    writes OUT/contact_types_kappa.csv and .md, and with several seeds per
    (kappa, I) OUT/contact_types_points.csv.

    Parameters
    ----------
    out : str
        Output folder (the analyses go there too).
    dumps : list of str
        Kernel S1 dumps.
    from_eps1 : float
        The least eps_1 of the shear snapshots averaged.

    Returns
    -------
    str
        The text of contact_types_kappa.md.
    """
    os.makedirs(out, exist_ok=True)
    rows = [dump_row(d, out, t, from_eps1) for d in dumps for t in ("points", "commonplane")]
    table = pd.DataFrame(rows).sort_values(["criterion", "I", "kappa"])
    table.to_csv(os.path.join(out, "contact_types_kappa.csv"), index=False)
    lines = ["| criterion | κ | I | contacts | simple / double / triple | ½ × | 2 × | move | f ratio s / d / t |",
             "|---|---|---|---|---|---|---|---|---|"]
    for _, r in table.iterrows():
        f = lambda s: " / ".join(f"{r[g + s]:.2f}" for g in GROUPS)  # noqa: E731
        lines.append(f"| {r['criterion']} | {r['kappa']:g} | {r['I']:g} | {r['contacts']} | {f('')} | {f('_lo')} | "
                     f"{f('_hi')} | {r['move']:.3f} | "
                     + " / ".join(f"{r['fratio_' + g]:.2f}" for g in GROUPS) + " |")
    points = point_means(table)
    if (points["seeds"] > 1).any():
        points.to_csv(os.path.join(out, "contact_types_points.csv"), index=False)
        lines += ["", "Means over seeds (95 % t):", "",
                  "| criterion | κ | I | seeds | contacts | simple | double | triple | move | f ratio s / d / t |",
                  "|---|---|---|---|---|---|---|---|---|---|"]
        ci = lambda r, c: f"{r[c]:.2f} ± {r[c + '_ci']:.2f}" if np.isfinite(r[c + "_ci"]) else f"{r[c]:.2f}"  # noqa: E731
        for _, r in points.iterrows():
            lines.append(f"| {r['criterion']} | {r['kappa']:g} | {r['I']:g} | {r['seeds']} | {r['contacts']} | "
                         + " | ".join(ci(r, g) for g in GROUPS) + f" | {ci(r, 'move')} | "
                         + " / ".join(f"{r['fratio_' + g]:.2f}" for g in GROUPS) + " |")
    text = "\n".join(lines) + "\n"
    with open(os.path.join(out, "contact_types_kappa.md"), "w") as fh:
        fh.write(text)
    return text
