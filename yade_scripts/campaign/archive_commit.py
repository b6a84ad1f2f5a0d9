"""An archive read by the code that made it: a git worktree of the commit
that last changed the archive, with its environment, and the collect run
there.

    python -m yade_scripts.campaign.archive collect-at-commit ARCHIVE OUT

An archive of another analysis version (:data:`postproc.provenance.ANALYSIS_VERSION`)
is not used by today's code; its numbers are still those of the code that
made them. This builds ``OUT/source``, a detached git worktree of the
commit ``git log -1 --format=%H -- ARCHIVE`` (the archive as committed, and
the code it was committed with), uses this interpreter there when that
commit's ``pyproject.toml`` is today's (the same dependencies; the
worktree's own packages come first on the path) or else makes the
worktree's own ``.venv`` with its Makefile (``make venv``: PyPI must be
reachable), takes the shape library of this checkout when its content is
the archived one (:func:`yade_scripts.campaign.archive_store.library_fingerprint`) or else
builds it there (``make shapes``, about 20 s), generates the study's run
folders in ``OUT/study`` and collects them with the archive
(``yade_scripts.campaign.study --collect OUT/study --archive ... --no-figures``) and
writes ``OUT/results.json`` (``postproc results``), each step with that
commit's code. It needs git, the repository's history (not a shallow
clone without that commit), and about 5 MB beside the archive. Nothing of
the archive or of this checkout is changed.
"""
from __future__ import annotations

import os
import subprocess
import sys

from ..scene.parameters import ConfigError
from .archive_store import library_fingerprint
from .generate import DEFAULT_LIBRARY

#: the driver run with the commit's code: the run folders of the archive's
#: study generated as the study made them (what
#: yade_scripts.campaign.archive_store.study_folders does), in either layout
#: of yade_scripts (its rooms, or the flat folder of modules before them)
DRIVER = r'''
import json, os, sys
try:                    # yade_scripts in its rooms
    from yade_scripts.campaign.archive_store import FOLDER_RECORD, RUN_RECORD, _folder_record
    from yade_scripts.campaign.generate import generate
    from yade_scripts.campaign.presets import resolve
except ImportError:     # a commit of the flat yade_scripts
    from yade_scripts.archive import FOLDER_RECORD, RUN_RECORD, _folder_record
    from yade_scripts.generate import generate
    from yade_scripts.presets import resolve
dest, out, library = sys.argv[1:4]
counts = set()
for name in sorted(os.listdir(dest)):
    path = os.path.join(dest, name, FOLDER_RECORD)
    if not os.path.isfile(path):
        continue
    rec = json.load(open(path))
    params = rec["params"]
    runs = [json.load(open(os.path.join(dest, name, f))) for f in os.listdir(os.path.join(dest, name))
            if f.endswith(RUN_RECORD)]
    seeds = sorted({int(r["seed"]) for r in runs})
    for r in runs:
        counts.update(r.get("counts", []))
    base = resolve(params["preset"], params["sample"])
    over = {k: v for k, v in params.items() if k in base and base[k] != v and k not in ("seed", "library")}
    table = os.path.join(out, name)
    generate(table, params["preset"], params["sample"], over, seeds=seeds, library=library)
    if _folder_record(table) != rec:
        sys.exit(f"{table}: generated with other parameters or another shape library than {dest}/{name}")
print(" ".join(sorted(counts)))
'''


def _git(args, cwd):
    """git's stdout (stripped), or ConfigError with its message."""
    try:
        r = subprocess.run(["git", *args], cwd=cwd, capture_output=True, text=True)
    except OSError as exc:
        raise ConfigError(f"git cannot be run ({exc.strerror or exc})") from None
    if r.returncode:
        raise ConfigError(f"git {' '.join(args)}: {(r.stderr.strip().splitlines() or ['failed'])[-1]}")
    return r.stdout.strip()


def archive_commit(archive):
    """(repository root, archive path relative to it, commit) of the commit
    that last changed the archive ``archive``.

    Raises
    ------
    ConfigError
        ``archive`` is not a folder, is not in a git repository, has
        changes not committed (the commit would not hold them), or was never
        committed.
    """
    if not os.path.isdir(archive):
        raise ConfigError(f"{archive}: no such archive folder")
    here = os.path.abspath(archive)
    try:
        root = _git(["rev-parse", "--show-toplevel"], here)
    except ConfigError:
        raise ConfigError(f"{archive}: not in a git repository, so no commit made it") from None
    rel = os.path.relpath(here, root)
    if _git(["status", "--porcelain", "--", rel], root):
        raise ConfigError(f"{archive}: has changes not committed (git status -- {rel}): commit them first, "
                          "or the archive's commit would not hold them")
    commit = _git(["log", "-1", "--format=%H", "--", rel], root)
    if not commit:
        raise ConfigError(f"{archive}: never committed (git log -- {rel} is empty)")
    return root, rel, commit


def collect_at_commit(archive, out, echo=print):
    """Collect the archive ``archive`` with the code of the commit that made
    it, into ``out`` (the module docstring). Returns the path of
    ``OUT/results.json``.

    Raises
    ------
    ConfigError
        A refusal of :func:`archive_commit`, ``out`` exists and is not
        empty, or a step failed (named, with the command).
    """
    root, rel, commit = archive_commit(archive)
    if os.path.exists(out) and (not os.path.isdir(out) or os.listdir(out)):
        raise ConfigError(f"{out}: exists and is not empty; give a new folder")
    out = os.path.abspath(out)
    source = os.path.join(out, "source")
    os.makedirs(out, exist_ok=True)
    echo(f"[archive] {rel} as of commit {commit[:12]}: worktree {source}")
    _git(["worktree", "add", "--detach", source, commit], root)
    same = _git(["show", f"{commit}:pyproject.toml"], root) == open(os.path.join(root, "pyproject.toml")).read().strip()
    if same:
        python = sys.executable
        echo("[archive] its pyproject.toml is today's: this environment runs its code")
    else:
        echo("[archive] its dependencies differ: making its own .venv (make venv)")
        _run(["make", "venv"], source)
        python = os.path.join(source, ".venv", "bin", "python")
    lib = DEFAULT_LIBRARY
    wanted = _archived_fingerprint(os.path.join(source, rel))
    if not (os.path.exists(lib) and library_fingerprint(lib) == wanted):
        echo("[archive] building the shape library with its code (make shapes)")
        _run(["make", "shapes", f"PY={python}"], source)
        lib = os.path.join(source, "runs", "shapes", "library.h5")
    env = {**os.environ, "PYTHONPATH": source}
    study = os.path.join(out, "study")
    counts = _run([python, "-c", DRIVER, os.path.join(source, rel), study, lib], source, env).split()
    _run([python, "-m", study_module(source), "--collect", study, "--archive", os.path.join(source, rel),
          "--no-figures", "--counts", *counts], source, env)
    results = os.path.join(out, "results.json")
    _run([python, "-m", "postproc.cli", "results", study, "--out", results], source, env)
    echo(f"[archive] collected with commit {commit[:12]}'s code: {results}")
    return results


def study_module(source):
    """The study's module in the checkout ``source``, for ``python -m``:
    ``yade_scripts.campaign.study``, or ``yade_scripts.study`` in a commit
    whose ``yade_scripts`` is one flat folder of modules.

    Parameters
    ----------
    source : str
        The checkout (a worktree of the archive's commit).

    Returns
    -------
    str
        The dotted module name.

    Examples
    --------
    >>> import tempfile
    >>> study_module(tempfile.mkdtemp())
    'yade_scripts.campaign.study'
    """
    flat = os.path.join(source, "yade_scripts", "study.py")
    return "yade_scripts.study" if os.path.exists(flat) else "yade_scripts.campaign.study"


def _archived_fingerprint(dest):
    """The shape library fingerprint of the archive's polyhedra folder (None: none)."""
    import json

    for name in sorted(os.listdir(dest)):
        path = os.path.join(dest, name, "archive.json")
        if os.path.isfile(path):
            with open(path) as fh:
                fp = json.load(fh).get("library_fingerprint")
            if fp:
                return fp
    return None


def _run(cmd, cwd, env=None):
    """Run one step; its stdout; ConfigError naming the command and its last error line."""
    r = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True)
    if r.returncode:
        last = (r.stderr.strip().splitlines() or r.stdout.strip().splitlines() or ["no output"])[-1]
        shown = " ".join(c if len(c) < 60 else c[:57] + "..." for c in cmd)
        raise ConfigError(f"{shown} (in {cwd}) failed, exit {r.returncode}: {last}")
    return r.stdout.strip().splitlines()[-1] if r.stdout.strip() else ""
