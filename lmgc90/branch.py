"""A CD run branched at its checkpoint, to go on under another solver setting.

    python -m lmgc90.branch RUN_FOLDER NEW_FOLDER --set nlgs_tol=3e-4 [--set NAME=VALUE ...]
    python -m lmgc90.triaxial NEW_FOLDER          # resumes the branch

The new folder gets a copy of the run as its newest checkpoint left it (the
DATBOX, the checkpoint, the dump's parts up to the checkpoint's snapshots,
the log and LMGC90's reactions), with the named parameters changed in the
checkpoint, so that ``python -m lmgc90.triaxial NEW_FOLDER`` resumes it from
that step under the new setting while the original run goes on untouched.
This is how a convergence check is made on a sheared state: the same grains,
positions, velocities and warm-started forces, solved from one step on with a
tighter NLGS tolerance (or another relaxation), and the snapshots the two
branches take at the same eps_1 compared (docs/lmgc90.md).

Only the solver's and the program's bookkeeping parameters can change
(:data:`BRANCHABLE`); the physics (grains, friction, walls, sigma0, dt, the
shear rate) cannot, since the state belongs to it. Refused in one line:
a run folder without a checkpoint, an existing NEW_FOLDER, a parameter
outside :data:`BRANCHABLE`, a value of the wrong type.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import sys

#: parameters a branch may change: NLGS's setting, the snapshots' spacing and
#: window, the end of the shear and the run's own bookkeeping
BRANCHABLE = ("nlgs_tol", "nlgs_relax", "nlgs_check_every", "nlgs_max_checks", "nlgs_norm", "nlgs_scramble",
              "dump_strain", "average_steps", "final_strain", "max_steps", "checkpoint_seconds",
              "checkpoint_steps", "report_seconds")


class BranchError(ValueError):
    """A branch that cannot be made (one line)."""


def _checkpoint(folder, stem):
    """The newest complete checkpoint folder of the run (run.ckpt, else run.ckpt.prev)."""
    from lmgc90.triaxial import newest_checkpoint
    path = newest_checkpoint(os.path.join(folder, stem))
    if path is None:
        raise BranchError(f"{folder}: no checkpoint ({stem}.ckpt/scene.json) to branch from "
                          "(a finished run keeps none)")
    return path


def coerce(saved, name, text):
    """``text`` as the type of the checkpoint's value of ``name``."""
    if name not in BRANCHABLE:
        raise BranchError(f"--set {name}: a branch changes only {', '.join(BRANCHABLE)}")
    kind = type(saved.get(name, 0.0))
    try:
        return kind(float(text)) if kind in (int, float) else str(text)
    except ValueError:
        raise BranchError(f"--set {name}={text}: {name} takes a {kind.__name__}") from None


def branch(run, new, changes, out="run.h5"):
    """Copy the CD run folder ``run`` at its newest checkpoint into ``new``.

    Parameters
    ----------
    run : str
        A run folder of ``python -m lmgc90.triaxial`` (unfinished, with its checkpoint).
    new : str
        The branch's folder (must not exist).
    changes : dict
        name -> value text, each name in :data:`BRANCHABLE`.
    out : str
        The run's dump name in its folder.

    Returns
    -------
    dict
        The branch record written into the new folder's run.params.json
        (``from``, ``step``, ``eps_1``, ``snapshots``, ``changed``).

    Raises
    ------
    BranchError
        (one line) as the module docstring lists; nothing is left at ``new``.
    """
    run, new = os.path.abspath(run), os.path.abspath(new)
    stem = out[:-3] if out.endswith(".h5") else out
    if os.path.exists(new):
        raise BranchError(f"{new}: exists already (a branch goes into a new folder)")
    if not os.path.isdir(os.path.join(run, "DATBOX")):
        raise BranchError(f"{run}: not a CD run folder (no DATBOX)")
    ckpt = _checkpoint(run, stem)
    with open(os.path.join(ckpt, "scene.json")) as fh:
        scene = json.load(fh)
    changed = {name: coerce(scene["parameters"], name, text) for name, text in changes.items()}
    if not changed:
        raise BranchError("nothing to change: give --set NAME=VALUE")
    tmp = new + ".tmp"
    if os.path.exists(tmp):
        shutil.rmtree(tmp)
    try:
        os.makedirs(tmp)
        shutil.copytree(ckpt, os.path.join(tmp, stem + ".ckpt"))
        shutil.copytree(os.path.join(run, "DATBOX"), os.path.join(tmp, "DATBOX"))
        shutil.copytree(os.path.join(run, out + ".parts"), os.path.join(tmp, out + ".parts"))
        shutil.copy2(os.path.join(run, out), os.path.join(tmp, out))
        for name in (stem + ".log.csv", stem + ".params.json"):
            if os.path.exists(os.path.join(run, name)):
                shutil.copy2(os.path.join(run, name), os.path.join(tmp, name))
        reactions = os.path.join(run, stem + ".reactions")
        if os.path.isdir(reactions):
            keep = {f"{k:06d}.npz" for k in range(int(scene["n_snapshots"]))}
            os.makedirs(os.path.join(tmp, stem + ".reactions"))
            for name in sorted(keep & set(os.listdir(reactions))):
                shutil.copy2(os.path.join(reactions, name), os.path.join(tmp, stem + ".reactions", name))
        scene["parameters"].update(changed)
        with open(os.path.join(tmp, stem + ".ckpt", "scene.json"), "w") as fh:
            json.dump(scene, fh)
        record = {"from": run, "step": int(scene["program"]["steps"]), "eps_1": float(scene["program"]["eps_1"]),
                  "stage": scene["program"]["stage"], "snapshots": int(scene["n_snapshots"]), "changed": changed}
        params_path = os.path.join(tmp, stem + ".params.json")
        params = {}
        if os.path.exists(params_path):
            with open(params_path) as fh:
                params = json.load(fh)
        params.update(changed)
        params["branch"] = record
        with open(params_path, "w") as fh:
            json.dump(params, fh, indent=1, default=float)
        os.replace(tmp, new)
    except OSError as exc:
        shutil.rmtree(tmp, ignore_errors=True)
        raise BranchError(f"{run}: could not copy into {new} ({exc.__class__.__name__}: {exc})") from None
    return record


def main(argv=None):
    """``python -m lmgc90.branch RUN NEW --set NAME=VALUE ...``; exit 0, or 2 with one line."""
    ap = argparse.ArgumentParser(prog="python -m lmgc90.branch", description=__doc__.split("\n")[0])
    ap.add_argument("run")
    ap.add_argument("new")
    ap.add_argument("--set", action="append", default=[], metavar="NAME=VALUE")
    a = ap.parse_args(argv)
    changes = {}
    for item in a.set:
        name, eq, text = item.partition("=")
        if not eq:
            ap.error(f"--set {item}: not NAME=VALUE")
        changes[name.strip()] = text.strip()
    try:
        rec = branch(a.run, a.new, changes)
    except BranchError as exc:
        print(f"lmgc90.branch: refused: {exc}", file=sys.stderr)
        return 2
    print(f"lmgc90.branch: {a.new} holds {a.run} at step {rec['step']} ({rec['stage']}, eps_1 {rec['eps_1']:.4f}, "
          f"{rec['snapshots']} snapshots) with {rec['changed']}; run python -m lmgc90.triaxial {a.new} to go on")
    return 0


if __name__ == "__main__":
    sys.exit(main())
