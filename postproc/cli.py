"""Command line: ``postproc analyze PATH --out DIR``.

Exit codes: 0 all snapshots analysed; 1 some snapshots were bad (the good
ones are written, the bad ones listed in ``DIR/errors.txt`` and on stderr);
2 nothing could be analysed (bad file or options; nothing written).
"""
from __future__ import annotations

import argparse
import os
import shutil
import sys
import tempfile

import numpy as np

from .errors import InputError
from .schema import DumpFormatError, DumpReader

BAD_INPUT = (InputError, DumpFormatError)


def _open_source(path, volume, box, cell=None, fmt=None, atoms=None):
    """(count, iterator of Snapshot or exception, close, shapes) for a dump
    or table; ``shapes`` is the dump's (vertices, triangles, faces) or None."""
    from .lammpsdump import read_text_dump, sniff

    if fmt is not None or atoms is not None or sniff(path) is not None:
        if volume is not None or box is not None or cell is not None:
            raise InputError("--volume, --box and --cell are for flat contact tables; "
                             "a LAMMPS/LIGGGHTS dump has its box")
        snaps = read_text_dump(path, fmt, atoms)
        return len(snaps), iter(snaps), lambda: None, None
    ext = os.path.splitext(path)[1].lower()
    if ext in (".csv", ".parquet", ".pq"):
        from .tables import read_contact_table

        snaps = read_contact_table(path, volume=volume, box=box, cell=cell)
        return len(snaps), iter(snaps), lambda: None, None
    if volume is not None or box is not None or cell is not None:
        raise InputError("--volume, --box and --cell are for flat contact tables; "
                         "a dump has its box")
    reader = DumpReader(path)
    if len(reader) == 0:
        reader.close()
        raise InputError(f"{path}: the dump holds no snapshots")

    def gen():
        for i in range(len(reader)):
            try:
                yield reader.read(i)
            except DumpFormatError as exc:
                yield exc

    try:
        shapes = reader.shapes()
    except DumpFormatError:
        reader.close()
        raise
    return len(reader), gen(), reader.close, shapes


def pooled_force_pdf(forces):
    """Long table (class, binning, x, pdf, pdf_weighted, count) of the densities of f_n/<f_n>
    over the pooled snapshots, each snapshot normalised by its own mean
    over all its force-bearing particle-particle contacts: class "all" and
    each contact class and group present. ``forces`` is a list of
    (normal_force (C,), labels (C,))."""
    import pandas as pd

    from .analysis import group_labels_of
    from .networks import force_pdf

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


def analyze_path(path, out, axis="z", volume=None, box=None, nbins=18,
                 errors=True, progress=None, theta_deg=None, types="points", threshold=None,
                 cell=None, fmt=None, atoms=None, tolerance=None):
    """Analyse every snapshot of ``path`` and write ``out/summary.csv`` and
    the figures. For a dump of polyhedra also the contact types
    (:class:`postproc.classify.Classifier`: ``types`` "points", the
    default, LMGC90's count of contact points with ``tolerance`` alpha,
    "footprint" with ``threshold`` in units of the pair size, or "angular"
    with tolerance ``theta_deg``), ``force_pdf.csv`` and their figures. Returns
    (n_good, list of error lines)."""
    from . import footprint as fpm
    from .classify import classifier_for, check_options

    check_options(types, threshold, theta_deg, tolerance)
    import pandas as pd

    from . import plots
    from .analysis import add_strains, analyze_snapshot
    from .statistics import steady_indices

    if volume is not None and not (np.isfinite(volume) and volume > 0):
        raise InputError(f"--volume must be finite and > 0, got {volume}")
    try:
        from .axes import axis_vector

        e = axis_vector(axis)
    except ValueError as exc:
        raise InputError(f"--axis: {exc}") from None
    count, snaps, close, shapes = _open_source(path, volume, box, cell, fmt, atoms)
    try:
        tables = classifier_for(shapes, types, threshold, theta_deg, tolerance)
    except InputError as exc:
        close()
        raise InputError(f"{path}: /shapes: {exc}") from None
    rows, lengths, stages, last, problems, forces = [], [], [], None, [], []
    fps = []                   # footprint extents over d of each snapshot (footprint criterion)
    try:
        from tqdm import tqdm

        bar = tqdm(snaps, total=count, unit="snapshot", file=sys.stderr,
                   disable=(count < 5) if progress is None else not progress)
        for snap in bar:
            if isinstance(snap, Exception):
                problems.append(str(snap))
                continue
            try:
                res = analyze_snapshot(snap, axis=e, nbins=nbins, errors=errors,
                                       tables=tables)
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
    lead = ["step", "eps_1", "eps_q", "eps_v", "p", "q", "q_over_p", "a", "a_l",
            "a_n", "a_t", "sff", "sff_residual", "z", "n_contacts"]
    df = df[lead + [c for c in df.columns if c not in lead]]

    label = os.path.basename(path)
    parent = os.path.dirname(os.path.abspath(out)) or "."
    os.makedirs(parent, exist_ok=True)
    tmp = tempfile.mkdtemp(prefix=".postproc-", dir=parent)
    try:
        df.to_csv(os.path.join(tmp, "summary.csv"), index=False)
        plots.plot_qp_sff(df, os.path.join(tmp, "qp_sff.png"), label)
        plots.plot_anisotropies(df, os.path.join(tmp, "anisotropies.png"), label)
        snap, res = last
        plots.plot_polar(res.angular, res.fits, os.path.join(tmp, "polar_last.png"),
                         f"{label}: snapshot {snap.name} (step {snap.step})")
        pool = steady_indices(df["eps_q"], df["stage"])
        pdf = pooled_force_pdf([forces[k] for k in pool])
        pdf.to_csv(os.path.join(tmp, "force_pdf.csv"), index=False)
        what = (f"{label}: snapshots {df['snapshot'].iloc[pool[0]]}-{df['snapshot'].iloc[pool[-1]]}"
                f" pooled ({len(pool)})")
        plots.plot_force_pdf(pdf, os.path.join(tmp, "force_pdf.png"), what)
        plots.plot_networks(df, os.path.join(tmp, "networks.png"), label)
        if "ct_method" in df:
            plots.plot_contact_types(df, os.path.join(tmp, "contact_types.png"), label)
            ext = [fps[k] for k in pool if fps[k] is not None and len(fps[k])]
            if ext and df["ct_method"].iloc[0] != "angular":
                t = float(df["ct_threshold"].iloc[0]) if df["ct_method"].iloc[0] == "footprint" \
                    else fpm.DEFAULT_THRESHOLD
                plots.plot_footprint(np.concatenate(ext), t,
                                     os.path.join(tmp, "footprint.png"), what)
        if problems:
            with open(os.path.join(tmp, "errors.txt"), "w") as fh:
                fh.write("\n".join(problems) + "\n")
        os.makedirs(out, exist_ok=True)
        stale = os.path.join(out, "errors.txt")
        if not problems and os.path.exists(stale):
            os.remove(stale)
        for name in os.listdir(tmp):
            os.replace(os.path.join(tmp, name), os.path.join(out, name))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return len(rows), problems


def main(argv=None):
    ap = argparse.ArgumentParser(prog="postproc", description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    an = sub.add_parser("analyze", help="stress, fabric and force anisotropies of a dump or contact table")
    an.add_argument("path", nargs="+",
                    help="RUN.h5 dump, flat contact table (.csv / .parquet) or LAMMPS/LIGGGHTS "
                         "local dump; several paths or a folder: one output folder each and "
                         "a combined summary.csv with a source column")
    an.add_argument("--jobs", type=int, default=1,
                    help="inputs analysed in parallel processes (default 1)")
    an.add_argument("--out", required=True, help="output folder")
    an.add_argument("--axis", default="z", help="compression axis: x, y or z (default z)")
    an.add_argument("--volume", type=float, help="packing volume in m^3 (flat tables)")
    an.add_argument("--box", type=float, nargs=3, metavar=("LX", "LY", "LZ"),
                    help="box lengths in m (flat tables; gives volume and wall areas)")
    an.add_argument("--cell", type=float, nargs=3, metavar=("LX", "LY", "LZ"),
                    help="periodic cell lengths in m (flat tables): minimum-image branch "
                         "vectors, volume LX*LY*LZ unless --volume")
    an.add_argument("--format", choices=("liggghts-local", "lammps-local"), default=None,
                    help="text dump of LIGGGHTS pair/gran/local or LAMMPS pair/local "
                         "(default: detected from the header)")
    an.add_argument("--atoms", help="LAMMPS dump custom (id x y z) with the positions, "
                                    "for --format lammps-local")
    an.add_argument("--bins", type=int, default=18, help="theta bins on [0, 90 deg] (default 18)")
    an.add_argument("--types", choices=("points", "footprint", "angular"), default="points",
                    help="contact-type criterion (polyhedra): LMGC90's count of contact points "
                         "(default), the overlap's footprint, or the angular one")
    an.add_argument("--tolerance", type=float, default=None,
                    help="points criterion: alpha, the distance tolerance in units of the overlap's "
                         "mean thickness V/area (default 0.1)")
    an.add_argument("--threshold", type=float, default=None,
                    help="footprint threshold in units of the pair size d (default 0.1)")
    an.add_argument("--theta", type=float, default=None,
                    help="angular tolerance in degrees: the criterion with --types angular, the "
                         "vertex/edge/face labels otherwise (default 5)")
    an.add_argument("--no-errors", action="store_true", help="skip standard errors (faster)")
    an.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                    help="progress bar (default: on for 5 snapshots or more)")
    sy = sub.add_parser("synthetic", help="write a synthetic dump with known anisotropies (no simulation)")
    sy.add_argument("path", help="RUN.h5 to create")
    sy.add_argument("--contacts", type=int, default=20000)
    sy.add_argument("--snapshots", type=int, default=6)
    sy.add_argument("--final", type=float, nargs=4, default=(0.3, 0.1, 0.5, 0.2),
                    metavar=("A", "A_L", "A_N", "A_T"), help="anisotropies of the last snapshot")
    sy.add_argument("--seed", type=int, default=0)
    rp = sub.add_parser("report", help="the study report (figures, published values, the six claims)")
    rp.add_argument("study", help="study folder written by 'make study' (holds manifest.json)")
    rp.add_argument("--out", help="report folder (default STUDY/report)")
    vt = sub.add_parser("export-vtk", help="VTK files (particles, contacts) per snapshot for ParaView")
    vt.add_argument("path", help="RUN.h5 dump")
    vt.add_argument("outdir", help="output folder")
    vt.add_argument("--types", choices=("points", "footprint", "angular"), default="points",
                    help="contact-type criterion (default points)")
    vt.add_argument("--tolerance", type=float, default=None, help="points tolerance alpha, units of V/area")
    vt.add_argument("--threshold", type=float, default=None, help="footprint threshold, units of d")
    vt.add_argument("--theta", type=float, default=None, help="angular tolerance, degrees")
    vt.add_argument("--snapshots", type=int, nargs="+", help="snapshot indices (default all; -1 = last)")
    args = ap.parse_args(argv)
    if args.cmd == "report":
        from .report import build_report

        if not os.path.isdir(args.study):
            print(f"postproc: error: {args.study}: no such study folder", file=sys.stderr)
            return 2
        path = build_report(args.study, args.out)
        print(f"postproc: report written to {path} (and report.html)", file=sys.stderr)
        return 0
    if args.cmd == "export-vtk":
        from .vtk import export_vtk

        try:
            snaps = None
            if args.snapshots:
                with DumpReader(args.path) as r:
                    n = len(r)
                bad = [k for k in args.snapshots if not -n <= k < n]
                if bad:
                    raise InputError(f"--snapshots: index {bad[0]} out of range (the dump has {n})")
                snaps = [k % n for k in args.snapshots]
            files = export_vtk(args.path, args.outdir, args.theta, snaps, progress=True, types=args.types,
                               threshold=args.threshold, tolerance=args.tolerance)
        except BAD_INPUT as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(f"postproc: wrote {len(files)} files to {args.outdir} (open particles.pvd and "
              f"contacts.pvd in ParaView)", file=sys.stderr)
        return 0
    if args.cmd == "synthetic":
        from .synthetic import write_synthetic_dump

        try:
            write_synthetic_dump(args.path, args.contacts, args.snapshots, tuple(args.final),
                                 seed=args.seed)
        except (ValueError, OSError) as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(f"postproc: wrote synthetic dump {args.path}", file=sys.stderr)
        return 0
    try:
        if len(args.path) > 1 or os.path.isdir(args.path[0]) or args.jobs != 1:
            from .many import run_from_args

            return run_from_args(args)
        args.path = args.path[0]
        if args.bins < 2:
            raise InputError("--bins must be at least 2")
        n, problems = analyze_path(args.path, args.out, axis=args.axis, volume=args.volume,
                                   box=args.box, nbins=args.bins, errors=not args.no_errors,
                                   progress=args.progress, theta_deg=args.theta, types=args.types,
                                   threshold=args.threshold, cell=args.cell, tolerance=args.tolerance,
                                   fmt=args.format, atoms=args.atoms)
    except BAD_INPUT as exc:
        print(f"postproc: error: {exc}", file=sys.stderr)
        return 2
    for line in problems:
        print(f"postproc: error: {line}", file=sys.stderr)
    print(f"postproc: analysed {n} snapshot(s) of {args.path} -> {args.out}"
          + (f"; {len(problems)} bad snapshot(s), see {args.out}/errors.txt" if problems else ""),
          file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
