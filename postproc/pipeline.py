"""The analysis of one input, end to end: read a dump, table or LAMMPS
dump, analyse every snapshot (:func:`postproc.analysis.analyze_snapshot`),
write ``summary.csv`` and the figures (:func:`analyze_path`).

The command line (:mod:`postproc.cli`), many inputs at once
(:mod:`postproc.many`) and the study driver call this; none of them goes
through argv strings to reach it.
"""
from __future__ import annotations

import json
import os
import shutil
import sys
import tempfile
from dataclasses import dataclass

import numpy as np
import pandas as pd

from . import footprint as fpm, plots
from .analysis import add_strains, analyze_snapshot, group_labels_of
from .axes import axis_vector
from .classify import CRITERIA, DEFAULT_METHOD, check_options, classifier_for
from .columns import LEAD
from .errors import InputError
from .lammpsdump import read_text_dump, sniff
from .networks import force_pdf
from .provenance import SOURCE_FILE, stamp
from .schema import DumpFormatError, DumpReader
from .statistics import steady_indices
from .tables import read_contact_table

BAD_INPUT = (InputError, DumpFormatError)


def open_source(path, volume=None, box=None, cell=None, fmt=None, atoms=None, snapshots=None):
    """(count, iterator of Snapshot or exception, close, shapes) for a dump
    or table; ``shapes`` is the dump's (vertices, triangles, faces) or None.
    ``snapshots``: indices of a dump's snapshots to read (None: all)."""

    if fmt is not None or atoms is not None or sniff(path) is not None:
        if volume is not None or box is not None or cell is not None:
            raise InputError("--volume, --box and --cell are for flat contact tables; "
                             "a LAMMPS/LIGGGHTS dump has its box")
        if snapshots is not None:
            raise InputError("a selection of snapshots is for dumps; a LAMMPS/LIGGGHTS dump is read whole")
        snaps = read_text_dump(path, fmt, atoms)
        return len(snaps), iter(snaps), lambda: None, None
    ext = os.path.splitext(path)[1].lower()
    if ext in (".csv", ".parquet", ".pq"):
        if snapshots is not None:
            raise InputError("a selection of snapshots is for dumps; a contact table is read whole")
        snaps = read_contact_table(path, volume=volume, box=box, cell=cell)
        return len(snaps), iter(snaps), lambda: None, None
    if volume is not None or box is not None or cell is not None:
        raise InputError("--volume, --box and --cell are for flat contact tables; "
                         "a dump has its box")
    reader = DumpReader(path)
    if len(reader) == 0:
        reader.close()
        raise InputError(f"{path}: the dump holds no snapshots")
    chosen = range(len(reader)) if snapshots is None else sorted(set(int(k) for k in snapshots))
    if snapshots is not None and not (chosen and 0 <= chosen[0] and chosen[-1] < len(reader)):
        reader.close()
        raise InputError(f"{path}: snapshots {list(snapshots)} are not among its {len(reader)} snapshots")

    def gen():
        for i in chosen:
            try:
                yield reader.read(i)
            except DumpFormatError as exc:
                yield exc

    try:
        shapes = reader.shapes()
    except DumpFormatError:
        reader.close()
        raise
    return len(chosen), gen(), reader.close, shapes


def pooled_force_pdf(forces):
    """Long table (class, binning, x, pdf, pdf_weighted, count) of the densities of f_n/<f_n>
    over the pooled snapshots, each snapshot normalised by its own mean
    over all its force-bearing particle-particle contacts: class "all" and
    each contact class and group present. ``forces`` is a list of
    (normal_force (C,), labels (C,))."""

    x = np.concatenate([f / f.mean() for f, _ in forces])
    lab = np.concatenate([lab for _, lab in forces])
    log_bins = np.geomspace(max(x[x > 0].min(), 1e-4), x.max() * (1 + 1e-9), 31)
    lin_bins = np.linspace(0, x.max() * (1 + 1e-9), 31)
    frames = []
    groups = group_labels_of(lab)
    for name, sel in [("all", np.ones(len(x), bool))] + \
            [(k, lab == k) for k in np.unique(lab)] + \
            [(g, groups == g) for g in np.unique(groups) if g not in np.unique(lab)]:
        if sel.sum() == 0:
            continue
        for binning, bins in (("log", log_bins), ("linear", lin_bins)):
            c, d = force_pdf(x[sel], mean=1.0, bins=bins)
            if binning == "linear":
                c = 0.5 * (bins[:-1] + bins[1:])
            # density of the class alone, and weighted by its share so the
            # classes add up to the "all" curve
            frames.append(pd.DataFrame({"class": name, "binning": binning, "x": c, "pdf": d,
                                        "pdf_weighted": d * sel.mean(), "count": int(sel.sum())}))
    return pd.concat(frames, ignore_index=True)


def reference_index(stages):
    """The snapshot whose box is zero strain: the last "isotropic" one (the
    state from which shear starts), else the first "shear" one, else 0."""
    iso = [k for k, s in enumerate(stages) if s == "isotropic"]
    if iso:
        return iso[-1]
    return next((k for k, s in enumerate(stages) if s == "shear"), 0)


#: the figures of an analysis (:func:`analyze_path`; some only with contact types)
FIGURE_FILES = ("qp_sff.png", "anisotropies.png", "polar_last.png", "force_pdf.png", "networks.png",
                "contact_types.png", "footprint.png")


@dataclass(frozen=True)
class AnalysisOptions:
    """How to analyse an input (the options of ``postproc analyze``).

    Attributes
    ----------
    axis : "x", "y", "z" or a vector, the compression axis.
    volume : float, m^3, the volume of a flat contact table.
    box : (3,) m, the walls' box of a flat contact table.
    cell : (3,) m, the periodic cell of a flat contact table (dumps carry
        their own box or cell).
    fmt : "liggghts-local" or "lammps-local" (default: detected).
    atoms : the LAMMPS ``dump custom`` with the positions.
    nbins : theta bins on [0, 90 deg].
    errors : compute standard errors.
    types : contact-type criterion of polyhedra, a name of the registry
        :data:`postproc.classify.CRITERIA` (default
        :data:`postproc.classify.DEFAULT_METHOD`, our count of contact points
        from the overlap), which says what each is.
    tolerance : the parameter of a criterion that takes ``--tolerance``
        (its ``parameter`` and ``default`` in the registry; None: its default).
    threshold : "footprint" threshold, in units of the pair size d.
    theta_deg : "angular" tolerance, degrees.
    snapshots : indices of a dump's snapshots to analyse (None: all); the
        strains are from the last isotropic one among them (give it too).
    figures : draw the figures (False: the same files without the figures,
        for numbers only; on a small dump the figures take most of the time).
    """
    axis: object = "z"
    volume: float | None = None
    box: tuple | None = None
    cell: tuple | None = None
    fmt: str | None = None
    atoms: str | None = None
    nbins: int = 18
    errors: bool = True
    types: str = DEFAULT_METHOD
    tolerance: float | None = None
    threshold: float | None = None
    theta_deg: float | None = None
    snapshots: tuple | None = None
    figures: bool = True

    def check(self):
        """Raise InputError (one line) for options that cannot work."""

        if self.nbins < 2:
            raise InputError("--bins must be at least 2")
        if self.volume is not None and not (np.isfinite(self.volume) and self.volume > 0):
            raise InputError(f"--volume must be finite and > 0, got {self.volume}")
        check_options(self.types, self.threshold, self.theta_deg, self.tolerance)


def analyze_path(path, out, options=AnalysisOptions(), progress=None):
    """Analyse every snapshot of ``path`` (a dump, a flat table or a
    LAMMPS/LIGGGHTS local dump) with :class:`AnalysisOptions` ``options``
    and write ``out/summary.csv`` (one row per snapshot) and the figures
    (:data:`FIGURE_FILES`; without ``options.figures``, none; a figure of
    that list an earlier analysis left in ``out`` and this one did not draw
    is removed).
    For a dump of polyhedra also the contact types
    (:class:`postproc.classify.Classifier`), ``force_pdf.csv`` and their
    figures, and ``source.json``: the input's files, the options and the
    code it was made from (:mod:`postproc.provenance`). Outputs go to a
    temporary folder first and are moved into ``out`` at the end. Returns
    (n_good, list of error lines); raises InputError when nothing could be
    analysed."""

    o = options
    o.check()
    try:
        source = stamp(path, o)             # before reading: what the analysis is made from
    except OSError:
        source = None
    try:
        e = axis_vector(o.axis)
    except ValueError as exc:
        raise InputError(f"--axis: {exc}") from None
    count, snaps, close, shapes = open_source(path, o.volume, o.box, o.cell, o.fmt, o.atoms, o.snapshots)
    try:
        tables = classifier_for(shapes, o.types, o.threshold, o.theta_deg, o.tolerance)
    except InputError as exc:
        close()
        raise InputError(f"{path}: /shapes: {exc}") from None
    rows, lengths, stages, last, problems, forces = [], [], [], None, [], []
    fps = []                   # footprint extents over d of each snapshot (footprint criterion)
    try:
        from tqdm import tqdm  # the progress bar: imported only when a run is analysed

        bar = tqdm(snaps, total=count, unit="snapshot", file=sys.stderr,
                   disable=(count < 5) if progress is None else not progress)
        for snap in bar:
            if isinstance(snap, Exception):
                problems.append(str(snap))
                continue
            try:
                res = analyze_snapshot(snap, axis=e, nbins=o.nbins, errors=o.errors, tables=tables)
            except BAD_INPUT as exc:
                problems.append(str(exc) if str(exc).startswith(("snapshot", path))
                                else f"snapshot {snap.name}: {exc}")
                continue
            rows.append(res.row)
            lengths.append(snap.box_lengths)
            stages.append(snap.stage)
            last = (snap, res)
            forces.append((res.normal_force, res.labels))
            fps.append(res.extents)
    finally:
        close()
    if not rows:
        raise InputError("no snapshot could be analysed: " + "; ".join(problems[:3]))
    ref = reference_index(stages)
    add_strains(rows, np.array(lengths), lengths[ref], e)
    df = pd.DataFrame(rows)
    df = df[list(LEAD) + [c for c in df.columns if c not in LEAD]]      # the schema's leading columns first

    label = os.path.basename(path)
    parent = os.path.dirname(os.path.abspath(out)) or "."
    os.makedirs(parent, exist_ok=True)
    tmp = tempfile.mkdtemp(prefix=".postproc-", dir=parent)
    try:
        df.to_csv(os.path.join(tmp, "summary.csv"), index=False)
        pool = steady_indices(df["eps_q"], df["stage"])
        pdf = pooled_force_pdf([forces[k] for k in pool])
        pdf.to_csv(os.path.join(tmp, "force_pdf.csv"), index=False)
        if o.figures:
            _figures(tmp, df, last, pdf, pool, fps, label)
        if problems:
            with open(os.path.join(tmp, "errors.txt"), "w") as fh:
                fh.write("\n".join(problems) + "\n")
        if source is not None:
            with open(os.path.join(tmp, SOURCE_FILE), "w") as fh:
                json.dump(source, fh, indent=1)
        os.makedirs(out, exist_ok=True)
        for name, keep in (("errors.txt", problems), (SOURCE_FILE, source is not None),
                           *((f, os.path.exists(os.path.join(tmp, f))) for f in FIGURE_FILES)):
            stale = os.path.join(out, name)
            if not keep and os.path.exists(stale):
                os.remove(stale)
        for name in os.listdir(tmp):
            os.replace(os.path.join(tmp, name), os.path.join(out, name))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return len(rows), problems


def _figures(tmp, df, last, pdf, pool, fps, label):
    """The figures of an analysis (:func:`analyze_path`) into the folder
    ``tmp``: q/p and the solid fraction, the anisotropies, the polar
    diagrams of the last snapshot, the pooled force densities, the
    networks and, with contact types, their proportions and footprints."""
    plots.plot_qp_sff(df, os.path.join(tmp, "qp_sff.png"), label)
    plots.plot_anisotropies(df, os.path.join(tmp, "anisotropies.png"), label)
    snap, res = last
    plots.plot_polar(res.angular, res.fits, os.path.join(tmp, "polar_last.png"),
                     f"{label}: snapshot {snap.name} (step {snap.step})")
    what = (f"{label}: snapshots {df['snapshot'].iloc[pool[0]]}-{df['snapshot'].iloc[pool[-1]]}"
            f" pooled ({len(pool)})")
    plots.plot_force_pdf(pdf, os.path.join(tmp, "force_pdf.png"), what)
    plots.plot_networks(df, os.path.join(tmp, "networks.png"), label)
    if "ct_method" in df:
        plots.plot_contact_types(df, os.path.join(tmp, "contact_types.png"), label)
        ext = [fps[k] for k in pool if fps[k] is not None and len(fps[k])]
        option = CRITERIA[df["ct_method"].iloc[0]].option
        if ext and option != "--theta":
            # the footprint threshold: the criterion's own when it is its parameter
            t = float(df["ct_threshold"].iloc[0]) if option == "--threshold" else fpm.DEFAULT_THRESHOLD
            plots.plot_footprint(np.concatenate(ext), t, os.path.join(tmp, "footprint.png"), what)
