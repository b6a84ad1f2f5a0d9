"""Generate a run folder: ``python -m yade_scripts.campaign.generate``.

    python -m yade_scripts.campaign.generate --preset tiny --sample polyhedra --out runs/t1 \
        [--set kappa=3000 --set seed=4] [--seeds 1 2 3] [--library LIB.h5]

The folder holds everything the run needs, so it can be moved or rerun:

    triaxial.py   the scene, its parameter block set from the preset
    pkg/          a copy of this repository's packages yade_scripts, shapes and
                  postproc (the scene imports them under their own names)
    shapes.h5     the polyhedra library (polyhedra runs)
    params.json   the resolved parameters
    table.txt     a yade-batch table (one line per seed, or the one run)

Run it with ``cd FOLDER && yade -x triaxial.py`` or, every line of the
table, ``python -m yade_scripts.launch.batch FOLDER --jobs 2`` (or
``yade-batch -j 2 table.txt triaxial.py``). With ``--slurm`` also
``slurm.sh``, a SLURM job array with one task per table line
(:mod:`yade_scripts.launch.slurm`): ``sbatch FOLDER/slurm.sh`` from any folder.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import sys

from .. import yadeplugin
from ..launch import slurm
from ..launch.batch import read_table
from ..scene.parameters import SAMPLES, ConfigError, scene_with_block
from .presets import resolve

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
#: the scene's template, copied into every run folder as ``triaxial.py``
SCENE = os.path.join(ROOT, "yade_scripts", "scene", "triaxial.py")
#: the packages a run folder gets a copy of, under their own names, in its
#: ``pkg/`` (the scene puts ``pkg/`` first on its sys.path): the scene's own
#: modules, the shapes and the contact kernel (its C source included), the
#: dump schema
PACKAGES = ("yade_scripts", "shapes", "postproc")
DEFAULT_LIBRARY = os.path.join(ROOT, "runs", "shapes", "library.h5")


def render_scene(params):
    """triaxial.py with its parameter block set to the checked ``params``
    (:func:`yade_scripts.scene.parameters.render_block`)."""
    with open(SCENE) as fh:
        return scene_with_block(fh.read(), params)


def parse_overrides(items):
    """The overrides of ``--set NAME=VALUE`` options: {NAME: VALUE text}.

    Parameters
    ----------
    items : list of str or None
        The options' values, as argparse gives them (None: none given).

    Returns
    -------
    dict
        name -> value text, both stripped; the values are checked later
        (:func:`yade_scripts.scene.parameters.coerce`).

    Raises
    ------
    ConfigError
        An item without ``=``.

    Examples
    --------
    >>> parse_overrides(["kappa=1000", " seed = 4"])
    {'kappa': '1000', 'seed': '4'}
    >>> parse_overrides(None)
    {}
    """
    out = {}
    for item in items or []:
        if "=" not in item:
            raise ConfigError(f"--set takes NAME=VALUE, got {item!r}")
        k, v = item.split("=", 1)
        out[k.strip()] = v.strip()
    return out


def generate(out, preset, sample, overrides=None, seeds=None, library=None):
    """Create the run folder ``out``: everything one sample's runs need, so
    that the folder can be moved and run again.

    It holds ``triaxial.py`` (the scene, its parameter block set to the
    resolved parameters), ``pkg/`` (:func:`copy_packages`), ``params.json``
    (the preset's name and the parameters), ``table.txt`` (a yade-batch
    table, one line per seed, :func:`write_seed_table`) and, for
    polyhedra, the shape library under the name of the ``library``
    parameter (``shapes.h5``). Nothing is run: ``cd out && yade -x
    triaxial.py`` runs the scene's own parameters,
    ``python -m yade_scripts.launch.batch out`` every line of the table.

    Parameters
    ----------
    out : str
        The folder to make (its parents too); it must not hold a
        ``triaxial.py`` already.
    preset : str
        A preset of :data:`yade_scripts.campaign.presets.PRESETS` ("tiny", "default"
        ...).
    sample : {"polyhedra", "spheres"}
        S1 or S2.
    overrides : dict, optional
        name -> value (or its text, as ``--set`` gives it), applied last
        (:func:`yade_scripts.campaign.presets.resolve`).
    seeds : list of int, optional
        One table line per seed (default: the resolved ``seed``, 1 unless
        overridden).
    library : str, optional
        The polyhedra's shape library (an HDF5 file of
        :mod:`shapes.library`; default :data:`DEFAULT_LIBRARY`, which
        ``make shapes`` builds); not read for spheres.

    Returns
    -------
    dict
        The resolved, checked parameters the scene runs with (those of
        ``params.json`` but for ``preset``).

    Raises
    ------
    ConfigError
        One line, before anything is written: an invalid preset, sample or
        override, a folder that holds a run already, or a missing shape
        library.

    Examples
    --------
    >>> import os, tempfile
    >>> out = os.path.join(tempfile.mkdtemp(), "t1")
    >>> p = generate(out, "tiny", "spheres", {"kappa": "300"}, seeds=[1, 2])
    >>> p["n_particles"], p["kappa"], p["sigma0"]          # 40 spheres, kappa set, sigma0 in Pa
    (40, 300.0, 10000.0)
    >>> sorted(os.listdir(out)), sorted(os.listdir(os.path.join(out, "pkg")))
    (['params.json', 'pkg', 'table.txt', 'triaxial.py'], ['postproc', 'shapes', 'yade_scripts'])
    >>> print(open(os.path.join(out, "table.txt")).read(), end="")
    description seed out
    spheres-seed1 1 'spheres-seed1.h5'
    spheres-seed2 2 'spheres-seed2.h5'
    >>> "    kappa=300.0," in open(os.path.join(out, "triaxial.py")).read()
    True
    >>> generate(out, "tiny", "spheres")
    Traceback (most recent call last):
        ...
    yade_scripts.scene.parameters.ConfigError: .../t1 already holds a run; choose another --out
    """
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
    """``python -m yade_scripts.campaign.generate``: make a run folder
    (:func:`generate`) and, with ``--slurm``, its SLURM array script
    (:func:`yade_scripts.launch.slurm.write_slurm`); prints how to run it.

    Parameters
    ----------
    argv : list of str, optional
        The command line's arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit code: 0 made, 2 refused (one line on stderr).
    """
    ap = argparse.ArgumentParser(prog="python -m yade_scripts.campaign.generate", description=__doc__.splitlines()[0])
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
