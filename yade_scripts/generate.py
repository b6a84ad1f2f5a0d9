"""Generate a run folder: ``python -m yade_scripts.generate``.

    python -m yade_scripts.generate --preset tiny --sample polyhedra --out runs/t1 \
        [--set kappa=3000 --set seed=4] [--seeds 1 2 3] [--library LIB.h5]

The folder holds everything the run needs, so it can be moved or rerun:

    triaxial.py   the scene, its parameter block set from the preset
    pkg/          a copy of this repository's packages yade_scripts, shapes and
                  postproc (the scene imports them under their own names)
    shapes.h5     the polyhedra library (polyhedra runs)
    params.json   the resolved parameters
    table.txt     a yade-batch table (one line per seed, or the one run)

Run it with ``cd FOLDER && yade -x triaxial.py`` or, every line of the
table, ``python -m yade_scripts.batch FOLDER --jobs 2`` (or
``yade-batch -j 2 table.txt triaxial.py``). With ``--slurm`` also
``slurm.sh``, a SLURM job array with one task per table line
(:mod:`yade_scripts.slurm`): ``sbatch FOLDER/slurm.sh`` from any folder.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import sys

from . import slurm, yadeplugin
from .parameters import SAMPLES, ConfigError, scene_with_block
from .presets import resolve

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
#: the packages a run folder gets a copy of, under their own names, in its
#: ``pkg/`` (the scene puts ``pkg/`` first on its sys.path): the scene's own
#: modules, the shapes and the contact kernel (its C source included), the
#: dump schema
PACKAGES = ("yade_scripts", "shapes", "postproc")
DEFAULT_LIBRARY = os.path.join(ROOT, "runs", "shapes", "library.h5")


def render_scene(params):
    """triaxial.py with its parameter block set to the checked ``params``
    (:func:`yade_scripts.parameters.render_block`)."""
    with open(os.path.join(HERE, "triaxial.py")) as fh:
        return scene_with_block(fh.read(), params)


def parse_overrides(items):
    out = {}
    for item in items or []:
        if "=" not in item:
            raise ConfigError(f"--set takes NAME=VALUE, got {item!r}")
        k, v = item.split("=", 1)
        out[k.strip()] = v.strip()
    return out


def generate(out, preset, sample, overrides=None, seeds=None, library=None):
    """Create the run folder ``out``; returns the resolved parameters."""
    params = resolve(preset, sample, overrides)
    if os.path.exists(os.path.join(out, "triaxial.py")):
        raise ConfigError(f"{out} already holds a run; choose another --out")
    lib_src = library or DEFAULT_LIBRARY
    if sample == "polyhedra" and not os.path.exists(lib_src):
        raise ConfigError(f"shape library {lib_src} not found: build it with 'make shapes'")
    os.makedirs(out, exist_ok=True)
    copy_packages(out)
    if sample == "polyhedra":
        shutil.copyfile(lib_src, os.path.join(out, params["library"]))
    with open(os.path.join(out, "triaxial.py"), "w") as fh:
        fh.write(render_scene(params))
    with open(os.path.join(out, "params.json"), "w") as fh:
        json.dump({"preset": preset, **params}, fh, indent=1)
    write_seed_table(out, sample, seeds or [params["seed"]])
    return params


def copy_packages(out):
    """``out/pkg/<package>`` for each of :data:`PACKAGES`: this repository's
    code as the run ran it (Python files, the kernel's C source, the YADE
    plugin's source; no caches, no compiled kernel: it is built in the copy
    on first use), and the YADE plugin's build for the installed YADE when
    there is one (:mod:`yade_scripts.yadeplugin`; the folder then carries
    it, else its scene steps the kernel from a PyRunner)."""
    for name in PACKAGES:
        shutil.copytree(os.path.join(ROOT, name), os.path.join(out, "pkg", name), dirs_exist_ok=True,
                        ignore=shutil.ignore_patterns("__pycache__", "_build", "*.pyc", "*.so"))
    yadeplugin.copy_build(os.path.join(out, "pkg", "yade_scripts", "yadeplugin"))


def write_seed_table(out, sample, seeds):
    """``out/table.txt``: a yade-batch table with one line per seed, each
    writing ``<sample>-seed<k>.h5``."""
    with open(os.path.join(out, "table.txt"), "w") as fh:
        fh.write("description seed out\n")
        for s in seeds:
            # yade-batch evaluates each value as Python: strings are quoted
            fh.write(f"{sample}-seed{s} {s} '{sample}-seed{s}.h5'\n")


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m yade_scripts.generate", description=__doc__.splitlines()[0])
    ap.add_argument("--preset", default="default")
    ap.add_argument("--sample", required=True, choices=SAMPLES)
    ap.add_argument("--out", required=True)
    ap.add_argument("--set", action="append", metavar="NAME=VALUE", help="override a parameter")
    ap.add_argument("--seeds", type=int, nargs="+", help="seeds for the yade-batch table")
    ap.add_argument("--library", help="shape library (default runs/shapes/library.h5)")
    ap.add_argument("--slurm", action="store_true",
                    help="also write slurm.sh: a SLURM job array, one task per table line")
    slurm.add_options(ap)
    args = ap.parse_args(argv)
    try:
        if args.slurm:
            slurm.check_options(**slurm.options_of(args))
        p = generate(args.out, args.preset, args.sample, parse_overrides(args.set), args.seeds, args.library)
        if args.slurm:
            from .batch import read_table

            script = slurm.write_slurm(args.out, **slurm.options_of(args))
            print(f"generate: {script}: {len(read_table(args.out))} array task(s), about "
                  f"{slurm.estimate(p)['core_hours']:.3g} core-hours each; submit from any folder with: "
                  f"sbatch {script}", file=sys.stderr)
    except ConfigError as exc:
        print(f"generate: error: {exc}", file=sys.stderr)
        return 2
    prefix = yadeplugin.environment(run_folder=args.out).get("YADE_PREFIX") if p["sample"] == "polyhedra" else None
    run = f"YADE_PREFIX={prefix} yade -x triaxial.py" if prefix else "yade -x triaxial.py"
    print(f"generate: {args.out}: {p['n_particles']} {p['sample']} ({args.preset}); "
          f"run with: cd {args.out} && {run}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
