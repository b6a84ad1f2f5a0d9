"""The kernel's YADE plugin (yade_scripts/yadeplugin): its build against the
installed YADE, its path against the PyRunner path, its refusal and the
fallbacks. ``make test`` builds it first (``make kernel``)."""
import json
import os
import shutil
import subprocess

import pytest

from yade_scripts import yadeplugin

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
YADE = shutil.which("yade")
CASES = os.path.join(ROOT, "tests", "yade_cases", "plugin_cases.py")
needs_yade = pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")
pytestmark = pytest.mark.yade


def _buildable():
    """The plugin can be built here: g++ and every header package present."""
    try:
        yade = yadeplugin.find_yade()
    except yadeplugin.PluginError:
        return False
    return shutil.which("g++") is not None and not yadeplugin._missing_headers(yade)


@pytest.fixture(scope="module")
def prefix():
    """The ready plugin's YADE_PREFIX (make kernel built it; built here if not)."""
    st = yadeplugin.build()
    if not st["ok"] and not _buildable():
        pytest.skip(f"the plugin cannot be built here: {st['why']}")
    assert st["ok"], st["why"]
    return st["prefix"]


def case(mode, prefix=None, timeout=300):
    env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")
    env.pop("YADE_PREFIX", None)
    env.pop(yadeplugin.SKIP_VARIABLE, None)
    if prefix:
        env["YADE_PREFIX"] = prefix
    out = subprocess.run([YADE, "-j1", "-n", "-x", CASES, mode, ROOT], capture_output=True, text=True, env=env,
                         timeout=timeout, stdin=subprocess.DEVNULL, cwd=ROOT)
    lines = [x for x in out.stdout.splitlines() if x.startswith("RESULT ")]
    assert out.returncode == 0 and lines, out.stdout[-2000:] + out.stderr[-2000:]
    return json.loads(lines[-1][len("RESULT "):])


# ------------------------------------------------------------ the build
@needs_yade
def test_the_build_matches_the_installed_yade(prefix):
    """The sizes the build checked are the installed libyade's (read again
    here), no shared vtable differs, and the probe passed bit for bit."""
    st = yadeplugin.status()
    yade = yadeplugin.find_yade()
    assert st["ok"] and st["prefix"] == prefix
    assert st["sizes_checked"] == yadeplugin.allocated_sizes(yade["libyade"])
    lib = os.path.join(yadeplugin.prefix_libdir(prefix, yade), yadeplugin.LIBRARY_NAME)
    assert yadeplugin.vtable_mismatches(lib, yade["lib_dir"]) == []
    assert "equal bit for bit on both paths" in st["why"]
    # the prefix holds YADE's own plugins and this one, as YADE will list them
    names = set(os.listdir(yadeplugin.prefix_libdir(prefix, yade)))
    assert set(os.listdir(yade["lib_dir"])) | {yadeplugin.LIBRARY_NAME} <= names


@needs_yade
def test_the_class_sizes_come_from_libyade():
    """Sizes read off libyade.so's factories keep the classes' known
    relations: ThermalState adds members to State, GlobalEngine adds none
    to Engine, and a State holds at least its position, orientation,
    velocities and mass (two references, a Se3r, 4 vectors, 2 quaternions)."""
    yade = yadeplugin.find_yade()
    sizes = yadeplugin.allocated_sizes(yade["libyade"], ("State", "ThermalState", "Engine", "GlobalEngine"))
    assert sizes["ThermalState"] > sizes["State"] > sizes["Engine"] >= 8
    assert sizes["GlobalEngine"] == sizes["Engine"]          # GlobalEngine adds no member
    assert sizes["State"] >= 8 * (2 + 7 + 4 * 3 + 2 * 4 + 1)


@needs_yade
@pytest.mark.skipif(shutil.which("g++") is None, reason="no g++")
def test_a_vtable_of_another_size_is_found(tmp_path):
    """A library whose yade::Engine has another virtual table than YADE's
    (one virtual function): vtable_mismatches names it."""
    src = tmp_path / "fake.cpp"
    src.write_text("namespace yade { struct Engine { virtual ~Engine(); virtual void action(); }; "
                   "Engine::~Engine() {} void Engine::action() {} }\n")
    lib = tmp_path / "libfake.so"
    subprocess.run(["g++", "-shared", "-fPIC", "-o", str(lib), str(src)], check=True)
    bad = yadeplugin.vtable_mismatches(str(lib), yadeplugin.find_yade()["lib_dir"])
    assert [c for c, _, _ in bad] == ["yade::Engine"] and bad[0][1] != bad[0][2]


def test_features_decide_the_definitions():
    """Definitions follow the features, as YADE's CMakeLists.txt sets them;
    an unknown feature or another precision is refused in one line."""
    yade = {"version": "x", "features": ["OPENMP", "MPI", "LOGGER"], "real_bits": 64, "real_digits": 15}
    d = yadeplugin.defines(yade)
    assert {"YADE_OPENMP", "YADE_MPI", "YADE_BOOST_LOG", "EIGEN_DONT_ALIGN", "YADE_REAL_BIT=64"} <= set(d)
    assert "YADE_OPENGL" not in d
    assert "EIGEN_DONT_ALIGN" not in yadeplugin.defines({**yade, "features": ["VECTORIZE"]})
    with pytest.raises(yadeplugin.PluginError, match="features this build does not know: NEWTHING"):
        yadeplugin.defines({**yade, "features": ["OPENMP", "NEWTHING"]})
    with pytest.raises(yadeplugin.PluginError, match="128-bit"):
        yadeplugin.defines({**yade, "real_bits": 128})


def test_no_yade_means_no_plugin(tmp_path):
    """A folder that is not YADE's: the status says so, nothing is built,
    and the launchers' environment gets no YADE_PREFIX."""
    st = yadeplugin.build(lib_dir=str(tmp_path))
    assert not st["ok"] and "not a YADE library folder" in st["why"]
    assert "YADE_PREFIX" not in yadeplugin.environment({"PATH": os.environ.get("PATH", ""),
                                                        yadeplugin.SKIP_VARIABLE: "1"})


# ------------------------------------------------------------ the paths in YADE
@needs_yade
def test_plugin_and_pyrunner_step_the_box_alike(prefix):
    """The probe's box (27 grains, 6 walls, 30 steps): with the plugin and
    on the PyRunner path, every pose, velocity, force and torque and every
    contact equal bit for bit; the plugin's first step passed its check."""
    res = case("compare", prefix)
    assert res["ok"], res["why"]
    assert res["touching_contact_steps"] > 300


@needs_yade
def test_a_plugin_that_reads_wrong_is_refused(prefix):
    """One body moved by one ulp between the plugin's read and the check:
    refused with the body named, the kernel put back, the step redone on
    the PyRunner path, which stays; the run equals a PyRunner run that saw
    the same move, bit for bit."""
    res = case("refuse", prefix)
    assert res["path_at_start"] == "plugin"
    assert res["refused"].startswith("body 13: position read")
    assert res["path"] == "pyrunner" and res["engine"] == "PyRunner" and res["later"] == []
    assert res["calls"] == 12 and res["same_as_pyrunner_run"]


@needs_yade
def test_without_the_prefix_the_scene_loads_the_plugin_itself(prefix):
    """YADE started without YADE_PREFIX (``yade triaxial.py`` typed by hand):
    the scene loads this copy's ready build itself (yadeplugin.load), and its
    first step passes the same start-up check. (A copy without a ready build
    steps on the PyRunner and says why: tests/test_yade_scenes.py.)"""
    res = case("absent")
    assert res["path"] == "plugin" and res["engine"] == "PolyhedraKernelEngine" and res["calls"] == 12
    assert res["note"] == "its first step read and added exactly what YADE's Python sees"


@needs_yade
def test_a_refused_step_says_why(prefix):
    """A NaN position: the plugin adds no force and names the cause in the
    kernel's words (the scene then stops with it)."""
    res = case("error", prefix)
    assert res["path"] == "plugin" and res["before"] is None and res["code"] == -2
    assert res["after"] == "particle positions are not finite"
    assert res["touch_steps_unchanged"] and res["force_on_nudged"] == [0.0, 0.0, 0.0]
