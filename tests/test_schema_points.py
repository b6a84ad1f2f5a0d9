"""Contact points in the dump (schema version 3): round trip, checksum, refusals.

A dump that holds ``points/*`` says schema version 3; one without stays the
version-2 file it always was (its units attribute and checksums unchanged).
"""
import json

import h5py
import numpy as np
import pytest
from builders import lattice_snapshot, snapshot_dicts, write_snapshot

from postproc.schema import (POINT_FIELDS, POINTS_SCHEMA_VERSION, SCHEMA_VERSION, UNITS, DumpFormatError,
                             DumpReader, DumpWriter, snapshot_checksum, verify_dump)


def lattice_points(snap, per_contact=(1, 2, 3)):
    """Points of the lattice's contacts: contact c gets per_contact[c % 3]
    points spread on its contact plane, whose forces sum to the contact's,
    and gaps -1e-6 * (k + 1) m at its k-th point."""
    fn, ft = snap.force_normal, snap.force - snap.force_normal
    rows, point, normal, pfn, pft, gap = [], [], [], [], [], []
    for c in range(len(snap.id1)):
        m = per_contact[c % len(per_contact)]
        n = snap.normal[c]
        t = np.cross(n, [1.0, 0, 0]) if abs(n[0]) < 0.9 else np.cross(n, [0, 1.0, 0])
        t /= np.linalg.norm(t)
        for k in range(m):
            rows.append(c)
            point.append(snap.point[c] + 1e-4 * (k - (m - 1) / 2) * t)
            normal.append(n)
            pfn.append(fn[c] / m)
            pft.append(ft[c] / m)
            gap.append(-1e-6 * (k + 1))
    return {"contact": np.array(rows), "point": np.array(point), "normal": np.array(normal),
            "force_normal": np.array(pfn), "force_tangential": np.array(pft), "gap": np.array(gap)}


def _one_line(match, fn, *a, **kw):
    with pytest.raises(DumpFormatError, match=match) as info:
        fn(*a, **kw)
    assert "\n" not in str(info.value)
    return str(info.value)


def test_points_round_trip_and_version_3(tmp_path):
    snap, _, _ = lattice_snapshot()
    pts = lattice_points(snap)
    path = tmp_path / "cd.h5"
    with DumpWriter(str(path), "polyhedra", {}) as w:
        write_snapshot(w, snap, step=0)                    # a snapshot without points
        write_snapshot(w, snap, step=1, points=pts)
    with h5py.File(path, "r") as f:
        assert int(f.attrs["schema_version"]) == POINTS_SCHEMA_VERSION == 3
        units = json.loads(f.attrs["units"])
        assert units["points/gap"] == "m" and units["points/force_normal"] == "N"
    with DumpReader(str(path)) as r:
        assert r.version == 3
        s0, s1 = list(r)
    assert s0.points is None
    assert sorted(s1.points) == sorted(POINT_FIELDS)
    for k in POINT_FIELDS:
        np.testing.assert_array_equal(s1.points[k], pts[k])
    assert s1.points["contact"].dtype == np.int64
    # the points' forces sum to the contact's, exactly as built (1, 2, 3 points)
    total = np.zeros_like(snap.force)
    np.add.at(total, s1.points["contact"], s1.points["force_normal"] + s1.points["force_tangential"])
    np.testing.assert_allclose(total, s1.force, rtol=1e-15, atol=1e-15)
    np.testing.assert_array_equal(s1.force, snap.force)
    assert verify_dump(str(path)).checksums


def test_a_dump_without_points_stays_version_2(tmp_path):
    """No points: version 2, the units attribute exactly UNITS, and the
    checksum of the same snapshot does not depend on whether a sibling
    snapshot of another dump held points."""
    snap, _, _ = lattice_snapshot()
    plain, mixed = tmp_path / "plain.h5", tmp_path / "mixed.h5"
    with DumpWriter(str(plain), "spheres", {}) as w:
        write_snapshot(w, snap)
    with DumpWriter(str(mixed), "spheres", {}) as w:
        write_snapshot(w, snap)
        write_snapshot(w, snap, step=1, points=lattice_points(snap))
    with h5py.File(plain, "r") as f, h5py.File(mixed, "r") as g:
        assert int(f.attrs["schema_version"]) == SCHEMA_VERSION == 2
        assert json.loads(f.attrs["units"]) == UNITS
        assert "points" not in f["snapshots/000000"]
        assert f["index/checksum"][0] == g["index/checksum"][0]
        assert f["index/checksum"][0] != g["index/checksum"][1]


def test_the_checksum_covers_the_points(tmp_path):
    snap, _, _ = lattice_snapshot()
    path = tmp_path / "cd.h5"
    with DumpWriter(str(path), "spheres", {}) as w:
        write_snapshot(w, snap, points=lattice_points(snap))
    with h5py.File(path, "r") as f:
        g = f["snapshots/000000"]
        d = {}
        g.visititems(lambda n, o: d.__setitem__(n, o[()]) if isinstance(o, h5py.Dataset) else None)
        assert any(k.startswith("points/") for k in d)
        assert snapshot_checksum(0, 0.0, "shear", d) == f["index/checksum"][0]
    with h5py.File(path, "r+") as f:                 # one gap changed by one ulp
        gap = f["snapshots/000000/points/gap"]
        v = gap[()]
        v[3] = np.nextafter(v[3], 0.0)
        gap[...] = v
    _one_line(r"snapshot 000000 does not match its index row \(checksum", verify_dump, str(path))


@pytest.mark.parametrize("change, match", [
    (lambda p, c: {**p, "contact": np.where(np.arange(len(p["contact"])) == 4, c, p["contact"])},
     r"points/contact: row \d+ at point 4 is outside 0\.\.\d+"),
    (lambda p, c: {**p, "contact": p["contact"] - 1}, r"row -1 at point 0 is outside"),
    (lambda p, c: {**p, "gap": np.where(np.arange(len(p["gap"])) == 2, np.nan, p["gap"])},
     r"points/gap: not finite at point 2"),
    (lambda p, c: {**p, "force_normal": p["force_normal"] + np.array([[0, np.inf, 0]] + [[0, 0, 0]] * (len(p["gap"]) - 1))},
     r"points/force_normal: not finite at point 0"),
    (lambda p, c: {**p, "point": p["point"][:, :2]}, r"points/point: expected shape \(\d+, 3\), got \(\d+, 2\)"),
    (lambda p, c: {**p, "gap": p["gap"][:-1]}, r"points/gap: expected shape"),
    (lambda p, c: {**p, "normal": 2 * p["normal"]}, r"points/normal: not a unit vector at point 0 \(length 2\)"),
    (lambda p, c: {k: v for k, v in p.items() if k != "gap"}, r"points: missing gap"),
    (lambda p, c: {**p, "rn": p["gap"]}, r"points: unknown rn"),
    (lambda p, c: {**p, "contact": p["contact"] + 0.5}, r"points/contact: expected integers"),
])
def test_the_writer_refuses_bad_points_in_one_line(tmp_path, change, match):
    snap, _, _ = lattice_snapshot()
    w = DumpWriter(str(tmp_path / "cd.h5"), "spheres", {})
    _one_line(match, write_snapshot, w, snap, points=change(lattice_points(snap), len(snap.id1)))
    assert w.n_snapshots == 0 and w.attrs["schema_version"] == 2   # nothing written, still version 2
    w.close()


def _rewrite(path, name, value, fix_index=True):
    """Replace dataset ``name`` of snapshot 000000 and, when fix_index, its
    index checksum (a consistent but invalid file)."""
    with h5py.File(path, "r+") as f:
        g = f["snapshots/000000"]
        if name in g:
            del g[name]
        g[name] = value
        if fix_index:
            d = {}
            g.visititems(lambda n, o: d.__setitem__(n, o[()]) if isinstance(o, h5py.Dataset) else None)
            f["index/checksum"][0] = snapshot_checksum(g.attrs["step"], g.attrs["time"], g.attrs["stage"], d)


def test_the_reader_refuses_bad_points_in_one_line(tmp_path):
    snap, _, _ = lattice_snapshot()
    pts = lattice_points(snap)
    nc = len(snap.id1)
    cases = [("points/contact", np.full(len(pts["contact"]), nc), rf"snapshot 000000 points/contact: row {nc} "),
             ("points/normal", np.zeros_like(pts["normal"]), r"snapshot 000000 points/normal: not a unit"),
             ("points/gap", np.full(len(pts["gap"]), np.nan), r"snapshot 000000 points/gap: not finite"),
             ("points/force_tangential", pts["force_tangential"][:-1], r"points/force_tangential: expected shape")]
    for k, (name, value, match) in enumerate(cases):
        path = tmp_path / f"cd{k}.h5"
        with DumpWriter(str(path), "spheres", {}) as w:
            write_snapshot(w, snap, points=pts)
        _rewrite(path, name, value)
        msg = _one_line(match, verify_dump, str(path))
        assert str(path) in msg
    # a version-2 dump with a points group: not what a writer makes
    path = tmp_path / "v2.h5"
    with DumpWriter(str(path), "spheres", {}) as w:
        write_snapshot(w, snap)
    _rewrite(path, "points/gap", np.zeros(3))
    _one_line(r"holds points/ but the dump says schema version 2", verify_dump, str(path))
    # a point field missing in the file
    path = tmp_path / "missing.h5"
    with DumpWriter(str(path), "spheres", {}) as w:
        write_snapshot(w, snap, points=pts)
    with h5py.File(path, "r+") as f:
        del f["snapshots/000000/points/gap"]
    _one_line(r"snapshot 000000 (does not match its index row|points: missing gap)", verify_dump, str(path))


def test_a_run_with_points_resumes(tmp_path):
    snap, _, _ = lattice_snapshot()
    pts = lattice_points(snap)
    path = str(tmp_path / "cd.h5")
    w = DumpWriter(path, "spheres", {})
    for k in range(3):
        write_snapshot(w, snap, step=k, points=pts)
    del w                                              # died: never closed
    w = DumpWriter.resume(path, 2)
    write_snapshot(w, snap, step=7, points=pts)
    w.close()
    with DumpReader(path) as r:
        assert r.version == 3 and [s.step for s in r] == [0, 1, 7]
        np.testing.assert_array_equal(r.read(2).points["gap"], pts["gap"])
