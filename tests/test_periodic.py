"""Periodic cells: minimum-image branch vectors in flat tables
(--cell) and in dumps (the optional /cell), against exact lattice stresses
and invariance under re-wrapping."""
import numpy as np
import pandas as pd
import pytest

from postproc.cli import main
from postproc.errors import InputError
from postproc.periodic import minimum_image
from postproc.schema import DumpFormatError, DumpReader, DumpWriter
from postproc.tables import read_contact_table

STRESS = ("s_xx", "s_yy", "s_zz", "s_yz", "s_xz", "s_xy", "p", "q", "q_over_p")
FABRIC = ("a", "a_l", "a_n", "a_t", "a_se", "a_n_se", "l0", "f0", "a_fit", "a_n_fit",
          "b_xx", "b_zz", "b_xz", "sff")


def periodic_lattice(n=(3, 4, 5), d=0.02, F=(3.0, 5.0, 7.0), T=1.5):
    """Simple cubic lattice of spacing d filling the periodic cell n*d. Each
    particle touches its + neighbour along every axis (wrapping across the
    boundary); x-contacts carry F_x e_x + T e_y, y-contacts T e_x + F_y e_y,
    z-contacts F_z e_z. Exact stress (every particle in equilibrium, no
    boundary term): [[F_x, T, 0], [T, F_y, 0], [0, 0, F_z]] / d^2."""
    n = np.array(n)
    g = np.stack(np.meshgrid(*[np.arange(k) for k in n], indexing="ij"), -1).reshape(-1, 3)
    idx = lambda gg: np.ravel_multi_index(tuple((gg % n).T), n)  # noqa: E731
    pos = (g + 0.5) * d
    forces = [np.array([F[0], T, 0.0]), np.array([T, F[1], 0.0]), np.array([0, 0, F[2]])]
    rows = []
    for b in range(3):
        e = np.eye(3, dtype=int)[b]
        j = idx(g + e)
        i = idx(g)
        rows.append(pd.DataFrame({
            "id1": i, "id2": j, "x1": pos[i, 0], "y1": pos[i, 1], "z1": pos[i, 2],
            "x2": pos[j, 0], "y2": pos[j, 1], "z2": pos[j, 2],
            "cx": pos[i, 0] + d / 2 * e[0], "cy": pos[i, 1] + d / 2 * e[1],
            "cz": pos[i, 2] + d / 2 * e[2],
            "fx": forces[b][0], "fy": forces[b][1], "fz": forces[b][2]}))
    sigma = np.array([[F[0], T, 0], [T, F[1], 0], [0, 0, F[2]]]) / d ** 2
    return pd.concat(rows, ignore_index=True), n * d, sigma


def random_periodic(seed=0, n=600, L=(1.0, 1.2, 0.9)):
    """Random spheres in a periodic cell joined within a cut-off (cKDTree with
    boxsize: an independent minimum image), with random forces."""
    from scipy.spatial import cKDTree

    rng = np.random.default_rng(seed)
    L = np.array(L)
    x = rng.random((n, 3)) * L
    r = (3 * 6 * np.prod(L) / (4 * np.pi * n)) ** (1 / 3)
    pairs = cKDTree(x, boxsize=L).query_pairs(r, output_type="ndarray")
    i, j = pairs[:, 0], pairs[:, 1]
    dx = x[j] - x[i]
    true_branch = dx - L * np.round(dx / L)
    f = rng.normal(size=(len(i), 3)) + 2.0 * true_branch / r
    df = pd.DataFrame({"id1": i, "id2": j, "x1": x[i, 0], "y1": x[i, 1], "z1": x[i, 2],
                       "x2": x[j, 0], "y2": x[j, 1], "z2": x[j, 2],
                       "cx": x[i, 0] + true_branch[:, 0] / 2,
                       "cy": x[i, 1] + true_branch[:, 1] / 2,
                       "cz": x[i, 2] + true_branch[:, 2] / 2,
                       "fx": f[:, 0], "fy": f[:, 1], "fz": f[:, 2]})
    return df, L, true_branch


def analyze_table(tmp_path, df, name, *opts):
    path = tmp_path / f"{name}.csv"
    df.to_csv(path, index=False)
    out = tmp_path / f"out_{name}"
    assert main(["analyze", str(path), "--out", str(out), "--no-progress", "--no-figures", *opts]) == 0
    return pd.read_csv(out / "summary.csv").iloc[0]


def test_periodic_lattice_exact_stress_across_the_boundary(tmp_path):
    df, L, sigma = periodic_lattice()
    row = analyze_table(tmp_path, df, "lat", "--cell", *map(str, L))
    ij = {"xx": (0, 0), "yy": (1, 1), "zz": (2, 2), "yz": (1, 2), "xz": (0, 2), "xy": (0, 1)}
    for c, (a, b) in ij.items():
        # round-off only: 180 contacts of O(1) terms
        assert row[f"s_{c}"] == pytest.approx(sigma[a, b], rel=1e-12, abs=1e-12 * sigma.max())
        assert row[f"b_{c}"] == pytest.approx(sigma[a, b], rel=1e-12, abs=1e-12 * sigma.max())
    assert row["volume"] == pytest.approx(np.prod(L), rel=1e-15)
    # every particle has 6 bearing contacts in an infinite lattice: no rattler
    assert row["z"] == 6 and row["n_rattlers"] == 0
    assert row["a"] == pytest.approx(0, abs=1e-12)
    # read as a closed box, each line of the lattice has n-1 branch vectors
    # +d and one -(n-1)d across the boundary: the stress cancels exactly
    flat = analyze_table(tmp_path, df, "flat", "--volume", repr(float(np.prod(L))))
    assert abs(flat["s_xx"]) < 1e-12 * sigma.max() and abs(flat["s_zz"]) < 1e-12 * sigma.max()


@pytest.mark.slow
def test_same_contacts_with_and_without_wrapping_give_the_same_row(tmp_path):
    df, L, _ = random_periodic()
    ref = analyze_table(tmp_path, df, "wrapped", "--cell", *map(str, L))
    rng = np.random.default_rng(1)
    # each body moved to one image of its own (unwrapped) ...
    nb = int(max(df.id1.max(), df.id2.max())) + 1
    shift = rng.integers(-3, 4, size=(nb, 3)) * L
    un = df.copy()
    for s, cols in (("1", ["x1", "y1", "z1"]), ("2", ["x2", "y2", "z2"])):
        un[cols] = df[cols].to_numpy() + shift[df["id" + s].to_numpy()]
    # ... and every row with an image of its own (a body at several images)
    rows = df.copy()
    for cols in (["x1", "y1", "z1"], ["x2", "y2", "z2"], ["cx", "cy", "cz"]):
        rows[cols] = df[cols].to_numpy() + rng.integers(-2, 3, size=(len(df), 3)) * L
    # ... and with the branch vectors given explicitly
    br = df.copy()
    d = df[["x2", "y2", "z2"]].to_numpy() - df[["x1", "y1", "z1"]].to_numpy()
    br[["lx", "ly", "lz"]] = d - L * np.round(d / L)
    for name, other in (("unwrapped", un), ("images", rows), ("branch", br)):
        got = analyze_table(tmp_path, other, name, "--cell", *map(str, L))
        for c in ref.index:
            if isinstance(ref[c], str):
                assert got[c] == ref[c], (name, c)
            else:
                assert got[c] == pytest.approx(ref[c], rel=1e-9, abs=1e-9 * abs(ref["p"]) + 1e-300,
                                               nan_ok=True), (name, c)


def test_periodic_row_matches_an_independent_unwrapped_computation(tmp_path):
    # each contact with its own pair of ids and the true (cKDTree) branch
    # vector: no periodicity needed, the stress and fabric must agree
    df, L, true_branch = random_periodic(seed=3)
    ref = analyze_table(tmp_path, df, "cell", "--cell", *map(str, L))
    flat = df.copy()
    C = len(df)
    flat["id1"], flat["id2"] = np.arange(C), C + np.arange(C)
    flat[["x2", "y2", "z2"]] = df[["x1", "y1", "z1"]].to_numpy() + true_branch
    got = analyze_table(tmp_path, flat, "flat", "--volume", repr(float(np.prod(L))))
    for c in STRESS + FABRIC:
        assert got[c] == pytest.approx(ref[c], rel=1e-10, abs=1e-12), c


def test_minimum_image_sheared_cell_by_fractional_coordinates():
    H = np.array([[1.0, 0.0, 0.3], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    d = np.array([[0.05, 0.0, 0.05]])
    for n in ([0, 0, 1], [2, -1, 0], [-1, 3, -2]):
        assert np.allclose(minimum_image(d + H @ np.array(n), H), d, atol=1e-14)


def test_dump_with_a_sheared_periodic_cell(tmp_path):
    # a lattice in a sheared cell (columns of H are the cell vectors), written
    # with no walls; central forces F_b along each lattice direction b
    n = np.array([3, 3, 4])
    H = np.array([[0.06, 0.0, 0.024], [0.0, 0.06, 0.0], [0.0, 0.0, 0.08]])
    g = np.stack(np.meshgrid(*[np.arange(k) for k in n], indexing="ij"), -1).reshape(-1, 3)
    pos = ((g + 0.5) / n) @ H.T
    F = (2.0, 3.0, 5.0)
    id1, id2, point, fn, normal = [], [], [], [], []
    for b in range(3):
        e = np.eye(3, dtype=int)[b]
        lb = H[:, b] / n[b]
        u = lb / np.linalg.norm(lb)
        i = np.ravel_multi_index(tuple(g.T), n)
        j = np.ravel_multi_index(tuple(((g + e) % n).T), n)
        id1.append(i); id2.append(j); point.append(pos[i] + lb / 2)
        fn.append(np.tile(F[b] * u, (len(i), 1))); normal.append(np.tile(u, (len(i), 1)))
    id1, id2 = np.concatenate(id1), np.concatenate(id2)
    point, fn, normal = map(np.concatenate, (point, fn, normal))
    V = np.linalg.det(H)
    N = len(g)
    sigma = sum(N * F[b] * np.outer(H[:, b] / n[b], H[:, b] / n[b])
                / np.linalg.norm(H[:, b] / n[b]) for b in range(3)) / V
    B = len(g)
    path = str(tmp_path / "peri.h5")
    with DumpWriter(path, "spheres", {}) as w:
        w.write_snapshot(
            step=0, time=0.0, stage="shear", box_lo=np.zeros(3), box_hi=np.diag(H),
            wall_ids=[], wall_forces=np.zeros((0, 3)), cell=H,
            bodies={"id": np.arange(B), "kind": np.zeros(B), "position": pos,
                    "orientation": np.tile([1.0, 0, 0, 0], (B, 1)), "volume": np.ones(B),
                    "mass": np.ones(B), "shape_index": -np.ones(B), "size": np.full(B, 0.02)},
            contacts={"id1": id1, "id2": id2, "point": point, "normal": normal,
                      "force_normal": fn, "force_tangential": np.zeros_like(fn),
                      "overlap": np.zeros(len(id1))})
    with DumpReader(path) as r:
        snap = r.read(0)
    assert np.array_equal(snap.cell, H) and len(snap.wall_ids) == 0
    assert snap.volume == pytest.approx(V, rel=1e-15)
    out = tmp_path / "o"
    assert main(["analyze", path, "--out", str(out), "--no-progress", "--no-figures"]) == 0
    row = pd.read_csv(out / "summary.csv").iloc[0]
    for c, (a, b) in {"xx": (0, 0), "yy": (1, 1), "zz": (2, 2), "xz": (0, 2), "xy": (0, 1)}.items():
        assert row[f"s_{c}"] == pytest.approx(sigma[a, b], rel=1e-12, abs=1e-12 * sigma.max()), c
    assert np.isnan(row["p_wall"])


def test_bad_cells(tmp_path, capsys):
    df, L, _ = periodic_lattice((3, 3, 3))
    path = tmp_path / "t.csv"
    df.to_csv(path, index=False)
    with pytest.raises(InputError, match="exclude each other"):
        read_contact_table(str(path), box=L, cell=L)
    with pytest.raises(InputError, match="must be finite and > 0"):
        read_contact_table(str(path), cell=(1.0, -1.0, 1.0))
    # a body whose two centres are not images of each other
    bad = df.copy()
    bad.loc[5, "x1"] += 0.3 * L[0]
    bad.to_csv(path, index=False)
    with pytest.raises(InputError, match="not images of each other"):
        read_contact_table(str(path), cell=L)
    # half of the branch columns, NaN branch
    part = df.copy()
    part["lx"] = 0.0
    part.to_csv(path, index=False)
    with pytest.raises(InputError, match="given without ly, lz"):
        read_contact_table(str(path), cell=L)
    part["ly"], part["lz"] = 0.0, np.nan
    part.to_csv(path, index=False)
    with pytest.raises(InputError, match=r"line 2: lx,ly,lz .* missing or NaN"):
        read_contact_table(str(path), cell=L)
    with DumpWriter(str(tmp_path / "b.h5"), "spheres", {}) as w:
        with pytest.raises(DumpFormatError, match="det > 0"):
            w.write_snapshot(step=0, time=0, stage="s", box_lo=np.zeros(3), box_hi=np.ones(3),
                             wall_ids=[], wall_forces=[], bodies={}, contacts={},
                             cell=np.diag([1.0, 1.0, -1.0]))
    # --cell on a dump is refused in one line
    assert main(["analyze", str(tmp_path / "b.h5"), "--out", str(tmp_path / "o"), "--no-figures",
                 "--cell", "1", "1", "1"]) == 2
    assert "--cell are for flat contact tables" in capsys.readouterr().err
