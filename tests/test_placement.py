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


# ------------------------------------------------------------ the scene's draws (yade_scripts.scene.grains)
def test_the_scene_s_spheres_are_drawn_sizes_first_then_places():
    """draw_grains draws from one generator in the scene's order: the sizes,
    then the places; the same seed gives the same sample, bit for bit, and
    no two bounding spheres overlap."""
    from shapes.sizes import sample_diameters
    from yade_scripts.scene.grains import draw_grains

    g = draw_grains(50, 11, False, initial_fraction=0.3, aspect=2.0)
    rng = np.random.default_rng(11)
    d = sample_diameters(50, rng)
    box0, centres = sample.place_in_box(d, 0.3, 2.0, rng)
    assert g.d.tobytes() == d.tobytes() and g.centres.tobytes() == centres.tobytes()
    assert g.box0.tobytes() == box0.tobytes() and g.d_mean == float(d.mean()) and not g.poly
    gap = np.linalg.norm(g.centres[:, None] - g.centres[None], axis=2) - (g.d[:, None] + g.d[None]) / 2
    assert np.all(gap[~np.eye(50, dtype=bool)] >= -1e-12)
    assert draw_grains(50, 11, False, initial_fraction=0.3).centres.tobytes() == g.centres.tobytes()


@pytest.mark.parametrize("placement", ["grains", "spheres"])
def test_the_scene_s_polyhedra_are_drawn_sizes_shapes_orientations_then_places(shape_library, placement):
    """For polyhedra: the sizes, the shapes, the orientations, then the
    places (the grains themselves tested exactly, or their bounding spheres),
    and the library's grains scaled: volumes d^3 V, vertices d v, the mean
    face area of the library (d = 1)."""
    from shapes.library import ShapeLibrary
    from shapes.sizes import sample_diameters
    from yade_scripts.scene.grains import draw_grains

    g = draw_grains(24, 3, True, shape_library, placement, 0.12, 2.0)
    lib = ShapeLibrary(shape_library)
    rng = np.random.default_rng(3)
    d = sample_diameters(24, rng)
    shape_of = rng.integers(len(lib), size=24)
    quats = sample.random_quaternions(24, rng)
    if placement == "grains":
        oriented = overlap.OrientedGrains([(lib[s][0] * d[k], lib[s][1]) for k, s in enumerate(shape_of)], quats)
        box0, centres = sample.place_exact_in_box(d ** 3 * lib.volume[shape_of], d / 2, 0.12, 2.0, rng,
                                                  oriented.overlaps)
    else:
        box0, centres = sample.place_in_box(d, 0.12, 2.0, rng)
    for got, want in ((g.d, d), (g.shape_of, shape_of), (g.quats, quats), (g.centres, centres), (g.box0, box0)):
        assert got.dtype == want.dtype and got.tobytes() == want.tobytes()
    assert np.allclose(np.linalg.norm(g.quats, axis=1), 1.0, rtol=0, atol=1e-12)
    assert np.array_equal(g.volumes(), d ** 3 * lib.volume[shape_of])
    k = 5
    assert np.array_equal(g.vertices()[k], lib[int(shape_of[k])][0] * d[k])
    assert np.array_equal(g.triangles()[k], lib[int(shape_of[k])][1])
    # the mean face area (d = 1) by hand, over every triangle of the library
    per_shape = []
    for s in range(len(lib)):
        v, t, _ = lib[s]
        per_shape.append([0.5 * np.linalg.norm(np.cross(v[b] - v[a], v[c] - v[a])) for a, b, c in t])
    assert g.a_face == pytest.approx(np.mean(np.concatenate(per_shape)), rel=1e-12)
    assert np.allclose(g.max_face, [max(a) for a in per_shape], rtol=1e-12, atol=0) and g.poly
