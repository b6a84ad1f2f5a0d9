"""O.save / O.load of a user's scene on PolyhedraContactEngine (Debian's
yade, the plugin loaded by the script itself): the loaded scene steps on
with the kernel's state as saved (the same forces, bit for bit, as the run
that was not saved and loaded), and every process exits with 0, whether the
engine stepped or not (tests/yade_cases/user_save.py)."""
import json
import os
import shutil
import subprocess

import numpy as np
import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
YADE = shutil.which("yade")
CASE = os.path.join(ROOT, "tests", "yade_cases", "user_save.py")
pytestmark = [pytest.mark.yade, pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")]
#: each mode's process is started this many times (the exit status must be 0 every time)
REPEATS = 3


def run_case(mode, path):
    """(exit status, RESULT dict or None, output tail) of one YADE process."""
    env = {k: v for k, v in os.environ.items() if k != "YADE_PREFIX"}
    env["OMP_WAIT_POLICY"] = "PASSIVE"
    out = subprocess.run([YADE, "-j1", "-n", "-x", CASE, ROOT, mode, str(path)], cwd=ROOT, capture_output=True,
                         text=True, timeout=300, env=env, stdin=subprocess.DEVNULL)
    lines = [x for x in out.stdout.splitlines() if x.startswith("RESULT ")]
    return out.returncode, (json.loads(lines[-1][len("RESULT "):]) if lines else None), \
        (out.stdout[-2000:] + out.stderr[-2000:])


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    from yade_scripts import yadeplugin

    if not yadeplugin.build()["ok"]:
        pytest.skip("the YADE plugin is not built here")
    d = tmp_path_factory.mktemp("saved")
    got = {m: [] for m in ("save", "load", "nostep", "loadonly", "saveadd", "loadadd")}
    for k in range(REPEATS):
        saved = d / f"scene{k}.yade.gz"
        for mode, path in (("save", saved), ("load", saved), ("nostep", d / f"unstepped{k}.yade.gz"),
                           ("loadonly", saved), ("saveadd", d / f"added{k}.yade.gz"),
                           ("loadadd", d / f"added{k}.yade.gz")):
            got[mode].append(run_case(mode, path))
    return got


def forces(r):
    return np.array(r["forces"], float)


def test_every_process_exits_with_0(runs):
    """Saving, loading (in the same process and in another), with the
    engine stepped before and after, or never: exit status 0 each time."""
    for mode, results in runs.items():
        for rc, res, tail in results:
            assert rc == 0 and res is not None, f"{mode}: exit {rc}\n{tail}"


def test_a_loaded_scene_steps_on_bit_for_bit(runs):
    """After O.load (of the binary file in a new process, of the XML file
    and by O.loadTmp in the same process) the scene's next 200 steps give
    every body the forces and torques of the run that went on without
    being saved, bit for bit, and the same interactions in O.interactions
    (the wall contact that ends after the save is erased there too)."""
    for (_, s, _), (_, ld, _) in zip(runs["save"], runs["load"]):
        cont = forces(s["cont"])
        # the steps compared are of contacts with shear history: grain-grain, grain-facet, grain-wall
        pairs = {(a, b) for a, b, *_ in s["before"]["inter"]}
        assert {(2, 1), (1, 0), (2, 0), (3, 0), (4, 3)} <= {(max(a, b), min(a, b)) for a, b in pairs}
        assert max(np.linalg.norm(ft) for _, _, _, ft, _ in s["cont"]["inter"]) > 0
        assert s["cont"]["counts"][0] > s["cont"]["counts"][-1]       # a contact ends after the save
        for name, r in (("O.load of the file in another process", ld["loaded"]), ("O.loadTmp", s["tmp"]),
                        ("O.load of the XML file", s["xml"])):
            assert np.array_equal(forces(r), cont), name
            assert r["inter"] == s["cont"]["inter"] and r["counts"] == s["cont"]["counts"], name
            assert r["iter"] == s["cont"]["iter"] == 400, name
        assert ld["scans"] == 1 and s["tmp_scans"] == 1


def test_a_body_added_after_the_load(runs):
    """A body appended to the loaded scene before its first step: the
    adoption's scan takes the new body and carries the saved state over by
    body id, and the next 200 steps equal, bit for bit, those of the unsaved
    run given the same body (which scans again at its next step)."""
    for (_, s, _), (_, ld, _) in zip(runs["saveadd"], runs["loadadd"]):
        assert np.array_equal(forces(ld["added"]), forces(s["added"]))
        assert ld["added"]["inter"] == s["added"]["inter"] and ld["added"]["iter"] == s["added"]["iter"] == 400
        assert (s["scans"], ld["scans"]) == (2, 1)
        assert any(5 in (a, b) for a, b, *_ in s["added"]["inter"])          # the cube is on the facet


def test_without_the_saved_state_the_forces_differ(runs):
    """The check above can fail: the same loaded scene stepped by a new
    engine (no saved state: the shear histories start from zero) differs
    from the continued run from its first step on."""
    for _, s, _ in runs["save"]:
        fresh, cont = forces(s["fresh"]), forces(s["cont"])
        assert np.any(fresh[0] != cont[0]) and not np.array_equal(fresh, cont)


def test_a_loop_of_loads_keeps_one_kernel(runs):
    """20 O.loadTmp, each stepped: the engine each load replaced is parted
    from its SceneContacts (they hold each other through C++) and its
    kernel freed, so one SceneContacts of the label is left, not 21."""
    for _, s, _ in runs["save"]:
        assert s["live"] == 1


def test_the_loaded_engine_before_its_first_step(runs):
    """O.load gives back a PolyhedraContactEngine with its label, fillEvery
    and savedState, not yet given its scan (its first step calls
    contacts.adopt); one saved before it ever stepped holds no kernel
    state and loads the same way."""
    for mode in ("load", "loadonly", "nostep"):
        for _, r, _ in runs[mode]:
            e = r["engine"]
            assert e["class"] == "PolyhedraContactEngine" and e["label"] == "grains" and e["fillEvery"] == 1
            assert not e["hasScan"] and e["saved"] > 0
    assert runs["save"][0][1]["tmp_engine"]["saved"] == runs["load"][0][1]["engine"]["saved"]


def test_a_loaded_engine_without_the_clone_on_the_path_says_why(runs, tmp_path):
    """A YADE started with YADE_PREFIX (the class known, the project's
    Python not on sys.path) loads the saved scene, and its first step
    stops with one line naming what is missing."""
    from yade_scripts import yadeplugin

    saved = runs["save"][0][1]["file"]
    script = tmp_path / "bare.py"
    script.write_text(f"O.load({saved!r})\ntry:\n    O.step()\nexcept Exception as exc:\n"
                      "    print('STOPPED ' + type(exc).__name__ + ': ' + str(exc))\n")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env.update(YADE_PREFIX=yadeplugin.status()["prefix"], OMP_WAIT_POLICY="PASSIVE")
    out = subprocess.run([YADE, "-j1", "-n", "-x", str(script)], cwd=tmp_path, capture_output=True, text=True,
                         timeout=300, env=env, stdin=subprocess.DEVNULL)
    lines = [x for x in out.stdout.splitlines() if x.startswith("STOPPED ")]
    assert out.returncode == 0 and lines == [
        "STOPPED RuntimeError: PolyhedraContactEngine (read by O.load): No module named 'yade_scripts' "
        "(the project's clone must be on PYTHONPATH)"], out.stdout[-2000:] + out.stderr[-2000:]
