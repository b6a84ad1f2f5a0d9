"""postproc.study.branchlength: a_l of contact subsets against synthetic sets of
known a_l, and the polyhedron geometry against exact answers."""
import numpy as np
import pytest
from scipy.spatial import ConvexHull

from postproc.axes import rotation_z_to
from postproc.study.branchlength import (length_profile, principal_extents, radial_distance,
                                   subset_anisotropy)
from postproc.synthetic import harmonic_contacts


def _hull(points):
    """Outward-oriented triangles of the convex hull of ``points``."""
    h = ConvexHull(points)
    tri = h.simplices.copy()
    c = points.mean(axis=0)
    for k, (i, j, m) in enumerate(tri):
        n = np.cross(points[j] - points[i], points[m] - points[i])
        if n @ (points[i] - c) < 0:
            tri[k] = (i, m, j)
    return tri


def test_known_a_l_recovered_within_standard_error():
    s = harmonic_contacts(200_000, a=0.1, a_l=0.12, spread_l=0.3, seed=3)
    r = subset_anisotropy(s.branch, axis=2)
    # 4 standard errors: fails by chance with probability 6e-5
    assert abs(r["a_l"] - 0.12) < 4 * r["a_l_se"]
    assert abs(r["a"] - 0.1) < 4 * r["a_se"]
    assert 0 < r["a_l_se"] < 0.01
    assert r["n"] == 200_000
    assert r["l0"] == pytest.approx(0.03, rel=4 * r["a_l_se"] + 0.01)


def test_mask_selects_a_subset_with_its_own_a_l():
    s1 = harmonic_contacts(100_000, a=0.2, a_l=0.25, seed=1)
    s2 = harmonic_contacts(100_000, a=-0.1, a_l=-0.15, seed=2)
    branch = np.concatenate([s1.branch, s2.branch])
    first = np.r_[np.ones(100_000, bool), np.zeros(100_000, bool)]
    for mask, a, a_l in ((first, 0.2, 0.25), (~first, -0.1, -0.15)):
        r = subset_anisotropy(branch, mask, axis="z")
        assert abs(r["a_l"] - a_l) < 4 * r["a_l_se"]
        assert abs(r["a"] - a) < 4 * r["a_se"]
        assert r["n"] == 100_000


def test_other_axis_and_rescaled_lengths():
    s = harmonic_contacts(100_000, a=0.15, a_l=0.1, axis=0, seed=5)
    rx = subset_anisotropy(s.branch, axis=0)
    assert abs(rx["a_l"] - 0.1) < 4 * rx["a_l_se"]
    # a length proportional to |l| has the same a_l (exact: a ratio)
    norm = np.linalg.norm(s.branch, axis=1)
    r2 = subset_anisotropy(s.branch, axis=0, length=norm / 0.03)
    assert r2["a_l"] == pytest.approx(rx["a_l"], abs=1e-12)
    assert r2["mean"] == pytest.approx(norm.mean() / 0.03)
    # a length independent of direction gives a_l = 0 exactly, whatever a
    r3 = subset_anisotropy(s.branch, axis=0, length=np.full(len(norm), 2.0))
    assert r3["a_l"] == pytest.approx(0.0, abs=1e-12)
    assert r3["a"] == pytest.approx(rx["a"], abs=1e-12)


def test_small_and_bad_subsets():
    s = harmonic_contacts(10, seed=0)
    r = subset_anisotropy(s.branch, np.zeros(10, bool))
    assert r["n"] == 0 and np.isnan(r["a_l"])
    with pytest.raises(ValueError, match="mask"):
        subset_anisotropy(s.branch, np.ones(3, bool))
    bad = s.branch.copy()
    bad[0] = 0
    with pytest.raises(ValueError, match="zero length"):
        subset_anisotropy(bad)
    with pytest.raises(ValueError, match="lengths"):
        subset_anisotropy(s.branch, length=-np.ones(10))


def test_length_profile_follows_the_harmonic_form():
    s = harmonic_contacts(300_000, a=0.0, a_l=0.2, spread_l=0.2, seed=7)
    p = length_profile(s.branch, axis=2, edges_deg=(0, 10, 80, 90))
    assert p["n"].sum() == 300_000
    # bin means of l0 [1 + a_l P2] with P2 averaged over the bin (uniform
    # density in cos theta since a = 0)
    for j, (lo, hi) in enumerate(zip(p["lo"], p["hi"])):
        c1, c0 = np.cos(np.radians(lo)), np.cos(np.radians(hi))
        mean_c2 = (c1 ** 3 - c0 ** 3) / 3 / (c1 - c0)
        expect = 0.03 * (1 + 0.2 * (3 * mean_c2 - 1))
        assert p["mean"][j] == pytest.approx(expect, abs=4 * p["se"][j])


def test_principal_extents_and_radial_distance_of_a_rotated_box():
    half = np.array([0.5, 1.5, 1.0])          # extents 1, 3, 2
    corners = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]) * half
    R = rotation_z_to(np.array([1.0, 2.0, 2.0]) / 3)
    v = corners @ R.T + np.array([0.3, -0.2, 0.1])
    tri = _hull(v)
    dims, axes = principal_extents(v, tri)
    assert dims == pytest.approx([3.0, 2.0, 1.0], rel=1e-12)
    # the long axis is the box's y axis, rotated
    assert abs(axes[:, 0] @ (R @ [0, 1, 0])) == pytest.approx(1.0, rel=1e-12)
    # radial distances from the centre along the box axes and a diagonal
    u = np.array([R @ [1, 0, 0], R @ [0, 1, 0], -(R @ [0, 0, 1]),
                  R @ (np.array([1, 1, 0]) / np.sqrt(2))])
    r = radial_distance(v, tri, u)
    assert r == pytest.approx([0.5, 1.5, 1.0, 0.5 * np.sqrt(2)], rel=1e-12)


def test_al_investigation_command(tmp_path, capsys):
    """``postproc al-investigation`` on a small synthetic spheres dump and a
    missing one: the synthetic check first, sections 1 and 2 of the
    spheres, the missing dump said and skipped, the summary row last."""
    from postproc.cli import main
    from postproc.synthetic import write_synthetic_dump

    path = str(tmp_path / "syn.h5")
    write_synthetic_dump(path, n_contacts=2000, n_snapshots=4, seed=1)
    assert main(["investigate", "al-investigation", path, str(tmp_path / "none.h5"), "--pairs", "100"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("synthetic check (200000 contacts, a = 0.08, a_l = 0.12")
    assert f"## {path}: spheres" in out and "1. overall" in out and "2. <l / d_pair>(theta)" in out
    assert "3. a_l by" not in out                   # the polyhedra's sections only
    assert f"## {tmp_path / 'none.h5'}: skipped:" in out
    assert out.rstrip().splitlines()[-1].startswith(f"| {path} | ")
