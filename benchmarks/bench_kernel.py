"""The contact kernel alone on a real packing (no YADE): cost per step, per
touching contact and per neighbour pair, with 1 and 2 threads, and memory.

    python benchmarks/bench_kernel.py RUN.h5 [--snapshot 0] [--steps 200] [--repeat 5]

Loads one snapshot of a polyhedra dump (shapes, positions, orientations, box),
builds the kernel's engine (``shapes/polycontact.c`` through ctypes, as the
YADE scene does) with the run's k_V, k_t and friction, and times
``pc_engine_step`` on that state. The poses are moved each step by a small
random rigid motion (1e-6 d, 1e-5 rad per body), so the neighbour list, the
cached separating axes and the clipping work as in a run (a static state would
let the cached axes hide all the work). Times are the medians of ``--repeat``
blocks of ``--steps`` steps; the two thread counts alternate block by block,
so a drift of the shared machine hits both alike.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from postproc.schema import DumpReader  # noqa: E402
from shapes.engine import ContactEngine  # noqa: E402


def make_engine(v, t, shape_index, sizes, params, threads):
    """The engine with the run's parameters (as the YADE scene builds it)."""
    kv = params["kn_volumetric"]
    return ContactEngine(v, t, shape_index, sizes, kv, params["tangential_ratio"] * kv * params["a_face"],
                         params["friction"], params["wall_friction"], params.get("verlet_skin", 0.1) * params["d_mean"],
                         walls=True, threads=threads)


def quat_mul(a, b):
    w1, x1, y1, z1 = a.T
    w2, x2, y2, z2 = b.T
    return np.stack([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                     w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2], axis=1)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dump")
    ap.add_argument("--snapshot", type=int, default=0)
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--json", help="write the results here")
    args = ap.parse_args(argv)
    with DumpReader(args.dump) as r:
        v, t, _ = r.shapes()
        s = r.read(args.snapshot)
        params = r.parameters
    n = len(s.body_ids)
    wall_pos = np.array([s.box_lo[0], s.box_hi[0], s.box_lo[1], s.box_hi[1], s.box_lo[2], s.box_hi[2]])
    rng = np.random.default_rng(0)
    d = float(np.mean(s.sizes))
    # one random walk of poses, shared by every thread count
    steps = args.steps
    dpos = rng.normal(scale=1e-6 * d, size=(steps, n, 3))
    drot = rng.normal(scale=0.5e-5, size=(steps, n, 3))
    engines = {th: make_engine(v, [np.asarray(x, np.int32) for x in t], s.shape_index, s.sizes, params, th)
               for th in args.threads}
    stats = {}
    for th in args.threads:                                 # warm-up pass: counts per step
        eng = engines[th]
        pos = s.positions.copy()
        q = s.orientations.copy()
        touching = pairs = clipped = 0
        for k in range(steps):
            pos = pos + dpos[k]
            q = quat_mul(np.concatenate([np.ones((n, 1)), drot[k]], axis=1), q)
            q /= np.linalg.norm(q, axis=1)[:, None]
            eng.step(pos, q, wall_pos)
            touching += eng.stat[0] + eng.stat[1]
            pairs += eng.stat[2]
            clipped += eng.stat[7]
        stats[th] = (touching / steps, pairs / steps, clipped / steps)
    # timed passes: only the kernel calls
    times = {th: [] for th in args.threads}
    for rep in range(args.repeat):
        for th in args.threads:
            eng = engines[th]
            pos = s.positions.copy()
            q = s.orientations.copy()
            poses = []
            for k in range(steps):
                pos = pos + dpos[k]
                q = quat_mul(np.concatenate([np.ones((n, 1)), drot[k]], axis=1), q)
                q /= np.linalg.norm(q, axis=1)[:, None]
                poses.append((np.ascontiguousarray(pos), np.ascontiguousarray(q)))
            t0 = time.perf_counter()
            for pc, qc in poses:
                eng.step(pc, qc, wall_pos)
            times[th].append((time.perf_counter() - t0) / steps)
    out = {"dump": args.dump, "snapshot": args.snapshot, "particles": n, "steps_per_block": steps,
           "blocks": args.repeat, "results": {}}
    print(f"{n} polyhedra, snapshot {args.snapshot} of {args.dump}; medians of {args.repeat} blocks of {steps} steps")
    print(f"{'threads':>8} {'ms/step':>9} {'touching':>9} {'pairs':>7} {'clipped':>8} "
          f"{'us/touching':>12} {'us/pair':>8} {'MB':>6}")
    for th in args.threads:
        med = float(np.median(times[th]))
        touching, pairs, clipped = stats[th]
        mem = engines[th].memory_bytes() / 1e6
        out["results"][th] = {"ms_per_step": med * 1e3, "touching": touching, "pairs": pairs, "clipped": clipped,
                              "us_per_touching": med * 1e6 / touching, "us_per_pair": med * 1e6 / pairs,
                              "memory_MB": mem, "blocks_ms": [x * 1e3 for x in times[th]]}
        print(f"{th:>8} {med * 1e3:9.3f} {touching:9.0f} {pairs:7.0f} {clipped:8.0f} {med * 1e6 / touching:12.2f} "
              f"{med * 1e6 / pairs:8.3f} {mem:6.1f}")
    if len(args.threads) == 2:
        a, b = args.threads
        ratio = np.median(np.array(times[a]) / np.array(times[b]))
        print(f"speed-up {a} -> {b} threads (median of block ratios): {ratio:.2f}")
        out["speedup"] = float(ratio)
    for eng in engines.values():
        eng.close()
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(out, fh, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
