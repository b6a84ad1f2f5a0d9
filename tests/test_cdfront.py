"""postproc.study.cdfront: the CD front's table from run folders, on
hand-built folders with exact means, and the table of docs/front.md held to
the archived runs of reference_data/cd-front."""
import json
import os
import re

import numpy as np
import pandas as pd
import pytest

from postproc.cli import main
from postproc.errors import InputError
from postproc.study import cdfront

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ARCHIVE = os.path.join(ROOT, "reference_data", "cd-front")


def make_run(folder, tol, qp, iterations, converged):
    os.makedirs(os.path.join(folder, "analysis"))
    with open(os.path.join(folder, "run.params.json"), "w") as fh:
        json.dump({"dt": 1e-3, "nlgs_tol": tol, "nlgs_relax": 1.0, "start": "yade"}, fh)
    with open(os.path.join(folder, "run.info.json"), "w") as fh:
        json.dump({"steps": len(iterations) + 1, "wall_seconds": 10.0, "solid_fraction_isotropic": 0.54}, fh)
    pd.DataFrame({"step": np.arange(len(iterations) + 1), "stage": ["isotropic"] + ["shear"] * len(iterations),
                  "nlgs_iterations": [99] + list(iterations), "converged": [1] + list(converged)}
                 ).to_csv(os.path.join(folder, "run.log.csv"), index=False)
    eps = [0.0, 0.05, 0.1, 0.2, 0.3, 0.35]
    pd.DataFrame({"stage": ["isotropic"] + ["shear"] * 5, "eps_1": eps, "q_over_p": qp,
                  "cd_force_frac_simple": [0.5] * 6}).to_csv(os.path.join(folder, "analysis", "summary.csv"),
                                                             index=False)


def test_the_front_s_means_and_differences_are_exact(tmp_path):
    a, b = str(tmp_path / "a"), str(tmp_path / "b")
    make_run(a, 1e-3, [0.0, 9.0, 0.4, 0.5, 0.6, 9.0], [10, 20, 30, 40], [1, 1, 0, 0])
    make_run(b, 1e-2, [0.0, 9.0, 0.3, 0.3, 0.3, 9.0], [2, 2, 2, 2], [1, 1, 1, 1])
    assert main(["investigate", "cd-front", a, b, "--out", str(tmp_path / "out")]) == 0
    df = pd.read_csv(tmp_path / "out" / "cd-front.csv")
    assert df["q_over_p"].tolist() == pytest.approx([0.5, 0.3], abs=1e-15)   # eps_1 0.1-0.3 only
    assert df["d_q_over_p"].tolist() == pytest.approx([0.0, -0.2], abs=1e-15)
    assert df["iterations"].tolist() == [25.0, 2.0] and df["at_cap"].tolist() == [0.5, 0.0]
    assert df["snapshots"].tolist() == [3, 3] and np.isnan(df["a_t"]).all()    # a column the runs lack
    assert "| a | 0.001 | 0.001 | yade | 25 | 50.0 % | 0.500 |" in (tmp_path / "out" / "cd-front.md").read_text()


def test_a_broken_run_folder_is_refused_in_one_line(tmp_path, capsys):
    a = str(tmp_path / "a")
    make_run(a, 1e-3, [0.0] * 6, [1], [1])
    os.remove(os.path.join(a, "run.log.csv"))
    with pytest.raises(InputError, match="run.log.csv"):
        cdfront.read_run(a)
    assert main(["investigate", "cd-front", a, "--out", str(tmp_path / "out")]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1


def test_docs_front_table_is_the_archived_runs():
    """Every number of the CD front's table in docs/front.md is what the
    command gives on reference_data/cd-front, at the table's digits."""
    order = ["polyhedra-seed1-tol1e-3", "polyhedra-seed1-tol3e-3", "polyhedra-seed1-tol1e-2",
             "polyhedra-seed1-tol1e-2-dt0.0005", "polyhedra-seed1-tol1e-2-dt0.002", "loose-polyhedra-seed1-tol1e-2"]
    rows = [cdfront.front_row(n, *cdfront.read_run(os.path.join(ARCHIVE, n))) for n in order]
    text = open(os.path.join(ROOT, "docs", "front.md"), encoding="utf-8").read()
    section = text[text.index("## The CD time step and tolerance"):text.index("### At 1000 grains")]
    lines = [ln for ln in section.splitlines() if re.match(r"\| \d", ln)]
    assert len(lines) == len(rows)
    for line, r in zip(lines, rows):
        cells = [c.strip().replace("−", "-") for c in line.strip("|").split("|")]
        assert float(cells[0]) == r["dt"] and float(cells[1]) == r["nlgs_tol"]
        assert int(cells[3]) == round(r["iterations"])
        for k, q in zip(range(5, 10), ("q_over_p", "a", "a_l", "a_n", "a_t")):
            assert cells[k] == f"{r[q]:.3f}", (q, cells[k], r[q])
        assert cells[11] == " / ".join(f"{r[f'cd_alert_frac_{g}']:.2f}" for g in ("simple", "double", "triple"))
        assert cells[12] == " / ".join(f"{r[f'cd_force_frac_{g}']:.2f}" for g in ("simple", "double", "triple"))


def test_docs_branch_check_is_the_archived_branches():
    """The convergence check quoted in docs/front.md (seed 1 branched at
    eps_1 0.144 into tolerances 1e-3 and 3e-4): its means over the snapshots
    after the branch are the archived runs'."""
    text = open(os.path.join(ROOT, "docs", "front.md"), encoding="utf-8").read()
    got = {}
    for tol in ("1e-3", "3e-4"):
        folder = os.path.join(ARCHIVE, f"branch-polyhedra-seed1-eps0.144-tol{tol}")
        params, _, log, summary = cdfront.read_run(folder)
        after = summary[summary["step"] > params["branch"]["step"]]
        assert len(after) == 3
        got[tol] = (after["cd_force_frac_simple"].mean(), after["cd_force_frac_double"].mean(),
                    after["cd_alert_frac_simple"].mean(), after["q_over_p"].mean(),
                    log[log["step"] > params["branch"]["step"]]["nlgs_iterations"].mean())
    a, b = got["1e-3"], got["3e-4"]
    assert f"force-carrying simple share of {a[0]:.3f} and {b[0]:.3f}" in text
    assert f"double\n  {a[1]:.3f} and {b[1]:.3f}" in text
    assert f"every-point simple share of {a[2]:.3f} and {b[2]:.3f}" in text
    assert f"({a[3]:.3f} and {b[3]:.3f})" in text
    assert f"{b[4]:.0f} iterations a step against {a[4]:.0f}" in text


def test_docs_1000_grain_branch_table_is_the_archived_runs():
    """The 1000-grain table of docs/front.md (seed 1 at tolerance 1e-2 and
    its branch into 1e-3 at eps_1 0.162, means over eps_1 0.165-0.205) is
    what the command gives on reference_data/cd-1000-front, at its digits,
    over the same four snapshots after the branch."""
    folder = os.path.join(ROOT, "reference_data", "cd-1000-front")
    names = ("polyhedra-seed1-tol1e-2", "branch-polyhedra-seed1-eps0.162-tol1e-3")
    runs = [cdfront.read_run(os.path.join(folder, n)) for n in names]
    step = runs[1][0]["branch"]["step"]
    rows = []
    for n, run in zip(names, runs):
        s = run[3]
        window = s[(s["eps_1"] >= 0.165) & (s["eps_1"] <= 0.205)]
        assert len(window) == 4 and (window["step"] > step).all()
        rows.append(cdfront.front_row(n, *run, eps_lo=0.165, eps_hi=0.205))
    text = open(os.path.join(ROOT, "docs", "front.md"), encoding="utf-8").read()
    section = text[text.index("### At 1000 grains the tolerance moves the stress too"):text.index("## Analysis estimators")]
    lines = [ln for ln in section.splitlines() if re.match(r"\| 1e-", ln)]
    assert len(lines) == 2
    for line, r, tol in zip(lines, rows, (0.01, 0.001)):
        cells = [c.strip().replace("−", "-") for c in line.strip("|").split("|")]
        assert float(cells[0]) == r["nlgs_tol"] == tol
        for k, q in zip(range(1, 6), ("q_over_p", "a", "a_l", "a_n", "a_t")):
            assert cells[k] == f"{r[q]:.3f}", (q, cells[k], r[q])
        assert cells[6] == f"{r['z']:.2f}"
        assert cells[7] == " / ".join(f"{r[f'cd_alert_frac_{g}']:.2f}" for g in ("simple", "double", "triple"))
        assert cells[8] == " / ".join(f"{r[f'cd_force_frac_{g}']:.2f}" for g in ("simple", "double", "triple"))
    shifts = [rows[1][q] - rows[0][q] for q in ("q_over_p", "a", "a_n", "a_t")]
    assert "by " + ", ".join(f"{x:.3f}" for x in shifts[:3]) + f" and {shifts[3]:.3f}" in section
