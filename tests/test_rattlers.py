"""Rattlers as a queue-driven k-core: the same set as the former
layer-by-layer peeling on every kind of graph, in O(particles + contacts)."""
import numpy as np
import pytest

import postproc.coordination as coord
from postproc.coordination import rattlers


def layered_rattlers(i1, i2, bearing, n, k=2):
    """The former implementation (one layer per pass), kept as the reference."""
    active = np.asarray(bearing, bool).copy()
    rat = np.zeros(n, bool)
    while True:
        deg = (np.bincount(i1[active & (i1 >= 0)], minlength=n)
               + np.bincount(i2[active & (i2 >= 0)], minlength=n))
        new = (deg < k) & ~rat
        if not new.any():
            return rat
        rat |= new
        gone = ((i1 >= 0) & rat[np.maximum(i1, 0)]) | ((i2 >= 0) & rat[np.maximum(i2, 0)])
        active &= ~gone


def is_k_core_complement(i1, i2, bearing, rat, k):
    """Independent check of the definition: every kept particle has >= k
    bearing contacts with kept particles or walls, and no removed particle
    could be put back (the core is maximal: checked by re-running the peel
    from the kept set, which must remove nothing)."""
    keep = ~rat
    ok1 = (i1 < 0) | keep[np.maximum(i1, 0)]
    ok2 = (i2 < 0) | keep[np.maximum(i2, 0)]
    live = bearing & ok1 & ok2
    n = len(rat)
    deg = (np.bincount(i1[live & (i1 >= 0)], minlength=n)
           + np.bincount(i2[live & (i2 >= 0)], minlength=n))
    return bool(np.all(deg[keep] >= k))


def random_graph(rng, n, c, walls=0.05, loose=0.1):
    i1 = rng.integers(0, n, c)
    i2 = rng.integers(0, n, c)
    i2[rng.random(c) < walls] = -1
    keep = i1 != i2
    i1, i2 = i1[keep], i2[keep]
    bearing = rng.random(len(i1)) > loose
    return i1, i2, bearing


@pytest.mark.parametrize("wide", [0, 1, 3, 10**9])
@pytest.mark.parametrize("seed", range(12))
def test_same_as_layered_peeling_on_random_graphs(monkeypatch, wide, seed):
    # wide = 0: everything through the queue; 1e9: every layer a whole-array pass
    monkeypatch.setattr(coord, "_SCAN_LAYERS", wide)
    rng = np.random.default_rng(seed)
    n = int(rng.integers(5, 400))
    c = int(rng.integers(1, 3 * n))
    i1, i2, bearing = random_graph(rng, n, c)
    for k in (1, 2, 3, 4):
        got = rattlers(i1, i2, bearing, n, k)
        assert np.array_equal(got, layered_rattlers(i1, i2, bearing, n, k))
        assert is_k_core_complement(i1, i2, bearing, got, k)


@pytest.mark.parametrize("wide", [0, 8, 10**9])
def test_chain_is_all_rattlers_and_a_wall_anchored_chain_is_not(monkeypatch, wide):
    monkeypatch.setattr(coord, "_SCAN_LAYERS", wide)
    n = 1001
    i1, i2 = np.arange(n - 1), np.arange(1, n)
    assert rattlers(i1, i2, np.ones(n - 1, bool), n).all()
    # both ends on a wall: every particle has two contacts, none rattles
    j1 = np.concatenate([i1, [0, n - 1]])
    j2 = np.concatenate([i2, [-1, -2]])
    assert not rattlers(j1, j2, np.ones(n + 1, bool), n).any()
    # one end on a wall: the chain unzips from the free end
    j1, j2 = np.concatenate([i1, [0]]), np.concatenate([i2, [-1]])
    assert rattlers(j1, j2, np.ones(n, bool), n).all()


def test_ring_with_trees_keeps_the_ring():
    # a ring of 50 particles with a binary tree of 63 particles hung on each
    # of 5 ring particles: the 2-core is the ring exactly
    ring = np.arange(50)
    i1, i2 = list(ring), list(np.roll(ring, -1))
    n = 50
    for root in (0, 10, 20, 30, 40):
        base = n
        n += 63
        i1.append(root)
        i2.append(base)
        for t in range(1, 63):
            i1.append(base + (t - 1) // 2)
            i2.append(base + t)
    i1, i2 = np.array(i1), np.array(i2)
    rat = rattlers(i1, i2, np.ones(len(i1), bool), n)
    assert not rat[:50].any() and rat[50:].all()


def test_double_contacts_count_twice_and_unbearing_do_not():
    # two contacts between 0 and 1 (a double contact of polyhedra) keep both
    i1, i2 = np.array([0, 0]), np.array([1, 1])
    assert not rattlers(i1, i2, np.array([True, True]), 2).any()
    assert rattlers(i1, i2, np.array([True, False]), 2).all()


def test_empty_and_isolated():
    e = np.zeros(0, np.int64)
    assert rattlers(e, e, np.zeros(0, bool), 3).all()
    assert rattlers(e, e, np.zeros(0, bool), 0).shape == (0,)


def test_packing_scale_matches_layered():
    # a 20 000-particle random packing-like graph with dangling chains
    rng = np.random.default_rng(7)
    n = 20_000
    i1, i2, bearing = random_graph(rng, n, 45_000, walls=0.02, loose=0.2)
    chain = np.arange(n - 300, n)
    i1 = np.concatenate([i1, chain[:-1]])
    i2 = np.concatenate([i2, chain[1:]])
    bearing = np.concatenate([bearing, np.ones(len(chain) - 1, bool)])
    got = rattlers(i1, i2, bearing, n)
    assert np.array_equal(got, layered_rattlers(i1, i2, bearing, n))
