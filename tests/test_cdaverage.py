"""lmgc90.cdaverage: the mean CD forces over a window of steps, against
hand-built cases and the sums it must keep (pure numpy, no LMGC90)."""
import numpy as np
import pytest

from lmgc90.cdaverage import ForceWindow


def _frames(n, rng):
    """n random orthonormal frames (columns t, n, s)."""
    q, _ = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    return q


def _step(keys, rng, walls=None):
    P = len(keys)
    keys = np.asarray(keys)
    return dict(keys=keys, candidate=keys[:, 1], antagonist=keys[:, 2], point=rng.normal(size=(P, 3)),
                frames=_frames(P, rng), reactions=rng.uniform(0, 1, size=(P, 3)), gap=rng.normal(size=P),
                wall_forces=rng.normal(size=(6, 3)) if walls is None else walls)


def _key(cd, an, vertex):
    return [0, cd, an, 1, 1, vertex, 1]


def test_a_point_s_mean_is_its_impulse_sum_over_k_steps_and_absent_steps_count_zero():
    rng = np.random.default_rng(1)
    w = ForceWindow(3)
    steps = [_step([_key(1, 2, 1), _key(1, 2, 2)], rng), _step([_key(1, 2, 2)], rng),
             _step([_key(1, 2, 2), _key(3, 2, 1)], rng)]
    for s in steps:
        w.add(**s)
    cd, an, x, uc, r, gap, walls = w.mean()
    glob = np.einsum("pij,pj->pi", uc, r)
    # the vanished point (1, 2, vertex 1): only step 0's force, over 3 steps, at its step-0 position
    want = {}
    for s in steps:
        for k, F, rr in zip(map(tuple, s["keys"].tolist()), s["frames"], s["reactions"]):
            want[k] = want.get(k, 0) + F @ rr / 3
    assert len(cd) == 3
    got = {(0, int(c), int(a), 1, 1, v, 1): g for c, a, g, v in zip(cd, an, glob, [1, 2, 1])}
    for k, g in got.items():
        assert np.allclose(g, want[k], rtol=0, atol=1e-14)
    i_vanished = 0       # keys sort as (1,2,v1), (1,2,v2), (3,2,v1)
    assert np.array_equal(x[i_vanished], steps[0]["point"][0]) and gap[i_vanished] == steps[0]["gap"][0]
    assert np.array_equal(x[1], steps[2]["point"][0]) and np.array_equal(uc[2], steps[2]["frames"][1])
    assert np.allclose(walls, sum(s["wall_forces"] for s in steps) / 3, rtol=0, atol=1e-15)


def test_the_oldest_step_drops_out_and_a_zero_mean_point_not_alive_is_left_out():
    rng = np.random.default_rng(2)
    w = ForceWindow(2)
    old = _step([_key(5, 6, 1)], rng)
    w.add(**old)
    w.add(**_step([_key(7, 6, 1)], rng))
    w.add(**_step([_key(7, 6, 1)], rng))
    cd, an, *_ = w.mean()
    assert cd.tolist() == [7] and len(w) == 2 and w.full
    # a point seen in the window with zero force, absent at the last step: dropped; alive with zero: kept
    z = ForceWindow(2)
    a = _step([_key(1, 2, 1), _key(1, 2, 2)], rng)
    a["reactions"][0] = 0.0
    b = _step([_key(1, 2, 2), _key(1, 2, 3)], rng)
    b["reactions"][1] = 0.0
    z.add(**a)
    z.add(**b)
    cd, an, x, uc, r, gap, _ = z.mean()
    assert len(cd) == 2 and np.all(r[1] == 0.0)


def test_every_body_s_mean_force_is_the_mean_of_its_step_forces():
    """Invariance: the mean forces summed per body equal the per-step sums
    averaged, whatever points come and go (what makes the dump's net
    forces LMGC90's mean reactions)."""
    rng = np.random.default_rng(3)
    K = 7
    w = ForceWindow(K)
    per_step = []
    for _ in range(K + 3):
        keys = [_key(int(c), int(a), int(v)) for c, a, v in
                zip(rng.integers(0, 5, 30), rng.integers(5, 9, 30), rng.integers(1, 4, 30))]
        keys = np.unique(np.array(keys), axis=0)
        s = _step(keys, rng)
        w.add(**s)
        net = np.zeros((9, 3))
        np.add.at(net, s["candidate"], np.einsum("pij,pj->pi", s["frames"], s["reactions"]))
        per_step.append(net)
    cd, an, x, uc, r, gap, _ = w.mean()
    net = np.zeros((9, 3))
    np.add.at(net, cd, np.einsum("pij,pj->pi", uc, r))
    assert np.allclose(net, np.mean(per_step[-K:], axis=0), rtol=0, atol=1e-12)


def test_one_step_windows_give_that_step_back():
    rng = np.random.default_rng(4)
    w = ForceWindow(1)
    s = _step([_key(2, 1, 1), _key(3, 1, 2)], rng)
    w.add(**s)
    cd, an, x, uc, r, gap, walls = w.mean()
    assert np.allclose(r, s["reactions"], rtol=0, atol=1e-14) and np.array_equal(walls, s["wall_forces"])


def test_bad_input_is_refused_in_one_line():
    with pytest.raises(ValueError, match="at least one step"):
        ForceWindow(0)
    with pytest.raises(ValueError, match="holds no step"):
        ForceWindow(2).mean()
    w = ForceWindow(2)
    rng = np.random.default_rng(5)
    s = _step([_key(2, 1, 1), _key(3, 1, 2)], rng)
    s["gap"] = s["gap"][:1]
    with pytest.raises(ValueError, match="gap has 1 entries for 2 points"):
        w.add(**s)


def test_points_sharing_lmgc90_s_identity_are_matched_by_rank():
    """LMGC90 gives every point of a PRPRx pair one identity: the k-th point
    of the pair in one step meets the k-th of another; a third point present
    in one step of two gets half its force, the two others their means."""
    rng = np.random.default_rng(6)
    w = ForceWindow(2)
    a = _step([_key(1, 2, 0)] * 3, rng)
    b = _step([_key(1, 2, 0)] * 2, rng)
    w.add(**a)
    w.add(**b)
    cd, an, x, uc, r, gap, _ = w.mean()
    glob = np.einsum("pij,pj->pi", uc, r)
    fa = np.einsum("pij,pj->pi", a["frames"], a["reactions"])
    fb = np.einsum("pij,pj->pi", b["frames"], b["reactions"])
    assert len(cd) == 3
    assert np.allclose(glob, np.vstack([(fa[:2] + fb) / 2, fa[2:] / 2]), rtol=0, atol=1e-14)
    assert np.array_equal(x[:2], b["point"]) and np.array_equal(x[2], a["point"][2])
