"""The kernel's neighbour list with bodies much larger than the others (a
user scene's facets and slabs, kept out of the cell grid): every pair whose
bounding spheres come within the skin is listed, and no other, as a brute
force over all pairs finds them."""
import numpy as np

from shapes.engine import ContactEngine


def box(h):
    """(8, 3) vertices and (12, 3) outward triangles of a box of half sides h."""
    hx, hy, hz = h
    v = np.array([(x, y, z) for x in (-hx, hx) for y in (-hy, hy) for z in (-hz, hz)], float)
    t = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4), (2, 6, 7), (2, 7, 3),
         (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]
    return v, np.array(t)


def listed_pairs(n_small, large_sizes, seed):
    rng = np.random.default_rng(seed)
    shapes = [box((0.01, 0.012, 0.009))] + [box(s) for s in large_sizes]
    kinds = np.r_[np.zeros(n_small, int), 1 + np.arange(len(large_sizes))]
    rng.shuffle(kinds)                                   # large bodies anywhere in the row order
    pos = rng.uniform(-0.15, 0.15, (len(kinds), 3))
    skin = 0.004
    eng = ContactEngine([s[0] for s in shapes], [s[1] for s in shapes], kinds, np.ones(len(kinds)), 1e6, 0.0,
                        0.5, 0.5, skin, walls=False, threads=1)
    quat = np.tile([1.0, 0, 0, 0], (len(kinds), 1))
    eng.step(pos, quat)
    got = {tuple(p) for p in eng.state()["pair_ids"].tolist()}
    r = np.array([np.linalg.norm(shapes[k][0], axis=1).max() for k in kinds])
    want = {(i, j) for i in range(len(kinds)) for j in range(i + 1, len(kinds))
            if np.linalg.norm(pos[j] - pos[i]) <= r[i] + r[j] + skin}
    eng.close()
    return got, want, kinds


def test_large_bodies_are_listed_against_every_body_in_reach():
    got, want, kinds = listed_pairs(300, [(0.3, 0.3, 0.005), (0.005, 0.25, 0.25), (0.2, 0.2, 0.2)], seed=4)
    assert len(want) > 300                            # the large ones reach many
    assert got == want


def test_without_large_bodies_the_grid_lists_the_same_pairs():
    got, want, kinds = listed_pairs(400, [], seed=5)
    assert len(want) > 50 and got == want
