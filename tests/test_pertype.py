"""Per-class partial stresses and statistics."""
import numpy as np
import pytest
from builders import lattice_snapshot

from postproc.contactset import resolve
from postproc.pertype import class_statistics, partial_stresses
from postproc.stress import contact_stress


def test_partial_stresses_sum_to_the_total_in_any_order():
    snap, sigma, _ = lattice_snapshot(3, 4, 5, T=0.8)
    cs = resolve(snap)
    rng = np.random.default_rng(0)
    labels = np.where(cs.pp, rng.choice(["VF", "EE", "EF", "FF"], len(cs.pp)), "wall")
    parts = partial_stresses(labels, cs.force, cs.arm, cs.volume)
    total = contact_stress(cs.force, cs.arm, cs.volume)
    np.testing.assert_allclose(sum(parts.values()), total, rtol=0, atol=1e-12 * np.abs(total).max())
    np.testing.assert_allclose(total, sigma, rtol=1e-12)
    p = rng.permutation(len(labels))
    parts2 = partial_stresses(labels[p], cs.force[p], cs.arm[p], cs.volume)
    for k in parts:
        np.testing.assert_allclose(parts2[k], parts[k], rtol=1e-12, atol=1e-12 * np.abs(total).max())


def test_class_statistics_known_answers():
    # class A: 2 contacts along z (the axis), forces 3 and 5; class B: 2
    # contacts along x, forces 1 and 1
    labels = np.array(["A", "A", "B", "B"])
    fn = np.array([3.0, 5.0, 1.0, 1.0])
    branch = np.array([[0, 0, 1.0], [0, 0, -2.0], [1.0, 0, 0], [-3.0, 0, 0]])
    st = class_statistics(labels, fn, branch, axis=2)
    assert st["A"]["fraction"] == 0.5
    assert st["A"]["mean_force_ratio"] == pytest.approx(4.0 / 2.5)
    assert st["A"]["force_share"] == pytest.approx(0.8)
    assert st["B"]["force_share"] == pytest.approx(0.2)
    # all along the axis: a = (5/4)(3 - 1) = 2.5; all lateral: a = -5/4 (signed)
    assert st["A"]["fabric_a"] == pytest.approx(2.5)
    assert st["B"]["fabric_a"] == pytest.approx(-1.25)
    assert sum(v["fraction"] for v in st.values()) == pytest.approx(1.0)


def test_isotropic_class_has_zero_fabric_within_its_error():
    rng = np.random.default_rng(4)
    n = rng.normal(size=(40_000, 3))
    st = class_statistics(np.full(len(n), "X"), np.ones(len(n)), n, axis=0)["X"]
    # the exact standard error for isotropic directions is sqrt(5/4 / N)
    assert st["fabric_a_se"] == pytest.approx(np.sqrt(1.25 / len(n)), rel=0.05)
    assert abs(st["fabric_a"]) < 5 * st["fabric_a_se"]
