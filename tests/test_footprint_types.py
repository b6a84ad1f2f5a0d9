"""Contact groups from the overlap's footprint (postproc.footprint,
postproc.classify) on hand-built pairs with exact answers, over depths,
rigid motions, thresholds, a kernel engine's contact set, and bad input."""
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from postproc.classify import Classifier
from postproc.errors import InputError
from postproc.footprint import (DEFAULT_THRESHOLD, DOUBLE, SIMPLE, TRIPLE, footprint_groups, pair_size,
                                relative_extents)
from postproc.schema import Snapshot
from shapes.overlap import pair_overlap
from shapes.polyhedron import geometric_faces, hull
from test_contact_types import CORNER_DOWN, quat_from_matrix, rot

CUBE = hull(np.array([[x, y, z] for x in (-.5, .5) for y in (-.5, .5) for z in (-.5, .5)], float))
TETRA_PTS = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], float) * 0.4
TETRA = hull(TETRA_PTS)
SHAPES = [CUBE, TETRA]
D_CUBE = np.sqrt(3.0)                       # d = 2 x the largest centre-to-vertex distance
D_TETRA = 2 * np.linalg.norm(TETRA_PTS[0])
I3 = np.eye(3)
T = DEFAULT_THRESHOLD


def _low(shape, R):
    """Depth of the lowest point of a shape below its centre (turned by R)."""
    return -(SHAPES[shape][0] @ R.T)[:, 2].min()


def _high(shape, R):
    return (SHAPES[shape][0] @ R.T)[:, 2].max()


def _tetra_down(feature):
    """A rotation putting a vertex, the middle of an edge or a face of the
    tetrahedron straight down (-z)."""
    v = TETRA_PTS
    target = {"vertex": v[0], "edge": (v[0] + v[1]) / 2, "face": (v[0] + v[1] + v[2]) / 3}[feature]
    R = Rotation.align_vectors([[0, 0, -1]], [target / np.linalg.norm(target)])[0].as_matrix()
    if feature == "edge":        # turn about z so that the edge lies flat (it does: symmetric)
        pass
    return R


# name: (shape A, R_A, shape B, R_B, lateral offset of B, expected group, expected type)
CASES = {
    "cube face on cube face": (0, I3, 0, I3, (0, 0), TRIPLE, "FF"),
    "cube edge on cube face": (0, I3, 0, rot([1, 0, 0], 45), (0, 0), DOUBLE, "EF"),
    "cube vertex on cube face": (0, I3, 0, CORNER_DOWN, (0, 0), SIMPLE, "VF"),
    "crossed cube edges": (0, rot([0, 1, 0], 45), 0, rot([1, 0, 0], 45), (0, 0), SIMPLE, "EE"),
    "tetrahedron vertex on cube face": (0, I3, 1, _tetra_down("vertex"), (0, 0), SIMPLE, "VF"),
    "tetrahedron edge on cube face": (0, I3, 1, _tetra_down("edge"), (0, 0), DOUBLE, "EF"),
    "tetrahedron face on cube face": (0, I3, 1, _tetra_down("face"), (0, 0), TRIPLE, "FF"),
}


def _pose(case, depth):
    """Positions: A at the origin, B above it, dipping ``depth`` m into A."""
    sa, Ra, sb, Rb, off = case[:5]
    zb = _high(sa, Ra) + _low(sb, Rb) - depth
    return np.zeros(3), np.array([off[0], off[1], zb])


def _snapshot(pairs):
    """A Snapshot of independent pairs [(sa, Ra, xa, sb, Rb, xb)], each pair
    far from the others; normals and footprints from the kernel (dumped as a
    kernel run would)."""
    k = len(pairs)
    ids = np.arange(2 * k) + 6
    pos, quat, shape, normal, fp, area, vol = [], [], [], [], [], [], []
    for m, (sa, Ra, xa, sb, Rb, xb) in enumerate(pairs):
        shift = np.array([10.0 * m, 0, 0])
        qa, qb = quat_from_matrix(Ra), quat_from_matrix(Rb)
        r = pair_overlap(*SHAPES[sa], xa + shift, qa, *SHAPES[sb], xb + shift, qb)
        pos += [xa + shift, xb + shift]
        quat += [qa, qb]
        shape += [sa, sb]
        normal.append(r["normal"])
        fp.append(r["footprint"])
        area.append(r["area"])
        vol.append(r["volume"])
    pos = np.array(pos)
    n = np.array(normal)
    f = n * 1.0
    sizes = np.array([D_CUBE, D_TETRA])[shape]
    return Snapshot(name="000001", step=1, time=0.0, stage="shear", volume=1e3, box_lo=np.zeros(3),
                    box_hi=np.full(3, 10.0), wall_ids=np.arange(6), wall_forces=None, body_ids=ids,
                    positions=pos, id1=ids[0::2].copy(), id2=ids[1::2].copy(), point=pos[0::2] + [0, 0, 0.5],
                    force=f, force_normal=f, normal=n, overlap=np.array(vol), body_kind=np.ones(2 * k, np.int8),
                    orientations=np.array(quat), shape_index=np.array(shape, np.int32), sizes=sizes,
                    footprint=np.array(fp), footprint_area=np.array(area))


@pytest.fixture(scope="module")
def classifier():
    shapes = [(v, t, geometric_faces(v, t)) for v, t in SHAPES]
    return Classifier(tuple(map(list, zip(*shapes))), method="footprint")


def _pairs(cases, depth_of_d):
    out = []
    for c in cases:
        d = pair_size(np.array([D_CUBE, D_TETRA])[c[0]], np.array([D_CUBE, D_TETRA])[c[2]])
        xa, xb = _pose(c, depth_of_d * d)
        out.append((c[0], c[1], xa, c[2], c[3], xb))
    return out


def test_exact_footprints_of_the_cube_pairs():
    """Face-face: the whole face (1 x 1); edge-face: the edge by twice the
    depth (the cube's 90-degree edge at 45 degrees); vertex-face: the
    equilateral triangle cut off the corner, of side a = sqrt(6) h: its
    second moment is isotropic, so its principal axes are any, and its
    widths lie between its height (sqrt(3)/2) a and a."""
    h = 1e-3
    for name, expect in (("cube face on cube face", (1.0, 1.0)), ("cube edge on cube face", (1.0, 2 * h))):
        c = CASES[name]
        xa, xb = _pose(c, h)
        r = pair_overlap(*SHAPES[c[0]], xa, quat_from_matrix(c[1]), *SHAPES[c[2]], xb, quat_from_matrix(c[3]))
        np.testing.assert_allclose(r["footprint"], expect, rtol=1e-9)
    c = CASES["cube vertex on cube face"]
    xa, xb = _pose(c, h)
    r = pair_overlap(*SHAPES[0], xa, quat_from_matrix(c[1]), *SHAPES[0], xb, quat_from_matrix(c[3]))
    a = np.sqrt(6) * h
    assert np.all(r["footprint"] >= np.sqrt(3) / 2 * a * (1 - 1e-9)) and np.all(r["footprint"] <= a * (1 + 1e-9))
    assert r["area"] == pytest.approx(np.sqrt(3) / 4 * a * a, rel=1e-9)


@pytest.mark.parametrize("depth", [1e-4, 1e-3, 1e-2])
def test_known_pairs_at_every_depth(classifier, depth):
    """Overlaps from 1e-4 d to 1e-2 d: the group and the pair type are the
    geometric ones; the dumped and the recomputed footprint agree."""
    cases = list(CASES.values())
    snap = _snapshot(_pairs(cases, depth))
    res = classifier.classify(snap)
    assert res.labels.tolist() == [c[6] for c in cases]
    groups = footprint_groups(res.rel, T)
    assert groups.tolist() == [c[5] for c in cases]
    snap.footprint = None
    again = classifier.classify(snap)
    assert again.labels.tolist() == res.labels.tolist() and again.columns["ct_fp_recomputed"] == 1
    np.testing.assert_allclose(again.rel, res.rel, rtol=1e-12)


def test_rigid_motions_and_swapped_sides_change_nothing(classifier):
    cases = list(CASES.values())
    rng = np.random.default_rng(7)
    for depth in (1e-4, 1e-2):
        base = _pairs(cases, depth)
        ref = classifier.classify(_snapshot(base))
        for _ in range(4):
            Q = Rotation.random(random_state=rng).as_matrix()
            x0 = rng.normal(size=3) * 3
            moved = [(sa, Q @ Ra, Q @ xa + x0, sb, Q @ Rb, Q @ xb + x0) for sa, Ra, xa, sb, Rb, xb in base]
            res = classifier.classify(_snapshot(moved))
            assert res.labels.tolist() == ref.labels.tolist()
            # a square or an equilateral triangle has an isotropic second moment, so its
            # principal axes are any and its widths vary between w and sqrt(2) w
            ratio = res.rel / ref.rel
            assert np.all(ratio > 2 ** -0.5 - 1e-9) and np.all(ratio < 2 ** 0.5 + 1e-9)
            iso = np.array([c[6] in ("VF", "EE", "FF") for c in cases])     # symmetric footprints
            np.testing.assert_allclose(res.rel[~iso], ref.rel[~iso], rtol=1e-9)
            swapped = [(sb, Rb, xb, sa, Ra, xa) for sa, Ra, xa, sb, Rb, xb in moved]
            res = classifier.classify(_snapshot(swapped))
            assert res.labels.tolist() == ref.labels.tolist()


def test_partial_edge_and_face_just_below_and_above_the_threshold(classifier):
    """An edge lying on a face over a length s (B shifted along the edge) is
    double when s >= t d and simple below; a face on a face over an s x 3s
    or an s x 1 patch is triple when s >= t d and double below. Margins of
    2 % around t d; the footprint is exact up to the normal's tilt (relative
    order (h/s)^2). (Rectangles, not squares: a square's principal axes are
    any, and its widths vary between s and sqrt(2) s.)"""
    h = 1e-4 * D_CUBE
    td = T * D_CUBE
    pairs, expect = [], []
    for f, lab_edge in ((0.98, "VF"), (1.02, "EF")):
        s = f * td
        c = CASES["cube edge on cube face"]
        xa, xb = _pose(c, h)
        pairs.append((0, I3, xa, 0, c[3], xb + [1 - s, 0, 0]))          # edge along x over length s
        expect.append(lab_edge)
        c = CASES["cube face on cube face"]
        xa, xb = _pose(c, h)
        pairs.append((0, I3, xa, 0, I3, xb + [1 - s, 1 - 3 * s, 0]))    # an s x 3s patch
        expect.append("FF" if f > 1 else "EF")
        pairs.append((0, I3, xa, 0, I3, xb + [1 - s, 0, 0]))            # an s x 1 strip
        expect.append("FF" if f > 1 else "EF")
    res = classifier.classify(_snapshot(pairs))
    assert res.labels.tolist() == expect


def test_a_tilted_edge_just_below_and_above_the_threshold(classifier):
    """A cube edge on a face, tilted by alpha about the vertical plane of the
    edge so that its lower end dips h: it touches over h / tan(alpha) (the
    footprint's L1, to relative order alpha), a point below t d, a line
    above (10 % margins)."""
    h = 1e-3 * D_CUBE
    td = T * D_CUBE
    pairs = []
    for f in (0.9, 1.1):
        alpha = np.arctan(h / (f * td))
        Rb = rot([0, 1, 0], np.degrees(alpha)) @ rot([1, 0, 0], 45)
        zb = 0.5 + _low(0, Rb) - h
        pairs.append((0, I3, np.zeros(3), 0, Rb, np.array([0, 0, zb])))
    res = classifier.classify(_snapshot(pairs))
    assert res.labels.tolist() == ["VF", "EF"]
    np.testing.assert_allclose(res.rel[:, 0] * D_CUBE, [0.9 * td, 1.1 * td], rtol=0.02)


def test_halving_and_doubling_the_threshold_is_monotonic():
    rng = np.random.default_rng(3)
    rel = np.sort(10 ** rng.uniform(-4, 0, size=(5000, 2)), axis=1)[:, ::-1]
    g = [footprint_groups(rel, t) for t in (T / 2, T, 2 * T)]
    assert np.all(g[0] >= g[1]) and np.all(g[1] >= g[2])
    assert footprint_groups(np.array([[T, T], [T, 0.0], [np.nextafter(T, 0), 0.0]]), T).tolist() == \
        [TRIPLE, DOUBLE, SIMPLE]



def kernel_snapshot(seed):
    """A contact set from the kernel's stepping engine (no YADE): 64 random
    library grains in a loose 4 x 4 x 4 lattice, posed with rng ``seed``,
    as a Snapshot with the dumped overlap volume and footprint. Returns
    (snapshot, (vertices, triangles, geometric faces) of the shapes)."""
    from shapes.engine import ContactEngine
    from shapes.generate import generate_library

    shapes, _ = generate_library(8, seed=3)
    rng = np.random.default_rng(seed)
    m = 4
    n = m ** 3
    idx = np.stack(np.meshgrid(*[np.arange(m)] * 3, indexing="ij"), -1).reshape(-1, 3)
    pos = 0.56 * idx + rng.uniform(-0.03, 0.03, size=(n, 3))
    quat = np.roll(Rotation.random(n, random_state=rng).as_quat(), 1, axis=1)
    shape = rng.integers(len(shapes), size=n)
    verts = [s.vertices for s in shapes]
    tris = [s.triangles for s in shapes]
    faces = [geometric_faces(v, t) for v, t in zip(verts, tris)]
    sizes = np.array([2 * np.linalg.norm(verts[s], axis=1).max() for s in shape])
    eng = ContactEngine(verts, tris, shape, sizes, 1e7, 2e5, 0.5, 0.0, 0.05, walls=False, threads=1)
    eng.step(pos, quat)
    c = eng.contacts()
    eng.close()
    assert len(c["i"]) > 40
    ids = np.arange(n) + 6
    snap = Snapshot(name="000001", step=1, time=0.0, stage="shear", volume=8.0, box_lo=np.full(3, -0.5),
                    box_hi=np.full(3, 1.5), wall_ids=np.arange(6), wall_forces=None, body_ids=ids,
                    positions=pos, id1=ids[c["i"]], id2=ids[c["j"]], point=c["point"],
                    force=c["force_normal"] + c["force_tangential"], force_normal=c["force_normal"],
                    normal=c["normal"], overlap=c["volume"], body_kind=np.ones(n, np.int8), orientations=quat,
                    shape_index=shape.astype(np.int32), sizes=sizes, footprint=c["footprint"],
                    footprint_area=c["area"])
    return snap, (verts, tris, faces)


def kernel_sets_dump(path, n, wall_forces, parameters=None, overlap_kind="depth", footprint=False, points=None):
    """A polyhedra dump of ``n`` kernel contact sets (:func:`kernel_snapshot`
    of seeds 20, 21, ...): one isotropic snapshot, then shear snapshots with
    the box shortened along z by 1 % each, unit volumes and masses.

    wall_forces : (6, 3) N, every snapshot's; parameters, overlap_kind: the
    writer's; footprint: the overlaps' footprints dumped; points: a function
    of the snapshot giving its contact points (schema version 3), or None.
    Returns ``path``."""
    from builders import snapshot_dicts, write_snapshot
    from postproc.schema import DumpWriter

    with DumpWriter(path, "polyhedra", parameters or {}, overlap_kind=overlap_kind) as w:
        for k in range(n):
            snap, (verts, tris, faces) = kernel_snapshot(20 + k)
            if k == 0:
                w.write_shapes(verts, tris, faces)
            snap.volumes = np.ones(len(snap.body_ids))
            snap.masses = np.ones(len(snap.body_ids))
            hi = snap.box_hi.copy()
            hi[2] = snap.box_lo[2] + (hi[2] - snap.box_lo[2]) * (1 - 0.01 * k)
            extra = {"points": points(snap)} if points else {}
            if footprint:
                _, contacts = snapshot_dicts(snap)
                contacts.update(footprint=snap.footprint, footprint_area=snap.footprint_area)
                extra["contacts"] = contacts
            write_snapshot(w, snap, step=k, stage="isotropic" if k == 0 else "shear", box_hi=hi,
                           wall_forces=wall_forces, **extra)
    return path

def test_engine_contacts_classify_as_their_recomputation(classifier):
    """A contact set from the kernel's stepping engine (no YADE), written to
    a dump with its footprint, and the same snapshot without it (as a stock
    or version-1 dump): recomputed from the shapes and poses, every contact
    gets the same class, and the analysis rows agree."""
    from postproc.analysis import analyze_snapshot
    from postproc.classify import classifier_for

    snap, (verts, tris, faces) = kernel_snapshot(4)
    cl = classifier_for((verts, tris, faces), "footprint")
    dumped = cl.classify(snap)
    rec = Classifier((verts, tris, faces), "footprint", recompute="always").classify(snap)
    assert rec.columns["ct_fp_recomputed"] == 1 and dumped.columns["ct_fp_recomputed"] == 0
    assert dumped.labels.tolist() == rec.labels.tolist()
    for tag in ("lo", "hi"):
        assert dumped.variants[tag].tolist() == rec.variants[tag].tolist()
    np.testing.assert_allclose(dumped.rel, rec.rel, rtol=0, atol=1e-9)
    assert len(set(dumped.labels.tolist())) >= 2
    row_d = analyze_snapshot(snap, tables=cl, errors=False).row
    snap.footprint = None
    row_r = analyze_snapshot(snap, tables=cl, errors=False).row
    for k, v in row_d.items():
        if k.startswith("ct_") and k != "ct_fp_recomputed" and not isinstance(v, str):
            assert row_r[k] == pytest.approx(v, rel=1e-9, abs=1e-12, nan_ok=True), k


def test_bad_input_gets_one_line_errors(classifier):
    with pytest.raises(InputError, match=r"contact 1: footprint \[nan, 0.0\] is not finite"):
        relative_extents(np.array([[1.0, 0.5], [np.nan, 0.0]]), np.ones(2))
    with pytest.raises(InputError, match="contact 0: pair size -1.0 is not finite and > 0"):
        relative_extents(np.array([[1.0, 0.5]]), np.array([-1.0]))
    with pytest.raises(InputError, match=r"footprint must be \(C, 2\)"):
        relative_extents(np.ones((3, 3)), np.ones(3))
    snap = _snapshot(_pairs(list(CASES.values()), 1e-3))
    snap.footprint[2] = [-1.0, 0.0]
    with pytest.raises(InputError, match=r"snapshot 000001 \(step 1\): contact 2: footprint \[-1.0, 0.0\]"):
        classifier.classify(snap)
    snap = _snapshot(_pairs(list(CASES.values()), 1e-3))
    snap.footprint = snap.footprint[:3]
    with pytest.raises(InputError, match=r"contacts/footprint has shape \(3, 2\), expected \(7, 2\)"):
        classifier.classify(snap)
    snap = _snapshot(_pairs(list(CASES.values()), 1e-3))
    snap.sizes[5] = 0.0
    with pytest.raises(InputError, match="contact 2: a particle size is not finite and > 0"):
        classifier.classify(snap)
    snap = _snapshot(_pairs(list(CASES.values()), 1e-3))
    snap.footprint = None
    snap.orientations[3] = 0.0
    with pytest.raises(InputError, match="polyhedron 9 has a zero or non-finite orientation"):
        classifier.classify(snap)
    shapes = [(v, t, geometric_faces(v, t)) for v, t in SHAPES]
    for kw, msg in (({"method": "shape"}, "--types must be one of points, footprint, angular"),
                    ({"threshold": 0.0}, r"--threshold must be in \(0, 1\)"),
                    ({"threshold": float("nan")}, r"--threshold must be in \(0, 1\)"),
                    ({"theta_deg": 60}, r"--theta must be in \(0, 45\)")):
        with pytest.raises(InputError, match=msg):
            Classifier(tuple(map(list, zip(*shapes))), **kw)


def test_a_contact_without_overlap_keeps_its_angular_class(classifier):
    """Cubes 1e-9 d apart (a contact of a hand-built or stock dump whose
    exact overlap is empty) have no footprint: the contact keeps its angular
    type and is counted."""
    snap = _snapshot(_pairs([CASES["cube face on cube face"], CASES["cube edge on cube face"]], 1e-3))
    snap.positions[1::2, 2] += (1e-3 + 1e-9) * D_CUBE
    snap.footprint = None
    res = classifier.classify(snap)
    assert res.labels.tolist() == ["FF", "EF"] and res.columns["ct_fp_missing"] == 2


@pytest.mark.slow
def test_cli_footprint_recomputes_without_one(tmp_path, capsys, monkeypatch):
    """postproc analyze --types footprint on a dump with and without contacts/footprint (a
    kernel run, a stock or version-1 dump): the same contact-type columns,
    footprint.png, the stability columns at t/2 and 2t; --types angular; bad
    options get one line and exit code 2."""
    import pandas as pd

    from saved_figures import check_footprint_figure, is_png, record

    from builders import snapshot_dicts, write_snapshot
    from postproc.cli import main
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
        assert main(["analyze", path, "--out", str(tmp_path / name), "--types", "footprint"]) == 0
        out[name] = pd.read_csv(tmp_path / name / "summary.csv")
        assert is_png(tmp_path / name / "footprint.png")      # the L1/d, L2/d figure stays
        pool = steady_indices(out[name]["eps_q"], out[name]["stage"])
        figs = saved.named("footprint.png")
        assert len(figs) == len(out)                                      # one per run: this run's last
        fig = figs[-1]
        check_footprint_figure(fig, np.tile(rel, (len(pool), 1)), T)
        assert fig.axes[0].get_title().startswith(f"{name}.h5: snapshots ")
    k, s = out["kernel"], out["stock"]
    assert (k["ct_fp_recomputed"] == 0).all() and (s["ct_fp_recomputed"] == 1).all()
    assert (k["ct_method"] == "footprint").all() and (k["ct_threshold"] == T).all()
    cols = [c for c in k.columns if c.startswith("ct_frac_")]
    assert len(cols) == 3 * 9
    np.testing.assert_allclose(k[cols].to_numpy(float), s[cols].to_numpy(float), atol=1e-12)
    n = len(CASES)
    assert k["ct_frac_triple"].iloc[-1] == pytest.approx(2 / n) and k["ct_frac_double"].iloc[-1] == pytest.approx(2 / n)
    assert main(["analyze", str(tmp_path / "kernel.h5"), "--out", str(tmp_path / "a"), "--types", "angular"]) == 0
    assert (pd.read_csv(tmp_path / "a" / "summary.csv")["ct_method"] == "angular").all()
    capsys.readouterr()
    assert main(["analyze", str(tmp_path / "kernel.h5"), "--out", str(tmp_path / "b"), "--threshold", "2"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--threshold must be in (0, 1)" in err[0]
    assert not (tmp_path / "b").exists()
