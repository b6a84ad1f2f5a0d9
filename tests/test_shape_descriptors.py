"""Descriptors of generated and imported libraries, the side-by-side report,
``build --like`` and the study report's library section."""
import json
import os

import numpy as np
import pytest
import trimesh
from saved_figures import check_descriptor_figure, is_png, record

from shapes import polyhedron as P
from shapes.__main__ import main
from shapes.descriptors import NAMES, compare, grain_descriptors, library_descriptors
from shapes.generate import Recipe, generate_library
from shapes.library import ShapeLibrary, write_library
from shapes.match import generate_like, smoothed_bootstrap, stretch_to
from shapes.hullreduce import Budget
from shapes.meshimport import import_paths
from shapes.polyhedron import check_polyhedron, hull
from shapes.report import study_section

TOL = {k: getattr(P, k) for k in ("VERTEX_TOL", "EDGE_TOL", "HEIGHT_TOL", "VOLUME_TOL")}


@pytest.fixture(scope="module")
def generated():
    """The first 60 grains of the seed-0 library (the same as the first 60
    of ``make shapes``: one random stream)."""
    return generate_library(60, seed=0)[0]


def reimport(shapes, folder):
    """Write each grain as a binary STL (float32 coordinates) and import the
    folder with an error target of 0 (every hull vertex kept)."""
    os.makedirs(folder, exist_ok=True)
    for k, s in enumerate(shapes):
        trimesh.Trimesh(s.vertices, s.triangles, process=False).export(os.path.join(folder, f"g{k:04d}.stl"))
    grains, refused, _ = import_paths([folder], Budget(max_error=0.0, max_vertices=100))
    assert refused == []
    return grains


DX = np.sqrt(3) * 2.0 ** -25          # float32 rounding of a vertex at |x| <= d/2 = 0.5 (d = 1)


def rounding_bounds(s):
    """Bounds on how much the float32 rounding of grain s's vertices (each
    moved by at most DX) can move its descriptors: an outward normal turns
    by at most 2 DX / h per triangle (h its smallest altitude, >= 0.01 d
    here), so an edge angle by 4 DX / h; a principal axis turns by at most
    |dJ| / gap (Davis-Kahan; dJ the inertia tensor's change, gap the least
    distance between principal moments), so an extent changes by at most
    2 DX + 2 r_max |dJ| / gap, and a ratio a/b by (da + (a/b) db) / b."""
    import trimesh as tm

    v, t = s.vertices, s.triangles
    v32 = v.astype(np.float32).astype(np.float64)
    J = tm.Trimesh(v, t, process=False).moment_inertia
    dJ = np.linalg.norm(tm.Trimesh(v32, t, process=False).moment_inertia - J, 2)
    lam = np.linalg.eigvalsh(J)
    gap = np.min(np.diff(lam))
    d_ext = 2 * DX + 2 * np.linalg.norm(v, axis=1).max() * 2 * dJ / gap
    L, I, S = s.dims
    _, area = P.triangle_normals(v, t)
    longest = np.max([np.linalg.norm(v[t[:, i]] - v[t[:, (i + 1) % 3]], axis=1) for i in range(3)], axis=0)
    angle = np.degrees(4 * DX / (2 * area / longest).min())
    rel_vol_area = DX * area.sum() / s.volume + 2 * DX * 3 / (2 * area / longest).min()
    return {"elongation": (d_ext + I / L * d_ext) / L, "flatness": (d_ext + S / I * d_ext) / I,
            "s_over_l": (d_ext + S / L * d_ext) / L, "sphericity": rel_vol_area,
            "angularity_deg": angle, "sharpest_edge_deg": angle}


def check_reproduced(shapes, grains):
    """Every imported grain has the descriptors of the float32-rounded
    generated grain to float64 round-off (the import adds no error of its
    own), and differs from the float64 original by no more than the
    rounding can explain (:func:`rounding_bounds`). Returns the largest
    differences from the originals."""
    worst = {k: 0.0 for k in NAMES[:9]}
    for s, g in zip(shapes, grains):
        v32 = s.vertices.astype(np.float32).astype(np.float64)
        vh, th = hull(v32)
        ref = grain_descriptors(vh, th)
        got = grain_descriptors(g.polyhedron.vertices, g.polyhedron.triangles, g.polyhedron.triangle_face,
                                dims=g.polyhedron.dims)
        orig = grain_descriptors(s.vertices, s.triangles, s.triangle_face, dims=s.dims)
        bound = rounding_bounds(s)
        for k in ref:
            if k.startswith("n_"):
                assert got[k] == ref[k] == orig[k], k
            else:
                assert got[k] == pytest.approx(ref[k], rel=1e-9, abs=1e-9), k
                assert abs(got[k] - orig[k]) <= bound[k], (k, got[k] - orig[k], bound[k])
                worst[k] = max(worst[k], abs(got[k] - orig[k]))
        assert g.convexity_deficit < 1e-9 and g.reduction_hausdorff < 1e-12 and abs(g.reduction_volume_change) < 1e-12
    return worst


def test_generated_grains_written_as_stl_reimport_with_their_descriptors(generated, tmp_path):
    """60 grains of the seed-0 library through STL (float32) and back: each
    grain's descriptors within the bounds of the rounding
    (:func:`check_reproduced`), so the library's distributions keep their
    order: the KS distance between the two is at most one grain in 60.
    (The same check on all 1000 grains of ``make shapes`` took 70-170 s and
    found at most 2 of 1000 moving rank; the per-grain bounds are the
    stronger check.)"""
    shapes = generated[:60]
    grains = reimport(shapes, str(tmp_path / "stl"))
    check_reproduced(shapes, grains)
    a = {k: np.array([grain_descriptors(s.vertices, s.triangles)[k] for s in shapes]) for k in NAMES[:9]}
    b = {k: np.array([grain_descriptors(g.polyhedron.vertices, g.polyhedron.triangles)[k] for g in grains])
         for k in NAMES[:9]}
    for k, st in compare(a, b, NAMES[:9]).items():
        assert st["ks_D"] <= 1 / 60 + 1e-12, k


def test_descriptors_are_invariant_and_compare_is_zero_on_itself(generated):
    s = generated[3]
    rng = np.random.default_rng(1)
    Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    if np.linalg.det(Q) < 0:
        Q[:, 0] *= -1
    a = grain_descriptors(s.vertices, s.triangles)
    b = grain_descriptors(s.vertices @ Q.T * 0.037 + 5.0, s.triangles)
    for k in a:
        assert b[k] == pytest.approx(a[k], rel=1e-9), k
    x = {k: np.arange(10.0) for k in NAMES}
    st = compare(x, x)
    assert all(v["ks_D"] == 0 and v["dq50"] == 0 for v in st.values())
    # KS D of two disjoint samples is 1
    assert compare({"e": np.zeros(5) + 0.1}, {"e": np.ones(7)}, ["e"])["e"]["ks_D"] == 1.0


def test_smoothed_bootstrap_keeps_mean_and_variance():
    """E[x*] = m; Var[x*] = (s^2 (n-1)/n + h^2) / (1 + h^2/s^2) (the
    resampled population variance plus the kernel's, shrunk): checked on
    k draws within 5 standard errors of the sample mean and variance."""
    n, k = 50, 200_000
    x = np.random.default_rng(0).uniform(0.4, 0.9, n)
    rng = np.random.default_rng(1)
    y = smoothed_bootstrap(x, rng.integers(n, size=k), rng)
    s2 = x.var(ddof=1)
    h2 = (1.06 * np.sqrt(s2) * n ** -0.2) ** 2
    expect = (s2 * (n - 1) / n + h2) / (1 + h2 / s2)
    assert abs(y.mean() - x.mean()) < 5 * y.std() / np.sqrt(k)
    assert abs(y.var() - expect) < 5 * np.sqrt(np.var((y - y.mean()) ** 2) / k)


def test_stretch_gives_the_drawn_elongation_and_flatness_exactly(generated):
    for s in generated[:20]:
        e, f = 0.6, 0.55
        try:
            p = stretch_to(s, e, f)
        except P.ShapeError:
            continue
        check_polyhedron(p.vertices, p.triangles, p.triangle_face)
        assert p.dims[1] / p.dims[0] == pytest.approx(e, rel=1e-9)
        assert p.dims[2] / p.dims[1] == pytest.approx(f, rel=1e-9)
        assert p.n_vertices == s.n_vertices


def target_library(path, n=50, seed=7):
    """A family unlike the default recipe: elongated and flat grains with
    10-16 vertices."""
    r = Recipe(v_min=10, v_max=16, v_beta=(2.0, 2.0), elongation=(0.4, 0.6), flatness=(0.35, 0.55),
               max_s_over_l=1.0)
    shapes, _ = generate_library(n, seed=seed, recipe=r)
    write_library(str(path), shapes, seed, r.as_dict(), TOL, name="target family")
    return ShapeLibrary(str(path))


def test_build_like_matches_the_target_and_the_default_does_not(tmp_path, default_library, capsys, monkeypatch):
    saved = record(monkeypatch)
    target = target_library(tmp_path / "target.h5")
    out = tmp_path / "like.h5"
    assert main(["build", "--like", str(target.path), "--n", "150", "--seed", "2", "--out", str(out)]) == 0
    err = capsys.readouterr().err
    assert "KS D" in err
    # progress on stderr, every n // 20 grains and at the end
    assert "shapes: --like: 7 of 150 grains in" in err and "shapes: --like: 150 of 150 grains in" in err
    like = ShapeLibrary(str(out))
    stats = json.loads((tmp_path / "like-report" / "compare.json").read_text())["stats"]
    default = library_descriptors(ShapeLibrary(str(default_library)))
    off = compare(library_descriptors(target), default)
    for k in ("elongation", "flatness", "n_vertices"):
        # the match: below the 95 % critical value of two samples from one distribution
        assert stats[k]["ks_D"] < stats[k]["ks_D_crit95"], (k, stats[k])
        # the test can tell: the default recipe is far outside it
        assert off[k]["ks_D"] > 2 * off[k]["ks_D_crit95"], (k, off[k])
    assert set(like.n_vertices.tolist()) <= set(target.n_vertices.tolist())
    assert json.loads(like.attrs["recipe"])["like"] == str(target.path)
    md = (tmp_path / "like-report" / "compare.md").read_text()
    assert "target" in md and "KS D" in md and is_png(tmp_path / "like-report" / "compare.png")
    # compare.md says which descriptors are matched and which are not, each with its measured D;
    # the summary names the unmatched ones that differ
    matched = next(x for x in md.splitlines() if x.startswith("Matched by construction"))
    rest = next(x for x in md.splitlines() if x.startswith("Not matched"))
    for k, label in (("elongation", "elongation I/L"), ("flatness", "flatness S/I"), ("n_vertices", "vertices")):
        assert f"{label} D = {stats[k]['ks_D']:.3f}" in matched
    for k, label in (("sphericity", "Wadell sphericity"), ("n_faces", "faces"),
                     ("sharpest_edge_deg", "sharpest edge (deg)")):
        assert f"{label} D = {stats[k]['ks_D']:.3f}" in rest and label not in matched
        differs = stats[k]["ks_D"] > stats[k]["ks_D_crit95"]
        assert (f"{label} {stats[k]['ks_D']:.3f}" in err.split("not matched")[1]) == differs
    # compare.png: the target's and the new library's descriptors overlaid, as labelled
    check_descriptor_figure(saved.at(tmp_path / "like-report" / "compare.png"),
                            {"target": (target, library_descriptors(target)),
                             like.name: (like, library_descriptors(like))})


def flat_disc(n_side=16, thickness=0.05):
    """A regular n-gon prism, thickness x its diameter: flatness S/I =
    thickness, elongation 1, 2 n vertices."""
    a = 2 * np.pi * np.arange(n_side) / n_side
    ring = np.stack([np.cos(a), np.sin(a), np.zeros(n_side)], axis=1) / 2
    v, t = hull(np.vstack([ring, ring + [0, 0, thickness]]))
    return P.normalise(v, t)


def test_build_like_refuses_an_unreachable_target_in_one_line_and_in_bounded_time(tmp_path, capsys):
    """A target of one very flat grain with 32 vertices (once: hours of
    redraws at grain 852 of 1000): the build stops within its draws, or its
    time, in one line naming the grain, the target grain and the
    rejections."""
    disc = flat_disc()
    e, f = disc.dims[1] / disc.dims[0], disc.dims[2] / disc.dims[1]
    assert disc.n_vertices == 32 and 0.98 < e <= 1 and 0.05 <= f < 0.052
    write_library(str(tmp_path / "flat.h5"), [disc], -1, {}, TOL, name="flat", extra={"source": ["slab.stl"]})
    rc = main(["build", "--like", str(tmp_path / "flat.h5"), "--n", "3", "--max-draws", "5",
               "--out", str(tmp_path / "like.h5")])
    err = capsys.readouterr().err
    assert rc == 2 and not (tmp_path / "like.h5").exists()      # bounded by its draws (said below), not timed
    lines = [x for x in err.strip().splitlines()]
    assert len(lines) == 1 and "Traceback" not in err, err
    assert lines[0].startswith(f"shapes: error: grain 1 of 3: no valid grain with 32 vertices, elongation {e:.3f} "
                               f"and flatness {f:.3f} (drawn from target grain 0, slab.stl: {e:.3f}, {f:.3f}) "
                               "in 5 draws (")
    assert "rejected: nearly flat edge" in lines[0] and "remove it from the target" in lines[0]
    # a slow grain is shown while it is drawn (here every draw: a heartbeat of 0 s)
    notes = []
    with pytest.raises(P.ShapeError, match="grain 1 of 2: no valid grain with 32 vertices"):
        generate_like(library_descriptors(ShapeLibrary(str(tmp_path / "flat.h5"))), 2, max_draws=3,
                      heartbeat=0.0, progress=lambda k, n, s, note: notes.append((k, n, note)))
    assert [(k, n) for k, n, _ in notes] == [(0, 2), (0, 2)]
    assert notes[0][2].startswith(f"grain 1 (32 vertices, elongation {e:.3f}, flatness {f:.3f}): 1 draws in ")
    assert "rejected: nearly flat edge" in notes[1][2]
    # the time limit stops it too
    rc = main(["build", "--like", str(tmp_path / "flat.h5"), "--n", "3", "--max-draws", "100000",
               "--max-seconds", "2", "--out", str(tmp_path / "like.h5")])
    err = capsys.readouterr().err
    assert rc == 2 and "in the time allowed (2 s; " in err and len(err.strip().splitlines()) == 1


@pytest.fixture(scope="module")
def default_library(tmp_path_factory):
    """150 grains of the default recipe (seed 3)."""
    path = tmp_path_factory.mktemp("default") / "default.h5"
    assert main(["build", "--n", "150", "--seed", "3", "--out", str(path)]) == 0
    return path


@pytest.mark.slow
def test_report_against_shows_two_libraries_side_by_side(tmp_path, default_library, capsys, monkeypatch):
    saved = record(monkeypatch)
    a = target_library(tmp_path / "a.h5", n=30)
    b = default_library
    rep = tmp_path / "rep"
    assert main(["report", str(a.path), "--report", str(rep), "--against", str(b)]) == 0
    md = (rep / "compare.md").read_text()
    assert "target family: min / mean / max" in md and "default: min / mean / max" in md
    assert "8–37, mean 20" in md
    assert (rep / "report.md").stat().st_size > 100
    assert is_png(rep / "compare.png") and is_png(rep / "descriptors.png")
    other = ShapeLibrary(str(b))
    da = library_descriptors(a)
    check_descriptor_figure(saved.at(rep / "descriptors.png"), {"target family": (a, da)})
    check_descriptor_figure(saved.at(rep / "compare.png"), {"target family": (a, da),
                                                            "default": (other, library_descriptors(other))})
    assert main(["report", str(tmp_path / "nope.h5"), "--report", str(rep)]) == 2
    assert "Traceback" not in capsys.readouterr().err


def test_study_section_names_the_library_and_shows_its_descriptors(tmp_path, monkeypatch):
    v, t = trimesh.creation.box().vertices, trimesh.creation.box().faces
    d = tmp_path / "scans"
    d.mkdir()
    for k in range(3):
        trimesh.Trimesh(np.asarray(v) * [1, 0.8 - 0.1 * k, 0.5], t).export(str(d / f"s{k}.stl"))
    assert main(["import", str(d), "--out", str(tmp_path / "scans.h5"), "--name", "my boxes"]) == 0
    saved = record(monkeypatch)
    lines = study_section(str(tmp_path / "scans.h5"), str(tmp_path))
    text = "\n".join(lines)
    assert "## The grains of S1" in text and "**my boxes**" in text and "imported from 3 meshes" in text
    assert "8–37, mean 20" in text and "12–70, mean 35" in text and "convexity deficit" in text
    assert is_png(tmp_path / "library_descriptors.png")
    lib = ShapeLibrary(str(tmp_path / "scans.h5"))
    check_descriptor_figure(saved.at(tmp_path / "library_descriptors.png"),
                            {"my boxes": (lib, library_descriptors(lib))})
    bad = study_section(str(tmp_path / "missing.h5"), str(tmp_path))
    assert "could not be read" in "\n".join(bad)
