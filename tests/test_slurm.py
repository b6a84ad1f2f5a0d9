"""SLURM job arrays: generate --slurm writes a script bash accepts,
one array task per table line; tiny lines run locally with
SLURM_ARRAY_TASK_ID set (from another folder, one stopped by SIGTERM and
resumed, bad lines refused), then study --collect analyses what has
finished and lists every line. The real single-node cluster is
tests/test_slurm_cluster.py."""
import json
import math
import os
import shutil
import signal
import subprocess
import time

import h5py
import pytest

from yade_scripts.campaign.generate import main as generate_main
from yade_scripts.campaign.presets import resolve
from yade_scripts.launch.slurm import (COMPACTION_STEPS, CONTACTS_PER_GRAIN, PLACEMENT_FACTOR, SHEAR_STEPS,
                                       US_PER_CONTACT_STEP, estimate, shear_step_factor)

#: the reference run's 1/dt over the expected 1/dt of 1000 grains drawn from
#: the library (its dt 3.953 us, the library's limit 3.276 us = 1/(1.11 x the
#: expectation)), and the expected 1/dt of N grains over that of 1000
REF_RATE = 3.276 * 1.1100 / 3.953
DRAWS = {200: 0.8725, 1000: 1.0, 2000: 1.0479, 5000: 1.0967, 10_000: 1.1089, 36_933: 1.1100}
from yade_scripts.campaign.study import main as study_main

YADE = shutil.which("yade")


def make(tmp_path, seeds=(1, 2, 3), *extra):
    out = tmp_path / "arr"
    assert generate_main(["--preset", "tiny", "--sample", "spheres", "--out", str(out),
                          "--seeds", *map(str, seeds), "--slurm", *extra]) == 0
    return out


def task_env(k, **extra):
    env = {k_: v for k_, v in os.environ.items() if not k_.startswith("SLURM_")}
    if k is not None:
        env["SLURM_ARRAY_TASK_ID"] = str(k)
    return {**env, **extra}


def task(out, k, cwd, **extra):
    return subprocess.run(["bash", str(out / "slurm.sh")], cwd=cwd, env=task_env(k, **extra),
                          capture_output=True, text=True, timeout=600)


def test_script_is_valid_bash_with_one_task_per_line(tmp_path):
    out = make(tmp_path, (1, 2, 3), "--slurm-cpus", "4", "--slurm-time", "2-00:00:00")
    script = (out / "slurm.sh").read_text()
    assert subprocess.run(["bash", "-n", str(out / "slurm.sh")]).returncode == 0
    assert "#SBATCH --array=1-3" in script and "#SBATCH --cpus-per-task=4" in script
    assert "#SBATCH --time=2-00:00:00" in script
    # SLURM's output in the run folder whatever folder sbatch runs in, kept across requeues; SIGUSR1
    # before the time limit to the batch shell, which is the task itself (exec)
    assert f"#SBATCH --output={out}/slurm-%A_%a.out" in script and "#SBATCH --open-mode=append" in script
    assert "#SBATCH --signal=B:USR1@300" in script and "#SBATCH --requeue" in script
    assert f'HERE="${{RUN_DIR:-{out}}}"' in script
    assert 'exec "$PY" -m yade_scripts.launch.task "$HERE" --requeues 10' in script
    # task k is the k-th run line of the table
    from yade_scripts.launch.batch import table_lines
    assert [(t.task, t.number, t.description) for t in table_lines(str(out))] == [
        (1, 2, "spheres-seed1"), (2, 3, "spheres-seed2"), (3, 4, "spheres-seed3")]
    # out-of-range and missing task ids are refused without running anything
    for k in (0, 4, "x"):
        r = task(out, k, tmp_path)
        assert r.returncode == 2 and "no such line" in r.stderr
    r = task(out, None, tmp_path)
    assert r.returncode != 0 and "SLURM_ARRAY_TASK_ID is not set" in r.stderr
    assert not any((out / f"spheres-seed{k}").exists() for k in (1, 2, 3))


def test_bad_options_and_empty_collect(tmp_path, capsys):
    assert generate_main(["--preset", "tiny", "--sample", "spheres", "--out",
                          str(tmp_path / "x"), "--slurm", "--slurm-time", "soon"]) == 2
    assert "--slurm-time" in capsys.readouterr().err
    assert study_main(["--collect", str(tmp_path)]) == 2
    assert "no generated run folder" in capsys.readouterr().err
    set_aside = make(tmp_path / "study", (1,))              # a run folder the study set aside
    set_aside.rename(tmp_path / "study" / f"{set_aside.name}.old-1")
    assert study_main(["--collect", str(tmp_path / "study")]) == 2
    assert "no generated run folder" in capsys.readouterr().err
    out = make(tmp_path, (1,))
    assert study_main(["--collect", str(out), "--no-figures"]) == 0   # nothing finished: still a manifest and a report
    assert "no run has finished yet (1 not finished)" in capsys.readouterr().err
    manifest = json.loads((out / "manifest.json").read_text())
    assert [m["status"] for m in manifest["spheres"]] == ["not started"]
    assert "| S2 spheres | seed 1 | not started" in (out / "report" / "report.md").read_text()
    for bad in (["--slurm-signal", "90", "--slurm-time", "1:00"], ["--slurm-requeues", "-1"],
                ["--slurm-cpus", "0"]):
        assert generate_main(["--preset", "tiny", "--sample", "spheres", "--out", str(tmp_path / "y"),
                              "--slurm", *bad]) == 2
        assert "--slurm-" in capsys.readouterr().err and not (tmp_path / "y").exists()


def test_the_script_runs_from_any_folder_and_names_a_missing_table(tmp_path):
    """sbatch from another folder (SLURM_SUBMIT_DIR is that folder) or with
    -D: the task runs in its generated folder; a moved or broken folder is
    one line, and nothing is created outside the run folder."""
    out = make(tmp_path, (1, 2))
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    os.remove(out / "table.txt")
    r = task(out, 1, elsewhere, SLURM_SUBMIT_DIR=str(elsewhere))
    assert r.returncode == 2 and r.stderr.strip() == (
        f"slurm.sh: {out}/table.txt is missing: not the generated run folder (moved? write slurm.sh again "
        f"there: python -m yade_scripts.launch.slurm FOLDER)")
    assert list(elsewhere.iterdir()) == [] and not (out / "spheres-seed1").exists()
    # RUN_DIR names the folder instead (a moved one)
    moved = tmp_path / "moved"
    shutil.copytree(out, moved, symlinks=True)
    r = task(out, 1, elsewhere, RUN_DIR=str(moved))
    assert r.returncode == 2 and f"{moved}/table.txt is missing" in r.stderr
    from yade_scripts.launch.slurm import main as slurm_main
    (out / "table.txt").write_text("description seed out\nspheres-seed1 1 'spheres-seed1.h5'\n")
    assert slurm_main([str(out), "--cpus", "1"]) == 0
    assert "#SBATCH --array=1-1" in (out / "slurm.sh").read_text()


def test_a_bad_table_line_fails_its_task_alone_in_one_line_before_yade(tmp_path):
    """A hand-edited table: a value out of range, one that is not a number,
    a misspelt column. Each task of a bad line stops at once with one line
    naming the line and the parameter (exit 2, no YADE, no run folder); a
    good line of the same table is unaffected (its task would run)."""
    out = make(tmp_path, (1, 2, 3))
    (out / "table.txt").write_text("description seed kappa out\n"
                                   "spheres-seed1 1 150.0 'spheres-seed1.h5'\n"
                                   "spheres-seed2 2 -150 'spheres-seed2.h5'\n"
                                   "spheres-seed3 15O 150.0 'spheres-seed3.h5'\n")
    r = task(out, 2, tmp_path)
    assert r.returncode == 2 and r.stderr.strip().splitlines()[-1] == (
        f"task: FINAL invalid line: {out}/table.txt line 3: kappa = -150.0 is outside [1, 1e+09]")
    r = task(out, 3, tmp_path)
    assert r.returncode == 2 and r.stderr.strip().splitlines()[-1] == (
        f"task: FINAL invalid line: {out}/table.txt line 4: seed = 15O is not a Python literal")
    (out / "table.txt").write_text("description seed kapa out\nspheres-seed1 1 150.0 'spheres-seed1.h5'\n")
    r = task(out, 1, tmp_path)
    assert r.returncode == 2 and r.stderr.strip().splitlines()[-1] == (
        f"task: FINAL invalid line: {out}/table.txt line 2: unknown parameter 'kapa' (did you mean 'kappa'?)")
    assert not any((out / f"spheres-seed{k}").exists() for k in (1, 2, 3))
    assert "Traceback" not in r.stdout + r.stderr


def test_cost_model_scaling():
    """The paper preset from the measured constants, by hand: kappa 1e4 and
    safety 0.45 (sqrt(1e4/3000) x 0.3/0.45 the steps), I 1e-3 (5 x the shear steps of I = 5e-3),
    I_c 1e-2 (10^0.55 x the compaction steps of I_c = 0.1); the soft preset's
    bounding-sphere placement multiplies the compaction by its measured
    factor; the reference point gives the reference steps themselves."""
    p = resolve("paper", "polyhedra")
    e = estimate(p)
    root = math.sqrt(1e4 / 3000) * 0.3 / 0.45                # and its time step at 0.45, not 0.3
    grown = 36.933 ** 0.25                                 # the compaction's growth with N, above 1000 grains
    assert e["compaction_steps"] == pytest.approx(COMPACTION_STEPS["polyhedra"] * root * 10 ** 0.55 * grown,
                                                  rel=1e-12)
    # the shear at the time step expected of 36 933 grains, every sample holding the library's limit
    assert e["shear_steps"] == pytest.approx(SHEAR_STEPS["polyhedra"] * root * 5 * DRAWS[36_933] / REF_RATE,
                                             rel=1e-12)
    assert e["contacts"] == pytest.approx(36933 * CONTACTS_PER_GRAIN["polyhedra"])
    assert e["core_hours"] == pytest.approx(e["steps"] * e["contacts"] * US_PER_CONTACT_STEP["polyhedra"] * 1.04
                                            / 3.6e9, rel=1e-12)                # the 5000-grain cost per contact
    assert US_PER_CONTACT_STEP["polyhedra"] == pytest.approx(1.41 * 0.670, rel=1e-12)    # the plugin's step
    assert estimate(p, "pyrunner")["core_hours"] == pytest.approx(e["core_hours"] / 0.670, rel=1e-12)
    with pytest.raises(ValueError, match="kernel_path"):
        estimate(p, "python")
    # the cost per contact-step from 1000 to 5000 grains, linear in log N; the compaction above 1000 only
    from yade_scripts.launch.slurm import _grains_factor
    assert [_grains_factor(n, 5000, 1.08) for n in (200, 1000, 5000, 36933)] == [1.0, 1.0, 1.08, 1.08]
    assert _grains_factor(math.sqrt(5) * 1000, 5000, 1.08) == pytest.approx(1.04, rel=1e-12)
    # the shear's time step: the table's points, linear in log N between, flat beyond
    for n, g in DRAWS.items():
        assert shear_step_factor("polyhedra", n) == pytest.approx(g / REF_RATE, rel=1e-12)
    assert shear_step_factor("polyhedra", math.sqrt(2000 * 5000)) == pytest.approx(
        (DRAWS[2000] + DRAWS[5000]) / 2 / REF_RATE, rel=1e-12)
    assert shear_step_factor("polyhedra", 20) == shear_step_factor("polyhedra", 200)
    assert shear_step_factor("polyhedra", 10 ** 6) == shear_step_factor("polyhedra", 36_933)
    assert [shear_step_factor("spheres", n) for n in (200, 1000, 36_933)] == [1.0, 1.0, 1.0]
    small, default = estimate(resolve("small", "polyhedra")), estimate(resolve("default", "polyhedra"))
    assert small["compaction_steps"] == pytest.approx(default["compaction_steps"], rel=1e-12)
    assert small["shear_steps"] == pytest.approx(default["shear_steps"] * DRAWS[200] / DRAWS[1000], rel=1e-12)
    q = dict(p, kappa=4e4, inertial_number=2e-3)          # 2 x sqrt(kappa), 1/2 I: the same shear
    assert estimate(q)["shear_steps"] == pytest.approx(e["shear_steps"], rel=1e-12)
    q = dict(p, safety=2 * p["safety"])                   # a time step twice as long: half the steps
    assert estimate(q)["steps"] == pytest.approx(e["steps"] / 2, rel=1e-12)
    # the default's polyhedra step at 0.45 too: the reference point (0.3) in 2/3 of its steps
    d = estimate(resolve("default", "polyhedra"))
    k = DRAWS[1000] / REF_RATE                              # 1000 grains' expected step against the reference run's
    assert d["steps"] == pytest.approx((COMPACTION_STEPS["polyhedra"] + SHEAR_STEPS["polyhedra"] * k) * 0.3 / 0.45,
                                       rel=1e-12)
    assert estimate(resolve("default", "polyhedra", {"safety": 0.3}))["steps"] == pytest.approx(
        COMPACTION_STEPS["polyhedra"] + SHEAR_STEPS["polyhedra"] * k, rel=1e-12)
    # the spheres' constants are measured at the default's own point (I = 1e-3), and
    # their placement factor does not apply: the soft preset (kappa 300, I 2e-2,
    # I_c 5e-2) scales them by sqrt(0.1), 2^0.55 and 1/20 only
    d = estimate(resolve("default", "spheres"))
    assert d["steps"] == pytest.approx(COMPACTION_STEPS["spheres"] + SHEAR_STEPS["spheres"], rel=1e-12)
    soft = estimate(resolve("soft", "spheres"))
    assert soft["compaction_steps"] == pytest.approx(COMPACTION_STEPS["spheres"] * math.sqrt(0.1) * 2 ** 0.55,
                                                     rel=1e-12)
    assert soft["shear_steps"] == pytest.approx(SHEAR_STEPS["spheres"] * math.sqrt(0.1) / 20, rel=1e-12)
    soft = estimate(resolve("soft", "polyhedra"))
    assert soft["compaction_steps"] == pytest.approx(COMPACTION_STEPS["polyhedra"] * math.sqrt(0.1) * 2 ** 0.55
                                                     * PLACEMENT_FACTOR["spheres"], rel=1e-12)
    # half the strain: the top wall travels 1 - exp(-eps) of the height
    h = estimate(dict(resolve("default", "polyhedra"), final_strain=0.15, safety=0.3))
    assert h["shear_steps"] == pytest.approx(SHEAR_STEPS["polyhedra"] * (1 - math.exp(-0.15))
                                             / (1 - math.exp(-0.3)) * DRAWS[1000] / REF_RATE, rel=1e-12)


@pytest.mark.yade
@pytest.mark.skipif(YADE is None, reason="needs Debian's yade")
def test_two_tiny_lines_run_locally_then_collect(tmp_path, capsys):
    out = make(tmp_path, (1, 2, 3))
    with open(out / "table.txt", "a") as fh:                # a hand edit: a fourth line, out of range
        fh.write("spheres-seed4 4 'spheres-seed4.h5'\n".replace(" 4 ", " -4 "))
    for k in (1, 2):
        r = task(out, k, tmp_path)            # from another folder: the script finds its own
        assert r.returncode == 0, r.stdout + r.stderr
        d = out / f"spheres-seed{k}"
        assert (d / "triaxial.log").exists() and "done in" in (d / "triaxial.log").read_text()
        with h5py.File(d / f"spheres-seed{k}.h5", "r") as f:
            assert f.attrs["complete"] == 1
            assert json.loads(f.attrs["parameters"])["seed"] == k     # the line's parameters
    again = task(out, 1, tmp_path)
    assert again.returncode == 0 and "is complete and verifies, nothing to do" in again.stdout
    # line 3 never ran, line 4 is invalid: both listed, the two finished ones analysed
    assert study_main(["--collect", str(out), "--no-figures"]) == 0
    err = capsys.readouterr().err
    assert "not finished: spheres-seed3 (not started)" in err
    assert f"resubmit the unfinished lines of arr: sbatch --array=3 {out}/slurm.sh" in err
    manifest = json.loads((out / "manifest.json").read_text())
    assert [m["label"] for m in manifest["spheres"]] == ["seed 1", "seed 2", "seed 3", "spheres-seed4"]
    assert [m["status"] for m in manifest["spheres"][:3]] == ["ok", "ok", "not started"]
    assert manifest["spheres"][3]["status"] == (f"invalid line: {out}/table.txt line 5: seed = -4 is outside "
                                                f"[0, 9.22337e+18]")
    assert manifest["spheres"][2]["resubmit"] == f"sbatch --array=3 {out}/slurm.sh"
    md = (out / "report" / "report.md").read_text()
    assert f"| S2 spheres | seed 3 | not started (resubmit the unfinished lines of arr: sbatch --array=3 " \
           f"{out}/slurm.sh) |" in md
    assert "* S2 spheres spheres-seed4: invalid line:" in md
    # a complete dump that lost a snapshot (another writer's doing): refused in one line, never analysed
    with h5py.File(out / "spheres-seed2" / "spheres-seed2.h5", "a") as f:
        n = int(f.attrs["n_snapshots"])
        del f[f"snapshots/{n - 2:06d}"]
    assert study_main(["--collect", str(out), "--no-figures"]) == 0
    err = capsys.readouterr().err
    assert f"not finished: spheres-seed2 (refused, not analysed: {out}/spheres-seed2/spheres-seed2.h5: complete but " \
        f"does not verify: says {n} snapshots, holds {n - 1}" in err
    assert f"resubmit the unfinished lines of arr: sbatch --array=3 {out}/slurm.sh" in err      # not line 2
    manifest = json.loads((out / "manifest.json").read_text())
    assert manifest["spheres"][1]["status"].startswith("refused, not analysed:")
    assert "move it aside" in manifest["spheres"][1]["note"]


@pytest.mark.yade
@pytest.mark.skipif(YADE is None, reason="needs Debian's yade")
def test_sigterm_stops_the_task_resumably_and_every_attempt_is_kept(tmp_path, capsys):
    """SIGTERM to the task (what SLURM's --signal sends the batch shell):
    YADE writes its checkpoint, the task says it is resumable and at which
    step, exits 75 (no SLURM here to requeue it); run again, it resumes to
    the end, and the line's log keeps both attempts. --collect in between
    says the line is resumable at that step."""
    # a line that outlasts the signal's way (the pool polls once a second) tenfold: its shear alone,
    # 80 000 steps, takes about 10 s on a quiet core (I = 5e-3 took 1 s and once finished first)
    out = make(tmp_path, (1,), "--set", "final_strain=0.1", "--set", "inertial_number=2e-4")
    d = out / "spheres-seed1"
    p = subprocess.Popen(["bash", str(out / "slurm.sh")], cwd=tmp_path, env=task_env(1), stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    t0 = time.time()
    while not ((d / "spheres-seed1.log.csv").exists() and "triaxial.py: 40 spheres" in
               (d / "triaxial.log").read_text()):
        assert p.poll() is None and time.time() - t0 < 300, "the run did not start"
        time.sleep(0.2)
    p.send_signal(signal.SIGTERM)
    text = p.communicate(timeout=300)[0]
    assert p.returncode == 75, text
    from yade_scripts.runs.runstate import checkpoint_position
    step, stage = checkpoint_position(str(d / "spheres-seed1.h5"))
    assert text.count("task: FINAL") == 1
    assert f"task: FINAL stopped on request (SIGTERM) (resumable at step {step} ({stage})); to resume: run the " \
        "task again" in text
    assert study_main(["--collect", str(tmp_path)]) == 0     # nothing finished yet
    assert f"not finished: arr/spheres-seed1 (resumable at step {step} ({stage}))" in capsys.readouterr().err
    r = task(out, 1, tmp_path)
    assert r.returncode == 0 and "task: FINAL done: spheres-seed1.h5 complete" in r.stdout
    log = (d / "triaxial.log").read_text()
    assert log.count("==== attempt ") == 2 and "==== attempt 2 of spheres-seed1: resumes from its checkpoint " \
        f"at step {step}" in log
    assert log.index("stopped on SIGTERM") < log.index(f"resumed from spheres-seed1.ckpt at step {step}")
    tries = json.loads((d / "spheres-seed1.attempts.json").read_text())
    assert [(a["exit"], a["requested"], a["action"]) for a in tries] == [(75, True, "resume"), (0, False, "done")]


def started(d, p, name="spheres-seed1"):
    """Wait until the scene of the task process ``p`` has started in ``d``."""
    t0 = time.time()
    while not ((d / f"{name}.log.csv").exists() and "triaxial.py: 40 spheres" in
               (d / "triaxial.log").read_text()):
        assert p.poll() is None and time.time() - t0 < 300, "the run did not start"
        time.sleep(0.2)


def yade_child(pid):
    """The pid of the YADE process the task ``pid`` started."""
    r = subprocess.run(["pgrep", "-P", str(pid)], capture_output=True, text=True)
    kids = [int(x) for x in r.stdout.split()]
    assert len(kids) == 1, r.stdout
    return kids[0]


@pytest.mark.yade
@pytest.mark.skipif(YADE is None, reason="needs Debian's yade")
def test_one_writer_per_line_and_a_crash_before_any_checkpoint_is_retried(tmp_path, capsys):
    """Two local tasks on one line: the second refuses at once (exit 4,
    one FINAL line naming the first's pid), touching nothing; a scene
    started by hand in the line's folder refuses too. --collect meanwhile
    lists the line as running and leaves it out of the resubmit command.
    Then YADE is killed before its first checkpoint: the task starts it
    afresh by itself, and the record holds both attempts. The whole line
    runs in about 5 s, so its YADE is frozen (SIGSTOP) as soon as it has
    started: the line stays running, whatever the host's speed, until
    the kill."""
    out = make(tmp_path, (1, 2), "--set", "final_strain=0.05", "--set", "inertial_number=2e-4")
    d = out / "spheres-seed1"
    p = subprocess.Popen(["bash", str(out / "slurm.sh")], cwd=tmp_path, env=task_env(1), stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    started(d, p)
    yade = yade_child(p.pid)
    os.kill(yade, signal.SIGSTOP)
    assert "yade" in open(f"/proc/{yade}/cmdline").read()       # YADE itself, not a wrapper
    second = task(out, 1, tmp_path)
    assert second.returncode == 4, second.stdout + second.stderr
    final = [x for x in (second.stdout + second.stderr).splitlines() if x.startswith("task: FINAL")]
    assert len(final) == 1 and final[0].startswith(f"task: FINAL refused: task 1 (spheres-seed1) is being written "
                                                   f"by pid {p.pid} on {os.uname().nodename} (a task)")
    hand = subprocess.run([YADE, "-n", "-x", "triaxial.py"], cwd=d, capture_output=True, text=True, timeout=120,
                          env={**os.environ, "YADE_BATCH": f"{out}/table.txt:2"})     # the line, by hand
    assert hand.returncode == 4 and "triaxial.py: refused: spheres-seed1/spheres-seed1 is being written by " \
        f"pid {p.pid}" in hand.stdout
    assert study_main(["--collect", str(out), "--no-figures"]) == 0
    err = capsys.readouterr().err
    assert f"not finished: spheres-seed1 (running: pid {p.pid} on" in err
    assert f"resubmit the unfinished lines of arr: sbatch --array=2 {out}/slurm.sh" in err
    # no checkpoint yet (the first is due after 300 s): a crash starts it afresh
    assert not (d / "spheres-seed1.ckpt").exists()
    os.kill(yade, signal.SIGKILL)          # a stopped process dies of SIGKILL too
    text = p.communicate(timeout=600)[0]
    assert p.returncode == 0, text
    assert "crashed (exit -9) before its first checkpoint: it starts afresh (retry 1 of at most 2)" in text
    tries = json.loads((d / "spheres-seed1.attempts.json").read_text())
    # the refused ones left no attempt, and the dump is the first task's, whole
    assert [(a["attempt"], a["exit"], a["action"]) for a in tries] == [(1, -9, "resume"), (2, 0, "done")]
    with h5py.File(d / "spheres-seed1.h5", "r") as f:
        assert f.attrs["complete"] == 1 and f.attrs["n_snapshots"] == len(f["snapshots"])


@pytest.mark.yade
@pytest.mark.skipif(YADE is None, reason="needs Debian's yade")
def test_an_attempt_killed_with_its_task_is_recorded_and_the_run_taken_over(tmp_path):
    """SIGKILL to the task and its YADE at once (what a node failure does):
    the lock goes with them; the next task takes the run over, records the
    killed attempt as killed under its own number and runs the line to the
    end as attempt 2."""
    out = make(tmp_path, (1,), "--set", "final_strain=0.02", "--set", "inertial_number=2e-4")
    d = out / "spheres-seed1"
    p = subprocess.Popen(["bash", str(out / "slurm.sh")], cwd=tmp_path, env=task_env(1), stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, start_new_session=True)
    started(d, p)
    os.killpg(p.pid, signal.SIGKILL)
    p.communicate(timeout=60)
    r = task(out, 1, tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    assert f"taking over the run from pid {p.pid} on {os.uname().nodename} (a task)" in r.stdout
    assert "attempt(s) 1 ended without a record (killed with their launcher): recorded as killed" in r.stdout
    tries = json.loads((d / "spheres-seed1.attempts.json").read_text())
    assert [(a["attempt"], a["action"]) for a in tries] == [(1, "killed"), (2, "done")]
    log = (d / "triaxial.log").read_text()
    assert log.count("==== attempt 1 ") == 1 and log.count("==== attempt 2 ") == 1


def test_intermediate_preset_fills_a_16_core_node(tmp_path):
    """The 5000-grain preset: its parameters, a 16-line table, and its cost
    from the model (the default S1's shear steps, its compaction 5^0.25 as
    long, 5000 grains' contacts at the 5000-grain cost per contact-step)."""
    p = resolve("intermediate", "polyhedra")
    assert (p["n_particles"], p["kappa"], p["inertial_number"]) == (5000, 3000.0, 5e-3)
    assert p["compaction_friction"] == 0.5 and p["friction"] == 0.5
    # S2 at the same N and as in the default (frictionless compaction, I = 1e-3), but
    # for the 5000 spheres' compaction gain (their taller box's walls oscillated at the default's)
    for name, n, spheres in (("small", 200, {}), ("intermediate", 5000, {"compaction_gain": 0.2})):
        assert resolve(name, "spheres") == {**resolve("default", "spheres"), "n_particles": n, **spheres}
        assert resolve(name, "polyhedra") == {**resolve("default", "polyhedra"), "n_particles": n}
    e = estimate(p)
    steps = (COMPACTION_STEPS["polyhedra"] * 5 ** 0.25
             + SHEAR_STEPS["polyhedra"] * DRAWS[5000] / REF_RATE) * 0.3 / 0.45   # the default's dt, 5000 grains' draws
    assert e["core_hours"] == pytest.approx(steps * 5000 * CONTACTS_PER_GRAIN["polyhedra"]
                                            * US_PER_CONTACT_STEP["polyhedra"] * 1.04 / 3.6e9, rel=1e-12)
    out = tmp_path / "node"
    assert generate_main(["--preset", "intermediate", "--sample", "spheres", "--out", str(out),
                          "--seeds", *map(str, range(1, 17))]) == 0
    lines = (out / "table.txt").read_text().splitlines()
    assert len(lines) == 17 and lines[16].split()[1] == "16"
    assert study_main(["--preset", "intermediate", "--out", str(tmp_path / "s"), "--ensemble", "16",
                       "--jobs", "16", "--job-threads", "0"]) == 2
