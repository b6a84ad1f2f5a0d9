"""The dump schema: round trip, atomic snapshots, clear errors."""
import os
import shutil
import signal
import subprocess
import sys
import textwrap
import time

import h5py
import numpy as np
import pytest
from builders import lattice_snapshot, write_snapshot

from postproc.schema import SCHEMA_VERSION, DumpFormatError, DumpReader, DumpWriter

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def test_round_trip(tmp_path):
    snap, _, _ = lattice_snapshot()
    path = tmp_path / "run.h5"
    cube = np.array([[x, y, z] for x in (-.5, .5) for y in (-.5, .5) for z in (-.5, .5)])
    with DumpWriter(str(path), "polyhedra", {"seed": 3, "sigma0": 1e4}, overlap_kind="volume") as w:
        w.write_shapes([cube], [np.array([[0, 1, 3], [0, 3, 2]])], [np.array([0, 0])])
        write_snapshot(w, snap)
        w.update_parameters(phi=0.6)
        write_snapshot(w, snap, step=10, stage="final")
    assert not os.path.exists(str(path) + ".parts")           # packed into one file
    with DumpReader(str(path)) as r:
        assert r.complete and r.sample_kind == "polyhedra" and r.overlap_kind == "volume"
        assert r.parameters == {"seed": 3, "sigma0": 1e4, "phi": 0.6}
        assert len(r) == 2
        v, t, tf = r.shapes()
        np.testing.assert_array_equal(v[0], cube)
        np.testing.assert_array_equal(tf[0], [0, 0])
        s0, s1 = list(r)
    assert s1.step == 10 and s1.stage == "final"
    for name in ("id1", "id2", "point", "force", "force_normal", "normal", "positions", "body_ids"):
        np.testing.assert_array_equal(getattr(s0, name), getattr(snap, name))
    assert s0.volume == pytest.approx(snap.volume, rel=1e-15)


def test_unpacked_run_reads_the_same(tmp_path):
    snap, _, _ = lattice_snapshot()
    path = str(tmp_path / "run.h5")
    w = DumpWriter(path, "spheres", {})
    write_snapshot(w, snap)
    # not closed: the master links to the part files
    with DumpReader(path) as r:
        assert len(r) == 1 and not r.complete
        np.testing.assert_array_equal(r.read(0).force, snap.force)


def test_writer_rejects_bad_shapes_and_overwrite(tmp_path):
    snap, _, _ = lattice_snapshot()
    path = str(tmp_path / "run.h5")
    w = DumpWriter(path, "spheres", {})
    with pytest.raises(DumpFormatError, match="contacts/point"):
        write_snapshot(w, snap, contacts={**_contacts(snap), "point": snap.point[:-1]})
    with pytest.raises(DumpFormatError, match="overwrite"):
        DumpWriter(path, "spheres", {})
    with pytest.raises(DumpFormatError, match="sample_kind"):
        DumpWriter(str(tmp_path / "x.h5"), "cubes", {})


def _contacts(snap):
    from builders import snapshot_dicts

    return snapshot_dicts(snap)[1]


def test_reader_errors_are_one_line(tmp_path):
    with pytest.raises(DumpFormatError, match="no such file"):
        DumpReader(str(tmp_path / "missing.h5"))
    bad = tmp_path / "v99.h5"
    with h5py.File(bad, "w") as f:
        f.attrs["schema"] = "granular-contact-dump"
        f.attrs["schema_version"] = 99
    with pytest.raises(DumpFormatError, match=f"schema version 99 is not supported.*{SCHEMA_VERSION}"):
        DumpReader(str(bad))
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f["x"] = 1
    with pytest.raises(DumpFormatError, match="not a granular-contact-dump"):
        DumpReader(str(other))
    # a truncated file
    snap, _, _ = lattice_snapshot()
    good = str(tmp_path / "good.h5")
    with DumpWriter(good, "spheres", {}) as w:
        write_snapshot(w, snap)
    data = open(good, "rb").read()
    cut = tmp_path / "cut.h5"
    cut.write_bytes(data[: len(data) // 2])
    with pytest.raises(DumpFormatError, match="truncated or corrupt"):
        DumpReader(str(cut))


def test_missing_part_is_reported_per_snapshot(tmp_path):
    snap, _, _ = lattice_snapshot()
    path = str(tmp_path / "run.h5")
    w = DumpWriter(path, "spheres", {})
    write_snapshot(w, snap)
    write_snapshot(w, snap, step=5)
    os.remove(os.path.join(path + ".parts", "snapshot_000001.h5"))
    with DumpReader(path) as r:
        r.read(0)
        with pytest.raises(DumpFormatError, match="snapshot 000001 is incomplete"):
            r.read(1)


WRITER = textwrap.dedent("""
    import sys, numpy as np
    sys.path.insert(0, {root!r}); sys.path.insert(0, {tests!r})
    from postproc.schema import DumpWriter
    from builders import lattice_snapshot, write_snapshot
    snap, _, _ = lattice_snapshot(12, 12, 12)   # ~5000 contacts per snapshot
    w = DumpWriter(sys.argv[1], "spheres", {{}})
    k = 0
    while True:
        write_snapshot(w, snap, step=k)
        k += 1
""")


@pytest.mark.parametrize("delay", [0.4, 0.9, 1.7])
def test_killed_writer_leaves_earlier_snapshots_readable(tmp_path, delay):
    script = tmp_path / "writer.py"
    script.write_text(WRITER.format(root=ROOT, tests=os.path.join(ROOT, "tests")))
    path = str(tmp_path / "run.h5")
    proc = subprocess.Popen([sys.executable, str(script), path])
    time.sleep(delay)
    deadline = time.time() + 30
    while not os.path.exists(path) and time.time() < deadline:
        time.sleep(0.05)
    time.sleep(0.2)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    with DumpReader(path) as r:
        assert len(r) >= 1 and not r.complete
        steps = [r.read(i).step for i in range(len(r))]
    assert steps == list(range(len(steps)))


@pytest.mark.skipif(not os.path.exists("/usr/bin/python3"), reason="no system python")
def test_system_python_can_write_a_dump(tmp_path):
    """YADE's interpreter (Debian python3, numpy 1.24, h5py 3.7) imports the
    schema module alone and writes a dump that the package reads."""
    probe = subprocess.run(["/usr/bin/python3", "-c", "import numpy, h5py"], capture_output=True)
    if probe.returncode != 0:
        pytest.skip("system python lacks numpy/h5py (make test installs python3-h5py)")
    script = tmp_path / "w.py"
    script.write_text(textwrap.dedent(f"""
        import sys
        sys.path.insert(0, {ROOT!r}); sys.path.insert(0, {os.path.join(ROOT, 'tests')!r})
        from postproc.schema import DumpWriter
        from builders import lattice_snapshot, write_snapshot
        snap, _, _ = lattice_snapshot()
        with DumpWriter(sys.argv[1], "spheres", {{"python": sys.version}}) as w:
            write_snapshot(w, snap)
        assert "scipy" not in sys.modules and "pandas" not in sys.modules
    """))
    path = str(tmp_path / "sys.h5")
    out = subprocess.run(["/usr/bin/python3", str(script), path], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    with DumpReader(path) as r:
        assert len(r) == 1 and r.complete


def test_footprint_round_trip_and_version_1_still_reads(tmp_path):
    """Version 2 adds the optional contacts/footprint (C, 2) and
    footprint_area (C,); a version-1 file (no footprint) still reads, with
    footprint None, and a footprint of the wrong shape is refused."""
    from builders import snapshot_dicts

    snap, _, _ = lattice_snapshot()
    bodies, contacts = snapshot_dicts(snap)
    n = len(snap.id1)
    fp = np.column_stack([np.linspace(2e-3, 3e-3, n), np.linspace(1e-3, 2e-3, n)])
    area = fp.prod(axis=1) * 0.7
    path = tmp_path / "v2.h5"
    kw = dict(step=0, time=0.0, stage="isotropic", box_lo=snap.box_lo, box_hi=snap.box_hi,
              wall_ids=snap.wall_ids, wall_forces=snap.wall_forces, bodies=bodies)
    with DumpWriter(str(path), "spheres", {}) as w:
        w.write_snapshot(**kw, contacts={**contacts, "footprint": fp, "footprint_area": area})
        with pytest.raises(DumpFormatError, match="contacts/footprint"):
            w.write_snapshot(**kw, contacts={**contacts, "footprint": fp[:, :1]})
    with DumpReader(str(path)) as r:
        assert r.version == SCHEMA_VERSION == 2
        s = r.read(0)
        np.testing.assert_array_equal(s.footprint, fp)
        np.testing.assert_array_equal(s.footprint_area, area)
    old = tmp_path / "v1.h5"
    with DumpWriter(str(old), "spheres", {}) as w:
        w.write_snapshot(**kw, contacts=contacts)
    with h5py.File(old, "r+") as f:                 # what a version-1 writer left
        f.attrs["schema_version"] = 1
    with DumpReader(str(old)) as r:
        assert r.version == 1
        s = r.read(0)
        assert s.footprint is None and s.footprint_area is None
        np.testing.assert_array_equal(s.force, snap.force)


def test_resume_appends_after_the_checkpoint_count(tmp_path):
    """A run that wrote 5 snapshots and died, resumed from a checkpoint taken
    after 3: snapshots 3 and 4 are dropped, the resumed run writes its own,
    and the closed dump holds 0..4 in order with no duplicate."""
    snap, _, _ = lattice_snapshot()
    path = str(tmp_path / "run.h5")
    w = DumpWriter(path, "spheres", {"seed": 1})
    for k in range(5):
        write_snapshot(w, snap, step=10 * k)
    del w                                              # died: never closed
    with pytest.raises(DumpFormatError, match="snapshot 000005 is missing"):
        DumpWriter.resume(path, 8)
    w = DumpWriter.resume(path, 3)
    with DumpReader(path) as r:                        # readable right away, 3 snapshots
        assert len(r) == 3 and not r.complete
    for k in range(3, 6):
        write_snapshot(w, snap, step=1000 + k)
    w.close()
    with DumpReader(path) as r:
        assert r.complete and r.parameters == {"seed": 1}
        assert [s.step for s in r] == [0, 10, 20, 1003, 1004, 1005]
    with pytest.raises(DumpFormatError, match="no parts folder"):
        DumpWriter.resume(path, 2)
