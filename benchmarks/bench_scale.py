"""What S1 costs as it grows: the whole YADE step at several numbers of
grains and threads, the set-up, and the peak memory.

    python benchmarks/bench_scale.py [--n 1000 5000 36933] [--threads 1 2] [--steps 300] \
        [--repeat 3] [--out runs/bench-scale] [--library runs/shapes/library.h5]

For every N, a polyhedra run folder is generated (``yade_scripts.generate``:
the default preset with ``n_particles = N``, or the ``paper`` preset for
N = 36 933, the published sample) and run as the study runs it (``yade -jT
-n -x triaxial.py``) from the grains' placement into isotropic compaction.
When its progress line reports ``--steps`` steps the run is sent SIGTERM,
writes its checkpoint at the end of that step and exits 75; the
checkpoint's header carries the engine times of the attempt (YADE's
``O.timingEnabled``: the kernel's PyRunner, the controller, Newton, ...) and
the kernel's own split of its PyRunner (reading the poses, the C kernel,
adding the forces), the step count and the touching contact-steps. The
set-up (sizes, shapes, the exact placement, the bodies) is the time from
the start to the scene's first line (``N polyhedra, dt = ...``); the peak
memory is the process's maximum resident set (``os.wait4``).

Runs alternate: every (N, threads) runs once per round, ``--repeat``
rounds, so a drift of the shared machine hits all alike; figures are
medians over rounds, and the per-grain ratios (N against the smallest N at
the same threads) are medians of the per-round ratios. The first steps of
compaction hold few touching contacts (the grains start at a solid fraction
of 0.25), so the kernel's share here is below a dense packing's; per touching
contact-step the kernel's cost is given apart. Writes OUT/bench-scale.csv
(one row per run) and OUT/bench-scale.md (medians and ratios).
"""
from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

import numpy as np
import pandas as pd

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)
from yade_scripts.checkpoint import read as read_checkpoint  # noqa: E402
from yade_scripts.generate import DEFAULT_LIBRARY, generate  # noqa: E402

PAPER_N = 36933
STEP_LINE = re.compile(r"step (\d+) ")


def run_once(folder, threads, steps, timeout):
    """Run the scene in ``folder`` on ``threads`` threads until ``steps``
    steps, SIGTERM it, and return its figures (dict)."""
    for stale in os.listdir(folder):           # the last round's dump, log and checkpoints: start afresh
        if stale.startswith("run."):
            path = os.path.join(folder, stale)
            shutil.rmtree(path) if os.path.isdir(path) else os.remove(path)
    env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")
    t0 = time.perf_counter()
    proc = subprocess.Popen(["yade", "-j", str(threads), "-n", "-x", "triaxial.py"], cwd=folder, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, bufsize=1)
    setup, sent, lines = None, False, []
    for line in proc.stdout:
        lines.append(line)
        if setup is None and " dt = " in line:
            setup = time.perf_counter() - t0
        m = STEP_LINE.search(line)
        if m and not sent and int(m.group(1)) >= steps:
            proc.send_signal(signal.SIGTERM)
            sent = True
        if time.perf_counter() - t0 > timeout and not sent:
            proc.send_signal(signal.SIGTERM)
            sent = True
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 75:
        tail = "".join(lines[-5:])
        raise SystemExit(f"bench_scale: {folder}: exit {proc.returncode}, not a checkpoint (75):\n{tail}")
    meta, _, _ = read_checkpoint(os.path.join(folder, "run.ckpt"))
    eng = meta["engine_seconds"]
    k = meta["kernel_counters"]
    n = meta["step"]
    calls = max(k["calls"], 1)
    out = {"steps": n, "setup_s": setup, "peak_rss_mb": usage.ru_maxrss / 1024,
           "wall_s": meta["wall_seconds"], "touch_per_step": k["touch_steps"] / calls,
           "read_ms": 1e3 * k["seconds"]["read"] / calls, "kernel_ms": 1e3 * k["seconds"]["kernel"] / calls,
           "apply_ms": 1e3 * k["seconds"]["apply"] / calls,
           "newton_ms": 1e3 * eng.get("newton", np.nan) / n, "controller_ms": 1e3 * eng.get("controller", np.nan) / n,
           "other_ms": 1e3 * sum(v for e, v in eng.items()
                                 if e not in ("newton", "controller", "kernel_contacts")) / n}
    out["step_ms"] = 1e3 * sum(eng.values()) / n
    out["us_per_touch"] = 1e3 * out["kernel_ms"] / out["touch_per_step"] if out["touch_per_step"] else np.nan
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=[1000, 5000, PAPER_N])
    ap.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--steps", type=int, default=300)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--timeout", type=float, default=3600.0, help="s per run before it is stopped anyway")
    ap.add_argument("--out", default=os.path.join(ROOT, "runs", "bench-scale"))
    ap.add_argument("--library", default=DEFAULT_LIBRARY)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    folders = {}
    for n in args.n:
        folder = os.path.join(args.out, f"n{n}")
        if not os.path.exists(os.path.join(folder, "triaxial.py")):
            preset, over = ("paper", {}) if n == PAPER_N else ("default", {"n_particles": n})
            generate(folder, preset, "polyhedra", {**over, "checkpoint_seconds": 0, "report_seconds": 1,
                                                   "log_every": 50, "check_every": 50}, library=args.library)
        folders[n] = folder
    rows = []
    for rnd in range(args.repeat):
        for n in args.n:
            for th in args.threads:
                r = run_once(folders[n], th, args.steps, args.timeout)
                rows.append({"round": rnd, "n": n, "threads": th, **r})
                print(f"round {rnd} N {n} threads {th}: {r['step_ms']:.2f} ms/step "
                      f"({1e3 * r['step_ms'] / n:.2f} us/grain-step), set-up {r['setup_s']:.1f} s, "
                      f"{r['peak_rss_mb']:.0f} MB, {r['touch_per_step']:.0f} touching contacts", flush=True)
                pd.DataFrame(rows).to_csv(os.path.join(args.out, "bench-scale.csv"), index=False)
    df = pd.DataFrame(rows)
    df["us_per_grain_step"] = 1e3 * df["step_ms"] / df["n"]
    df["roundtrip_us_per_grain"] = 1e3 * (df["read_ms"] + df["apply_ms"]) / df["n"]
    cols = ["step_ms", "us_per_grain_step", "kernel_ms", "read_ms", "apply_ms", "newton_ms", "controller_ms",
            "other_ms", "roundtrip_us_per_grain", "us_per_touch", "touch_per_step", "setup_s", "peak_rss_mb"]
    med = df.groupby(["n", "threads"])[cols].median().reset_index()
    base = min(args.n)
    ratio = []
    for (n, th), g in df.groupby(["n", "threads"]):
        ref = df[(df["n"] == base) & (df["threads"] == th)].set_index("round")["us_per_grain_step"]
        r = g.set_index("round")["us_per_grain_step"] / ref
        ratio.append({"n": n, "threads": th, "per_grain_ratio": float(np.median(r.dropna()))})
    med = med.merge(pd.DataFrame(ratio), on=["n", "threads"])
    sp = []
    for (n, th), g in df.groupby(["n", "threads"]):
        one = df[(df["n"] == n) & (df["threads"] == min(args.threads))].set_index("round")["step_ms"]
        sp.append({"n": n, "threads": th, "speedup": float(np.median((one / g.set_index("round")["step_ms"]).dropna()))})
    med = med.merge(pd.DataFrame(sp), on=["n", "threads"])
    med.to_csv(os.path.join(args.out, "bench-scale-medians.csv"), index=False)
    lines = [f"First {args.steps} steps of compaction from the placed grains, medians of {args.repeat} rounds "
             f"(bench_scale.py, {time.strftime('%Y-%m-%d')}):", "",
             "| N | threads | ms per step | µs per grain-step | per grain vs N = " + str(base) +
             " | speed-up vs 1 thread | kernel | read poses | add forces | Newton | controller | other | "
             "touching contacts | µs per touching contact (kernel) | set-up (s) | peak memory (MB) |",
             "|---" * 16 + "|"]
    for _, r in med.iterrows():
        lines.append(f"| {int(r['n'])} | {int(r['threads'])} | {r['step_ms']:.2f} | {r['us_per_grain_step']:.2f} | "
                     f"{r['per_grain_ratio']:.2f} | {r['speedup']:.2f} | {r['kernel_ms']:.2f} | {r['read_ms']:.2f} | "
                     f"{r['apply_ms']:.2f} | {r['newton_ms']:.2f} | {r['controller_ms']:.2f} | {r['other_ms']:.2f} | "
                     f"{r['touch_per_step']:.0f} | {r['us_per_touch']:.2f} | {r['setup_s']:.1f} | "
                     f"{r['peak_rss_mb']:.0f} |")
    with open(os.path.join(args.out, "bench-scale.md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
