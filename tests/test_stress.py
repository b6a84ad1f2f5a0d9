"""Stress tensors against hand-built configurations with exact stresses."""
import numpy as np
import pytest
from builders import lattice_snapshot

from postproc.analysis import analyze_snapshot
from postproc.contactset import resolve
from postproc.stress import contact_stress, invariants, wall_stress

RTOL = 1e-12  # exact configurations: only round-off


@pytest.mark.parametrize("shape", [(3, 2, 4), (1, 1, 1), (5, 5, 2)])
def test_three_stress_forms_on_a_lattice(shape):
    snap, sigma, n = lattice_snapshot(*shape)
    cs = resolve(snap)
    s_m = contact_stress(cs.force, cs.arm, cs.volume)
    s_w = wall_stress(snap.wall_forces, snap.box_lengths)
    s_b = contact_stress(cs.force[cs.pp], cs.arm[cs.pp], cs.volume)
    np.testing.assert_allclose(s_m, sigma, rtol=RTOL, atol=RTOL * np.abs(sigma).max())
    np.testing.assert_allclose(s_w, sigma, rtol=RTOL, atol=RTOL * np.abs(sigma).max())
    # the branch form misses the wall-contact moments: column b scaled by (n_b-1)/n_b
    np.testing.assert_allclose(s_b, sigma * ((n - 1) / n)[None, :], rtol=RTOL,
                               atol=RTOL * np.abs(sigma).max())


def test_wall_forces_from_contacts_match_stored():
    from postproc.analysis import wall_forces_from_contacts

    snap, _, _ = lattice_snapshot()
    np.testing.assert_allclose(wall_forces_from_contacts(resolve(snap)), snap.wall_forces,
                               rtol=1e-12, atol=1e-12)


def test_invariants_of_a_known_tensor():
    s = np.diag([2.0, 2.0, 5.0])       # axial 5, lateral 2
    inv = invariants(s, axis=2)
    assert inv["p"] == pytest.approx(3.0)
    assert inv["q"] == pytest.approx(1.0)          # (5 - 2)/3
    assert inv["q_over_p"] == pytest.approx(1 / 3)
    assert inv["q_axial"] == pytest.approx(1.0)
    assert inv["angle_1"] == pytest.approx(0.0, abs=1e-6)
    # extension along the axis: q stays positive, q_axial turns negative
    inv = invariants(np.diag([5.0, 5.0, 2.0]), axis=2)
    assert inv["q"] == pytest.approx(1.0) and inv["q_axial"] == pytest.approx(-1.0)


def test_rotation_invariance_of_p_q():
    rng = np.random.default_rng(4)
    A = rng.normal(size=(3, 3))
    s = A @ A.T
    Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    a, b = invariants(s), invariants(Q @ s @ Q.T)
    assert a["p"] == pytest.approx(b["p"], rel=1e-12)
    assert a["q"] == pytest.approx(b["q"], rel=1e-12)


def test_lattice_analysis_row():
    snap, sigma, n = lattice_snapshot(3, 3, 6, F=(2.0, 2.0, 5.0), T=0.0)
    row = analyze_snapshot(snap).row
    d2 = (2 * 0.01) ** 2
    assert row["p"] == pytest.approx(3.0 / d2, rel=1e-12)
    assert row["q_over_p"] == pytest.approx(1 / 3, rel=1e-12)
    assert row["q_over_p_wall"] == pytest.approx(1 / 3, rel=1e-12)
    assert row["reldiff_wall"] < 1e-12
    assert row["antisymmetry"] < 1e-12
    # lattice fabric: contacts along x, y, z only, equal numbers in each
    # direction (3x3x6: 6*2*3... counted) -> a from exact counts
    nx, ny, nz = n
    cx, cy, cz = (nx - 1) * ny * nz, nx * (ny - 1) * nz, nx * ny * (nz - 1)
    F3 = cz / (cx + cy + cz)
    assert row["a"] == pytest.approx(2.5 * (F3 - (1 - F3) / 2), rel=1e-12)
    assert row["a_t"] == pytest.approx(0.0, abs=1e-12)
