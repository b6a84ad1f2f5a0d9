"""The CD study: the YADE study's starting states taken through Contact Dynamics.

    python -m lmgc90.study --from YADE_STUDY --out CD_STUDY [--seeds 1 2 3]
        [--samples polyhedra spheres] [--jobs 2] [--set NAME=VALUE ...] [--set-aside]
        [--archive DEST] [--dry-run] [--collect] [--slurm [--slurm-time T] ...] [--no-figures]
    make cd-study [CD_STUDY=runs/cd-small FROM=runs/small JOBS=2]

For each sample and seed, the YADE study's dump of that seed (found through
YADE_STUDY/manifest.json, which the YADE study writes when its runs end) is
the starting state of the CD run folder CD_STUDY/<sample>-seed<K>/:
``python -m lmgc90.triaxial CD_STUDY/<sample>-seed<K> --start yade --source
DUMP --set ...`` with the study's parameters (:data:`STUDY_SETTINGS` over the
scene's defaults, the YADE run's own shear rate, then ``--set``). Folders
already there are adopted: a finished run (complete dump and
``run.info.json``) is not run again, an unfinished one resumes from its
checkpoint (the same command), one that another process writes (its
``run.lock``: a run started by hand) is left alone, and one whose
``run.params.json`` holds other parameters is refused in one line naming
them (``--set-aside``: renamed ``.old-K`` and started afresh). The runs go
through :func:`yade_scripts.launch.pool.run_pool` on ``--jobs`` cores (the
launcher of the YADE runs: longest first by :func:`estimate`, every attempt
recorded, a crash resumed from its checkpoint, SIGTERM or Ctrl-C forwarded
so that each run checkpoints and exits 75); each finished run is analysed
on a free core (``postproc analyze``'s analysis into ``<run>/analysis``) and
CD_STUDY/manifest.json and CD_STUDY/report/ are written as the YADE study
writes them (:func:`yade_scripts.campaign.study.analyse_and_report`), so
``postproc report CD_STUDY`` reads a CD study as a YADE one.

``--slurm`` writes CD_STUDY/slurm.sh, a job array of one task per run to do
(``--task K``: that run, resumed on requeue), its time limit from
:func:`estimate`; ``--collect`` then analyses and reports what has finished,
running nothing. ``--archive DEST`` keeps each finished run's numbers (its
analysis's csv/json/txt, ``run.params.json``, ``run.info.json``, no dump)
in DEST/<sample>-seed<K>/ and takes a run from DEST when it is not complete
here (:func:`archive_runs`, :func:`from_archive`).

Exit codes as the YADE study's: 0 every sample has a usable run; 1 a sample
has none; 2 invalid options, a missing YADE study or seed, a folder of other
parameters; 4 another process writes the CD study (its ``study.lock``); 75
stopped (SIGTERM, Ctrl-C: run the same command again to resume).
"""
from __future__ import annotations

import argparse
import contextlib
import datetime
import functools
import io
import json
import math
import os
import shutil
import signal
import sys

from lmgc90 import triaxial
from postproc.errors import InputError
from postproc.provenance import ANALYSIS_VERSION, code_hash, is_today
from postproc.schema import DumpReader
from postproc.study.manifest import read_manifest
from yade_scripts.campaign.archive_store import _copy_run, _lock, _made_from, sha256_of
from yade_scripts.campaign.runfolders import analysis_folder, whole
from yade_scripts.campaign.study import analyse_after, analyse_and_report, report_lock, unusable_samples
from yade_scripts.launch.pool import Job, run_pool
from yade_scripts.launch.slurm import DEFAULT_REQUEUES, DEFAULT_SIGNAL_SECONDS, check_options
from yade_scripts.launch.task import scontrol, slurm_job
from yade_scripts.runs.runlock import RunBusy, RunLock, describe, run_holder
from yade_scripts.runs.runstate import (EXIT_BUSY, EXIT_TERM, complete, has_checkpoint, mark_requeued, state_of,
                                        task_requeues)
from yade_scripts.scene.parameters import ConfigError

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SAMPLES = ("polyhedra", "spheres")
#: the CD study's parameters over the scene's defaults (lmgc90.triaxial.PARAMETERS):
#: dt = 1e-3 s, the step of the 200-grain runs measured in docs/measurements.md
#: ("The CD triaxial scene's cost and its walls": isotropic at step 146)
STUDY_SETTINGS = {"dt": 1e-3}
#: parameters of how a run is watched, not of what it computes: a folder made
#: with other values of these is adopted (a resumed run keeps its own)
OPERATIONAL = ("report_seconds", "checkpoint_seconds", "checkpoint_steps", "lmgc90_build")
#: the cost model (:func:`estimate`), docs/measurements.md "The CD triaxial scene's cost
#: and its walls": 200 grains of PRESET=small's S1 at dt = 1e-3, 3-5 s a shear step
#: (median 3.1) and 2.4 s an isotropic one on one core of the loaded 2-core host; the
#: isotropic state at step 146
SECONDS_PER_STEP = 4.0
REFERENCE_GRAINS = 200
ISOTROPIC_STEPS = 150
#: a SLURM task's time limit: the estimate times this, at least an hour
SLURM_MARGIN = 1.5
SLURM_PLAN = "slurm-plan.json"
#: the archive's record of one CD run, in its folder
ARCHIVE_RECORD = "run.archived.json"


def say(message, err=False):
    """One line of the study, ``lmgc90.study: <message>``."""
    print(f"lmgc90.study: {message}", file=sys.stderr if err else sys.stdout, flush=True)


# ------------------------------------------------------------------ the plan
def yade_sources(yade_study, samples, seeds):
    """{(sample, seed): the YADE dump} of the YADE study ``yade_study``, read
    from its manifest.json (:func:`postproc.study.manifest.read_manifest`);
    ConfigError in one line when the study, a sample, a seed or its dump is
    missing, or its run is not usable ("ok" or "partial")."""
    path = os.path.join(yade_study, "manifest.json")
    if not os.path.isdir(yade_study):
        raise ConfigError(f"--from {yade_study}: no such YADE study (make study PRESET=small STUDY={yade_study} "
                          "makes it; the CD study does not run YADE)")
    if not os.path.exists(path):
        raise ConfigError(f"--from {yade_study}: no manifest.json, not a finished YADE study (make study writes it "
                          "when its runs end; the CD study does not run YADE)")
    try:
        runs = read_manifest(path)
    except InputError as exc:
        raise ConfigError(str(exc)) from None
    out = {}
    for s in samples:
        by_seed = {}
        for r in runs.get(s, []):
            label = r["label"].split()
            if len(label) == 2 and label[0] == "seed" and label[1].isdigit():
                by_seed[int(label[1])] = r
        for k in seeds:
            r = by_seed.get(k)
            if r is None:
                raise ConfigError(f"--from {yade_study}: its manifest has no {s} seed {k} "
                                  f"(it has {', '.join(map(str, sorted(by_seed))) or 'none'})")
            dump = r.get("dump")
            dump = dump and (dump if os.path.isabs(dump) else os.path.join(yade_study, dump))
            if r["status"] not in ("ok", "partial"):
                raise ConfigError(f"--from {yade_study}: {s} seed {k} is not usable ({r['status']})")
            if not dump or not os.path.exists(dump):
                raise ConfigError(f"--from {yade_study}: {s} seed {k}: its dump {dump} is not on this host")
            out[(s, k)] = os.path.abspath(dump)
    return out


def source_state(dump):
    """What the cost and the shear rate need of a YADE dump: its grains'
    number, mean size (m), isotropic box height (m) and ``rate_shear``
    (1/s, or None)."""
    with DumpReader(dump) as r:
        rate = r.parameters.get("rate_shear")
        for k in range(len(r)):
            snap = r.read(k)
            if snap.stage == "isotropic":
                break
        else:
            raise ConfigError(f"{dump}: no isotropic snapshot to start a CD run from")
    return {"n": len(snap.body_ids), "d_mean": float(snap.sizes.mean()),
            "height": float(snap.box_hi[2] - snap.box_lo[2]),
            "rate_shear": float(rate) if isinstance(rate, (int, float)) and rate > 0 else None}


def check_sets(items):
    """{name: value} of ``--set NAME=VALUE`` items, typed as the scene's
    PARAMETERS; ConfigError in one line for an unknown name or a bad value."""
    out = {}
    for item in items or []:
        name, eq, text = item.partition("=")
        if not eq or name not in triaxial.PARAMETERS or name in ("start", "source"):
            raise ConfigError(f"--set {item}: not NAME=VALUE with NAME a parameter of lmgc90.triaxial "
                              "(start and source are the study's)")
        kind = type(triaxial.PARAMETERS[name])
        try:
            out[name] = kind(float(text)) if kind in (int, float) else text
        except ValueError:
            raise ConfigError(f"--set {item}: {name} takes a {kind.__name__}") from None
    return out


def run_parameters(source, sets, state):
    """The parameters of the CD run from the YADE dump ``source``: the
    scene's defaults, :data:`STUDY_SETTINGS`, the YADE run's shear rate
    (``shear_rate`` = its ``rate_shear``, so that both methods shear at one
    rate), then ``sets``; checked by the scene's own parser (ConfigError in
    one line)."""
    p = {**STUDY_SETTINGS, **({"shear_rate": state["rate_shear"]} if state["rate_shear"] else {}), **sets}
    argv = ["x", "--start", "yade", "--source", source]
    for name, value in p.items():
        argv += ["--set", f"{name}={value!r}" if isinstance(value, float) else f"{name}={value}"]
    err = io.StringIO()
    try:
        with contextlib.redirect_stderr(err):
            _, params = triaxial.parse(argv)
    except SystemExit:
        raise ConfigError(err.getvalue().strip().splitlines()[-1].split("error: ", 1)[-1]) from None
    return params


def scene_command(folder, params):
    """The command of the CD run in ``folder`` (every attempt's: the scene
    resumes from its checkpoint by itself)."""
    cmd = [sys.executable, "-m", "lmgc90.triaxial", folder, "--start", "yade", "--source", params["source"]]
    for name in triaxial.PARAMETERS:
        if name not in ("start", "source") and params[name] != triaxial.PARAMETERS[name]:
            v = params[name]
            cmd += ["--set", f"{name}={v!r}" if isinstance(v, float) else f"{name}={v}"]
    return cmd


def differing(stored, requested):
    """The parameters (names) of a run folder's ``run.params.json``
    (``stored``) that differ from ``requested``, with both values: [(name,
    stored, requested)]. Compared: the scene's PARAMETERS but
    :data:`OPERATIONAL`; the source by its real path; numbers to 1e-12
    relative; a name the folder does not record counts as the scene's
    default."""
    out = []
    for name, default in triaxial.PARAMETERS.items():
        if name in OPERATIONAL:
            continue
        a, b = stored.get(name, default), requested[name]
        if name == "source":
            same = os.path.realpath(a) == os.path.realpath(b) if a and b else a == b
        elif isinstance(default, (int, float)) and isinstance(a, (int, float)):
            same = math.isclose(float(a), float(b), rel_tol=1e-12, abs_tol=0.0)
        else:
            same = a == b
        if not same:
            out.append((name, a, b))
    return out


def estimate(n_grains, dt, final_strain, shear_rate, seconds_per_step=SECONDS_PER_STEP,
             reference_grains=REFERENCE_GRAINS, isotropic_steps=ISOTROPIC_STEPS):
    """The cost of one CD run on one core.

    Steps: ``isotropic_steps`` to the isotropic state, then the shear to
    ``final_strain`` at the rate ``shear_rate`` (eps_1 = rate x time: the
    top wall moves at rate x H0), final_strain / (rate x dt) steps. Each
    step costs ``seconds_per_step`` at ``reference_grains`` grains, taken in
    proportion to the grains (the NLGS sweeps every contact at every
    iteration).

    Parameters
    ----------
    n_grains : int
    dt : float
        s, the time step.
    final_strain : float
        eps_1 at the end.
    shear_rate : float
        1/s.
    seconds_per_step, reference_grains, isotropic_steps
        The model's measured inputs (module constants).

    Returns
    -------
    dict
        "steps", "shear_steps", "seconds".

    Examples
    --------
    The 200-grain S1 at the YADE run's rate 0.2894/s, dt = 1e-3 s, to eps_1 = 0.3:

    >>> e = estimate(200, 1e-3, 0.3, 0.2894)
    >>> round(e["shear_steps"]), round(e["seconds"] / 3600, 2)
    (1037, 1.32)
    """
    shear = final_strain / (shear_rate * dt)
    steps = isotropic_steps + shear
    return {"steps": steps, "shear_steps": shear,
            "seconds": steps * seconds_per_step * n_grains / reference_grains}


def shear_rate_of(params, state):
    """The shear's rate (1/s) the scene takes from ``params``: shear_rate,
    wall_speed over the YADE box's height, or the inertial number."""
    if params["wall_speed"] > 0:
        return params["wall_speed"] / state["height"]
    if params["shear_rate"] > 0:
        return params["shear_rate"]
    return params["inertial_number"] / (state["d_mean"] * math.sqrt(params["density"] / params["sigma0"]))


def plan(yade_study, out, samples, seeds, sets, set_aside=False):
    """What the study would do with each run, done nothing of: a list of
    dicts, one a run (in the order sample, seed): "sample", "seed", "label",
    "folder", "dump", "source", "params", "command", "cost" (s), and
    "action": "finished" (adopted, not run again), "resume" (from its
    checkpoint), "run" (afresh), "busy" (another process writes it: left
    alone; "holder" says who), "set-aside" (other parameters, renamed
    .old-K before it runs afresh: with ``set_aside``). ConfigError in one
    line for the first folder of other parameters (without ``set_aside``)
    and for whatever :func:`yade_sources` refuses."""
    sources = yade_sources(yade_study, samples, seeds)
    sets = check_sets(sets)
    todo = []
    for (s, k), src in sources.items():
        state = source_state(src)
        params = run_parameters(src, sets, state)
        folder = os.path.join(os.path.abspath(out), f"{s}-seed{k}")
        dump = os.path.join(folder, params["out"])
        e = {"sample": s, "seed": k, "label": f"seed {k}", "folder": folder, "dump": dump, "source": src,
             "params": params, "command": scene_command(folder, params),
             "cost": estimate(state["n"], params["dt"], params["final_strain"], shear_rate_of(params, state))}
        stored_path = os.path.join(folder, os.path.splitext(params["out"])[0] + ".params.json")
        holder = run_holder(dump) if os.path.isdir(folder) else None
        diff = []
        if os.path.exists(stored_path):
            with open(stored_path) as fh:
                diff = differing(json.load(fh), params)
        if diff and (holder is not None or not set_aside):
            names = ", ".join(f"{n} {a!r} there, {b!r} asked" for n, a, b in diff)
            how = (f"{describe(holder)} writes it: nothing run" if holder is not None else
                   "nothing run: give another --out, or --set-aside to keep it as .old-K and start afresh")
            raise ConfigError(f"{folder}: a CD run of other parameters ({names}); {how}")
        if holder is not None:
            e.update(action="busy", holder=describe(holder))
        elif diff:
            e.update(action="set-aside", differing=[n for n, _, _ in diff])
        elif os.path.exists(os.path.join(folder, "run.info.json")) and complete(dump):
            e.update(action="finished")
        elif has_checkpoint(dump):
            e.update(action="resume")
        else:
            e.update(action="run")
        todo.append(e)
    return todo


WORDS = {"finished": "finished, adopted (not run again)", "resume": "unfinished, resumes from its checkpoint",
         "run": "to run", "busy": "written by another process, left alone",
         "set-aside": "other parameters: kept as .old-K, runs afresh"}


def describe_plan(entries):
    """One line per run of :func:`plan`, then the counts."""
    lines = []
    for e in entries:
        extra = f" ({e['holder']})" if e["action"] == "busy" else \
            f" ({', '.join(e['differing'])})" if e["action"] == "set-aside" else ""
        cost = f"; about {e['cost']['steps']:.0f} steps, {e['cost']['seconds'] / 3600:.2g} h on one core" \
            if e["action"] in ("run", "resume", "set-aside") else ""
        lines.append(f"[{e['sample']}] {e['label']}: {os.path.basename(e['folder'])}: {WORDS[e['action']]}{extra}"
                     f"{cost}; from {e['source']}")
    n = {a: sum(1 for e in entries if e["action"] == a) for a in WORDS}
    lines.append(f"{n['finished']} finished, {n['resume']} to resume, {n['run'] + n['set-aside']} to run, "
                 f"{n['busy']} written by another process")
    return lines


def set_aside_folder(folder):
    """Rename ``folder`` FOLDER.old-K (the first K free); returns the new name."""
    k = 1
    while os.path.exists(f"{folder}.old-{k}"):
        k += 1
    os.rename(folder, f"{folder}.old-{k}")
    return f"{folder}.old-{k}"


def job_of(e):
    """The pool's :class:`yade_scripts.launch.pool.Job` of a planned run."""
    return Job(e["folder"], None, f"{e['sample']}-seed{e['seed']}", e["dump"], cost=e["cost"]["seconds"],
               tag=e["sample"], threads=1, log=os.path.join(e["folder"], "lmgc90.log"), command=e["command"],
               prefix="lmgc90.triaxial: ")


def scene_environment():
    """The scene runs in its folder: this checkout on its PYTHONPATH."""
    old = os.environ.get("PYTHONPATH")
    os.environ["PYTHONPATH"] = ROOT + (os.pathsep + old if old else "")


# ------------------------------------------------------------------ the archive
def archive_runs(entries, dest, echo=print):
    """Keep in ``dest`` the numbers of every finished run of ``entries``
    whose analysis was made from its dump by today's code: DEST/<run
    folder>/ with run.params.json, run.info.json, run.attempts.json, the
    analysis folder's csv/json/txt
    (:func:`yade_scripts.campaign.archive_store._copy_run`, the YADE
    archive's copy) and :data:`ARCHIVE_RECORD` (the dump's name, size,
    snapshots and SHA-256, the analysis version and code, every file's
    SHA-256), written last. A run archived already from the same dump is
    left; one archived from another dump is never replaced (named). One
    process adds to ``dest`` at a time (its archive.lock). Returns
    (saved, skipped) lines."""
    os.makedirs(dest, exist_ok=True)
    lock = _lock(dest, echo)
    saved, skipped = [], []
    try:
        for e in entries:
            name = os.path.basename(e["folder"])
            dump, into = e["dump"], os.path.join(dest, name)
            if not (complete(dump) and os.path.exists(os.path.join(e["folder"], "run.info.json"))):
                continue
            why = whole(dump) or _made_from(analysis_folder(dump), dump)
            if why:
                skipped.append(f"{name}: {why}")
                continue
            sha = sha256_of(dump)
            old = _read(os.path.join(into, ARCHIVE_RECORD))
            if old and old.get("dump", {}).get("sha256") == sha:
                continue
            if old:
                skipped.append(f"{name}: archived from another dump (SHA-256 {old['dump']['sha256'][:12]}), "
                               "not replaced")
                continue
            os.makedirs(into, exist_ok=True)
            files = _copy_run(dump, e["folder"], into, {"": analysis_folder(dump)})
            params = os.path.join(e["folder"], "run.params.json")
            shutil.copyfile(params, os.path.join(into, "run.params.json"))
            files["run.params.json"] = sha256_of(params)
            with DumpReader(dump) as r:
                n = len(r)
            record = {"sample": e["sample"], "seed": e["seed"], "analysis": "analysis", "info": "run.info.json",
                      "dump": {"name": os.path.basename(dump), "bytes": os.path.getsize(dump), "snapshots": n,
                               "sha256": sha},
                      "version": ANALYSIS_VERSION, "code": code_hash(), "files": files,
                      "saved": datetime.datetime.now().isoformat(timespec="seconds")}
            with open(os.path.join(into, ARCHIVE_RECORD + ".tmp"), "w") as fh:
                json.dump(record, fh, indent=1)
            os.replace(os.path.join(into, ARCHIVE_RECORD + ".tmp"), os.path.join(into, ARCHIVE_RECORD))
            saved.append(name)
            echo(f"[archive] {name}: kept ({len(files)} files)")
    finally:
        lock.release()
    return saved, skipped


def _read(path):
    try:
        with open(path) as fh:
            return json.load(fh)
    except (OSError, ValueError):
        return None


def from_archive(e, dest):
    """The archived record of the planned run ``e`` in ``dest`` when it can
    be used: the same parameters (:func:`differing` on its run.params.json),
    today's analysis version and every kept file as recorded; else None."""
    into = os.path.join(dest, os.path.basename(e["folder"]))
    rec, stored = _read(os.path.join(into, ARCHIVE_RECORD)), _read(os.path.join(into, "run.params.json"))
    if not rec or not stored or differing(stored, e["params"]) or not is_today(rec):
        return None
    for rel, sha in rec.get("files", {}).items():
        path = os.path.join(into, rel)
        if not os.path.exists(path) or sha256_of(path) != sha:
            return None
    return rec


def archived_entry(out, e, dest, rec):
    """The manifest entry of a run taken from the archive (paths relative to ``out``)."""
    into = os.path.join(dest, os.path.basename(e["folder"]))
    return {"label": e["label"], "dump": os.path.relpath(e["dump"], out),
            "analysis": os.path.relpath(os.path.join(into, rec["analysis"]), out),
            "info": os.path.relpath(os.path.join(into, rec["info"]), out), "status": "ok", "state": "ok",
            "archived": {"archive": os.path.relpath(dest, out), "dump_sha256": rec["dump"]["sha256"],
                         "saved": rec.get("saved")},
            "note": f"from the archive {dest}: analysed on {rec.get('saved', '?')}, its dump "
                    f"({rec['dump']['snapshots']} snapshots) not on this host"}


# ------------------------------------------------------------------ the study
def run_study(out, entries, jobs, figures=True, archive=None, collect=False):
    """Run (unless ``collect``) the planned runs that are not finished nor
    written by another process on ``jobs`` cores, analyse every finished
    one, write OUT/manifest.json and OUT/report/; returns the exit code."""
    held = {}
    if archive:
        for e in entries:
            if not complete(e["dump"]):
                rec = from_archive(e, archive)
                if rec:
                    held[e["dump"]] = archived_entry(out, e, archive, rec)
                    say(f"[{e['sample']}] {e['label']}: taken from the archive {archive}, not run here")
    for e in entries:
        if e["action"] == "set-aside" and not collect and e["dump"] not in held:
            kept = set_aside_folder(e["folder"])
            say(f"[{e['sample']}] {e['label']}: parameters changed ({', '.join(e['differing'])}): previous run "
                f"kept as {kept}")
        if e["action"] == "busy":
            say(f"[{e['sample']}] {e['label']}: {e['holder']} writes {e['folder']}: left alone")
    to_run = [e for e in entries if e["action"] in ("run", "resume", "set-aside") and e["dump"] not in held]
    status = {}
    if to_run and not collect:
        for e in to_run:
            os.makedirs(e["folder"], exist_ok=True)
        scene_environment()
        pool = [job_of(e) for e in to_run]
        status = run_pool(pool, jobs, record=os.path.join(out, "schedule.json"), echo=lambda m: print(m, flush=True),
                          after=functools.partial(analyse_after, counts=(), figures=figures))
    runs, others = {}, {}
    for e in entries:
        d = f"{e['sample']}-seed{e['seed']}"
        if e["dump"] in held:
            others.setdefault(e["sample"], []).append(held[e["dump"]])
        elif e["action"] == "finished" or status.get(d) == 0 or complete(e["dump"]):
            runs.setdefault(e["sample"], []).append((e["label"], e["dump"], 0))
        elif d in status:
            runs.setdefault(e["sample"], []).append((e["label"], e["dump"], status[d]))
        else:
            st = state_of(e["dump"])
            others.setdefault(e["sample"], []).append({"label": e["label"], "dump": os.path.relpath(e["dump"], out),
                                                       "status": st.detail, "state": st.state})
    stopped = [f"{s} {label}" for s in runs for label, _, st in runs[s] if st == "stopped"]
    if stopped:
        say(f"stopped (SIGTERM or Ctrl-C): {', '.join(stopped)} not finished, each run kept its checkpoint; run "
            "the same command again to resume", err=True)
        return EXIT_TERM
    lock = report_lock(out, wait=True)
    try:
        failed = analyse_and_report(out, runs, unfinished=others, counts=(), figures=figures)
        missing = unusable_samples(out)
    finally:
        lock.release()
    if archive:
        _, skipped = archive_runs([e for e in entries if e["dump"] not in held], archive,
                                  echo=lambda m: print(m, flush=True))
        for line in skipped:
            say(f"archive: {line} (not archived)")
    if failed:
        say(f"failed: {', '.join(failed)} (the report lists them)", err=True)
    if missing:
        say(f"no usable run of {', '.join(missing)} yet: {out}/manifest.json says what each run is", err=True)
        return 1
    say(f"report in {out}/report/report.md (and report.html)", err=True)
    return 0


# ------------------------------------------------------------------ SLURM
def slurm_time(seconds, margin=SLURM_MARGIN):
    """A SLURM time limit for a run of ``seconds``.

    Parameters
    ----------
    seconds : float
        s, the run's :func:`estimate`.
    margin : float
        The limit over the estimate (:data:`SLURM_MARGIN`).

    Returns
    -------
    str
        ``D-HH:MM:SS``: ``seconds`` x ``margin`` rounded up to the hour, at
        least one hour.

    Examples
    --------
    >>> slurm_time(4770), slurm_time(3 * 86400)
    ('0-02:00:00', '4-12:00:00')
    """
    hours = max(1, math.ceil(seconds * margin / 3600))
    return f"{hours // 24}-{hours % 24:02d}:00:00"


def write_slurm(out, entries, time=None, partition=None, requeues=DEFAULT_REQUEUES,
                signal_seconds=DEFAULT_SIGNAL_SECONDS, figures=True):
    """Write OUT/slurm.sh, a job array of one task per run to do (not
    finished, not written by another process), and its plan
    OUT/:data:`SLURM_PLAN` (task K -> the run's folder, dump and command).
    The time limit is ``time`` or :func:`slurm_time` of the longest run's
    :func:`estimate`; ``figures=False``: the tasks' analyses without their
    figures. Returns the script's path, or None when there is no run to
    do. ConfigError (one line) for bad options or a path with spaces."""
    tasks = [e for e in entries if e["action"] in ("run", "resume", "set-aside")]
    if not tasks:
        return None
    out = os.path.abspath(out)
    longest = max(e["cost"]["seconds"] for e in tasks)
    time = time or slurm_time(longest)
    check_options(1, time, partition, requeues, signal_seconds)
    if any(" " in p for p in (out, ROOT, sys.executable)):
        raise ConfigError(f"{out}: a CD study for SLURM needs paths without spaces (#SBATCH --output)")
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, SLURM_PLAN), "w") as fh:
        json.dump({"tasks": [{k: e[k] for k in ("sample", "seed", "label", "folder", "dump", "source", "command",
                                                "cost", "action")} for e in tasks]}, fh, indent=1)
    part = f"#SBATCH --partition={partition}\n" if partition else ""
    worst = max(tasks, key=lambda e: e["cost"]["seconds"])
    text = f"""#!/bin/bash
#SBATCH --job-name={os.path.basename(out)}
#SBATCH --array=1-{len(tasks)}
#SBATCH --cpus-per-task=1
#SBATCH --time={time}
#SBATCH --signal=B:USR1@{int(signal_seconds)}
#SBATCH --requeue
#SBATCH --open-mode=append
#SBATCH --output={out}/slurm-%A_%a.out
{part}# Written by python -m lmgc90.study --slurm: one array task per CD run of {SLURM_PLAN}
# ({len(tasks)} runs: {', '.join(os.path.basename(e['folder']) for e in tasks)}). Submit from anywhere:
#   sbatch {out}/slurm.sh          (some runs only: sbatch --array=2 ...)
# By hand, one task: SLURM_ARRAY_TASK_ID=1 bash slurm.sh
# Task K runs its CD run in its folder, resuming from its checkpoint; SIGUSR1
# {int(signal_seconds)} s before the time limit: the scene writes its checkpoint and the task
# requeues itself (at most {requeues} times). Then: python -m lmgc90.study ... --collect
#
# Cost model (lmgc90/study.py estimate): (isotropic + shear steps) x s a step at
# {REFERENCE_GRAINS} grains ({SECONDS_PER_STEP:g} s) x grains / {REFERENCE_GRAINS}; the longest run,
#   {os.path.basename(worst['folder'])}: ~{worst['cost']['steps']:.0f} steps, ~{worst['cost']['seconds'] / 3600:.2g} h on one core
#   (time limit: {SLURM_MARGIN:g} x that, rounded up to the hour, unless given)
for f in "{ROOT}/lmgc90/study.py" "{out}/{SLURM_PLAN}" "{sys.executable}"; do
    if [[ ! -e "$f" ]]; then
        echo "slurm.sh: $f is missing on $(hostname) (write slurm.sh again: python -m lmgc90.study ... --slurm)" >&2
        exit 2
    fi
done
export PYTHONPATH="{ROOT}" OMP_NUM_THREADS=1
cd "{ROOT}"
exec "{sys.executable}" -m lmgc90.study --task "${{SLURM_ARRAY_TASK_ID:?not an array task}}" --out "{out}" --requeues {int(requeues)}{"" if figures else " --no-figures"}
"""
    path = os.path.join(out, "slurm.sh")
    with open(path, "w") as fh:
        fh.write(text)
    mode = os.stat(path).st_mode
    os.chmod(path, mode | (mode & 0o444) >> 2)
    return path


def run_task(out, k, requeues=DEFAULT_REQUEUES, figures=True):
    """``--task K``: task K of OUT/slurm.sh, its run through the pool (one
    core), analysed when it finishes; on SIGUSR1 (the time limit's warning)
    the scene checkpoints and the task requeues its job while it has
    requeued itself fewer than ``requeues`` times; on SIGTERM it stops
    (resumable). ``figures=False``: its analysis without figures. Exit 0 done or requeued, 2 no such task, 3 failed, 4
    another process writes the run, 75 stopped, not requeued."""
    try:
        with open(os.path.join(out, SLURM_PLAN)) as fh:
            tasks = json.load(fh)["tasks"]
        if k < 1:
            raise IndexError
        e = tasks[k - 1]
    except (OSError, ValueError, KeyError, IndexError):
        say(f"{out}: no task {k} in {SLURM_PLAN}", err=True)
        return 2
    job = job_of(e)
    os.makedirs(e["folder"], exist_ok=True)
    scene_environment()
    flag = []
    signal.signal(signal.SIGUSR1, lambda *_: flag.append("usr1"))
    signal.signal(signal.SIGTERM, lambda *_: flag.append("term"))
    slurm, _ = slurm_job()
    try:
        status = run_pool([job], 1, echo=lambda m: print(m, flush=True), stopping=lambda: bool(flag),
                          note={"slurm_job": slurm} if slurm else None,
                          after=functools.partial(analyse_after, counts=(), figures=figures))
    except RunBusy as exc:
        say(f"refused: {exc}", err=True)
        return EXIT_BUSY
    st = status.get(job.description)
    if st == 0:
        say(f"FINAL done: {e['folder']}")
        return 0
    if st == "stopped" and "usr1" in flag and slurm:
        used = task_requeues(e["dump"])
        if used < requeues:
            why = scontrol("requeue", slurm)
            if why is None:
                mark_requeued(e["dump"], f"requeue {used + 1} of at most {requeues}")
                say(f"FINAL requeued ({used + 1} of at most {requeues}): resumes from its checkpoint")
                return 0
            say(f"FINAL stopped, resumable: the requeue failed ({why}): sbatch --array={k} {out}/slurm.sh", err=True)
            return EXIT_TERM
    if st == "stopped":
        say(f"FINAL stopped, resumable: sbatch --array={k} {out}/slurm.sh", err=True)
        return EXIT_TERM
    say(f"FINAL failed ({st}): see {job.log}", err=True)
    return 3


# ------------------------------------------------------------------ the command line
def main(argv=None):
    """``python -m lmgc90.study`` (the module docstring); returns the exit code."""
    ap = argparse.ArgumentParser(prog="python -m lmgc90.study", description=__doc__.splitlines()[0])
    ap.add_argument("--from", dest="yade", metavar="YADE_STUDY", help="the YADE study (its manifest.json)")
    ap.add_argument("--out", required=True, metavar="CD_STUDY")
    ap.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    ap.add_argument("--samples", nargs="+", choices=SAMPLES, default=list(SAMPLES))
    ap.add_argument("--jobs", type=int, default=2, help="cores: runs at once (one core each)")
    ap.add_argument("--set", action="append", metavar="NAME=VALUE", help="a parameter of lmgc90.triaxial")
    ap.add_argument("--set-aside", action="store_true",
                    help="rename a run folder of other parameters FOLDER.old-K and start it afresh")
    ap.add_argument("--archive", metavar="DEST", help="keep the finished runs' numbers here, take runs from it")
    ap.add_argument("--dry-run", action="store_true", help="say what would run, be adopted or left; do nothing")
    ap.add_argument("--collect", action="store_true", help="analyse and report what has finished; run nothing")
    ap.add_argument("--slurm", action="store_true", help="write CD_STUDY/slurm.sh (a job array), run nothing")
    ap.add_argument("--slurm-time", help="a task's time limit (default: from the cost estimate)")
    ap.add_argument("--slurm-partition")
    ap.add_argument("--requeues", type=int, default=DEFAULT_REQUEUES, help="requeues of a SLURM task at most")
    ap.add_argument("--task", type=int, help=argparse.SUPPRESS)
    ap.add_argument("--no-figures", action="store_true", help="numbers only")
    args = ap.parse_args(argv)
    out = os.path.abspath(args.out)
    if args.task is not None:
        return run_task(out, args.task, args.requeues, figures=not args.no_figures)
    try:
        if not args.yade:
            raise ConfigError("--from YADE_STUDY is required")
        if args.jobs < 1 or min(args.seeds) < 1:
            raise ConfigError(f"--jobs and the seeds must be >= 1, got {args.jobs} and {args.seeds}")
        entries = plan(args.yade, out, args.samples, sorted(set(args.seeds)), args.set, args.set_aside)
    except ConfigError as exc:
        say(f"error: {exc}", err=True)
        return 2
    if args.dry_run:
        for line in describe_plan(entries):
            say(line)
        say(f"dry run of {args.out}: nothing run or written")
        return 0
    if args.slurm:
        try:
            path = write_slurm(out, entries, args.slurm_time, args.slurm_partition, args.requeues,
                               figures=not args.no_figures)
        except ConfigError as exc:
            say(f"error: {exc}", err=True)
            return 2
        for line in describe_plan(entries):
            say(line)
        say(f"wrote {path}: sbatch {path}" if path else "nothing to run: every run is finished or written elsewhere")
        return 0
    try:
        os.makedirs(out, exist_ok=True)
        lock = RunLock(os.path.join(out, "study.lock"), "lmgc90.study").acquire()
    except RunBusy as exc:
        say(f"error: {exc}", err=True)
        return EXIT_BUSY
    try:
        for line in describe_plan(entries):
            say(line)
        return run_study(out, entries, args.jobs, figures=not args.no_figures, archive=args.archive,
                         collect=args.collect)
    except RunBusy as exc:          # a run taken by another process between the plan and the pool
        say(f"error: {exc}", err=True)
        return EXIT_BUSY
    except ConfigError as exc:
        say(f"error: {exc}", err=True)
        return 2
    finally:
        lock.release()


if __name__ == "__main__":
    sys.exit(main())
