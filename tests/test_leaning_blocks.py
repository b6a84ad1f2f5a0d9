"""postproc.study.leaning (``postproc leaning-blocks``): block leanings and
the scaling fit, checked on hand-built contact sets with exact values."""
import os

import numpy as np
import pandas as pd
import pytest

from postproc.statistics import steady_indices
from postproc.study import leaning as lb
from test_claim6_counts import dump, tiny_study  # noqa: F401  (fixtures: a tiny study)


def contacts():
    """Two snapshots of 80 grains; VF contacts in blocks 0 and 7 of a 2 x 2 x 2
    grid, EE contacts only in block 7 and only in snapshot 1."""
    frac = np.array([[0.1, 0.1, 0.1], [0.2, 0.3, 0.4], [0.9, 0.9, 0.9],     # snapshot 0: VF, VF, VF
                     [0.1, 0.2, 0.3], [0.6, 0.7, 1.0], [1.0, 1.0, 1.0]])    # snapshot 1: VF, VF, EE
    return {"frac": frac, "label": np.array(["VF", "VF", "VF", "VF", "VF", "EE"]),
            "g": np.array([1.0, 0.0, 2.5, -1.25, 0.5, 0.25]), "snap": np.array([0, 0, 0, 1, 1, 1]),
            "n_particles": np.array(80)}


def test_block_values_are_window_means_of_snapshot_means():
    vals, n = lb.block_values(contacts(), 2)
    assert n == 10 and vals.shape == (2, 8)
    vf, ee = vals
    # block 0: snapshot 0 mean (1 + 0) / 2 = 0.5, snapshot 1 -1.25: window mean -0.375
    assert vf[0] == pytest.approx(-0.375)
    # block 7 (fractions >= 0.5 on every axis, 1.0 included): 2.5 then 0.5
    assert vf[7] == pytest.approx(1.5)
    assert np.isnan(vf[1:7]).all() and ee[7] == pytest.approx(0.25) and np.isnan(ee[:7]).all()
    whole, n1 = lb.block_values(contacts(), 1)
    # the whole packing: snapshot means (1 + 0 + 2.5) / 3 and (-1.25 + 0.5) / 2, as the study's leaning
    assert n1 == 80 and whole[0, 0] == pytest.approx((3.5 / 3 - 0.375) / 2) and whole[1, 0] == pytest.approx(0.25)


def test_slope_recovers_an_exact_power_law():
    pts = [(n, 0.9 * n ** -0.5, dof) for n, dof in ((25, 7), (125, 14), (625, 14), (37, 52))]
    b, lo, hi = lb.slope(pts)
    assert b == pytest.approx(-0.5) and lo <= -0.5 <= hi
    assert np.isnan(lb.slope(pts[:2])[0])


def test_the_command_says_what_is_missing_in_one_line(tmp_path, capsys):
    """``postproc leaning-blocks`` on a folder without a study, and with a
    grid list that leaves out the whole packing: exit 2, one line each."""
    from postproc.cli import main

    assert main(["investigate", "leaning-blocks", str(tmp_path), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "no complete S1 run" in err
    assert main(["investigate", "leaning-blocks", str(tmp_path), "--grids", "2", "3"]) == 2
    assert "include 1" in capsys.readouterr().err
    assert not (tmp_path / "o").exists()


def test_the_command_on_a_tiny_study(tiny_study, tmp_path, capsys):
    """``postproc leaning-blocks`` on one 64-grain run: at g = 1 each
    type's leaning is the study's own (the window mean of its summary's
    ct_fabric_*), at g = 2 the blocks' rows are there, the run's contacts
    are cached; a count the study did not analyse leaves no run: exit 2."""
    from postproc.cli import main

    out = tmp_path / "blocks"
    assert main(["investigate", "leaning-blocks", tiny_study, "--types", "points", "--grids", "1", "2", "--min-grains", "1",
                 "--out", str(out)]) == 0
    tab = pd.read_csv(out / "blocks.csv")
    assert sorted(zip(tab["type"], tab["grid"])) == [("EE", 1), ("EE", 2), ("VF", 1), ("VF", 2)]
    own = pd.read_csv(os.path.join(tiny_study, "analysis", "summary.csv"))
    window = steady_indices(own["eps_q"], own["stage"])
    for t in ("VF", "EE"):
        whole = tab[(tab["type"] == t) & (tab["grid"] == 1)].iloc[0]
        assert whole["N"] == 64 and whole["seeds"] == 1
        assert whole["mean"] == pytest.approx(np.nanmean(own[f"ct_fabric_{t}"].to_numpy(float)[window]), abs=1e-9)
    assert len(os.listdir(out / "cache")) == 1
    assert "| points | VF | 64 | 1 | 2 |" in capsys.readouterr().out
    assert main(["investigate", "leaning-blocks", tiny_study, "--types", "lmgc90", "--out", str(out)]) == 2
    assert "no run with the counts asked for" in capsys.readouterr().err
