"""SLURM job arrays: generate --slurm writes a script bash accepts,
one array task per table line; two tiny lines run locally with
SLURM_ARRAY_TASK_ID set, then study --collect analyses what has finished."""
import json
import math
import os
import shutil
import subprocess

import h5py
import pytest

from yade_scripts.generate import main as generate_main
from yade_scripts.presets import resolve
from yade_scripts.slurm import (COMPACTION_STEPS, CONTACTS_PER_GRAIN, PLACEMENT_FACTOR, SHEAR_STEPS,
                                US_PER_CONTACT_STEP, estimate)
from yade_scripts.study import main as study_main

YADE = shutil.which("yade")


def make(tmp_path, seeds=(1, 2, 3), *extra):
    out = tmp_path / "arr"
    assert generate_main(["--preset", "tiny", "--sample", "spheres", "--out", str(out),
                          "--seeds", *map(str, seeds), "--slurm", *extra]) == 0
    return out


def task(out, k, cwd):
    env = {k_: v for k_, v in os.environ.items() if not k_.startswith("SLURM_")}
    if k is not None:
        env["SLURM_ARRAY_TASK_ID"] = str(k)
    return subprocess.run(["bash", str(out / "slurm.sh")], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=600)


def test_script_is_valid_bash_with_one_task_per_line(tmp_path):
    out = make(tmp_path, (1, 2, 3), "--slurm-cpus", "4", "--slurm-time", "2-00:00:00")
    script = (out / "slurm.sh").read_text()
    assert subprocess.run(["bash", "-n", str(out / "slurm.sh")]).returncode == 0
    assert "#SBATCH --array=1-3" in script and "#SBATCH --cpus-per-task=4" in script
    assert "#SBATCH --time=2-00:00:00" in script
    assert "LINES=(2 3 4)" in script and "DESCS=(spheres-seed1 spheres-seed2 spheres-seed3)" in script
    assert "yade -j" in script and "-x triaxial.py" in script
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
    out = make(tmp_path, (1,))
    assert study_main(["--collect", str(out)]) == 2
    assert "no run has finished yet (1 pending)" in capsys.readouterr().err


def test_cost_model_scaling():
    """The paper preset from the measured constants, by hand: kappa 1e4 and
    safety 0.45 (sqrt(1e4/3000) x 0.3/0.45 the steps), I 1e-3 (5 x the shear steps of I = 5e-3),
    I_c 1e-2 (10^0.55 x the compaction steps of I_c = 0.1); the soft preset's
    bounding-sphere placement multiplies the compaction by its measured
    factor; the reference point gives the reference steps themselves."""
    p = resolve("paper", "polyhedra")
    e = estimate(p)
    root = math.sqrt(1e4 / 3000) * 0.3 / 0.45                # and its time step at 0.45, not 0.3
    assert e["compaction_steps"] == pytest.approx(COMPACTION_STEPS["polyhedra"] * root * 10 ** 0.55, rel=1e-12)
    assert e["shear_steps"] == pytest.approx(SHEAR_STEPS["polyhedra"] * root * 5, rel=1e-12)
    assert e["contacts"] == pytest.approx(36933 * CONTACTS_PER_GRAIN["polyhedra"])
    assert e["core_hours"] == pytest.approx(e["steps"] * e["contacts"] * US_PER_CONTACT_STEP["polyhedra"]
                                            / 3.6e9, rel=1e-12)
    q = dict(p, kappa=4e4, inertial_number=2e-3)          # 2 x sqrt(kappa), 1/2 I: the same shear
    assert estimate(q)["shear_steps"] == pytest.approx(e["shear_steps"], rel=1e-12)
    q = dict(p, safety=2 * p["safety"])                   # a time step twice as long: half the steps
    assert estimate(q)["steps"] == pytest.approx(e["steps"] / 2, rel=1e-12)
    # the default's polyhedra step at 0.45 too: the reference point (0.3) in 2/3 of its steps
    d = estimate(resolve("default", "polyhedra"))
    assert d["steps"] == pytest.approx((COMPACTION_STEPS["polyhedra"] + SHEAR_STEPS["polyhedra"]) * 0.3 / 0.45,
                                       rel=1e-12)
    assert estimate(resolve("default", "polyhedra", {"safety": 0.3}))["steps"] == pytest.approx(
        COMPACTION_STEPS["polyhedra"] + SHEAR_STEPS["polyhedra"], rel=1e-12)
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
                                             / (1 - math.exp(-0.3)), rel=1e-12)


@pytest.mark.yade
@pytest.mark.skipif(YADE is None, reason="needs Debian's yade")
def test_two_tiny_lines_run_locally_then_collect(tmp_path, capsys):
    out = make(tmp_path, (1, 2, 3))
    for k in (1, 2):
        r = task(out, k, tmp_path)            # from another folder: the script finds its own
        assert r.returncode == 0, r.stdout + r.stderr
        d = out / f"spheres-seed{k}"
        assert (d / "triaxial.log").exists() and "done in" in (d / "triaxial.log").read_text()
        with h5py.File(d / f"spheres-seed{k}.h5", "r") as f:
            assert f.attrs["complete"] == 1
            assert json.loads(f.attrs["parameters"])["seed"] == k     # the line's parameters
    again = task(out, 1, tmp_path)
    assert again.returncode == 0 and "is complete, nothing to do" in again.stdout
    # line 3 never ran: collected as pending, the two finished ones analysed
    assert study_main(["--collect", str(out)]) == 0
    err = capsys.readouterr().err
    assert "not finished: spheres-seed3 (not started)" in err
    manifest = json.loads((out / "manifest.json").read_text())
    assert [m["label"] for m in manifest["spheres"]] == ["seed 1", "seed 2"]
    assert all(m["status"] == "ok" for m in manifest["spheres"])
    assert (out / "report" / "report.md").exists()


def test_intermediate_preset_fills_a_16_core_node(tmp_path):
    """The 5000-grain preset: its parameters, a 16-line yade-batch table, and
    its cost from the model (the default S1's steps with 5000 grains' contacts)."""
    p = resolve("intermediate", "polyhedra")
    assert (p["n_particles"], p["kappa"], p["inertial_number"]) == (5000, 3000.0, 5e-3)
    assert p["compaction_friction"] == 0.5 and p["friction"] == 0.5
    # S2 at the same N and as in the default (frictionless compaction, I = 1e-3)
    for name, n in (("small", 200), ("intermediate", 5000)):
        assert resolve(name, "spheres") == {**resolve("default", "spheres"), "n_particles": n}
        assert resolve(name, "polyhedra") == {**resolve("default", "polyhedra"), "n_particles": n}
    e = estimate(p)
    steps = (COMPACTION_STEPS["polyhedra"] + SHEAR_STEPS["polyhedra"]) * 0.3 / 0.45     # the default's time step
    assert e["core_hours"] == pytest.approx(steps * 5000 * CONTACTS_PER_GRAIN["polyhedra"]
                                            * US_PER_CONTACT_STEP["polyhedra"] / 3.6e9, rel=1e-12)
    out = tmp_path / "node"
    assert generate_main(["--preset", "intermediate", "--sample", "spheres", "--out", str(out),
                          "--seeds", *map(str, range(1, 17))]) == 0
    lines = (out / "table.txt").read_text().splitlines()
    assert len(lines) == 17 and lines[16].split()[1] == "16"
    assert study_main(["--preset", "intermediate", "--out", str(tmp_path / "s"), "--ensemble", "16",
                       "--jobs", "16", "--job-threads", "0"]) == 2
