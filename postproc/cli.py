"""Command line: ``postproc analyze PATH --out DIR``, and the study's tools.

``postproc --help`` lists a user's commands first: ``analyze`` (a dump or
contact table), ``report`` (a study's report), ``results`` (a study's
results file and the README's table), ``compare-results`` (a study against
the committed results), ``export-vtk`` (ParaView files), ``import-lmgc90``
(an LMGC90 run's own output files as a dump), then ``synthetic``
(a test dump) and ``investigate``: the study's one-off investigations
(``postproc investigate --help`` lists them; docs/postproc.md), each once a
top-level command whose old spelling still runs, with a one-line note.

Every command is one entry of :data:`USER_COMMANDS`, :data:`TOOLS` or
:data:`INVESTIGATIONS` (its name, help, arguments and function); a
function returns the exit code and raises on bad input, and :func:`main`
turns any of :data:`ERRORS` into one line ``postproc: error: ...`` and
exit code 2.

Exit codes of ``analyze``: 0 all snapshots analysed; 1 some snapshots were
bad (the good ones are written, the bad ones listed in ``DIR/errors.txt``
and on stderr); 2 nothing could be analysed (bad file or options; nothing
written).
"""
from __future__ import annotations

import argparse
import os
import sys
from dataclasses import dataclass
from typing import Callable

from .classify import CRITERIA, DEFAULT_METHOD
from .errors import InputError
from .many import analyze_many
from .pipeline import BAD_INPUT, AnalysisOptions, analyze_path
from .schema import DumpReader
from .study.claim6 import DEFAULT_CRITERIA as CLAIM6_CRITERIA
from .study.leaning import DEFAULT_COUNTS as LEANING_COUNTS
from .study.report import build_report
from .synthetic import write_synthetic_dump
from .vtk import export_vtk

#: what a command may raise on bad input: one line on stderr, exit code 2
ERRORS = BAD_INPUT + (OSError, ValueError, KeyError)


@dataclass(frozen=True)
class Command:
    """One subcommand: ``postproc NAME ...`` (or ``postproc investigate NAME ...``).

    Attributes
    ----------
    name : str
        The subcommand.
    help : str
        One line for ``postproc --help``.
    arguments : callable
        ``arguments(parser)`` adds its arguments to an argparse parser.
    run : callable
        ``run(args)`` -> int, the exit code; raises one of :data:`ERRORS`
        (one line) on bad input.
    """

    name: str
    help: str
    arguments: Callable
    run: Callable


# ----------------------------------------------------------------- analyze

def _types_help():
    """analyze --types' help, from the registry of criteria."""
    return "contact-type criterion (polyhedra): " + "; ".join(
        f"{c.name}, {c.description}" for c in CRITERIA.values())


def _tolerance_help():
    """--tolerance's help: what it is for each criterion that takes it, from
    the registry (criteria with the same parameter named together)."""
    by = {}
    for c in CRITERIA.values():
        if c.option == "--tolerance":
            by.setdefault((c.parameter, c.default), []).append(c.name)
    return "; ".join(f"{', '.join(names)}: {parameter} (default {default:g})"
                     for (parameter, default), names in by.items())


def _analyze_arguments(an):
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
    an.add_argument("--types", choices=tuple(CRITERIA), default=DEFAULT_METHOD, help=_types_help())
    an.add_argument("--tolerance", type=float, default=None, help=_tolerance_help())
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


def _analyze(args):
    options = AnalysisOptions(axis=args.axis, volume=args.volume, box=args.box, cell=args.cell, fmt=args.format,
                              atoms=args.atoms, nbins=args.bins, errors=not args.no_errors, types=args.types,
                              tolerance=args.tolerance, threshold=args.threshold, theta_deg=args.theta,
                              figures=not args.no_figures)
    if len(args.path) > 1 or os.path.isdir(args.path[0]) or args.jobs != 1:
        return _analyze_many(args, options)
    n, problems = analyze_path(args.path[0], args.out, options, progress=args.progress)
    for line in problems:
        print(f"postproc: error: {line}", file=sys.stderr)
    print(f"postproc: analysed {n} snapshot(s) of {args.path[0]} -> {args.out}"
          + (f"; {len(problems)} bad snapshot(s), see {args.out}/errors.txt" if problems else ""),
          file=sys.stderr)
    return 1 if problems else 0


def _analyze_many(args, options):
    """``postproc analyze`` with several inputs, a folder or ``--jobs``:
    the same options for every input (:func:`postproc.many.analyze_many`).
    Returns the exit code (0 all good, 1 some files or snapshots bad); bad
    options raise."""
    if options.atoms is not None:
        raise InputError("--atoms names the positions of one LAMMPS dump; analyse "
                         "LAMMPS dumps one at a time")
    options.check()
    done, errors = analyze_many(args.path, args.out, jobs=args.jobs, options=options)
    for line in errors:
        print(f"postproc: error: {line}", file=sys.stderr)
    print(f"postproc: analysed {done} file(s) -> {args.out}/summary.csv"
          + (f"; {len(errors)} problem(s), see {args.out}/errors.txt" if errors else ""),
          file=sys.stderr)
    return 1 if errors else 0


# ------------------------------------------------ report, results, compare

def _report_arguments(rp):
    rp.add_argument("study", help="study folder written by 'make study' (holds manifest.json)")
    rp.add_argument("--out", help="report folder (default STUDY/report)")
    rp.add_argument("--no-figures", action="store_true",
                    help="the report's tables and text without its figures (numbers only)")


def _report(args):
    if not os.path.isdir(args.study):
        raise InputError(f"{args.study}: no such study folder")
    path = build_report(args.study, args.out, figures=not args.no_figures)
    print(f"postproc: report written to {path} (and report.html)", file=sys.stderr)
    return 0


def _results_arguments(rs):
    rs.add_argument("study", help="study folder with its report (report/claims.csv, comparison.csv, claim6.csv)")
    rs.add_argument("--out", required=True, help="results file to write (make results: "
                                                 "reference_data/default-study.json)")
    rs.add_argument("--readme", help="README whose generated claims table is rewritten from the results")
    rs.add_argument("--figure", help="copy the report's q/p figure (report/fig_qp.png) there")


def _results(args):
    from .study.results import update_readme, write_results

    results = write_results(args.study, args.out, figure=args.figure)
    changed = update_readme(args.readme, results) if args.readme else False
    print(f"postproc: results written to {args.out}"
          + (f"; {args.readme}'s claims table {'rewritten' if changed else 'unchanged'}" if args.readme else "")
          + (f"; figure {args.figure}" if args.figure else ""), file=sys.stderr)
    return 0


def _methods_arguments(cm):
    cm.add_argument("yade_study", help="the YADE study folder (its manifest.json and analyses)")
    cm.add_argument("cd_study", help="the Contact Dynamics study folder, of the same grains and starting states")
    cm.add_argument("--out", required=True, help="folder for methods.md and methods.json")
    cm.add_argument("--json", help="also write the comparison there (the README's source: "
                                   "reference_data/methods-1000.json)")
    cm.add_argument("--readme", help="README whose by-method table is rewritten from the comparison (needs "
                                     "--json: the block names that file)")


def _compare_methods(args):
    from .study.methods import write_methods
    from .study.methodsreadme import save, update_readme

    if args.readme and not args.json:
        raise InputError("compare-methods: --readme needs --json FILE (the README's block names the file it is "
                         "generated from)")
    result = write_methods(args.yade_study, args.cd_study, args.out)
    if args.json:
        save(result, args.json)
    source = os.path.relpath(os.path.abspath(args.json), os.path.dirname(os.path.abspath(args.readme))) \
        if args.readme else None
    changed = update_readme(args.readme, result, source) if args.readme else False
    print(f"postproc: {os.path.join(args.out, 'methods.md')} and methods.json written"
          + (f"; {args.json}" if args.json else "")
          + (f"; {args.readme}'s by-method table {'rewritten' if changed else 'unchanged'}" if args.readme else ""),
          file=sys.stderr)
    return 0


def _compare_arguments(cr):
    cr.add_argument("study", help="study folder with its report (make study: runs/study)")
    cr.add_argument("--reference", default=None, help="committed results (default: "
                                                      "reference_data/default-study.json)")


def _compare_results(args):
    from .study.results import RESULTS, collect, compare, load_results

    ref_path = args.reference or RESULTS
    reference = load_results(ref_path)
    if reference is None:
        raise InputError(f"{ref_path}: no committed results to compare with")
    differences = compare(collect(args.study), reference)
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


# ------------------------------------------------------ export-vtk, synthetic

def _vtk_arguments(vt):
    vt.add_argument("path", help="RUN.h5 dump")
    vt.add_argument("outdir", help="output folder")
    vt.add_argument("--types", choices=tuple(CRITERIA), default=DEFAULT_METHOD,
                    help=f"contact-type criterion, as for analyze (default {DEFAULT_METHOD})")
    vt.add_argument("--tolerance", type=float, default=None, help=_tolerance_help())
    vt.add_argument("--threshold", type=float, default=None, help="footprint threshold, units of d")
    vt.add_argument("--theta", type=float, default=None, help="angular tolerance, degrees")
    vt.add_argument("--snapshots", type=int, nargs="+", help="snapshot indices (default all; -1 = last)")


def _export_vtk(args):
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
    print(f"postproc: wrote {len(files)} files to {args.outdir} (open particles.pvd and "
          f"contacts.pvd in ParaView)", file=sys.stderr)
    return 0


def _synthetic_arguments(sy):
    sy.add_argument("path", help="RUN.h5 to create")
    sy.add_argument("--contacts", type=int, default=20000)
    sy.add_argument("--snapshots", type=int, default=6)
    sy.add_argument("--final", type=float, nargs=4, default=(0.3, 0.1, 0.5, 0.2),
                    metavar=("A", "A_L", "A_N", "A_T"), help="anisotropies of the last snapshot")
    sy.add_argument("--seed", type=int, default=0)


def _synthetic(args):
    write_synthetic_dump(args.path, args.contacts, args.snapshots, tuple(args.final), seed=args.seed)
    print(f"postproc: wrote synthetic dump {args.path}", file=sys.stderr)
    return 0


# ---------------------------------------------------------- investigations

def _cd_front_arguments(cf):
    cf.add_argument("run", nargs="+", help="CD run folders (lmgc90.triaxial's, or reference_data/cd-front/*): "
                                           "the first is the reference")
    cf.add_argument("--out", required=True, help="output folder (cd-front.md, .csv, .json)")
    cf.add_argument("--window", nargs=2, type=float, default=(0.1, 0.3), metavar=("EPS_LO", "EPS_HI"),
                    help="the steady window in eps_1 (default 0.1 0.3)")


def _cd_front(args):
    from .study.cdfront import write_front

    write_front(args.run, args.out, *args.window)
    print(f"postproc: CD front written to {os.path.join(args.out, 'cd-front.md')}", file=sys.stderr)
    return 0


def _size_front_arguments(sz):
    sz.add_argument("study", nargs="+", help="study folders of 'make study', one per number of grains")
    sz.add_argument("--out", required=True, help="output folder (size.md, size.csv, size-front.png, ...)")


def _size_front(args):
    from .study.sizefront import write_size_front

    path = write_size_front(args.study, args.out)
    print(f"postproc: size front written to {path} (and size-front.png)", file=sys.stderr)
    return 0


def _shape_front_arguments(sh):
    sh.add_argument("study", nargs="+", help="study folders of 'make study' at one number of grains: the reference "
                                              "(e.g. generated grains) first, then e.g. SHAPES=real stones")
    sh.add_argument("--out", required=True, help="output folder (shape.md, shape.csv, shape-front.png, ...)")
    sh.add_argument("--labels", nargs="+", help="a name per study (default: its S1 library's name)")


def _shape_front(args):
    from .study.shapefront import write_shape_front

    if args.labels and len(args.labels) != len(args.study):
        raise InputError(f"{len(args.labels)} labels for {len(args.study)} studies")
    path = write_shape_front(args.study, args.out, labels=args.labels)
    print(f"postproc: shape front written to {path} (and shape-front.png)", file=sys.stderr)
    return 0


def _leaning_arguments(lb):
    lb.add_argument("study", nargs="+", help="study folders of 'make study', any numbers of grains")
    lb.add_argument("--types", nargs="+", default=list(LEANING_COUNTS),
                    help=f"the counts whose analyses are used (default {' '.join(LEANING_COUNTS)})")
    lb.add_argument("--grids", nargs="+", type=int, default=[1, 2, 3, 4],
                    help="blocks per axis, 1 (the whole packing) included (default 1 2 3 4)")
    lb.add_argument("--min-grains", type=float, default=25.0,
                    help="least mean number of grains per block of a grid (default 25)")
    lb.add_argument("--out", default="runs/leaning-blocks",
                    help="output folder: blocks.csv, blocks.md, cache/ (default runs/leaning-blocks)")


def _leaning_blocks(args):
    from .study.leaning import write_blocks

    print(write_blocks(args.study, args.out, types=args.types, grids=args.grids, min_grains=args.min_grains))
    return 0


def _size_strain_arguments(sa):
    sa.add_argument("folder", nargs="+", help="folders searched for <sample>-seed<K>/summary.csv (a study, "
                                              "or the --out of postproc analyze)")
    sa.add_argument("--sample", default="polyhedra", choices=("polyhedra", "spheres"))
    sa.add_argument("--bins", type=float, nargs="+", default=[0.04, 0.075, 0.105, 0.145],
                    help="increasing edges of eps_1 (default 0.04 0.075 0.105 0.145)")
    sa.add_argument("--out", default="runs/size-at-strain",
                    help="output folder: size-at-strain.csv and .md (default runs/size-at-strain)")


def _size_at_strain(args):
    from .study.sizestrain import write_size_at_strain

    print(write_size_at_strain(args.folder, args.out, sample=args.sample, bins=args.bins))
    return 0


def _analysis_front_arguments(af):
    af.add_argument("--out", default="runs/front-analysis",
                    help="output folder: analysis_front.csv and .png (default runs/front-analysis)")
    af.add_argument("--reps", type=int, default=40, help="synthetic sets per sample size (default 40)")


def _analysis_front(args):
    from .study.front import ANALYSIS_FRONT_COLUMNS, write_analysis_front

    table = write_analysis_front(args.out, reps=args.reps)
    print(table[list(ANALYSIS_FRONT_COLUMNS)].to_string(index=False, float_format=lambda x: f"{x:.3g}"))
    return 0


def _claim6_arguments(c6):
    c6.add_argument("study", help="study folder written by 'make study' (holds manifest.json); the analyses and "
                                  "claim6.md go to STUDY/claim6")
    c6.add_argument("--types", nargs="+", default=list(CLAIM6_CRITERIA),
                    help=f"the criteria, as for analyze --types (default {' '.join(CLAIM6_CRITERIA)})")
    c6.add_argument("--tolerance", nargs="+", type=float, default=[None],
                    help="the criterion's tolerance, as for analyze --tolerance; default its own")


def _claim6_criteria(args):
    from .study.claim6 import write_claim6

    print(write_claim6(args.study, args.types, args.tolerance), flush=True)
    return 0


def _lmgc90_arguments(lm):
    lm.add_argument("--out", default="runs/lmgc90",
                    help="output folder: lmgc90_agreement.csv and .md (default runs/lmgc90)")
    lm.add_argument("--fixtures", help="folder of the packing-*.npz fixtures (default tests/data/lmgc90)")


def _lmgc90_agreement(args):
    from .study.lmgc90 import FIXTURES, write_agreement

    print(write_agreement(args.out, args.fixtures or FIXTURES))
    return 0


def _al_arguments(al):
    al.add_argument("dump", nargs="+", help="RUN.h5 dumps (their steady snapshots are pooled)")
    al.add_argument("--axis", default="z", help="compression axis: x, y or z (default z)")
    al.add_argument("--pairs", type=int, default=20000,
                    help="random pairs for the isotropic geometric model (default 20000)")


def _al_investigation(args):
    from .study.alinvestigation import investigate

    investigate(args.dump, args.axis, args.pairs)
    return 0


def _kappa_arguments(tk):
    tk.add_argument("out", help="output folder: the analyses, contact_types_kappa.csv and .md")
    tk.add_argument("dump", nargs="+", help="kernel S1 dumps (RUN.h5), e.g. a front's")
    tk.add_argument("--from-eps1", type=float, default=0.1,
                    help="the shear snapshots with eps_1 from this on are averaged (default 0.1)")


def _types_kappa(args):
    from .study.typeskappa import write_types_kappa

    print(write_types_kappa(args.out, args.dump, args.from_eps1))
    return 0


def _cpref_arguments(cr):
    cr.add_argument("out", help="output folder: commonplane_reference.csv and .md")
    cr.add_argument("dump", nargs="+", help="S1 dumps (RUN.h5)")
    cr.add_argument("--from-eps1", type=float, default=0.1,
                    help="the shear snapshots with eps_1 from this on are classified (default 0.1)")
    cr.add_argument("--every", type=int, default=1, help="every n-th of those snapshots (default 1)")
    cr.add_argument("--tau", type=float, default=0.1, help="the band tau, units of ref (default 0.1)")


def _commonplane_reference(args):
    from .study.commonplaneref import write_reference

    print(write_reference(args.out, args.dump, args.from_eps1, args.every, args.tau))
    return 0


def _facepair_arguments(fp):
    fp.add_argument("out", help="output folder: facepair_tilt.csv(.gz), .md and the figure")
    fp.add_argument("dump", nargs="+", help="kernel S1 dumps (RUN.h5), one per kappa and seed")
    fp.add_argument("--from-eps1", type=float, default=0.1,
                    help="the shear snapshots with eps_1 from this on are used (default 0.1)")
    fp.add_argument("--figure", help="the figure's PNG (default OUT/facepair-tilt.png)")


def _facepair_tilt(args):
    from .study.facepair import write_facepair

    print(write_facepair(args.out, args.dump, args.from_eps1, args.figure))
    return 0


def _random_arguments(rt):
    rt.add_argument("--library", default="runs/shapes/library.h5",
                    help="the shape library (default runs/shapes/library.h5, make shapes)")
    rt.add_argument("--pairs", type=int, default=100_000, help="random contacts classified (default 100000)")


def _random_types(args):
    from shapes.library import ShapeLibrary

    from .study.randomtypes import lines, random_type_fractions

    try:
        lib = ShapeLibrary(args.library)
    except (OSError, ValueError, KeyError) as exc:
        raise InputError(f"{args.library}: {exc}") from None
    print("\n".join(lines(random_type_fractions(lib, pairs=args.pairs))))
    return 0


def _timestep_arguments(ts):
    ts.add_argument("out", help="the front's folder (front-plan.json, the analysed runs); timestep.csv and .md "
                                "are written there")
    ts.add_argument("--reference", type=float, default=0.3,
                    help="the safety the others are compared with (default 0.3)")


def _timestep_front(args):
    from .study.timestepfront import write_timestep_front

    print(write_timestep_front(args.out, reference=args.reference))
    return 0


def _import_lmgc90_arguments(im):
    im.add_argument("run_dir", help="an LMGC90 run's folder, holding DATBOX/ and OUTBOX/ (DOF.OUT.n, Vloc_Rloc.OUT.n)")
    im.add_argument("out", help="the dump to write (must not exist); then: postproc analyze OUT --out DIR")


def _import_lmgc90(args):
    from .lmgc90files import convert
    from .schema import verify_dump

    n = convert(args.run_dir, args.out, progress=lambda line: print(line, file=sys.stderr))
    check = verify_dump(args.out)
    print(f"{args.out}: {n} snapshots from {args.run_dir} (verified: {check.n_snapshots} snapshots)")
    return 0


#: a user's commands, first in ``postproc --help``
USER_COMMANDS = (
    Command("analyze", "stress, fabric and force anisotropies of a dump or contact table",
            _analyze_arguments, _analyze),
    Command("report", "the study report (figures, published values, the six claims)", _report_arguments, _report),
    Command("results", "the study's results as one JSON file, and the README's claims table",
            _results_arguments, _results),
    Command("compare-results", "a study's results against the committed ones (the README's table): the same, "
                               "or what differs", _compare_arguments, _compare_results),
    Command("compare-methods", "the six claims and the contact types by method: a YADE study beside a Contact "
                               "Dynamics one of the same grains", _methods_arguments, _compare_methods),
    Command("export-vtk", "VTK files (particles, contacts) per snapshot for ParaView", _vtk_arguments, _export_vtk),
    Command("import-lmgc90", "an LMGC90 run's own output files (DATBOX/, OUTBOX/) as a contact dump, every CD "
                             "contact point kept", _import_lmgc90_arguments, _import_lmgc90),
)
#: the other top-level commands, after the user's
TOOLS = (
    Command("synthetic", "write a synthetic dump with known anisotropies (no simulation)",
            _synthetic_arguments, _synthetic),
)
#: the study's investigations: ``postproc investigate NAME ...`` (docs/postproc.md)
INVESTIGATIONS = (
    Command("cd-front", "CD runs of one state under several time steps and NLGS tolerances, side by side",
            _cd_front_arguments, _cd_front),
    Command("size-front", "the study's quantities against the number of grains (several studies)",
            _size_front_arguments, _size_front),
    Command("shape-front", "the study's quantities on two grain libraries (two studies at one size)",
            _shape_front_arguments, _shape_front),
    Command("leaning-blocks", "how the scatter of claim 6's leanings scales with the number of grains, from "
                              "blocks of each packing (several studies)", _leaning_arguments, _leaning_blocks),
    Command("size-at-strain", "the study's quantities by number of grains, compared at the same axial strain",
            _size_strain_arguments, _size_at_strain),
    Command("analysis-front", "speed against error of the analysis estimators on synthetic contact sets with "
                              "known anisotropies", _analysis_front_arguments, _analysis_front),
    Command("claim6-criteria", "claim 6 on one study, decided with each contact-type criterion (and, with "
                               "--tolerance, the leanings' stability)", _claim6_arguments, _claim6_criteria),
    Command("lmgc90-agreement", "our counts of contact points against LMGC90's compiled code, on the committed "
                                "packing fixtures", _lmgc90_arguments, _lmgc90_agreement),
    Command("al-investigation", "why the branch-length anisotropy a_l is about 0: its estimators, subsets and "
                                "geometric model, printed", _al_arguments, _al_investigation),
    Command("contact-types-kappa", "contact types against the contact stiffness: the point count and the "
                                   "common-plane count on the same dumps", _kappa_arguments, _types_kappa),
    Command("commonplane-reference", "the common-plane count with its band measured from the extreme vertex and "
                                     "along the normal", _cpref_arguments, _commonplane_reference),
    Command("facepair-tilt", "the face-pair tilt against the overlap thickness of kernel S1 dumps (python -m "
                             "yade_scripts.campaign.facepair_sweep runs its plan first)", _facepair_arguments, _facepair_tilt),
    Command("random-types", "the pair types of random contacts between library grains (the geometric chance), "
                            "angular criterion at theta/2, theta, 2 theta", _random_arguments, _random_types),
    Command("timestep-front", "the time step's cost and error, paired by seed, from the runs of the timestep "
                              "plan (python -m yade_scripts.campaign.timestep_sweep)", _timestep_arguments, _timestep_front),
)


def build_parser():
    """The argument parser of ``postproc``: the user's commands, the tools,
    ``investigate`` with the investigations, and the investigations' old
    top-level spellings (not listed; they run with a note).

    Returns
    -------
    argparse.ArgumentParser
        The parser; a parsed namespace carries ``command`` (the
        :class:`Command` to run) and ``old_spelling`` (None, or the old
        name the investigation was called by).
    """
    ap = argparse.ArgumentParser(prog="postproc", description="The analysis of a dump, a contact table or a study: "
                                 "a user's commands first, the study's investigations under 'postproc investigate'.")
    sub = ap.add_subparsers(dest="cmd", required=True, metavar="COMMAND", title="commands")
    for c in USER_COMMANDS + TOOLS:
        c.arguments(sub.add_parser(c.name, help=c.help, description=c.help))
        sub.choices[c.name].set_defaults(command=c, old_spelling=None)
    inv = sub.add_parser("investigate", help="the study's investigations: postproc investigate NAME ... "
                                             "(postproc investigate --help lists them)",
                         description="The study's one-off investigations (docs/postproc.md).")
    isub = inv.add_subparsers(dest="investigation", required=True, metavar="NAME", title="investigations")
    for c in INVESTIGATIONS:
        c.arguments(isub.add_parser(c.name, help=c.help, description=c.help))
        isub.choices[c.name].set_defaults(command=c, old_spelling=None)
        # the old spelling, postproc NAME ...: not listed (no help), the same arguments
        c.arguments(sub.add_parser(c.name, description=c.help))
        sub.choices[c.name].set_defaults(command=c, old_spelling=c.name)
    return ap


def main(argv=None):
    """``postproc``: parse ``argv`` and run the command.

    Parameters
    ----------
    argv : list of str or None, optional
        The arguments (None: ``sys.argv[1:]``).

    Returns
    -------
    int
        The command's exit code; 2 with one line ``postproc: error: ...`` on
        stderr when it raised one of :data:`ERRORS`. argparse exits (code 2)
        on unknown options, as it does.
    """
    args = build_parser().parse_args(argv)
    if args.old_spelling:
        print(f"postproc: note: 'postproc {args.old_spelling}' is now 'postproc investigate {args.old_spelling}'; "
              "the old spelling will be removed", file=sys.stderr)
    try:
        return args.command.run(args)
    except ERRORS as exc:
        print(f"postproc: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
