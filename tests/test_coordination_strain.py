"""Coordination numbers, rattlers, weak forces and box strains."""
import numpy as np
import pytest

from postproc.coordination import coordination, fraction_below_mean, rattlers
from postproc.strain import box_strains


def test_coordination_with_a_rattler_chain():
    # particles 0-1-2-0 form a loaded triangle; 3 touches 0 only; 4 touches 3
    # only (removing 4 leaves 3 with one contact: both are rattlers)
    i1 = np.array([0, 1, 2, 3, 4, 0])
    i2 = np.array([1, 2, 0, 0, 3, -1])      # last one: particle 0 on a wall
    f = np.ones((6, 3))
    co = coordination(i1, i2, f, 5)
    assert co["n_rattlers"] == 2
    assert co["z"] == pytest.approx(2 * 3 / 3)          # 3 pp contacts among 3 particles
    assert co["z_all"] == pytest.approx(2 * 5 / 5)      # 5 pp contacts among 5 particles


def test_zero_force_contacts_do_not_count():
    i1, i2 = np.array([0, 1, 2]), np.array([1, 2, 0])
    f = np.array([[1.0, 0, 0], [1.0, 0, 0], [0.0, 0, 0]])
    # 0 and 2 keep one bearing contact each -> rattlers; then 1 has none
    rat = rattlers(i1, i2, np.array([True, True, False]), 3)
    assert rat.all()
    co = coordination(i1, i2, f, 3)
    assert co["n_bearing"] == 2


def test_force_scale_does_not_matter():
    rng = np.random.default_rng(0)
    i1, i2 = rng.integers(0, 50, 300), rng.integers(0, 50, 300)
    keep = i1 != i2
    f = rng.exponential(size=(keep.sum(), 3))
    ref = coordination(i1[keep], i2[keep], f, 50)
    for s in (1e-9, 1e9):
        assert coordination(i1[keep], i2[keep], f * s, 50) == ref


def test_fraction_below_mean_exponential():
    # for an exponential law P(f < mean) = 1 - 1/e; binomial se = sqrt(p(1-p)/N)
    N = 100_000
    f = np.random.default_rng(3).exponential(size=N)
    p = 1 - np.exp(-1)
    assert abs(fraction_below_mean(f) - p) < 5 * np.sqrt(p * (1 - p) / N)


def test_box_strains_compression_positive():
    ref = np.array([1.0, 1.0, 2.0])
    lengths = np.array([[1.0, 1.0, 2.0], [1.05, 1.02, 1.8]])
    eps = box_strains(lengths, ref, axis=2)
    assert eps["eps_1"][1] == pytest.approx(np.log(2.0 / 1.8))
    assert eps["eps_2"][1] == pytest.approx(np.log(1 / 1.02))
    assert eps["eps_3"][1] == pytest.approx(np.log(1 / 1.05))
    assert eps["eps_q"][1] == pytest.approx(np.log(2 / 1.8) - np.log(1 / 1.05))
    assert eps["eps_v"][1] == pytest.approx(np.log(2.0 / (1.05 * 1.02 * 1.8)))
    assert eps["eps_q"][0] == 0.0
    # additivity of log strains: two steps = one step
    mid = np.array([1.02, 1.01, 1.9])
    e_ab = box_strains(mid, ref)["eps_1"][0] + box_strains(lengths[1], mid)["eps_1"][0]
    assert e_ab == pytest.approx(eps["eps_1"][1], rel=1e-12)
