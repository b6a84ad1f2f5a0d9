"""The YADE examples of examples/ at a tiny size (Debian's yade, the plugin
loaded by the scripts themselves): they run, write what they say, and their
numbers obey what they impose."""
import os
import re
import shutil
import subprocess

import numpy as np
import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
YADE = shutil.which("yade")
pytestmark = [pytest.mark.yade, pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")]


def run_example(name, args, cwd):
    from yade_scripts import yadeplugin

    if not yadeplugin.build()["ok"]:
        pytest.skip("the YADE plugin is not built here")
    env = {k: v for k, v in os.environ.items() if k != "YADE_PREFIX"}
    env["OMP_WAIT_POLICY"] = "PASSIVE"
    out = subprocess.run([YADE, "-j1", "-n", "-x", os.path.join(ROOT, "examples", name), *map(str, args)], cwd=cwd,
                         capture_output=True, text=True, timeout=900, env=env, stdin=subprocess.DEVNULL)
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    return out.stdout


def test_ballast_box(tmp_path):
    """24 grains, 3 load cycles: one settlement line per cycle, and once
    seated the box carries the grains' and the sleeper's weight and the
    load (static equilibrium, averaged over 0.05 s, within 10 %)."""
    text = run_example("ballast_box.py", [24, 3], tmp_path)
    m = re.search(r"seated: box reaction ([-0-9.e+]+) N, weight of ballast and sleeper and loadMin ([0-9.e+]+) N", text)
    assert m, text[-2000:]
    assert float(m.group(1)) == pytest.approx(float(m.group(2)), rel=0.1)
    rows = np.loadtxt(tmp_path / "ballast-settlement.txt", ndmin=2)
    assert rows[:, 0].tolist() == [1, 2, 3]
    assert np.all(np.abs(rows[:, 1]) < 0.01)                     # m: the sleeper stays on the ballast
    assert np.all(rows[:, 2] > 24)                                  # the contacts are in O.interactions


def test_triax_polyhedra(tmp_path):
    """24 grains, at most 3000 steps a stage: the recorded axial strain is
    the imposed rate times the elapsed time (the walls' kinematics), the
    lateral stresses stay at the 10 kPa goal on average, and the porosity
    fell below the loose cloud's."""
    text = run_example("triax_polyhedra.py", [24, 3000], tmp_path)
    data = np.genfromtxt(tmp_path / "results_triax_polyhedra.txt", names=True, deletechars="")
    assert len(data) > 50
    t = data["t"] - data["t"][0]
    e22 = data["e22"] - data["e22"][0]
    np.testing.assert_allclose(e22, 0.02 * t, rtol=1e-3, atol=1e-9)
    assert np.mean(data["s11"]) == pytest.approx(1e4, rel=0.05)
    assert np.mean(data["s33"]) == pytest.approx(1e4, rel=0.05)
    assert np.all(data["contacts"] > 0)
    first = float(re.search(r"Isotropic state .*porosity ([0-9.]+)", text).group(1))
    assert data["porosity"][-1] < first


def test_clump_deposition(tmp_path):
    """8 clumps a wave, 2 waves: each wave appended mid-run is picked up (a
    scan each), no interaction between members of one clump, the pile grows,
    and at rest the box carries the clumps' weight (static equilibrium,
    averaged over 0.05 s, within 10 % as for the ballast box)."""
    text = run_example("clump_deposition.py", [8, 2], tmp_path)
    m = re.search(r"at rest: box reaction ([-0-9.e+]+) N, weight of the clumps ([0-9.e+]+) N", text)
    assert m, text[-2000:]
    assert float(m.group(1)) == pytest.approx(float(m.group(2)), rel=0.1)
    assert "wave 2: 16 clumps" in text and re.search(r"wave 2: .* 2 scans", text)
    rows = np.loadtxt(tmp_path / "clump-deposit.txt", ndmin=2)
    assert rows[:, 0].tolist() == [1, 2] and rows[:, 1].tolist() == [8, 16]
    assert rows[1, 2] > rows[0, 2] and np.all(rows[:, 3] > 0)
    assert np.all(rows[:, 4] == 0)                                 # no contact within a clump
