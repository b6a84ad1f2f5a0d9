"""What S1 costs as it grows: the whole YADE step at several numbers of
grains and threads, the set-up, and the peak memory.

    python benchmarks/bench_scale.py [--n 1000 5000 36933] [--threads 1 2] [--steps 300] \
        [--repeat 3] [--out runs/bench-scale] [--library runs/shapes/library.h5]
    python benchmarks/bench_scale.py --dense RUN1000.h5:SNAP RUN5000.h5:SNAP [--threads 1 2] \
        [--steps 200] [--blocks 5] [--out runs/bench-scale]

The second form steps dense packings of the study's own dumps instead (the
same strain in a 1000- and a 5000-grain S1, say): see bench_scale_dense.py;
the per-grain cost of a step at 5000 against 1000 is this form's ratio.

For every N, a polyhedra run folder is generated (``yade_scripts.campaign.generate``:
the default preset with ``n_particles = N``, or the ``paper`` preset for
N = 36 933, the published sample) and run as the study runs it (``yade -jT
-n -x triaxial.py``) from the grains' placement into isotropic compaction.
When its progress line reports ``--steps`` more steps the run is sent
SIGTERM, writes its checkpoint at the end of that step and exits 75; the
next attempt resumes from it (on the other thread count), so one sample per
N is built once and stepped on, attempt after attempt. The checkpoint's
header carries the run's cumulative engine times (YADE's
``O.timingEnabled``: the kernel's PyRunner, the controller, Newton, ...),
the kernel's own split of its PyRunner (reading the poses, the C kernel,
adding the forces) and the touching contact-steps: an attempt's figures are
the differences between the checkpoints before and after it. The set-up
(sizes, shapes, the exact placement, the bodies; redone by every attempt
before the checkpoint replaces the scene) is the time from the start to the
scene's first line (``N polyhedra, dt = ...``); the peak memory is the
process's own high-water mark (VmHWM, read at every line it prints, the
last after its checkpoint is written).

Attempts alternate: every (N, threads) runs once per round, ``--repeat``
rounds, so a drift of the shared machine hits all alike; figures are
medians over rounds, and the per-grain ratios (N against the smallest N at
the same threads) are medians of the per-round ratios. These are the first
steps of compaction: they hold fewer touching contacts than a dense packing
(the grains start at a solid fraction of 0.25), so the kernel's share here
is below a dense packing's; per touching contact-step the kernel's cost is
given apart. Writes OUT/bench-scale.csv
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
from yade_scripts.runs import noremote  # noqa: E402
from yade_scripts import yadeplugin  # noqa: E402
from yade_scripts.runs.checkpoint import read as read_checkpoint  # noqa: E402
from yade_scripts.campaign.generate import DEFAULT_LIBRARY, generate  # noqa: E402

PAPER_N = 36933
STEP_LINE = re.compile(r"step (\d+) ")


def _peak_mb(pid):
    """The process's own peak resident memory so far (VmHWM, MB); 0 when gone."""
    try:
        with open(f"/proc/{pid}/status") as fh:
            for line in fh:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024
    except OSError:
        pass
    return 0.0


def run_once(folder, threads, steps, timeout, fresh):
    """Run the scene in ``folder`` on ``threads`` threads for ``steps``
    steps (from the start when ``fresh``, else resumed from the checkpoint
    the last attempt left), SIGTERM it, and return the attempt's figures
    (dict): differences of the cumulative engine times and kernel counters
    between the checkpoint before and after it."""
    ckpt = os.path.join(folder, "run.ckpt")
    if fresh:
        for stale in os.listdir(folder):           # an earlier benchmark's dump, log, checkpoints
            if stale.startswith("run."):
                path = os.path.join(folder, stale)
                shutil.rmtree(path) if os.path.isdir(path) else os.remove(path)
        before = {"step": 0, "engine_seconds": {}, "kernel_counters": {"seconds": {}, "calls": 0, "touch_steps": 0}}
    else:
        before = read_checkpoint(ckpt)[0]
    env = dict(yadeplugin.environment(run_folder=folder), OMP_WAIT_POLICY="PASSIVE")    # as the study runs it
    t0 = time.perf_counter()
    proc = subprocess.Popen(noremote.command(shutil.which("yade"), ["-j", str(threads), "-n", "-x", "triaxial.py"]), cwd=folder, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, bufsize=1)
    setup, sent, lines, hwm = None, False, [], 0.0
    for line in proc.stdout:
        lines.append(line)
        hwm = max(hwm, _peak_mb(proc.pid))
        if setup is None and " dt = " in line:
            setup = time.perf_counter() - t0
        m = STEP_LINE.search(line)
        if m and not sent and int(m.group(1)) >= before["step"] + steps:
            proc.send_signal(signal.SIGTERM)
            sent = True
        if time.perf_counter() - t0 > timeout and not sent:
            proc.send_signal(signal.SIGTERM)
            sent = True
    _, status, _ = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    code = os.waitstatus_to_exitcode(status)
    if code != 75:
        raise SystemExit(f"bench_scale: {folder}: exit {code}, not a checkpoint (75):\n{''.join(lines[-5:])}")
    after = read_checkpoint(ckpt)[0]
    eng = {e: v - before["engine_seconds"].get(e, 0.0) for e, v in after["engine_seconds"].items()}
    ka, kb = after["kernel_counters"], before["kernel_counters"]
    n = after["step"] - before["step"]
    calls = max(ka["calls"] - kb["calls"], 1)
    sec = {k: v - kb["seconds"].get(k, 0.0) for k, v in ka["seconds"].items()}
    out = {"from_step": before["step"], "steps": n, "setup_s": setup, "attempt_wall_s": wall,
           "peak_rss_mb": hwm, "touch_per_step": (ka["touch_steps"] - kb["touch_steps"]) / calls,
           "read_ms": 1e3 * sec["read"] / calls, "kernel_ms": 1e3 * sec["kernel"] / calls,
           "apply_ms": 1e3 * sec["apply"] / calls,
           "newton_ms": 1e3 * eng.get("newton", np.nan) / n, "controller_ms": 1e3 * eng.get("controller", np.nan) / n,
           "other_ms": 1e3 * sum(v for e, v in eng.items()
                                 if e not in ("newton", "controller", "kernel_contacts")) / n,
           "step_ms": 1e3 * sum(eng.values()) / n}
    out["us_per_touch"] = 1e3 * out["kernel_ms"] / out["touch_per_step"] if out["touch_per_step"] else np.nan
    if sum(eng.values()) > wall:
        raise SystemExit(f"bench_scale: {folder}: engine times {sum(eng.values()):.1f} s exceed the attempt's "
                         f"{wall:.1f} s (counted twice after a resume?)")
    return out


def controller_ms(spec):
    """The scene's controller (servo, snapshots and dumps, log rows) in ms
    per step over the whole run that wrote the dump ``spec`` ("RUN.h5:SNAP"),
    from its RUN.info.json, else its last checkpoint (NaN when the run kept
    no timing)."""
    stem = spec.rsplit(":", 1)[0][:-3]
    try:
        with open(stem + ".info.json") as fh:
            i = json.load(fh)
        return 1e3 * i["engine_seconds"]["controller"] / i["steps"]
    except (OSError, KeyError, ValueError, ZeroDivisionError):
        pass
    try:                                  # a run still going: its last checkpoint
        meta = read_checkpoint(stem + ".ckpt")[0]
        return 1e3 * meta["engine_seconds"]["controller"] / meta["step"]
    except Exception:                     # noqa: BLE001 - no timing of this run: the column stays empty
        return np.nan


def dense(specs, threads, steps, blocks, out):
    """The dense packings ``specs`` ("RUN.h5:SNAP") stepped side by side in
    one YADE run per thread count (``bench_scale_dense.py``), each on both
    kernel paths: medians over blocks of every figure, per-grain ratios
    against the smallest packing and speed-ups against the fewest threads
    (paired block by block, path by path), the PyRunner's step against the
    plugin's, and the serial share. The whole step adds the scene's
    controller (servo, dumps), timed in the run that wrote each dump (its
    info.json), to the engines stepped here; the serial share is the part
    of it that runs on one thread whatever the thread count: reading the
    poses, adding the forces and the controller.
    Writes OUT/bench-scale-dense.md and returns its lines."""
    rows = []
    env = dict(yadeplugin.environment(), OMP_WAIT_POLICY="PASSIVE")
    if "YADE_PREFIX" not in env:
        print(f"bench_scale: no ready kernel plugin ({yadeplugin.status()['why']}): the PyRunner path only",
              flush=True)
        env["BENCH_PATHS"] = "pyrunner"
    ctrl = {}
    for th in threads:
        js = os.path.join(out, f"dense-j{th}.json")
        subprocess.run(noremote.command(shutil.which("yade"), ["-j", str(th), "-n", "-x",
                        os.path.join(ROOT, "benchmarks", "bench_scale_dense.py"), js, str(steps), str(blocks), *specs]), check=True, env=env, stdout=subprocess.DEVNULL)
        with open(js) as fh:
            res = json.load(fh)
        for spec, p in zip(specs, res["packings"]):
            ctrl[p["particles"]] = controller_ms(spec)
            for b, blk in enumerate(p["blocks"]):
                e, k = blk["engines_ms_per_step"], blk["kernel_split_ms_per_step"]
                rows.append({"n": p["particles"], "threads": th, "path": blk.get("path", "pyrunner"),
                             "block": b // (2 if len(p["blocks"]) > blocks else 1),
                             "step_ms": blk["wall_ms_per_step"],
                             "us_per_grain_step": blk["us_per_grain_step"], "kernel_ms": k["kernel"],
                             "read_ms": k["read"], "apply_ms": k["apply"], "newton_ms": e.get("newton", np.nan),
                             "touching": blk["touching"],
                             "us_per_touch": 1e3 * k["kernel"] / blk["touching"] if blk["touching"] else np.nan,
                             "kernel_memory_mb": blk["memory_bytes"] / 2 ** 20})
    df = pd.DataFrame(rows)
    df["controller_ms"] = df["n"].map(ctrl)
    df["whole_ms"] = df["step_ms"] + df["controller_ms"].fillna(0)
    df["serial_share"] = (df["read_ms"] + df["apply_ms"] + df["controller_ms"].fillna(0)) / df["whole_ms"]
    df.to_csv(os.path.join(out, "bench-scale-dense.csv"), index=False)
    key = ["n", "threads", "path", "block"]
    idx = df.set_index(key)
    base, few = df["n"].min(), min(threads)
    df["per_grain_ratio"] = [r["us_per_grain_step"] / idx.loc[(base, r["threads"], r["path"], r["block"]),
                                                              "us_per_grain_step"] for _, r in df.iterrows()]
    df["speedup"] = [idx.loc[(r["n"], few, r["path"], r["block"]), "step_ms"] / r["step_ms"] for _, r in df.iterrows()]
    has_py = (df["path"] == "pyrunner").any()
    df["pyrunner_over_plugin"] = [
        (idx.loc[(r["n"], r["threads"], "pyrunner", r["block"]), "whole_ms"] / r["whole_ms"])
        if has_py and r["path"] == "plugin" else np.nan for _, r in df.iterrows()]
    med = df.groupby(["n", "threads", "path"]).median(numeric_only=True).reset_index()
    med = med.sort_values(["n", "threads", "path"])
    lines = [f"Dense packings ({', '.join(specs)}), {steps} steps per block, medians of {blocks} blocks "
             f"(bench_scale.py --dense, {time.strftime('%Y-%m-%d')}); the controller per step is the run's "
             f"own (its info.json), the same on both paths:", "",
             f"| N | threads | kernel path | ms per step (engines) | + controller | whole step ms | "
             f"PyRunner / plugin (whole step) | µs per grain-step | per grain vs N = {base} | "
             f"speed-up vs {few} thread(s) | kernel | read poses | add forces | Newton | serial share | "
             "touching contacts | µs per touching contact (kernel) | kernel memory (MB) |", "|---" * 18 + "|"]
    for _, r in med.iterrows():
        ratio = "" if np.isnan(r["pyrunner_over_plugin"]) else f"{r['pyrunner_over_plugin']:.2f}"
        lines.append(f"| {int(r['n'])} | {int(r['threads'])} | {r['path']} | {r['step_ms']:.2f} | "
                     f"{r['controller_ms']:.2f} | {r['whole_ms']:.2f} | {ratio} | {r['us_per_grain_step']:.2f} | "
                     f"{r['per_grain_ratio']:.3f} | {r['speedup']:.2f} | {r['kernel_ms']:.2f} | {r['read_ms']:.3f} | "
                     f"{r['apply_ms']:.3f} | {r['newton_ms']:.2f} | {r['serial_share']:.3f} | {r['touching']:.0f} | "
                     f"{r['us_per_touch']:.2f} | {r['kernel_memory_mb']:.1f} |")
    with open(os.path.join(out, "bench-scale-dense.md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, nargs="+", default=[1000, 5000, PAPER_N])
    ap.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--steps", type=int, default=300)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--timeout", type=float, default=3600.0, help="s per run before it is stopped anyway")
    ap.add_argument("--out", default=os.path.join(ROOT, "runs", "bench-scale"))
    ap.add_argument("--library", default=DEFAULT_LIBRARY)
    ap.add_argument("--dense", nargs="+", metavar="RUN.h5:SNAP",
                    help="instead: these dense packings stepped side by side in YADE (bench_scale_dense.py)")
    ap.add_argument("--blocks", type=int, default=5, help="--dense: blocks (rounds) per thread count")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.dense:
        print("\n".join(dense(args.dense, args.threads, args.steps, args.blocks, args.out)))
        return
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
                r = run_once(folders[n], th, args.steps, args.timeout, fresh=(rnd == 0 and th == args.threads[0]))
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
