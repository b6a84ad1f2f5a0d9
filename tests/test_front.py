"""The speed/error front: a two-point sweep per sample on the tiny preset
(YADE, yade-batch), and the front's pure parts on known inputs."""
import math
import shutil

import numpy as np
import pandas as pd
import pytest

from postproc.front import add_errors, analysis_front, pareto


def test_pareto_and_errors_on_a_known_table():
    assert pareto([1, 2, 3, 4], [4, 3, 3.5, 1]).tolist() == [True, True, False, True]
    runs = pd.DataFrame({"sample": ["s"] * 3, "run": ["ref", "b", "c"], "kappa": [1e3, 300, 150],
                         "inertial_number": [1e-3, 1e-2, 1e-2], "n_particles": [10, 10, 10],
                         "q_over_p": [0.4, 0.5, 0.3], "a": [0.1, 0.1, 0.2],
                         "a_n": [0.2, 0.25, 0.2], "a_t": [0.1, 0.1, 0.1]})
    out = add_errors(runs)
    assert out["ref"].tolist() == [True, False, False]
    assert out["err_max"].tolist() == pytest.approx([0.0, 0.1, 0.1])
    assert out["err_a_n"].tolist() == pytest.approx([0.0, 0.05, 0.0])
    # without a "ref" line: the stiffest, slowest run
    runs["run"] = ["x", "y", "z"]
    assert add_errors(runs)["ref"].tolist() == [True, False, False]


def test_analysis_front_errors_shrink_as_one_over_sqrt_n():
    t = analysis_front(sizes=(400, 6400), bins=(9,), reps=30, seed=1)
    assert set(t["estimator"]) == {"tensors", "fit-9"}
    for name, g in t.groupby("estimator"):
        g = g.sort_values("n")
        ratio = g["rms_max"].iloc[0] / g["rms_max"].iloc[1]
        # sqrt(16) = 4; the RMS over 30 sets has a relative s.e. of about 1/sqrt(60)
        assert 4 * (1 - 3 / math.sqrt(60)) < ratio < 4 * (1 + 3 / math.sqrt(60)), name
    assert (t["seconds"] > 0).all()


@pytest.mark.skipif(shutil.which("yade-batch") is None, reason="Debian yade is not installed")
def test_two_point_sweep_on_the_tiny_preset(tmp_path, shape_library):
    from yade_scripts.front import main

    out = tmp_path / "front"
    assert main(["--plan", "smoke", "--out", str(out), "--library", shape_library]) == 0
    table = pd.read_csv(out / "front.csv")
    assert (out / "front.png").stat().st_size > 1000
    assert sorted(table["sample"]) == ["polyhedra", "polyhedra", "spheres", "spheres"]
    cols = ["wall_seconds", "steps", "contact_steps", "q_over_p", "a", "a_n", "a_t", "err_max"]
    assert np.isfinite(table[cols].to_numpy(float)).all()
    ref = table[table["ref"]]
    assert len(ref) == 2 and (ref["err_max"] == 0).all()
    assert set(table.loc[table["sample"] == "polyhedra", "library"]) == {"shapes.h5", "shapes-low.h5"}
