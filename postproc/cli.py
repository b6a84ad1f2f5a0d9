"""Command line: ``postproc analyze PATH --out DIR``.

Exit codes: 0 all snapshots analysed; 1 some snapshots were bad (the good
ones are written, the bad ones listed in ``DIR/errors.txt`` and on stderr);
2 nothing could be analysed (bad file or options; nothing written).
"""
from __future__ import annotations

import argparse
import os
import sys

from .errors import InputError
from .many import analyze_many
from .pipeline import BAD_INPUT, AnalysisOptions, analyze_path
from .schema import DumpReader
from .synthetic import write_synthetic_dump
from .vtk import export_vtk
from .study.report import build_report


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
    an.add_argument("--types", choices=("points", "footprint", "angular", "commonplane", "lmgc90",
                                        "lmgc90-planplan", "lmgc90-2009"), default="points",
                    help="contact-type criterion (polyhedra): a count of contact points from the "
                         "overlap (default), the overlap's footprint, the angular one, our common-plane "
                         "band count, or LMGC90's own count (its CpCundall detection with today's point "
                         "stage, lmgc90, or the older planplan stage, lmgc90-planplan, or planplan with "
                         "the length-tolerant intersection it used before Clipper2, lmgc90-2009)")
    an.add_argument("--tolerance", type=float, default=None,
                    help="points criterion: alpha, the distance tolerance in units of the overlap's "
                         "mean thickness V/area (default 0.1); lmgc90, lmgc90-planplan, lmgc90-2009: the alert "
                         "distance in units of the smallest grain radius (default 0.1); commonplane: tau, the band in "
                         "units of the centre-to-extreme-vertex distance (default 0.1)")
    an.add_argument("--threshold", type=float, default=None,
                    help="footprint threshold in units of the pair size d (default 0.1)")
    an.add_argument("--theta", type=float, default=None,
                    help="angular tolerance in degrees: the criterion with --types angular, the "
                         "vertex/edge/face labels otherwise (default 5)")
    an.add_argument("--no-errors", action="store_true", help="skip standard errors (faster)")
    an.add_argument("--no-figures", action="store_true",
                    help="numbers only: the same tables without the figures (faster; most of a small dump's time)")
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
    rp.add_argument("--no-figures", action="store_true",
                    help="the report's tables and text without its figures (numbers only)")
    rs = sub.add_parser("results", help="the study's results as one JSON file, and the README's claims table")
    rs.add_argument("study", help="study folder with its report (report/claims.csv, comparison.csv, claim6.csv)")
    rs.add_argument("--out", required=True, help="results file to write (make results: "
                                                 "reference_data/default-study.json)")
    rs.add_argument("--readme", help="README whose generated claims table is rewritten from the results")
    rs.add_argument("--figure", help="copy the report's q/p figure (report/fig_qp.png) there")
    cr = sub.add_parser("compare-results", help="a study's results against the committed ones (the README's "
                                                "table): the same, or what differs")
    cr.add_argument("study", help="study folder with its report (make study: runs/study)")
    cr.add_argument("--reference", default=None, help="committed results (default: "
                                                      "reference_data/default-study.json)")
    sz = sub.add_parser("size-front", help="the study's quantities against the number of grains (several studies)")
    sz.add_argument("study", nargs="+", help="study folders of 'make study', one per number of grains")
    sz.add_argument("--out", required=True, help="output folder (size.md, size.csv, size-front.png, ...)")
    sh = sub.add_parser("shape-front", help="the study's quantities on two grain libraries (two studies at one size)")
    sh.add_argument("study", nargs="+", help="study folders of 'make study' at one number of grains: the reference "
                                              "(e.g. generated grains) first, then e.g. SHAPES=real stones")
    sh.add_argument("--out", required=True, help="output folder (shape.md, shape.csv, shape-front.png, ...)")
    sh.add_argument("--labels", nargs="+", help="a name per study (default: its S1 library's name)")
    lb = sub.add_parser("leaning-blocks", help="how the scatter of claim 6's leanings scales with the number of "
                                               "grains, from blocks of each packing (several studies)")
    lb.add_argument("study", nargs="+", help="study folders of 'make study', any numbers of grains")
    lb.add_argument("--types", nargs="+", default=["points", "lmgc90"],
                    help="the counts whose analyses are used (default points lmgc90)")
    lb.add_argument("--grids", nargs="+", type=int, default=[1, 2, 3, 4],
                    help="blocks per axis, 1 (the whole packing) included (default 1 2 3 4)")
    lb.add_argument("--min-grains", type=float, default=25.0,
                    help="least mean number of grains per block of a grid (default 25)")
    lb.add_argument("--out", default="runs/leaning-blocks",
                    help="output folder: blocks.csv, blocks.md, cache/ (default runs/leaning-blocks)")
    sa = sub.add_parser("size-at-strain", help="the study's quantities by number of grains, compared at the "
                                               "same axial strain")
    sa.add_argument("folder", nargs="+", help="folders searched for <sample>-seed<K>/summary.csv (a study, "
                                              "or the --out of postproc analyze)")
    sa.add_argument("--sample", default="polyhedra", choices=("polyhedra", "spheres"))
    sa.add_argument("--bins", type=float, nargs="+", default=[0.04, 0.075, 0.105, 0.145],
                    help="increasing edges of eps_1 (default 0.04 0.075 0.105 0.145)")
    sa.add_argument("--out", default="runs/size-at-strain",
                    help="output folder: size-at-strain.csv and .md (default runs/size-at-strain)")
    af = sub.add_parser("analysis-front", help="speed against error of the analysis estimators on synthetic "
                                               "contact sets with known anisotropies")
    af.add_argument("--out", default="runs/front-analysis",
                    help="output folder: analysis_front.csv and .png (default runs/front-analysis)")
    af.add_argument("--reps", type=int, default=40, help="synthetic sets per sample size (default 40)")
    c6 = sub.add_parser("claim6-criteria", help="claim 6 on one study, decided with each contact-type criterion "
                                                "(and, with --tolerance, the leanings' stability)")
    c6.add_argument("study", help="study folder written by 'make study' (holds manifest.json); the analyses and "
                                  "claim6.md go to STUDY/claim6")
    c6.add_argument("--types", nargs="+", default=["points", "commonplane"],
                    help="the criteria, as for analyze --types (default points commonplane)")
    c6.add_argument("--tolerance", nargs="+", type=float, default=[None],
                    help="the criterion's tolerance (points: alpha; commonplane: tau); default its own")
    lm = sub.add_parser("lmgc90-agreement", help="our counts of contact points against LMGC90's compiled code, "
                                                 "on the committed packing fixtures")
    lm.add_argument("--out", default="runs/lmgc90",
                    help="output folder: lmgc90_agreement.csv and .md (default runs/lmgc90)")
    lm.add_argument("--fixtures", help="folder of the packing-*.npz fixtures (default tests/data/lmgc90)")
    al = sub.add_parser("al-investigation", help="why the branch-length anisotropy a_l is about 0: its "
                                                 "estimators, subsets and geometric model, printed")
    al.add_argument("dump", nargs="+", help="RUN.h5 dumps (their steady snapshots are pooled)")
    al.add_argument("--axis", default="z", help="compression axis: x, y or z (default z)")
    al.add_argument("--pairs", type=int, default=20000,
                    help="random pairs for the isotropic geometric model (default 20000)")
    tk = sub.add_parser("contact-types-kappa", help="contact types against the contact stiffness: the point "
                                                    "count and the common-plane count on the same dumps")
    tk.add_argument("out", help="output folder: the analyses, contact_types_kappa.csv and .md")
    tk.add_argument("dump", nargs="+", help="kernel S1 dumps (RUN.h5), e.g. a front's")
    tk.add_argument("--from-eps1", type=float, default=0.1,
                    help="the shear snapshots with eps_1 from this on are averaged (default 0.1)")
    cr = sub.add_parser("commonplane-reference", help="the common-plane count with its band measured from "
                                                      "the extreme vertex and along the normal")
    cr.add_argument("out", help="output folder: commonplane_reference.csv and .md")
    cr.add_argument("dump", nargs="+", help="S1 dumps (RUN.h5)")
    cr.add_argument("--from-eps1", type=float, default=0.1,
                    help="the shear snapshots with eps_1 from this on are classified (default 0.1)")
    cr.add_argument("--every", type=int, default=1, help="every n-th of those snapshots (default 1)")
    cr.add_argument("--tau", type=float, default=0.1, help="the band tau, units of ref (default 0.1)")
    fp = sub.add_parser("facepair-tilt", help="the face-pair tilt against the overlap thickness of kernel S1 "
                                              "dumps (python -m yade_scripts.campaign.facepair_sweep runs its plan first)")
    fp.add_argument("out", help="output folder: facepair_tilt.csv(.gz), .md and the figure")
    fp.add_argument("dump", nargs="+", help="kernel S1 dumps (RUN.h5), one per kappa and seed")
    fp.add_argument("--from-eps1", type=float, default=0.1,
                    help="the shear snapshots with eps_1 from this on are used (default 0.1)")
    fp.add_argument("--figure", help="the figure's PNG (default OUT/facepair-tilt.png)")
    rt = sub.add_parser("random-types", help="the pair types of random contacts between library grains (the "
                                             "geometric chance), angular criterion at theta/2, theta, 2 theta")
    rt.add_argument("--library", default="runs/shapes/library.h5",
                    help="the shape library (default runs/shapes/library.h5, make shapes)")
    rt.add_argument("--pairs", type=int, default=100_000, help="random contacts classified (default 100000)")
    ts = sub.add_parser("timestep-front", help="the time step's cost and error, paired by seed, from the "
                                               "runs of the timestep plan (python -m yade_scripts.campaign.timestep_sweep)")
    ts.add_argument("out", help="the front's folder (front-plan.json, the analysed runs); timestep.csv and .md "
                                "are written there")
    ts.add_argument("--reference", type=float, default=0.3,
                    help="the safety the others are compared with (default 0.3)")
    vt = sub.add_parser("export-vtk", help="VTK files (particles, contacts) per snapshot for ParaView")
    vt.add_argument("path", help="RUN.h5 dump")
    vt.add_argument("outdir", help="output folder")
    vt.add_argument("--types", choices=("points", "footprint", "angular", "commonplane", "lmgc90",
                                        "lmgc90-planplan", "lmgc90-2009"), default="points",
                    help="contact-type criterion (default points)")
    vt.add_argument("--tolerance", type=float, default=None, help="points tolerance alpha (units of V/area), commonplane tau, or the lmgc90 "
                         "alert distance (units of the smallest grain radius)")
    vt.add_argument("--threshold", type=float, default=None, help="footprint threshold, units of d")
    vt.add_argument("--theta", type=float, default=None, help="angular tolerance, degrees")
    vt.add_argument("--snapshots", type=int, nargs="+", help="snapshot indices (default all; -1 = last)")
    args = ap.parse_args(argv)
    if args.cmd == "report":

        if not os.path.isdir(args.study):
            print(f"postproc: error: {args.study}: no such study folder", file=sys.stderr)
            return 2
        try:
            path = build_report(args.study, args.out, figures=not args.no_figures)
        except InputError as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(f"postproc: report written to {path} (and report.html)", file=sys.stderr)
        return 0
    if args.cmd == "compare-results":
        from .study.results import RESULTS, collect, compare, load_results

        ref_path = args.reference or RESULTS
        try:
            reference = load_results(ref_path)
            if reference is None:
                raise InputError(f"{ref_path}: no committed results to compare with")
            differences = compare(collect(args.study), reference)
        except (InputError, OSError, ValueError, KeyError) as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        if not differences:
            print(f"same as the README: every verdict, and every number at the table's precision, equals "
                  f"{os.path.relpath(ref_path)}")
            return 0
        print(f"differs from {os.path.relpath(ref_path)} (the README's table) in {len(differences)} place(s):")
        for line in differences:
            print(f"  {line}")
        print("A run on another machine can follow another trajectory from its first differing bit (numpy and "
              "glibc's libm choose their code by the CPU): numbers move within their intervals and a verdict "
              "near its threshold can change (docs/study.md, \"Reproducing the committed results\").")
        return 1
    if args.cmd == "results":
        from .study.results import update_readme, write_results

        try:
            results = write_results(args.study, args.out, figure=args.figure)
            changed = update_readme(args.readme, results) if args.readme else False
        except (InputError, OSError) as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(f"postproc: results written to {args.out}"
              + (f"; {args.readme}'s claims table {'rewritten' if changed else 'unchanged'}" if args.readme else "")
              + (f"; figure {args.figure}" if args.figure else ""), file=sys.stderr)
        return 0
    if args.cmd == "shape-front":
        from .study.shapefront import write_shape_front

        if args.labels and len(args.labels) != len(args.study):
            print(f"postproc: error: {len(args.labels)} labels for {len(args.study)} studies", file=sys.stderr)
            return 2
        try:
            path = write_shape_front(args.study, args.out, labels=args.labels)
        except BAD_INPUT as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(f"postproc: shape front written to {path} (and shape-front.png)", file=sys.stderr)
        return 0
    if args.cmd == "size-front":
        from .study.sizefront import write_size_front

        try:
            path = write_size_front(args.study, args.out)
        except BAD_INPUT as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(f"postproc: size front written to {path} (and size-front.png)", file=sys.stderr)
        return 0
    if args.cmd == "leaning-blocks":
        from .study.leaning import write_blocks

        try:
            text = write_blocks(args.study, args.out, types=args.types, grids=args.grids,
                                min_grains=args.min_grains)
        except BAD_INPUT as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(text)
        return 0
    if args.cmd == "size-at-strain":
        from .study.sizestrain import write_size_at_strain

        try:
            text = write_size_at_strain(args.folder, args.out, sample=args.sample, bins=args.bins)
        except BAD_INPUT as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(text)
        return 0
    if args.cmd == "claim6-criteria":
        from .study.claim6 import write_claim6

        try:
            text = write_claim6(args.study, args.types, args.tolerance)
        except BAD_INPUT as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(text, flush=True)
        return 0
    if args.cmd == "lmgc90-agreement":
        from .study.lmgc90 import FIXTURES, write_agreement

        try:
            text = write_agreement(args.out, args.fixtures or FIXTURES)
        except BAD_INPUT as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(text)
        return 0
    if args.cmd == "al-investigation":
        from .study.alinvestigation import investigate

        investigate(args.dump, args.axis, args.pairs)
        return 0
    if args.cmd == "contact-types-kappa":
        from .study.typeskappa import write_types_kappa

        try:
            text = write_types_kappa(args.out, args.dump, args.from_eps1)
        except BAD_INPUT as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(text)
        return 0
    if args.cmd == "commonplane-reference":
        from .study.commonplaneref import write_reference

        try:
            text = write_reference(args.out, args.dump, args.from_eps1, args.every, args.tau)
        except BAD_INPUT as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(text)
        return 0
    if args.cmd == "facepair-tilt":
        from .study.facepair import write_facepair

        try:
            text = write_facepair(args.out, args.dump, args.from_eps1, args.figure)
        except BAD_INPUT as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(text)
        return 0
    if args.cmd == "random-types":
        from shapes.library import ShapeLibrary

        from .study.randomtypes import lines, random_type_fractions

        try:
            lib = ShapeLibrary(args.library)
        except (OSError, ValueError, KeyError) as exc:
            print(f"postproc: error: {args.library}: {exc}", file=sys.stderr)
            return 2
        print("\n".join(lines(random_type_fractions(lib, pairs=args.pairs))))
        return 0
    if args.cmd == "timestep-front":
        from .study.timestepfront import write_timestep_front

        try:
            text = write_timestep_front(args.out, reference=args.reference)
        except BAD_INPUT as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(text)
        return 0
    if args.cmd == "analysis-front":
        from .study.front import ANALYSIS_FRONT_COLUMNS, write_analysis_front

        table = write_analysis_front(args.out, reps=args.reps)
        print(table[list(ANALYSIS_FRONT_COLUMNS)].to_string(index=False, float_format=lambda x: f"{x:.3g}"))
        return 0
    if args.cmd == "export-vtk":

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

        try:
            write_synthetic_dump(args.path, args.contacts, args.snapshots, tuple(args.final),
                                 seed=args.seed)
        except (ValueError, OSError) as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(f"postproc: wrote synthetic dump {args.path}", file=sys.stderr)
        return 0
    options = AnalysisOptions(axis=args.axis, volume=args.volume, box=args.box, cell=args.cell, fmt=args.format,
                              atoms=args.atoms, nbins=args.bins, errors=not args.no_errors, types=args.types,
                              tolerance=args.tolerance, threshold=args.threshold, theta_deg=args.theta,
                              figures=not args.no_figures)
    if len(args.path) > 1 or os.path.isdir(args.path[0]) or args.jobs != 1:
        return _analyze_many(args, options)
    try:
        n, problems = analyze_path(args.path[0], args.out, options, progress=args.progress)
    except BAD_INPUT as exc:
        print(f"postproc: error: {exc}", file=sys.stderr)
        return 2
    for line in problems:
        print(f"postproc: error: {line}", file=sys.stderr)
    print(f"postproc: analysed {n} snapshot(s) of {args.path[0]} -> {args.out}"
          + (f"; {len(problems)} bad snapshot(s), see {args.out}/errors.txt" if problems else ""),
          file=sys.stderr)
    return 1 if problems else 0


def _analyze_many(args, options):
    """``postproc analyze`` with several inputs, a folder or ``--jobs``:
    the same options for every input (:func:`postproc.many.analyze_many`).
    Returns the exit code (0 all good, 1 some files or snapshots bad, 2
    nothing analysed)."""

    try:
        if options.atoms is not None:
            raise InputError("--atoms names the positions of one LAMMPS dump; analyse "
                             "LAMMPS dumps one at a time")
        options.check()
        done, errors = analyze_many(args.path, args.out, jobs=args.jobs, options=options)
    except BAD_INPUT as exc:
        print(f"postproc: error: {exc}", file=sys.stderr)
        return 2
    for line in errors:
        print(f"postproc: error: {line}", file=sys.stderr)
    print(f"postproc: analysed {done} file(s) -> {args.out}/summary.csv"
          + (f"; {len(errors)} problem(s), see {args.out}/errors.txt" if errors else ""),
          file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
