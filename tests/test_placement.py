"""Placing polyhedra with their exact shapes (yade_scripts.scene.sample.place_exact,
shapes.overlap.OrientedGrains): no two grains overlap, the solid fraction
asked for is the one in the box, and the cheap proof of separation never
calls an overlapping pair apart."""
from __future__ import annotations

import numpy as np
import pytest

from shapes import overlap
from shapes.generate import generate_library
from yade_scripts.scene import sample


@pytest.fixture(scope="module")
def grains():
    shapes, _ = generate_library(40, seed=3)
    rng = np.random.default_rng(7)
    n = 120
    d = rng.choice([0.025, 0.0375, 0.05], size=n, p=[0.5, 0.34, 0.16])
    pick = rng.integers(len(shapes), size=n)
    quat = sample.random_quaternions(n, rng)
    own = [(shapes[s].vertices * d[k], shapes[s].triangles) for k, s in enumerate(pick)]
    vol = np.array([shapes[s].volume for s in pick]) * d ** 3
    return d, own, quat, vol


def test_support_proof_agrees_with_the_kernel(grains):
    """OrientedGrains.overlaps equals the kernel's volume > 0 on pairs at
    every distance from deep overlap to apart (the support-plane shortcut
    may only prove separations the kernel confirms)."""
    d, own, quat, _ = grains
    og = overlap.OrientedGrains(own, quat)
    rng = np.random.default_rng(1)
    n = len(d)
    k = np.arange(n)
    for scale in (0.2, 0.5, 0.8, 1.0):
        J = (k + 1 + rng.integers(n - 1, size=n)) % n
        u = rng.normal(size=(n, 3))
        u /= np.linalg.norm(u, axis=1)[:, None]
        X = np.zeros((n, 3))
        Y = X + u * (scale * (d + d[J]) / 2)[:, None]
        ref = overlap.batch_overlap(og.table, k, X, quat, J, Y, quat[J])["volume"] > 0
        got = np.array([og.overlaps(int(i), X[i:i + 1], J[i:i + 1], Y[i:i + 1])[0] for i in range(n)])
        assert np.array_equal(got, ref), scale
    assert 0 < ref.sum() < n or scale == 1.0


def test_exact_placement_has_no_overlap_and_the_fraction_asked(grains):
    d, own, quat, vol = grains
    og = overlap.OrientedGrains(own, quat)
    box, pos = sample.place_exact(vol, d / 2, 0.2, 2.0, np.random.default_rng(4), og.overlaps)
    assert vol.sum() / np.prod(box) == pytest.approx(0.2, rel=1e-12)
    assert box[2] == pytest.approx(2 * box[0], rel=1e-12)
    r = d / 2
    assert np.all(pos - r[:, None] >= 0) and np.all(pos + r[:, None] <= box)       # bounding spheres inside
    i, j = np.triu_indices(len(d), 1)
    res = overlap.batch_overlap(og.table, i, pos[i], quat[i], j, pos[j], quat[j])
    assert not np.any(res["volume"] > 0)
    near = np.linalg.norm(pos[i] - pos[j], axis=1) < r[i] + r[j]
    assert near.sum() > 0          # the bounding spheres do overlap: denser than sphere placement allows
    # the same generator state gives the same sample
    box2, pos2 = sample.place_exact(vol, d / 2, 0.2, 2.0, np.random.default_rng(4), og.overlaps)
    assert np.array_equal(pos, pos2)


def test_exact_placement_refuses_or_grows_when_too_dense(grains):
    d, own, quat, vol = grains
    og = overlap.OrientedGrains(own, quat)
    with pytest.raises(RuntimeError, match="no room for grain"):
        sample.place_exact(vol, d / 2, 0.6, 2.0, np.random.default_rng(0), og.overlaps, batch=8, max_batches=5)
    box, pos = sample.place_exact_in_box(vol, d / 2, 0.6, 2.0, np.random.default_rng(0), og.overlaps,
                                         grow=1.2, max_batches=20)
    assert vol.sum() / np.prod(box) < 0.6 and np.isfinite(pos).all()


def _place_all_pairs(volumes, radii, fraction, aspect, rng, overlaps, batch=64):
    """The placement with every placed grain tested against every trial (the
    O(n^2) form): the reference the grid of cells must reproduce exactly."""
    vol, r = np.asarray(volumes, float), np.asarray(radii, float)
    L = (vol.sum() / fraction / aspect) ** (1 / 3)
    box = np.array([L, L, aspect * L])
    pos = np.full((len(vol), 3), np.nan)
    placed = []
    for k in np.argsort(-r, kind="stable"):
        lo, hi = np.full(3, r[k]), box - r[k]
        P = np.array(placed, dtype=int)
        while True:
            X = lo + (hi - lo) * rng.random((batch, 3))
            if not len(P):
                pos[k] = X[0]
                break
            near = np.linalg.norm(X[:, None, :] - pos[P][None, :, :], axis=2) < r[k] + r[P][None, :]
            free = ~near.any(axis=1)
            last = int(np.argmax(free)) if free.any() else batch - 1
            rows, cols = np.nonzero(near[:last + 1])
            hit = np.zeros(last + 1, bool)
            if len(rows):
                hit[rows[overlaps(k, X[rows], P[cols], pos[P[cols]])]] = True
            ok = np.flatnonzero(~hit)
            if len(ok):
                pos[k] = X[ok[0]]
                break
        placed.append(k)
    return box, pos


@pytest.mark.parametrize("fraction, batch", [(0.2, 64), (0.25, 8), (0.05, 64)])
def test_cell_grid_gives_the_all_pairs_sample(grains, fraction, batch):
    """The grid of cells finds exactly the pairs whose bounding spheres meet,
    so the sample is the one of testing every placed grain, bit for bit
    (dense, sparse, and small batches where many trials are busy)."""
    d, own, quat, vol = grains
    og = overlap.OrientedGrains(own, quat)
    box, pos = sample.place_exact(vol, d / 2, fraction, 2.0, np.random.default_rng(11), og.overlaps, batch=batch)
    box2, pos2 = _place_all_pairs(vol, d / 2, fraction, 2.0, np.random.default_rng(11), og.overlaps, batch=batch)
    assert np.array_equal(box, box2) and np.array_equal(pos, pos2)


def test_shape_table_subset_holds_the_same_shapes(grains):
    """A subset of the shape table gives the kernel the same numbers: the
    overlaps of pairs computed on it equal those on the whole table, bit
    for bit, in any order of its rows."""
    d, own, quat, _ = grains
    og = overlap.OrientedGrains(own, quat)
    rng = np.random.default_rng(5)
    n = len(d)
    a, b = rng.integers(n, size=60), rng.integers(n, size=60)
    Xa = rng.uniform(0, 0.02, size=(60, 3))
    Xb = Xa + rng.normal(size=(60, 3)) * 0.015
    whole = overlap.batch_overlap(og.table, a, Xa, quat[a], b, Xb, quat[b], threads=1)
    rows = rng.permutation(np.unique(np.concatenate([a, b])))
    where = {int(r): k for k, r in enumerate(rows)}
    sub = og.table.subset(rows)
    part = overlap.batch_overlap(sub, [where[int(x)] for x in a], Xa, quat[a], [where[int(x)] for x in b], Xb,
                                 quat[b], threads=1)
    assert sub.n == len(rows) < n
    for key in ("volume", "centroid", "normal", "footprint", "area", "status"):
        np.testing.assert_array_equal(part[key], whole[key])
    assert np.sum(whole["volume"] > 0) > 5
