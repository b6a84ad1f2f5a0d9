"""The size front (postproc.study.sizefront): the trend in N^(-1/3) against
an independent weighted fit, the differences and the scatter ratio against
their textbook formulas, and the whole front of hand-built studies with
known plateaus, its tables and what its figure draws."""
import json

import numpy as np
import pandas as pd
import pytest
from scipy.stats import f as f_dist
from scipy.stats import t

from postproc.errors import InputError
from postproc.statistics import Estimate
from postproc.study import sizefront as sf


def test_trend_is_the_weighted_line_in_n_to_the_minus_third():
    ns = np.array([200, 1000, 5000])
    x = ns ** (-1 / 3)
    y = 0.40 + 0.5 * x + np.array([0.002, -0.003, 0.001])
    se = np.array([0.02, 0.01, 0.005])
    pts = [(int(n), Estimate(v, s, 2, 3, "seeds")) for n, v, s in zip(ns, y, se)]
    y_inf, slope = sf._trend(pts)
    coef, cov = np.polyfit(x, y, 1, w=1 / se, cov="unscaled")      # independent: numpy's weighted fit
    assert slope.mean == pytest.approx(coef[0], rel=1e-10) and y_inf.mean == pytest.approx(coef[1], rel=1e-10)
    assert slope.se == pytest.approx(np.sqrt(cov[0, 0]), rel=1e-10)
    assert y_inf.se == pytest.approx(np.sqrt(cov[1, 1]), rel=1e-10)
    # exact data: the intercept is the value at N -> inf
    exact = [(int(n), Estimate(0.4 + 0.5 * n ** (-1 / 3), 0.01, 2, 3, "seeds")) for n in ns]
    assert sf._trend(exact)[0].mean == pytest.approx(0.4, abs=1e-12)
    # fewer than three points, or no error: no trend
    assert not np.isfinite(sf._trend(exact[:2])[0].mean)
    assert not np.isfinite(sf._trend([(n, Estimate(1.0, np.nan, 0, 1, "one value")) for n in ns])[0].mean)


def _values():
    rows = []
    for n, vals in ((1000, [1.0, 2.0, 3.0]), (4000, [1.0, 1.5, 2.0])):
        for k, v in enumerate(vals):
            rows.append({"study": f"s{n}", "sample": "polyhedra", "n_particles": n, "run": f"seed {k + 1}",
                         "q_over_p": v, "points:ct_fabric_EE": v / 10})
    return pd.DataFrame(rows)


def test_size_table_means_differences_and_scatter_ratio():
    table = sf.size_table(_values())
    q = table[table["quantity"] == "q_over_p"].set_index("n_particles")
    assert q.loc[1000, "mean"] == 2.0 and q.loc[4000, "mean"] == 1.5
    h = t.ppf(0.975, 2) * 1.0 / np.sqrt(3)
    assert (q.loc[1000, "ci_low"], q.loc[1000, "ci_high"]) == pytest.approx((2 - h, 2 + h), rel=1e-12)
    se1, se2 = 1 / np.sqrt(3), 0.5 / np.sqrt(3)                 # Welch
    nu = (se1 ** 2 + se2 ** 2) ** 2 / (se1 ** 4 / 2 + se2 ** 4 / 2)
    hd = t.ppf(0.975, nu) * np.hypot(se1, se2)
    assert q.loc[4000, "diff"] == -0.5 and q.loc[4000, "diff_from"] == 1000
    assert (q.loc[4000, "diff_low"], q.loc[4000, "diff_high"]) == pytest.approx((-0.5 - hd, -0.5 + hd), rel=1e-9)
    sc = sf.scatter_table(_values()).set_index("n_particles")
    assert sc.loc[1000, "sd"] == pytest.approx(0.1) and sc.loc[4000, "sd"] == pytest.approx(0.05)
    assert sc.loc[4000, "ratio"] == pytest.approx(2.0) and sc.loc[4000, "expected"] == pytest.approx(2.0)
    F = f_dist.ppf(0.975, 2, 2)
    assert F == pytest.approx(39.0)
    assert sc.loc[4000, "ratio_low"] == pytest.approx(2 / np.sqrt(39.0))
    assert sc.loc[4000, "ratio_high"] == pytest.approx(2 * np.sqrt(39.0))
    assert (sc["count"] == "points").all() and (sc["leaning"] == "EE").all()


def _study(root, n, plateau, seeds=3, counts=True):
    """A study folder with S1 and S2 runs whose steady q/p and leanings are
    ``plateau`` + seed offsets: summaries written by hand."""
    study = root / f"n{n}"
    manifest = {}
    for sample in ("polyhedra", "spheres"):
        manifest[sample] = []
        for k in range(seeds):
            run = study / f"{sample}-seed{k + 1}"
            run.mkdir(parents=True)
            (run / "params.json").write_text(json.dumps({"n_particles": n, "sample": sample}))
            (run / "run.info.json").write_text(json.dumps({"solid_fraction_isotropic": 0.58 + 0.001 * k}))
            off = 0.01 * (k - 1)
            eq = np.linspace(0, 0.3, 7)
            base = {"snapshot": [f"{i:06d}" for i in range(7)], "eps_q": eq,
                    "stage": ["isotropic"] + ["shear"] * 6, "q_over_p": plateau + off,
                    "q_axial_over_p": plateau + off, "sff": 0.9 * (plateau + off), "a": 0.1, "a_l": 0.0,
                    "a_n": 0.5, "a_t": 0.4, "z": 5.0, "frac_below_mean": 0.6}
            entry = {"label": f"seed {k + 1}", "dump": str(run / "run.h5"), "analysis": str(run / "analysis"),
                     "info": str(run / "run.info.json"), "status": "ok"}
            if sample == "polyhedra":
                base.update({"ct_method": "points", "ct_threshold": 0.1, "ct_fabric_VF": 0.03 + off,
                             "ct_fabric_EE": 0.08 + off, "ct_frac_triple": 0.02})
                if counts:
                    cp = run / "analysis-commonplane"
                    cp.mkdir()
                    pd.DataFrame({**base, "ct_method": "commonplane", "ct_fabric_VF": -0.03 + off,
                                  "ct_fabric_EE": -0.04 + off, "ct_frac_triple": 0.4}).to_csv(cp / "summary.csv",
                                                                                               index=False)
                    entry["counts"] = {"commonplane": str(cp)}
            (run / "analysis").mkdir()
            pd.DataFrame(base).to_csv(run / "analysis" / "summary.csv", index=False)
            manifest[sample].append(entry)
    (study / "manifest.json").write_text(json.dumps(manifest))
    return str(study)


def test_write_size_front_of_hand_built_studies(tmp_path, monkeypatch):
    from saved_figures import is_png, record

    studies = [_study(tmp_path, 200, 0.50), _study(tmp_path, 1000, 0.45), _study(tmp_path, 5000, 0.43)]
    saved = record(monkeypatch)
    path = sf.write_size_front(studies, str(tmp_path / "front"))
    table = pd.read_csv(tmp_path / "front" / "size.csv")
    q = table[(table["quantity"] == "q_over_p") & (table["sample"] == "polyhedra")].set_index("n_particles")
    np.testing.assert_allclose(q["mean"], [0.50, 0.45, 0.43], rtol=1e-12)
    rel = table[(table["quantity"] == "sff_rel_residual")]
    np.testing.assert_allclose(rel["mean"], 0.1, rtol=1e-9)
    cp = table[table["quantity"] == "commonplane:ct_fabric_EE"].set_index("n_particles")
    np.testing.assert_allclose(cp["mean"], -0.04, atol=1e-12)
    phi = table[(table["quantity"] == "phi_iso") & (table["sample"] == "spheres")]
    np.testing.assert_allclose(phi["mean"], 0.581, rtol=1e-12)
    verdicts = pd.read_csv(tmp_path / "front" / "verdicts.csv")
    assert set(verdicts["n_particles"]) == {200, 1000, 5000}
    assert set(verdicts.loc[verdicts["claim"] == 6, "count"]) == {"primary", "points", "commonplane"}
    md = open(path).read()
    assert "| q/p plateau | polyhedra | 0.500 [" in md and "N = 5000" in md
    # size-front.png, as written: a panel per quantity of the table, each series its means and 95 %
    # intervals at N = 200, 1000, 5000, its line in N^(-1/3) and the published values dashed
    assert is_png(tmp_path / "front" / "size-front.png")
    fig = saved.at(tmp_path / "front" / "size-front.png")
    from postproc.plots import SIZE_PANELS

    quantities = set(table["quantity"])
    panels = {ax.get_title(): ax for ax in fig.axes if ax.get_title()}
    assert list(panels) == [title for q, title in SIZE_PANELS
                            if any(t == q or t.endswith(":" + q) for t in quantities)]
    assert "q/p plateau" in panels and "EE leaning (S1)" in panels
    with open(sf.REFERENCE) as fh:
        pub = json.load(fh)["results"]["q_over_p_plateau"]
    for title, q, series in (("q/p plateau", "q_over_p", {"S1": ("polyhedra", "q_over_p"),
                                                          "S2": ("spheres", "q_over_p")}),
                             ("EE leaning (S1)", "ct_fabric_EE", {"S1 points": ("polyhedra", "points:ct_fabric_EE"),
                                                                  "S1 commonplane": ("polyhedra",
                                                                                     "commonplane:ct_fabric_EE")})):
        ax = panels[title]
        assert ax.get_xscale() == "log" and ax.get_xlabel() == "N (grains per sample)"
        bars = {c.get_label(): c for c in ax.containers}
        assert sorted(bars) == sorted(series), title
        for lab, (sample, name) in series.items():
            g = table[(table["quantity"] == name) & (table["sample"] == sample)].sort_values("n_particles")
            data, _, (segments,) = bars[lab].lines
            np.testing.assert_array_equal(data.get_xdata(), [200, 1000, 5000])
            np.testing.assert_allclose(data.get_ydata(), g["mean"], rtol=1e-12)
            # the error bars: the interval of each mean
            np.testing.assert_allclose([seg[:, 1] for seg in segments.get_segments()],
                                       g[["ci_low", "ci_high"]].to_numpy(float), rtol=1e-12)
            # the straight line in N^(-1/3) through the means: extrapolated + slope N^(-1/3)
            y0, c = g["extrapolated"].iloc[0], g["slope"].iloc[0]
            assert np.isfinite(y0) and np.isfinite(c)
            (fit,) = [ln for ln in ax.get_lines() if ln.get_linestyle() == "-" and ln.get_color() == data.get_color()]
            np.testing.assert_allclose(fit.get_ydata(), y0 + c * fit.get_xdata() ** (-1 / 3), rtol=1e-12)
            assert fit.get_xdata().min() < 200 and fit.get_xdata().max() > 5000
        dashed = sorted(ln.get_ydata()[0] for ln in ax.get_lines() if ln.get_linestyle() == "--")
        assert dashed == (sorted([pub["polyhedra"], pub["spheres"]]) if q == "q_over_p" else [])
    from postproc.plots import plot_size_front

    drawn = plot_size_front(table, str(tmp_path / "again.png"))
    by = {(title, lab): (n, m) for title, lab, n, m in drawn}
    n, m = by[("q/p plateau", "S1")]
    assert n.tolist() == [200, 1000, 5000] and np.allclose(m, [0.50, 0.45, 0.43])
    assert set(lab for title, lab, _, _ in drawn if title == "EE leaning (S1)") == {"S1 points", "S1 commonplane"}


def test_bad_inputs_are_one_line(tmp_path):
    with pytest.raises(InputError, match="no manifest.json"):
        sf.study_values(str(tmp_path))
    one = _study(tmp_path, 1000, 0.45)
    with pytest.raises(InputError, match="two numbers of grains"):
        sf.write_size_front([one], str(tmp_path / "f"))


def test_cli_size_front(tmp_path, capsys):
    from postproc.cli import main

    studies = [_study(tmp_path, 200, 0.50), _study(tmp_path, 1000, 0.45)]
    assert main(["investigate", "size-front", *studies, "--out", str(tmp_path / "f")]) == 0
    assert (tmp_path / "f" / "size.md").exists()
    capsys.readouterr()
    assert main(["investigate", "size-front", str(tmp_path / "nothing"), str(tmp_path / "n200"), "--out", str(tmp_path / "g")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "no manifest.json" in err[0]
