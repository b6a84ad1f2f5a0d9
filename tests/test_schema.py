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


# ------------------------------------------------ whole dumps: index, counts, checksums
def _run(path, n=3, pack=True, F=(3.0, 5.0, 7.0)):
    """A dump of ``n`` small lattice snapshots (steps 0, 10, 20 ...), packed
    or left unpacked (the master linking to its parts)."""
    snap, _, _ = lattice_snapshot(F=F)
    w = DumpWriter(str(path), "spheres", {"seed": 1})
    for k in range(n):
        write_snapshot(w, snap, step=10 * k, time=0.5 * k)
    if pack:
        w.close()
    return w


def _one_line_error(match, fn, *args):
    with pytest.raises(DumpFormatError, match=match) as info:
        fn(*args)
    assert "\n" not in str(info.value)
    return str(info.value)


def _read_all(path):
    with DumpReader(str(path)) as r:
        return [r.read(i) for i in range(len(r))]


def test_index_rows_follow_the_documented_checksum(tmp_path):
    """/index holds step, bodies, contacts and the crc32-v1 checksum of each
    snapshot, computed here from the docstring's recipe (a periodic
    snapshot without walls and one without contacts included)."""
    import zlib

    snap, _, _ = lattice_snapshot()
    from builders import snapshot_dicts

    bodies, contacts = snapshot_dicts(snap)
    path = tmp_path / "run.h5"
    with DumpWriter(str(path), "spheres", {}) as w:
        write_snapshot(w, snap, step=7, time=0.25, stage="isotropic")
        write_snapshot(w, snap, step=8, time=0.5, wall_ids=np.zeros(0, np.int64), wall_forces=np.zeros((0, 3)),
                       cell=np.diag(snap.box_hi))
        write_snapshot(w, snap, step=9, contacts={k: v[:0] for k, v in contacts.items()})

    def by_hand(g):
        crc = zlib.crc32(f"step {g.attrs['step']} time {float(g.attrs['time']).hex()} "
                         f"stage {g.attrs['stage']}\n".encode())
        names = []
        g.visit(lambda n: names.append(n) if isinstance(g[n], h5py.Dataset) else None)
        for n in sorted(names):
            a = np.ascontiguousarray(g[n][()])
            crc = zlib.crc32(f"{n} {a.dtype.str} {'x'.join(map(str, a.shape))}\n".encode(), crc)
            crc = zlib.crc32(a.tobytes(), crc)
        return crc

    with h5py.File(path, "r") as f:
        assert f["index"].attrs["checksum_kind"] == "crc32-v1"
        idx = {k: f["index/" + k][()] for k in ("step", "n_bodies", "n_contacts", "checksum")}
        assert idx["checksum"].dtype == np.uint32 and idx["step"].dtype == np.int64
        assert list(idx["step"]) == [7, 8, 9]
        assert list(idx["n_bodies"]) == [len(snap.body_ids)] * 3
        assert list(idx["n_contacts"]) == [len(snap.id1), len(snap.id1), 0]
        assert list(idx["checksum"]) == [by_hand(f[f"snapshots/{k:06d}"]) for k in range(3)]
    check = __import__("postproc.schema", fromlist=["verify_dump"]).verify_dump(str(path))
    assert (check.n_snapshots, check.checksums, check.complete) == (3, True, True)


@pytest.mark.parametrize("pack", [True, False])
def test_a_removed_snapshot_group_is_refused(tmp_path, pack):
    """A group taken out of a packed dump, or a link out of an unfinished
    master: the count, the names and the index no longer add up."""
    for name, held in (("000001", r"holds 2 \(000000, 000002\), lacks 000001"),
                       ("000002", r"holds 2 \(000000–000001\), lacks 000002")):
        path = tmp_path / f"{pack}-{name}.h5"
        _run(path, 3, pack=pack)
        with h5py.File(path, "r+") as f:
            del f["snapshots/" + name]
        msg = _one_line_error(f"says 3 snapshots, {held}: not a whole dump", DumpReader, str(path))
        assert msg.startswith(str(path))
    # the count fixed up by hand as well: the gap, then the index, still tell
    path = tmp_path / f"{pack}-fixed.h5"
    _run(path, 3, pack=pack)
    with h5py.File(path, "r+") as f:
        del f["snapshots/000001"]
        f.attrs["n_snapshots"] = 2
    _one_line_error(r"says 2 snapshots, holds 2 \(000000, 000002\)", DumpReader, str(path))
    with h5py.File(path, "r+") as f:
        f.move("snapshots/000002", "snapshots/000001")
    _one_line_error("the index has 3 rows for 2 snapshots: not a whole dump", DumpReader, str(path))


def test_n_snapshots_saying_more_than_the_dump_holds_is_refused(tmp_path):
    """The cluster case: complete = 1 and n_snapshots = 11 over snapshots
    0-4 only."""
    path = tmp_path / "run.h5"
    _run(path, 5)
    with h5py.File(path, "r+") as f:
        f.attrs["n_snapshots"] = 11
        assert f.attrs["complete"] == 1
    msg = _one_line_error("says 11 snapshots, holds 5", DumpReader, str(path))
    assert msg == (f"{path}: says 11 snapshots, holds 5 (000000–000004), lacks 000005–000010: "
                   f"not a whole dump (two writers?)")


def test_another_writer_s_part_fails_its_checksum(tmp_path):
    """A part replaced by another writer's snapshot of the same name (same
    step and counts, other forces): reading it, packing the run and
    resuming it are refused; the other snapshots still read."""
    a, b = tmp_path / "a.h5", tmp_path / "b.h5"
    wa = _run(a, 3, pack=False)
    _run(b, 3, pack=False, F=(3.0, 5.0, 7.5))
    part = "snapshot_000001.h5"
    shutil.copy(str(b) + ".parts/" + part, str(a) + ".parts/" + part)
    with DumpReader(str(a)) as r:
        assert r.indexed and r.read(0).step == 0 and r.read(2).step == 20
        msg = _one_line_error(r"snapshot 000001 does not match its index row \(checksum [0-9a-f]{8}, "
                              r"the index says [0-9a-f]{8}\): replaced or damaged", r.read, 1)
        assert "bodies" not in msg and "step" not in msg      # same step and counts: only the checksum
        _one_line_error("snapshot 000001", r.verify)
    _one_line_error("snapshot 000001 in a.h5.parts/ is not what this writer wrote.*not packed", wa.close)
    assert os.path.isdir(str(a) + ".parts") and not os.path.exists(str(a) + ".pack.tmp")
    with DumpReader(str(a)) as r:
        assert not r.complete and len(r) == 3               # left as it was
    _one_line_error(r"snapshot 000001 \(a.h5.parts/snapshot_000001.h5\) is not what the master recorded"
                    r".*cannot resume", DumpWriter.resume, str(a), 3)
    w = DumpWriter.resume(str(a), 1)                          # before the replaced part: fine
    w.close()
    assert [s.step for s in _read_all(a)] == [0]


def test_a_changed_packed_snapshot_fails_its_checksum(tmp_path):
    path = tmp_path / "run.h5"
    _run(path, 3)
    with h5py.File(path, "r+") as f:
        f["snapshots/000002/contacts/force_normal"][0, 0] += 1e-9
    with DumpReader(str(path)) as r:
        r.read(1)
        _one_line_error("snapshot 000002 does not match its index row", r.read, 2)
    from postproc.schema import verify_dump

    _one_line_error("snapshot 000002", verify_dump, str(path))
    with h5py.File(path, "r+") as f:                          # another writer's step and body count
        g = f["snapshots/000002"]
        g.attrs["step"] = 99
        ids = g["bodies/id"][()]
        del g["bodies/id"]
        g["bodies/id"] = ids[:-1]
    with DumpReader(str(path)) as r:
        _one_line_error(r"step 99, the index says 20; 23 bodies, the index says 24; checksum", r.read, 2)


def test_a_resumed_writer_keeps_the_index_right(tmp_path):
    """5 snapshots written, died, resumed after 3: the master's index has
    the 3 kept rows at once, then the new ones; the packed dump verifies.
    A master written before the index existed resumes too (the index is
    computed from its parts)."""
    path = str(tmp_path / "run.h5")
    _run(path, 5, pack=False)
    w = DumpWriter.resume(path, 3)
    with h5py.File(path, "r") as f:
        assert list(f["index/step"][()]) == [0, 10, 20] and f.attrs["n_snapshots"] == 3
    with DumpReader(path) as r:
        assert r.verify().checksums and len(r) == 3
    snap, _, _ = lattice_snapshot(F=(1.0, 2.0, 3.0))
    write_snapshot(w, snap, step=1003)
    w.close()
    with h5py.File(path, "r") as f:
        assert list(f["index/step"][()]) == [0, 10, 20, 1003]
        assert list(f["index/n_contacts"][()]) == [len(snap.id1)] * 4
    with DumpReader(path) as r:
        check = r.verify()
        assert (check.n_snapshots, check.checksums, check.complete) == (4, True, True)
        np.testing.assert_array_equal(r.read(3).force, snap.force)
    # an older master (no /index): resumed, its index rebuilt from the parts
    old = str(tmp_path / "old.h5")
    _run(old, 3, pack=False)
    with h5py.File(old, "r+") as f:
        del f["index"]
    w = DumpWriter.resume(old, 2)
    write_snapshot(w, snap, step=5)
    w.close()
    with DumpReader(old) as r:
        assert r.indexed and r.verify().checksums and [s.step for s in r] == [0, 10, 5]
    # a kept part beyond what the master's index records is not trusted
    path = str(tmp_path / "short.h5")
    _run(path, 3, pack=False)
    with h5py.File(path, "r+") as f:
        rows = {k: f["index/" + k][:2] for k in ("step", "n_bodies", "n_contacts", "checksum")}
        for k, v in rows.items():
            del f["index/" + k]
            f["index/" + k] = v
    _one_line_error("snapshot 000002 is not in the master's index", DumpWriter.resume, path, 3)


@pytest.mark.parametrize("pack", [True, False])
def test_a_dump_without_an_index_still_reads(tmp_path, pack):
    """Dumps written before the index existed: read and verified without
    checksums; the count and name checks still apply."""
    path = tmp_path / "old.h5"
    _run(path, 3, pack=pack)
    with h5py.File(path, "r+") as f:
        del f["index"]
    with DumpReader(str(path)) as r:
        assert not r.indexed and [s.step for s in r] == [0, 10, 20]
        check = r.verify()
        assert check.n_snapshots == 3 and not check.checksums and check.complete == pack
    with h5py.File(path, "r+") as f:
        del f["snapshots/000001"]
        del f.attrs["n_snapshots"]                             # nothing says how many: the gap tells
    _one_line_error(r"holds 2 \(000000, 000002\), not 000000–000001 without a gap", DumpReader, str(path))


def test_complete_is_written_last_after_n_snapshots(tmp_path, monkeypatch):
    """Packing copies the data first, then the index and the attributes,
    n_snapshots and complete last; the master is written in the same
    order."""
    events = []
    set_attr, copy, set_item = h5py.AttributeManager.__setitem__, h5py.Group.copy, h5py.Group.__setitem__

    def spy_attr(self, name, value):
        events.append(("attr", name))
        return set_attr(self, name, value)

    def spy_copy(self, source, dest, name=None, **kw):
        events.append(("copy", name))
        return copy(self, source, dest, name=name, **kw)

    def spy_item(self, name, obj):
        events.append(("data", name))
        return set_item(self, name, obj)

    w = _run(tmp_path / "run.h5", 2, pack=False)
    monkeypatch.setattr(h5py.AttributeManager, "__setitem__", spy_attr)
    monkeypatch.setattr(h5py.Group, "copy", spy_copy)
    monkeypatch.setattr(h5py.Group, "__setitem__", spy_item)
    snap, _, _ = lattice_snapshot()
    write_snapshot(w, snap, step=20)
    master = events[events.index(("data", "snapshots/000000")):]     # the master's rewrite
    assert master[-2:] == [("attr", "n_snapshots"), ("attr", "complete")]
    assert ("data", "checksum") in master               # /index/checksum
    events.clear()
    w.close()
    assert events[-2:] == [("attr", "n_snapshots"), ("attr", "complete")]
    copies = [e for e in events if e[0] == "copy"]
    assert copies == [("copy", f"snapshots/{k:06d}") for k in range(3)]
    assert max(events.index(e) for e in events if e[0] != "attr") < events.index(("attr", "n_snapshots"))
    with h5py.File(tmp_path / "run.h5", "r") as f:
        assert f.attrs["complete"] == 1 and f.attrs["n_snapshots"] == 3 and len(f["index/step"]) == 3


def test_an_empty_file_and_a_file_that_is_not_hdf5_are_named_as_such(tmp_path):
    """h5py's one OSError for all three is told apart: an empty file, a
    file without HDF5's signature (text, another format), and a cut HDF5
    file (above)."""
    empty = tmp_path / "empty.h5"
    empty.write_bytes(b"")
    with pytest.raises(DumpFormatError, match=r"empty.h5: an empty file \(0 bytes\), not a dump"):
        DumpReader(str(empty))
    text = tmp_path / "text.h5"
    text.write_text("step,id1,id2\n")
    with pytest.raises(DumpFormatError, match=r"text.h5: not an HDF5 file \(13 bytes, no HDF5 signature"):
        DumpReader(str(text))
