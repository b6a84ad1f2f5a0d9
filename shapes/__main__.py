"""``python -m shapes build --n 1000 --seed 0 --out LIB.h5 [--report DIR]``"""
from __future__ import annotations

import argparse
import os
import sys
import time


def main(argv=None):
    from . import polyhedron
    from .generate import Recipe, generate_library
    from .library import ShapeLibrary, write_library
    from .report import write_report

    ap = argparse.ArgumentParser(prog="python -m shapes", description="ballast-like polyhedra library")
    sub = ap.add_subparsers(dest="cmd", required=True)
    b = sub.add_parser("build", help="generate a library and its report")
    b.add_argument("--n", type=int, default=1000, help="number of shapes (default 1000)")
    b.add_argument("--seed", type=int, default=0)
    b.add_argument("--out", required=True, help="library file (.h5)")
    b.add_argument("--report", help="folder for the report (default: next to the library)")
    r = sub.add_parser("report", help="report on an existing library")
    r.add_argument("library")
    r.add_argument("--report", required=True)
    args = ap.parse_args(argv)
    if args.cmd == "build":
        if args.n < 1:
            print("shapes: error: --n must be at least 1", file=sys.stderr)
            return 2
        folder = os.path.dirname(os.path.abspath(args.out))
        try:
            os.makedirs(folder, exist_ok=True)      # --out may name a folder that does not exist yet
        except OSError as exc:
            print(f"shapes: error: cannot make the folder of --out {args.out}: {exc.strerror}", file=sys.stderr)
            return 2
        t0 = time.perf_counter()
        recipe = Recipe()
        shapes, rejections = generate_library(args.n, args.seed, recipe)
        tol = {k: getattr(polyhedron, k) for k in
               ("VERTEX_TOL", "EDGE_TOL", "HEIGHT_TOL", "VOLUME_TOL", "CONVEX_TOL", "COPLANAR_DEG")}
        write_library(args.out, shapes, args.seed, recipe.as_dict(), tol)
        seconds = time.perf_counter() - t0
        report = args.report or args.out.rsplit(".", 1)[0] + "-report"
        st = write_report(ShapeLibrary(args.out), report, rejections, seconds)
        print(f"shapes: {args.n} shapes -> {args.out} in {seconds:.1f} s; mean vertices "
              f"{st['n_vertices']['mean']:.1f}, faces {st['n_faces']['mean']:.1f}; report in {report}",
              file=sys.stderr)
        return 0
    st = write_report(ShapeLibrary(args.library), args.report)
    print(f"shapes: report in {args.report}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
