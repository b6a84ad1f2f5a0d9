"""Import speed of scanned grains: ``python -m shapes import`` on meshes of
5 120 to 1 310 720 triangles, made here.

Run by hand: ``python benchmarks/bench_import.py [--repeat 3] [--out runs/bench-import]
[--figure docs/figures/import-speed.png]``. Two kinds of mesh, each an
icosphere of 20 x 4^k triangles (k = 4..8) written as binary STL:

  scan    a scanned stone: a generated grain (seed 0, grain 0, 20 vertices)
          ray-cast from its centre onto the sphere's vertices (a dense mesh
          of its flat faces and sharp edges), radial scanner noise of
          0.1 % of d (uniform), and three dents (Gaussian, 3 % of d deep):
          non-convex, with a hull of a few percent of the vertices.
  smooth  an ellipsoid 1 : 0.75 : 0.5 without noise: every vertex is on the
          hull, the worst case for qhull and the reduction.

Each file is imported as the command does (read, merge and checks, hull,
reduction, normalisation) with the default budget, on one thread; each
stage's CPU time and wall time are the medians of ``--repeat`` runs in this
process. The machine is shared (long simulations on both cores), so the
figure shows CPU time, the cost on one core, and the table both with the
load average. The table goes to ``OUT/import-speed.json`` and the figure to
``--figure``. (The scans are :mod:`shapes.scans`', which also writes scans
to try the import on and calibrates its default error target.)
"""
from __future__ import annotations

import argparse
import json
import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")     # one core: CPU time = the cost on one core
os.environ.setdefault("OMP_NUM_THREADS", "1")
import statistics
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)

from shapes.generate import generate_library  # noqa: E402
from shapes.hullreduce import Budget  # noqa: E402
from shapes.meshimport import import_mesh, read_mesh  # noqa: E402
from shapes.scans import scan_mesh, smooth_mesh, write_stl  # noqa: E402


def time_import(path, repeat):
    """Median seconds per stage of importing the STL at ``path``, and the
    grain of the last run."""
    runs = []
    for _ in range(repeat):
        t0, c0 = time.perf_counter(), time.process_time()
        v, t = read_mesh(path)
        read, read_cpu = time.perf_counter() - t0, time.process_time() - c0
        g = import_mesh(v, t, Budget(), source=path)
        runs.append({"read": read, "read_cpu": read_cpu, **g.seconds, "total": time.perf_counter() - t0,
                     "total_cpu": time.process_time() - c0})
    return {k: statistics.median(r[k] for r in runs) for k in runs[0]}, g


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--levels", type=int, nargs="+", default=[4, 5, 6, 7, 8])
    ap.add_argument("--out", default=os.path.join(ROOT, "runs", "bench-import"))
    ap.add_argument("--figure", default=os.path.join(ROOT, "docs", "figures", "import-speed.png"))
    args = ap.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    grain = generate_library(1, seed=0)[0][0]
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for kind in ("scan", "smooth"):
            for k in args.levels:
                v, t = scan_mesh(grain, k) if kind == "scan" else smooth_mesh(k)
                path = os.path.join(tmp, f"{kind}-{k}.stl")
                write_stl(path, v, t)
                sec, g = time_import(path, args.repeat)
                row = {"kind": kind, "triangles": len(t), "vertices": len(v), "hull_vertices": g.hull_vertices,
                       "grain_vertices": g.polyhedron.n_vertices, "hausdorff": g.reduction_hausdorff,
                       "deficit": g.convexity_deficit, "load_average": os.getloadavg()[0],
                       **{f"s_{a}": b for a, b in sec.items()}}
                rows.append(row)
                print(f"{kind:6s} {len(t):8d} triangles, hull {g.hull_vertices:7d} vertices -> "
                      f"{g.polyhedron.n_vertices:2d}: CPU {sec['total_cpu']:.2f} s (read {sec['read_cpu']:.2f}, "
                      f"checks {sec['check_cpu']:.2f}, hull {sec['hull_cpu']:.2f}, reduce {sec['reduce_cpu']:.2f}), "
                      f"wall {sec['total']:.2f} s; error {g.reduction_hausdorff:.4f} d, deficit "
                      f"{g.convexity_deficit:.4f}; load {row['load_average']:.1f}", flush=True)
    with open(os.path.join(args.out, "import-speed.json"), "w") as fh:
        json.dump({"cores": os.cpu_count(), "repeat": args.repeat, "rows": rows}, fh, indent=1)
    plot(rows, args.figure)
    print(f"bench_import: {args.out}/import-speed.json, figure {args.figure}")


def plot(rows, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
    for ax, kind in zip(axes, ("scan", "smooth")):
        r = [x for x in rows if x["kind"] == kind]
        n = np.array([x["triangles"] for x in r])
        for key, col in (("total", "k"), ("read", "tab:blue"), ("check", "tab:orange"),
                         ("hull", "tab:green"), ("reduce", "tab:red")):
            ax.loglog(n, [x[f"s_{key}_cpu"] for x in r], "o-", color=col, lw=2 if key == "total" else 1,
                      label={"total": "whole import", "check": "merge + checks", "hull": "hull (qhull)",
                             "reduce": "reduction + normalisation"}.get(key, key))
        ax.loglog(n, [x["s_total"] for x in r], "x:", color="k", lw=1, label="whole import, wall (shared host)")
        ax.axvline(1e6, color="0.6", ls=":")
        ax.set_xlabel("triangles")
        ax.set_title({"scan": "scanned stone (hull: a few % of the vertices)",
                      "smooth": "smooth ellipsoid (every vertex on the hull)"}[kind], fontsize=9)
        ax.grid(alpha=0.3, which="both")
    axes[0].set_ylabel("CPU seconds on one core (median)")
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(os.path.dirname(path), exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
