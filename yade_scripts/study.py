"""Run S1 and S2 on a preset side by side and analyse both dumps:
``python -m yade_scripts.study --preset default --out runs/study``.

Each sample gets its own run folder (``OUT/polyhedra``, ``OUT/spheres``); a
run whose dump is complete is not run again. YADE's progress lines are
relayed with the sample name in front. A failed run is reported and the other
one is still analysed; the exit code is non-zero when any run failed.
"""
from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import threading

from .generate import DEFAULT_LIBRARY, generate, parse_overrides
from .presets import ConfigError, resolve

SAMPLES = ("polyhedra", "spheres")


def finished(folder):
    """True when the folder holds a complete dump."""
    path = os.path.join(folder, "run.h5")
    if not os.path.exists(os.path.join(folder, "run.info.json")) or not os.path.exists(path):
        return False
    import h5py

    try:
        with h5py.File(path, "r") as f:
            return bool(f.attrs.get("complete", 0))
    except OSError:
        return False


def _set_aside_if_changed(folder, preset, sample, overrides):
    """A run folder made with other parameters is renamed FOLDER.old-K, so
    that the run is generated afresh (and never silently reused)."""
    path = os.path.join(folder, "params.json")
    if not os.path.exists(path):
        return
    import json

    with open(path) as fh:
        old = json.load(fh)
    new = {"preset": preset, **resolve(preset, sample, overrides)}
    if old == json.loads(json.dumps(new)):
        return
    k = 1
    while os.path.exists(f"{folder}.old-{k}"):
        k += 1
    os.rename(folder, f"{folder}.old-{k}")
    print(f"[{sample}] parameters changed: previous run kept as {folder}.old-{k}", flush=True)


def _relay(name, proc, logpath):
    with open(logpath, "a") as log:
        for line in proc.stdout:
            log.write(line)
            log.flush()
            if line.startswith("triaxial.py:"):
                print(f"[{name}] {line[len('triaxial.py: '):].rstrip()}", flush=True)


def run_samples(out, preset, overrides=None, library=None, samples=SAMPLES):
    """Generate (if needed) and run the samples in parallel; returns
    {sample: return code (0 = done or already done)}."""
    yade = shutil.which("yade")
    if yade is None:
        raise ConfigError("yade is not installed (make installs Debian's yade)")
    procs = {}
    for s in samples:
        folder = os.path.join(out, s)
        _set_aside_if_changed(folder, preset, s, overrides)
        if finished(folder):
            print(f"[{s}] already complete in {folder}, not run again", flush=True)
            continue
        if os.path.exists(os.path.join(folder, "triaxial.py")):
            # an unfinished earlier attempt: start afresh, keep its log
            for name in ("run.h5", "run.h5.parts", "run.log.csv", "run.info.json"):
                p = os.path.join(folder, name)
                shutil.rmtree(p, ignore_errors=True) if os.path.isdir(p) else (os.path.exists(p) and os.remove(p))
        else:
            generate(folder, preset, s, overrides, library=library or DEFAULT_LIBRARY)
        proc = subprocess.Popen([yade, "-n", "-x", "triaxial.py"], cwd=folder, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, text=True, bufsize=1)
        t = threading.Thread(target=_relay, args=(s, proc, os.path.join(folder, "yade.log")), daemon=True)
        t.start()
        procs[s] = (proc, t)
    codes = {s: 0 for s in samples}
    for s, (proc, t) in procs.items():
        codes[s] = proc.wait()
        t.join()
        status = "done" if codes[s] == 0 else f"FAILED (exit {codes[s]}, see {os.path.join(out, s, 'yade.log')})"
        print(f"[{s}] {status}", flush=True)
    return codes


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m yade_scripts.study", description=__doc__.splitlines()[0])
    ap.add_argument("--preset", default="default")
    ap.add_argument("--out", required=True)
    ap.add_argument("--set", action="append", metavar="NAME=VALUE")
    ap.add_argument("--library")
    args = ap.parse_args(argv)
    try:
        codes = run_samples(args.out, args.preset, parse_overrides(args.set), args.library)
    except ConfigError as exc:
        print(f"study: error: {exc}", file=sys.stderr)
        return 2
    from postproc.cli import main as postproc_main

    for s, code in codes.items():
        dump = os.path.join(args.out, s, "run.h5")
        if os.path.exists(dump):
            rc = postproc_main(["analyze", dump, "--out", os.path.join(args.out, s, "analysis")])
            if rc:
                print(f"study: analysis of {s} exited {rc}", file=sys.stderr)
    failed = [s for s, c in codes.items() if c]
    if failed:
        print(f"study: failed runs: {', '.join(failed)}", file=sys.stderr)
        return 1
    print(f"study: results in {args.out}/<sample>/analysis/", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
