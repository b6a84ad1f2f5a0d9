"""postproc.study.timestepfront (``postproc timestep-front``): the time
step's cost and paired differences on a hand-made table of runs, checked
against values computed here, and the command on a folder of the plan."""
import json

import numpy as np
import pandas as pd
import pytest
from scipy import stats

from postproc.cli import main
from postproc.study import timestepfront as tf

SAFETIES = (0.3, 0.45, 0.6, 0.9)
SEEDS = (1, 2, 3)


def runs_table():
    """One row per (safety, seed): steps as 1/safety, q/p plateau shifted by
    0.01 per unit of safety plus a seed offset, the other quantities
    equal at every safety."""
    rows = []
    for s in SAFETIES:
        for seed in SEEDS:
            steps = 1e5 * 0.3 / s * (1 + 0.01 * seed)
            row = {"run": f"dt{s:g}-s{seed}", "safety": s, "seed": seed, "steps": steps,
                   "compaction_steps": 0.1 * steps, "shear_steps": 0.9 * steps, "wall_seconds": steps / 1000}
            row.update({q: 0.5 for q in tf.QUANTITIES})
            row["qp_plateau"] = 0.4 + 0.01 * s + [0.0, 0.003, -0.002][seed - 1] + (0.001 * seed * s)
            rows.append(row)
    return pd.DataFrame(rows)


def test_paired_and_cost_tables():
    runs = runs_table()
    cost = tf.cost_table(runs).set_index("safety")
    assert cost.loc[0.45, "steps_ratio"] == pytest.approx(0.3 / 0.45)
    assert cost.loc[0.3, "runs"] == 3 and cost.loc[0.9, "steps"] == pytest.approx(1e5 / 3 * 1.02)
    paired = tf.paired_table(runs).set_index(["safety", "quantity"])
    d = np.array([0.01 * 0.6 + 0.001 * k * 0.6 for k in SEEDS]) - np.array([0.01 * 0.3 + 0.001 * k * 0.3 for k in SEEDS])
    row = paired.loc[(0.6, "qp_plateau")]
    half = stats.t.ppf(0.975, 2) * d.std(ddof=1) / np.sqrt(3)
    assert row["diff"] == pytest.approx(d.mean()) and row["n"] == 3
    assert row["lo"] == pytest.approx(d.mean() - half) and row["hi"] == pytest.approx(d.mean() + half)
    assert paired.loc[(0.6, "a"), "diff"] == 0
    md = tf.markdown(tf.cost_table(runs), tf.paired_table(runs), [("dt0.9-s4", 1)])
    assert "| 0.45 | 3 |" in md and md.rstrip().endswith("Failed runs: dt0.9-s4 (exit 1)")


def test_the_command_on_a_folder_of_the_plan(tmp_path, monkeypatch, capsys):
    """``postproc timestep-front`` keeps the plan's runs only (a run of
    another plan in the folder is left out), writes its three files; a
    folder without a plan: exit 2."""
    runs = pd.concat([runs_table(), runs_table().iloc[:1].assign(run="other", safety=0.2)], ignore_index=True)
    monkeypatch.setattr(tf, "collect_runs", lambda folder: runs)
    plan = {"plan": "timestep", "polyhedra": [[f"dt{s:g}-s{k}", {"safety": s, "seed": k}]
                                              for k in SEEDS for s in SAFETIES]}
    (tmp_path / "front-plan.json").write_text(json.dumps(plan))
    assert main(["investigate", "timestep-front", str(tmp_path)]) == 0
    assert len(pd.read_csv(tmp_path / "timestep-runs.csv")) == 12
    assert set(pd.read_csv(tmp_path / "timestep.csv")["safety"]) == set(SAFETIES)
    assert (tmp_path / "timestep.md").read_text() in capsys.readouterr().out
    assert main(["investigate", "timestep-front", str(tmp_path / "none")]) == 2
    assert "not a readable plan" in capsys.readouterr().err


def test_the_driver_answers_help(capsys):
    """``python -m yade_scripts.campaign.timestep_sweep`` (runs the plan, then this
    table) answers --help without running anything."""
    from yade_scripts.campaign import timestep_sweep as timestep_front

    with pytest.raises(SystemExit) as exc:
        timestep_front.main(["--help"])
    assert exc.value.code == 0 and "usage: python -m yade_scripts.campaign.timestep_sweep" in capsys.readouterr().out
