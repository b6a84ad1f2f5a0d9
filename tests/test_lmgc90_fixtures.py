"""LMGC90's own count (postproc.lmgc90count.lmgc90_points, --types lmgc90
and lmgc90-planplan) against LMGC90's compiled code.

The fixtures (tests/data/lmgc90, made by make_fixtures.py with the
compas_lmgc90 0.1.11 wheel; the suite does not need the wheel) hold the
interactions LMGC90's CpCundall detection stores at a first step: hand-built
pairs (cubes face on face, flush and tilted, edge on face, vertex on face,
crossed edges, near misses within and beyond the alert distance) and two
snapshots of the default study's 1000-grain S1 (seed 1), each at two alert
distances, for today's default point stage ("new") and the older planplan
route ("old").

Tolerances. Counts: every hand-built case exactly; at least 98 % of the
packing pairs (the issue's bar). Where LMGC90's arithmetic is reproduced the
numbers agree to round-off: gaps 1e-12 m, normals 1e-9 rad (grains of 1-5 cm,
double precision: 1e-16 relative). Contact points of the planplan stage pass
through Clipper2, which rounds coordinates to a grid of 1e-8 m (8 decimals):
a point may move by half a grid step in each coordinate in LMGC90 and in
ours, so points agree within 2e-8 m. In a packing some pairs sit on a tie of
Cundall's search (a face lying on the common plane: several vertices at the
same height): there the outcome is decided by round-off, and LMGC90 itself
changes its count on about 1 % of the pairs when the vertices move by
1e-12 m (docs/lmgc90-contacts.md). Where the counts agree, the points, gaps
and normal agree to round-off on about 93 % of the pairs (checked: at least
90 %); on the others the two searches took different paths through such a
tie and end on planes that differ by less than the search's last step
(theta_min = 0.0017 rad), checked on at least 97 % of them.
"""
import collections
import json
import os

import numpy as np
import pytest
from scipy.spatial import cKDTree

from postproc import lmgc90count as lmgc
from postproc import lmgc90shape as lshape
from postproc.classify import Classifier, check_options
from postproc.contacttypes import PAIR_TYPES
from postproc.errors import InputError
from postproc.schema import Snapshot

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "lmgc90")
ROUTES = {"new": "lmgc90", "old": "lmgc90-planplan"}
TOL_POINT = 2e-8           # m: Clipper2's 1e-8 grid, in LMGC90 and in ours
TOL_GAP = 1e-12            # m: round-off on 1-5 cm grains
TOL_NORMAL = 1e-9          # rad: round-off
THETA_MIN = 0.0017         # rad: the last step of Cundall's search
PACKINGS = sorted(f for f in os.listdir(HERE) if f.startswith("packing-") and f.endswith(".npz"))


def _load(name):
    with np.load(os.path.join(HERE, name)) as f:
        return {k: f[k] for k in f.files}


def _shapes(F):
    vo, to = F["shape_vertex_offsets"], F["shape_triangle_offsets"]
    return [lshape.lmgc90_shape(F["shape_vertices"][vo[i]:vo[i + 1]], F["shape_triangles"][to[i]:to[i + 1]])
            for i in range(len(vo) - 1)]


def _same_points(P, Q, tol):
    """Every point of P within tol of a point of Q and back."""
    if len(P) != len(Q):
        return False
    if not len(P):
        return True
    D = np.linalg.norm(P[:, None] - Q[None], axis=2)
    return D.min(axis=1).max() <= tol and D.min(axis=0).max() <= tol


def _quat(M):
    """(w, x, y, z) of a rotation matrix."""
    from scipy.spatial.transform import Rotation
    x, y, z, w = Rotation.from_matrix(M).as_quat()
    return np.array([w, x, y, z])


def _angle(a, b):
    """The angle between two vectors, rad, accurate near 0 (atan2 of the
    cross and dot products; arccos of the dot loses half the digits)."""
    return float(np.arctan2(np.linalg.norm(np.cross(a, b)), np.dot(a, b)))


def test_provenance_of_the_fixtures():
    for name in ["pairs.npz"] + PACKINGS:
        prov = json.loads(str(_load(name)["provenance"]))
        assert prov["wheel"] == "compas_lmgc90==0.1.11"
        assert len(prov["library_sha256"]) == 64
        assert prov["detection"].startswith("CpCundall")
        assert prov["cundall_iterations"] == lmgc.LMGC90_ITERATIONS
    assert len(PACKINGS) >= 2


F_PAIRS = _load("pairs.npz")
CASES = [str(x) for x in F_PAIRS["names"]]


@pytest.mark.parametrize("route", sorted(ROUTES))
@pytest.mark.parametrize("case", CASES)
def test_hand_built_pairs(case, route):
    """Every hand-built pair: LMGC90's number of points, the points, their
    gaps and the normal."""
    F = F_PAIRS
    shapes = _shapes(F)
    ci = CASES.index(case)
    alert = float(F["alert"])
    rows = np.flatnonzero(F["body_case"] == ci)
    bodies = [lmgc._Body(shapes[F["body_shape"][k]], F["body_R"][k], F["body_x"][k]) for k in rows]
    m = (F["lmgc_case"] == ci) & (F["lmgc_route"] == route)
    assert set(F["lmgc_cd"][m]) <= {1} and set(F["lmgc_an"][m]) <= {2}   # candidate: the lower number
    r = lmgc.lmgc90_pair(bodies[0], bodies[1], alert, route=ROUTES[route])
    assert len(r["points"]) == m.sum()
    assert _same_points(F["lmgc_point"][m], r["points"], TOL_POINT)
    assert np.allclose(np.sort(F["lmgc_gap"][m]), np.sort(r["gaps"]), rtol=0, atol=TOL_GAP)
    for n in F["lmgc_n"][m]:
        assert _angle(n, r["normal"]) <= TOL_NORMAL
    # the same through the block path the analysis uses
    R = F["body_R"][rows]
    q = np.array([_quat(M) for M in R])
    v = lmgc.lmgc90_points(shapes, F["body_shape"][rows[:1]], F["body_x"][rows[:1]], q[:1],
                         F["body_shape"][rows[1:2]], F["body_x"][rows[1:2]], q[1:2], alert, route=ROUTES[route])
    assert v["points"].tolist() == [m.sum()]
    assert _same_points(F["lmgc_point"][m], v["xyz"][0], TOL_POINT)
    assert np.allclose(np.sort(F["lmgc_gap"][m]), np.sort(v["gaps"][0]), rtol=0, atol=TOL_GAP)


def test_hand_built_counts_are_the_expected_geometry():
    """The compiled code's counts themselves (what the cases are for):
    today's stage gives 4 / 2 / 1 / 1 points for face, edge, vertex on a
    face and crossed edges, the planplan stage 4 or nothing."""
    F = F_PAIRS
    count = lambda case, route: int(np.sum((F["lmgc_case"] == CASES.index(case)) & (F["lmgc_route"] == route)))
    expect = {"face on face, flush": (4, 4), "edge on face": (2, 0), "vertex on face": (1, 0),
              "crossed edges": (1, 0), "face on face, within alert": (4, 4), "face on face, beyond alert": (0, 0),
              "vertex on face, within alert": (1, 0), "vertex on face, beyond alert": (0, 0)}
    for case, (new, old) in expect.items():
        assert (count(case, "new"), count(case, "old")) == (new, old), case


def _dumped_pairs(F):
    idx = {int(i): k for k, i in enumerate(F["body_ids"])}
    out = set()
    for a, b in zip(F["contact_id1"], F["contact_id2"]):
        if int(a) in idx and int(b) in idx:
            i, j = idx[int(a)], idx[int(b)]
            out.add((min(i, j), max(i, j)))
    return out


@pytest.mark.slow
@pytest.mark.parametrize("route", sorted(ROUTES))
@pytest.mark.parametrize("alert", [0, 1])
@pytest.mark.parametrize("packing", PACKINGS)
def test_packing_pairs(packing, alert, route):
    """A 1000-grain packing: the count equals LMGC90's on at least 98 % of
    the pairs (every pair LMGC90 finds and every dumped contact) and of the
    dumped contacts; where the counts agree, the points, gaps and normal
    agree to round-off on at least 90 % of the pairs and the normals within
    the search's last step on at least 97 %."""
    F = _load(packing)
    vo, to = F["shape_vertex_offsets"], F["shape_triangle_offsets"]
    tables = lshape.lmgc90_tables([F["shape_vertices"][vo[i]:vo[i + 1]] for i in range(len(vo) - 1)],
                              [F["shape_triangles"][to[i]:to[i + 1]] for i in range(len(to) - 1)])
    row = {s: k for k, s in enumerate(F["shape_rows"])}
    srow = np.array([row[s] for s in F["shape_index"]])
    assert tables.rmin == pytest.approx(float(F["r_min"]), rel=1e-12)
    adist = float(F["alerts"][alert])
    cd, an = F[f"{route}{alert}_cd"] - 1, F[f"{route}{alert}_an"] - 1
    assert np.all(cd < an)                                   # LMGC90's candidate: the lower number
    where = collections.defaultdict(list)
    for k, p in enumerate(zip(cd.tolist(), an.tolist())):
        where[p].append(k)
    dumped = _dumped_pairs(F)
    pairs = sorted(set(where) | dumped)
    i, j = np.array(pairs).T
    x, q = F["positions"], F["orientations"]
    r = lmgc.lmgc90_points(tables, srow[i], x[i], q[i], srow[j], x[j], q[j], adist, route=ROUTES[route])
    equal, geometry, close = {}, [], []
    for k, p in enumerate(pairs):
        ks = where.get(p, [])
        equal[p] = r["points"][k] == len(ks)
        if equal[p] and ks:
            ang = _angle(F[f"{route}{alert}_n"][ks[0]], r["normal"][k])
            geometry.append(_same_points(F[f"{route}{alert}_point"][ks], r["xyz"][k], TOL_POINT)
                            and np.allclose(np.sort(F[f"{route}{alert}_gap"][ks]), np.sort(r["gaps"][k]),
                                            rtol=0, atol=TOL_GAP)
                            and ang <= TOL_NORMAL)
            close.append(ang <= THETA_MIN)
    assert np.mean([equal[p] for p in pairs]) >= 0.98
    assert np.mean([equal[p] for p in dumped]) >= 0.98
    assert np.mean(geometry) >= 0.90
    assert np.mean(close) >= 0.97


def _snapshot(F, k=None):
    """The dumped grain contacts of a packing fixture (the first k, with
    only their bodies and shapes, in the dump's order; or all) as a
    Snapshot, and the classifier's shapes (the fixture carries the rows of
    the dump's shapes that it uses)."""
    ids = F["body_ids"]
    idx = {int(i): r for r, i in enumerate(ids)}
    keep = [j for j, (a, b) in enumerate(zip(F["contact_id1"], F["contact_id2"])) if int(a) in idx and int(b) in idx]
    keep = keep[:k] if k else keep
    bodies = np.arange(len(ids))
    if k:
        bodies = np.unique([idx[int(x)] for j in keep for x in (F["contact_id1"][j], F["contact_id2"][j])])
    rows = {s: r for r, s in enumerate(F["shape_rows"])}
    srow = np.array([rows[s] for s in F["shape_index"][bodies]])
    used, shape_index = np.unique(srow, return_inverse=True)
    c = len(keep)
    snap = Snapshot(name="fixture", step=int(F["step"]), time=0.0, stage=str(F["stage"]), volume=1.0,
                    box_lo=np.zeros(3), box_hi=np.ones(3), wall_ids=np.zeros(0, np.int64), wall_forces=None,
                    body_ids=ids[bodies], positions=F["positions"][bodies], id1=F["contact_id1"][keep],
                    id2=F["contact_id2"][keep], point=np.zeros((c, 3)), force=np.zeros((c, 3)),
                    force_normal=np.zeros((c, 3)), normal=F["contact_normal"][keep],
                    body_kind=np.ones(len(bodies), np.int8), orientations=F["orientations"][bodies],
                    shape_index=shape_index.astype(np.int32), sizes=F["sizes"][bodies])
    swap = np.arange(c) % 2 == 1                           # id1/id2 order must not matter
    snap.id1, snap.id2 = np.where(swap, snap.id2, snap.id1), np.where(swap, snap.id1, snap.id2)
    vo, to = F["shape_vertex_offsets"], F["shape_triangle_offsets"]
    shapes = ([F["shape_vertices"][vo[i]:vo[i + 1]] for i in used],
              [F["shape_triangles"][to[i]:to[i + 1]] for i in used],
              [np.arange(to[i + 1] - to[i]) for i in used])
    return snap, shapes


@pytest.mark.slow
@pytest.mark.parametrize("route", sorted(ROUTES))
def test_classifier_groups_are_lmgc90s(route):
    """--types lmgc90 / lmgc90-planplan through the classifier, on every
    dumped contact of the last packing (id1, id2 in either order) at the
    fixture's default alert distance: the groups (simple, double, triple)
    are those of LMGC90's point counts on at least 98 % of the contacts
    (99.2 % and 99.6 % measured: the ties of docs/lmgc90-contacts.md)."""
    F = _load(PACKINGS[-1])
    snap, shapes = _snapshot(F)
    clf = Classifier(shapes, ROUTES[route], tolerance=float(F["alerts_rel"][0]))
    cl = clf.classify(snap, variants=False)
    assert cl.columns["ct_alert_m"] == pytest.approx(float(F["alerts"][0]), rel=1e-12)
    idx = {int(i): k for k, i in enumerate(F["body_ids"])}
    cnt = collections.Counter(zip((F[f"{route}0_cd"] - 1).tolist(), (F[f"{route}0_an"] - 1).tolist()))
    group = {"VV": 0, "VE": 0, "VF": 0, "EE": 0, "EF": 1, "FF": 2}
    ok = []
    for a, b, lab in zip(snap.id1, snap.id2, cl.labels):
        i, j = sorted((idx[int(a)], idx[int(b)]))
        n = cnt.get((i, j), 0)
        assert lab in PAIR_TYPES
        ok.append(group[lab] == (2 if n >= 3 else 1 if n == 2 else 0))
    assert len(ok) > 2000 and np.mean(ok) >= 0.98


@pytest.mark.parametrize("route", sorted(ROUTES))
def test_classifier_labels_and_variants(route):
    """The classifier's labels are lmgc90_points' pair types with LMGC90's
    candidate (the lower body number) whatever the order of id1, id2, at
    the alert distance and at half and twice it (40 dumped contacts)."""
    F = _load(PACKINGS[-1])
    small, shapes = _snapshot(F, 40)
    idx = {int(i): k for k, i in enumerate(small.body_ids)}
    clf = Classifier(shapes, ROUTES[route], tolerance=float(F["alerts_rel"][0]))
    cl = clf.classify(small, variants=True)
    tables = clf.lmgc90_tables
    alert = float(F["alerts_rel"][0]) * tables.rmin
    i1 = np.array([idx[int(a)] for a in small.id1])
    i2 = np.array([idx[int(b)] for b in small.id2])
    lo, hi = np.minimum(i1, i2), np.maximum(i1, i2)
    x, q, s = small.positions, small.orientations, small.shape_index
    for tag, f in (("base", 1.0), ("lo", 0.5), ("hi", 2.0)):
        r = lmgc.lmgc90_points(tables, s[lo], x[lo], q[lo], s[hi], x[hi], q[hi], f * alert, route=ROUTES[route])
        labels = cl.labels if tag == "base" else cl.variants[tag]
        assert labels.tolist() == np.array(PAIR_TYPES)[r["pair"]].tolist()


@pytest.mark.parametrize("route", lmgc.LMGC90_ROUTES)
def test_several_alerts_at_once_are_each_alert_alone(route):
    """lmgc90_points_alerts (one detection for the band test's three
    alert distances, given out of order) gives, value for value, what
    lmgc90_points gives at each alert distance alone, on every fifth pair
    of the last packing that LMGC90 finds or YADE dumped (all touching:
    kept at every alert distance) and every tenth of the other pairs whose
    bounding spheres overlap (some kept only at the larger distances, so
    the pairs kept per alert distance are exercised)."""
    F = _load(PACKINGS[-1])
    vo, to = F["shape_vertex_offsets"], F["shape_triangle_offsets"]
    tables = lshape.lmgc90_tables([F["shape_vertices"][vo[i]:vo[i + 1]] for i in range(len(vo) - 1)],
                              [F["shape_triangles"][to[i]:to[i + 1]] for i in range(len(to) - 1)])
    row = {s: k for k, s in enumerate(F["shape_rows"])}
    srow = np.array([row[s] for s in F["shape_index"]])
    x, q = F["positions"], F["orientations"]
    known = set(zip((F["new1_cd"] - 1).tolist(), (F["new1_an"] - 1).tolist())) | _dumped_pairs(F)
    radius = np.array([tables[k].radius for k in srow])
    near = cKDTree(x).query_pairs(2 * radius.max(), output_type="ndarray")
    near = np.sort(near[np.linalg.norm(x[near[:, 0]] - x[near[:, 1]], axis=1)
                        < radius[near[:, 0]] + radius[near[:, 1]]], axis=1)
    others = sorted(set(map(tuple, near.tolist())) - known)
    i, j = np.array(sorted(known)[::5] + others[::10]).T
    args = (tables, srow[i], x[i], q[i], srow[j], x[j], q[j])
    a = float(F["alerts"][0])
    alerts = [a, 2 * a, a / 2]
    together = lmgc.lmgc90_points_alerts(*args, alerts, route=route)
    assert len(together) == 3
    same = lambda u, v: u.dtype == v.dtype and u.shape == v.shape and u.tobytes() == v.tobytes()
    for alert, got in zip(alerts, together):
        alone = lmgc.lmgc90_points(*args, alert, route=route)
        assert sorted(got) == sorted(alone)
        for key in alone:
            if key in ("xyz", "gaps"):
                assert len(got[key]) == len(alone[key]) == len(i)
                assert all(same(u, v) for u, v in zip(got[key], alone[key])), key
            else:
                assert same(got[key], alone[key]), key
    contacts = [int(np.sum(r["stage"] >= 0)) for r in together]
    assert contacts[2] < contacts[0] < contacts[1]
    # each alert distance's points are arrays of its own
    assert not any(u is v for u, v in zip(together[0]["xyz"], together[1]["xyz"]))
    with pytest.raises(InputError, match="no alert distance"):
        lmgc.lmgc90_points_alerts(*args, [], route=route)
    for bad in ([a, -a], [a, float("nan")], [10 ** 400], "12", a, [[a]]):
        with pytest.raises(InputError, match="alert"):
            lmgc.lmgc90_points_alerts(*args, bad, route=route)


def test_options_and_bad_input():
    check_options("lmgc90", tolerance=0.05)
    check_options("lmgc90-planplan")
    for bad in (0.0, -1.0, float("nan")):
        with pytest.raises(InputError, match="alert distance"):
            check_options("lmgc90", tolerance=bad)
    F = F_PAIRS
    tables = _shapes(F)
    one = lambda v: np.array([v], float)
    args = (np.array([0]), one(np.zeros(3)), one([1.0, 0, 0, 0]), np.array([1]), one([0.0, 0, 0.05]),
            one([1.0, 0, 0, 0]))
    with pytest.raises(InputError, match="route"):
        lmgc.lmgc90_points(tables, *args, 1e-5, route="lmgc")
    with pytest.raises(InputError, match="out of range"):
        lmgc.lmgc90_points(tables, np.array([99]), *args[1:], 1e-5)
    with pytest.raises(InputError, match="not finite"):
        lmgc.lmgc90_points(tables, args[0], one([np.nan, 0, 0]), *args[2:], 1e-5)
    with pytest.raises(InputError, match="coincide"):
        lmgc.lmgc90_points(tables, args[0], args[1], args[2], args[3], one(np.zeros(3)), args[5], 1e-5)
    with pytest.raises(InputError, match="alert"):
        lmgc.lmgc90_points(tables, *args, 0.0)
    r = lmgc.lmgc90_points(tables, *args, 1e-5)               # far apart: no point, counted simple
    assert r["points"].tolist() == [0] and r["stage"].tolist() == [-1]


@pytest.mark.slow
def test_cli_analyze_with_lmgc90s_count(tmp_path, capsys):
    """postproc analyze --types lmgc90: the summary names the count, its
    alert distance (units of the smallest grain radius, and in metres) and
    the groups of the hand-built contacts (cube and tetrahedron pairs at an
    overlap of 1e-3 d); a bad alert distance gets one line, exit 2."""
    import pandas as pd

    from builders import snapshot_dicts, write_snapshot
    from postproc.cli import main
    from shapes.polyhedron import geometric_faces
    from postproc.schema import DumpWriter
    from test_footprint_types import CASES as KCASES, SHAPES, _pairs, _snapshot as kernel_snapshot

    snap = kernel_snapshot(_pairs(list(KCASES.values()), 1e-3))
    snap.volumes = np.ones(len(snap.body_ids))
    snap.masses = np.ones(len(snap.body_ids))
    snap.wall_forces = np.zeros((6, 3))
    path = str(tmp_path / "k.h5")
    with DumpWriter(path, "polyhedra", {}) as w:
        w.write_shapes([v for v, _ in SHAPES], [t for _, t in SHAPES], [geometric_faces(v, t) for v, t in SHAPES])
        for step, stage in ((0, "isotropic"), (1, "shear")):
            write_snapshot(w, snap, step=step, stage=stage, contacts=snapshot_dicts(snap)[1])
    for types in ("lmgc90", "lmgc90-planplan"):
        out = tmp_path / types
        assert main(["analyze", path, "--out", str(out), "--types", types, "--no-errors", "--no-figures"]) == 0
        s = pd.read_csv(out / "summary.csv")
        assert (s["ct_method"] == types).all() and (s["ct_threshold"] == lmgc.DEFAULT_ALERT).all()
        r_min = lshape.lmgc90_tables([v for v, _ in SHAPES], [t for _, t in SHAPES]).rmin
        assert s["ct_alert_m"].iloc[0] == pytest.approx(lmgc.DEFAULT_ALERT * r_min, rel=1e-12)
        fr = s[[c for c in s.columns if c.startswith("ct_frac_")]].iloc[-1]
        assert fr[["ct_frac_simple", "ct_frac_double", "ct_frac_triple"]].sum() == pytest.approx(1.0)
    capsys.readouterr()
    assert main(["analyze", path, "--out", str(tmp_path / "bad"), "--types", "lmgc90", "--tolerance", "0"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "alert distance" in err[0]
    assert not (tmp_path / "bad").exists()


def test_agreement_command_needs_its_fixtures(tmp_path, capsys):
    """``postproc lmgc90-agreement`` says in one line when its fixture
    folder holds no packing, and writes nothing. (The whole table takes
    about a minute; the counts it tabulates are checked pair by pair by
    test_packing_pairs above.)"""
    from postproc.cli import main

    assert main(["investigate", "lmgc90-agreement", "--fixtures", str(tmp_path), "--out", str(tmp_path / "o")]) == 2
    assert "no packing-*.npz fixture" in capsys.readouterr().err
    assert main(["investigate", "lmgc90-agreement", "--fixtures", str(tmp_path / "none"), "--out", str(tmp_path / "o")]) == 2
    assert capsys.readouterr().err.count("\n") == 1 and not (tmp_path / "o").exists()
