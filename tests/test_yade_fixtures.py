"""Files written by the real YADE (tests/data/yade, made by make_fixtures.py
there with Debian's yade 2023.02a): a periodic packing of 150 frictional
spheres, isotropic at 10 kPa then sheared in xz (a tilted cell), dumped
through the project's own path (yade.h5) and as a flat table written by hand
from O.interactions (table-K.csv), beside YADE's own utils.getStress() and
utils.fabricTensor(). No YADE is needed to run these tests.

Both files hold the values exactly (HDF5 float64; repr() in the tables), so
the only differences are the round-off of two sums taken in other orders:
at most a few ulps per term, bounded here by 1e-13 of the sum of the
terms' magnitudes.

Conventions found: YADE's getStress is tension positive with the same index
order as ours, sigma_YADE[i, j] = -sum f_i l_j / V (force on id2 by id1,
l = x2 - x1 through the periodic image); fabricTensor is <n (x) n> over the
contacts with n the ScGeom normal, which YADE computes before the step moves
the particles: it lags the branch direction at the dump time by one step.
"""
import json
import os

import numpy as np
import pytest

from postproc.contactset import resolve
from postproc.schema import DumpReader
from postproc.stress import contact_stress
from postproc.tables import read_contact_table

DATA = os.path.join(os.path.dirname(__file__), "data", "yade")
REF = json.load(open(os.path.join(DATA, "reference.json")))["snapshots"]


def bound(cs):
    """(3, 3) Pa: round-off allowance of the stress sum (module docstring)."""
    terms = np.abs(cs.force)[:, :, None] * np.abs(cs.arm)[:, None, :]
    return 1e-13 * terms.sum(0) / cs.volume


def fabric(n):
    """<n (x) n> over the rows of n (C, 3)."""
    return n.T @ n / len(n)


def check_against_yade(cs, ref, lag):
    """Stress to round-off; fabric from the branch vectors within ``lag``:
    YADE's fabricTensor averages the ScGeom normals, computed before the
    step moved the particles, and the branch directions at the dump time
    differ from them by at most ``lag`` (each entry of n (x) n then by at
    most 2 lag)."""
    sigma = contact_stress(cs.force, cs.arm, cs.volume)
    yade = -np.array(ref["getStress"])
    assert np.all(np.abs(sigma - yade) <= bound(cs)), (ref["step"], np.abs(sigma - yade).max())
    F = fabric(cs.arm / np.linalg.norm(cs.arm, axis=1)[:, None])
    assert np.abs(F - np.array(ref["fabricTensor"])).max() <= 2 * lag
    assert cs.pp.sum() == ref["n_contacts"]
    return sigma


def dump_snapshots():
    with DumpReader(os.path.join(DATA, "yade.h5")) as r:
        return list(r)


def normal_lag(snap):
    """max |n - l/|l||: YADE's normals against the dump's branch directions."""
    cs = resolve(snap)
    return float(np.abs(snap.normal - cs.arm / np.linalg.norm(cs.arm, axis=1)[:, None]).max())


def test_the_project_dump_gives_yades_stress_and_fabric():
    snaps = dump_snapshots()
    assert len(snaps) == len(REF) == 3
    for snap, ref in zip(snaps, REF):
        assert snap.step == ref["step"]
        np.testing.assert_array_equal(snap.cell, np.array(ref["hSize"]))
        assert snap.volume == pytest.approx(ref["cell_volume"], rel=1e-14)
        # the dump keeps YADE's own normals: their average is fabricTensor to round-off
        np.testing.assert_allclose(fabric(snap.normal), np.array(ref["fabricTensor"]), rtol=0, atol=1e-15)
        lag = normal_lag(snap)
        sigma = check_against_yade(resolve(snap), ref, lag)
    # the sheared states: tilted cells and a stress that is far from symmetric
    # and from diagonal, so that every index is checked
    assert REF[2]["hSize"][0][2] > 0
    assert abs(sigma[0, 2]) > 0.3 * sigma[0, 0] and abs(sigma[0, 1] - sigma[1, 0]) > 1.0


def test_a_users_flat_table_gives_the_same_numbers():
    for ref, snap in zip(REF, dump_snapshots()):
        snaps = read_contact_table(os.path.join(DATA, ref["table"]), volume=ref["cell_volume"])
        assert len(snaps) == 1
        check_against_yade(resolve(snaps[0]), ref, normal_lag(snap))


def test_without_branch_vectors_the_isotropic_table_needs_its_cell(tmp_path):
    """The isotropic cell is orthorhombic: the same table without lx,ly,lz
    gives the same numbers through --cell (minimum images), and without the
    cell its branch vectors across the boundary are wrong."""
    import pandas as pd

    ref = REF[0]
    df = pd.read_csv(os.path.join(DATA, ref["table"])).drop(columns=["lx", "ly", "lz"])
    p = tmp_path / "nobranch.csv"
    df.to_csv(p, index=False, float_format="%.17g")
    L = np.diag(np.array(ref["hSize"]))
    check_against_yade(resolve(read_contact_table(str(p), cell=L)[0]), ref, normal_lag(dump_snapshots()[0]))
    cs = resolve(read_contact_table(str(p), volume=ref["cell_volume"])[0])
    sigma = contact_stress(cs.force, cs.arm, cs.volume)
    assert np.abs(sigma + np.array(ref["getStress"])).max() > 100 * bound(cs).max()
