"""The contact kernel alone on a real packing (no YADE): cost per step, per
touching contact and per neighbour pair, with 1 and 2 threads, and memory.

    python benchmarks/bench_kernel.py RUN.h5 [--snapshot 0] [--steps 200] [--repeat 5]

Loads one snapshot of a polyhedra dump (shapes, positions, orientations, box),
builds the kernel's engine, on its fast path and on the plain one, (``shapes/polycontact.c`` through ctypes, as the
YADE scene does) with the run's k_V, k_t and friction, and times
``pc_engine_step`` on that state. The poses are moved each step by a small
random rigid motion (1e-6 d, 1e-5 rad per body), so the neighbour list, the
cached separating axes and the clipping work as in a run (a static state would
let the cached axes hide all the work). Times are the medians of ``--repeat``
blocks of ``--steps`` steps; the engines (path x thread count) alternate
block by block, so a drift of the shared machine hits all alike. A first
pass runs them in lockstep and reports how far each is from the first:
forces, torques and every contact value, and contacts found by one only.
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


def make_engine(v, t, shape_index, sizes, params, threads, fast=True):
    """The engine with the run's parameters (as the YADE scene builds it)."""
    kv = params["kn_volumetric"]
    return ContactEngine(v, t, shape_index, sizes, kv, params["tangential_ratio"] * kv * params["a_face"],
                         params["friction"], params["wall_friction"], params.get("verlet_skin", 0.1) * params["d_mean"],
                         walls=True, threads=threads, fast=fast)


def quat_mul(a, b):
    w1, x1, y1, z1 = a.T
    w2, x2, y2, z2 = b.T
    return np.stack([w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2, w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
                     w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2], axis=1)


def pose_walk(s, steps, rng):
    """The poses of ``steps`` steps: each body moved by a small random rigid
    motion per step (1e-6 d, 1e-5 rad), from the snapshot's poses."""
    n = len(s.body_ids)
    d = float(np.mean(s.sizes))
    dpos = rng.normal(scale=1e-6 * d, size=(steps, n, 3))
    drot = rng.normal(scale=0.5e-5, size=(steps, n, 3))
    pos, q, out = s.positions.copy(), s.orientations.copy(), []
    for k in range(steps):
        pos = pos + dpos[k]
        q = quat_mul(np.concatenate([np.ones((n, 1)), drot[k]], axis=1), q)
        q /= np.linalg.norm(q, axis=1)[:, None]
        out.append((np.ascontiguousarray(pos), np.ascontiguousarray(q)))
    return out


def contact_table(eng):
    """Touching contacts of the last step as a sorted (i, j) key and their values."""
    c = eng.contacts()
    key = c["i"] * (eng.n + 1) + c["j"]
    o = np.argsort(key)
    vals = np.column_stack([c["point"], c["normal"], c["force_normal"], c["force_tangential"], c["volume"],
                            c["footprint"], c["area"]])
    return key[o], vals[o]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dump")
    ap.add_argument("--snapshot", type=int, default=0)
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--modes", nargs="+", choices=("fast", "plain"), default=["fast", "plain"],
                    help="the engine's fast path (proofs of separation, culled clipping) and the plain one")
    ap.add_argument("--shrink", type=float, default=1.0,
                    help="scale every grain about its centre (0.98: the same neighbour list with almost no contact, "
                         "so ms/step over listed pairs is the cost of a separated candidate)")
    ap.add_argument("--json", help="write the results here")
    args = ap.parse_args(argv)
    with DumpReader(args.dump) as r:
        v, t, _ = r.shapes()
        s = r.read(args.snapshot)
        params = r.parameters
    v = [np.asarray(x) * args.shrink for x in v]
    n = len(s.body_ids)
    wall_pos = np.array([s.box_lo[0], s.box_hi[0], s.box_lo[1], s.box_hi[1], s.box_lo[2], s.box_hi[2]])
    poses = pose_walk(s, args.steps, np.random.default_rng(0))       # one walk, shared by every engine
    combos = [(m, th) for m in args.modes for th in args.threads]
    engines = {c: make_engine(v, [np.asarray(x, np.int32) for x in t], s.shape_index, s.sizes, params, c[1],
                              fast=c[0] == "fast") for c in combos}
    # warm-up pass, step by step in lockstep: counts, and every engine against the first
    stats = {c: {} for c in combos}
    worst = {"force": 0.0, "torque": 0.0, "wall_force": 0.0, "contacts": 0.0, "set_differences": 0}
    for pc, qc in poses:
        out = {c: [a.copy() for a in engines[c].step(pc, qc, wall_pos)] for c in combos}
        for c in combos:
            for k, x in engines[c].stats.items():
                stats[c][k] = stats[c].get(k, 0.0) + x / len(poses)
        ref = combos[0]
        kr, vr = contact_table(engines[ref])
        for c in combos[1:]:
            for name, a, b in zip(("force", "torque", "wall_force"), out[ref], out[c]):
                scale = np.abs(a).max() or 1.0
                worst[name] = max(worst[name], float(np.abs(a - b).max() / scale))
            kc, vc = contact_table(engines[c])
            if len(kc) != len(kr) or np.any(kc != kr):
                worst["set_differences"] += len(np.setxor1d(kc, kr))
                continue
            scale = np.abs(vr).max(axis=0)
            scale[scale == 0] = 1.0
            worst["contacts"] = max(worst["contacts"], float((np.abs(vr - vc) / scale).max()))
    # timed passes: only the kernel calls, combos in turn block by block
    times = {c: [] for c in combos}
    for rep in range(args.repeat):
        for c in combos:
            eng = engines[c]
            t0 = time.perf_counter()
            for pc, qc in poses:
                eng.step(pc, qc, wall_pos)
            times[c].append((time.perf_counter() - t0) / len(poses))
    out = {"dump": args.dump, "snapshot": args.snapshot, "particles": n, "steps_per_block": len(poses),
           "blocks": args.repeat, "agreement": worst, "results": {}}
    print(f"{n} polyhedra, snapshot {args.snapshot} of {args.dump}, grains scaled by {args.shrink}; medians of "
          f"{args.repeat} blocks of {len(poses)} steps")
    print(f"{'mode':>6} {'threads':>7} {'ms/step':>8} {'touching':>8} {'pairs':>6} {'clipped':>7} {'motion':>7} "
          f"{'axis':>6} {'search':>6} {'us/touching':>11} {'us/pair':>7} {'MB':>5}")
    for c in combos:
        med = float(np.median(times[c]))
        st = stats[c]
        touching = st["touching_pairs"] + st["wall_contacts"]
        mem = engines[c].memory_bytes() / 1e6
        out["results"][f"{c[0]}-{c[1]}"] = {"ms_per_step": med * 1e3, "counts": st,
                                           "us_per_touching": med * 1e6 / touching if touching else None,
                                           "us_per_pair": med * 1e6 / st["listed_pairs"], "memory_MB": mem,
                                           "blocks_ms": [x * 1e3 for x in times[c]]}
        print(f"{c[0]:>6} {c[1]:>7} {med * 1e3:8.3f} {touching:8.0f} {st['listed_pairs']:6.0f} {st['clipped_pairs']:7.0f} "
              f"{st['apart_by_motion_bound']:7.0f} {st['apart_by_cached_axis']:6.0f} {st['apart_by_axis_search']:6.0f} "
              f"{med * 1e6 / max(touching, 1):11.2f} {med * 1e6 / st['listed_pairs']:7.3f} {mem:5.1f}")
    for a_, b_ in zip(combos, combos[1:]):
        ratio = float(np.median(np.array(times[b_]) / np.array(times[a_])))
        print(f"{b_[0]}-{b_[1]} / {a_[0]}-{a_[1]} (median of block ratios): {ratio:.2f}")
        out.setdefault("ratios", {})[f"{b_[0]}-{b_[1]}/{a_[0]}-{a_[1]}"] = ratio
    print("agreement with {}-{}: max |dF|/max|F| {:.2e}, torque {:.2e}, walls {:.2e}; contact values {:.2e} of "
          "each column's max; contacts in one set only: {}".format(*combos[0], worst["force"], worst["torque"],
                                                                   worst["wall_force"], worst["contacts"],
                                                                   worst["set_differences"]))
    for eng in engines.values():
        eng.close()
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(out, fh, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
