"""A real single-node SLURM cluster (.ci/slurm-node: Debian's slurm-wlm 22.05
and munge, accounting by slurmdbd and MariaDB) runs arrays of tiny scenes:

* array A, two tiny S1 lines (both at once on the 2-core node) whose runs outlast the one-minute time limit,
  submitted once from another folder: SIGUSR1 before the limit, each task
  checkpoints and requeues itself, without a human (once each line has
  been requeued twice or is done, the test raises the array's time limit,
  as an admin would, and each line ends in one more job); SLURM's
  accounting shows the requeues and the final COMPLETED with the task's
  reason; every attempt's log and SLURM's own output are kept;
  line 1's dump equals, bit for bit, that of the same line run
  uninterrupted (line 2 takes the same path with another seed);
* array C, tiny S2 lines with a hand-edited invalid fourth line, of which
  only line 1 and the invalid one are submitted (``sbatch -D`` elsewhere):
  the invalid task fails at once, named in the accounting; ``--collect``
  on the partly finished array (and on the folder of both arrays) lists
  every line with its state and the command that resubmits the rest;
* array B, two tiny S2 lines for one writer per run and for stopping
  (:func:`test_one_writer_stops_and_collect_on_a_real_cluster`).

Needs root, yade and the Debian packages (``make test-slurm`` installs
them); skipped otherwise, with the reason. Its time on a fresh clone is in
docs/measurements.md ("The test suite").
"""
import json
import os
import shutil
import subprocess
import time

import h5py
import numpy as np
import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
NODE = os.path.join(ROOT, ".ci", "slurm-node")
YADE = shutil.which("yade")
pytestmark = [pytest.mark.yade, pytest.mark.slurm, pytest.mark.timeout(1800)]


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    """SLURM_CONF of a single-node cluster brought up for these tests (and
    taken down after)."""
    if YADE is None:
        pytest.skip("Debian yade is not installed")
    check = subprocess.run([NODE, "check"], capture_output=True, text=True)
    if check.returncode != 0:
        pytest.skip(f"no single-node SLURM on this host: {check.stderr.strip()}")
    d = tmp_path_factory.mktemp("slurm-node")
    up = subprocess.run([NODE, "up", str(d)], capture_output=True, text=True, timeout=300)
    assert up.returncode == 0, up.stderr
    env = dict(os.environ, SLURM_CONF=str(d / "slurm.conf"))
    version = subprocess.run(["sinfo", "--version"], capture_output=True, text=True, env=env).stdout.strip()
    print(f"cluster: {up.stderr.strip()} ({version})")
    yield env
    subprocess.run([NODE, "down", str(d)], capture_output=True, text=True, timeout=300)


def run(env, *cmd, cwd=None):
    r = subprocess.run(list(cmd), env=env, cwd=cwd, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, f"{' '.join(cmd)}: {r.stderr}"
    return r.stdout


def sbatch(env, *args, cwd):
    return run(env, "sbatch", "--parsable", *args, cwd=cwd).strip().split(";")[0]


def wait_for(env, job, timeout):
    """Seconds until no task of ``job`` is pending or running."""
    t0 = time.time()
    while True:
        r = subprocess.run(["squeue", "-h", "-j", job, "-o", "%i %T %r"], env=env, capture_output=True, text=True)
        if r.returncode != 0 or not r.stdout.strip():
            return time.time() - t0
        assert time.time() - t0 < timeout, f"job {job} not done after {timeout} s:\n{r.stdout}"
        time.sleep(3)


def records(env, job, tasks, timeout=120):
    """{task: [(state, exit code, comment)]} of the job's array tasks from
    sacct (requeued instances included, oldest first), once every task has
    a final record (slurmdbd writes them a little after the end)."""
    t0 = time.time()
    while True:
        out = run(env, "sacct", "-j", job, "--duplicates", "--parsable2", "--noheader",
                  "--format=JobID,State,ExitCode,Comment")
        recs = {}
        for line in out.splitlines():
            jid, state, code, comment = line.split("|", 3)
            if "." in jid or "_" not in jid:
                continue
            recs.setdefault(int(jid.split("_")[1]), []).append((state, code, comment))
        final = {k: v for k, v in recs.items() if v and v[-1][0] not in ("PENDING", "RUNNING", "REQUEUED")}
        if set(final) >= set(tasks):
            return recs
        assert time.time() - t0 < timeout, f"sacct has no final record of every task of {job}:\n{out}"
        time.sleep(2)


def datasets(path):
    with h5py.File(path, "r") as f:
        out = {}
        f.visititems(lambda n, o: out.__setitem__(n, np.asarray(o[()])) if isinstance(o, h5py.Dataset) else None)
        return out, json.loads(f.attrs["parameters"]), bool(f.attrs["complete"])


def test_arrays_on_a_real_cluster(cluster, tmp_path, shape_library, capsys, monkeypatch):
    from yade_scripts.launch.batch import run_batch
    from yade_scripts.campaign.generate import main as generate
    from yade_scripts.campaign.study import main as study

    t_start = time.time()
    env = cluster
    monkeypatch.setenv("SLURM_CONF", env["SLURM_CONF"])       # --collect below asks squeue, in this process
    arrays, elsewhere, other = tmp_path / "arrays", tmp_path / "elsewhere", tmp_path / "other"
    for d in (arrays, elsewhere, other):
        d.mkdir()
    # C: S2 lines, the fourth invalid (a hand edit); only lines 1 and 4 submitted, with -D elsewhere
    c = arrays / "C"
    assert generate(["--preset", "tiny", "--sample", "spheres", "--out", str(c), "--seeds", "1", "2", "3",
                     "--slurm", "--slurm-cpus", "1", "--slurm-time", "10:00", "--slurm-signal", "60"]) == 0
    (c / "table.txt").write_text("description seed kappa out\n" + "".join(
        f"spheres-seed{k} {k} {kappa} 'spheres-seed{k}.h5'\n" for k, kappa in ((1, "150.0"), (2, "150.0"),
                                                                              (3, "150.0"), (4, "-150"))))
    job_c = sbatch(env, "-D", str(other), "--array=1,4", str(c / "slurm.sh"), cwd=elsewhere)
    # A: two S1 lines (one round on the 2-core node; a third took a second round, 2-3 min more); first line 1
    # run uninterrupted, here: how long it takes on this host sets A's time limit, so that every line outlasts
    # it whatever the host's speed (one reference line, not two: the requeue path is the same for both)
    # lines of a minute or more: SLURM keeps time limits in whole minutes and checks them about every 30 s, so
    # a line must outlast a minute to be sure to meet its first warning (at final_strain 0.05 and the tiny
    # preset's I a line of 18 s once finished before it)
    a_set = ["--set", "final_strain=0.2", "--set", "inertial_number=2e-3", "--set", "kernel_threads=1"]
    ref, a = tmp_path / "ref", arrays / "A"
    for out, seeds in ((ref, ["1"]), (a, ["1", "2"])):
        assert generate(["--preset", "tiny", "--sample", "polyhedra", "--out", str(out), "--seeds", *seeds,
                         "--library", shape_library, *a_set]) == 0
    assert run_batch(str(ref), jobs=1, echo=lambda m: None) == {"polyhedra-seed1": 0}
    line_seconds = json.loads((ref / "polyhedra-seed1.attempts.json").read_text())[-1]["seconds"]
    # SIGUSR1 comes up to 30 s off the gap asked for: a fifth of the line, at least 20 s
    gap, lead = max(20, int(line_seconds / 5)), 30
    limit = gap + lead
    from yade_scripts.launch.slurm import main as write_slurm
    # each attempt nets 15-30 s of the line (SIGUSR1 about 25 s after its start, YADE's start and the
    # checkpoint's load first): 3 requeues a task on a quiet host, 11-12 beside a study on both cores
    assert write_slurm([str(a), "--cpus", "1", "--time", f"{limit // 60}:{limit % 60:02d}", "--signal", str(lead),
                        "--requeues", "30"]) == 0
    job_a = sbatch(env, str(a / "slurm.sh"), cwd=elsewhere)            # from another folder

    # ------------------------------------------------------------ C: one line done, one invalid
    wait_for(env, job_c, 600)
    rc = records(env, job_c, (1, 4))
    assert rc[1][-1][:2] == ("COMPLETED", "0:0") and rc[1][-1][2] == "done: spheres-seed1.h5 complete"
    assert rc[4] == [("FAILED", "2:0", f"invalid line: {c}/table.txt line 5: kappa = -150.0 is outside "
                                       f"[1, 1e+09]")]
    assert not (c / "spheres-seed4").exists()                            # YADE never started
    assert "task: FINAL invalid line:" in (c / f"slurm-{job_c}_4.out").read_text()
    assert study(["--collect", str(c), "--no-figures"]) == 0             # a partly finished array
    err = capsys.readouterr().err
    assert f"resubmit the unfinished lines of C: sbatch --array=2,3 {c}/slurm.sh" in err
    m = json.loads((c / "manifest.json").read_text())["spheres"]
    assert [(e["label"], e["status"].split(":")[0]) for e in m] == [
        ("seed 1", "ok"), ("seed 2", "not started"), ("seed 3", "not started"), ("spheres-seed4", "invalid line")]
    # both arrays from their parent, A perhaps still running: every line listed
    assert study(["--collect", str(arrays), "--no-figures"]) == 0
    capsys.readouterr()
    m = json.loads((arrays / "manifest.json").read_text())
    assert len(m["polyhedra"]) == 2 and len(m["spheres"]) == 4 and m["spheres"][0]["status"] == "ok"
    # A's lines are in SLURM's hands: running, or pending between two of their jobs (or done)
    assert all(e["status"] == "ok" or e["status"].startswith((f"running: SLURM job {job_a}_",
                                                              f"pending: SLURM job {job_a}_"))
               for e in m["polyhedra"]), m["polyhedra"]

    # ------------------------------------------------------------ A: requeued to the end, without a human
    # Once every line has been requeued twice (a resumed attempt requeued again) or is done, the array's
    # time limit is raised, as an admin does for a job that needs longer: the rest of each line runs in
    # one job. At a minute's limit a line nets 15-30 s an attempt, and beside other work (the rest of the
    # suite) it took up to 12 requeues, each a YADE start and a checkpoint's load.
    def requeued_twice_or_done(k):
        out = a / f"slurm-{job_a}_{k}.out"
        text = out.read_text() if out.exists() else ""
        return text.count("task: FINAL requeued to resume") >= 2 or "task: FINAL done" in text

    t0 = time.time()
    while not all(requeued_twice_or_done(k) for k in (1, 2)):
        assert time.time() - t0 < 1500, f"array A: no two requeues of each line after {time.time() - t0:.0f} s"
        time.sleep(2)
    raised = subprocess.run(["scontrol", "update", f"JobId={job_a}", "TimeLimit=30:00"], env=env,
                            capture_output=True, text=True)
    if raised.returncode != 0:                      # refused only for an array that has just ended
        left = subprocess.run(["squeue", "-h", "-j", job_a], env=env, capture_output=True, text=True).stdout
        assert not left.strip(), f"scontrol update of array A: {raised.stderr}"
    seconds_a = wait_for(env, job_a, 1500)
    ra = records(env, job_a, (1, 2))
    for k in (1, 2):
        recs = ra[k]
        requeued = [r for r in recs[:-1] if r[0] == "REQUEUED"]
        assert len(requeued) == len(recs) - 1 >= 1, recs                 # the time limit forced requeues
        assert all(r[2].startswith("requeued to resume (") for r in requeued), recs
        assert recs[-1] == ("COMPLETED", "0:0", f"done: polyhedra-seed{k}.h5 complete"), recs
        d = a / f"polyhedra-seed{k}"
        log = (d / "triaxial.log").read_text()
        assert log.count("==== attempt ") == len(recs), log[-3000:]       # every attempt's log kept
        assert "resumed from polyhedra-seed%d.ckpt" % k in log and "done in" in log
        out = (a / f"slurm-{job_a}_{k}.out").read_text()                  # SLURM's output, every job of the task
        assert out.count(f"task: task {k} of {a}") == len(recs)
        assert out.count("task: FINAL requeued to resume") == len(requeued)
        assert out.rstrip().endswith(f"task: FINAL done: polyhedra-seed{k}.h5 complete")
        tries = json.loads((d / f"polyhedra-seed{k}.attempts.json").read_text())
        assert tries[-1]["action"] == "done" and all(t["slurm_job"] == f"{job_a}_{k}" for t in tries)
        got, par, complete = datasets(d / f"polyhedra-seed{k}.h5")
        assert complete and par["seed"] == k
        if k == 1:
            want, par_ref, _ = datasets(ref / "polyhedra-seed1.h5")
            assert par == par_ref and sorted(got) == sorted(want)
            for name in want:                                             # bit for bit
                assert got[name].dtype == want[name].dtype and got[name].tobytes() == want[name].tobytes(), name
    assert list(elsewhere.iterdir()) == [] and list(other.iterdir()) == []   # nothing outside the run folders
    print(f"cluster test: line 1 takes {line_seconds:.0f} s uninterrupted; time limit {limit} s, SIGUSR1 {lead} s "
          f"before; array A done {seconds_a:.0f} s after C; requeues per task {[len(ra[k]) - 1 for k in (1, 2)]}; "
          f"whole test {time.time() - t_start:.0f} s")


def scene_started(d, name, timeout=300):
    t0 = time.time()
    while not ((d / "triaxial.log").exists() and "triaxial.py: 40 spheres" in (d / "triaxial.log").read_text()
               and (d / f"{name}.log.csv").exists()):
        assert time.time() - t0 < timeout, f"{d}: the run did not start"
        time.sleep(1)


def test_one_writer_stops_and_collect_on_a_real_cluster(cluster, tmp_path, capsys, monkeypatch):
    """Line 1 submitted twice: the second job refuses at once (FAILED, exit
    4, its comment naming the first job), touching nothing. --collect
    while line 1 runs and line 2 is held in the queue lists them as
    running and pending, in no resubmit command. ``scancel --batch
    --signal=TERM`` stops line 1 for good (checkpoint, exit 75, comment);
    ``scancel --batch --signal=USR1`` stops line 2 and requeues it, and it
    runs to the end by itself; plain ``scancel`` of line 1 resubmitted
    stops it too, with one FINAL line (SLURM takes no comment for a
    cancelled job); submitted once more, it resumes to the end."""
    from yade_scripts.campaign.generate import main as generate
    from yade_scripts.runs.runstate import checkpoint_position
    from yade_scripts.campaign.study import main as study

    env = cluster
    monkeypatch.setenv("SLURM_CONF", env["SLURM_CONF"])       # --collect below asks squeue, in this process
    b = tmp_path / "B"
    assert generate(["--preset", "tiny", "--sample", "spheres", "--out", str(b), "--seeds", "1", "2", "--slurm",
                     "--slurm-cpus", "1", "--slurm-time", "30:00", "--set", "final_strain=0.1",
                     "--set", "inertial_number=1e-4"]) == 0
    d1, d2 = b / "spheres-seed1", b / "spheres-seed2"
    # a first job on a node just up: one submitted within a second of slurmctld's start once ended at once
    wait_for(env, sbatch(env, "--wrap", "true", cwd=tmp_path), 120)
    first = run(env, sys_python(), "-m", "yade_scripts.launch.slurm", str(b), "--submit", "--array", "1", cwd=tmp_path)
    job1 = json.loads((b / "slurm-jobs.json").read_text())[-1]["job"]
    scene_started(d1, "spheres-seed1")
    twice = sbatch(env, "--array=1", str(b / "slurm.sh"), cwd=tmp_path)        # the same line again
    held = sbatch(env, "--hold", "--array=2", str(b / "slurm.sh"), cwd=tmp_path)  # line 2, held in the queue
    wait_for(env, twice, 300)
    r = records(env, twice, (1,))
    assert r[1][-1][:2] == ("FAILED", "4:0"), r
    assert r[1][-1][2].startswith(f"refused: task 1 (spheres-seed1) is being written by pid ") and \
        f"(SLURM job {job1}_1, a task)" in r[1][-1][2], r
    out = (b / f"slurm-{twice}_1.out").read_text()
    assert out.count("task: FINAL") == 1 and "==== attempt" not in out
    # while line 1 runs and line 2 waits
    assert study(["--collect", str(b), "--no-figures"]) == 0
    err = capsys.readouterr().err
    assert f"not finished: spheres-seed1 (running: SLURM job {job1}_1, RUNNING)" in err
    assert f"not finished: spheres-seed2 (pending: SLURM job {held}_2, PENDING, JobHeldUser)" in err
    assert "resubmit" not in err
    # stop line 1 for good
    run(env, "scancel", "--batch", "--signal=TERM", f"{job1}_1")
    wait_for(env, job1, 300)
    r = records(env, job1, (1,))
    step, stage = checkpoint_position(str(d1 / "spheres-seed1.h5"))
    stopped = (f"stopped on request (SIGTERM, scancel) (resumable at step {step} ({stage})); to resume: "
               f"sbatch --array=1 {b}/slurm.sh")
    assert r[1] == [("FAILED", "75:0", stopped[:250])], r
    out = (b / f"slurm-{job1}_1.out").read_text()
    assert out.count("task: FINAL") == 1 and out.rstrip().endswith(f"task: FINAL {stopped}")
    assert study(["--collect", str(b), "--no-figures"]) == 0
    err = capsys.readouterr().err
    assert f"not finished: spheres-seed1 (resumable at step {step} ({stage}))" in err
    assert f"resubmit the unfinished lines of B: sbatch --array=1 {b}/slurm.sh" in err     # not line 2: queued
    # line 2: released, then stopped to resume later; it requeues itself and ends
    run(env, "scontrol", "release", held)
    scene_started(d2, "spheres-seed2")
    run(env, "scancel", "--batch", "--signal=USR1", f"{held}_2")
    wait_for(env, held, 900)
    r = records(env, held, (2,))
    assert [x[0] for x in r[2]] == ["REQUEUED", "COMPLETED"], r
    assert r[2][0][2].startswith("requeued to resume (resumable at step ") and \
        r[2][1][2] == "done: spheres-seed2.h5 complete", r
    out = (b / f"slurm-{held}_2.out").read_text()
    assert out.count("task: FINAL") == 2      # one per job of the task
    # line 1 again: plain scancel stops it too (one FINAL line, no comment), then it resumes to the end
    again = run(env, sys_python(), "-m", "yade_scripts.launch.slurm", str(b), "--submit", "--array", "1", cwd=tmp_path)
    job3 = json.loads((b / "slurm-jobs.json").read_text())[-1]["job"]
    t0 = time.time()
    while "resumed from spheres-seed1.ckpt" not in (d1 / "triaxial.log").read_text():
        assert time.time() - t0 < 300
        time.sleep(1)
    time.sleep(3)
    run(env, "scancel", f"{job3}_1")
    wait_for(env, job3, 300)
    out = (b / f"slurm-{job3}_1.out").read_text()
    # SLURM may show the cancelled job as COMPLETING by then: the task says only what it knows
    assert out.count("task: FINAL") == 1 and ("task: FINAL stopped on request (SIGTERM, scancel)" in out or
                                              "task: FINAL stopped by SLURM (SIGTERM: scancel or requeue" in out)
    assert "the job's comment could not be set" in out
    assert checkpoint_position(str(d1 / "spheres-seed1.h5"))[0] > step
    job4 = sbatch(env, "--array=1", str(b / "slurm.sh"), cwd=tmp_path)
    wait_for(env, job4, 900)
    assert records(env, job4, (1,))[1][-1] == ("COMPLETED", "0:0", "done: spheres-seed1.h5 complete")
    tries = json.loads((d1 / "spheres-seed1.attempts.json").read_text())
    assert [t["attempt"] for t in tries] == list(range(1, len(tries) + 1)) and tries[-1]["action"] == "done"
    assert study(["--collect", str(b), "--no-figures"]) == 0
    m = json.loads((b / "manifest.json").read_text())["spheres"]
    assert [e["status"] for e in m] == ["ok", "ok"]
    print(f"cluster test: submitted {first.strip() or 'line 1'}; {again.strip() or 'line 1 again'}")


def sys_python():
    """The Python of the venv that runs the tests (it has the packages)."""
    import sys

    return sys.executable
