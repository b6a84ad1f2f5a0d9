"""The CD study driver (lmgc90/study.py) on tiny CD runs: 24 spheres, a few
dozen isotropic steps and 0.4 % of shear each.

The YADE study it starts from is made by the fixture in the YADE study's
layout (``<sample>-ensemble/<sample>-seedK.h5`` and the manifest.json that
postproc.study.manifest reads), its dumps hand-built: one isotropic snapshot
of 24 spheres on a 2 x 3 x 4 lattice in a walled box (tests/builders.py), their
diameters shrunk by up to 4 % at random by the seed, and the YADE run's
``rate_shear`` among the parameters. A real tiny YADE study takes minutes
(tests/test_study_smoke.py); the CD scene needs of a YADE dump only its first
isotropic snapshot (lmgc90/cdstart.py), which these are.

The module's study: seed 2 started by hand (the scene's own command) and
stopped by SIGTERM after its first checkpoint, then the driver on 2 jobs
runs seed 1 afresh and resumes seed 2. Each later test reads that study or
calls the driver again on it.
"""
import json
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest


ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
from lmgc90mark import needs_lmgc90

RATE = 2.0       # 1/s, the fixture's YADE rate_shear
TINY = ["--set", "dt=2e-4", "--set", "iso_window=20", "--set", "iso_min_steps=20", "--set", "iso_volume_tolerance=1e-3",
        "--set", "iso_tolerance=0.1", "--set", "final_strain=0.004", "--set", "dump_strain=0.002",
        "--set", "average_steps=5", "--set", "report_seconds=1000", "--set", "max_steps=2000"]


def make_yade_study(folder, seeds, sample="spheres"):
    """A YADE study's layout and manifest, its dumps hand-built (module docstring)."""
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from builders import lattice_snapshot, snapshot_dicts
    from postproc.schema import DumpWriter

    os.makedirs(os.path.join(folder, f"{sample}-ensemble"), exist_ok=True)
    entries = []
    for k in seeds:
        snap, _, _ = lattice_snapshot(nx=2, ny=3, nz=4, r=0.005)
        bodies, contacts = snapshot_dicts(snap)
        bodies["size"] = bodies["size"] * (1 - 0.04 * np.random.default_rng(k).random(len(bodies["size"])))
        bodies["volume"] = np.pi / 6 * bodies["size"] ** 3
        rel = f"{sample}-ensemble/{sample}-seed{k}.h5"
        w = DumpWriter(os.path.join(folder, rel), sample, {"rate_shear": RATE, "final_strain": 0.3, "seed": k})
        w.write_snapshot(step=0, time=0.0, stage="isotropic", box_lo=snap.box_lo, box_hi=snap.box_hi,
                         wall_ids=snap.wall_ids, wall_forces=snap.wall_forces, bodies=bodies, contacts=contacts)
        w.close()
        entries.append({"label": f"seed {k}", "dump": rel, "analysis": f"{sample}-ensemble/analysis-{sample}-seed{k}",
                        "status": "ok", "state": "ok"})
    with open(os.path.join(folder, "manifest.json"), "w") as fh:
        json.dump({sample: entries}, fh)
    return str(folder)


def study(*args):
    """``python -m lmgc90.study`` in a fresh Python: (exit code, stdout, stderr)."""
    res = subprocess.run([sys.executable, "-m", "lmgc90.study", *map(str, args)], cwd=ROOT, capture_output=True,
                         text=True, timeout=600)
    return res.returncode, res.stdout, res.stderr


def log_steps(folder):
    with open(os.path.join(folder, "run.log.csv")) as fh:
        return [int(line.split(",", 1)[0]) for line in fh.readlines()[1:]]


@pytest.fixture(scope="module")
def yade_study(tmp_path_factory):
    return make_yade_study(tmp_path_factory.mktemp("yade") / "small", [1, 2, 3])


@pytest.fixture(scope="module")
def cd_study(tmp_path_factory, yade_study):
    """(CD study folder, exit code, stdout, stderr, the interrupted run's steps before its resume)."""
    from lmgc90.study import plan

    out = tmp_path_factory.mktemp("cd") / "cd-small"
    # seed 2 by hand, as the lead starts runs: the study's own command, stopped after a checkpoint
    e = [x for x in plan(yade_study, str(out), ["spheres"], [2], TINY[1::2]) if x["seed"] == 2][0]
    os.makedirs(e["folder"])
    cmd = e["command"] + ["--set", "checkpoint_steps=10"]
    proc = subprocess.Popen(cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    ckpt = os.path.join(e["folder"], "run.ckpt", "scene.json")
    t0 = time.time()
    while not os.path.exists(ckpt) and proc.poll() is None and time.time() - t0 < 300:
        time.sleep(0.05)
    proc.send_signal(signal.SIGTERM)
    text = proc.communicate(timeout=300)[0]
    assert proc.returncode == 75, text
    before = log_steps(e["folder"])
    rc, so, se = study("--from", yade_study, "--out", out, "--seeds", 1, 2, "--samples", "spheres", "--jobs", 2,
                       "--no-figures", *TINY)
    return out, rc, so, se, before


@needs_lmgc90
def test_two_seeds_on_two_jobs_make_a_manifest_the_report_reads(cd_study, yade_study):
    from postproc.study.manifest import read_manifest
    from postproc.study.report import discover, usable_runs

    out, rc, so, se, _ = cd_study
    assert rc == 0, so + se
    assert read_manifest(str(out / "manifest.json")) == json.load(open(out / "manifest.json"))
    runs = discover(str(out))
    assert list(runs) == ["spheres"] and [r["label"] for r in usable_runs(runs, "spheres")] == ["seed 1", "seed 2"]
    for r in runs["spheres"]:
        assert r["status"] == "ok" and r["dump"] == str(out / f"spheres-{r['label'].replace(' ', '')}" / "run.h5")
        assert os.path.exists(os.path.join(r["analysis"], "summary.csv")) and os.path.exists(r["info"])
    assert (out / "report" / "report.md").exists()
    # both runs at once on the two jobs
    attempts = [a for a in json.load(open(out / "schedule.json"))["attempts"] if a.get("kind") != "after"]
    assert sorted(a["job"] for a in attempts) == ["spheres-seed1", "spheres-seed2"]
    assert max(a["start"] for a in attempts) < min(a["end"] for a in attempts)
    # each from its YADE dump, at the YADE run's shear rate and the study's dt
    for k in (1, 2):
        p = json.load(open(out / f"spheres-seed{k}" / "run.params.json"))
        assert p["source"] == os.path.join(yade_study, "spheres-ensemble", f"spheres-seed{k}.h5")
        assert p["shear_rate"] == RATE and p["dt"] == 2e-4 and p["start"] == "yade"


@needs_lmgc90
def test_the_run_started_by_hand_is_resumed_with_no_step_lost_or_repeated(cd_study):
    out, rc, so, se, before = cd_study
    assert rc == 0, so + se
    assert "[spheres] seed 2: spheres-seed2: unfinished, resumes from its checkpoint" in so
    assert "[spheres] seed 1: spheres-seed1: to run" in so
    log = open(out / "spheres-seed2" / "lmgc90.log").read()
    assert "resumed from run.ckpt" in log
    steps = log_steps(out / "spheres-seed2")
    assert steps == list(range(1, len(steps) + 1)) and len(steps) > len(before) > 0


@needs_lmgc90
def test_a_second_call_runs_nothing_again(cd_study, yade_study):
    out = cd_study[0]
    watched = [out / f"spheres-seed{k}" / name for k in (1, 2) for name in ("run.h5", "run.attempts.json",
                                                                             "lmgc90.log")]
    before = {p: os.stat(p).st_mtime_ns for p in watched}
    rc, so, se = study("--from", yade_study, "--out", out, "--seeds", 1, 2, "--samples", "spheres", "--jobs", 2,
                       "--no-figures", *TINY)
    assert rc == 0, so + se
    assert {p: os.stat(p).st_mtime_ns for p in watched} == before
    assert so.count("finished, adopted (not run again)") == 2 and "started on" not in so


@needs_lmgc90
def test_the_dry_run_lists_the_plan_and_writes_nothing(cd_study, yade_study):
    out = cd_study[0]
    listing = sorted(os.listdir(out))
    rc, so, se = study("--from", yade_study, "--out", out, "--seeds", 1, 2, 3, "--samples", "spheres", "--dry-run",
                       *TINY)
    assert rc == 0, se
    lines = so.splitlines()
    assert lines[0].startswith("lmgc90.study: [spheres] seed 1: spheres-seed1: finished, adopted")
    assert lines[1].startswith("lmgc90.study: [spheres] seed 2: spheres-seed2: finished, adopted")
    assert lines[2].startswith("lmgc90.study: [spheres] seed 3: spheres-seed3: to run; about ")
    assert lines[3] == "lmgc90.study: 2 finished, 0 to resume, 1 to run, 0 written by another process"
    assert sorted(os.listdir(out)) == listing


@needs_lmgc90
def test_a_run_another_process_writes_is_left_alone(cd_study, yade_study):
    from yade_scripts.runs.runlock import RunLock

    folder = cd_study[0] / "spheres-seed3"
    folder.mkdir()
    lock = RunLock(str(folder / "run.lock"), "lmgc90.triaxial").acquire()
    try:
        from lmgc90.study import plan
        e = plan(yade_study, str(cd_study[0]), ["spheres"], [3], TINY[1::2])[0]
        assert e["action"] == "busy" and f"pid {os.getpid()}" in e["holder"]
    finally:
        lock.release()
        os.remove(folder / "run.lock")
        folder.rmdir()


@needs_lmgc90
def test_a_folder_of_other_parameters_is_refused_in_one_line(cd_study, yade_study):
    out = cd_study[0]
    rc, so, se = study("--from", yade_study, "--out", out, "--seeds", 1, 2, "--samples", "spheres",
                       *TINY, "--set", "dt=1e-4")
    assert rc == 2 and so == ""
    assert len(se.strip().splitlines()) == 1, se
    assert "spheres-seed1: a CD run of other parameters (dt 0.0002 there, 0.0001 asked)" in se and "--set-aside" in se
    assert sorted(n for n in os.listdir(out) if n.startswith("spheres-seed")) == ["spheres-seed1", "spheres-seed2"]


@pytest.mark.parametrize("make, words", [
    (lambda p: None, "no such YADE study"),
    (lambda p: p.mkdir(), "no manifest.json, not a finished YADE study"),
    (lambda p: make_yade_study(p, [1]), "its manifest has no spheres seed 2 (it has 1)"),
])
def test_a_missing_yade_study_or_seed_is_refused_in_one_line(tmp_path, make, words):
    yade = tmp_path / "small"
    make(yade)
    rc, so, se = study("--from", yade, "--out", tmp_path / "cd", "--seeds", 1, 2, "--samples", "spheres")
    assert rc == 2 and so == "" and len(se.strip().splitlines()) == 1, se
    assert words in se and "lmgc90.study: error: --from" in se
    assert not (tmp_path / "cd").exists()


@needs_lmgc90
def test_the_archive_keeps_the_numbers_and_a_new_host_collects_them(cd_study, yade_study, tmp_path):
    from postproc.study.report import discover

    out, dest = cd_study[0], tmp_path / "archive"
    rc, so, se = study("--from", yade_study, "--out", out, "--seeds", 1, 2, "--samples", "spheres", "--no-figures",
                       "--archive", dest, *TINY)
    assert rc == 0, so + se
    for k in (1, 2):
        kept = dest / f"spheres-seed{k}"
        rec = json.load(open(kept / "run.archived.json"))
        assert {"run.params.json", "run.info.json", "analysis/summary.csv"} <= set(rec["files"])
        assert rec["dump"]["name"] == "run.h5" and not any(n.endswith(".h5") for n in os.listdir(kept))
    # another host: none of the run folders, the archive only
    rc, so, se = study("--from", yade_study, "--out", tmp_path / "elsewhere", "--seeds", 1, 2, "--samples", "spheres",
                       "--no-figures", "--archive", dest, "--collect", *TINY)
    assert rc == 0, so + se
    runs = discover(str(tmp_path / "elsewhere"))["spheres"]
    assert [r["status"] for r in runs] == ["ok", "ok"] and all("archived" in r for r in runs)
    assert os.path.exists(os.path.join(runs[0]["analysis"], "summary.csv"))
    assert not os.path.exists(tmp_path / "elsewhere" / "spheres-seed1" / "run.h5")


@needs_lmgc90
def test_the_slurm_script_runs_one_task_per_run_to_do(cd_study, yade_study):
    from lmgc90.study import SLURM_PLAN, estimate, slurm_time

    out = cd_study[0]
    rc, so, se = study("--from", yade_study, "--out", out, "--seeds", 1, 2, 3, "--samples", "spheres", "--slurm",
                       "--no-figures", *TINY)
    assert rc == 0, se
    text = open(out / "slurm.sh").read()
    tasks = json.load(open(out / SLURM_PLAN))["tasks"]
    assert [t["label"] for t in tasks] == ["seed 3"]            # seeds 1 and 2 are finished
    # 24 grains, 150 + 0.004 / (2 x 2e-4) steps: the limit is the one-hour floor
    assert tasks[0]["cost"] == estimate(24, 2e-4, 0.004, RATE)
    assert f"#SBATCH --time={slurm_time(tasks[0]['cost']['seconds'])}\n" in text and "0-01:00:00" in text
    for line in ("#SBATCH --array=1-1\n", "#SBATCH --signal=B:USR1@300\n", "#SBATCH --requeue\n",
                 f"#SBATCH --output={out}/slurm-%A_%a.out\n", "#SBATCH --cpus-per-task=1\n"):
        assert line in text
    assert f'-m lmgc90.study --task "${{SLURM_ARRAY_TASK_ID:?not an array task}}" --out "{out}" --requeues 10 --no-figures\n' in text
    assert subprocess.run(["bash", "-n", str(out / "slurm.sh")]).returncode == 0
    # a task by hand, as the script's comment says: it runs seed 3 and analyses it
    res = subprocess.run(["bash", str(out / "slurm.sh")], env={**os.environ, "SLURM_ARRAY_TASK_ID": "1"},
                         capture_output=True, text=True, timeout=600)
    assert res.returncode == 0, res.stdout + res.stderr
    assert "lmgc90.study: FINAL done" in res.stdout
    assert os.path.exists(out / "spheres-seed3" / "analysis" / "summary.csv")
    res = subprocess.run(["bash", str(out / "slurm.sh")], env={**os.environ, "SLURM_ARRAY_TASK_ID": "2"},
                         capture_output=True, text=True)
    assert res.returncode == 2 and "no task 2" in res.stderr


def test_the_cost_model_gives_the_measured_shear_steps():
    """About 1100 shear steps to eps_1 = 0.3 at dt = 1e-3 s and the YADE
    S1's rate (0.2894/s), 2-4 s a step at 200 grains (docs/measurements.md)."""
    from lmgc90.study import ISOTROPIC_STEPS, estimate

    e = estimate(200, 1e-3, 0.3, 0.2894)
    assert round(e["shear_steps"]) == 1037
    assert 2 * e["steps"] <= e["seconds"] <= 4 * e["steps"]
    assert estimate(400, 1e-3, 0.3, 0.2894)["seconds"] == 2 * e["seconds"]
    assert estimate(200, 5e-4, 0.3, 0.2894)["steps"] == ISOTROPIC_STEPS + 2 * e["shear_steps"]


@needs_lmgc90
def test_sigterm_reaches_the_runs_which_checkpoint(yade_study, tmp_path):
    """The study stopped by SIGTERM stops its runs (each writes its checkpoint
    and exits 75), exits 75 itself, and the next call resumes the run."""
    out = tmp_path / "cd"
    long = [a if not a.startswith("final_strain=") else "final_strain=0.3" for a in TINY]
    proc = subprocess.Popen([sys.executable, "-m", "lmgc90.study", "--from", yade_study, "--out", str(out),
                             "--seeds", "1", "--samples", "spheres", "--no-figures", *long], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    progress = out / "spheres-seed1" / "run.progress.json"
    t0 = time.time()
    while not progress.exists() and proc.poll() is None and time.time() - t0 < 300:
        time.sleep(0.05)
    time.sleep(1.0)
    proc.send_signal(signal.SIGTERM)
    text = proc.communicate(timeout=300)[0]
    assert proc.returncode == 75, text
    assert "[spheres] spheres-seed1: stopped on request (exit 75); it resumes from its checkpoint" in text
    assert (out / "spheres-seed1" / "run.ckpt" / "scene.json").exists()
    from yade_scripts.runs.runstate import complete
    assert not complete(str(out / "spheres-seed1" / "run.h5"))
    rc, so, se = study("--from", yade_study, "--out", out, "--seeds", 1, "--samples", "spheres", "--dry-run", *long)
    assert rc == 0 and "spheres-seed1: unfinished, resumes from its checkpoint" in so, so + se
