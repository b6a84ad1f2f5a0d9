"""The ballast-like shape library."""
import numpy as np
import pytest

from shapes import polyhedron as P
from shapes.generate import Recipe, generate_library
from shapes.library import LibraryError, ShapeLibrary, write_library
from shapes.polyhedron import ShapeError, check_polyhedron, polyhedron_from_points
from shapes.report import PUBLISHED, library_stats
from shapes.sizes import CLASS_DIAMETERS, CLASS_FRACTIONS, class_counts, sample_diameters

N_LIBRARY = 1000


@pytest.fixture(scope="module")
def library(tmp_path_factory):
    shapes, rejections = generate_library(N_LIBRARY, seed=0)
    path = tmp_path_factory.mktemp("lib") / "lib.h5"
    tol = {k: getattr(P, k) for k in ("VERTEX_TOL", "EDGE_TOL", "HEIGHT_TOL", "VOLUME_TOL")}
    write_library(str(path), shapes, 0, Recipe().as_dict(), tol)
    return ShapeLibrary(str(path))


def test_every_shape_is_valid_and_normalised(library):
    for s in range(len(library)):
        v, t, tf = library[s]
        check_polyhedron(v, t, tf)
        assert 2 * np.max(np.linalg.norm(v, axis=1)) == pytest.approx(1.0, abs=1e-12)
        # Euler's formula on the geometric counts; every face is a triangle
        assert library.n_vertices[s] - library.n_edges[s] + library.n_faces[s] == 2
        assert library.n_faces[s] == len(t)


def test_counts_match_the_published_library(library):
    st = library_stats(library)
    for key, (lo, hi, mean) in PUBLISHED.items():
        x = getattr(library, key)
        assert x.min() >= lo and x.max() <= hi, key
        assert abs(x.mean() / mean - 1) < 0.15, (key, x.mean())
        assert st[key]["mean"] == pytest.approx(x.mean())
    # crushed stone, not blobs: every grain is elongated or flat (S/L <= 0.8)
    assert np.all(library.dims[:, 2] / library.dims[:, 0] <= Recipe().max_s_over_l + 1e-12)


def tetra_mass_properties(v, t):
    """Independent volume, barycentre and inertia (unit density) by
    decomposition into tetrahedra (origin, triangle); integral of x x^T over
    a tetrahedron (0, a, b, c) = V/20 (a a^T + b b^T + c c^T + s s^T), s = a+b+c."""
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    vol = np.einsum("ij,ij->i", a, np.cross(b, c)) / 6
    V = vol.sum()
    centre = (vol[:, None] * (a + b + c) / 4).sum(axis=0) / V
    s = a + b + c
    C = sum(np.einsum("i,ij,ik->jk", vol / 20, x, x) for x in (a, b, c, s))
    C -= V * np.outer(centre, centre)
    return V, centre, np.trace(C) * np.eye(3) - C


def test_mass_properties_agree_with_tetrahedral_decomposition(library):
    for s in range(0, len(library), 7):
        v, t, _ = library[s]
        V, centre, I = tetra_mass_properties(v, t)
        assert abs(V / library.volume[s] - 1) < 1e-10
        assert np.linalg.norm(centre) < 1e-10          # d = 1
        scale = np.linalg.norm(I)
        assert np.linalg.norm(I - library.inertia[s]) < 1e-10 * scale
        # principal frame: diagonal, increasing moments
        off = I - np.diag(np.diag(I))
        assert np.linalg.norm(off) < 1e-10 * scale
        assert np.all(np.diff(np.diag(I)) >= -1e-10 * scale)


def test_reproducible_from_seed():
    a, _ = generate_library(5, seed=42)
    b, _ = generate_library(5, seed=42)
    c, _ = generate_library(5, seed=43)
    for x, y in zip(a, b):
        np.testing.assert_array_equal(x.vertices, y.vertices)
    assert not np.array_equal(a[0].vertices, c[0].vertices)


# ------------------------------------------------------------- hard cases
CUBE = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], float)


def test_coplanar_points_are_rejected():
    rng = np.random.default_rng(0)
    grid = np.stack(np.meshgrid(np.arange(5), np.arange(4)), -1).reshape(-1, 2) * 0.25
    pts = np.column_stack([grid + rng.uniform(-0.05, 0.05, grid.shape), np.zeros(20)])
    with pytest.raises(ShapeError, match="coplanar"):
        polyhedron_from_points(pts)
    pts[:, 2] = 1e-9 * rng.uniform(size=20)      # nearly coplanar
    with pytest.raises(ShapeError, match="coplanar"):
        polyhedron_from_points(pts)


def test_sliver_tetrahedron_is_rejected():
    sliver = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.3, 0.3, 0.003]])
    with pytest.raises(ShapeError, match="coplanar|sliver"):
        polyhedron_from_points(sliver)
    # a sliver face on an otherwise fat body: a cube with one vertex nudged
    # barely out of its face plane makes a needle-thin triangle
    pts = np.vstack([CUBE, [[0.5, 1e-3, 1.0005]]])
    with pytest.raises(ShapeError):
        polyhedron_from_points(pts, allow_interior=True)


def test_duplicate_vertices_are_rejected():
    with pytest.raises(ShapeError, match="duplicate"):
        polyhedron_from_points(np.vstack([CUBE, CUBE[3]]))
    with pytest.raises(ShapeError, match="near-duplicate vertices"):
        polyhedron_from_points(np.vstack([CUBE, CUBE[3] + 1e-6]))


@pytest.mark.parametrize("scale", [1e-6, 1e6])
def test_scaling_is_handled(scale):
    (grain,), _ = generate_library(1, seed=3)
    pts = grain.vertices
    ref = polyhedron_from_points(pts)
    scaled = polyhedron_from_points(pts * scale + 5 * scale)
    np.testing.assert_allclose(scaled.vertices, ref.vertices, atol=1e-9)
    assert scaled.volume == pytest.approx(ref.volume, rel=1e-9)


def test_bad_meshes_are_rejected():
    v, t = P.hull(CUBE)
    check_polyhedron(v, t)
    with pytest.raises(ShapeError, match="not closed|vertex .* belongs to no triangle"):
        check_polyhedron(v, t[1:])
    flipped = t.copy()
    flipped[0] = flipped[0][[0, 2, 1]]
    with pytest.raises(ShapeError, match="oriented|closed"):
        check_polyhedron(v, flipped)
    inward = t[:, [0, 2, 1]]
    with pytest.raises(ShapeError, match="not positive"):
        check_polyhedron(v, inward)
    dent = v.copy()
    dent[0] = dent[0] * 0.6 + v.mean(axis=0) * 0.4       # push a corner inwards
    with pytest.raises(ShapeError, match="not convex"):
        check_polyhedron(dent, t)
    with pytest.raises(ShapeError, match="NaN"):
        polyhedron_from_points(np.vstack([CUBE, [np.nan, 0, 0]]))
    with pytest.raises(ShapeError, match="inside the hull"):
        polyhedron_from_points(np.vstack([CUBE, [0.5, 0.5, 0.5]]))


def test_library_reader_errors(tmp_path):
    with pytest.raises(LibraryError, match="no such shape library"):
        ShapeLibrary(str(tmp_path / "none.h5"))
    (tmp_path / "junk.h5").write_bytes(b"not hdf5")
    with pytest.raises(LibraryError, match="unreadable"):
        ShapeLibrary(str(tmp_path / "junk.h5"))


# ------------------------------------------------------------- sizes
def test_size_classes_within_binomial_error():
    n = 200_000
    d = sample_diameters(n, seed=1, exact=False)
    for dc, p in zip(CLASS_DIAMETERS, CLASS_FRACTIONS):
        frac = np.mean(d == dc)
        assert abs(frac - p) < 5 * np.sqrt(p * (1 - p) / n)
    assert set(np.unique(d)) == set(CLASS_DIAMETERS)


def test_exact_class_counts_and_reproducibility():
    assert class_counts(100).tolist() == [50, 34, 16]
    assert class_counts(7).sum() == 7
    d = sample_diameters(1000, seed=5)
    assert [int(np.sum(d == c)) for c in CLASS_DIAMETERS] == [500, 340, 160]
    np.testing.assert_array_equal(d, sample_diameters(1000, seed=5))
    assert not np.array_equal(d, sample_diameters(1000, seed=6))


def test_build_command_writes_library_and_report(tmp_path, monkeypatch):
    """The report's figures show the library written: its vertex and face
    counts, its Zingg ratios and sphericities, a sheet of its first dozen
    grains and its descriptors (each figure read back as it was saved)."""
    from saved_figures import bars, check_descriptor_figure, is_png, legend_texts, record

    from shapes.__main__ import main
    from shapes.descriptors import library_descriptors

    saved = record(monkeypatch)
    out = tmp_path / "lib.h5"
    rep = tmp_path / "rep"
    assert main(["build", "--n", "24", "--seed", "1", "--out", str(out), "--report", str(rep)]) == 0
    lib = ShapeLibrary(str(out))
    assert len(lib) == 24
    for f in ("report.md", "stats.json"):
        assert (rep / f).stat().st_size > 100
    for f in ("counts.png", "shape_ratios.png", "sheet.png", "descriptors.png"):
        assert is_png(rep / f), f
    # counts.png: one bar per count, every grain counted once, the published range and both means
    fig = saved.at(rep / "counts.png")
    for ax, key, label in zip(fig.axes, ("n_vertices", "n_faces"), ("vertices", "geometric faces")):
        x = getattr(lib, key)
        left, width, height = bars(ax)
        np.testing.assert_array_equal(left + width / 2, np.arange(x.min(), x.max() + 1))
        np.testing.assert_array_equal(height, np.bincount(x - x.min()))
        lo, hi, mean = PUBLISHED[key]
        assert legend_texts(ax) == [f"published range {lo}-{hi}", f"published mean {mean:g}",
                                    f"library mean {x.mean():.1f}"]
        means = {ln.get_label(): ln.get_xdata()[0] for ln in ax.get_lines()}
        assert means == {f"published mean {mean:g}": mean, f"library mean {x.mean():.1f}": pytest.approx(x.mean())}
        assert ax.get_xlabel() == label
    assert len(fig.axes) == 2
    # shape_ratios.png: every grain's I/L and S/I, and the histogram of the sphericities
    zingg, sph = saved.at(rep / "shape_ratios.png").axes
    np.testing.assert_array_equal(zingg.collections[0].get_offsets(),
                                  np.column_stack([lib.dims[:, 1] / lib.dims[:, 0], lib.dims[:, 2] / lib.dims[:, 1]]))
    assert zingg.get_xlabel() == "elongation I/L" and zingg.get_ylabel() == "flatness S/I"
    left, width, height = bars(sph)
    counts, edges = np.histogram(lib.sphericity, bins=30)
    np.testing.assert_array_equal(height, counts)
    np.testing.assert_allclose(np.r_[left, left[-1] + width[-1]], edges, rtol=1e-12)
    assert height.sum() == 24 and sph.get_xlabel() == "Wadell sphericity"
    # sheet.png: the first 12 grains, each drawn with all its triangles
    sheet = saved.at(rep / "sheet.png").axes
    assert len(sheet) == 12
    for k, ax in enumerate(sheet):
        assert ax.get_title() == f"#{k}: {lib.n_vertices[k]} v, {lib.n_faces[k]} f"
        assert len(ax.collections) == 1 and len(ax.collections[0].get_paths()) == len(lib[k][1])
    check_descriptor_figure(saved.at(rep / "descriptors.png"), {lib.name: (lib, library_descriptors(lib))})


def test_build_makes_the_folder_of_its_library(tmp_path, capsys):
    """``python -m shapes build --out NEW/DIR/LIB.h5`` (docs/shapes.md) makes
    the missing folders; a folder that cannot be made is one line, exit 2."""
    from shapes.__main__ import main

    out = tmp_path / "new" / "dir" / "lib.h5"
    assert main(["build", "--n", "3", "--seed", "2", "--out", str(out)]) == 0
    assert len(ShapeLibrary(str(out))) == 3
    assert (tmp_path / "new" / "dir" / "lib-report" / "report.md").exists()
    capsys.readouterr()
    (tmp_path / "file").write_text("")
    assert main(["build", "--n", "3", "--out", str(tmp_path / "file" / "lib.h5")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("shapes: error: cannot make the folder of --out")


def test_a_library_that_cannot_be_written_is_one_line_and_leaves_no_tmp(tmp_path, capsys, monkeypatch):
    """An --out that cannot be written is refused before the build; a disk
    that fills during the write is a LibraryError in one line (exit 2),
    with no half-written .tmp file left."""
    import errno

    import shapes.library as L
    from shapes.__main__ import main

    (tmp_path / "dir.h5").mkdir()
    assert main(["build", "--n", "3", "--out", str(tmp_path / "dir.h5")]) == 2
    assert capsys.readouterr().err.strip() == f"shapes: error: --out {tmp_path / 'dir.h5'} is a folder, not a library file"
    ro = tmp_path / "ro"
    ro.mkdir()
    monkeypatch.setattr("builtins.open", _refusing_open(open, str(ro)))
    assert main(["build", "--n", "3", "--out", str(ro / "lib.h5")]) == 2
    assert capsys.readouterr().err.strip() == f"shapes: error: cannot write --out {ro / 'lib.h5'}: Permission denied"
    monkeypatch.undo()

    def full(tmp, *args):
        open(tmp, "wb").write(b"half")
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(L, "_write_tmp", full)
    out = tmp_path / "lib.h5"
    with pytest.raises(LibraryError, match=r"lib.h5: cannot write the library \(No space left on device\)"):
        write_library(str(out), [], 0, {}, {})
    assert main(["build", "--n", "3", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"shapes: error: {out}: cannot write the library (No space left on device)"]
    assert not out.exists() and not (tmp_path / "lib.h5.tmp").exists()


def _refusing_open(real, folder):
    """``open`` that refuses to create files in ``folder`` (root ignores
    file modes, so permission is simulated)."""
    import errno

    def fake(path, mode="r", *args, **kw):
        if str(path).startswith(folder) and any(c in mode for c in "wax"):
            raise PermissionError(errno.EACCES, "Permission denied", str(path))
        return real(path, mode, *args, **kw)
    return fake
