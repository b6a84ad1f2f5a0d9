"""``python -m shapes``: build, import and report shape libraries.

::

    python -m shapes build --n 1000 --seed 0 --out LIB.h5 [--report DIR]
                    [--like TARGET.h5 [--max-draws N] [--max-seconds S]]
    python -m shapes import MESH_OR_FOLDER... --out LIB.h5 [--report DIR]
                     [--vertices N | --max-error E] [--max-vertices M] [--components]
                     [--merge-tolerance T] [--name NAME]
    python -m shapes report LIB.h5 --report DIR [--against OTHER.h5]

Exit codes: 0 done; 1 (import) some meshes refused, the library holds the
others; 2 nothing written (bad options, an unreadable library, every mesh
refused).
"""
from __future__ import annotations

import argparse
import os
import sys
import time


def _tolerances():
    from . import polyhedron

    return {k: getattr(polyhedron, k) for k in
            ("VERTEX_TOL", "EDGE_TOL", "HEIGHT_TOL", "VOLUME_TOL", "CONVEX_TOL", "COPLANAR_DEG")}


def _err(msg):
    print(f"shapes: error: {msg}", file=sys.stderr)
    return 2


def _make_folder_of(out):
    """Make the folder of ``--out`` when missing and check that a file can
    be written there (before a build that may take minutes); the error
    message, or None."""
    try:
        os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    except OSError as exc:
        return f"cannot make the folder of --out {out}: {exc.strerror}"
    if os.path.isdir(out):
        return f"--out {out} is a folder, not a library file"
    probe = str(out) + ".tmp"
    try:
        with open(probe, "wb"):
            pass
        os.remove(probe)
    except OSError as exc:
        return f"cannot write --out {out}: {exc.strerror}"
    return None


def _parser():
    from .hullreduce import DEFAULT_MAX_ERROR, DEFAULT_MAX_VERTICES

    ap = argparse.ArgumentParser(prog="python -m shapes", description="ballast-like polyhedra libraries")
    sub = ap.add_subparsers(dest="cmd", required=True)
    b = sub.add_parser("build", help="generate a library and its report")
    b.add_argument("--n", type=int, default=1000, help="number of shapes (default 1000)")
    b.add_argument("--seed", type=int, default=0)
    b.add_argument("--out", required=True, help="library file (.h5)")
    b.add_argument("--report", help="folder for the report (default: next to the library)")
    b.add_argument("--like", metavar="TARGET.h5",
                   help="draw grains whose elongation, flatness and vertex counts follow this library's")
    b.add_argument("--max-draws", type=int, default=None, metavar="N",
                   help="with --like: generator draws allowed per grain before the build stops "
                        "(default 200)")
    b.add_argument("--max-seconds", type=float, default=3600.0, metavar="S",
                   help="with --like: wall-clock seconds allowed for all the grains (default 3600)")
    b.add_argument("--name", help="the library's name (default: the file's stem)")
    i = sub.add_parser("import", help="grains from mesh files (STL, OBJ, PLY, OFF)")
    i.add_argument("paths", nargs="+", metavar="MESH_OR_FOLDER")
    i.add_argument("--out", required=True, help="library file (.h5)")
    i.add_argument("--report", help="folder for the report (default: next to the library)")
    g = i.add_mutually_exclusive_group()
    g.add_argument("--vertices", type=int, metavar="N", help="reduce every grain to N vertices")
    g.add_argument("--max-error", type=float, metavar="E",
                   help=f"fewest vertices within E d of the hull (default {DEFAULT_MAX_ERROR})")
    i.add_argument("--max-vertices", type=int, default=DEFAULT_MAX_VERTICES,
                   help=f"at most this many vertices with --max-error (default {DEFAULT_MAX_VERTICES})")
    i.add_argument("--components", action="store_true",
                   help="each connected piece of a file is a grain (file#k, largest first); inward-facing "
                        "shells and slivers are refused as scan artefacts")
    i.add_argument("--merge-tolerance", type=float, default=0.0, metavar="T",
                   help="merge vertices closer than T, in the mesh's units (default 0: exact duplicates only)")
    i.add_argument("--name", help="the library's name (default: the file's stem)")
    r = sub.add_parser("report", help="report on an existing library, or two side by side")
    r.add_argument("library")
    r.add_argument("--report", required=True)
    r.add_argument("--against", metavar="OTHER.h5", help="a second library, compared side by side")
    return ap


def main(argv=None):
    """Run ``python -m shapes`` (module docstring).

    Parameters
    ----------
    argv : list of str, optional
        The command line after ``python -m shapes`` (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit code: 0 done; 1 (import) some meshes refused, the library
        holds the others; 2 nothing written. Bad options exit through
        argparse (SystemExit, code 2).
    """
    args = _parser().parse_args(argv)
    return {"build": _build, "import": _import, "report": _report}[args.cmd](args)


def _build(args):
    from .generate import Recipe, generate_library
    from .library import LibraryError, ShapeLibrary, write_library
    from .report import write_comparison, write_report

    if args.n < 1:
        return _err("--n must be at least 1")
    problem = _make_folder_of(args.out)
    if problem:
        return _err(problem)
    report = args.report or args.out.rsplit(".", 1)[0] + "-report"
    t0 = time.perf_counter()
    recipe = Recipe()
    if args.like:
        from .descriptors import library_descriptors
        from .match import MATCHED, MAX_DRAWS, generate_like
        from .polyhedron import ShapeError

        draws = MAX_DRAWS if args.max_draws is None else args.max_draws
        if draws < 1 or not args.max_seconds > 0:
            return _err("--max-draws must be at least 1 and --max-seconds above 0")

        def progress(k, n, s, note):
            print(f"shapes: --like: {k} of {n} grains in {s:.0f} s" + (f"; slow: {note}" if note else ""),
                  file=sys.stderr)

        try:
            target = ShapeLibrary(args.like)
            names = [os.path.basename(x.decode() if isinstance(x, bytes) else str(x))
                     for x in target.source] if getattr(target, "source", None) is not None else None
            shapes, rejections = generate_like(library_descriptors(target), args.n, args.seed, recipe,
                                               max_draws=draws, max_seconds=args.max_seconds,
                                               progress=progress, names=names)
        except (LibraryError, ShapeError) as exc:
            return _err(str(exc))
        spec = {**recipe.as_dict(), "like": args.like, "matched": list(MATCHED), "max_draws": draws,
                "method": "smoothed bootstrap of the target, generated grains stretched along their "
                          "principal axes (shapes/match.py)"}
        created = f"python -m shapes build --like {os.path.basename(args.like)}"
    else:
        shapes, rejections = generate_library(args.n, args.seed, recipe)
        spec, created = recipe.as_dict(), "python -m shapes build"
    try:
        write_library(args.out, shapes, args.seed, spec, _tolerances(), name=args.name, created_by=created)
    except LibraryError as exc:
        return _err(str(exc))
    seconds = time.perf_counter() - t0
    lib = ShapeLibrary(args.out)
    st = write_report(lib, report, rejections, seconds)
    from .blaspin import openblas_core

    msg = (f"shapes: {args.n} shapes -> {args.out} in {seconds:.1f} s; mean vertices "
           f"{st['n_vertices']['mean']:.1f}, faces {st['n_faces']['mean']:.1f}; report in {report}; "
           f"OpenBLAS kernels {openblas_core() or 'unknown'}")
    if args.like:
        from .report import LABELS

        cmp = write_comparison(target, lib, report, "target", lib.name, matched=MATCHED)
        ks = ", ".join(f"{k} {cmp[k]['ks_D']:.3f}" for k in MATCHED)
        differ = [k for k in cmp if k not in MATCHED and cmp[k]["ks_D"] > cmp[k]["ks_D_crit95"]]
        msg += (f"\nshapes: match to {args.like} ({len(target)} grains), KS D: {ks} (95 % critical value "
                f"{cmp['elongation']['ks_D_crit95']:.3f}); not matched, and differing from the target: "
                + (", ".join(f"{LABELS[k]} {cmp[k]['ks_D']:.3f}" for k in differ) or "none")
                + f"; {report}/compare.md")
    print(msg, file=sys.stderr)
    return 0


def _import(args):
    import numpy as np

    from .library import LibraryError, write_library
    from .hullreduce import Budget
    from .meshimport import import_paths, library_datasets, mixed_units
    from .report import budget_text, write_report

    try:
        budget = (Budget(vertices=args.vertices, max_error=None) if args.vertices is not None else
                  Budget(max_error=args.max_error, max_vertices=args.max_vertices)
                  if args.max_error is not None else Budget(max_vertices=args.max_vertices))
    except ValueError as exc:
        return _err(str(exc))
    if not (args.merge_tolerance >= 0):
        return _err(f"--merge-tolerance must be at least 0 (the mesh's units), got {args.merge_tolerance}")
    problem = _make_folder_of(args.out)          # before the import, which may take minutes
    if problem:
        return _err(problem)
    t0 = time.perf_counter()
    grains, refused, ignored = import_paths(
        args.paths, budget, split=args.components, merge_tolerance=args.merge_tolerance,
        log=lambda name, reason: print(f"shapes: refused {name}: {reason}", file=sys.stderr))
    seconds = time.perf_counter() - t0
    if not grains:
        print(f"shapes: 0 grains imported, {len(refused)} refused (listed above); no library written",
              file=sys.stderr)
        return 2
    extra = library_datasets(grains)
    spec = {"source": "meshes", "inputs": list(args.paths), "budget": budget.as_dict(),
            "components": bool(args.components), "merge_tolerance": args.merge_tolerance}
    try:
        write_library(args.out, [g.polyhedron for g in grains], -1, spec, _tolerances(), name=args.name,
                      created_by="python -m shapes import", extra=extra)
    except LibraryError as exc:
        return _err(str(exc))
    from .library import ShapeLibrary

    report = args.report or args.out.rsplit(".", 1)[0] + "-report"
    nv = np.array([g.polyhedron.n_vertices for g in grains])
    err = extra["reduction_hausdorff"]
    dvol = extra["reduction_volume_change"]
    missed = [(g.source, g.polyhedron.n_vertices, g.reduction_hausdorff, g.reduction_volume_change, g.miss)
              for g in grains if not g.target_met]
    notes = [f"{budget_text(budget.as_dict())}; the import took {seconds:.1f} s",
             f"reduction error (Hausdorff / d): median {np.median(err):.3g}, max {err.max():.3g}; volume "
             f"change median {np.median(dvol):+.3f}, worst {dvol.min():+.3f}"]
    miss_line = ""
    if missed:
        target = budget.max_error if budget.vertices is None else None
        over = np.array([m[2] for m in missed])
        at_cap = sum(m[4].startswith("at the ") for m in missed)
        by = f"by up to {over.max() / target:.2f}x, " if target else ""
        miss_line = (f"{len(missed)} of {len(grains)} above the error target {target} d ({by}median "
                     f"{np.median(over):.3g} d): {at_cap} at the {budget.max_vertices}-vertex cap, "
                     f"{len(missed) - at_cap} where every nearer choice failed the validity checks"
                     if target is not None else
                     f"{len(missed)} of {len(grains)} without a valid grain of {budget.vertices} vertices")
        notes.append(miss_line + " (listed below)")
    units = mixed_units(extra["source_d"])
    if units:
        notes.append(f"warning: {units}")
        print(f"shapes: warning: {units}", file=sys.stderr)
    if ignored:
        notes.append(f"{ignored} files in the folders were not meshes and were ignored")
    write_report(ShapeLibrary(args.out), report, seconds=seconds, refused=refused, notes=notes,
                 missed=missed, target=budget.max_error if budget.vertices is None else None)
    print(f"shapes: {len(grains)} grains imported -> {args.out} in {seconds:.1f} s, {len(refused)} refused"
          + (" (listed above)" if refused else "")
          + f"; vertices {nv.min()}-{nv.max()} (mean {nv.mean():.1f}), reduction error median "
          f"{np.median(err):.3g} d, max {err.max():.3g} d, volume change worst {dvol.min():+.3f}"
          + (f"; {miss_line} (each in the report)" if missed else "")
          + (f"; {ignored} non-mesh file{'s' if ignored > 1 else ''} ignored" if ignored else "")
          + f"; report in {report}", file=sys.stderr)
    return 1 if refused else 0


def _report(args):
    from .library import LibraryError, ShapeLibrary
    from .report import write_comparison, write_report

    try:
        lib = ShapeLibrary(args.library)
        other = ShapeLibrary(args.against) if args.against else None
    except LibraryError as exc:
        return _err(str(exc))
    write_report(lib, args.report)
    if other is not None:
        st = write_comparison(lib, other, args.report)
        worst = max(st, key=lambda k: st[k]["ks_D"] / st[k]["ks_D_crit95"])
        print(f"shapes: {args.report}/compare.md: largest KS D {st[worst]['ks_D']:.3f} ({worst}, "
              f"95 % critical value {st[worst]['ks_D_crit95']:.3f})", file=sys.stderr)
    print(f"shapes: report in {args.report}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    from .blaspin import pin

    pin(sys.argv[1:])          # the same library on every CPU of a kind (shapes/blaspin.py)
    sys.exit(main())
