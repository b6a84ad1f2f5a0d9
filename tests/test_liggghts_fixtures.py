"""Dumps written by the real LIGGGHTS (tests/data/liggghts, made by
make_fixtures.py there with Debian's ``liggghts``, LIGGGHTS-PUBLIC 3.8.0):
our contact stress against LIGGGHTS's own pair virial (``compute pressure
thermo_temp pair``) at the same steps, from the 12-column (pos id force) and
the 15-column (pos id force_normal force_tangential) layouts, in a periodic
box compressed and then sheared; the contacts against an independent count
from the particles; ids above 10^6 written by the default ``%g`` refused
with the dump_modify line LIGGGHTS accepts.

Error bound, from the text and floating-point precision (u = 2^-53, the unit
round-off of a double):

* every dumped value is written with %.17g, which gives back the double
  LIGGGHTS held, and the force columns of ``force`` are the very doubles its
  virial tallies (src/pair_gran_base.h hands ``i_forces.delta_F`` to both
  ``ev_tally_xyz`` and the compute): no error from the text. With
  ``force_normal force_tangential`` the sum fn + ft restores that force to
  |delta f_a| <= 4u (|fn_a| + |ft_a|) (LIGGGHTS's ft = f - fn, our fn + ft:
  two roundings);
* the header's box bounds are printed with %g (6 digits), but the box was
  deformed to bounds of 4 significant digits, so they are LIGGGHTS's box to
  the last bit (checked against the %.20g values in pressure.json);
* branch vectors: LIGGGHTS's x_i - x_j uses the ghost image x_j +- L; ours
  the positions it remapped into the box (x +- L), their difference and its
  minimum image: at most five roundings of numbers no larger than 1.5 L, so
  |delta l_b| <= 8u L_b;
* the sums: LIGGGHTS and we each add n products in some order and divide by
  V (LIGGGHTS multiplies by 1/V): 2 (n + 2) u of the sum of |f_a l_b|.

So |sigma_ab - P_ba| <= [sum_c (|delta f_a| |l_b| + |f_a| 8u L_b) +
2 (n + 2) u sum_c |f_a l_b|] / V (:func:`bound`), about 9e-14 of the
largest entry here. It is a worst case: the measured differences are at
most 1.3e-15 of the largest entry (1.5 % of the bound), the same from both
layouts.
"""
import json
import os
import re

import numpy as np
import pytest

from postproc.errors import InputError
from postproc.lammpsdump import liggghts_exact_format, read_atoms, read_text_dump
from postproc.stress import contact_stress
from builders import pressure_tensor, raw_rows

DATA = os.path.join(os.path.dirname(__file__), "data", "liggghts")
REF = json.load(open(os.path.join(DATA, "pressure.json")))
U = 2.0 ** -53
LAYOUTS = {"contacts.dump": 12, "contacts-nt.dump": 15}


def bound(snap, rows):
    """(3, 3) Pa: the largest error of each sigma entry (module docstring)."""
    f, l = np.abs(snap.force), np.abs(snap.branch)
    if rows.shape[1] == 15:
        df = 4 * U * (np.abs(rows[:, 9:12]) + np.abs(rows[:, 12:15]))
    else:
        df = np.zeros_like(f)
    dl = 8 * U * (snap.box_hi - snap.box_lo)
    terms = f[:, :, None] * l[:, None, :]
    err = (df[:, :, None] * l[:, None, :] + f[:, :, None] * dl[None, None, :]).sum(0)
    n = len(f)
    return (err + 2 * (n + 2) * U * terms.sum(0)) / snap.volume


@pytest.mark.parametrize("name", sorted(LAYOUTS))
def test_stress_equals_liggghts_pair_virial(name):
    path = os.path.join(DATA, name)
    snaps = read_text_dump(path)
    rows = raw_rows(path)
    assert len(snaps) == len(REF["snapshots"]) == 3
    for snap, ref, r in zip(snaps, REF["snapshots"], rows):
        assert not isinstance(snap, Exception), snap
        assert r.shape[1] == LAYOUTS[name]
        assert snap.step == ref["step"]
        assert len(snap.id1) == len(r) == ref["contacts"]                  # every LIGGGHTS row is a contact
        # the %g header holds LIGGGHTS's box (printed with %.20g) to the last bit
        for got, exact in ((snap.box_lo, ref["lo"]), (snap.box_hi, ref["hi"])):
            assert np.all(np.abs(got - exact) <= 2 * U * np.abs(exact))
        assert snap.volume == pytest.approx(ref["volume"], rel=8 * U)
        sigma = contact_stress(snap.force, snap.branch, snap.volume)
        P = pressure_tensor(ref)
        err = bound(snap, r)
        assert np.all(np.diag(P) > 0)                                      # compressed: positive
        # our sigma_ab = sum f_a l_b / V is LIGGGHTS's P_ba: the diagonal
        # and the transpose of its upper triangle
        for a, b in ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)):
            assert abs(sigma[b, a] - P[a, b]) <= err[b, a], (snap.step, a, b, sigma[b, a], P[a, b], err[b, a])


def test_sheared_snapshots_are_anisotropic():
    """The fixtures are not all isotropic: after the shear pzz - pxx is a
    large part of the mean (so the diagonal comparison tells the axes apart)."""
    P = [np.diag(pressure_tensor(s)) for s in REF["snapshots"]]
    assert abs(P[0][2] - P[0][0]) < 0.2 * P[0].mean()
    assert all(p[2] - p[0] > 0.5 * p.mean() for p in P[1:])
    lo = [np.array(s["lo"]) for s in REF["snapshots"]]
    assert lo[0][0] == lo[0][2] and lo[1][0] < lo[1][2] and lo[2][0] < lo[1][0]


def test_off_diagonal_convention_is_the_transpose_of_liggghts():
    """The stress is not symmetric (tangential forces): LIGGGHTS's pxy is
    sum l_x f_y / V, our sigma[1, 0]; comparing it with sigma[0, 1] is off
    by far more than the bound allows."""
    path = os.path.join(DATA, "contacts.dump")
    for snap, ref, r in zip(read_text_dump(path), REF["snapshots"], raw_rows(path)):
        sigma = contact_stress(snap.force, snap.branch, snap.volume)
        P = pressure_tensor(ref)
        err = bound(snap, r)
        wrong = [abs(sigma[a, b] - P[a, b]) / err[a, b] for a, b in ((0, 1), (0, 2), (1, 2))]
        assert max(wrong) > 1e6


def periodic_pairs(ids, pos, radius, lo, hi):
    """{(id, id): 0 or 1} of the touching pairs (distance < r1 + r2 through
    the periodic box), 1 when the shortest path crosses a boundary; and the
    smallest relative gap |d - (r1 + r2)| / (r1 + r2) over all pairs."""
    L = hi - lo
    d = pos[None, :, :] - pos[:, None, :]
    wrapped = d - L * np.round(d / L)
    dist = np.linalg.norm(wrapped, axis=2)
    rsum = radius[:, None] + radius[None, :]
    iu = np.triu_indices(len(ids), 1)
    touch = (dist < rsum)[iu]
    across = np.any(np.abs(wrapped - d) > 0.5 * L, axis=2)[iu]
    pairs = {tuple(sorted((int(ids[i]), int(ids[j])))): int(c)
             for i, j, t, c in zip(*iu, touch, across) if t}
    margin = np.min(np.abs(dist - rsum)[iu] / rsum[iu])
    return pairs, margin


def test_contacts_and_periodic_flags_match_the_particles():
    """The touching pairs found from atoms.dump (id x y z radius, %.17g) are
    the rows of the dump, and LIGGGHTS's periodic flag (third id column) is
    1 exactly for the pairs whose nearest image lies across the box."""
    atoms = read_atoms(os.path.join(DATA, "atoms.dump"))
    radius = [r[:, 4] for r in raw_rows(os.path.join(DATA, "atoms.dump"))]
    path = os.path.join(DATA, "contacts.dump")
    for snap, rows, rad, ref in zip(read_text_dump(path), raw_rows(path), radius, REF["snapshots"]):
        ids, pos = atoms[snap.step]
        pairs, margin = periodic_pairs(ids, pos, rad, snap.box_lo, snap.box_hi)
        assert margin > 1e-9                     # no pair so near contact that rounding could decide it
        dumped = {tuple(sorted((int(a), int(b)))): int(c) for a, b, c in rows[:, 6:9]}
        assert len(dumped) == len(rows) == ref["contacts"]              # each pair once
        assert dumped == pairs
        assert 0 < sum(pairs.values()) < len(pairs)                     # both kinds present
        # ids above 10^6 read exactly: the data file's 2 000 001 + 7 k
        assert np.all((snap.body_ids - REF["first_id"]) % REF["id_step"] == 0)
        assert snap.body_ids.min() >= REF["first_id"] > 10 ** 6


def test_ids_rounded_by_the_default_format_are_refused_with_the_line_liggghts_accepts(tmp_path, capsys):
    path = os.path.join(DATA, "contacts-g.dump")
    snaps = read_text_dump(path)
    assert len(snaps) == 3 and all(isinstance(s, InputError) for s in snaps)
    msg = str(snaps[0])
    assert "\n" not in msg and "id written as '2.00" in msg and "6 significant digits" in msg
    fix = liggghts_exact_format(12)
    assert fix in msg and "format float" not in msg
    # the advice is the line that wrote contacts.dump (LIGGGHTS 3.8 ran it)
    script = open(os.path.join(DATA, "in.fixtures")).read()
    assert re.search(r"^dump_modify d12 append yes format " + re.escape(fix.split(" format ")[1]) + "$",
                     script, re.M)
    from postproc.cli import main

    code = main(["analyze", path, "--out", str(tmp_path / "out"), "--no-figures"])
    assert code != 0
    err = capsys.readouterr().err
    assert "6 significant digits" in err and "Traceback" not in err
