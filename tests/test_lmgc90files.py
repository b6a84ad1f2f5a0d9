"""LMGC90's own output files read into a dump (postproc.lmgc90files).

The files come from a real tiny LMGC90 run made here with pylmgc90
(tests/lmgc90_tiny_run.py: eight POLYR grains settling on the floor of a box
of six PLANx walls); the converted dump is checked against what chipy itself
says at the end of the run: every body's reaction, the stress from those
reactions and the grains' vertices. The refusals are made on damaged copies
of those files; the geometry helpers are tested on hand-built shapes.
"""
import json
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

from postproc.cdpoints import cd_type_columns
from postproc.contactset import resolve
from postproc.lmgc90files import (LmgcFileError, canonical_frame, convert, labelled, mesh_mass_properties,
                                  quaternion_of, read_vloc_rloc)
from postproc.schema import WALL_ORDER, DumpReader, verify_dump
from postproc.stress import contact_stress
from shapes.overlap import rotation_matrices

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEXT = 1e-6      # relative precision of LMGC90's D14.7 text fields (7 significant digits, with margin)


def _tiny_run(tmp_path_factory, *flags):
    """(run folder, converted dump, chipy's end-of-run record)."""
    from lmgc90.build import LMGC90BuildError, pylmgc90_path

    try:
        pylmgc90_path()
    except LMGC90BuildError as exc:
        pytest.skip(f"LMGC90 is not built ({exc})")
    folder = tmp_path_factory.mktemp("lmgc90run")
    subprocess.run([sys.executable, os.path.join(ROOT, "tests", "lmgc90_tiny_run.py"), *flags], cwd=folder,
                   check=True, capture_output=True, timeout=600)
    out = str(folder / "run.h5")
    assert convert(str(folder), out) == 5                 # steps 400, 500, ... 800
    with open(folder / "reactions.json") as fh:
        return folder, out, json.load(fh)


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """The eight POLYR grains."""
    return _tiny_run(tmp_path_factory)


@pytest.fixture(scope="module")
def sphere_run(tmp_path_factory):
    """Eight SPHER grains (SPSPx and SPPLx interactions)."""
    return _tiny_run(tmp_path_factory, "--spheres")


def _resultants(snap, n_bodies):
    """(B, 3) N: each body's resultant of the dump's point forces (rows by
    RBDY3 number - 1)."""
    out = np.zeros((n_bodies, 3))
    f = snap.points["force_normal"] + snap.points["force_tangential"]
    row = snap.points["contact"]
    np.add.at(out, snap.id2[row] - 1, f)
    np.add.at(out, snap.id1[row] - 1, -f)
    return out


def _last(out):
    with DumpReader(out) as r:
        return r.read(len(r) - 1), r.shapes()


def test_the_dump_verifies_and_holds_every_interaction(run):
    folder, out, _ = run
    check = verify_dump(out)
    assert check.n_snapshots == 5 and check.checksums and check.complete
    snap, _ = _last(out)
    vl = read_vloc_rloc(os.path.join(folder, "OUTBOX", "Vloc_Rloc.OUT.5"))
    assert snap.step == vl["step"] == 800
    assert len(snap.points["contact"]) == len(vl["cd"]) > len(snap.id1) > 0
    # the pairs' forces are their points' sums
    f = snap.points["force_normal"] + snap.points["force_tangential"]
    total = np.zeros((len(snap.id1), 3))
    np.add.at(total, snap.points["contact"], f)
    np.testing.assert_allclose(snap.force, total, rtol=0, atol=1e-14 * np.abs(f).max())
    # walls: bodies 9..14 as written (floor 9 = z-, lid 10 = z+, then x-, x+, y-, y+)
    assert snap.wall_ids.tolist() == [11, 12, 13, 14, 9, 10]
    np.testing.assert_allclose(snap.box_lo, [0, 0, 0], atol=1e-12)
    np.testing.assert_allclose(snap.box_hi, [0.03, 0.03, 0.03], rtol=1e-12)


def test_forces_on_every_body_are_lmgc90_s_reactions(run):
    """Each body's resultant of the dump's point forces (on id2, minus on
    id1) against chipy's RBDY3 'Reac_' (a force: LMGC90 stores the impulse
    over H), grains and walls, at the last step."""
    _, out, rec = run
    snap, _ = _last(out)
    reac = np.array(rec["reac"])[:, :3]
    mine = _resultants(snap, len(reac))
    assert np.abs(reac).max() > 1e-3                       # the grains' weights, about 5e-3 N
    np.testing.assert_allclose(mine, reac, rtol=0, atol=TEXT * np.abs(reac).max())
    # walls/force is the force on each wall
    walls = snap.wall_ids - 1
    np.testing.assert_allclose(snap.wall_forces, reac[walls], rtol=0, atol=TEXT * np.abs(reac).max())


def test_the_stress_is_the_one_from_lmgc90_s_reactions(run):
    """postproc's stress (seed eq. 2, internal-moment form over the pairs and
    wall contacts of the dump) against the same sum made from chipy's body
    reactions R_i and centres x_i: sigma_aa V = sum_grains R_ia x_ia +
    sum_walls R_wa X_wa, X_w the wall's contact face. They differ by the
    wall points' distance to the face (their gaps) times their forces, and
    by the text's 7 digits."""
    _, out, rec = run
    snap, _ = _last(out)
    cs = resolve(snap)
    sigma = contact_stress(cs.force, cs.arm, cs.volume)
    reac, coor = np.array(rec["reac"])[:, :3], np.array(rec["coor"])[:, :3]
    grains = snap.body_ids - 1
    M = np.einsum("ia,ib->ab", reac[grains], coor[grains])
    faces = np.empty(6)
    faces[0::2], faces[1::2] = snap.box_lo, snap.box_hi
    for slot, wid in enumerate(snap.wall_ids):
        a = slot // 2
        M[a, a] += reac[wid - 1, a] * faces[slot]
    on_wall = np.isin(snap.id1[snap.points["contact"]], snap.wall_ids)
    fmag = np.linalg.norm(snap.points["force_normal"] + snap.points["force_tangential"], axis=1)
    bound = (np.sum(fmag[on_wall] * np.abs(snap.points["gap"][on_wall]))
             + TEXT * np.sum(np.abs(reac[grains]) * np.abs(coor[grains]))) / snap.volume
    assert sigma[2, 2] > 1.0 and bound < 1e-3 * sigma[2, 2]
    np.testing.assert_allclose(np.diag(sigma), np.diag(M) / snap.volume, rtol=0, atol=bound)


def test_the_grains_vertices_are_lmgc90_s(run):
    """Global vertices from the dump (position + R(q) v, the project's
    shapes and poses) against chipy's POLYR_GetVertex (current centre, frame
    of the last detection: they differ by the rotation over one step)."""
    _, out, rec = run
    snap, (verts, tris, _) = _last(out)
    R = rotation_matrices(snap.orientations)
    omega = np.linalg.norm(np.array(rec["vlocy"])[:, 3:], axis=1)
    for k, body in enumerate(snap.body_ids):
        mine = snap.positions[k] + verts[snap.shape_index[k]] @ R[k].T
        theirs = np.array(rec["vertices"][k])
        d = snap.sizes[k]
        tol = (omega[body - 1] * rec["dt"] + 10 * TEXT) * d
        assert np.abs(np.sort(mine, axis=0) - np.sort(theirs, axis=0)).max() < tol, body
        # the project's frame: centre of mass at the origin, inertia diagonal
        vol, c, inertia = mesh_mass_properties(verts[snap.shape_index[k]], tris[snap.shape_index[k]])
        assert np.linalg.norm(c) < 10 * TEXT * d and vol == pytest.approx(snap.volumes[k], rel=1e-12)
        assert np.abs(inertia - np.diag(np.diag(inertia))).max() < 10 * TEXT * np.trace(inertia)


def test_a_sphere_run_converts_with_lmgc90_s_reactions(sphere_run):
    folder, out, rec = sphere_run
    assert verify_dump(out).checksums
    snap, shapes = _last(out)
    assert shapes is None and set(snap.body_kind.tolist()) == {0}
    vl = read_vloc_rloc(os.path.join(folder, "OUTBOX", "Vloc_Rloc.OUT.5"))
    assert set(vl["kind"].tolist()) == {"SPSPx", "SPPLx"}
    reac = np.array(rec["reac"])[:, :3]
    assert np.abs(reac).max() > 1e-3
    np.testing.assert_allclose(_resultants(snap, len(reac)), reac, rtol=0, atol=TEXT * np.abs(reac).max())
    np.testing.assert_allclose(snap.positions, np.array(rec["coor"])[snap.body_ids - 1, :3], rtol=0,
                               atol=TEXT * 0.03)
    np.testing.assert_allclose(snap.sizes, 2 * 0.005 * (0.9 + 0.02 * np.arange(8)), rtol=TEXT)


def test_postproc_analyses_the_dump_and_reads_the_cd_types(run, tmp_path):
    from postproc.cli import main

    _, out, _ = run
    assert main(["analyze", out, "--out", str(tmp_path / "an"), "--no-figures"]) == 0
    assert (tmp_path / "an" / "summary.csv").exists()
    snap, _ = _last(out)
    row = cd_type_columns(snap)
    assert row["cd_points"] == len(snap.points["contact"])
    fr = [row[f"cd_force_frac_{g}"] for g in ("simple", "double", "triple")]
    assert sum(fr) == pytest.approx(1.0, abs=1e-12) and row["cd_pairs"] > 0


def test_postproc_import_lmgc90_converts_a_run_and_refuses_a_bad_one_in_one_line(run, tmp_path, capsys):
    from postproc.cli import main

    folder, out, _ = run
    mine = tmp_path / "mine.h5"
    assert main(["import-lmgc90", str(folder), str(mine)]) == 0
    said = capsys.readouterr().out
    with DumpReader(out) as a, DumpReader(str(mine)) as b:
        assert len(a) == len(b) and f"{len(b)} snapshots" in said
        last_a, last_b = a.read(len(a) - 1), b.read(len(b) - 1)
        assert np.array_equal(last_a.force, last_b.force) and np.array_equal(last_a.points["gap"], last_b.points["gap"])
    broken = _copy(run, tmp_path)
    os.remove(broken / "DATBOX" / "BODIES.DAT")
    assert main(["import-lmgc90", str(broken), str(tmp_path / "no.h5")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("postproc: error:") and "BODIES.DAT" in err and "\n" not in err
    assert not (tmp_path / "no.h5").exists()


# -------------------------------------------------------------- refusals
def _copy(run, tmp_path):
    folder = tmp_path / "copy"
    shutil.copytree(run[0], folder, ignore=shutil.ignore_patterns("*.h5", "*.parts", "DISPLAY", "POSTPRO"))
    return folder


def _refused(folder, tmp_path, match):
    with pytest.raises(LmgcFileError, match=match) as info:
        convert(str(folder), str(tmp_path / f"out{len(os.listdir(tmp_path))}.h5"))
    assert "\n" not in str(info.value)
    return str(info.value)


def test_truncated_and_malformed_files_are_refused_in_one_line(run, tmp_path):
    folder = _copy(run, tmp_path)
    vpath = folder / "OUTBOX" / "Vloc_Rloc.OUT.3"
    lines = vpath.read_text().split("\n")
    start = max(k for k, s in enumerate(lines) if s.startswith("$icdan"))
    vpath.write_text("\n".join(lines[:start + 7]) + "\n")           # cut inside the last interaction
    msg = _refused(folder, tmp_path, r"Vloc_Rloc\.OUT\.3:\d+: interaction \d+ \(PR(PL|PR)x, from line \d+\) ends before its")
    assert "truncated" in msg
    vpath.write_text("\n".join(lines[:start + 3] + [lines[start + 3].replace("D", "Q", 1)] + lines[start + 4:]))
    _refused(folder, tmp_path, rf"Vloc_Rloc\.OUT\.3:{start + 4}: interaction \d+: expected rlt/H, rln/H, rls/H")
    vpath.write_text("\n".join(lines))
    dpath = folder / "OUTBOX" / "DOF.OUT.2"
    dl = dpath.read_text().split("\n")
    end = max(k for k, s in enumerate(dl) if s.startswith("$$$$$$"))
    dpath.write_text("\n".join(dl[:end - 2]) + "\n")
    _refused(folder, tmp_path, r"DOF\.OUT\.2:\d+: the body starting here has no closing")
    dpath.write_text("\n".join(dl[:end + 1]) + "\n")
    _refused(folder, tmp_path, r"DOF\.OUT\.2:\d+: no closing '!-----' line after the last body \(truncated\?\)")
    dpath.write_text("\n".join(dl))
    bpath = folder / "DATBOX" / "BODIES.DAT"
    bl = bpath.read_text().split("\n")
    k = next(j for j, s in enumerate(bl) if "ver1=" in s)
    bpath.write_text("\n".join(bl[:k] + [bl[k].replace("ver1=      4", "ver1=     99")] + bl[k + 1:]))
    _refused(folder, tmp_path, rf"BODIES\.DAT:{k + 1}: face vertex \[99, .*\] outside 1\.\.8")
    bpath.write_text("\n".join(bl))
    assert convert(str(folder), str(tmp_path / "whole.h5")) == 5         # the restored copy converts


def test_a_box_that_is_not_six_axis_aligned_walls_is_refused(run, tmp_path):
    folder = _copy(run, tmp_path)
    bpath = folder / "DATBOX" / "BODIES.DAT"
    text = bpath.read_text()
    last = text.rindex("$bdyty")
    bpath.write_text(text[:last])                                      # the y+ wall gone
    _refused(folder, tmp_path, r"DOF\.OUT\.1: body 14 is not in BODIES\.DAT")
    dofs = {p: p.read_text() for p in (folder / "OUTBOX").glob("DOF.OUT.*")}
    for p, t in dofs.items():                                          # ... from the DOF files too
        i = t.index("$bdyty\n RBDY3       14")
        p.write_text(t[:i] + t[t.index("$$$$$$", i) + 7:])
    _refused(folder, tmp_path, r"DOF\.OUT\.1: 5 PLANx bodies; a box of six PLANx walls is read")
    bpath.write_text(text)
    for p, t in dofs.items():
        p.write_text(t)
    dpath = folder / "OUTBOX" / "DOF.OUT.1"
    dl = dpath.read_text().split("\n")
    k = max(j for j, s in enumerate(dl) if "g(1)=" in s)                 # tilt the last wall's frame
    c, s = np.cos(0.01), np.sin(0.01)
    frame = [f"a(1)={1.0: .7E}  a(2)={0.0: .7E}  a(3)={0.0: .7E}", f"b(1)={0.0: .7E}  b(2)={c: .7E}  b(3)={s: .7E}",
             f"g(1)={0.0: .7E}  g(2)={-s: .7E}  g(3)={c: .7E}"]
    dl[k - 2:k + 1] = [" " * 29 + x for x in frame]
    dpath.write_text("\n".join(dl))
    _refused(folder, tmp_path, r"DOF\.OUT\.1: PLANx body 14 has normal .* not along x, y or z")


# -------------------------------------------------------------- helpers, no LMGC90
def test_labelled_reads_fortran_and_pre_numbers():
    d = labelled("  rlt/H-0.1500000D+01  rln/H 0.2500000-100  coo1= 7.5000000E-03")
    assert d == {"rlt/H": -1.5, "rln/H": 2.5e-101, "coo1": 7.5e-3}


def test_canonical_frame_moves_an_offset_turned_box_to_its_principal_frame():
    """A 1 x 2 x 3 box whose vertices are given shifted by c and turned by
    Q: the canonical shape is the box centred on its axes (up to the order
    and signs of the axes), and x + F centroid, F rotation give back the
    same global vertices."""
    rng = np.random.default_rng(3)
    half = np.array([0.5, 1.0, 1.5])
    box = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * half
    tri = np.array([[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                    [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]])
    Q = np.linalg.qr(rng.normal(size=(3, 3)))[0]
    Q *= np.sign(np.linalg.det(Q))
    c0 = np.array([0.3, -0.2, 0.7])
    given = box @ Q.T + c0
    v, c, R, vol = canonical_frame(given, tri)
    assert vol == pytest.approx(6.0, rel=1e-12)
    np.testing.assert_allclose(c, c0, atol=1e-12)
    np.testing.assert_allclose(np.sort(np.abs(v).max(axis=0)), [0.5, 1.0, 1.5], atol=1e-12)
    _, c1, inertia = mesh_mass_properties(v, tri)
    np.testing.assert_allclose(c1, 0, atol=1e-12)
    assert np.abs(inertia - np.diag(np.diag(inertia))).max() < 1e-12
    q = rng.normal(size=4)
    F, x = rotation_matrices((q / np.linalg.norm(q))[None])[0], np.array([1.0, 2.0, 3.0])   # a body at x, turned F
    np.testing.assert_allclose((x + F @ c) + v @ (F @ R).T, x + given @ F.T, atol=1e-12)
    np.testing.assert_allclose(rotation_matrices(quaternion_of(F @ R)[None])[0], F @ R, atol=1e-12)
    assert np.linalg.det(R) == pytest.approx(1.0)
    # a shape already in its frame is kept as it is
    v2, c2, R2, _ = canonical_frame(box, tri)
    assert np.array_equal(v2, box) and not c2.any() and np.array_equal(R2, np.eye(3))


def test_quaternion_of_inverts_rotation_matrices():
    rng = np.random.default_rng(5)
    q = rng.normal(size=(50, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    q[q[:, 0] < 0] *= -1
    np.testing.assert_allclose(quaternion_of(rotation_matrices(q)), q, atol=1e-12)
    assert WALL_ORDER[4] == "z-"
