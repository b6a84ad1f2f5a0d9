"""Checkpoints and resume: the checkpoint file format (no YADE),
then tiny YADE runs killed by SIGKILL or stopped by SIGTERM and resumed."""
import os
import random
import shutil
import signal
import subprocess
import time

import numpy as np
import pytest

from postproc.schema import DumpReader
from yade_scripts.runs import checkpoint
from yade_scripts.campaign.generate import generate

YADE = shutil.which("yade")


# ------------------------------------------------------------ the file format
def _sample():
    meta = {"step": 7, "stage": "shear", "x": 0.1 + 0.2, "fingerprint": "f", "n_snapshots": 2}
    arrays = {"kernel/R": np.random.default_rng(0).normal(size=(4, 9)), "ids": np.arange(6).reshape(3, 2)}
    return meta, arrays, {"scene": bytes(range(256)) * 3}


def test_round_trip_is_exact_and_previous_is_kept(tmp_path):
    path = str(tmp_path / "run.ckpt")
    meta, arrays, blobs = _sample()
    checkpoint.save(path, meta, arrays, blobs)
    checkpoint.save(path, {**meta, "step": 8}, arrays, blobs)
    assert checkpoint.candidates(path) == [path, path + ".prev"]
    m, a, b = checkpoint.read(path)
    assert m["step"] == 8 and m["x"] == 0.1 + 0.2                    # floats bit for bit
    assert all(np.array_equal(a[k], arrays[k]) and a[k].dtype == arrays[k].dtype for k in arrays)
    assert b == blobs
    assert checkpoint.read(path + ".prev")[0]["step"] == 7
    checkpoint.remove(path)
    assert checkpoint.candidates(path) == []


@pytest.mark.parametrize("damage, message", [
    (lambda d: d[:-100], "truncated"),
    (lambda d: d[:40], "header line unreadable"),
    (lambda d: d[:-50] + bytes([d[-50] ^ 1]) + d[-49:], "checksum mismatch"),
    (lambda d: b"garbage\n" + d, "not a triaxial checkpoint"),
    (lambda d: d.replace(b"triaxial-checkpoint 1", b"triaxial-checkpoint 9", 1), "format version 9"),
    (lambda d: b"", "not a triaxial checkpoint"),
])
def test_damaged_checkpoint_is_refused_in_one_line(tmp_path, damage, message):
    path = str(tmp_path / "run.ckpt")
    checkpoint.save(path, *_sample())
    with open(path, "rb") as fh:
        data = fh.read()
    with open(path, "wb") as fh:
        fh.write(damage(data))
    with pytest.raises(checkpoint.CheckpointError, match=message) as exc:
        checkpoint.read(path)
    assert "\n" not in str(exc.value)


def test_choose_falls_back_to_the_previous_checkpoint_then_gives_up(tmp_path):
    path = str(tmp_path / "run.ckpt")
    meta, arrays, blobs = _sample()
    checkpoint.save(path, meta, arrays, blobs)
    checkpoint.save(path, {**meta, "step": 8}, arrays, blobs)
    said = []
    ok = checkpoint.choose(path, "f", lambda m: m["step"], say=said.append)
    assert ok[0] == path and ok[4] == 8 and said == []
    with open(path, "r+b") as fh:                 # the newest is truncated: the previous one is used
        fh.truncate(os.path.getsize(path) - 10)
    ok = checkpoint.choose(path, "f", lambda m: m["step"], say=said.append)
    assert ok[0] == path + ".prev" and ok[4] == 7
    assert "truncated" in said[0] and "trying the previous one" in said[0]
    said.clear()                                  # another run's parameters: neither is used
    assert checkpoint.choose(path, "other", lambda m: m, say=said.append) is None
    assert "starting afresh" in said[-1] and "other parameters" in said[-1]
    said.clear()                                  # the caller's check refuses it (e.g. a missing snapshot)

    def refuse(m):
        raise ValueError("run.h5: snapshot 000001 is missing or unreadable")
    assert checkpoint.choose(path + ".none", "f", refuse, say=said.append) is None and said == []


def test_a_checkpoint_lacking_a_field_is_refused_not_a_traceback(tmp_path):
    path = str(tmp_path / "run.ckpt")
    checkpoint.save(path, {"fingerprint": "f", "step": 1})
    said = []
    assert checkpoint.choose(path, "f", lambda m: m["n_snapshots"], say=said.append) is None
    assert said == [f"checkpoint not used: {path}: field 'n_snapshots' missing; starting afresh"]


def test_a_checkpoint_with_a_field_of_the_wrong_type_is_refused_not_a_traceback(tmp_path):
    path = str(tmp_path / "run.ckpt")
    checkpoint.save(path, {"fingerprint": "f", "step": 1, "n_snapshots": None})
    said = []
    assert checkpoint.choose(path, "f", lambda m: m["n_snapshots"] + 1, say=said.append) is None
    assert len(said) == 1 and said[0].startswith(f"checkpoint not used: {path}: a field of the wrong type (")
    assert said[0].endswith("); starting afresh") and "\n" not in said[0]


def test_fingerprint_ignores_runtime_parameters_only():
    p = {"seed": 1, "kappa": 150.0, "checkpoint_seconds": 300.0, "max_steps": 0, "resume": True}
    assert checkpoint.fingerprint(p) == checkpoint.fingerprint({**p, "checkpoint_seconds": 1, "resume": False,
                                                                "max_steps": 10})
    assert checkpoint.fingerprint(p) != checkpoint.fingerprint({**p, "kappa": 151.0})


# ------------------------------------------------------------ YADE runs
def needs_yade(test):
    """Runs YADE: marked ``yade`` and skipped without Debian's yade."""
    return pytest.mark.yade(pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")(test))
ENV = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")
TINY = {"checkpoint_seconds": 0.3, "kernel_threads": 1, "final_strain": 0.03}


def _start(folder):
    log = open(os.path.join(folder, "yade.log"), "a")
    return subprocess.Popen([YADE, "-n", "-x", "triaxial.py"], cwd=folder, stdout=log, stderr=subprocess.STDOUT,
                            stdin=subprocess.DEVNULL, env=ENV)


def _wait_for(cond, timeout=300):
    t = time.time()
    while not cond():
        assert time.time() - t < timeout, "timed out"
        time.sleep(0.05)


def _log(folder):
    with open(os.path.join(folder, "yade.log")) as fh:
        return fh.read()


def _snapshots(path):
    with DumpReader(path) as r:
        assert r.complete
        return [r.read(i) for i in range(len(r))]


@needs_yade
def test_sigkill_at_a_random_moment_then_resume_matches_the_uninterrupted_run(tmp_path, shape_library):
    """Run A goes to the end uninterrupted; C is a copy of A taken at one of
    its checkpoints (the checkpoint first, then the dump parts, which only
    grow), so A is C's uninterrupted continuation. C is resumed, SIGKILLed
    at a random moment, resumed again: its dump must hold the same snapshots
    as A's, in order, without duplicates, and bit for bit (the resume is
    exact on the kernel path; docs/scenes.md says why)."""
    a, c = str(tmp_path / "A"), str(tmp_path / "C")
    generate(a, "tiny", "polyhedra", dict(TINY), library=shape_library)
    pa = _start(a)
    _wait_for(lambda: os.path.exists(os.path.join(a, "run.ckpt")) or pa.poll() is not None)
    os.makedirs(c)
    shutil.copy(os.path.join(a, "run.ckpt"), os.path.join(c, "run.ckpt"))
    for name in os.listdir(a):
        src = os.path.join(a, name)
        if not name.startswith("run.ckpt") and name != "yade.log":
            (shutil.copytree if os.path.isdir(src) else shutil.copy)(src, os.path.join(c, name))
    assert pa.wait(timeout=600) == 0, _log(a)[-2000:]
    pc = _start(c)
    _wait_for(lambda: "resumed from" in _log(c) or pc.poll() is not None)
    time.sleep(random.uniform(0.5, 3.0))
    pc.send_signal(signal.SIGKILL)
    pc.wait()
    rc = _start(c).wait(timeout=600)
    assert rc == 0, _log(c)[-2000:]
    assert _log(c).count("resumed from") == 2 or "done" in _log(c)
    sa, sc = _snapshots(os.path.join(a, "run.h5")), _snapshots(os.path.join(c, "run.h5"))
    steps = [s.step for s in sc]
    assert steps == sorted(set(steps)) == [s.step for s in sa]
    assert [s.stage for s in sc] == [s.stage for s in sa]
    for x, y in zip(sa, sc):
        for field in ("positions", "orientations", "id1", "id2", "force", "force_normal", "point", "wall_forces",
                      "box_lo", "box_hi", "volumes", "masses"):
            assert np.array_equal(getattr(x, field), getattr(y, field)), (x.name, field)
    assert not os.path.exists(os.path.join(c, "run.ckpt"))          # removed once the run is complete


@needs_yade
def test_sigterm_checkpoints_and_exits_75_then_a_damaged_checkpoint_falls_back(tmp_path, shape_library):
    d = str(tmp_path / "D")
    generate(d, "tiny", "polyhedra", dict(TINY), library=shape_library)
    p = _start(d)
    # after the second periodic checkpoint is written (a SIGTERM during its writing ends the run on it,
    # "checkpoint (periodic)", with no checkpoint of its own: that case once came up here)
    _wait_for(lambda: _log(d).count("checkpoint (periodic)") >= 2 or p.poll() is not None)
    p.send_signal(signal.SIGTERM)
    assert p.wait(timeout=120) == 75, _log(d)[-2000:]
    newest = checkpoint.read(os.path.join(d, "run.ckpt"))[0]
    prev = checkpoint.read(os.path.join(d, "run.ckpt.prev"))[0]
    # the run stops exactly at its newest checkpoint: its own, or (SIGTERM while a periodic one was written,
    # unlikely after the wait above but possible on a loaded host) that one
    assert newest["why"] in ("SIGTERM", "periodic")
    assert f"checkpoint ({newest['why']}) at step {newest['step']} " in _log(d)
    assert f"stopped on SIGTERM at step {newest['step']};" in _log(d) and prev["step"] < newest["step"]
    with DumpReader(os.path.join(d, "run.h5")) as r:       # the dump is left open for the resume
        assert not r.complete and len(r) >= newest["n_snapshots"]
    with open(os.path.join(d, "run.ckpt"), "r+b") as fh:    # damage the newest: the previous one is used
        fh.truncate(os.path.getsize(os.path.join(d, "run.ckpt")) // 2)
    assert _start(d).wait(timeout=600) == 0, _log(d)[-2000:]
    text = _log(d)
    assert "checkpoint not used:" in text and "truncated" in text
    assert f"resumed from run.ckpt.prev at step {prev['step']}" in text
    snaps = _snapshots(os.path.join(d, "run.h5"))
    steps = [s.step for s in snaps]
    assert steps == sorted(set(steps)) and snaps[0].stage == "isotropic" and snaps[-1].stage == "shear"
    import json

    info = json.load(open(os.path.join(d, "run.info.json")))
    assert len(info["resumes"]) == 1 and info["resumes"][0]["step"] == prev["step"]
    with open(os.path.join(d, "run.log.csv")) as fh:        # the log has no repeated step either
        log_steps = [int(line.split(",")[0]) for line in fh.readlines()[1:]]
    assert log_steps == sorted(set(log_steps))


# ------------------------------------------------------------ the study: partial runs
@needs_yade
def test_study_uses_a_partial_run_and_fails_only_without_any_usable_run(tmp_path, shape_library):
    """S1 'failed' (exit -6) at eps_1 = 0.04 of a run meant to reach 0.06
    (the dump's final_strain is raised after the fact): it is past the start
    of the steady state (0.5 x 0.06 = 0.03) with two steady snapshots, so it
    is analysed, marked PARTIAL with the strain it reached, and its steady
    snapshots (eps_1 >= 0.03 only) give the S1 numbers. S2 failed before
    shearing: no usable run, the one case that makes the study fail."""
    import json

    import h5py
    import pandas as pd

    from postproc.study.report import build_report
    from yade_scripts.campaign.study import analyse_and_report, unusable_samples

    out = tmp_path / "study"
    folders = {}
    for s in ("polyhedra", "spheres"):
        folders[s] = out / s
        generate(str(folders[s]), "tiny", s, {"final_strain": 0.04, "kernel_threads": 1} if s == "polyhedra"
                 else {"final_strain": 0.04}, library=shape_library)
    procs = [_start(str(f)) for f in folders.values()]
    assert [p.wait(timeout=600) for p in procs] == [0, 0]
    dump = str(folders["polyhedra"] / "run.h5")
    with h5py.File(dump, "r+") as f:
        params = json.loads(f.attrs["parameters"])
        f.attrs["parameters"] = json.dumps({**params, "final_strain": 0.06})
    sph = str(folders["spheres"] / "run.h5")           # spheres: only the isotropic snapshot survives
    with h5py.File(sph, "r+") as f:
        for name in list(f["snapshots"])[1:]:
            del f["snapshots/" + name]
    runs = {"polyhedra": [("seed 1", dump, -6)], "spheres": [("seed 1", sph, -6)]}
    failed = analyse_and_report(str(out), runs, attempts={("polyhedra", "seed 1"): [-9, -6, -6]}, figures=False)
    assert failed == ["polyhedra seed 1", "spheres seed 1"]
    manifest = json.loads((out / "manifest.json").read_text())
    s1, s2 = manifest["polyhedra"][0], manifest["spheres"][0]
    assert s1["status"] == "partial" and s1["attempts"] == [-9, -6, -6]
    assert s1["partial"]["eps_1_reached"] == pytest.approx(0.04, abs=2e-3)
    assert s1["partial"]["steady_from_eps_1"] == pytest.approx(0.03) and s1["partial"]["steady_snapshots"] == 2
    assert s2["status"].startswith("run failed (-6)")
    assert unusable_samples(str(out)) == ["spheres"]
    md = (out / "report" / "report.md").read_text()
    assert "| S1 polyhedra | seed 1 | PARTIAL (run failed (exit -6) at eps_1 = 0.04" in md
    assert "resumed 2 time(s)" in md and "S2 spheres: no analysed run" in md
    comp = pd.read_csv(out / "report" / "comparison.csv")
    ours = comp.loc[(comp["sample"] == "polyhedra") & (comp["quantity"] == "q/p plateau"), "ours"].item()
    summary = pd.read_csv(folders["polyhedra"] / "analysis" / "summary.csv")
    steady = summary[(summary["stage"] == "shear") & (summary["eps_1"] >= 0.03 - 1e-9)]
    assert len(steady) == 2 and ours == pytest.approx(steady["q_over_p"].mean(), rel=1e-12)
    # the same report rebuilt from the manifest alone
    (out / "report2").mkdir()
    (out / "report2" / "fig_qp.png").write_bytes(b"an earlier report's")   # numbers only: not left beside them
    md2 = open(build_report(str(out), str(out / "report2"), figures=False)).read()
    assert "PARTIAL" in md2 and "Not drawn" in md2 and not list(out.rglob("*.png"))


def test_a_crashed_run_is_resumed_a_stated_number_of_times(tmp_path, capsys):
    """The one rule (yade_scripts.runs.runstate.judge, applied by the pool that
    runs every run) with a stand-in for YADE: a run killed by SIGKILL that
    left a checkpoint is started again until it ends with 0, at most
    MAX_RESUMES times; a crash before the first checkpoint starts afresh,
    as many times at most; a blow-up (exit 3) is not retried."""
    from yade_scripts.launch.pool import Job, run_pool
    from yade_scripts.runs.runstate import MAX_RESUMES

    def exits(script):
        exe = tmp_path / "fake-yade"
        exe.write_text("#!/bin/bash\n" + script + "\n")
        exe.chmod(0o755)
        job = Job(str(tmp_path), None, "s", str(tmp_path / "run.h5"), tag="s", log=str(tmp_path / "yade.log"))
        run_pool([job], 1, echo=print, yade=str(exe))
        return job.exits

    (tmp_path / "run.ckpt").write_bytes(b"x")
    assert exits("if [ -f tried ]; then exit 0; fi; touch tried; kill -9 $$") == [-9, 0]
    assert "exit -9: resuming from its checkpoint (resume 1 of at most 2)" in capsys.readouterr().out
    assert exits("kill -9 $$") == [-9] * (MAX_RESUMES + 1)
    assert exits("exit 3") == [3]
    (tmp_path / "run.ckpt").unlink()
    assert exits("kill -9 $$") == [-9] * (MAX_RESUMES + 1)
    assert "crashed (exit -9) before its first checkpoint: it starts afresh (retry 1 of at most 2)" in \
        capsys.readouterr().out
