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


def _rows_close(r1, r2, keys, rel=1e-9):
    for k in keys:
        assert r1[k] == pytest.approx(r2[k], rel=rel, abs=1e-9 * max(1.0, abs(r2[k]))), k


def test_snapshot_invariances():
    """Permuting contacts, swapping id1/id2 with the force sign, rotating the
    whole set together with the axis and scaling forces by 1e-9 or 1e9 leave
    the invariants unchanged (stresses scale with the forces)."""
    import copy

    from postproc.axes import rotation_z_to

    snap, _, _ = lattice_snapshot(4, 3, 5, F=(2.0, 3.0, 6.0), T=0.7)
    keys = ("p", "q", "q_over_p", "q_axial_over_p", "a", "a_l", "a_n", "a_t", "sff",
            "z", "q_over_p_branch", "reldiff_branch", "frac_below_mean")
    ref = analyze_snapshot(snap).row
    rng = np.random.default_rng(0)
    perm = copy.deepcopy(snap)
    p = rng.permutation(len(snap.id1))
    for k in ("id1", "id2", "point", "force", "force_normal", "normal", "overlap"):
        setattr(perm, k, getattr(snap, k)[p])
    _rows_close(analyze_snapshot(perm).row, ref, keys)
    sw = copy.deepcopy(snap)
    sw.id1, sw.id2 = snap.id2.copy(), snap.id1.copy()
    sw.force, sw.force_normal, sw.normal = -snap.force, -snap.force_normal, -snap.normal
    _rows_close(analyze_snapshot(sw).row, ref, keys + ("s_xx", "s_xy", "p_wall"))
    R = rotation_z_to((0.2, 0.5, 0.8)) @ rotation_z_to((0.0, 1.0, 0.0))
    rot = copy.deepcopy(snap)
    for k in ("positions", "point", "force", "force_normal", "normal"):
        setattr(rot, k, getattr(snap, k) @ R.T)
    rot.wall_forces = None          # the walls no longer bound an axis-aligned box
    _rows_close(analyze_snapshot(rot, axis=R[:, 2]).row, ref, keys)
    for scale in (1e-9, 1e9):
        sc = copy.deepcopy(snap)
        sc.force, sc.force_normal, sc.wall_forces = snap.force * scale, snap.force_normal * scale, snap.wall_forces * scale
        row = analyze_snapshot(sc).row
        _rows_close(row, ref, ("q_over_p", "a", "a_l", "a_n", "a_t", "z", "frac_below_mean"))
        assert row["p"] == pytest.approx(ref["p"] * scale, rel=1e-12)
