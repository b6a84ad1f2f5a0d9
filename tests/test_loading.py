"""The scene's loading program and run attempt without YADE: the servo
reaches the isotropic state of a known elastic box, the shear schedule takes
its snapshots at the stated strains and stops at the final one, a
checkpointed program continues exactly as the uninterrupted one, and the
attempt starts afresh, resumes or stops as stated."""
import json
import os
import signal

import numpy as np
import pytest

from postproc import schema
from yade_scripts.runs import attempt, checkpoint
from yade_scripts.scene.loading import ISO_CHECK_EVERY, LOG_HEADER, TriaxialLoading

SIGMA0, K, LF = 1e4, 3e6, np.array([0.1, 0.1, 0.2])   # Pa, Pa per unit log strain, stress-free box (m)
DT = 1e-5


def elastic_stress(L):
    """A box of bulk stiffness K that carries no stress until it is smaller
    than LF: sigma_a = K ln(LF_a / L_a), compression positive."""
    return K * np.maximum(np.log(LF / L), 0.0)


def step_box(L, vel, dt=DT):
    """The box after one step of wall velocities (6, 3): each axis shrinks
    by the closing speeds of its two walls."""
    return np.array([L[a] - (vel[2 * a, a] - vel[2 * a + 1, a]) * dt for a in range(3)])


def program(**kw):
    p = dict(sigma0=SIGMA0, rate_compaction=2.0, rate_shear=1.0, wall_speed=0.0, servo_gain=10.0,
             servo_time=0.01, kappa=300.0, dt=DT, iso_tolerance=0.01, unbalanced_tolerance=0.02,
             dump_strain=0.01, final_strain=0.05)
    p.update(kw)
    return TriaxialLoading(**p)


def compact(prog, L, max_steps=200_000):
    for step in range(1, max_steps):
        sig = elastic_stress(L)
        if prog.isotropic(step, sig, lambda: 0.0):
            return step, L, sig
        L = step_box(L, prog.compaction_velocities(sig, L))
    raise AssertionError("the servo never reached the isotropic state")


def test_compaction_reaches_sigma0_on_every_axis():
    prog = program()
    step, L, sig = compact(prog, 1.3 * LF)
    assert step % ISO_CHECK_EVERY == 0
    assert np.all(np.abs(sig - SIGMA0) < 0.01 * SIGMA0)
    # the stable gain caps kappa * rate * gain * dt at 0.2
    assert prog.stable_gain(1e9) == pytest.approx(0.2 / (300.0 * 1e9 * DT), rel=1e-15)
    assert prog.stable_gain(1e-9) == 10.0
    # a large unbalanced force keeps it compacting
    assert not prog.isotropic(step, sig, lambda: 1.0)
    assert not prog.isotropic(step + 1, sig, lambda: 0.0)


def test_the_compaction_gain_drives_the_compaction_only():
    """compaction_gain replaces servo_gain in the compaction (where the same
    cap still applies) and leaves the shear's servo as it was; 0 means
    servo_gain."""
    L, sig = 1.1 * LF, np.array([0.95, 0.9, 0.5]) * SIGMA0
    own = program(compaction_gain=0.2)
    np.testing.assert_array_equal(own.compaction_velocities(sig, L),
                                  program(servo_gain=0.2).compaction_velocities(sig, L))
    np.testing.assert_array_equal(program(compaction_gain=0.0).compaction_velocities(sig, L),
                                  program().compaction_velocities(sig, L))
    # rate 2/s, the error (0.05, 0.1, 0.5): 0.2 e + the integral's first step, closing at rate L/2
    e = np.array([0.05, 0.1, 0.5])
    J = np.where(e < 0.2, 0.2 * e * DT / (0.01 / 2.0), 0.0)
    expected = 2.0 * (0.2 * e + J) * L / 2
    np.testing.assert_allclose(program(compaction_gain=0.2).compaction_velocities(sig, L)[[0, 2, 4], [0, 1, 2]],
                               expected, rtol=1e-14)
    assert program(compaction_gain=1e9).stable_gain(2.0, 1e9) == pytest.approx(0.2 / (300.0 * 2.0 * DT))
    plain = program()
    for prog in (own, plain):
        prog.start_shear(L, 0.6, 0, 0.0)
    np.testing.assert_array_equal(own.shear_velocities(sig, 0.99 * L), plain.shear_velocities(sig, 0.99 * L))


def test_shear_moves_the_top_wall_holds_the_sides_and_snapshots_on_schedule():
    prog = program()
    _, L, _ = compact(prog, 1.3 * LF)
    v_top = prog.start_shear(L, 0.6, 1234, 5.0)
    assert v_top == pytest.approx(1.0 * L[2], rel=1e-15)          # rate_shear times the height
    assert prog.stage == "shear" and prog.phi_iso == 0.6 and prog.shear_start_step == 1234
    eps_at_snapshot = []
    for _ in range(200_000):
        sig = elastic_stress(L)
        vel = prog.shear_velocities(sig, L)
        assert np.all(vel[4] == 0) and tuple(vel[5]) == (0.0, 0.0, -v_top)
        if prog.snapshot_due():
            eps_at_snapshot.append(prog.eps_1)
        if prog.finished():
            break
        L = step_box(L, vel)
    assert prog.stage == "done"
    # one snapshot per dump_strain, the first at dump_strain, the last at
    # the end; each within one step's strain of its target
    d_eps = v_top * DT / L[2]
    np.testing.assert_allclose(eps_at_snapshot, [0.01, 0.02, 0.03, 0.04, 0.05], atol=1.01 * d_eps)
    assert prog.eps_1 == pytest.approx(np.log(prog.L0[2] / L[2]), rel=1e-14)
    assert prog.seconds_left(L, 100.0) <= 0
    # the lateral servo held its axes near sigma0 (the elastic box has no
    # Poisson coupling, so the sides stay where they were)
    assert np.all(np.abs(elastic_stress(L)[:2] - SIGMA0) < 0.01 * SIGMA0)


def test_a_fixed_wall_speed_overrides_the_inertial_rate():
    prog = program(wall_speed=0.25)
    _, L, _ = compact(prog, 1.3 * LF)
    assert prog.start_shear(L, 0.6, 1, 0.0) == 0.25


def test_a_restored_program_continues_exactly_as_the_uninterrupted_one():
    a = program()
    _, L, _ = compact(a, 1.3 * LF)
    a.start_shear(L, 0.6, 1, 0.0)
    for _ in range(500):
        L = step_box(L, a.shear_velocities(elastic_stress(L), L))
    saved = json.loads(json.dumps(a.saved()))     # through JSON, as in a checkpoint
    b = program()
    b.restore(saved)
    La = Lb = L
    for _ in range(2000):
        va, vb = a.shear_velocities(elastic_stress(La), La), b.shear_velocities(elastic_stress(Lb), Lb)
        assert np.array_equal(va, vb) and a.snapshot_due() == b.snapshot_due()
        La, Lb = step_box(La, va), step_box(Lb, vb)
    assert np.array_equal(La, Lb) and a.saved() == b.saved()
    # before shear the strain-related values are None and survive the trip too
    c = program()
    c.restore(json.loads(json.dumps(program().saved())))
    assert c.L0 is None and c.stage == "compaction" and np.array_equal(c.strains(LF), np.zeros(3))


def test_log_row_matches_its_header():
    prog = program()
    _, L, _ = compact(prog, 1.3 * LF)
    prog.start_shear(L, 0.6, 1, 0.0)
    prog.count(100, 40, 200)
    assert (prog.contact_steps, prog.interaction_steps) == (8000, 20000)
    sig = np.array([1e4, 1e4, 2e4])
    row = prog.log_row(7, 0.5, sig, L * np.array([1, 1, 0.9]), 0.6, 0.01, 100, 40, 12.5).rstrip("\n").split(",")
    head = LOG_HEADER.rstrip("\n").split(",")
    assert len(row) == len(head)
    values = dict(zip(head, row))
    assert float(values["q_over_p"]) == pytest.approx((2e4 - 1e4) / (2e4 + 2e4), rel=1e-5)
    assert float(values["eps_1"]) == pytest.approx(-np.log(0.9), rel=1e-5)
    assert values["stage"] == "shear" and values["n_contacts"] == "40"


class FakeEngine:
    def __init__(self, label, exec_ns):
        self.label, self.execTime = label, exec_ns


class FakeO:
    """What an Attempt touches of YADE's Omega outside a run."""
    iter, stopAtIter, time = 41, 0, 0.0
    engines = [FakeEngine("newton", 0.5e9), FakeEngine("kernel", 1.0e9)]

    def load(self, path):
        assert os.path.exists(path)


def new_attempt(dump, params, resume, said):
    """An Attempt, the process's SIGTERM handler put back afterwards."""
    before = signal.getsignal(signal.SIGTERM)
    try:
        return attempt.Attempt(FakeO(), dump, params, 0.0, resume=resume, say=said.append)
    finally:
        signal.signal(signal.SIGTERM, before)


def test_attempt_starts_afresh_resumes_or_finds_the_run_complete(tmp_path):
    from yade_scripts.runs.runstate import RunFiles

    dump = str(tmp_path / "run.h5")
    files = RunFiles(dump)
    params = {"seed": 1, "kappa": 150.0}
    said = []
    # leftovers of an unfinished attempt without a checkpoint: removed
    for f in (files.log_csv, files.info, files.checkpoint + ".prev"):
        open(f, "w").close()
    os.makedirs(files.parts)
    run = new_attempt(dump, params, True, said)
    assert not run.complete and run.resumed is None
    assert not any(os.path.exists(p) for p in files.written_by_an_attempt())
    assert "removed the unfinished attempt" in said[-1]
    # a finished dump: nothing to do
    w = schema.DumpWriter(dump, "spheres", {"seed": 1})
    w.close(pack=True)
    assert new_attempt(dump, params, True, said).complete
    os.remove(dump)
    # a checkpoint of this run and its dump: resumed
    w = schema.DumpWriter(dump, "spheres", {"seed": 1})
    assert w.n_snapshots == 0
    checkpoint.save(files.checkpoint, {"fingerprint": checkpoint.fingerprint(params), "n_snapshots": 0, "step": 10,
                                       "dump_parameters": w.attrs["parameters"]}, {}, {"scene": b"yade"})
    run = new_attempt(dump, params, True, said)
    assert not run.complete and run.resumed.step == 10 and run.resumed.writer.n_snapshots == 0
    assert run.resumed.scene == b"yade" and run.resumed.dump_parameters == {"seed": 1}
    run.resumed.writer.close(pack=False, complete=False)
    # another run's checkpoint (other parameters) is not used
    run = new_attempt(dump, {**params, "kappa": 300.0}, True, said)
    assert run.resumed is None and "other parameters" in said[-2] and not os.path.exists(files.checkpoint)
    # resume=False starts afresh even with a checkpoint
    w = schema.DumpWriter(dump, "spheres", {"seed": 1})
    checkpoint.save(files.checkpoint, {"fingerprint": checkpoint.fingerprint(params), "n_snapshots": 0, "step": 10,
                                       "dump_parameters": w.attrs["parameters"]}, {}, {"scene": b"yade"})
    w.close(pack=False, complete=False)
    run = new_attempt(dump, params, False, said)
    assert run.resumed is None and not run.complete
    assert not os.path.exists(files.checkpoint)


def test_progress_lines_and_the_run_history(tmp_path):
    p = attempt.Progress(0.0)
    p.restart(100)
    sps = p.tick(300)
    assert sps is not None and sps > 0 and p.steps_per_second == sps and p.last_step == 300
    assert attempt.Progress(1e9).tick(10) is None

    said = []
    r = new_attempt(str(tmp_path / "run.h5"), {"seed": 1}, True, said)
    # what the checkpoint says the earlier attempts took, and the scene's state put back
    meta = {"wall_seconds": 7.0, "engine_seconds": {"newton": 2.0, "gone": 3.0}, "resumes": [{"step": 1}],
            "why": "SIGTERM",
            "x": 1, "step": 41}
    restored = []
    r.resumed = attempt.Resumed(str(tmp_path / "run.ckpt"), meta, {"a": np.zeros(2)}, b"scene", None)
    r.writer = r.resumed.writer = schema.DumpWriter(str(tmp_path / "run.h5"), "spheres", {})
    r.restore(lambda state, arrays: restored.append((state, sorted(arrays))), lambda: ("shear", 0.1))
    assert restored == [(meta, ["a"])] and "resumed from run.ckpt at step 41 (shear" in said[-1]
    h = r.history()
    assert h["engine_seconds"] == {"newton": 2.5, "kernel": 1.0, "gone": 3.0}     # an engine of earlier attempts only
    r.O.engines = [FakeEngine("", 0.25e9), FakeEngine("", 0.5e9)]                  # two unlabelled of one class: summed
    assert r.engine_seconds() == {"newton": 2.0, "gone": 3.0, "FakeEngine": 0.75}
    r.timing = False                                                                # an attempt without timing
    assert r.engine_seconds() == {"newton": 2.0, "gone": 3.0}
    r.O.engines = FakeO.engines
    r.timing = True
    assert h["resumes"][0] == {"step": 1} and h["resumes"][1]["step"] == 41
    assert h["resumes"][1]["written_because"] == "SIGTERM" and h["wall_seconds"] >= 7.0
    r.writer.close(pack=False, complete=False)
    r._pause_request = True
    r.end_of_step()
    assert r.O.stopAtIter == 42 and not r._pause_request
    r._on_term(15, None)
    assert r.terminated and r._run_until_stop() is True


def test_the_approach_runs_faster_until_half_the_target_stress_then_never_again():
    """approach_factor F: the walls close at F x the compaction rate while the
    mean wall stress has never reached sigma0 / 2, at the compaction rate
    from then on, even if the stress falls back; the latch survives a
    checkpoint; the isotropic state is the same as without the approach."""
    from yade_scripts.scene.loading import APPROACH_STRESS

    L = LF * 1.5
    slow, fast = program(), program(approach_factor=3.0)
    v_slow = slow.compaction_velocities(np.zeros(3), L)
    v_fast = fast.compaction_velocities(np.zeros(3), L)
    np.testing.assert_allclose(v_fast, 3.0 * v_slow, rtol=1e-15)         # far below sigma0: full speed, 3 x
    assert not fast.approached
    fast.compaction_velocities(np.full(3, APPROACH_STRESS * SIGMA0), L)
    assert fast.approached
    again = fast.compaction_velocities(np.zeros(3), L)                    # stress falls back: stays slow
    np.testing.assert_allclose(again, slow.compaction_velocities(np.zeros(3), L), rtol=1e-15)
    copy = program(approach_factor=3.0)
    copy.restore(json.loads(json.dumps(fast.saved())))
    assert copy.approached
    assert program(approach_factor=1.0).approached                        # no approach at all
    # both reach the isotropic state of the elastic box, the fast one in fewer steps
    steps = {}
    for name, p in (("slow", program()), ("fast", program(approach_factor=3.0))):
        L = LF * 1.5
        for n in range(1, 200_000):
            sig = elastic_stress(L)
            L = step_box(L, p.compaction_velocities(sig, L))
            if p.isotropic(n, sig, lambda: 0.0):
                break
        steps[name] = n
        np.testing.assert_allclose(elastic_stress(L), SIGMA0, rtol=0.011)
    assert steps["fast"] < steps["slow"]
