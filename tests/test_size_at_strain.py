"""postproc.study.sizestrain (``postproc size-at-strain``): per-seed bin
means and the seeds' mean and standard deviation, checked on hand-made
summaries with exact values, through the command line."""
import os

import numpy as np
import pandas as pd
import pytest

from postproc.cli import main
from postproc.study.sizestrain import QUANTITIES


def write(folder, n, values, eps=(0.0, 0.05, 0.06, 0.09, 0.2)):
    """A summary.csv: an isotropic snapshot, then shear snapshots at eps with q/p = values."""
    os.makedirs(folder)
    d = pd.DataFrame({"stage": ["isotropic"] + ["shear"] * (len(eps) - 1), "eps_1": eps, "n_particles": n})
    for q in QUANTITIES:
        d[q] = 0.0
    d["q_over_p"] = values
    d.to_csv(os.path.join(folder, "summary.csv"), index=False)


@pytest.fixture
def sizes(tmp_path):
    """Three study-like folders: a (1000 grains, 2 seeds and an LMGC90-count
    twin), b (5000, 1 seed), c (8000, 2 seeds)."""
    write(tmp_path / "a" / "analysis-polyhedra-seed1", 1000, [9.0, 0.30, 0.40, 0.50, 9.0])
    write(tmp_path / "a" / "analysis-polyhedra-seed2", 1000, [9.0, 0.32, 0.42, 0.70, 9.0])
    write(tmp_path / "a" / "analysis-polyhedra-seed1-lmgc90", 1000, [9.0] * 5)      # another count: left out
    write(tmp_path / "b" / "polyhedra-seed1", 5000, [9.0, 0.20, 0.20, 0.60, 9.0])
    write(tmp_path / "c" / "polyhedra-seed1", 8000, [9.0, 0.10, 0.10, 0.60, 9.0])
    write(tmp_path / "c" / "polyhedra-seed2", 8000, [9.0, 0.14, 0.14, 0.64, 9.0])
    return tmp_path


def test_bins_seeds_and_tables(sizes):
    tmp_path = sizes
    out = tmp_path / "out"
    assert main(["investigate", "size-at-strain", str(tmp_path / "a"), str(tmp_path / "b"), "--bins", "0.04", "0.075", "0.1",
                     "--out", str(out)]) == 0
    per = pd.read_csv(out / "size-at-strain.csv")
    assert len(per) == 6 and set(per["N"]) == {1000, 5000}
    assert "5000 − 1000" not in (out / "size-at-strain.md").read_text()       # one seed at 5000: no interval
    first = per[(per["N"] == 1000) & (per["bin"] == "0.04-0.075")]["q_over_p"].to_numpy()
    assert np.allclose(sorted(first), [0.35, 0.37], rtol=0, atol=1e-12)     # (0.30 + 0.40) / 2, (0.32 + 0.42) / 2
    md = (out / "size-at-strain.md").read_text()
    assert f"| 1000 | 0.360 ± {np.std([0.35, 0.37], ddof=1):.3f} (2) | 0.600 ± 0.141 (2) |" in md
    assert "| 5000 | 0.200 (1) | 0.600 (1) |" in md


def test_bad_input_is_one_line(tmp_path, capsys):
    assert main(["investigate", "size-at-strain", str(tmp_path), "--out", str(tmp_path / "o")]) == 2
    assert "no polyhedra-seed<K>/summary.csv under it" in capsys.readouterr().err
    (tmp_path / "x" / "polyhedra-seed1").mkdir(parents=True)
    (tmp_path / "x" / "polyhedra-seed1" / "summary.csv").write_text("step,eps_1\n1,0.1\n")
    assert main(["investigate", "size-at-strain", str(tmp_path / "x"), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "not a postproc analyze summary" in err
    assert main(["investigate", "size-at-strain", str(tmp_path / "x"), "--bins", "0.1", "0.05"]) == 2


def test_difference_is_welch_over_the_seeds(sizes):
    """1000 (seeds 0.35, 0.37) against 8000 (0.10, 0.14) in the first bin:
    the difference and its 95 % interval, Welch's, computed here with scipy."""
    from scipy import stats

    tmp_path = sizes
    out = tmp_path / "out"
    assert main(["investigate", "size-at-strain", str(tmp_path / "a"), str(tmp_path / "c"), "--bins", "0.04", "0.075", "0.1",
                     "--out", str(out)]) == 0
    x, y = np.array([0.10, 0.14]), np.array([0.35, 0.37])       # each seed's mean over the bin
    v1, v2 = x.var(ddof=1) / 2, y.var(ddof=1) / 2
    dof = (v1 + v2) ** 2 / (v1 ** 2 + v2 ** 2)
    half = stats.t.ppf(0.975, dof) * np.sqrt(v1 + v2)
    d = x.mean() - y.mean()
    row = next(line for line in (out / "size-at-strain.md").read_text().splitlines() if line.startswith("| 8000 − 1000"))
    assert row.split(" | ")[1] == f"{d:.3f} [{d - half:.3f}, {d + half:.3f}]"
