"""The paper's contact types read off CD contact points (postproc.cdpoints),
on hand-built snapshots with exact answers, and invariance under relabelling."""
import numpy as np
import pytest

from postproc.cdpoints import cd_labels, cd_type_columns, force_floor, group_of_count, points_per_pair
from postproc.errors import InputError
from postproc.schema import Snapshot

D = 0.01      # m, centre-to-centre distance of the pairs
V = 1e-3      # m^3


def four_pairs():
    """Eight grains in four pairs and one wall contact:

    A (bodies 10, 11, branch +x): 1 point, f_n 1 N               simple / simple
    B (12, 13, branch +y): 2 points, 2 + 2 N                     double / double
    C (14, 15, branch +z): 3 points, 3 + 3 + 0 N                 triple / double
    D (16, 17, branch +x): 2 points, both 0 N                    double / (none)
    W (wall 5 = z+ on body 15, normal +z): 1 point, 5 N

    Normals along the branch vectors, forces along the normals, so every
    number of claim 6 is known by hand."""
    pos = np.array([[0, 0, 0], [D, 0, 0], [0, 0.1, 0], [0, 0.1 + D, 0],
                    [0.2, 0, 0], [0.2, 0, D], [0.3, 0, 0], [0.3 + D, 0, 0]])
    ex, ey, ez = np.eye(3)
    id1 = np.array([10, 12, 14, 16, 15])
    id2 = np.array([11, 13, 15, 17, 5])
    normal = np.array([ex, ey, ez, ex, ez])
    pair_fn = np.array([1.0, 4.0, 6.0, 0.0, 5.0])
    point = np.array([pos[0] + D / 2 * ex, pos[2] + D / 2 * ey, pos[4] + D / 2 * ez, pos[6] + D / 2 * ex,
                      pos[5] + 0.004 * ez])
    rows = np.array([0, 1, 1, 2, 2, 2, 3, 3, 4])
    pfn = np.array([1.0, 2.0, 2.0, 3.0, 3.0, 0.0, 0.0, 0.0, 5.0])
    pts = {"contact": rows, "point": point[rows],
           "normal": normal[rows], "force_normal": pfn[:, None] * normal[rows],
           "force_tangential": np.zeros((9, 3)), "gap": np.array([-1e-6, 0, -2e-6, 0, 0, 3e-4, 1e-4, 2e-4, 0])}
    fn = pair_fn[:, None] * normal
    return Snapshot(name="000000", step=0, time=0.0, stage="shear", volume=V,
                    box_lo=np.full(3, -1.0), box_hi=np.full(3, 1.0), wall_ids=np.arange(6),
                    wall_forces=np.zeros((6, 3)), body_ids=np.arange(10, 18), positions=pos,
                    id1=id1, id2=id2, point=point, force=fn.copy(), force_normal=fn, normal=normal,
                    overlap=np.zeros(5), points=pts)


def test_counts_and_groups():
    snap = four_pairs()
    assert points_per_pair(snap.points["contact"], 5).tolist() == [1, 2, 3, 2, 1]
    assert group_of_count([0, 1, 2, 3, 4]).tolist() == ["none", "simple", "double", "triple", "triple"]
    lab = cd_labels(snap)
    assert lab["alert"].tolist() == ["simple", "double", "triple", "double", "wall"]
    assert lab["force"].tolist() == ["simple", "double", "double", "none", "wall"]
    assert lab["n_force"].tolist() == [1, 2, 2, 0, 1]
    # within an alert distance of 1.5e-4 m the 3e-4 m point of C and the 2e-4 m point of D drop out
    lab = cd_labels(snap, alert=1.5e-4)
    assert lab["alert"].tolist() == ["simple", "double", "double", "simple", "wall"]
    with pytest.raises(InputError, match="outside 0..4"):
        points_per_pair([0, 5], 5)


def test_claim6_quantities_by_hand():
    snap = four_pairs()
    row = cd_type_columns(snap)
    mean = 11 / 3                                   # force-bearing pairs A, B, C: 1, 4, 6 N
    assert row["cd_pairs"] == 3 and row["cd_pairs_all"] == 4
    assert row["cd_points"] == 9 and row["cd_points_carrying"] == 6
    assert row["cd_points_per_pair"] == pytest.approx(5 / 3, rel=1e-15)
    for g in ("simple", "double", "triple"):
        assert row[f"cd_alert_frac_{g}"] == pytest.approx(1 / 3, rel=1e-15)
    assert [row[f"cd_alert_frac_{g}_all"] for g in ("simple", "double", "triple")] == [0.25, 0.5, 0.25]
    assert [row[f"cd_force_frac_{g}"] for g in ("simple", "double", "triple")] == \
        pytest.approx([1 / 3, 2 / 3, 0.0], rel=1e-15)
    tol = dict(rel=1e-14)
    assert row["cd_alert_fratio_simple"] == pytest.approx(1 / mean, **tol)
    assert row["cd_alert_fratio_triple"] == pytest.approx(6 / mean, **tol)
    assert row["cd_force_fratio_double"] == pytest.approx(5 / mean, **tol)
    assert np.isnan(row["cd_force_fratio_triple"]) and row["cd_force_fshare_triple"] == 0.0
    assert row["cd_alert_fshare_triple"] == pytest.approx(6 / 11, **tol)
    # leaning (5/4)(3u^2 - 1): +x, +y -> -1.25, +z -> 2.5
    assert row["cd_alert_fabric_simple"] == pytest.approx(-1.25, **tol)
    assert row["cd_alert_fabric_triple"] == pytest.approx(2.5, **tol)
    assert row["cd_force_fabric_double"] == pytest.approx((-1.25 + 2.5) / 2, **tol)
    # strong network f_n > 11/3: B and C; triples among them
    assert row["cd_alert_strong_frac_triple"] == 0.5 and row["cd_alert_weak_frac_triple"] == 0.0
    assert row["cd_force_strong_frac_triple"] == 0.0
    # q/p shares by hand: sigma_g = sum f l / V; the wall contact's arm is its point minus body 15's centre
    s_xx, s_yy, s_zz = 1 * D / V, 4 * D / V, 6 * D / V
    s_wall = 5 * 0.004 / V
    p = (s_xx + s_yy + s_zz + s_wall) / 3
    q = {"simple": (0 - s_xx / 2) / 3, "double": (0 - s_yy / 2) / 3, "triple": s_zz / 3}
    for g in q:
        assert row[f"cd_alert_qp_{g}"] == pytest.approx(q[g] / p, **tol)
    assert row["cd_force_qp_double"] == pytest.approx((q["double"] + q["triple"]) / p, **tol)
    assert row["cd_force_qp_triple"] == 0.0


def test_the_force_floor_is_the_round_off_of_the_largest_force():
    eps = np.finfo(float).eps
    fn = np.array([1.0, 2.0, 2.0, 3.0, 3.0, 0.0, 0.0, 0.0, 5.0])
    assert force_floor(fn) == 9 * eps * 5.0
    assert force_floor(np.zeros(4)) == 0.0 and force_floor(-np.ones(2)) == 0.0
    # C's unloaded point given a force just above / below the floor
    for f, carried in ((2 * 9 * eps * 5.0, 3), (0.5 * 9 * eps * 5.0, 2)):
        s = four_pairs()
        s.points["force_normal"][5] = [0, 0, f]
        assert cd_labels(s)["n_force"][2] == carried


def _relabelled(snap, rng):
    """The same packing with the contact rows and the points shuffled, each
    pair's sides swapped at random (normals and forces flipped) and the
    bodies listed in another order."""
    nc, P = len(snap.id1), len(snap.points["contact"])
    perm = rng.permutation(nc)                        # new row k holds old row perm[k]
    inv = np.argsort(perm)
    pp = ~np.isin(snap.id2[perm], snap.wall_ids) & ~np.isin(snap.id1[perm], snap.wall_ids)
    swap = pp & (rng.random(nc) < 0.5)
    sign = np.where(swap, -1.0, 1.0)[:, None]
    id1 = np.where(swap, snap.id2[perm], snap.id1[perm])
    id2 = np.where(swap, snap.id1[perm], snap.id2[perm])
    q = rng.permutation(P)
    prow = inv[snap.points["contact"][q]]
    psign = sign[prow]
    pts = {"contact": prow, "point": snap.points["point"][q], "gap": snap.points["gap"][q]}
    for k in ("normal", "force_normal", "force_tangential"):
        pts[k] = psign * snap.points[k][q]
    b = rng.permutation(len(snap.body_ids))
    return Snapshot(name="000000", step=0, time=0.0, stage="shear", volume=snap.volume,
                    box_lo=snap.box_lo, box_hi=snap.box_hi, wall_ids=snap.wall_ids, wall_forces=snap.wall_forces,
                    body_ids=snap.body_ids[b], positions=snap.positions[b], id1=id1, id2=id2,
                    point=snap.point[perm], force=sign * snap.force[perm], force_normal=sign * snap.force_normal[perm],
                    normal=sign * snap.normal[perm], overlap=snap.overlap[perm], points=pts)


def test_invariant_under_relabelling():
    rng = np.random.default_rng(7)
    snap = four_pairs()
    want = cd_type_columns(snap)
    for _ in range(20):
        got = cd_type_columns(_relabelled(snap, rng))
        assert got.keys() == want.keys()
        for k in want:
            if isinstance(want[k], float) and np.isnan(want[k]):
                assert np.isnan(got[k]), k
            else:
                assert got[k] == pytest.approx(want[k], rel=1e-13, abs=1e-15), k


def test_refusals_are_one_line():
    snap = four_pairs()
    snap.points = None
    with pytest.raises(InputError, match="has no contact points") as info:
        cd_type_columns(snap)
    assert "\n" not in str(info.value)
    snap = four_pairs()
    snap.points["force_normal"][:] = 0.0
    with pytest.raises(InputError, match="no particle pair carries a force"):
        cd_type_columns(snap)
