"""The speed/error front: a two-point sweep per sample on the tiny preset
(YADE, yade-batch), and the front's pure parts on known inputs."""
import math
import os
import shutil

import numpy as np
import pandas as pd
import pytest

from postproc.study.front import (add_errors, analysis_front, cost_model, fit_rigid_quasistatic, fit_table,
                                  monotone, pareto, point_table)


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


def synthetic_sweep(x0=0.40, A=0.03, B=0.05, noise=0.0, seeds=(1, 2, 3), rng=None, alpha=1.0, beta=1.0):
    """Runs of a kappa sweep at I = 2e-2, an I sweep at kappa = 300 and a
    corner, obeying X = x0 + A (300/kappa)^alpha + B (I/2e-2)^beta + c_seed
    (+ noise)."""
    pts = [(300, 2e-2), (100, 2e-2), (1000, 2e-2), (3000, 2e-2), (300, 4e-2), (300, 1e-2),
           (300, 5e-3), (1000, 1e-2)]
    offsets = {1: 0.02, 2: -0.01, 3: -0.01}
    rows = []
    for seed in seeds:
        for k, i in pts:
            x = x0 + A * (300 / k) ** alpha + B * (i / 2e-2) ** beta + offsets[seed]
            if noise:
                x += noise * rng.standard_normal()
            rows.append({"sample": "polyhedra", "kappa": float(k), "inertial_number": i, "n_particles": 200,
                         "library": "shapes.h5", "seed": seed, "qp_plateau": x})
    return pd.DataFrame(rows)


def test_rigid_quasistatic_fit_recovers_an_exact_law():
    runs = synthetic_sweep()
    f = fit_rigid_quasistatic(runs, "qp_plateau")
    # exact data: only round-off is left
    assert f["X0"] == pytest.approx(0.40, abs=1e-12)
    assert f["A"] == pytest.approx(0.03, abs=1e-12) and f["B"] == pytest.approx(0.05, abs=1e-12)
    assert f["bias"] == pytest.approx(0.08, abs=1e-12) and f["resid_sd"] < 1e-12
    assert f["n"] == 24 and f["dof"] == 24 - 5          # X0, A, B and two seed offsets
    # the seeds' offsets do not leak into X0 when a seed misses a point
    f2 = fit_rigid_quasistatic(runs.drop(index=[9, 10]), "qp_plateau")
    assert f2["X0"] == pytest.approx(0.40, abs=1e-12)
    t = fit_table(runs, ("qp_plateau",))
    row = t.iloc[0]
    assert row["monotone_kappa"] == -1 and row["monotone_I"] == 1
    assert row["corner_residual"] == pytest.approx(0.0, abs=1e-12)
    assert (row["alpha"], row["beta"]) == (1.0, 1.0)
    # a law in kappa^-1/2 and I^1/2 (jamming-like): that form is chosen, exactly
    t = fit_table(synthetic_sweep(alpha=0.5, beta=0.5), ("qp_plateau",)).iloc[0]
    assert (t["alpha"], t["beta"]) == (0.5, 0.5) and t["X0"] == pytest.approx(0.40, abs=1e-12)
    assert t["X0_min"] - 1e-12 <= 0.40 <= t["X0_max"] + 1e-12 and t["X0_max"] - t["X0_min"] > 0.01


def test_fit_and_cost_take_each_samples_own_default_point():
    """Two samples around two default points (the plan's "reference"): each
    fit recovers its exact law in its own units (kappa_d/kappa, I/I_d), so
    A and B are the effects at that sample's default; the cost model scales
    each sample's steps to its own point."""
    ref = {"polyhedra": (3000.0, 5e-3), "spheres": (3000.0, 1e-3)}
    law = {"polyhedra": (0.40, 0.03, 0.05), "spheres": (0.25, -0.01, 0.02)}
    pts = {"polyhedra": [(3000, 5e-3), (300, 5e-3), (1000, 5e-3), (10000, 5e-3), (3000, 1e-2), (1000, 1e-2)],
           "spheres": [(3000, 1e-3), (300, 1e-3), (10000, 1e-3), (3000, 5e-4), (3000, 5e-3), (1000, 2e-3)]}
    rows = []
    for s, (kd, idd) in ref.items():
        x0, A, B = law[s]
        for seed, off in ((1, 0.01), (2, -0.02), (3, 0.01)):
            for k, i in pts[s]:
                c, sh = 4000 * math.sqrt(k / kd), 9000 * math.sqrt(k / kd) * idd / i
                rows.append({"sample": s, "kappa": float(k), "inertial_number": i, "n_particles": 200,
                             "library": "shapes.h5", "seed": seed, "final_strain": 0.3,
                             "qp_plateau": x0 + A * kd / k + B * i / idd + off,
                             "compaction_steps": c, "shear_steps": sh, "steps": c + sh,
                             "touch_steps": 2 * (c + sh), "contact_steps": np.nan, "wall_seconds": c + sh})
    runs = pd.DataFrame(rows)
    t = fit_table(runs, ("qp_plateau",), forms=((1.0, 1.0),), reference=ref).set_index("sample")
    for s, (x0, A, B) in law.items():
        assert (t.loc[s, "kappa_d"], t.loc[s, "inertial_d"]) == ref[s]
        assert t.loc[s, "X0"] == pytest.approx(x0, abs=1e-12) and t.loc[s, "A"] == pytest.approx(A, abs=1e-12)
        assert t.loc[s, "B"] == pytest.approx(B, abs=1e-12) and t.loc[s, "corner_residual"] == pytest.approx(0, abs=1e-12)
        assert t.loc[s, "default_mean"] == pytest.approx(x0 + A + B, abs=1e-12)
    # without the mapping the spheres' default point (300, 2e-2) has no runs: no default mean
    assert np.isnan(fit_table(runs, ("qp_plateau",)).set_index("sample").loc["spheres", "default_mean"])
    m = cost_model(runs, reference=ref).set_index("sample")
    assert m["compaction_steps_ref"].tolist() == pytest.approx([4000, 4000])
    assert m["shear_steps_ref"].tolist() == pytest.approx([9000, 9000]) and (m["shear_steps_ref_rsd"] < 1e-12).all()


def test_the_default_front_is_centred_on_the_default_preset():
    """The plan "default" names each sample's default point as its reference,
    that point is the preset's (kappa, I), it has 3 paired seeds, and both
    sweeps and a corner surround it (what the fit needs: two kappa and two I
    values besides the reference, one point off both sweeps)."""
    from yade_scripts.campaign.sweeps import PLANS
    from yade_scripts.campaign.presets import resolve

    plan = PLANS["default"]
    for s in ("polyhedra", "spheres"):
        p = resolve(plan["preset"], s)
        kd, idd = plan["reference"][s]
        assert (kd, idd) == (p["kappa"], p["inertial_number"])
        pts = {(o["kappa"], o["inertial_number"]) for _, o in plan[s]}
        assert {o["seed"] for _, o in plan[s]} == {1, 2, 3}
        assert all(sum(1 for _, o in plan[s] if (o["kappa"], o["inertial_number"]) == q) == 3 for q in pts)
        assert len({k for k, i in pts if i == idd} - {kd}) >= 2 and len({i for k, i in pts if k == kd} - {idd}) >= 2
        assert any(k != kd and i != idd for k, i in pts)
        assert min(i for k, i in pts if k == kd) < idd < max(i for k, i in pts if k == kd)


def test_rigid_quasistatic_fit_intervals_cover_the_truth():
    """With Gaussian noise of sd 0.01, the 95 % intervals of X0 and of the
    bias cover the truth in about 95 % of 400 sweeps (binomial sd 1.1 %:
    a band of 4 sd)."""
    rng = np.random.default_rng(3)
    cover = {"X0": 0, "bias": 0}
    for _ in range(400):
        f = fit_rigid_quasistatic(synthetic_sweep(noise=0.01, rng=rng), "qp_plateau")
        cover["X0"] += abs(f["X0"] - 0.40) <= f["ci_X0"]
        cover["bias"] += abs(f["bias"] - 0.08) <= f["ci_bias"]
    for k, c in cover.items():
        assert 0.95 - 4 * 0.011 < c / 400 < 0.95 + 4 * 0.011, (k, c)


def test_point_table_and_monotone_on_known_numbers():
    runs = pd.DataFrame({"sample": ["s"] * 6, "kappa": [300.0] * 3 + [1000.0] * 3,
                         "inertial_number": [0.02] * 6, "n_particles": [10] * 6, "library": ["x"] * 6,
                         "seed": [1, 2, 3] * 2, "q": [1.0, 2.0, 3.0, 5.0, 5.0, 5.0],
                         "wall_seconds": [1, 2, 3, 4, 5, 6], "steps": [10] * 6,
                         "compaction_steps": [4] * 6, "shear_steps": [6] * 6})
    p = point_table(runs, ("q",))
    assert p["n_seeds"].tolist() == [3, 3] and p["q"].tolist() == [2.0, 5.0]
    # t(0.975, 2) = 4.3027 times s.e. 1/sqrt(3)
    assert p["q_ci"].iloc[0] == pytest.approx(4.302653 / math.sqrt(3), rel=1e-6)
    assert p["q_ci"].iloc[1] == 0.0 and p["wall_seconds"].tolist() == [2.0, 5.0]
    pts = pd.DataFrame({"kappa": [100.0, 300, 1000, 3000], "inertial_number": [0.02] * 4,
                        "q": [1.0, 2.0, 2.5, 2.4]})
    assert monotone(pts, "q", "kappa", 0.02) == 0
    assert monotone(pts.iloc[:3], "q", "kappa", 0.02) == 1


def test_cost_model_scales_steps_to_the_default():
    """Steps that follow the laws exactly (compaction as kappa^1/2, shear
    as kappa^1/2 / I) scale back to one reference with no spread."""
    rows = []
    for k, i in [(300, 2e-2), (1200, 2e-2), (300, 5e-3), (75, 4e-2)]:
        c = 40000 * math.sqrt(k / 300)
        sh = 30000 * math.sqrt(k / 300) * (2e-2 / i) * (0.2 / 0.3)
        rows.append({"sample": "polyhedra", "n_particles": 200, "kappa": float(k), "inertial_number": i,
                     "final_strain": 0.2, "compaction_steps": c, "shear_steps": sh, "steps": c + sh,
                     "touch_steps": 600 * (c + sh), "contact_steps": np.nan,
                     "wall_seconds": (c + sh) * 600 * 5e-6})
    m = cost_model(pd.DataFrame(rows)).iloc[0]
    assert m["compaction_steps_ref"] == pytest.approx(40000) and m["shear_steps_ref"] == pytest.approx(30000)
    assert m["compaction_steps_ref_rsd"] < 1e-12 and m["shear_steps_ref_rsd"] < 1e-12
    assert m["contacts_per_grain"] == pytest.approx(3.0) and m["us_per_contact_step"] == pytest.approx(5.0)


def test_analysis_front_errors_shrink_as_one_over_sqrt_n():
    t = analysis_front(sizes=(400, 6400), bins=(9,), reps=30, seed=1)
    assert set(t["estimator"]) == {"tensors", "fit-9"}
    for name, g in t.groupby("estimator"):
        g = g.sort_values("n")
        ratio = g["rms_max"].iloc[0] / g["rms_max"].iloc[1]
        # sqrt(16) = 4; the RMS over 30 sets has a relative s.e. of about 1/sqrt(60)
        assert 4 * (1 - 3 / math.sqrt(60)) < ratio < 4 * (1 + 3 / math.sqrt(60)), name
    assert (t["seconds"] > 0).all()


def check_front_figures(out, saved):
    """front.png and front-trends.png, as written into the sweep folder
    ``out`` (``saved``: saved_figures.record), show front.csv and
    front-points.csv: per sample, every run's wall time against its largest
    error (filled when on the Pareto front) and each error, named by run;
    per sample and quantity, every point's mean and interval, at x = kd/k
    (kappa sweep and corner) or I/Id (I sweep), and the fitted limit X0 at
    x = 0 where there is one."""
    from saved_figures import is_png, line

    from postproc.plots import TREND_PANELS
    from postproc.study.front import FRONT_I, FRONT_KAPPA

    runs = pd.read_csv(out / "front.csv", dtype={"run": str})
    assert is_png(out / "front.png") and is_png(out / "front-trends.png")
    fig = saved.at(out / "front.png")
    samples = list(dict.fromkeys(runs["sample"]))
    assert [ax.get_title() for ax in fig.axes] == samples
    for ax, s in zip(fig.axes, samples):
        g = runs[runs["sample"] == s]
        x = g["wall_seconds"].to_numpy(float)
        largest = ax.collections[0]
        np.testing.assert_allclose(largest.get_offsets(), np.column_stack([x, g["err_max"]]), rtol=1e-12)
        assert (largest.get_facecolors()[:, 3] > 0).tolist() == g["pareto"].tolist()    # filled: Pareto
        for col, lab in (("err_q_over_p", "q/p"), ("err_a", "a"), ("err_a_n", "a_n"), ("err_a_t", "a_t")):
            np.testing.assert_allclose(line(ax, lab).get_xydata(), np.column_stack([x, g[col]]), rtol=1e-12)
        assert [t.get_text() for t in ax.texts] == g["run"].tolist()
        se = g.loc[g["ref"], "q_over_p_se"].to_numpy(float)[:1]
        band = [p for p in ax.patches if p.get_label() == "2 s.e. of the reference q/p (one seed)"]
        if len(se) and np.isfinite(se[0]):                            # the reference's own noise, shaded
            assert len(band) == 1 and band[0].get_y() == 0 and band[0].get_height() == pytest.approx(2 * se[0])
        else:
            assert not band
        assert ax.get_xscale() == "log" and ax.get_xlabel() == "wall time of the run (s)"
        assert ax.get_ylabel() == "|plateau - reference plateau|"
    points = pd.read_csv(out / "front-points.csv")
    fits = pd.read_csv(out / "front-fit.csv")
    fig = saved.at(out / "front-trends.png")
    samples = list(dict.fromkeys(points["sample"]))
    panels = [p for p in TREND_PANELS if p[0] in points]
    assert len(fig.axes) == len(samples) * len(panels)
    for r, s in enumerate(samples):
        fs = fits[fits["sample"] == s]
        kd, i_d = ((float(fs["kappa_d"].iloc[0]), float(fs["inertial_d"].iloc[0]))
                   if "kappa_d" in fs and len(fs) else (FRONT_KAPPA, FRONT_I))
        g = points[points["sample"] == s]
        g = g[g["n_particles"] == g["n_particles"].mode().iloc[0]]
        kap = np.isclose(g["inertial_number"], i_d)
        rate = np.isclose(g["kappa"], kd) & ~kap
        corner = ~kap & ~rate
        for c, (q, label) in enumerate(panels):
            ax = fig.axes[r * len(panels) + c]
            drawn = {b.get_label(): b.lines[0].get_xydata() for b in ax.containers}
            for sel, x, lab in ((kap, kd / g["kappa"], "x = κd/κ"), (rate, g["inertial_number"] / i_d, "x = I/Id"),
                                (corner, kd / g["kappa"], "corner (x = κd/κ)")):
                if sel.any():
                    np.testing.assert_allclose(drawn.pop(lab), np.column_stack([x[sel], g.loc[sel, q]]),
                                               rtol=1e-12, err_msg=f"{s} {q} {lab}")
            f = fs[fs["quantity"] == q]
            if np.isfinite(g[q].to_numpy(float)).any() and len(f) and np.isfinite(f["X0"].iloc[0]):
                np.testing.assert_allclose(drawn.pop("κ→∞, I→0"), [[0, f["X0"].iloc[0]]], rtol=1e-12)
            assert not drawn, (s, q, list(drawn))                     # nothing else
            if np.isfinite(g[q].to_numpy(float)).any():
                assert ax.get_title() == f"{s} (κd {kd:g}, Id {i_d:g}): {label}"
            else:
                assert not ax.axison                                  # e.g. contact types of spheres


@pytest.mark.yade
@pytest.mark.skipif(shutil.which("yade-batch") is None, reason="Debian yade is not installed")
def test_two_point_sweep_on_the_tiny_preset(tmp_path, shape_library, monkeypatch):
    from saved_figures import record

    from yade_scripts.campaign.sweeps import main

    out = tmp_path / "front"
    saved = record(monkeypatch)
    assert main(["--plan", "smoke", "--out", str(out), "--library", shape_library]) == 0
    table = pd.read_csv(out / "front.csv")
    check_front_figures(out, saved)
    assert sorted(table["sample"]) == ["polyhedra", "polyhedra", "spheres", "spheres"]
    cols = ["wall_seconds", "steps", "contact_steps", "q_over_p", "a", "a_n", "a_t", "err_max"]
    assert np.isfinite(table[cols].to_numpy(float)).all()
    ref = table[table["ref"]]
    assert len(ref) == 2 and (ref["err_max"] == 0).all()
    assert set(table.loc[table["sample"] == "polyhedra", "library"]) == {"shapes.h5", "shapes-low.h5"}
    # every comparison quantity per run, and the seed/fit/cost tables (two
    # points per sample leave the fit no degrees of freedom: nans, not numbers)
    assert np.isfinite(table[["qp_plateau", "qp_peak", "z", "phi_iso", "frac_below_mean"]].to_numpy(float)).all()
    points = pd.read_csv(out / "front-points.csv")
    assert len(points) == 4 and (points["n_seeds"] == 1).all()
    fits = pd.read_csv(out / "front-fit.csv")
    assert fits["X0"].isna().all() and set(fits["sample"]) == {"polyhedra", "spheres"}
    cost = pd.read_csv(out / "front-cost.csv")
    assert (cost["us_per_contact_step"] > 0).all() and (cost["contacts_per_grain"] > 0).all()
    assert "### cost" in (out / "front.md").read_text()


def test_a_library_the_front_cannot_write_is_one_line(tmp_path, capsys, monkeypatch):
    """The smoke and quick plans write a low-detail library: a disk error
    there (write_library's LibraryError) ends the front in one line, exit 2."""
    import errno

    import shapes.library as L
    from yade_scripts.campaign import sweeps as front

    def full(tmp, *args):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(L, "_write_tmp", full)
    monkeypatch.setattr(front, "generate", lambda folder, *a, **k: os.makedirs(folder, exist_ok=True))
    assert front.main(["--plan", "smoke", "--out", str(tmp_path / "f"), "--samples", "polyhedra"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"front: error: {tmp_path / 'f' / 'polyhedra' / 'shapes-low.h5'}: cannot write the library "
                   "(No space left on device)"]
