"""Strong/weak networks, force distributions and the per-type analysis of a
snapshot, on hand-built configurations with exact answers."""
import numpy as np
import pytest

from builders import lattice_snapshot
from postproc.analysis import analyze_snapshot
from postproc.contacttypes import PAIR_TYPES, shape_tables
from postproc.errors import InputError
from postproc.networks import force_pdf, network_statistics, strong_mask
from postproc.pertype import partial_stresses, stress_contributions
from shapes.polyhedron import geometric_faces, hull
from test_contact_types import quat_from_matrix, rot

NX, NY, NZ, F = 3, 2, 4, (3.0, 5.0, 7.0)


def cube_lattice(rotate_top=True):
    """The sphere lattice of builders.lattice_snapshot with every sphere
    replaced by a cube of side d = 2r, faces along the axes. With
    ``rotate_top`` the cubes of the top layer are turned 45 deg about x, so
    they touch the layer below with an edge (EF), each other along y with
    edges (EE) and along x with faces (FF). Forces and stress are those of
    the lattice (exact)."""
    snap, sigma, n = lattice_snapshot(NX, NY, NZ, F=F)
    d = snap.sizes[0]
    pts = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * d / 2
    v, t = hull(pts)
    tables = shape_tables([v], [t], [geometric_faces(v, t)])
    snap.body_kind = np.ones(len(snap.body_ids), np.int8)
    snap.shape_index = np.zeros(len(snap.body_ids), np.int32)
    if rotate_top:
        top = np.isclose(snap.positions[:, 2], snap.positions[:, 2].max())
        snap.orientations[top] = quat_from_matrix(rot([1, 0, 0], 45))
    return snap, sigma, tables


def expected_types():
    """Pair type of the particle-particle contacts of cube_lattice()."""
    counts = {"FF": (NX - 1) * NY * NZ + NX * (NY - 1) * (NZ - 1) + NX * NY * (NZ - 2),
              "EE": NX * (NY - 1), "EF": NX * NY}
    return counts


def test_cube_lattice_types_forces_and_partial_stresses():
    snap, sigma, tables = cube_lattice()
    res = analyze_snapshot(snap, axis=2, tables=tables, errors=False)
    row = res.row
    counts = expected_types()
    n_pp = sum(counts.values())
    assert len(res.labels) == n_pp
    for k in PAIR_TYPES:
        assert row[f"ct_frac_{k}"] == pytest.approx(counts.get(k, 0) / n_pp, abs=1e-15)
    assert row["ct_frac_double"] == pytest.approx(counts["EF"] / n_pp)
    assert row["ct_frac_simple"] == pytest.approx(counts["EE"] / n_pp)
    # mean normal force: x contacts carry F[0], y F[1], z F[2]
    nx_c, ny_c, nz_c = (NX - 1) * NY * NZ, NX * (NY - 1) * NZ, NX * NY * (NZ - 1)
    mean = (nx_c * F[0] + ny_c * F[1] + nz_c * F[2]) / n_pp
    assert row["ct_fratio_EF"] == pytest.approx(F[2] / mean, rel=1e-12)
    assert row["ct_fratio_EE"] == pytest.approx(F[1] / mean, rel=1e-12)
    assert row["ct_fshare_EF"] == pytest.approx(counts["EF"] * F[2] / (n_pp * mean), rel=1e-12)
    # EF contacts all lie along the axis (a = 5/2), EE across it (a = -5/4)
    assert row["ct_fabric_EF"] == pytest.approx(2.5, abs=1e-12)
    assert row["ct_fabric_EE"] == pytest.approx(-1.25, abs=1e-12)
    # partial stresses: EF carries sigma_zz = 6 F_z d / V only
    d = snap.sizes[0]
    p = np.trace(sigma) / 3
    V = NX * NY * NZ * d ** 3
    assert row["ct_qp_EF"] == pytest.approx(counts["EF"] * F[2] * d / (3 * V * p), rel=1e-12)
    qsum = sum(row[f"ct_qp_{k}"] for k in PAIR_TYPES + ("wall",) if f"ct_qp_{k}" in row)
    assert qsum == pytest.approx(row["q_axial_over_p"], abs=1e-14)
    assert row["ct_partial_sum_reldiff"] < 1e-14
    # one pair = one contact in z; z_points counts 1, 2, 3 points
    pts = (counts["EE"] + 2 * counts["EF"] + 3 * counts["FF"]) / n_pp
    assert row["z_points"] == pytest.approx(row["z"] * pts, rel=1e-12)
    # strong network = the z contacts (F_z > mean): all along the axis
    assert row["strong_fraction"] == pytest.approx(nz_c / n_pp)
    assert row["strong_a"] == pytest.approx(2.5, abs=1e-12)
    assert row["weak_a"] == pytest.approx(-1.25, abs=1e-12)
    assert row["strong_frac_EF"] == pytest.approx(counts["EF"] / nz_c)
    assert row["weak_frac_EF"] == 0
    assert row["strong_qp"] + row["weak_qp"] + row["wall_qp"] == pytest.approx(row["q_axial_over_p"], abs=1e-14)


def test_per_type_analysis_is_independent_of_contact_and_id_order():
    snap, _, tables = cube_lattice()
    ref = analyze_snapshot(snap, axis=2, tables=tables, errors=False).row
    rng = np.random.default_rng(1)
    perm = rng.permutation(len(snap.id1))
    for name in ("id1", "id2", "point", "force", "force_normal", "normal", "overlap"):
        setattr(snap, name, getattr(snap, name)[perm])
    flip = rng.random(len(snap.id1)) < 0.5          # swap the two sides of half the contacts
    snap.id1[flip], snap.id2[flip] = snap.id2[flip].copy(), snap.id1[flip].copy()
    for name in ("force", "force_normal", "normal"):
        getattr(snap, name)[flip] *= -1
    row = analyze_snapshot(snap, axis=2, tables=tables, errors=False).row
    for k, v in ref.items():
        if k.startswith(("ct_", "strong_", "weak_", "z")) and not isinstance(v, str):
            assert row[k] == pytest.approx(v, rel=1e-10, abs=1e-13, nan_ok=True), k


def test_all_face_face_without_rotation_and_spheres_have_no_types():
    snap, _, tables = cube_lattice(rotate_top=False)
    row = analyze_snapshot(snap, axis=2, tables=tables, errors=False).row
    assert row["ct_frac_FF"] == 1 and row["ct_frac_triple"] == 1
    assert row["z_points"] == pytest.approx(3 * row["z"])
    sph, _, _ = lattice_snapshot(NX, NY, NZ, F=F)
    row = analyze_snapshot(sph, axis=2, tables=tables, errors=False).row
    assert not any(k.startswith("ct_") for k in row)
    assert row["strong_a"] == pytest.approx(2.5, abs=1e-12)


def test_stress_contributions_sum_to_the_total():
    rng = np.random.default_rng(2)
    f, arm = rng.normal(size=(500, 3)), rng.normal(size=(500, 3))
    labels = rng.choice(["a", "b", "c"], 500)
    parts = partial_stresses(labels, f, arm, 2.0)
    total = sum(parts.values())
    p = np.trace(total) / 3
    c = stress_contributions(parts, p, 2)
    assert sum(v[0] for v in c.values()) == pytest.approx(1, abs=1e-12)
    qa = (total[2, 2] - (total[0, 0] + total[1, 1]) / 2) / 3
    assert sum(v[1] for v in c.values()) == pytest.approx(qa / p, abs=1e-12)


def test_force_pdf_of_an_exponential_sample():
    """f_n / <f_n> drawn from exp(-x): each bin's density is within 5
    Poisson standard errors of the exact bin average."""
    rng = np.random.default_rng(3)
    n = 200_000
    x = rng.exponential(size=n) * 40.0          # any unit
    bins = np.linspace(0, 6, 25)
    c, d = force_pdf(x, bins=bins)
    scale = x.mean() / 40.0                     # x / <x> is exp with mean 1 only approximately
    exact = (np.exp(-bins[:-1] * scale) - np.exp(-bins[1:] * scale)) / np.diff(bins)
    se = np.sqrt(exact * np.diff(bins) * n) / (n * np.diff(bins))
    assert np.all(np.abs(d - exact) < 5 * se)
    c, d = force_pdf(x)                         # default log bins cover every value
    y = x / x.mean()
    edges = np.geomspace(y.min(), y.max() * (1 + 1e-12), 31)
    assert np.allclose(c, np.sqrt(edges[:-1] * edges[1:]))
    assert np.sum(d * np.diff(edges)) == pytest.approx(1, abs=1e-12)


def test_network_bad_input():
    with pytest.raises(InputError, match="no contacts"):
        strong_mask([])
    with pytest.raises(InputError, match="not finite at contact 1"):
        strong_mask([1.0, np.nan])
    with pytest.raises(InputError, match="no positive normal forces"):
        force_pdf([0.0, 0.0])
    # a network of one contact gets NaN anisotropies, not a crash
    out = network_statistics(np.array([1.0, 1.0, 5.0]), np.eye(3), np.eye(3), 2)
    assert out["strong"]["fraction"] == pytest.approx(1 / 3) and np.isnan(out["strong"]["a"])


def test_cli_writes_contact_type_outputs_and_reports_bad_shapes(tmp_path, capsys, monkeypatch):
    import os

    import pandas as pd
    from saved_figures import is_png, legend_texts, line, record

    from builders import write_snapshot
    from postproc.cli import main
    from postproc.schema import DumpWriter
    from postproc.statistics import steady_indices

    snap, _, tables = cube_lattice()
    d = snap.sizes[0]
    pts = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * d / 2
    v, t = hull(pts)
    path = str(tmp_path / "cubes.h5")
    bad_shape = snap.shape_index.copy()
    bad_shape[5] = 3
    with DumpWriter(path, "polyhedra", {}) as w:
        w.write_shapes([v], [t], [geometric_faces(v, t)])
        write_snapshot(w, snap, step=0, stage="isotropic")
        write_snapshot(w, snap, step=1, stage="shear")
        bodies = {"id": snap.body_ids, "kind": snap.body_kind, "position": snap.positions,
                  "orientation": snap.orientations, "volume": snap.volumes, "mass": snap.masses,
                  "shape_index": bad_shape, "size": snap.sizes}
        write_snapshot(w, snap, step=2, stage="shear", bodies=bodies)
    out = tmp_path / "out"
    saved = record(monkeypatch)
    assert main(["analyze", path, "--out", str(out), "--types", "angular", "--theta", "2.5"]) == 1
    err = capsys.readouterr().err
    assert "polyhedron 11 of contact" in err and "shape index 3 out of range (0..0)" in err
    for name in ("summary.csv", "force_pdf.csv"):
        assert (out / name).stat().st_size > 0, name
    for name in ("contact_types.png", "force_pdf.png", "networks.png"):
        assert is_png(out / name), name
    df = pd.read_csv(out / "summary.csv")
    assert len(df) == 2 and (df["ct_theta_deg"] == 2.5).all()
    assert df["ct_frac_EF"].iloc[-1] == pytest.approx(expected_types()["EF"] / sum(expected_types().values()))
    pdf = pd.read_csv(out / "force_pdf.csv")
    assert {"all", "FF", "EF", "EE", "triple"} <= set(pdf["class"])
    # the figures show the summary's and force_pdf.csv's numbers (each drawn once, then moved into out)
    assert "footprint.png" not in {os.path.basename(p) for p, _ in saved}      # angular: no footprints
    x = df["eps_q"].to_numpy(float)
    assert (x == 0).all()                           # the box never changes: every snapshot at eps_q = 0

    def same(ln, col):
        np.testing.assert_allclose(ln.get_xdata(), x, rtol=0, atol=0)
        np.testing.assert_allclose(ln.get_ydata(), df[col].to_numpy(float), rtol=1e-12, err_msg=col)

    fig = saved.one("contact_types.png")
    frac, ratio, fabric, share = fig.axes
    for g in ("simple", "double", "triple"):
        same(line(frac, g), f"ct_frac_{g}")
        same(line(ratio, g), f"ct_fratio_{g}")
    for t in ("VF", "EE", "EF", "FF"):
        same(line(fabric, t), f"ct_fabric_{t}")
        same(line(share, t), f"ct_qp_{t}")
    same(line(share, "total"), "q_axial_over_p")
    assert fig._suptitle.get_text() == "cubes.h5: contact types, angular tolerance 2.5 deg"
    assert frac.get_ylabel() == "proportion (bands: 1.25 to 5 deg)"
    assert all(ax.get_xlabel() == r"$\varepsilon_q$" for ax in fig.axes)
    fig = saved.one("networks.png")
    left, right = fig.axes
    for k in ("a", "a_n", "a_t"):
        same(line(left, f"strong {k}"), f"strong_{k}")
        same(line(left, f"weak {k}"), f"weak_{k}")
    shares = [k for k in ("strong", "weak", "wall") if f"{k}_qp" in df]
    assert shares[:2] == ["strong", "weak"] and legend_texts(right) == [f"{k} network" for k in shares] + ["total"]
    for k in shares:
        same(line(right, f"{k} network"), f"{k}_qp")
    same(line(right, "total"), "q_axial_over_p")
    assert left.get_ylabel() == "anisotropy" and right.get_ylabel() == r"share of $q/p$ (axial)"
    assert fig._suptitle.get_text() == "cubes.h5"
    # force_pdf.png: every class of force_pdf.csv, each counting its contacts of the pooled snapshots
    fig = saved.one("force_pdf.png")
    log, lin = fig.axes
    pool = steady_indices(df["eps_q"], df["stage"])
    pooled = len(pool)
    counts = {"all": sum(expected_types().values()), **expected_types()}
    labels = []
    for c, g in pdf.groupby("class", sort=False):
        n = int(g["count"].iloc[0])
        if c in counts:
            assert n == pooled * counts[c], c
        labels.append(f"{c} (n={n})")
        for ax, binning in ((log, "log"), (lin, "linear")):
            d = g[(g["binning"] == binning) & (g["pdf"] > 0)]
            ln = line(ax, f"{c} (n={n})")
            np.testing.assert_allclose(ln.get_xdata(), d["x"], rtol=1e-12)
            np.testing.assert_allclose(ln.get_ydata(), d["pdf"], rtol=1e-12)
    assert sorted(legend_texts(log)) == sorted(labels)
    assert log.get_xscale() == "log" and lin.get_xscale() == "linear" and lin.get_yscale() == "log"
    assert log.get_xlabel() == lin.get_xlabel() == r"$f_n/\langle f_n\rangle$"
    names = pd.read_csv(out / "summary.csv", dtype={"snapshot": str})["snapshot"]
    assert fig._suptitle.get_text() == (f"cubes.h5: snapshots {names.iloc[pool[0]]}-{names.iloc[pool[-1]]} pooled "
                                        f"({pooled}) (each class normalised by the mean over all contacts)")
    assert main(["analyze", path, "--out", str(out), "--types", "angular", "--theta", "50"]) == 2
    assert "--theta must be in (0, 45)" in capsys.readouterr().err
