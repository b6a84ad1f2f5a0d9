"""LMGC90's common-plane count of contact points (postproc.commonplane) on
hand-built pairs with exact answers: cube and tetrahedron faces, edges and
vertices on a cube face, crossed edges; flush cubes at a gap just inside and
just outside the alert distance; a cube face tilted just inside and just
outside the band tau * ref; rigid motions and swapped sides; bad input."""
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from postproc import commonplane as cp
from postproc.contactpoints import DOUBLE, SIMPLE, TRIPLE
from postproc.contacttypes import EDGE, FACE, PAIR_TYPES, VERTEX
from postproc.errors import InputError
from test_contact_points import _arrays
from test_contact_types import quat_from_matrix, rot
from test_footprint_types import CASES, I3, SHAPES, _pairs

TABLES = cp.plane_tables([v for v, _ in SHAPES], [t for _, t in SHAPES])
# name: (points, group, pair); the tetrahedron's face is wider than the
# cube's: their intersection has more than 4 corners, LMGC90 keeps 4
EXPECT = {
    "cube face on cube face": (4, TRIPLE, "FF"),
    "cube edge on cube face": (2, DOUBLE, "EF"),
    "cube vertex on cube face": (1, SIMPLE, "VF"),
    "crossed cube edges": (1, SIMPLE, "EE"),
    "tetrahedron vertex on cube face": (1, SIMPLE, "VF"),
    "tetrahedron edge on cube face": (2, DOUBLE, "EF"),
    "tetrahedron face on cube face": (4, TRIPLE, "FF"),
}
EPS = 1e-9          # relative margin about a threshold: far above round-off (1e-16), far below any geometry


def _run(pairs, **kw):
    a = _arrays(pairs)
    return cp.contact_points(TABLES, *a[:7], **kw)


@pytest.mark.parametrize("depth", [1e-4, 1e-3, 1e-2])
@pytest.mark.parametrize("iterations", [0, 100])
def test_known_pairs(depth, iterations):
    """From the kernel's normal, with or without Cundall's search: the
    geometric count, with overlaps of 1e-4 d to 1e-2 d."""
    names = list(EXPECT)
    r = _run(_pairs([CASES[k] for k in names], depth), iterations=iterations)
    assert r["points"].tolist() == [EXPECT[k][0] for k in names]
    assert r["group"].tolist() == [EXPECT[k][1] for k in names]
    assert [PAIR_TYPES[p] for p in r["pair"]] == [EXPECT[k][2] for k in names]
    assert np.all(r["gap"] < 0)


def _cubes(Rb, xb, normal=(0.0, 0.0, 1.0)):
    """contact_points arguments for cube A at the origin and cube B at xb."""
    one = lambda v: np.array([v], float)
    return (np.array([0]), one(np.zeros(3)), one(quat_from_matrix(I3)), np.array([0]), one(xb),
            one(quat_from_matrix(Rb)), one(normal))


@pytest.mark.parametrize("gap", [1e-3, 1e-6])
def test_flush_cubes_at_the_alert_distance(gap):
    """Two aligned cubes a gap apart: 4 points when the gap is within the
    alert distance, none just beyond it; the gap itself is exact."""
    args = _cubes(I3, [0.0, 0.0, 1.0 + gap])
    r_in = cp.contact_points(TABLES, *args, alert=gap * (1 + EPS))
    r_out = cp.contact_points(TABLES, *args, alert=gap * (1 - EPS))
    assert r_in["gap"][0] == pytest.approx(gap, rel=1e-12, abs=1e-15)
    assert r_in["points"].tolist() == [4] and r_in["group"].tolist() == [TRIPLE]
    assert r_out["points"].tolist() == [0]
    # no alert distance: the pair is counted whatever the gap (a dumped contact)
    assert cp.contact_points(TABLES, *args)["points"].tolist() == [4]


@pytest.mark.parametrize("reference, ref", [("vertex", np.sqrt(3) / 2), ("normal", 0.5)])
@pytest.mark.parametrize("depth", [0.0, 1e-3])
@pytest.mark.parametrize("tau", [0.05, 0.1, 0.2])
def test_tilted_face_at_the_band(reference, ref, depth, tau):
    """Cube B tilted by phi about x, resting on its lowest edge dipping
    ``depth`` into A's top face: its bottom face's far edge stands sin(phi)
    above the lowest; it is kept when sin(phi) <= tau ref + depth / 2
    (ref: the centre-to-corner distance sqrt(3)/2, or 1/2 along n)."""
    s_star = tau * ref + depth / 2
    out = []
    for s in (s_star * (1 - EPS), s_star * (1 + EPS)):
        Rb = rot([1, 0, 0], np.degrees(np.arcsin(s)))
        low = -(SHAPES[0][0] @ Rb.T)[:, 2].min()
        r = cp.contact_points(TABLES, *_cubes(Rb, [0.0, 0.0, 0.5 + low - depth]), neighbor=tau,
                              reference=reference, iterations=0)
        assert r["gap"][0] == pytest.approx(-depth, abs=1e-12)
        out.append((r["points"][0], r["group"][0], PAIR_TYPES[r["pair"][0]], r["k2"][0]))
    assert out == [(4, TRIPLE, "FF", 4), (2, DOUBLE, "EF", 2)]


def test_cundall_search_finds_the_face_normal():
    """Started 4 degrees off, the search turns the plane back onto the face
    normal of a face-face pair (to its last step, 0.0017 / 2 rad), and the
    count is unchanged."""
    n0 = rot([1, 1, 0], 4.0) @ [0.0, 0.0, 1.0]
    args = _cubes(I3, [0.1, 0.2, 1.0 - 1e-3], n0)
    r = cp.contact_points(TABLES, *args)
    assert np.arccos(min(1.0, r["normal"][0] @ [0, 0, 1])) < cp.THETA_MIN
    assert r["points"].tolist() == [4]


def test_features():
    """Kept vertices: 1 vertex, 2 joined by an edge, 3+ face."""
    names = list(EXPECT)
    r = _run(_pairs([CASES[k] for k in names], 1e-3))
    f = {VERTEX: "V", EDGE: "E", FACE: "F"}
    got = ["".join(sorted(f[a] + f[b])) for a, b in zip(r["feature1"], r["feature2"])]
    assert got == ["FF", "EF", "FV", "EE", "FV", "EF", "FF"]


def test_rigid_motion_and_swap():
    """The same counts under random rigid motions, and with A and B swapped
    (normal reversed, features swapped)."""
    rng = np.random.default_rng(7)
    names = list(EXPECT)
    base = _pairs([CASES[k] for k in names], 1e-3)
    ref = _run(base)
    for _ in range(5):
        R = Rotation.random(random_state=rng).as_matrix()
        x0 = rng.normal(size=3) * 10
        moved = [(sa, R @ Ra, R @ xa + x0, sb, R @ Rb, R @ xb + x0) for sa, Ra, xa, sb, Rb, xb in base]
        r = _run(moved)
        for k in ("points", "group", "pair", "feature1", "feature2", "k1", "k2"):
            assert r[k].tolist() == ref[k].tolist(), k
        assert np.allclose(r["gap"], ref["gap"], atol=1e-12)
        a = _arrays(moved)
        sw = cp.contact_points(TABLES, a[3], a[4], a[5], a[0], a[1], a[2], -a[6])
        for k1, k2 in (("points", "points"), ("group", "group"), ("pair", "pair"), ("feature1", "feature2"),
                       ("k1", "k2")):
            assert sw[k1].tolist() == ref[k2].tolist(), k1


def test_bad_input():
    args = list(_cubes(I3, [0.0, 0.0, 1.0]))
    bad = [dict(neighbor=0), dict(neighbor=np.nan), dict(reference="x"), dict(iterations=-1),
           dict(alert=np.inf)]
    for kw in bad:
        with pytest.raises(InputError) as e:
            cp.contact_points(TABLES, *args, **kw)
        assert "\n" not in str(e.value)
    for i, v in ((0, np.array([5])), (6, np.array([[0.0, 0.0, 2.0]])), (1, np.array([[np.nan, 0, 0]])),
                 (2, np.zeros((1, 4)))):
        a = list(args)
        a[i] = v
        with pytest.raises(InputError) as e:
            cp.contact_points(TABLES, *a)
        assert "\n" not in str(e.value)
    with pytest.raises(InputError):
        cp.plane_tables([np.zeros((3, 3))], [np.array([[0, 1, 2]])])


def test_classifier_commonplane():
    """``--types commonplane``: the labels of a snapshot of the known pairs,
    at tau and at its half and double (no overlap needed)."""
    from postproc.classify import Classifier
    from shapes.polyhedron import geometric_faces
    from test_footprint_types import _snapshot
    shapes = [(v, t, geometric_faces(v, t)) for v, t in SHAPES]
    clf = Classifier(tuple(map(list, zip(*shapes))), method="commonplane")
    assert clf.parameter == cp.DEFAULT_NEIGHBOR
    names = list(EXPECT)
    res = clf.classify(_snapshot(_pairs([CASES[k] for k in names], 1e-3)))
    want = [EXPECT[k][2] for k in names]
    assert res.labels[res.poly].tolist() == want
    assert res.variants["lo"][res.poly].tolist() == want == res.variants["hi"][res.poly].tolist()
    assert res.columns["ct_method"] == "commonplane" and res.columns["ct_cp_empty"] == 0.0


@pytest.mark.parametrize("reference, want", [("vertex", "FF"), ("normal", "EF")])
def test_classifier_measures_ref_as_asked(reference, want):
    """The classifier's ``reference``: cube B tilted so that its bottom face's
    far edge stands 0.07 above its lowest one (which dips 1e-3 into A's top
    face). The band at tau = 0.1 is 0.1 ref + 5e-4: 0.0871 with ref the
    centre-to-corner distance sqrt(3)/2 (the face is kept: face-face), 0.0505
    with ref = 1/2 along the normal (only the edge: edge-face)."""
    from postproc.classify import Classifier
    from shapes.polyhedron import geometric_faces
    from test_footprint_types import _snapshot
    shapes = [(v, t, geometric_faces(v, t)) for v, t in SHAPES]
    Rb = rot([1, 0, 0], np.degrees(np.arcsin(0.07)))
    low = -(SHAPES[0][0] @ Rb.T)[:, 2].min()
    snap = _snapshot([(0, I3, np.zeros(3), 0, Rb, np.array([0.0, 0.0, 0.5 + low - 1e-3]))])
    clf = Classifier(tuple(map(list, zip(*shapes))), method="commonplane", reference=reference)
    res = clf.classify(snap)
    assert res.labels[res.poly].tolist() == [want]
    with pytest.raises(InputError) as e:
        Classifier(tuple(map(list, zip(*shapes))), method="commonplane", reference="centre")
    assert "reference" in str(e.value) and "\n" not in str(e.value)
