"""The contact kernel of another git revision beside today's, on the same poses.

    python benchmarks/kernel_vs_revision.py RUN.h5 [--rev 784c287] [--snapshot 0] [--steps 100] [--repeat 3]

Builds ``shapes/polycontact.c`` as it was at ``--rev`` (``git show``, gcc with
today's flags) into a temporary folder and drives both libraries through
``pc_engine_new`` / ``pc_engine_step`` (whose signatures have not changed) on
one snapshot of a polyhedra dump moved by the small random rigid motions of
``bench_kernel.py``. Reports, step by step, how far today's forces and
torques are from the revision's (max |difference| / max |force|) and the
per-step time of each (medians of alternating blocks, one thread). Both
libraries are built the same way and stepped through the same ``ctypes``
calls (the working tree's source, not the package's wrapper, whose Python
work per step would weigh on a small packing).
"""
from __future__ import annotations

import argparse
import ctypes
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, HERE)
from bench_kernel import make_engine, pose_walk  # noqa: E402
from postproc.schema import DumpReader  # noqa: E402
from shapes import ckernel  # noqa: E402


def build_revision(rev, folder, name="rev"):
    """The kernel of git revision ``rev`` (None: the working tree's), built
    with today's flags into ``folder``, loaded."""
    if rev is None:
        with open(os.path.join(os.path.dirname(HERE), "shapes", "polycontact.c")) as fh:
            text = fh.read()
    else:
        src = subprocess.run(["git", "-C", os.path.dirname(HERE), "show", f"{rev}:shapes/polycontact.c"],
                             capture_output=True, text=True)
        if src.returncode != 0:
            raise SystemExit(f"kernel_vs_revision: no shapes/polycontact.c at {rev}: {src.stderr.strip()}")
        text = src.stdout
    path = os.path.join(folder, f"polycontact_{name}.c")
    with open(path, "w") as fh:
        fh.write(text)
    lib = os.path.join(folder, f"polycontact_{name}.so")
    subprocess.run(["gcc", *ckernel.CFLAGS, "-o", lib, path, "-lm"], check=True)
    return ctypes.CDLL(lib)


class RevisionEngine:
    """pc_engine_new/step of a revision's library (no other call assumed)."""

    def __init__(self, lib, today):
        self.lib, self.n = lib, today.n
        P = ctypes.c_void_p
        lib.pc_engine_new.restype = P
        lib.pc_engine_step.argtypes = [P] + [ctypes.c_void_p] * 7
        lib.pc_engine_step.restype = ctypes.c_int
        self.args = (today.v, today.t, today.voff, today.toff, today.shape, today.size, today.wall_axis, today.wall_sign)
        p = today.params
        self.h = lib.pc_engine_new(
            ctypes.c_int(len(today.voff) - 1), ckernel.iptr(today.voff), ckernel.dptr(today.v), ckernel.iptr(today.toff),
            ckernel.iptr(today.t), ctypes.c_int(today.n), ckernel.iptr(today.shape), ckernel.dptr(today.size),
            ctypes.c_int(today.nw), ckernel.iptr(today.wall_axis), ckernel.dptr(today.wall_sign),
            *[ctypes.c_double(x) for x in p], ctypes.c_int(1))
        self.force, self.torque = np.zeros((self.n, 3)), np.zeros((self.n, 3))
        self.wall_force, self.stat = np.zeros((6, 3)), np.zeros(64)

    def step(self, pos, quat, walls):
        err = self.lib.pc_engine_step(self.h, pos.ctypes.data, quat.ctypes.data, walls.ctypes.data, self.force.ctypes.data,
                                      self.torque.ctypes.data, self.wall_force.ctypes.data, self.stat.ctypes.data)
        if err:
            raise SystemExit(f"kernel_vs_revision: the revision's step failed ({err})")
        return self.force, self.torque, self.wall_force


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dump")
    ap.add_argument("--rev", default="784c287")
    ap.add_argument("--snapshot", type=int, default=0)
    ap.add_argument("--steps", type=int, default=100)
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args(argv)
    with DumpReader(args.dump) as r:
        v, t, _ = r.shapes()
        s = r.read(args.snapshot)
        params = r.parameters
    walls = np.array([s.box_lo[0], s.box_hi[0], s.box_lo[1], s.box_hi[1], s.box_lo[2], s.box_hi[2]])
    today = make_engine(v, [np.asarray(x, np.int32) for x in t], s.shape_index, s.sizes, params, 1)
    kv = params["kn_volumetric"]
    today.params = (kv, params["tangential_ratio"] * kv * params["a_face"], params["friction"], params["wall_friction"],
                    params.get("verlet_skin", 0.1) * params["d_mean"])
    with tempfile.TemporaryDirectory() as tmp:
        old = RevisionEngine(build_revision(args.rev, tmp), today)
        # today's source driven the same way (ctypes, no Python wrapper), so the times compare the kernels only
        today = RevisionEngine(build_revision(None, tmp, "today"), today)
        poses = pose_walk(s, args.steps, np.random.default_rng(0))
        worst = {"force": 0.0, "torque": 0.0, "wall_force": 0.0}
        for pc, qc in poses:
            a = [x.copy() for x in today.step(pc, qc, walls)]
            b = old.step(pc, qc, walls)
            scale = np.abs(b[0]).max()
            for name, x, y in zip(worst, a, b):
                worst[name] = max(worst[name], float(np.abs(x - y).max() / scale))
        times = {"today": [], args.rev: []}
        for _ in range(args.repeat):
            for name, eng in (("today", today), (args.rev, old)):
                t0 = time.perf_counter()
                for pc, qc in poses:
                    eng.step(pc, qc, walls)
                times[name].append((time.perf_counter() - t0) / len(poses))
    ratio = float(np.median(np.array(times[args.rev]) / np.array(times["today"])))
    print(f"{s.positions.shape[0]} polyhedra, snapshot {args.snapshot}, {len(poses)} steps: today against {args.rev}: "
          f"max |dF|/max|F| {worst['force']:.2e}, torque {worst['torque']:.2e}, walls {worst['wall_force']:.2e}")
    print(f"ms per step (one thread, medians of {args.repeat} blocks): today {np.median(times['today']) * 1e3:.2f}, "
          f"{args.rev} {np.median(times[args.rev]) * 1e3:.2f}; {args.rev}/today {ratio:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
