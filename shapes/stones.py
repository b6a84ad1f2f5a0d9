"""The real-stone library: the scanned stones of the public StonePacking-3D
data set, imported and reduced as any scan (:mod:`shapes.meshimport`), kept
in the repository with each stone's source, licence and import error.

::

    git clone https://github.com/qianqing-wanggg/StonePacking-3D
    python -m shapes.stones StonePacking-3D [--out reference_data/stonepacking-3d.h5]

The command imports every mesh of ``data/example19/available_stones`` and
``data/example18/available_stones`` (:data:`FOLDERS`; the repository's other
folders hold rotated copies and the ground) at the import's default budget
(``--max-error 0.02``, at most 37 vertices), and writes

* ``OUT.h5``, a shape library (:mod:`shapes.library`) whose grains carry,
  besides the import's datasets (``source_d``, ``source_d_hull``,
  ``convexity_deficit``, ``reduction_hausdorff``,
  ``reduction_volume_change``, ...), ``source`` = the stone's file as
  ``owner/name@commit:path`` and ``licence``; the file attributes
  ``origin``, ``commit``, ``licence`` and ``refused`` (JSON, the stones the
  import refused with their reasons);
* ``OUT.md``, the stones' table (source, vertices, faces, error, volume
  change, deficit, target met) with the origin and the command;
* ``OUT.LICENSE``, the data set's licence text, copied from the checkout.

The checkout must hold the data set's MIT licence (its ``LICENSE``), or the
command refuses. The commit is read with ``git rev-parse HEAD`` in the
checkout, or given with ``--commit`` (a checkout that is not a git work tree,
e.g. a ``git archive`` of a mirror).

``make study SHAPES=reference_data/stonepacking-3d.h5`` runs the study's S1
on these stones (docs/study.md, "Real stones").
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import time

import numpy as np

REPOSITORY = "qianqing-wanggg/StonePacking-3D"
FOLDERS = ("data/example19/available_stones", "data/example18/available_stones")
LICENCE = "MIT"
COPYRIGHT = "Copyright (c) 2025 qianqing-wanggg"
DEFAULT_OUT = "reference_data/stonepacking-3d.h5"


class StonesError(ValueError):
    """A checkout that is not StonePacking-3D's as this command expects."""


def check_checkout(checkout):
    """The checkout's licence text, after checking that it is the data set's.

    Parameters
    ----------
    checkout : str
        A folder holding StonePacking-3D (its ``LICENSE`` and :data:`FOLDERS`).

    Returns
    -------
    str
        The text of ``LICENSE``.

    Raises
    ------
    StonesError
        One line: no such folder, no licence, a licence other than MIT by
        :data:`COPYRIGHT`, or a missing stone folder.

    Examples
    --------
    >>> import tempfile
    >>> check_checkout(tempfile.mkdtemp())          # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    shapes.stones.StonesError: ...: no LICENSE file: not a checkout of qianqing-wanggg/StonePacking-3D
    """
    if not os.path.isdir(checkout):
        raise StonesError(f"{checkout}: no such folder (clone https://github.com/{REPOSITORY} first)")
    path = os.path.join(checkout, "LICENSE")
    if not os.path.isfile(path):
        raise StonesError(f"{checkout}: no LICENSE file: not a checkout of {REPOSITORY}")
    with open(path, encoding="utf-8", errors="replace") as fh:
        text = fh.read()
    if not text.lstrip().startswith("MIT License") or COPYRIGHT not in text:
        raise StonesError(f"{path}: not the MIT licence of {REPOSITORY} ({COPYRIGHT!r} not found); "
                          "the library records that licence, so it refuses another")
    for folder in FOLDERS:
        if not os.path.isdir(os.path.join(checkout, folder)):
            raise StonesError(f"{checkout}: no folder {folder}: not a checkout of {REPOSITORY}")
    return text


def checkout_commit(checkout):
    """The commit of a git work tree (40 hex digits), or None when it is not
    one (or git is missing)."""
    try:
        out = subprocess.run(["git", "-C", checkout, "rev-parse", "HEAD"], capture_output=True, text=True,
                             timeout=30)
    except (OSError, subprocess.SubprocessError):
        return None
    sha = out.stdout.strip()
    return sha if out.returncode == 0 and len(sha) == 40 else None


def build_stone_library(checkout, out=DEFAULT_OUT, commit=None, budget=None, log=None):
    """Import the data set's stones into a library with their provenance
    (module docstring).

    Parameters
    ----------
    checkout : str
        A checkout of StonePacking-3D (:func:`check_checkout`).
    out : str
        The library to write; ``OUT.md`` and ``OUT.LICENSE`` go beside it.
    commit : str, optional
        The checkout's commit (default: read by git; "unknown" if neither).
    budget : shapes.hullreduce.Budget, optional
        The reduction's budget (default: the import's, 0.02 d, 37 vertices).
    log : callable, optional
        ``log(name, reason)`` at each refused stone.

    Returns
    -------
    dict
        ``n`` stones imported, ``refused`` [(path, reason)], ``seconds``,
        ``vertices`` (mean), ``error_median`` and ``error_max`` (Hausdorff /
        d_hull), ``within_target`` (count), ``units_warning`` (str or None).

    Examples
    --------
    One stone (the tests' copy of stone_041) in a folder laid out as the
    data set:

    >>> import tempfile
    >>> here = os.path.join(os.path.dirname(__file__), os.pardir, "tests", "data", "stonepacking")
    >>> repo = tempfile.mkdtemp()
    >>> os.makedirs(os.path.join(repo, FOLDERS[0])); os.makedirs(os.path.join(repo, FOLDERS[1]))
    >>> _ = shutil.copy(os.path.join(here, "LICENSE"), repo)
    >>> _ = shutil.copy(os.path.join(here, "stone_041.obj"), os.path.join(repo, FOLDERS[0]))
    >>> s = build_stone_library(repo, os.path.join(repo, "stones.h5"), commit="0" * 40)
    >>> s["n"], round(s["error_max"], 4), s["refused"]     # the other folder is empty here
    (1, 0.0237, [('data/example18/available_stones', 'no .obj, .off, .ply, .stl file in this folder (empty)')])
    >>> from shapes.library import ShapeLibrary
    >>> lib = ShapeLibrary(os.path.join(repo, "stones.h5"))
    >>> lib.source[0].decode(), lib.licence[0].decode()
    ('qianqing-wanggg/StonePacking-3D@0000000000000000000000000000000000000000:data/example19/available_stones/stone_041.obj', 'MIT, Copyright (c) 2025 qianqing-wanggg')
    """
    from .__main__ import _tolerances
    from .library import write_library
    from .hullreduce import Budget
    from .meshimport import import_paths, library_datasets, mixed_units

    licence_text = check_checkout(checkout)
    commit = commit or checkout_commit(checkout) or "unknown"
    budget = budget or Budget()
    t0 = time.perf_counter()
    out_abs = os.path.abspath(out)

    def in_repo(path):                          # a path as the repository names it
        return os.path.relpath(path, checkout).replace(os.sep, "/")

    grains, refused, _ = import_paths([os.path.join(checkout, f) for f in FOLDERS], budget,
                                      log=(lambda name, reason: log(in_repo(name), reason)) if log else None)
    refused = [(in_repo(name), reason) for name, reason in refused]
    seconds = time.perf_counter() - t0
    if not grains:
        raise StonesError(f"{checkout}: no stone imported ({len(refused)} refused)")
    licence = f"{LICENCE}, {COPYRIGHT}"
    extra = {**library_datasets(grains), "source": [f"{REPOSITORY}@{commit}:{in_repo(g.source)}" for g in grains],
             "licence": [licence] * len(grains)}
    recipe = {"source": "meshes", "repository": REPOSITORY, "commit": commit, "inputs": list(FOLDERS),
              "budget": budget.as_dict(), "components": False, "merge_tolerance": 0.0}
    os.makedirs(os.path.dirname(out_abs), exist_ok=True)
    write_library(out_abs, [g.polyhedron for g in grains], -1, recipe, _tolerances(), name="StonePacking-3D stones",
                  created_by="python -m shapes.stones", extra=extra)
    import h5py

    with h5py.File(out_abs, "a") as f:
        f.attrs.update({"origin": f"https://github.com/{REPOSITORY}", "commit": commit, "licence": licence,
                        "refused": json.dumps([[name, reason] for name, reason in refused])})
    base = out_abs.rsplit(".", 1)[0]
    with open(base + ".LICENSE", "w", encoding="utf-8") as fh:
        fh.write(licence_text)
    err = extra["reduction_hausdorff"]
    met = np.array([g.target_met for g in grains])
    summary = {"n": len(grains), "refused": refused, "seconds": seconds,
               "vertices": float(np.mean([g.polyhedron.n_vertices for g in grains])),
               "error_median": float(np.median(err)), "error_max": float(err.max()),
               "within_target": int(met.sum()), "units_warning": mixed_units(extra["source_d"])}
    _write_table(base + ".md", grains, extra, met, refused, summary, budget, commit, os.path.basename(out_abs))
    return summary


def _write_table(path, grains, extra, met, refused, summary, budget, commit, name):
    from .report import budget_text

    lines = [f"# {name}: the StonePacking-3D stones, reduced",
             "",
             f"Made by `python -m shapes.stones CHECKOUT --out {DEFAULT_OUT}` from the public data set "
             f"[{REPOSITORY}](https://github.com/{REPOSITORY}), commit `{commit}`, folders "
             + ", ".join(f"`{f}`" for f in FOLDERS) + f". Licence: {LICENCE}, {COPYRIGHT} (the text is "
             f"`{name.rsplit('.', 1)[0]}.LICENSE` beside this file).",
             "",
             f"Budget: {budget_text(budget.as_dict())}. {summary['n']} stones imported, "
             f"{len(refused)} refused; vertices {summary['vertices']:.1f} on average; reduction error "
             f"(Hausdorff distance to the full hull / d_hull) median {summary['error_median']:.4f}, max "
             f"{summary['error_max']:.4f}; {summary['within_target']} of {summary['n']} within the target."
             + (f" Warning: {summary['units_warning']} (the grains are normalised to d = 1, so only "
                "`source_d` is affected)." if summary["units_warning"] else ""),
             ""]
    if refused:
        lines += ["Refused:", ""] + [f"- `{n}`: {r}" for n, r in refused] + [""]
    lines += ["| grain | source | vertices | faces | error / d | volume change | convexity deficit | "
              "source d (file units) | target met |",
              "|---|---|---|---|---|---|---|---|---|"]
    for i, g in enumerate(grains):
        p = g.polyhedron
        lines.append(f"| {i} | `{extra['source'][i].split(':', 1)[1]}` | {p.n_vertices} | {p.n_faces} | {extra['reduction_hausdorff'][i]:.4f} | "
                     f"{extra['reduction_volume_change'][i]:+.3f} | {extra['convexity_deficit'][i]:.3f} | "
                     f"{extra['source_d'][i]:.4g} | {'yes' if met[i] else 'no'} |")
    with open(path, "w", encoding="utf-8") as fh:
        fh.write("\n".join(lines) + "\n")


def main(argv=None):
    """``python -m shapes.stones CHECKOUT [--out OUT.h5] [--commit SHA]``;
    exit 0 when every stone was imported, 1 when some were refused (listed
    on stderr, the library holds the others), 2 on an unusable checkout."""
    ap = argparse.ArgumentParser(prog="python -m shapes.stones", description=__doc__.split("\n\n")[0])
    ap.add_argument("checkout", help=f"a checkout of https://github.com/{REPOSITORY}")
    ap.add_argument("--out", default=DEFAULT_OUT, help=f"the library (default {DEFAULT_OUT})")
    ap.add_argument("--commit", help="the checkout's commit, when it is not a git work tree")
    args = ap.parse_args(argv)
    try:
        s = build_stone_library(args.checkout, args.out, commit=args.commit,
                                log=lambda name, reason: print(f"shapes.stones: refused {name}: {reason}",
                                                               file=sys.stderr))
    except StonesError as exc:
        print(f"shapes.stones: error: {exc}", file=sys.stderr)
        return 2
    if s["units_warning"]:
        print(f"shapes.stones: warning: {s['units_warning']}", file=sys.stderr)
    print(f"shapes.stones: {s['n']} stones -> {args.out} in {s['seconds']:.1f} s, {len(s['refused'])} refused; "
          f"vertices {s['vertices']:.1f} on average, error median {s['error_median']:.4f} d, max "
          f"{s['error_max']:.4f} d, {s['within_target']} within the target; table in "
          f"{args.out.rsplit('.', 1)[0]}.md", file=sys.stderr)
    return 1 if s["refused"] else 0


if __name__ == "__main__":
    sys.exit(main())
