"""Contact types of polyhedra on hand-built pairs with known answers."""
import numpy as np
import pytest

from postproc.axes import rotation_z_to
from postproc.contacttypes import (EDGE, FACE, PAIR_TYPES, VERTEX, classify_contacts,
                                   classify_snapshot, shape_tables)
from postproc.errors import InputError
from shapes.polyhedron import geometric_faces, hull

CUBE_PTS = np.array([[x, y, z] for x in (-.5, .5) for y in (-.5, .5) for z in (-.5, .5)])
PRISM_PTS = np.array([[x, y, z] for x in (-.5, .5) for (y, z) in ((-.5, -.3), (.5, -.3), (0, .4))])


def _shape(points):
    v, t = hull(points)
    return v, t, geometric_faces(v, t)


@pytest.fixture(scope="module")
def tables():
    shapes = [_shape(CUBE_PTS), _shape(PRISM_PTS)]
    return shape_tables(*zip(*shapes))


def quat_from_matrix(R):
    """(w, x, y, z) of a rotation matrix."""
    w = np.sqrt(max(0.0, 1 + np.trace(R))) / 2
    x = np.copysign(np.sqrt(max(0.0, 1 + R[0, 0] - R[1, 1] - R[2, 2])) / 2, R[2, 1] - R[1, 2])
    y = np.copysign(np.sqrt(max(0.0, 1 - R[0, 0] + R[1, 1] - R[2, 2])) / 2, R[0, 2] - R[2, 0])
    z = np.copysign(np.sqrt(max(0.0, 1 - R[0, 0] - R[1, 1] + R[2, 2])) / 2, R[1, 0] - R[0, 1])
    return np.array([w, x, y, z])


def rot(axis, deg):
    axis = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    a = np.radians(deg)
    return np.eye(3) + np.sin(a) * K + (1 - np.cos(a)) * K @ K


I3 = np.eye(3)
CORNER_DOWN = rotation_z_to(-np.array([1.0, 1.0, 1.0]) / np.sqrt(3)).T   # maps the (1,1,1) corner to -z
CASES = {
    # name: (shape1, R1, shape2, R2, expected pair); id1 below, id2 above, normal +z
    "face-face": (0, I3, 0, I3, "FF"),
    "edge-face": (0, I3, 0, rot([1, 0, 0], 45), "EF"),
    "vertex-face": (0, I3, 0, CORNER_DOWN, "VF"),
    "edge-edge": (0, rot([1, 0, 0], 45), 0, rot([0, 1, 0], 45), "EE"),
    "prism edges crossed": (1, I3, 1, rot([0, 0, 1], 90) @ rot([1, 0, 0], 180), "EE"),
    "prism edge on cube face": (0, I3, 1, rot([1, 0, 0], 180), "EF"),
}


def _classify(tables, cases, normal=None, theta=5.0):
    s1 = np.array([c[0] for c in cases])
    s2 = np.array([c[2] for c in cases])
    q1 = np.array([quat_from_matrix(c[1]) for c in cases])
    q2 = np.array([quat_from_matrix(c[3]) for c in cases])
    n = np.tile([0.0, 0.0, 1.0], (len(cases), 1)) if normal is None else normal
    return classify_contacts(tables, s1, s2, q1, q2, n, theta)


def test_known_pairs(tables):
    cases = list(CASES.values())
    f1, f2, pair = _classify(tables, cases)
    assert [PAIR_TYPES[p] for p in pair] == [c[4] for c in cases]
    # the corner really points down: the lowest vertex is unique
    v = CUBE_PTS @ CORNER_DOWN.T
    assert np.sum(np.isclose(v[:, 2], v[:, 2].min())) == 1


def test_rigid_motion_and_order_invariance(tables):
    cases = list(CASES.values())
    rng = np.random.default_rng(0)
    for _ in range(5):
        Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        Q *= np.sign(np.linalg.det(Q))
        moved = [(c[0], Q @ c[1], c[2], Q @ c[3], c[4]) for c in cases]
        n = np.tile(Q @ [0.0, 0.0, 1.0], (len(cases), 1))
        _, _, pair = _classify(tables, moved, n)
        assert [PAIR_TYPES[p] for p in pair] == [c[4] for c in cases]
        # id1 <-> id2 with the normal reversed
        swapped = [(c[2], c[3], c[0], c[1], c[4]) for c in moved]
        _, _, pair = _classify(tables, swapped, -n)
        assert [PAIR_TYPES[p] for p in pair] == [c[4] for c in cases]
        # contact order
        perm = rng.permutation(len(cases))
        _, _, pair = _classify(tables, [moved[k] for k in perm], n[perm])
        assert [PAIR_TYPES[p] for p in pair] == [cases[k][4] for k in perm]


def test_normal_tilt_within_and_beyond_the_tolerance(tables):
    """A face-face contact whose normal is tilted (deep or sheared overlaps
    tilt YADE's normal) stays face-face within theta and is no longer
    face-face beyond it."""
    ff = [CASES["face-face"]]
    for tilt, expected in ((2.0, "FF"), (4.9, "FF"), (10.0, None)):
        n = (rot([1, 0.3, 0], tilt) @ [0.0, 0.0, 1.0])[None, :]
        _, _, pair = _classify(tables, ff, n, theta=5.0)
        if expected:
            assert PAIR_TYPES[pair[0]] == expected
        else:
            assert PAIR_TYPES[pair[0]] != "FF"


def test_tolerance_sensitivity_is_monotonic(tables):
    """Doubling theta can only turn vertices into edges/faces and edges
    into faces."""
    rng = np.random.default_rng(3)
    n = 2000
    R1 = [rot(rng.normal(size=3), rng.uniform(0, 180)) for _ in range(n)]
    R2 = [rot(rng.normal(size=3), rng.uniform(0, 180)) for _ in range(n)]
    cases = [(rng.integers(2), a, rng.integers(2), b, None) for a, b in zip(R1, R2)]
    counts = []
    for theta in (2.5, 5.0, 10.0):
        f1, f2, _ = _classify(tables, cases, theta=theta)
        counts.append(np.bincount(np.concatenate([f1, f2]), minlength=3))
        if theta > 2.5:
            assert np.all(f1 >= prev1) and np.all(f2 >= prev2)
        prev1, prev2 = f1, f2
    assert counts[0][VERTEX] > counts[2][VERTEX] and counts[0][FACE] < counts[2][FACE]
    assert counts[1][EDGE] > 0


def _snapshot(tables, cases):
    from postproc.schema import Snapshot

    k = len(cases)
    ids = np.arange(2 * k) + 6
    q = np.array([quat_from_matrix(R) for c in cases for R in (c[1], c[3])])
    shape_index = np.array([s for c in cases for s in (c[0], c[2])])
    pos = np.array([[3.0 * i, 0, z] for i in range(k) for z in (0.0, 1.0)])
    return Snapshot(name="000000", step=0, time=0.0, stage="shear", volume=1.0, box_lo=np.zeros(3),
                    box_hi=np.ones(3), wall_ids=np.arange(6), wall_forces=None, body_ids=ids,
                    positions=pos, id1=ids[0::2].copy(), id2=ids[1::2].copy(), point=pos[0::2] + [0, 0, 0.5],
                    force=np.tile([0.0, 0, 1], (k, 1)), force_normal=np.tile([0.0, 0, 1], (k, 1)),
                    normal=np.tile([0.0, 0, 1], (k, 1)), body_kind=np.ones(2 * k, np.int8),
                    orientations=q, shape_index=shape_index, sizes=np.ones(2 * k))


def test_snapshot_classes_and_bad_input(tables):
    cases = list(CASES.values())
    snap = _snapshot(tables, cases)
    assert classify_snapshot(snap, tables).tolist() == [c[4] for c in cases]
    snap.body_kind[0] = 0
    assert classify_snapshot(snap, tables)[0] == "sphere"
    snap.body_kind[0] = 1
    snap.id2[1] = 0                                    # a wall
    snap.wall_ids = np.arange(6)
    assert classify_snapshot(snap, tables)[1] == "wall"
    snap = _snapshot(tables, cases)
    snap.shape_index[3] = -1
    with pytest.raises(InputError, match="polyhedron 9 of contact 1 has no shape"):
        classify_snapshot(snap, tables)
    snap.shape_index[3] = 7
    with pytest.raises(InputError, match="shape index 7 out of range"):
        classify_snapshot(snap, tables)
    snap = _snapshot(tables, cases)
    snap.normal[2] = [0.0, 0.0, 0.0]
    with pytest.raises(InputError, match="contact 2 has a degenerate normal"):
        classify_snapshot(snap, tables)


def test_tiny_and_deep_overlaps_classify_alike(tables):
    """The criterion uses orientations and the normal only, so a pair with a
    tiny (1e-9 d) or deep (0.3 d) overlap gets the same type."""
    cases = list(CASES.values())
    ref = classify_snapshot(_snapshot(tables, cases), tables).tolist()
    for depth in (1e-9, 0.3):
        snap = _snapshot(tables, cases)
        snap.positions[1::2, 2] -= depth
        snap.point[:, 2] -= depth / 2
        assert classify_snapshot(snap, tables).tolist() == ref == [c[4] for c in cases]


def test_threaded_blocks_match_one_thread(tables, monkeypatch):
    from postproc import contacttypes

    rng = np.random.default_rng(5)
    n = 5 * contacttypes._BLOCK + 17
    s1, s2 = rng.integers(2, size=n), rng.integers(2, size=n)
    q1, q2 = rng.normal(size=(n, 4)), rng.normal(size=(n, 4))
    nn = rng.normal(size=(n, 3))
    nn /= np.linalg.norm(nn, axis=1)[:, None]
    monkeypatch.setattr(contacttypes, "_THREADS", 1)
    one = classify_contacts(tables, s1, s2, q1, q2, nn)
    monkeypatch.setattr(contacttypes, "_THREADS", 3)
    many = classify_contacts(tables, s1, s2, q1, q2, nn)
    for a, b in zip(one, many):
        assert np.array_equal(a, b)
    assert len(np.unique(one[2])) >= 4


def test_random_types_command(tmp_path, capsys):
    """``postproc random-types`` on an 8-grain library: one line per
    tolerance, shares summing to 1, face-face growing with theta; the table
    is the classification of the first draws; a missing library: exit 2."""
    from postproc.cli import main
    from postproc.study.randomtypes import random_pairs, random_type_fractions
    from shapes.generate import Recipe, generate_library
    from shapes.library import ShapeLibrary, write_library

    path = str(tmp_path / "lib.h5")
    shapes, _ = generate_library(8, seed=5)
    write_library(path, shapes, 5, Recipe().as_dict(), {})
    assert main(["investigate", "random-types", "--library", path, "--pairs", "3000"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert [line.split(" deg")[0] for line in out] == ["theta  2.5", "theta  5.0", "theta 10.0"]
    lib = ShapeLibrary(path)
    tab = random_type_fractions(lib, pairs=3000)
    np.testing.assert_allclose(tab[list(PAIR_TYPES)].sum(axis=1), 1.0)
    assert np.all(np.diff(tab["FF"]) > 0)
    s1, s2, q1, q2, n = random_pairs(len(lib), 1_000_000)
    tables = shape_tables(*zip(*[lib[s] for s in range(len(lib))]))
    _, _, pair = classify_contacts(tables, s1[:3000], s2[:3000], q1[:3000], q2[:3000], n[:3000], 5.0)
    assert tab.loc[1, "FF"] == np.mean(np.array(PAIR_TYPES)[pair] == "FF")
    assert main(["investigate", "random-types", "--library", str(tmp_path / "none.h5")]) == 2
    assert "postproc: error:" in capsys.readouterr().err
