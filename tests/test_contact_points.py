"""LMGC90's count of contact points (postproc.contactpoints, the "points"
criterion of postproc.classify) on hand-built pairs with exact answers:
cubes and a tetrahedron face to face, edge on face, vertex on face, crossed
edges; faces and edges tilted just below and above the tolerance; overlaps
from 1e-4 d to 1e-2 d; rigid motions and swapped sides; bad input."""
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from postproc.classify import Classifier
from postproc.contactpoints import (DOUBLE, SIMPLE, TRIPLE, check_alpha, contact_points, point_tables,
                                    touching_counts)
from postproc.errors import InputError
from shapes.overlap import pair_overlap
from shapes.polyhedron import geometric_faces
from test_contact_types import quat_from_matrix, rot
from test_footprint_types import CASES, D_CUBE, I3, SHAPES, _pairs, _pose, _snapshot, kernel_snapshot

TABLES = point_tables([v for v, _ in SHAPES], [t for _, t in SHAPES])
# name: expected (points, group) at every depth and tolerance
EXPECT = {
    "cube face on cube face": (4, TRIPLE),
    "cube edge on cube face": (2, DOUBLE),
    "cube vertex on cube face": (1, SIMPLE),
    "crossed cube edges": (1, SIMPLE),
    "tetrahedron vertex on cube face": (1, SIMPLE),
    "tetrahedron edge on cube face": (2, DOUBLE),
    "tetrahedron face on cube face": (3, TRIPLE),
}


def _classifier(**kw):
    shapes = [(v, t, geometric_faces(v, t)) for v, t in SHAPES]
    return Classifier(tuple(map(list, zip(*shapes))), method="points", **kw)


def _arrays(pairs):
    """contact_points arguments for pairs [(sa, Ra, xa, sb, Rb, xb)], with
    the kernel's exact normal and h = V / area."""
    cols = {k: [] for k in ("sa", "xa", "qa", "sb", "xb", "qb", "n", "h")}
    for sa, Ra, xa, sb, Rb, xb in pairs:
        qa, qb = quat_from_matrix(Ra), quat_from_matrix(Rb)
        r = pair_overlap(*SHAPES[sa], xa, qa, *SHAPES[sb], xb, qb)
        assert r["volume"] > 0
        for k, v in zip(cols, (sa, xa, qa, sb, xb, qb, r["normal"], r["volume"] / r["area"])):
            cols[k].append(v)
    return [np.array(v) for v in cols.values()]


@pytest.mark.parametrize("depth", [1e-4, 1e-3, 1e-2])
@pytest.mark.parametrize("alpha", [0.05, 0.1, 0.2, 1.0])
def test_known_pairs_at_every_depth_and_tolerance(depth, alpha):
    """Overlaps of 1e-4 d to 1e-2 d: the count is the geometric one (the
    neighbours of the touching features sit 0.1 d or more off the plane)."""
    names = list(EXPECT)
    r = contact_points(TABLES, *_arrays(_pairs([CASES[k] for k in names], depth)), alpha=alpha)
    assert r["points"].tolist() == [EXPECT[k][0] for k in names]
    assert r["group"].tolist() == [EXPECT[k][1] for k in names]
    # the penetration along n: the depth of B's lowest point in A when the
    # normal is the face's (cube pairs; the wider tetrahedron face also cuts
    # A's sides, which tilts the kernel's normal)
    d = depth * D_CUBE
    np.testing.assert_allclose(r["g"][0], d, rtol=1e-9)
    assert np.all(r["g"] > 0.5 * d) and np.all(r["g"] < 2 * d)


@pytest.mark.parametrize("depth", [1e-4, 1e-2])
def test_classifier_labels_dumped_and_recomputed(depth):
    """The Classifier's pair types; the overlap read from the dump
    (contacts/overlap, contacts/footprint_area) and recomputed from the
    shapes and poses give the same classes."""
    names = list(EXPECT)
    snap = _snapshot(_pairs([CASES[k] for k in names], depth))
    clf = _classifier()
    res = clf.classify(snap)
    assert res.labels.tolist() == [CASES[k][6] for k in names]
    assert res.columns["ct_method"] == "points" and res.columns["ct_fp_recomputed"] == 0
    assert res.variants["lo"].tolist() == res.labels.tolist() == res.variants["hi"].tolist()
    snap.footprint_area = None
    snap.footprint = None
    again = clf.classify(snap)
    assert again.labels.tolist() == res.labels.tolist() and again.columns["ct_fp_recomputed"] == 1


def test_rigid_motions_and_swapped_sides_change_nothing():
    names = list(EXPECT)
    rng = np.random.default_rng(11)
    for depth in (1e-4, 1e-2):
        base = _pairs([CASES[k] for k in names], depth)
        ref = contact_points(TABLES, *_arrays(base))
        for _ in range(5):
            Q = Rotation.random(random_state=rng).as_matrix()
            x0 = rng.normal(size=3) * 3
            moved = [(sa, Q @ Ra, Q @ xa + x0, sb, Q @ Rb, Q @ xb + x0) for sa, Ra, xa, sb, Rb, xb in base]
            r = contact_points(TABLES, *_arrays(moved))
            for k in ("points", "pair", "k1", "k2"):
                assert r[k].tolist() == ref[k].tolist()
            swapped = [(sb, Rb, xb, sa, Ra, xa) for sa, Ra, xa, sb, Rb, xb in moved]
            s = contact_points(TABLES, *_arrays(swapped))
            assert s["points"].tolist() == ref["points"].tolist() and s["pair"].tolist() == ref["pair"].tolist()
            assert s["k1"].tolist() == ref["k2"].tolist() and s["k2"].tolist() == ref["k1"].tolist()


def _tilted(Rb_of_phi, rise_over_h, h, alpha):
    """(points of B's side, points) for B = Rb_of_phi(phi) dipping h into
    cube A, with sin(phi) = rise_over_h * h."""
    phi = np.arcsin(rise_over_h * h)
    Rb = Rb_of_phi(phi)
    c = (0, I3, 0, Rb, (0, 0))
    xa, xb = _pose(c, h)
    r = contact_points(TABLES, *_arrays([(0, I3, xa, 0, Rb, xb)]), alpha=alpha)
    return int(r["k2"][0]), int(r["points"][0])


@pytest.mark.parametrize("h", [1e-4, 1e-3, 1e-2])
@pytest.mark.parametrize("alpha", [0.1, 1.0])
def test_a_tilted_face_just_below_and_above_the_tolerance(h, alpha):
    """Cube B on cube A, B's bottom face tilted by phi about x (its far edge
    rises sin(phi) over the unit side), B's lowest edge h into A. The
    overlap is then a wedge of mean thickness V/area = h/2 and the normal
    is +z, so the far edge touches iff sin(phi) <= h + alpha h / 2: a face
    (4 points with A's face) just below, an edge (2) just above (2 %)."""
    lim = 1 + alpha / 2
    assert _tilted(lambda p: rot([1, 0, 0], np.degrees(p)), 0.98 * lim, h, alpha) == (4, 4)
    assert _tilted(lambda p: rot([1, 0, 0], np.degrees(p)), 1.02 * lim, h, alpha) == (2, 2)


@pytest.mark.parametrize("h", [1e-4, 1e-2])
@pytest.mark.parametrize("alpha", [0.1, 1.0])
def test_a_tilted_edge_just_below_and_above_the_tolerance(h, alpha):
    """A cube edge (B turned 45 degrees about x) on A's face, tilted by phi
    about y so that its far end rises sin(phi): the overlap is a groove of
    square cross-section depth^2 tapering to 0, V/area = h/3, so the edge
    touches iff sin(phi) <= h + alpha h / 3: an edge (2 points) just below,
    a vertex (1) just above."""
    lim = 1 + alpha / 3

    def R(p):
        return rot([0, 1, 0], np.degrees(p)) @ rot([1, 0, 0], 45)

    assert _tilted(R, 0.98 * lim, h, alpha) == (2, 2)
    assert _tilted(R, 1.02 * lim, h, alpha) == (1, 1)


def test_face_face_counts_do_not_depend_on_lateral_offsets():
    """Two cube faces overlapping on an s x s corner patch, or turned 45
    degrees about the normal (no vertex of either inside the other): still
    face on face, 4 points on each side."""
    h = 1e-3
    c = CASES["cube face on cube face"]
    xa, xb = _pose(c, h)
    pairs = [(0, I3, xa, 0, I3, xb + [0.7, 0.7, 0]), (0, I3, xa, 0, rot([0, 0, 1], 45), xb)]
    r = contact_points(TABLES, *_arrays(pairs))
    assert r["points"].tolist() == [4, 4] and r["group"].tolist() == [TRIPLE, TRIPLE]


def test_bad_input_gives_one_line_errors():
    base = _arrays(_pairs([CASES["cube face on cube face"]], 1e-3))
    sa, xa, qa, sb, xb, qb, n, h = base

    def call(**over):
        args = dict(zip(("shape1", "pos1", "quat1", "shape2", "pos2", "quat2", "normal", "h"), base))
        args.update(over)
        return touching_counts(TABLES, **args)

    bad = [({"normal": n[:, :2]}, "normal must have shape"), ({"normal": 2 * n}, "not a unit vector"),
           ({"pos1": np.full_like(xa, np.nan)}, "pos1 is not finite"), ({"h": -h}, "h < 0"),
           ({"shape2": np.array([5])}, "out of range"), ({"quat1": np.zeros_like(qa)}, "zero norm"),
           ({"shape1": np.array([0.0])}, "integer")]
    for over, msg in bad:
        with pytest.raises(InputError, match=msg) as exc:
            call(**over)
        assert "\n" not in str(exc.value)
    for a in (0, -1, np.nan, "x"):
        with pytest.raises(InputError, match="--tolerance"):
            check_alpha(a)
    with pytest.raises(InputError, match="--tolerance"):
        _classifier(tolerance=0)
    with pytest.raises(InputError, match="vertices must be"):
        point_tables([np.zeros((3, 3))], [np.zeros((4, 3), int)])
    snap = _snapshot(_pairs([CASES["cube face on cube face"]], 1e-3))
    snap.footprint_area = None
    clf = _classifier()
    clf.recompute = "never"
    with pytest.raises(InputError, match="no overlap area"):
        clf.classify(snap)
    snap = _snapshot(_pairs([CASES["cube face on cube face"]], 1e-3))
    snap.footprint_area = np.array([np.nan])
    with pytest.raises(InputError, match="snapshot 000001.*not finite"):
        _classifier().classify(snap)


def test_kernel_contact_set_dumped_and_recomputed_classify_identically():
    """A contact set from the kernel engine (random library grains in a
    loose lattice) classified with the dumped overlap (V, area) and with the
    overlap recomputed from the shapes and poses: every class agrees, at
    alpha, alpha/2 and 2 alpha."""
    from postproc.classify import classifier_for

    snap, (verts, tris, faces) = kernel_snapshot(5)
    cl = classifier_for((verts, tris, faces))
    assert cl.method == "points"
    dumped = cl.classify(snap)
    rec = Classifier((verts, tris, faces), recompute="always").classify(snap)
    assert rec.columns["ct_fp_recomputed"] == 1 and dumped.columns["ct_fp_recomputed"] == 0
    assert dumped.labels.tolist() == rec.labels.tolist()
    for tag in ("lo", "hi"):
        assert dumped.variants[tag].tolist() == rec.variants[tag].tolist()
    assert len(set(dumped.labels.tolist())) >= 2


@pytest.mark.slow
def test_cli_default_is_the_point_count(tmp_path, capsys, monkeypatch):
    """postproc analyze: the point count is the default (ct_method points,
    alpha 0.1), a dump without the overlap area gives the same columns
    (recomputed), --tolerance sets alpha, a bad one gets one line, exit 2."""
    import pandas as pd

    from saved_figures import check_footprint_figure, is_png, record

    from builders import snapshot_dicts, write_snapshot
    from postproc.cli import main
    from postproc.footprint import DEFAULT_THRESHOLD, pair_size, relative_extents      # points: the figure's t
    from postproc.pipeline import FIGURE_FILES
    from postproc.schema import DumpWriter
    from postproc.statistics import steady_indices

    snap = _snapshot(_pairs(list(CASES.values()), 1e-3))
    snap.volumes = np.ones(len(snap.body_ids))
    snap.masses = np.ones(len(snap.body_ids))
    snap.wall_forces = np.zeros((6, 3))
    faces = [geometric_faces(v, t) for v, t in SHAPES]
    # the footprints the figure must show: L1/d >= L2/d of every contact, in each pooled snapshot
    rel = relative_extents(snap.footprint, pair_size(snap.sizes[0::2], snap.sizes[1::2]))
    assert np.isfinite(rel).all() and (rel[:, 1] > 0).all()
    saved = record(monkeypatch)
    out = {}
    for name, fp in (("kernel", True), ("stock", False)):
        path = str(tmp_path / f"{name}.h5")
        with DumpWriter(path, "polyhedra", {}) as w:
            w.write_shapes([v for v, _ in SHAPES], [t for _, t in SHAPES], faces)
            for step, stage in ((0, "isotropic"), (1, "shear")):
                contacts = snapshot_dicts(snap)[1]
                if fp:
                    contacts.update(footprint=snap.footprint, footprint_area=snap.footprint_area)
                write_snapshot(w, snap, step=step, stage=stage, contacts=contacts)
        assert main(["analyze", path, "--out", str(tmp_path / name), "--no-errors"]) == 0
        out[name] = pd.read_csv(tmp_path / name / "summary.csv")
        assert is_png(tmp_path / name / "footprint.png")      # the L1/d, L2/d figure stays
        assert {f.name for f in (tmp_path / name).glob("*.png")} <= set(FIGURE_FILES)   # the list --no-figures clears
        pool = steady_indices(out[name]["eps_q"], out[name]["stage"])
        figs = saved.named("footprint.png")
        assert len(figs) == len(out)                                      # one per run: this run's last
        fig = figs[-1]
        check_footprint_figure(fig, np.tile(rel, (len(pool), 1)), DEFAULT_THRESHOLD)
        assert fig.axes[0].get_title().startswith(f"{name}.h5: snapshots ")
    k, s = out["kernel"], out["stock"]
    assert (k["ct_method"] == "points").all() and (k["ct_threshold"] == 0.1).all()
    assert (k["ct_fp_recomputed"] == 0).all() and (s["ct_fp_recomputed"] == 1).all()
    cols = [c for c in k.columns if c.startswith("ct_frac_")]
    np.testing.assert_allclose(k[cols].to_numpy(float), s[cols].to_numpy(float), atol=1e-12)
    n = len(CASES)
    assert k["ct_frac_triple"].iloc[-1] == pytest.approx(2 / n) and k["ct_frac_double"].iloc[-1] == pytest.approx(2 / n)
    assert main(["analyze", str(tmp_path / "kernel.h5"), "--out", str(tmp_path / "a"), "--tolerance", "1",
                 "--no-errors"]) == 0
    assert (pd.read_csv(tmp_path / "a" / "summary.csv")["ct_threshold"] == 1.0).all()
    capsys.readouterr()
    assert main(["analyze", str(tmp_path / "kernel.h5"), "--out", str(tmp_path / "b"), "--tolerance", "-1"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--tolerance must be finite and > 0" in err[0]
    assert not (tmp_path / "b").exists()
    assert main(["analyze", str(tmp_path / "kernel.h5"), "--out", str(tmp_path / "c"), "--types", "commonplane",
                 "--tolerance", "0"]) == 2                           # commonplane's tolerance is its band tau
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "tau" in err[0] and "must be finite and > 0" in err[0]
    assert not (tmp_path / "c").exists()


def test_a_contact_without_overlap_keeps_its_angular_class():
    """Cubes 1e-9 d apart (a stock-dump contact whose exact overlap is
    empty): no slab to count in; the contact keeps its angular type."""
    snap = _snapshot(_pairs([CASES["cube face on cube face"], CASES["crossed cube edges"]], 1e-3))
    snap.positions[1::2, 2] += (1e-3 + 1e-9) * D_CUBE
    snap.footprint = snap.footprint_area = None
    res = _classifier().classify(snap)
    assert res.labels.tolist() == ["FF", "EE"] and res.columns["ct_fp_missing"] == 2
