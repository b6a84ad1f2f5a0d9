"""The numpy parts of the YADE scene: presets, servo, sample, time step,
the tangential-law kernel and the generator (no YADE needed)."""
import os
import re

import numpy as np
import pytest

from yade_scripts.scene import sample, servo, timestep
from yade_scripts.campaign.generate import generate, render_scene
from yade_scripts.campaign.presets import PRESETS, ConfigError, resolve
from yade_scripts.scene.tangential import update_shear


def test_presets_resolve_and_reject_bad_config():
    for preset in PRESETS:
        for kind in ("polyhedra", "spheres"):
            p = resolve(preset, kind)
            assert p["sample"] == kind and p["n_particles"] >= 2
    assert resolve("paper", "polyhedra")["n_particles"] == 36933
    assert resolve("paper", "spheres")["n_particles"] == 19998
    # prepared as published (solid fraction about 0.6): polyhedra compacted
    # at the shear friction, spheres frictionless
    assert resolve("paper", "polyhedra")["compaction_friction"] == 0.5
    assert resolve("paper", "spheres")["compaction_friction"] == 0.0
    assert resolve("paper", "polyhedra")["safety"] == 0.45       # docs/front.md, the time step
    # the default's polyhedra and every preset built on it step at 0.45 too;
    # the spheres (not swept), the soft preset and the tests' tiny one at 0.3
    for name in ("default", "intermediate", "loose", "dense", "matched"):
        assert resolve(name, "polyhedra")["safety"] == 0.45
    for name in PRESETS:
        assert resolve(name, "spheres")["safety"] == 0.3
    assert resolve("soft", "polyhedra")["safety"] == resolve("tiny", "polyhedra")["safety"] == 0.3
    with pytest.raises(ConfigError, match="unknown parameter 'kapa' .*kappa"):
        resolve("tiny", "spheres", {"kapa": 3})
    with pytest.raises(ConfigError, match="friction = -1.0 is outside"):
        resolve("tiny", "spheres", {"friction": "-1"})
    with pytest.raises(ConfigError, match="n_particles = 'many' is not an integer"):
        resolve("tiny", "spheres", {"n_particles": "many"})
    with pytest.raises(ConfigError, match="n_particles = 2.5 is not an integer"):
        resolve("tiny", "spheres", {"n_particles": 2.5})
    # a fraction of any numeric type is refused (float32 and Decimal were truncated to 40),
    # a whole one of any type taken; a true/false value is no count
    import decimal
    import fractions

    import numpy as np
    for half in (np.float32(40.5), decimal.Decimal("40.5"), fractions.Fraction(81, 2), "40.5"):
        with pytest.raises(ConfigError, match="is not an integer"):
            resolve("tiny", "spheres", {"n_particles": half})
    for whole in (np.float32(40), decimal.Decimal("40"), fractions.Fraction(80, 2), "4e1", 40.0, np.int16(40)):
        assert resolve("tiny", "spheres", {"n_particles": whole})["n_particles"] == 40
    assert resolve("tiny", "spheres", {"seed": "1234567890123456789"})["seed"] == 1234567890123456789
    for bad in (True, np.bool_(True), float("nan"), float("inf"), None):
        with pytest.raises(ConfigError, match="n_particles = .* is not an integer"):
            resolve("tiny", "spheres", {"n_particles": bad})
    with pytest.raises(ConfigError, match="unknown preset"):
        resolve("huge", "spheres")
    with pytest.raises(ConfigError, match="dump_strain"):
        resolve("tiny", "spheres", {"dump_strain": 0.5})


def test_render_scene_sets_every_parameter():
    p = resolve("default", "polyhedra", {"kappa": "2500", "seed": "7"})
    text = render_scene(p)
    assert "    kappa=2500.0," in text and "    seed=7," in text
    assert "    sample='polyhedra'," in text
    compile(text, "triaxial.py", "exec")


def test_the_bare_scene_is_the_default_preset():
    """The template's parameter block is the one rendered from the
    parameter table's defaults, which are the default preset's S1: running
    the bare triaxial.py is the default experiment."""
    from yade_scripts.scene.parameters import BLOCK_END, BLOCK_START, DEFAULTS, PARAMETERS, render_block

    text = open(os.path.join(os.path.dirname(__file__), "..", "yade_scripts", "scene", "triaxial.py")).read()
    block = text[text.index(BLOCK_START):text.index(BLOCK_END)]
    assert block == render_block(DEFAULTS)
    assert resolve("default", "polyhedra") == DEFAULTS
    # read by the scene's body, or by its controller from the scene's parameters (p["name"])
    body = text[text.index(BLOCK_END):]
    controller = open(os.path.join(os.path.dirname(__file__), "..", "yade_scripts", "scene", "controller.py")).read()
    unused = [q.name for q in PARAMETERS if not re.search(rf"\b{q.name}\b", body)
              and f'p["{q.name}"]' not in controller and f"p['{q.name}']" not in controller]
    assert not unused, f"parameters the scene never reads: {unused}"


def test_a_batch_table_is_checked_before_any_run(tmp_path):
    from yade_scripts.launch.batch import read_table

    out = tmp_path / "run"
    generate(str(out), "tiny", "spheres", seeds=[3, 4])
    assert [r["seed"] for _, r in read_table(str(out))] == ["3", "4"]
    table = out / "table.txt"
    table.write_text("description seed kapa out\na 1 300.0 'a.h5'\n")
    with pytest.raises(ConfigError, match=r"table.txt line 2: unknown parameter 'kapa' \(did you mean 'kappa'\?\)"):
        read_table(str(out))
    table.write_text("description seed kappa out\na 1 -3.0 'a.h5'\n")
    with pytest.raises(ConfigError, match="line 2: kappa = -3.0 is outside"):
        read_table(str(out))
    table.write_text("description seed kappa out\na 1 stiff 'a.h5'\n")
    with pytest.raises(ConfigError, match="line 2: kappa = stiff is not a Python literal"):
        read_table(str(out))


def test_generate_run_folder(tmp_path):
    out = tmp_path / "run"
    generate(str(out), "tiny", "spheres", seeds=[3, 4])
    assert (out / "triaxial.py").exists() and (out / "pkg" / "postproc" / "schema.py").exists()
    lines = (out / "table.txt").read_text().splitlines()
    assert lines[0].split() == ["description", "seed", "out"] and len(lines) == 3
    with pytest.raises(ConfigError, match="already holds a run"):
        generate(str(out), "tiny", "spheres")
    with pytest.raises(ConfigError, match="shape library .* not found"):
        generate(str(tmp_path / "p"), "tiny", "polyhedra", library=str(tmp_path / "none.h5"))


def test_servo_closes_walls_below_target_and_opens_above():
    L = np.array([0.1, 0.1, 0.2])
    F = np.zeros((6, 3))
    sig = servo.wall_stresses(F, L)
    rates = servo.servo_rates(sig, 1e4, 0.5, 5.0)
    assert np.allclose(rates, 0.5)                       # empty box: full speed inwards
    v = servo.wall_velocities(rates, L)
    assert v[0, 0] > 0 and v[1, 0] < 0 and v[4, 2] > 0 and v[5, 2] < 0
    # stress exactly at target: walls at rest; far above: full speed outwards
    A = np.array([L[1] * L[2], L[0] * L[2], L[0] * L[1]])
    for a in range(3):
        F[2 * a, a], F[2 * a + 1, a] = -1e4 * A[a], 1e4 * A[a]
    assert np.allclose(servo.wall_stresses(F, L), 1e4)
    assert np.allclose(servo.servo_rates(servo.wall_stresses(F, L), 1e4, 0.5, 5.0), 0)
    assert np.allclose(servo.servo_rates(3 * servo.wall_stresses(F, L), 1e4, 0.5, 5.0), -0.5)


def test_place_spheres_without_overlap():
    rng = np.random.default_rng(0)
    d = np.repeat([0.025, 0.0375, 0.05], [50, 34, 16])
    box = sample.box_for(d, 0.25, 2.0)
    assert box[2] == pytest.approx(2 * box[0])
    pos = sample.place_spheres(d, box, rng)
    from scipy.spatial.distance import pdist, squareform

    gap = squareform(pdist(pos)) - (d[:, None] + d[None, :]) / 2
    np.fill_diagonal(gap, 1)
    assert gap.min() >= 0
    assert np.all(pos - d[:, None] / 2 >= -1e-12) and np.all(pos + d[:, None] / 2 <= box + 1e-12)
    with pytest.raises(RuntimeError, match="no room|larger than the box"):
        sample.place_spheres(d, box / 3, rng)
    # too dense for sequential addition: the box grows until everything fits
    box2, pos2 = sample.place_in_box(d, 0.33, 2.0, np.random.default_rng(2))
    assert np.all(box2 >= sample.box_for(d, 0.33, 2.0) - 1e-15)
    assert np.isfinite(pos2).all()


def test_random_quaternions_are_uniform_rotations():
    rng = np.random.default_rng(1)
    q = sample.random_quaternions(20000, rng)
    assert np.allclose(np.linalg.norm(q, axis=1), 1)
    from postproc.axes import quaternion_matrices

    R = quaternion_matrices(q)
    assert np.allclose(np.einsum("nij,nkj->nik", R, R), np.eye(3), atol=1e-12)
    # uniform rotations send e_z uniformly on the sphere: <z^2> = 1/3, se = sqrt(4/45/N)
    z = R[:, :, 2]
    assert abs(np.mean(z[:, 2] ** 2) - 1 / 3) < 5 * np.sqrt(4 / 45 / len(z))


def test_time_step_scaling():
    m, k = np.array([1.0, 4.0]), np.array([100.0, 100.0])
    assert timestep.critical_time_step(m, k) == pytest.approx(0.1)
    cube = np.array([[x, y, z] for x in (-.5, .5) for y in (-.5, .5) for z in (-.5, .5)])
    # unit cube: V = 1, I = 1/6, r_k^2 = 0.5 -> I/r^2 = 1/3
    assert timestep.rotational_mass(1.0, [1 / 6] * 3, cube) == pytest.approx(1 / 3)
    # I = rate d sqrt(rho/p)
    assert timestep.inertial_strain_rate(1e-3, 0.03, 2700, 1e4) * 0.03 * np.sqrt(0.27) == pytest.approx(1e-3)


def test_tangential_kernel_elastic_then_coulomb():
    n = np.array([[0.0, 0.0, 1.0]] * 3)
    zero = np.zeros((3, 3))
    inc = np.array([[1e-6, 0, 0], [-1e-6, 0, 0], [0, 0, 0]])
    fs = np.zeros((3, 3))
    kt, mu, fn = np.full(3, 1e5), np.full(3, 0.5), np.full(3, 2.0)
    for _ in range(5):
        fs, slide = update_shear(fs, n, zero, zero, inc, kt, mu, fn)
    assert np.allclose(fs[:, 0], [-0.5, 0.5, 0.0])      # 5 x 1e5 x 1e-6, history per contact
    assert not slide.any()
    for _ in range(20):
        fs, slide = update_shear(fs, n, zero, zero, inc, kt, mu, fn)
    assert np.allclose(fs[:, 0], [-1.0, 1.0, 0.0])      # Coulomb cap mu fn
    assert slide.tolist() == [True, True, False]
    # a tilted normal: the shear force is projected back into the tangent plane
    tilt = np.array([[0.0, np.sin(0.1), np.cos(0.1)]] * 3)
    fs2, _ = update_shear(np.array([[0.0, 0.3, 0.0]] * 3), tilt, zero, zero, zero, kt, mu, fn)
    assert np.allclose(np.einsum("ij,ij->i", fs2, tilt), 0)


def test_study_sets_aside_runs_made_with_other_parameters(tmp_path):
    from yade_scripts.campaign.presets import ConfigError
    from yade_scripts.campaign.study import _set_aside_if_changed, finished

    folder = tmp_path / "spheres"
    generate(str(folder), "tiny", "spheres")
    assert not finished(str(folder))                    # generated, not run
    _set_aside_if_changed(str(folder), "tiny", "spheres", None)
    assert folder.exists()                              # same parameters: kept
    with pytest.raises(ConfigError, match=r"spheres: a run folder of other parameters \(kappa\); nothing renamed"):
        _set_aside_if_changed(str(folder), "tiny", "spheres", {"kappa": 500})    # not asked: refused
    assert folder.exists() and not (tmp_path / "spheres.old-1").exists()
    _set_aside_if_changed(str(folder), "tiny", "spheres", {"kappa": 500}, set_aside=True)
    assert not folder.exists() and (tmp_path / "spheres.old-1").exists()


def test_a_parameter_missing_from_an_older_run_counts_as_its_default():
    """A run made before a parameter existed was made with what its default
    does, so it is not set aside for it; it is when the parameter is asked
    for with another value."""
    from yade_scripts.scene.parameters import DEFAULTS, changed

    wanted = {"preset": "intermediate", **resolve("intermediate", "polyhedra")}
    older = {k: v for k, v in wanted.items() if k != "compaction_gain"}
    assert wanted["compaction_gain"] == DEFAULTS["compaction_gain"] == 0.0
    assert changed(older, wanted) == []
    assert changed(older, {**wanted, "compaction_gain": 0.2}) == ["compaction_gain"]
    assert changed(older, {**wanted, "kappa": "3000"}) == []          # compared as set, "3000" is 3000.0
    assert changed({**older, "unknown": 1}, wanted) == ["unknown"]    # not a parameter: still compared


def test_presets_choose_the_contact_engine_and_the_study_its_threads():
    """Polyhedra default to the compiled kernel, which the single-run study
    starts with every core (yade -jN); spheres and the stock contacts run on
    one thread (stock polyhedra crashed with several)."""
    import os

    from yade_scripts.campaign.study import _threads

    p = resolve("default", "polyhedra")
    assert p["contact_engine"] == "kernel" and p["kernel_threads"] == 0 and p["verlet_skin"] == 0.1
    assert _threads("polyhedra", "default", None) == (os.cpu_count() or 1)
    assert _threads("polyhedra", "default", {"contact_engine": "yade", "placement": "spheres"}) == 1
    assert _threads("spheres", "default", None) == 1
    # the exact placement needs the kernel's frame of the grains
    with pytest.raises(ConfigError, match="placement 'grains' needs contact_engine 'kernel'"):
        resolve("default", "polyhedra", {"contact_engine": "yade"})
    with pytest.raises(ConfigError, match="contact_engine must be one of"):
        resolve("default", "polyhedra", {"contact_engine": "cgal"})


def test_a_study_on_a_folder_of_other_parameters_refuses_and_renames_nothing(tmp_path, capsys, shape_library):
    """``python -m yade_scripts.campaign.study`` on a study folder whose ensemble was
    made with other parameters exits 2 in one line and renames nothing; the
    other sample's folder is not touched either."""
    from yade_scripts.campaign.study import main

    out = tmp_path / "study"
    generate(str(out / "polyhedra-ensemble"), "tiny", "polyhedra", seeds=[1, 2], library=shape_library)
    generate(str(out / "spheres-ensemble"), "tiny", "spheres", {"kappa": 500}, seeds=[1, 2])
    table = (out / "polyhedra-ensemble" / "table.txt").read_text()
    assert main(["--preset", "tiny", "--out", str(out), "--ensemble", "3", "--no-figures",
                 "--library", shape_library]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "spheres-ensemble: a run folder of other parameters (kappa); nothing renamed" in err[0]
    assert "SET_ASIDE=1" in err[0]
    assert sorted(p.name for p in out.iterdir() if p.is_dir()) == ["polyhedra-ensemble", "spheres-ensemble"]
    assert (out / "polyhedra-ensemble" / "table.txt").read_text() == table          # not rewritten for 3 seeds
