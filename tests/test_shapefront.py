"""The shape front (postproc.study.shapefront): two hand-built studies at one
size whose plateaus differ by known amounts, the Welch difference against its
textbook formula, the paper's values and the direction, the libraries'
descriptors, and what its figure draws."""
import json
import os

import numpy as np
import pandas as pd
import pytest
from scipy.stats import t

from postproc.errors import InputError
from postproc.study import shapefront as sh

OFFSETS = (-0.01, 0.0, 0.01)          # per seed: sd 0.01, so every interval is finite


def _study(root, name, values, n=1000, library=None):
    """A study whose runs' steady plateaus are ``values`` + the seed's
    offset (S1 and S2 alike), with S1's points count, and its library."""
    study = root / name
    manifest = {}
    for sample in ("polyhedra", "spheres"):
        manifest[sample] = []
        for k, off in enumerate(OFFSETS):
            run = study / f"{sample}-seed{k + 1}"
            (run / "analysis").mkdir(parents=True)
            (run / "params.json").write_text(json.dumps({"n_particles": n, "sample": sample}))
            (run / "run.info.json").write_text(json.dumps({"solid_fraction_isotropic": 0.58 + off}))
            base = {"snapshot": [f"{i:06d}" for i in range(7)], "eps_q": np.linspace(0, 0.3, 7),
                    "stage": ["isotropic"] + ["shear"] * 6, "z": 5.0, "frac_below_mean": 0.6,
                    "a": 0.1, "a_n": 0.5, "a_t": 0.4}
            base.update({k2: v + off for k2, v in values.items()})
            base["q_axial_over_p"] = base["q_over_p"]
            base["sff"] = 0.4 * (base["a"] + base["a_l"] + base["a_n"] + base["a_t"])
            if sample == "polyhedra":
                base.update({"ct_method": "points", "ct_threshold": 0.1, "ct_frac_simple": 0.7 + off,
                             "ct_frac_double": 0.25, "ct_frac_triple": 0.05 - off,
                             "ct_fabric_VF": 0.03 + off, "ct_fabric_EE": 0.08 + off})
            pd.DataFrame(base).to_csv(run / "analysis" / "summary.csv", index=False)
            manifest[sample].append({"label": f"seed {k + 1}", "dump": str(run / "run.h5"),
                                     "analysis": str(run / "analysis"), "info": str(run / "run.info.json"),
                                     "status": "ok"})
    (study / "manifest.json").write_text(json.dumps(manifest))
    if library is not None:
        (study / "polyhedra-ensemble").mkdir()
        library(str(study / "polyhedra-ensemble" / "shapes.h5"))
    return str(study)


def _generated(path):
    from shapes.generate import generate_library
    from shapes.library import write_library

    write_library(path, generate_library(4, seed=0)[0], seed=0, recipe={}, tolerances={}, name="generated")


def _stone(path):
    from shapes.library import write_library
    from shapes.meshimport import import_paths

    here = os.path.join(os.path.dirname(__file__), "data", "stonepacking", "stone_041.obj")
    grains, _, _ = import_paths([here])
    write_library(path, [g.polyhedron for g in grains], -1, {}, {}, name="stones",
                  extra={"reduction_hausdorff": np.array([g.reduction_hausdorff for g in grains])})


def test_direction_and_paper_values():
    assert sh.direction(0.0, 0.01, 0.05, 0.12) == "toward"      # up, toward a larger paper value
    assert sh.direction(0.2, 0.01, 0.05, 0.12) == "away"        # up, from above it
    assert sh.direction(0.2, -0.05, -0.01, 0.12) == "toward"
    assert sh.direction(0.0, -0.01, 0.05, 0.12) == "no change"
    assert sh.direction(0.0, 0.01, 0.05, np.nan) == ""
    assert sh.direction(0.709, -0.175, -0.109, 0.70) == "away"   # past the paper's 0.70 by far more than 0.009
    assert sh.direction(0.0, 0.2, 0.3, 0.12) == "undecided"      # nearer below 0.24, farther above it
    rng = np.random.default_rng(0)                              # against the distances themselves
    for first, paper, lo in rng.uniform(-1, 1, (200, 3)):
        hi = lo + rng.uniform(0, 0.5)
        word = sh.direction(first, lo, hi, paper)
        near = [abs(first + d - paper) < abs(first - paper) for d in np.linspace(lo, hi, 201)]
        assert word == ("no change" if lo <= 0 <= hi else "toward" if all(near) else "away" if not any(near)
                        else "undecided"), (first, paper, lo, hi)
    with open(sh.REFERENCE) as fh:
        res = json.load(fh)["results"]
    assert sh.paper_value("q_over_p", "polyhedra") == res["q_over_p_plateau"]["polyhedra"]
    assert [sh.paper_value(f"lmgc90:ct_frac_{k}", "polyhedra") for k in ("simple", "double", "triple")] == \
        res["contact_types_simple_double_triple"]["polyhedra"]
    assert np.isnan(sh.paper_value("points:ct_fabric_EE", "polyhedra"))
    assert np.isnan(sh.paper_value("a_n", "polyhedra"))       # the paper states a_n + a_t only


def test_shape_front_of_two_hand_built_studies(tmp_path, monkeypatch):
    from saved_figures import is_png, record

    gen = _study(tmp_path, "gen", {"q_over_p": 0.44, "a_l": -0.03}, library=_generated)
    real = _study(tmp_path, "real", {"q_over_p": 0.40, "a_l": 0.05}, library=_stone)
    saved = record(monkeypatch)
    path = sh.write_shape_front([gen, real], str(tmp_path / "front"))
    table = pd.read_csv(tmp_path / "front" / "shape.csv").set_index(["quantity", "sample"])
    h = t.ppf(0.975, 2) * 0.01 / np.sqrt(3)                    # each mean's half-interval
    hd = t.ppf(0.975, 4) * np.hypot(0.01, 0.01) / np.sqrt(3)  # Welch, equal variances: 4 dof
    r = table.loc[("a_l", "polyhedra")]
    assert (r["mean:generated"], r["mean:stones"]) == pytest.approx((-0.03, 0.05), abs=1e-12)
    assert (r["low:stones"], r["high:stones"]) == pytest.approx((0.05 - h, 0.05 + h), rel=1e-9)
    assert (r["diff"], r["diff_low"], r["diff_high"]) == pytest.approx((0.08, 0.08 - hd, 0.08 + hd), rel=1e-9)
    assert r["paper"] == 0.12 and r["toward"] == "toward"
    q = table.loc[("q_over_p", "polyhedra")]
    assert q["diff"] == pytest.approx(-0.04) and q["toward"] == "away"          # 0.44 -> 0.40, paper 0.46
    s = table.loc[("points:ct_frac_simple", "polyhedra")]
    assert s["diff"] == pytest.approx(0, abs=1e-12) and s["toward"] == "no change" and s["paper"] == 0.70
    assert table.loc[("q_over_p", "spheres"), "toward"] == "toward"           # 0.44 -> 0.40, paper 0.23
    md = open(path).read()
    assert "| a_l | polyhedra | -0.030 [" in md and "**+0.080 [" in md and "| 0.12 | toward |" in md
    assert "generated (4 grains)" in md and "stones (1 grains)" in md
    assert "| vertices | " in md and "| reduction error (d) | 0.000 [0.000, 0.000] |" in md
    verdicts = pd.read_csv(tmp_path / "front" / "verdicts.csv")
    assert set(verdicts["study"]) == {"generated", "stones"}
    assert {"1", "3", "6", "6 (points)"} <= set(verdicts["claim"].astype(str))
    assert is_png(tmp_path / "front" / "shape-front.png")
    fig = saved.at(tmp_path / "front" / "shape-front.png")
    panels = {ax.get_title(): ax for ax in fig.axes if ax.get_title()}
    assert {"q/p plateau (S1)", "a_l (S1)", "simple contacts (S1)", "EE leaning (S1)"} <= set(panels)
    (bars,) = panels["a_l (S1)"].containers
    data, _, (segments,) = bars.lines
    np.testing.assert_allclose(data.get_ydata(), [-0.03, 0.05], atol=1e-12)
    np.testing.assert_allclose([seg[:, 1] for seg in segments.get_segments()],
                               [[-0.03 - h, -0.03 + h], [0.05 - h, 0.05 + h]], rtol=1e-9)
    dashed = [ln.get_ydata()[0] for ln in panels["a_l (S1)"].get_lines() if ln.get_linestyle() == "--"]
    assert dashed == [0.12]
    assert [tick.get_text() for tick in panels["a_l (S1)"].get_xticklabels()] == ["generated", "stones"]


def test_bad_inputs_are_one_line(tmp_path, capsys):
    from postproc.cli import main

    gen = _study(tmp_path, "gen", {"q_over_p": 0.44, "a_l": 0.0})
    big = _study(tmp_path, "big", {"q_over_p": 0.44, "a_l": 0.0}, n=5000)
    with pytest.raises(InputError, match="two studies or more"):
        sh.write_shape_front([gen], str(tmp_path / "f"))
    with pytest.raises(InputError, match=r"different numbers of grains \(\[1000, 5000\]\)"):
        sh.write_shape_front([gen, big], str(tmp_path / "f"))
    assert main(["investigate", "shape-front", gen, str(tmp_path / "none"), "--out", str(tmp_path / "g")]) == 2
    assert main(["investigate", "shape-front", gen, gen, "--out", str(tmp_path / "g"), "--labels", "one"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2 and "no manifest.json" in err[0] and "1 labels for 2 studies" in err[1]
    assert main(["investigate", "shape-front", gen, gen, "--out", str(tmp_path / "h"), "--labels", "a", "b"]) == 0
    assert "| q/p plateau | polyhedra | 0.440 [" in (tmp_path / "h" / "shape.md").read_text()
