"""The figures of postproc.plots hold the data they are given: every plot
function is called on hand-built inputs and its returned Figure is read
back (the plotted lines and points, axes labels, legends, titles), and the
file it wrote is a PNG."""
import numpy as np
import pandas as pd
import pytest
from matplotlib.collections import LineCollection, PolyCollection

from postproc import plots
from postproc.angular import angular_functions, fit_harmonics, harmonic_curves
from postproc.statistics import plateau_estimate
from postproc.synthetic import harmonic_contacts

from saved_figures import is_png as written, legend_texts, line


def summary(n=6, seed=0, shift=0.0):
    """A summary.csv-like frame of one run: isotropic row, then shear."""
    rng = np.random.default_rng(seed)
    eq = np.r_[0.0, np.linspace(0.05, 0.3, n - 1)]
    df = pd.DataFrame({"eps_q": eq, "stage": ["isotropic"] + ["shear"] * (n - 1)})
    for k, col in enumerate(("q_over_p", "q_over_p_branch", "sff", "sff_fit", "a", "a_l", "a_n", "a_t",
                             "a_fit", "a_l_fit", "a_n_fit", "a_t_fit", "q_axial_over_p")):
        df[col] = shift + 0.1 * k + rng.uniform(0, 0.05, n)
    for k in ("a", "a_l", "a_n", "a_t"):
        df[k + "_se"] = 0.01
    df["q_over_p_wall"] = np.nan
    return df


def test_qp_sff_draws_the_three_stress_forms_and_the_sum(tmp_path):
    df = summary()
    fig = plots.plot_qp_sff(df, tmp_path / "q.png", "run A")
    ax = fig.axes[0]
    for label, col in (("q/p (internal moments)", "q_over_p"), ("q/p (branch vectors)", "q_over_p_branch"),
                       (r"$\frac{2}{5}(a+a_l+a_n+a_t)$ tensors", "sff"), (r"$\frac{2}{5}\Sigma a$ fits", "sff_fit")):
        ln = line(ax, label)
        np.testing.assert_array_equal(ln.get_xdata(), df["eps_q"])
        np.testing.assert_array_equal(ln.get_ydata(), df[col])
    assert "q/p (walls)" not in legend_texts(ax)          # all NaN: not drawn
    df["q_over_p_wall"] = 0.5
    ax = plots.plot_qp_sff(df, tmp_path / "q2.png").axes[0]
    np.testing.assert_array_equal(line(ax, "q/p (walls)").get_ydata(), 0.5)
    assert ax.get_xlabel() == r"$\varepsilon_q$" and ax.get_ylabel() == "q/p" and fig.axes[0].get_title() == "run A"
    assert written(tmp_path / "q.png")


def test_without_strains_the_x_axis_is_the_snapshot(tmp_path):
    df = summary()
    df["eps_q"] = np.nan
    ax = plots.plot_qp_sff(df, tmp_path / "q.png").axes[0]
    assert ax.get_xlabel() == "snapshot"
    np.testing.assert_array_equal(line(ax, "q/p (internal moments)").get_xdata(), np.arange(len(df)))


def test_anisotropies_with_error_bands_and_fits(tmp_path):
    df = summary()
    fig = plots.plot_anisotropies(df, tmp_path / "a.png", "run A")
    ax = fig.axes[0]
    assert legend_texts(ax) == ["a", "a_l", "a_n", "a_t"]
    for k in ("a", "a_l", "a_n", "a_t"):
        np.testing.assert_array_equal(line(ax, k).get_ydata(), df[k])
    fits = [ln for ln in ax.get_lines() if ln.get_linestyle() == "--"]
    np.testing.assert_array_equal(np.array([ln.get_ydata() for ln in fits]),
                                  df[["a_fit", "a_l_fit", "a_n_fit", "a_t_fit"]].to_numpy().T)
    bands = [c for c in ax.collections if isinstance(c, PolyCollection)]
    assert len(bands) == 4
    # the band of a spans a +- 2 s.e.
    ys = bands[0].get_paths()[0].vertices[:, 1]
    assert ys.min() == pytest.approx((df["a"] - 0.02).min()) and ys.max() == pytest.approx((df["a"] + 0.02).max())
    assert ax.get_ylabel() == "anisotropy" and written(tmp_path / "a.png")


@pytest.fixture(scope="module")
def polar_data():
    c = harmonic_contacts(20000, 0.3, 0.1, 0.5, 0.2, seed=3)
    af = angular_functions(c.branch, c.force, 2, 9)
    return af, fit_harmonics(af)


def test_polar_mirrors_the_bins_and_draws_the_fits(tmp_path, polar_data):
    af, fits = polar_data
    fig = plots.plot_polar(af, fits, tmp_path / "p.png", "last")
    assert len(fig.axes) == 4
    tt = np.linspace(0, 2 * np.pi, 361)
    curves = harmonic_curves(fits, tt)
    for ax, data, key in zip(fig.axes, (af.P, af.l_mean, af.fn_mean, af.ft_mean), ("P", "l", "fn", "ft")):
        points, fit = ax.get_lines()
        th, r = points.get_xdata(), points.get_ydata()
        assert len(r) == 4 * len(af.centers)
        np.testing.assert_allclose(th[:9], af.centers)
        np.testing.assert_allclose(r[:9], np.abs(data))
        np.testing.assert_allclose(r[9:18], np.abs(data[::-1]))     # mirrored about the lateral plane
        np.testing.assert_allclose(fit.get_ydata(), np.abs(curves[key]))
    assert fig.axes[0].get_theta_offset() == pytest.approx(np.pi / 2)   # the axis drawn vertical
    assert written(tmp_path / "p.png")


def test_force_pdf_one_line_per_class(tmp_path):
    rows = []
    for c, n in (("all", 100), ("simple", 60), ("VF", 30)):
        for binning in ("log", "linear"):
            for x, p in ((0.5, 0.8), (1.0, 0.5), (2.0, 0.1)):
                rows.append({"class": c, "binning": binning, "x": x, "pdf": p * (2 if binning == "log" else 1),
                             "count": n})
    pdf = pd.DataFrame(rows)
    fig = plots.plot_force_pdf(pdf, tmp_path / "f.png", "S1")
    log, lin = fig.axes
    assert legend_texts(log) == ["all (n=100)", "simple (n=60)", "VF (n=30)"]
    np.testing.assert_array_equal(line(log, "all (n=100)").get_ydata(), [1.6, 1.0, 0.2])
    np.testing.assert_array_equal(line(lin, "simple (n=60)").get_ydata(), [0.8, 0.5, 0.1])
    assert log.get_xscale() == "log" and lin.get_xscale() == "linear" and lin.get_yscale() == "log"
    assert written(tmp_path / "f.png")


def test_networks_draw_both_networks_and_their_shares(tmp_path):
    df = summary()
    for k in ("a", "a_n", "a_t"):
        df[f"strong_{k}"], df[f"weak_{k}"] = df[k] + 0.1, df[k] - 0.1
    df["strong_qp"], df["weak_qp"] = 0.8 * df["q_axial_over_p"], 0.2 * df["q_axial_over_p"]
    fig = plots.plot_networks(df, tmp_path / "n.png", "S1")
    left, right = fig.axes
    np.testing.assert_allclose(line(left, "strong a_n").get_ydata(), df["a_n"] + 0.1)
    np.testing.assert_allclose(line(left, "weak a_t").get_ydata(), df["a_t"] - 0.1)
    assert legend_texts(right) == ["strong network", "weak network", "total"]       # no wall column
    np.testing.assert_allclose(line(right, "strong network").get_ydata(), 0.8 * df["q_axial_over_p"])
    assert written(tmp_path / "n.png")


def contact_type_summary(method="points"):
    df = summary()
    for g, f in (("simple", 0.7), ("double", 0.25), ("triple", 0.05)):
        df[f"ct_frac_{g}"], df[f"ct_frac_{g}_lo"], df[f"ct_frac_{g}_hi"] = f, f - 0.02, f + 0.03
        df[f"ct_fratio_{g}"] = 2 * f
    for t, v in (("VF", -0.05), ("EE", -0.02), ("EF", 0.1), ("FF", 0.3)):
        df[f"ct_fabric_{t}"], df[f"ct_qp_{t}"] = v, v / 2
    df["ct_method"], df["ct_threshold"], df["ct_theta_deg"] = method, 0.1, 5.0
    return df


@pytest.mark.parametrize("method, words", [("points", ("contact points, tolerance 0.1 V/area", "0.05 to 0.2 V/area")),
                                           ("footprint", ("footprint threshold 0.1 d", "0.05 d to 0.2 d")),
                                           ("angular", ("angular tolerance 5 deg", "2.5 to 10 deg"))])
def test_contact_types_name_their_criterion(tmp_path, method, words):
    df = contact_type_summary(method)
    fig = plots.plot_contact_types(df, tmp_path / "t.png", "S1")
    frac, ratio, fabric, share = fig.axes
    np.testing.assert_array_equal(line(frac, "triple").get_ydata(), 0.05)
    np.testing.assert_array_equal(line(ratio, "simple").get_ydata(), 1.4)
    np.testing.assert_array_equal(line(fabric, "VF").get_ydata(), -0.05)
    np.testing.assert_array_equal(line(share, "FF").get_ydata(), 0.15)
    assert fig._suptitle.get_text() == f"S1: contact types, {words[0]}"
    assert frac.get_ylabel() == f"proportion (bands: {words[1]})"
    band = frac.collections[2].get_paths()[0].vertices[:, 1]     # the triple band, lo to hi
    assert band.min() == pytest.approx(0.03) and band.max() == pytest.approx(0.08)


def slab_panel(labels=None):
    return {"polygons": [np.array([[0, 0], [0.01, 0], [0.01, 0.01]])],
            "discs": (np.array([[0.05, 0.05]]), np.array([0.01])),
            "segments": np.array([[[0, 0], [0.1, 0.1]], [[0, 0.1], [0.1, 0]], [[0, 0.05], [0.1, 0.05]]]),
            "fn": np.array([1.0, 3.0, 2.0]), "labels": labels, "plane": 0.0, "thickness": 0.03,
            "axes": (0, 2), "extent": np.array([[0.0, 0.0], [0.1, 0.2]])}


def test_slabs_draw_every_contact_by_its_force(tmp_path):
    fig = plots.plot_slabs([("S1", slab_panel()), ("S2", slab_panel())], tmp_path / "s.png")
    ax = fig.axes[0]
    lines = [c for c in ax.collections if isinstance(c, LineCollection)][0]
    # drawn from the weakest up, width 0.3 + 1.1 f/<f>
    np.testing.assert_allclose([s[0, 1] for s in lines.get_segments()], [0, 0.05, 0.1])
    np.testing.assert_allclose(lines.get_linewidths(), 0.3 + 1.1 * np.array([1, 2, 3]) / 2)
    assert ax.get_xlabel() == "x (m)" and ax.get_ylabel() == "z (m)"
    assert ax.get_title() == "S1\n3 contacts in a slab 30 mm thick"
    assert ax.get_xlim() == (0.0, 0.1) and ax.get_ylim() == (0.0, 0.2)
    assert len(fig.axes) == 3                                   # two panels and the colour bar
    fig = plots.plot_slabs([("S1", slab_panel(np.array(["simple", "triple", "double"])))], tmp_path / "t.png",
                           colour="type")
    ax = fig.axes[0]
    lines = [c for c in ax.collections if isinstance(c, LineCollection)][0]
    from matplotlib.colors import to_rgba
    assert [tuple(c) for c in lines.get_colors()] == [to_rgba(plots.TYPE_COLOURS[k]) for k in
                                                       ("simple", "double", "triple")]
    assert legend_texts(ax) == ["simple", "double", "triple"] and written(tmp_path / "t.png")


def test_report_qp_one_line_per_seed_and_the_published_plateaus(tmp_path):
    s = {"polyhedra": [summary(seed=1, shift=0.2), summary(seed=2, shift=0.2)], "spheres": [summary(seed=3)]}
    fig = plots.plot_report_qp(s, {"polyhedra": 0.46, "spheres": None}, tmp_path / "r.png")
    ax = fig.axes[0]
    seeds = [ln for ln in ax.get_lines() if ln.get_linestyle() == "-"]
    assert len(seeds) == 3
    sh = s["polyhedra"][1][s["polyhedra"][1]["stage"] == "shear"]
    np.testing.assert_array_equal(seeds[1].get_ydata(), sh["q_over_p"])
    pub = [ln for ln in ax.get_lines() if ln.get_linestyle() == "--"]
    assert len(pub) == 1 and list(pub[0].get_ydata()) == [0.46, 0.46]
    assert legend_texts(ax) == ["S1 polyhedra", "S1 polyhedra, published plateau", "S2 spheres"]
    assert written(tmp_path / "r.png")


def test_report_anisotropies_are_the_mean_over_seeds(tmp_path):
    a, b = summary(seed=1), summary(seed=2)
    fig = plots.plot_report_anisotropies({"polyhedra": [a, b], "spheres": [summary(seed=4)]}, tmp_path / "a.png")
    left, right = fig.axes
    sh = a["stage"] == "shear"
    np.testing.assert_allclose(line(left, "a_n").get_ydata(), (a["a_n"][sh].to_numpy() + b["a_n"][sh].to_numpy()) / 2)
    assert left.get_title() == "S1 polyhedra (2 seed(s))" and right.get_title() == "S2 spheres (1 seed(s))"


def test_report_sff_points_and_equality(tmp_path):
    a = summary(seed=1)
    ax = plots.plot_report_sff({"polyhedra": [a]}, tmp_path / "s.png").axes[0]
    sh = a[a["stage"] == "shear"]
    pts = line(ax, "S1 polyhedra")
    np.testing.assert_array_equal(pts.get_xdata(), sh["sff"])
    np.testing.assert_array_equal(pts.get_ydata(), sh["q_axial_over_p"])
    eq = line(ax, "equality")
    np.testing.assert_array_equal(eq.get_xdata(), eq.get_ydata())


def test_report_polar_a_row_per_sample(tmp_path, polar_data):
    af, fits = polar_data
    fig = plots.plot_report_polar({"polyhedra": (af, fits, "seed 1"), "spheres": (af, fits, "seed 1")},
                                  tmp_path / "p.png")
    assert len(fig.axes) == 4
    np.testing.assert_allclose(fig.axes[1].get_lines()[0].get_ydata()[:9], af.l_mean)
    assert fig.axes[2].get_title().startswith("S2 spheres: $P_\\Omega(\\theta)$\nseed 1")


def test_group_polar_closes_each_curve_and_shows_isotropy(tmp_path, polar_data):
    af, _ = polar_data
    ax = plots.plot_group_polar({"simple": af, "triple": af}, "snapshot 7", tmp_path / "g.png").axes[0]
    simple = line(ax, "simple")
    assert simple.get_ydata()[0] == simple.get_ydata()[-1] == af.P[0]
    np.testing.assert_allclose(line(ax, "isotropic").get_ydata(), 1 / (4 * np.pi))
    assert "snapshot 7" in ax.get_title()


def test_footprint_histograms_count_every_contact(tmp_path):
    rng = np.random.default_rng(0)
    l1 = rng.uniform(0.01, 0.5, 400)
    ext = np.column_stack([l1, l1 * rng.uniform(0.1, 1, 400)])
    ext[:5] = np.nan                                          # no overlap: left out
    fig = plots.plot_footprint(ext, 0.1, tmp_path / "f.png", "S1")
    ax = fig.axes[0]
    assert ax.get_title() == "S1: 395 contacts"
    for patch in ax.patches:                                  # density per unit ln(L/d) integrates to 1
        h = patch.get_data()
        assert np.sum(h.values * np.diff(np.log(h.edges))) == pytest.approx(1.0)
    assert sorted(ln.get_xdata()[0] for ln in ax.get_lines()) == [0.05, 0.1, 0.2]


def test_leanings_by_tolerance_mean_and_interval_over_seeds(tmp_path):
    tol = [0.05, 0.1, 0.2]
    vf = np.array([[0.01, -0.02, 0.00], [-0.03, -0.05, -0.01], [-0.06, -0.02, -0.07]])
    fig = plots.plot_leanings_by_tolerance(tol, {"VF": vf, "EE": vf + 0.1}, tmp_path / "l.png", "LMGC90", "x r")
    ax = fig.axes[0]
    container = ax.containers[0]
    assert container.get_label() == "mean, 95 % over seeds" and legend_texts(ax) == ["mean, 95 % over seeds"]
    np.testing.assert_allclose(container.lines[0].get_ydata(), vf.mean(axis=1))
    np.testing.assert_allclose(ax.get_lines()[0].get_ydata(), vf[:, 0])     # seed 1 across tolerances
    bars = container.lines[2][0].get_segments()               # the error bars: mean +- half width
    est = plateau_estimate([[x] for x in vf[1]])
    assert bars[1][0][1] == pytest.approx(est.ci()[0]) and bars[1][1][1] == pytest.approx(est.ci()[1])
    assert ax.get_title() == "VF leaning, 3 seeds" and ax.get_xlabel() == "tolerance x r"
    assert fig._suptitle.get_text() == "claim 6 against the tolerance of LMGC90"


def test_front_marks_the_pareto_runs(tmp_path):
    runs = pd.DataFrame({"sample": ["s1"] * 3, "run": ["ref", "k1000", "k300"], "wall_seconds": [100.0, 30.0, 10.0],
                         "err_q_over_p": [0, 0.01, 0.05], "err_a": [0, 0.02, 0.01], "err_a_n": [0, 0.0, 0.03],
                         "err_a_t": [0, 0.01, 0.02], "err_max": [0, 0.02, 0.05], "pareto": [True, True, True],
                         "ref": [True, False, False], "q_over_p_se": [0.004, np.nan, np.nan]})
    ax = plots.plot_front(runs, tmp_path / "f.png").axes[0]
    np.testing.assert_array_equal(line(ax, "a_n").get_ydata(), [0, 0.0, 0.03])
    pts = ax.collections[0]
    np.testing.assert_array_equal(pts.get_offsets()[:, 1], [0, 0.02, 0.05])
    assert [t.get_text() for t in ax.texts] == ["ref", "k1000", "k300"]
    assert ax.get_xscale() == "log" and ax.get_title() == "s1"


def test_front_trends_draw_the_sweeps_and_the_limit(tmp_path):
    pts = pd.DataFrame({"sample": ["s"] * 4, "kappa": [3000.0, 1000.0, 3000.0, 1000.0],
                        "inertial_number": [5e-3, 5e-3, 1e-2, 1e-2], "n_particles": [200] * 4,
                        "a": [0.30, 0.35, 0.32, 0.36], "a_ci": [0.01] * 4})
    fits = pd.DataFrame({"sample": ["s"], "quantity": ["a"], "X0": [0.28], "A": [0.02], "B": [0.01],
                         "alpha": [1.0], "beta": [1.0], "ci_X0": [0.02]})
    fig = plots.plot_front_trends(pts, fits, tmp_path / "t.png", 3000.0, 5e-3)
    ax = fig.axes[0]
    assert ax.get_title() == "s (κd 3000, Id 0.005): a"
    kappa_line, rate_line = [ln for ln in ax.get_lines() if ln.get_linestyle() == "-"][:2]
    x = kappa_line.get_xdata()
    np.testing.assert_allclose(kappa_line.get_ydata(), 0.28 + 0.02 * x + 0.01)
    np.testing.assert_allclose(rate_line.get_ydata(), 0.28 + 0.02 + 0.01 * x)
    star = [ln for ln in ax.get_lines() if ln.get_marker() == "*"][0]
    assert list(star.get_xdata()) == [0] and list(star.get_ydata()) == [0.28]


def test_analysis_front_errors_and_times(tmp_path):
    t = pd.DataFrame({"estimator": ["tensors", "tensors", "fit-9", "fit-9"], "n": [100, 400, 100, 400],
                      "rms_max": [0.2, 0.1, 0.22, 0.11], "seconds": [1e-4, 3e-4, 2e-4, 4e-4]})
    left, right = plots.plot_analysis_front(t, tmp_path / "a.png").axes
    np.testing.assert_array_equal(line(left, "fit-9").get_ydata(), [0.22, 0.11])
    np.testing.assert_allclose(line(left, r"$\propto n^{-1/2}$").get_ydata(), [0.2, 0.1])
    np.testing.assert_array_equal(line(right, "tensors").get_xdata(), [1e-4, 3e-4])
    assert left.get_xlabel() == "contacts per set" and right.get_ylabel() == "RMS error"
