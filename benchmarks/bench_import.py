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
``--figure``.
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
from shapes.meshimport import Budget, import_mesh, read_mesh  # noqa: E402
from shapes.polyhedron import triangle_normals  # noqa: E402


def ray_cast_convex(directions, vertices, triangles):
    """Distances (M,) along unit ``directions`` (M, 3) from the origin (inside)
    to the surface of a convex polyhedron: min over faces facing the ray of
    offset / (n . u)."""
    n, _ = triangle_normals(vertices, triangles)
    off = np.einsum("ij,ij->i", n, vertices[triangles[:, 0]])      # > 0: origin inside
    out = np.empty(len(directions))
    for s in range(0, len(directions), 65536):
        c = directions[s:s + 65536] @ n.T
        with np.errstate(divide="ignore"):
            out[s:s + 65536] = np.where(c > 1e-12, off / c, np.inf).min(axis=1)
    return out


def scan_mesh(poly, subdivisions, noise=1e-3, dents=3, depth=0.03, rng=None):
    """A synthetic scan of the convex grain ``poly`` (d = 1): (vertices,
    triangles) of an icosphere of ``subdivisions`` ray-cast onto it, with
    uniform radial noise of +-noise and ``dents`` Gaussian dents of the given
    depth (relative to d) and width 0.25 rad."""
    import trimesh

    rng = rng or np.random.default_rng(0)
    s = trimesh.creation.icosphere(subdivisions=subdivisions)
    u = s.vertices / np.linalg.norm(s.vertices, axis=1)[:, None]
    r = ray_cast_convex(u, poly.vertices, poly.triangles)
    for _ in range(dents):
        c = rng.normal(size=3)
        c /= np.linalg.norm(c)
        r -= depth * np.exp(-np.sum((u - c) ** 2, axis=1) / 0.25 ** 2)
    r += noise * rng.uniform(-1, 1, len(r))
    return u * r[:, None], np.asarray(s.faces)


def smooth_mesh(subdivisions, axes=(1.0, 0.75, 0.5)):
    import trimesh

    s = trimesh.creation.icosphere(subdivisions=subdivisions)
    return np.asarray(s.vertices) * np.asarray(axes), np.asarray(s.faces)


def write_stl(path, v, t):
    import trimesh

    trimesh.Trimesh(v, t, process=False).export(path)


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
    ap.add_argument("--write-scans", metavar="DIR",
                    help="only write --n synthetic scans of generated grains (seed 11, 20 480 triangles "
                         "each) as binary STL into DIR, to try the import on")
    ap.add_argument("--n", type=int, default=40)
    ap.add_argument("--calibrate", action="store_true",
                    help="only the default error target's calibration: --n scans of generated grains "
                         "(seed 3, 20 480 triangles each) imported at several error targets, the vertex "
                         "counts found against the grains' own")
    args = ap.parse_args(argv)
    if args.calibrate:
        calibrate(args.n)
        return
    if args.write_scans:
        os.makedirs(args.write_scans, exist_ok=True)
        rng = np.random.default_rng(11)
        for k, g in enumerate(generate_library(args.n, seed=11)[0]):
            v, t = scan_mesh(g, 5, rng=rng)
            write_stl(os.path.join(args.write_scans, f"stone{k:03d}.stl"), v * 40.0, t)   # d = 40 mm
        print(f"bench_import: {args.n} scans in {args.write_scans}")
        return
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


def calibrate(n, targets=(0.01, 0.015, 0.02, 0.03, 0.05)):
    """Scans of n generated grains (their vertex counts known: the paper's
    8-37, mean 20), imported at each error target: the mean count found,
    its correlation with the true count, the errors and the misses."""
    shapes = generate_library(n, seed=3)[0]
    rng = np.random.default_rng(0)
    meshes = [scan_mesh(s, 5, rng=rng) for s in shapes]
    true = np.array([s.n_vertices for s in shapes])
    print(f"{n} generated grains: vertices {true.min()}-{true.max()}, mean {true.mean():.1f}")
    for e in targets:
        gs = [import_mesh(v, t, Budget(max_error=e)) for v, t in meshes]
        nv = np.array([g.polyhedron.n_vertices for g in gs])
        err = np.array([g.reduction_hausdorff for g in gs])
        print(f"max error {e:<5g}: vertices {nv.min()}-{nv.max()}, mean {nv.mean():.1f}, correlation with the "
              f"true counts {np.corrcoef(nv, true)[0, 1]:.2f}; error median {np.median(err):.4f} d, max "
              f"{err.max():.4f} d; target missed {sum(not g.target_met for g in gs)}; volume change mean "
              f"{np.mean([g.reduction_volume_change for g in gs]):+.3f}", flush=True)
    axes = [(1.0, e, e * f) for e, f in ((0.6, 0.6), (0.75, 0.7), (0.9, 0.85))]
    for a in axes:
        v, t = smooth_mesh(5, a)
        g = import_mesh(v * (1 + 1e-3 * rng.uniform(-1, 1, (len(v), 1))), t, Budget())
        print(f"ellipsoid {a[0]:.2f} : {a[1]:.2f} : {a[2]:.2f} with 0.1 % noise, default budget: "
              f"{g.polyhedron.n_vertices} vertices, error {g.reduction_hausdorff:.4f} d")


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
