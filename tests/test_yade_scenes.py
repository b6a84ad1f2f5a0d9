"""YADE runs (Debian's yade): the tangential law, the tiny triaxial runs of S1
and S2, killed and blown-up runs. Skipped when yade is not installed
(``make test`` installs it)."""
import csv
import json
import os
import shutil
import signal
import subprocess
import time

import h5py
import numpy as np
import pytest

from postproc.contactset import resolve
from postproc.schema import DumpReader
from postproc.stress import contact_stress, wall_stress
from yade_scripts.campaign.generate import generate
from yade_scripts.runs.host import SIMD_FLAGS
from yade_scripts.launch.pool import yade_env
from yade_scripts.scene.servo import wall_stresses

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
YADE = shutil.which("yade")


def yade_numpy():
    """numpy's version on the Python YADE runs on (its script's #! line)."""
    with open(YADE) as fh:
        interpreter = fh.readline()[2:].split()[0]
    return subprocess.run([interpreter, "-c", "import numpy; print(numpy.__version__)"], capture_output=True,
                          text=True, check=True).stdout.strip()


pytestmark = [pytest.mark.yade,
              pytest.mark.skipif(YADE is None, reason="Debian yade is not installed")]
SIGMA0 = 1.0e4


def run_yade(args, cwd, timeout=600):
    return subprocess.run([YADE, "-n", "-x", *args], cwd=cwd, capture_output=True, text=True,
                          timeout=timeout, stdin=subprocess.DEVNULL)


# ------------------------------------------------------------ tangential law
def cube_pairs(mode):
    out = run_yade([os.path.join(ROOT, "tests", "yade_cases", "cube_pairs.py"), mode, ROOT], cwd=ROOT)
    assert out.returncode == 0, out.stdout[-2000:] + out.stderr[-2000:]
    line = [x for x in out.stdout.splitlines() if x.startswith("RESULT ")][-1]
    return json.loads(line[len("RESULT "):])


def test_stock_polyhedra_law_shares_shear_history():
    """The stock law gives the pair at rest a shear force it never built:
    the reproduction of the bug, which must fail the per-contact check."""
    res = cube_pairs("stock")
    at_rest = res["pairs"][2]["shear_x"]
    assert abs(at_rest) > 0.1, res


def test_per_contact_tangential_law():
    res = cube_pairs("ours")
    kt, dt, steps = res["kt"], res["dt"], res["steps"]
    for pair, v in zip(res["pairs"], res["speeds"]):
        # elastic: -kt x slip; the first step creates the contact (no
        # increment). The contact normal tilts by up to 4e-3 rad as the cube
        # slides, and only the tangential part of the slip counts (factor
        # 1 - n_x^2 = 1 - 1.4e-5): relative tolerance 5e-5.
        expected = -kt * v * dt * (steps - 1)
        assert pair["shear_x"] == pytest.approx(expected, rel=5e-5, abs=1e-12)
        assert abs(pair["shear_x"]) <= 0.5 * pair["normal"]


def test_kernel_tangential_law_and_normal():
    """The compiled kernel (no InteractionLoop) on the same three cube pairs:
    the same per-contact law, and the exact volumetric normal law. The pair
    at rest overlaps by exactly 0.1 mm over (2 cm)^2: V = 4e-8 m^3 and
    F_n = k_V V = (young / 2) V = 2 N, normal exactly along z (S_A of two
    aligned cubes). A sliding pair's overlap box loses the slid strip, and
    A's side face inside it tilts the normal by atan(depth / (2h - slip)):
    1e-4 / (0.02 - 1.9e-6) = 5.0005e-3 rad."""
    res = cube_pairs("kernel")
    kt, dt, steps = res["kt"], res["dt"], res["steps"]
    for k, (pair, v) in enumerate(zip(res["pairs"], res["speeds"])):
        expected = -kt * v * dt * (steps - 1)
        assert pair["shear_x"] == pytest.approx(expected, rel=5e-5, abs=1e-12)
        slip = abs(v) * dt * (steps - 1)
        assert pair["volume"] == pytest.approx(1e-4 * 0.02 * (0.02 - slip), rel=1e-9)
        assert pair["normal"] == pytest.approx(0.5e8 * pair["volume"], rel=1e-9)
        if v != 0:
            assert res["normal_tilt"][k] == pytest.approx(np.arctan(1e-4 / (0.02 - slip)), rel=1e-6)
    assert res["normal_tilt"][2] < 1e-15                            # at rest: exactly along z


# ------------------------------------------------------------ tiny triaxial runs
KINDS = ("polyhedra", "polyhedra-yade", "spheres")
# the tiny preset compacts frictionless (the dense preparation); its loose
# twins compact at the shear friction 0.5, from the same seed. The stock
# contacts' run, the longest of the fixture on YADE's slow stock contacts, is
# as small as still checks that path: 10 grains from their bounding spheres at
# 0.3 (the preset's 0.12 is of the grains), sheared to 1.2 % with three shear
# snapshots (about 7 700 steps and 80 s of CPU, against 11 100 steps and 210 s
# with 12 grains and 14 700 steps with the preset's 20)
VARIANTS = {"polyhedra": {}, "polyhedra-yade": {"contact_engine": "yade", "placement": "spheres",
                                                "initial_fraction": 0.3, "n_particles": 10,
                                                "final_strain": 0.012, "dump_strain": 0.004}, "spheres": {},
            "polyhedra-loose": {"compaction_friction": 0.5}, "spheres-loose": {"compaction_friction": 0.5}}


@pytest.fixture(scope="session")
def tiny_runs(tmp_path_factory, shape_library):
    """Both samples on the tiny preset, run side by side (2 cores); S1 with
    the compiled kernel (the default) and with YADE's stock contacts; both
    also with the loose preparation."""
    base = tmp_path_factory.mktemp("tiny")
    procs = {}
    for kind, extra in VARIANTS.items():
        out = base / kind
        generate(str(out), "tiny", kind.split("-")[0], overrides={"kernel_threads": 1, **extra},
                 library=shape_library)
        log = open(out / "yade.log", "w")
        # the stock contacts' run is the longest: YADE's InteractionLoop takes
        # both cores once the others are done
        threads = ["-j2"] if kind == "polyhedra-yade" else []
        procs[kind] = (subprocess.Popen([YADE, *threads, "-n", "-x", "triaxial.py"], cwd=out, stdout=log,
                                        env=yade_env(str(out)), stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL),
                       out, log)
    runs = {}
    for kind, (p, out, log) in procs.items():
        rc = p.wait(timeout=900)
        log.close()
        text = (out / "yade.log").read_text()
        assert rc == 0, f"{kind} tiny run failed ({rc}):\n{text[-3000:]}"
        runs[kind] = out
    return runs


@pytest.mark.parametrize("kind", KINDS)
def test_tiny_run_writes_a_complete_dump(tiny_runs, kind):
    out = tiny_runs[kind]
    info = json.loads((out / "run.info.json").read_text())
    assert 0.3 < info["solid_fraction_isotropic"] < 0.75
    # the host, read inside YADE: its Python's numpy (Debian's), the CPU
    assert info["host"]["numpy"] == yade_numpy() and info["host"]["libc"].startswith("glibc")
    assert info["host"]["machine"] and set(info["host"]["cpu_flags"]) <= set(SIMD_FLAGS)
    # YADE's scratch folder of the process (/tmp/yade-XXXXXX), which YADE leaves behind, is gone
    assert os.path.basename(info["yade_scratch"]).startswith("yade-") and not os.path.exists(info["yade_scratch"])
    with DumpReader(str(out / "run.h5")) as r:
        assert r.complete and r.sample_kind == kind.split("-")[0]
        # derived quantities are stored with the run parameters
        for key in ("dt", "dt_crit", "young", "rate_shear", "top_wall_speed", "solid_fraction_isotropic"):
            assert np.isfinite(r.parameters[key]) and r.parameters[key] > 0, key
        assert r.parameters["solid_fraction_isotropic"] == pytest.approx(info["solid_fraction_isotropic"])
        stages = [r.read(i).stage for i in range(len(r))]
        assert stages[0] == "isotropic" and stages.count("shear") >= 2
        if kind == "polyhedra":                                     # the kernel's footprint is dumped
            for i in range(len(r)):
                s = r.read(i)
                assert r.parameters["contact_engine"] == "kernel"
                assert s.footprint.shape == (len(s.id1), 2) and np.all(s.footprint[:, 0] >= s.footprint[:, 1])
                assert np.all(s.footprint[:, 1] > 0) and np.all(s.footprint_area > 0)
                # the shadow lies in its m1 x m2 bounding rectangle
                assert np.all(s.footprint_area <= s.footprint.prod(axis=1) * (1 + 1e-9))
        if kind == "polyhedra-yade":
            assert r.read(0).footprint is None and r.parameters["contact_engine"] == "yade"
        if kind.startswith("polyhedra"):
            v, t, _ = r.shapes()
            snap = r.read(0)
            assert len(v) == len(snap.body_ids)
            # the dumped shapes reproduce YADE's volumes and sizes
            for k in range(len(v)):
                a, b, c = v[k][t[k][:, 0]], v[k][t[k][:, 1]], v[k][t[k][:, 2]]
                vol = np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6
                assert vol == pytest.approx(snap.volumes[k], rel=1e-9)
                assert 2 * np.linalg.norm(v[k], axis=1).max() == pytest.approx(snap.sizes[k], rel=1e-6)
        for i in range(len(r)):
            s = r.read(i)
            fn = np.einsum("ij,ij->i", s.force_normal, s.normal)
            assert np.all(fn > 0)                                   # repulsive, on id2 by id1
            ft = np.linalg.norm(s.force - s.force_normal, axis=1)
            walls = np.isin(s.id1, s.wall_ids) | np.isin(s.id2, s.wall_ids)
            assert np.all(ft[~walls] <= 0.5 * fn[~walls] * (1 + 1e-9) + 1e-12)   # Coulomb, mu = 0.5
            assert np.all(ft[walls] <= 1e-9 * fn[walls] + 1e-12)                 # frictionless walls
            # dense preparation: frictionless compaction (compaction_friction 0),
            # mu = 0.5 from the start of shear, reached by sliding contacts in
            # every shear snapshot
            ratio = ft[~walls] / fn[~walls]
            assert r.parameters["friction"] == 0.5
            if s.stage == "isotropic":
                assert r.parameters["compaction_friction"] == 0.0 and np.all(ratio <= 1e-12)
            else:
                assert ratio.max() == pytest.approx(0.5, rel=1e-9)


@pytest.mark.parametrize("kind", ("polyhedra", "polyhedra-loose", "spheres"))
def test_preparation_reaches_the_isotropic_target(tiny_runs, kind):
    """The compaction (polyhedra: the grains placed with their exact shapes,
    the default's protocol) stops at the target state: every wall stress
    within iso_tolerance of sigma0, the unbalanced force below its tolerance,
    the solid fraction reported equal to the dumped one and to the box's, and
    the shear friction restored before shear when the compaction used
    another."""
    out = tiny_runs[kind]
    text = (out / "yade.log").read_text()
    line = [x for x in text.splitlines() if "isotropic state at step" in x]
    assert len(line) == 1, text[-2000:]
    sig = np.array(line[0].split("sigma/sigma0 = [")[1].split("]")[0].split(), float)
    phi = float(line[0].split("solid fraction ")[1].split(",")[0])
    unbalanced = float(line[0].split("unbalanced force ")[1])
    with DumpReader(str(out / "run.h5")) as r:
        par = r.parameters
        iso = r.read(0)
        assert iso.stage == "isotropic"
        # the log prints sigma/sigma0 and phi to 4 decimals (half a unit of
        # the last: 5e-5) and the unbalanced force to 3 significant digits
        assert np.all(np.abs(sig - 1) < par["iso_tolerance"] + 5e-5), sig
        assert 0 <= unbalanced < par["unbalanced_tolerance"] * (1 + 5e-3)
        assert abs(phi - par["solid_fraction_isotropic"]) <= 5e-5 + 1e-12
        assert par["solid_fraction_isotropic"] == pytest.approx(iso.volumes.sum() / np.prod(iso.box_lengths),
                                                                rel=1e-9)
        if kind.startswith("polyhedra"):
            assert par["placement"] == "grains" and par["contact_engine"] == "kernel"
        restored = f"friction {par['compaction_friction']:g} -> {par['friction']:g} for shear"
        assert (restored in text) == (par["compaction_friction"] != par["friction"])
        # the switch comes before the first shear snapshot
        assert text.index("isotropic state at step") < text.index("shear: top wall at")


@pytest.mark.parametrize("sample", ("polyhedra", "spheres"))
def test_dense_preparation_is_denser_than_the_loose_one(tiny_runs, sample):
    """Same seed, same grains: compaction frictionless (dense, the tiny and
    default presets' preparation) against compaction at mu = 0.5 (loose).
    Friction during compaction lets contacts hold the grains apart, so the
    loose isotropic state has the lower solid fraction; both shear at
    mu = 0.5, the loose one with friction already mobilized at the isotropic
    state (some contacts at the Coulomb limit)."""
    phi = {}
    for kind in (sample, sample + "-loose"):
        with DumpReader(str(tiny_runs[kind] / "run.h5")) as r:
            phi[kind] = r.parameters["solid_fraction_isotropic"]
            assert r.parameters["friction"] == 0.5
            assert r.parameters["compaction_friction"] == (0.5 if kind.endswith("loose") else 0.0)
            iso = r.read(0)
            assert iso.stage == "isotropic"
            walls = np.isin(iso.id1, iso.wall_ids) | np.isin(iso.id2, iso.wall_ids)
            fn = np.einsum("ij,ij->i", iso.force_normal, iso.normal)[~walls]
            ft = np.linalg.norm(iso.force - iso.force_normal, axis=1)[~walls]
            if kind.endswith("loose"):
                assert (ft / fn).max() == pytest.approx(0.5, rel=1e-9)
    assert phi[sample] > phi[sample + "-loose"], phi


@pytest.mark.parametrize("kind", KINDS)
def test_wall_stresses_follow_the_servo(tiny_runs, kind):
    out = tiny_runs[kind]
    with DumpReader(str(out / "run.h5")) as r:
        iso = r.read(0)
        sig = wall_stresses(iso.wall_forces, iso.box_lengths)
        assert np.all(np.abs(sig / SIGMA0 - 1) < 0.02), sig       # isotropic: within 2 %
    with open(out / "run.log.csv") as fh:
        rows = [row for row in csv.DictReader(fh) if row["stage"] == "shear"]
    assert len(rows) >= 5
    lateral = np.array([[float(row["s_xx"]), float(row["s_yy"])] for row in rows])
    assert np.all(np.abs(lateral / SIGMA0 - 1) < 0.05), np.abs(lateral / SIGMA0 - 1).max()
    axial = np.array([float(row["s_zz"]) for row in rows])
    assert axial[-1] > SIGMA0                                       # the top wall loads the sample


@pytest.mark.parametrize("kind", KINDS)
def test_contact_stress_equals_wall_stress_plus_known_terms(tiny_runs, kind):
    """With the origin at the box centre c, the internal-moment stress obeys
    exactly (diagonal, compression positive)

        sigma_M,aa = sigma_W,aa - (1/V) sum_wall f_a (x^c_a - h_a)
                                + (1/V) sum_i F_i,a (x_i,a - c_a)

    with f the force on the particle at a wall contact, x^c its contact point
    and h the wall plane (YADE puts the point inside the overlap, not on the
    plane), and F_i the net contact force on particle i (zero in static
    equilibrium). Checked to round-off, this says contacts, wall forces, box
    and positions of a dump are consistent; the two correction terms must
    then be small: the contact-point offset (of order overlap / box) below
    2 % of p and the inertial term below 10 % of p in these quasi-static
    runs of a few dozen particles."""
    out = tiny_runs[kind]
    with DumpReader(str(out / "run.h5")) as r:
        for i in range(len(r)):
            s = r.read(i)
            cs = resolve(s)
            sm = contact_stress(cs.force, cs.arm, cs.volume)
            sw = wall_stress(s.wall_forces, s.box_lengths)
            net = np.zeros((cs.n_particles, 3))
            np.add.at(net, cs.i2[cs.i2 >= 0], cs.force[cs.i2 >= 0])
            np.add.at(net, cs.i1[cs.i1 >= 0], -cs.force[cs.i1 >= 0])
            centre = (s.box_lo + s.box_hi) / 2
            inertia = np.einsum("ia,ia->a", net, s.positions - centre) / s.volume
            wall = ~cs.pp
            slot = cs.wall_slot[wall]
            assert np.all(slot >= 0)
            axis = slot // 2
            plane = np.where(slot % 2 == 0, s.box_lo[axis], s.box_hi[axis])
            f_particle = -cs.wall_sign[wall, None] * cs.force[wall]
            rows = np.arange(wall.sum())
            offset = np.zeros(3)
            np.add.at(offset, axis, -f_particle[rows, axis] * (s.point[wall][rows, axis] - plane) / s.volume)
            p = np.trace(sm) / 3
            assert np.allclose(np.diag(sm), np.diag(sw) + offset + inertia, rtol=0, atol=1e-9 * p)
            assert np.all(np.abs(offset) < 0.02 * p), offset / p
            assert np.all(np.abs(inertia) < 0.10 * p), inertia / p


def test_postproc_reads_both_dumps(tiny_runs, tmp_path):
    from postproc.cli import main

    for kind, out in tiny_runs.items():
        assert main(["analyze", str(out / "run.h5"), "--out", str(tmp_path / kind), "--no-figures"]) == 0
        import pandas as pd

        df = pd.read_csv(tmp_path / kind / "summary.csv")
        with DumpReader(str(out / "run.h5")) as r:
            final = r.parameters["final_strain"]          # 0.02, the stock contacts' run 0.012
        assert df["eps_1"].iloc[0] == 0 and df["eps_1"].iloc[-1] == pytest.approx(final, abs=0.002)
        assert np.all(np.isfinite(df[["p", "q_over_p", "a", "a_n", "a_t", "z"]].to_numpy()))


# ------------------------------------------------------------ same seed, same numbers
def copy_inputs(run, dest, *ignore):
    """A new run folder ``dest`` with the inputs of the run folder ``run``
    (scene, parameters, table, shapes, ``pkg/`` without ``ignore``)."""
    dest.mkdir()
    for name in ("triaxial.py", "params.json", "table.txt", "shapes.h5"):
        if (run / name).exists():
            shutil.copy(run / name, dest / name)
    shutil.copytree(run / "pkg", dest / "pkg", ignore=shutil.ignore_patterns(*ignore))
    return dest


def test_the_same_seed_gives_the_same_run_bit_for_bit(tiny_runs, tmp_path):
    """The tiny S1 run (kernel, one thread) run again from a copy of its
    inputs: every snapshot's positions, orientations, wall forces, contact
    pairs, points and forces, the shapes, and the step count are the same
    to the bit (the kernel takes the grains from the library in its own
    order and frame, not from YADE's CGAL re-hull). The first ran as the
    launchers run it, on the kernel's YADE plugin where it is built (its
    first step checked); the copy runs without YADE_PREFIX, on the PyRunner
    path: so the two paths give the same run, every dataset of the dumps."""
    from yade_scripts import yadeplugin

    first = tiny_runs["polyhedra"]
    again = copy_inputs(first, tmp_path / "again", "_build", "__pycache__")     # no plugin build: the PyRunner
    res = run_yade(["triaxial.py"], cwd=again, timeout=900)
    assert res.returncode == 0, res.stdout[-3000:] + res.stderr[-2000:]
    with DumpReader(str(first / "run.h5")) as a, DumpReader(str(again / "run.h5")) as b:
        assert len(a) == len(b) > 1
        for va, vb in zip(a.shapes(), b.shapes()):
            for x, y in zip(va, vb):
                np.testing.assert_array_equal(x, y)
        for k in range(len(a)):
            sa, sb = a.read(k), b.read(k)
            assert sa.step == sb.step
            for name in ("positions", "orientations", "wall_forces", "id1", "id2", "point", "force"):
                np.testing.assert_array_equal(getattr(sa, name), getattr(sb, name), err_msg=f"{name}, snapshot {k}")
    paths = [json.loads((f / "run.info.json").read_text())["kernel"] for f in (first, again)]
    assert paths[1]["path"] == "pyrunner" and "without YADE_PREFIX" in paths[1]["path_note"]
    if yadeplugin.status()["ok"]:
        assert paths[0] == {**paths[0], "path": "plugin",
                            "path_note": "its first step read and added exactly what YADE's Python sees"}
    with h5py.File(first / "run.h5", "r") as fa, h5py.File(again / "run.h5", "r") as fb:
        names = []
        fa.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
        assert len(names) > 20
        for n in names:
            assert fa[n].dtype == fb[n].dtype and np.array_equal(fa[n][()], fb[n][()]), n
    assert paths[0]["touch_steps"] == paths[1]["touch_steps"] > 0



def test_the_thread_count_and_its_change_mid_run_leave_the_run_bit_for_bit(tiny_runs, tmp_path):
    """The pool widens a running S1 from one kernel thread to two (a stop
    at a checkpoint, a resume on more threads). The tiny S1, with every step
    forced onto the kernel's parallel path (POLYCONTACT_PARALLEL_MIN=0; a
    real step goes parallel from 400 pair and wall tests), run on one
    thread, stopped by SIGTERM mid-run and resumed on two: every dataset of
    its dump equals, to the bit, the fixture's run on one thread throughout.
    The kernel sums each body's forces serially in the pair list's order,
    whatever thread computed a pair."""
    first = tiny_runs["polyhedra"]
    d = copy_inputs(first, tmp_path / "switched", "__pycache__")               # the plugin's build kept
    _set_params(d, kernel_threads=0)                 # YADE's -j: 1, then 2
    env = {**yade_env(str(d)), "POLYCONTACT_PARALLEL_MIN": "0"}
    p = subprocess.Popen([YADE, "-j1", "-n", "-x", "triaxial.py"], cwd=d, env=env, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True, stdin=subprocess.DEVNULL)
    t0 = time.time()
    while True:            # well into the compaction (the tiny S1 takes ~15 000 steps): the log's rows say
        try:
            rows = (d / "run.log.csv").read_text().splitlines()
            step = int(rows[-1].split(",")[0]) if len(rows) > 1 else 0
        except (OSError, ValueError):
            step = 0
        if step >= 2000 or p.poll() is not None:
            break
        assert time.time() - t0 < 300
        time.sleep(0.05)
    p.send_signal(signal.SIGTERM)
    out = p.communicate(timeout=300)[0]
    # stopped with its checkpoint, and out cleanly: a process that saved or loaded a scene
    # with the plugin stepping could abort among YADE's static destructors at exit (double
    # free, -6); the scene now leaves by yade_scripts.runs.attempt.leave
    assert "run again in this folder to resume (exit 75)" in out and p.returncode == 75, out[-3000:]
    again = subprocess.run([YADE, "-j2", "-n", "-x", "triaxial.py"], cwd=d, env=env, capture_output=True,
                           text=True, timeout=600, stdin=subprocess.DEVNULL)
    assert again.returncode == 0 and "resumed from run.ckpt" in again.stdout, again.stdout[-3000:]
    info = json.loads((d / "run.info.json").read_text())
    assert info["kernel"]["threads"] == 2 and len(info["resumes"]) == 1
    with h5py.File(first / "run.h5", "r") as fa, h5py.File(d / "run.h5", "r") as fb:
        names = []
        fa.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
        assert len(names) > 20
        for n in names:
            assert fa[n].dtype == fb[n].dtype and np.array_equal(fa[n][()], fb[n][()]), n


# ------------------------------------------------------------ failures
def _set_params(folder, **values):
    path = folder / "triaxial.py"
    text = path.read_text()
    for k, v in values.items():
        import re

        text, n = re.subn(rf"^(\s+){k}=.*?,(\s+#.*)?$", rf"\g<1>{k}={v!r},\g<2>", text, flags=re.M)
        assert n == 1, k
    path.write_text(text)


def test_killed_run_keeps_earlier_snapshots(tmp_path):
    out = tmp_path / "killed"
    generate(str(out), "tiny", "spheres", overrides={"dump_strain": 0.001, "final_strain": 0.5})
    p = subprocess.Popen([YADE, "-n", "-x", "triaxial.py"], cwd=out, stdout=subprocess.DEVNULL,
                         stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL)
    deadline = time.time() + 300
    n = 0
    while time.time() < deadline and n < 3:
        time.sleep(0.5)
        if (out / "run.h5").exists():
            try:
                with DumpReader(str(out / "run.h5")) as r:
                    n = len(r)
            except Exception:
                n = 0
    p.send_signal(signal.SIGKILL)
    p.wait()
    assert n >= 3, "the run wrote no snapshots in time"
    with DumpReader(str(out / "run.h5")) as r:
        assert not r.complete and len(r) >= 3
        for i in range(len(r)):
            assert len(r.read(i).id1) > 0


def test_blow_up_stops_with_a_message_and_keeps_dumps(tmp_path):
    out = tmp_path / "boom"
    generate(str(out), "tiny", "spheres", overrides={"dump_strain": 0.002})
    _set_params(out, safety=40.0)     # outside the parameter's range: refused before the run, in one line
    res = run_yade(["triaxial.py"], cwd=out, timeout=300)
    assert res.returncode == 2 and "invalid parameter: safety = 40.0 is outside [0.001, 1]" in res.stdout
    assert not (out / "run.h5").exists()
    _set_params(out, safety=1.0)      # a scene edited by hand to step at 40 x the critical step: explodes
    scene = (out / "triaxial.py").read_text()
    assert scene.count("O.dt = safety * dt_crit") == 1
    (out / "triaxial.py").write_text(scene.replace("O.dt = safety * dt_crit", "O.dt = 40 * safety * dt_crit"))
    res = run_yade(["triaxial.py"], cwd=out, timeout=300)
    assert res.returncode == 3, res.stdout[-2000:]
    assert "STOPPED" in res.stdout
    with DumpReader(str(out / "run.h5")) as r:
        assert not r.complete
        for i in range(len(r)):
            r.read(i)
