"""The same run on the kernel plugin's path and on the PyRunner path: every
dataset of the dumps compared bit for bit.

    python benchmarks/plugin_same_run.py [--preset default] [--seed 1] [--final-strain 0.01] \
        [--threads 1] [--out runs/plugin-same-run] [--library runs/shapes/library.h5]

Three run folders of the preset's S1 (``final_strain`` set, nothing else
changed) are run one after another, each alone: ``plugin`` (YADE started
with the plugin's YADE_PREFIX, as the launchers do), ``pyrunner`` (the same
with POLYHEDRA_NO_PLUGIN=1: the scene's PyRunner steps the kernel) and
``plugin-again`` (the plugin once more: same seed, same dump). For each pair
(plugin against pyrunner, plugin against plugin-again) every dataset of the
two dumps is compared; a dataset that differs is reported with its largest
relative difference. The runs' wall times and the kernel's split (reading
the poses, the kernel, adding the forces) come from each run's info.json.
Writes OUT/plugin-same-run.md and prints it. Finished runs are not run again.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import time

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)
from yade_scripts.runs import noremote  # noqa: E402
from yade_scripts import yadeplugin  # noqa: E402
from yade_scripts.campaign.generate import DEFAULT_LIBRARY, generate  # noqa: E402


def datasets(path):
    """{name: array} of every dataset of an HDF5 file."""
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda n, o: out.__setitem__(n, o[()]) if isinstance(o, h5py.Dataset) else None)
    return out


def compare(a, b):
    """(equal datasets, [(name, why)] of those that differ)."""
    bad = []
    for k in sorted(set(a) | set(b)):
        if k not in a or k not in b:
            bad.append((k, "only in one dump"))
            continue
        x, y = a[k], b[k]
        if x.shape != y.shape or x.dtype != y.dtype:
            bad.append((k, f"shape/dtype {x.shape} {x.dtype} against {y.shape} {y.dtype}"))
        elif not np.array_equal(x, y, equal_nan=x.dtype.kind == "f"):
            if x.dtype.kind == "f":
                scale = np.maximum(np.abs(x), np.abs(y))
                rel = np.where(scale > 0, np.abs(x - y) / np.where(scale > 0, scale, 1), 0)
                bad.append((k, f"largest relative difference {np.nanmax(rel):.3g}"))
            else:
                bad.append((k, f"{int(np.sum(x != y))} of {x.size} values differ"))
    return len(set(a) & set(b)) - len(bad), bad


def run(folder, plugin, threads):
    """Run the folder's scene (unless its dump is complete); returns its info.json."""
    info_path = os.path.join(folder, "run.info.json")
    if not os.path.exists(info_path):
        env = yadeplugin.environment(run_folder=folder) if plugin else dict(os.environ, **{yadeplugin.SKIP_VARIABLE: "1"})
        if plugin and "YADE_PREFIX" not in env:
            raise SystemExit(f"plugin_same_run: no ready plugin ({yadeplugin.status()['why']}): make kernel")
        env["OMP_WAIT_POLICY"] = "PASSIVE"
        t0 = time.time()
        with open(os.path.join(folder, "yade.log"), "w") as log:
            rc = subprocess.run(noremote.command(shutil.which("yade"), ["-j", str(threads), "-n", "-x", "triaxial.py"]),
                                cwd=folder, env=env,
                                stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL).returncode
        if rc != 0:
            raise SystemExit(f"plugin_same_run: {folder}: exit {rc} (see yade.log)")
        print(f"{os.path.basename(folder)}: {time.time() - t0:.0f} s", flush=True)
    with open(info_path) as fh:
        return json.load(fh)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--preset", default="default")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--final-strain", type=float, default=0.01)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--out", default=os.path.join(ROOT, "runs", "plugin-same-run"))
    ap.add_argument("--library", default=DEFAULT_LIBRARY)
    args = ap.parse_args()
    over = {"seed": args.seed, "final_strain": args.final_strain, "checkpoint_seconds": 0}
    infos, dumps = {}, {}
    for name, plugin in (("plugin", True), ("pyrunner", False), ("plugin-again", True)):
        folder = os.path.join(args.out, name)
        if not os.path.exists(os.path.join(folder, "triaxial.py")):
            generate(folder, args.preset, "polyhedra", over, library=args.library)
        infos[name] = run(folder, plugin, args.threads)
        dumps[name] = datasets(os.path.join(folder, "run.h5"))
        if infos[name]["kernel"]["path"] != ("plugin" if plugin else "pyrunner"):
            raise SystemExit(f"plugin_same_run: {name} ran on the {infos[name]['kernel']['path']} path: "
                             f"{infos[name]['kernel']['path_note']}")
    lines = [f"# The same run on both kernel paths ({time.strftime('%Y-%m-%d')})", "",
             f"Preset {args.preset}, S1, seed {args.seed}, to eps_1 = {args.final_strain}, {args.threads} thread(s) "
             f"(`python benchmarks/plugin_same_run.py`).", "",
             "| run | steps | snapshots | wall s | read poses s | kernel s | add forces s | touching contact-steps |",
             "|---|---|---|---|---|---|---|---|"]
    for name, i in infos.items():
        k = i["kernel"]
        lines.append(f"| {name} | {i['steps']} | {i['snapshots']} | {i['wall_seconds']:.0f} | {k['read']:.2f} | "
                     f"{k['kernel']:.1f} | {k['apply']:.2f} | {k['touch_steps']} |")
    lines.append("")
    for a, b in (("plugin", "pyrunner"), ("plugin", "plugin-again")):
        n, bad = compare(dumps[a], dumps[b])
        verdict = "every dataset equal bit for bit" if not bad else f"{len(bad)} dataset(s) differ"
        lines.append(f"- {a} against {b}: {n} of {len(dumps[a])} datasets equal; {verdict}")
        lines += [f"  - {k}: {why}" for k, why in bad[:20]]
    text = "\n".join(lines) + "\n"
    with open(os.path.join(args.out, "plugin-same-run.md"), "w") as fh:
        fh.write(text)
    print(text)


if __name__ == "__main__":
    main()
