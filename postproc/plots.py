"""Figures of the seed paper from analysis results (matplotlib, Agg).

Every function writes one PNG to ``path`` and returns the matplotlib
``Figure`` it drew (closed: detached from pyplot, its axes, lines, labels
and texts still readable), so that tests and callers can check what was
plotted; :func:`plot_size_front` returns the plotted series instead.
"""
from __future__ import annotations

import numpy as np

from .angular import AngularFunctions, harmonic_curves
from .columns import label as column_label
from .statistics import plateau_estimate


def _plt():
    import matplotlib  # the Agg backend must be chosen before pyplot is imported

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # after the backend (above)

    return plt


def _xaxis(df):
    x = df["eps_q"].to_numpy(float)
    if np.all(np.isfinite(x)):
        return x, r"$\varepsilon_q$"
    return np.arange(len(df)), "snapshot"


def plot_qp_sff(df, path, label=""):
    """q/p (three stress forms) and (2/5)(a+a_l+a_n+a_t) against eps_q
    (seed figs. 3 and 8)."""
    plt = _plt()
    x, xl = _xaxis(df)
    fig, ax = plt.subplots(figsize=(5.5, 4))
    ax.plot(x, df["q_over_p"], "k-o", ms=3, label="q/p (internal moments)")
    ax.plot(x, df["q_over_p_branch"], "-", color="0.5", label="q/p (branch vectors)")
    if np.isfinite(df["q_over_p_wall"]).any():
        ax.plot(x, df["q_over_p_wall"], ":", color="tab:green", label="q/p (walls)")
    ax.plot(x, df["sff"], "r--s", ms=3, label=r"$\frac{2}{5}(a+a_l+a_n+a_t)$ tensors")
    ax.plot(x, df["sff_fit"], "b:^", ms=3, label=r"$\frac{2}{5}\Sigma a$ fits")
    ax.set_xlabel(xl)
    ax.set_ylabel("q/p")
    ax.set_title(label)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


def plot_anisotropies(df, path, label=""):
    """a, a_l, a_n, a_t against eps_q (seed figs. 6 and 7): tensors (solid,
    with standard-error bands when present) and fits (dashed)."""
    plt = _plt()
    x, xl = _xaxis(df)
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for k, col in zip(("a", "a_l", "a_n", "a_t"), ("C0", "C1", "C2", "C3")):
        y = df[k].to_numpy(float)
        ax.plot(x, y, "-o", ms=3, color=col, label=k)
        if k + "_se" in df:
            se = df[k + "_se"].to_numpy(float)
            ax.fill_between(x, y - 2 * se, y + 2 * se, color=col, alpha=0.15, lw=0)
        ax.plot(x, df[k + "_fit"], "--", color=col, lw=1)
    ax.axhline(0, color="0.7", lw=0.5)
    ax.set_xlabel(xl)
    ax.set_ylabel("anisotropy")
    ax.set_title(label + " (solid: tensors, bands: 2 s.e.; dashed: fits)", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


def plot_polar(af: AngularFunctions, fits, path, label=""):
    """Polar plots of P_Omega, <l>, <f_n'>, |<f_t'>| with their harmonic fits
    (seed figs. 5 and 7). theta is measured from the compression axis, drawn
    vertical; the data are mirrored to the full circle by symmetry."""
    plt = _plt()
    th = af.centers
    full = np.concatenate([th, np.pi - th[::-1], np.pi + th, 2 * np.pi - th[::-1]])
    tt = np.linspace(0, 2 * np.pi, 361)
    curves = harmonic_curves(fits, tt)

    def mirror(v):
        return np.concatenate([v, v[::-1], v, v[::-1]])

    panels = [("P", af.P, r"$P_\Omega(\theta)$"), ("l", af.l_mean, r"$\langle\ell\rangle(\theta)$"),
              ("fn", af.fn_mean, r"$\langle f_{n'}\rangle(\theta)$"),
              ("ft", af.ft_mean, r"$|\langle f_{t'}\rangle(\theta)|$")]
    fig, axes = plt.subplots(1, 4, subplot_kw={"projection": "polar"}, figsize=(12, 3.4))
    for ax, (key, data, title) in zip(axes, panels):
        ax.set_theta_zero_location("N")
        ax.plot(full, np.abs(mirror(data)), "o", ms=3, color="k")
        ax.plot(tt, np.abs(curves[key]), "r-", lw=1)
        ax.set_title(title, fontsize=10)
        ax.tick_params(labelsize=6)
    fig.suptitle(label, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


_CLASS_COLOURS = {"all": "k", "simple": "C0", "double": "C1", "triple": "C3", "VV": "C7",
                  "VE": "C8", "VF": "C0", "EE": "C9", "EF": "C1", "FF": "C3", "sphere": "C2"}


def plot_force_pdf(pdf, path, label=""):
    """Probability densities of f_n/<f_n> for all contacts and each class,
    log-log and lin-log (seed fig. 9 style). ``pdf`` is the long table of
    :func:`postproc.pipeline.pooled_force_pdf`."""
    plt = _plt()
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    classes = [c for c in ("all", "simple", "double", "triple", "VF", "EE", "EF", "FF", "sphere")
               if c in set(pdf["class"])]
    for ax, logx in zip(axes, (True, False)):
        for c in classes:
            d = pdf[(pdf["class"] == c) & (pdf["pdf"] > 0)
                    & (pdf["binning"] == ("log" if logx else "linear"))]
            style = "-o" if c in ("all", "simple", "double", "triple", "sphere") else ":"
            ax.plot(d["x"], d["pdf"], style, ms=3, color=_CLASS_COLOURS.get(c, None),
                    label=f"{c} (n={int(d['count'].iloc[0]) if len(d) else 0})")
        ax.set_yscale("log")
        if logx:
            ax.set_xscale("log")
        ax.set_xlabel(r"$f_n/\langle f_n\rangle$")
        ax.set_ylabel("probability density")
        ax.axvline(1, color="0.7", lw=0.5)
    axes[0].legend(fontsize=7)
    fig.suptitle(label + " (each class normalised by the mean over all contacts)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


def plot_networks(df, path, label=""):
    """Strong (f_n > <f_n>) and weak networks against eps_q: their
    anisotropies a, a_n, a_t and their shares of q/p."""
    plt = _plt()
    x, xl = _xaxis(df)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for k, col in zip(("a", "a_n", "a_t"), ("C0", "C2", "C3")):
        axes[0].plot(x, df[f"strong_{k}"], "-o", ms=3, color=col, label=f"strong {k}")
        axes[0].plot(x, df[f"weak_{k}"], "--", color=col, label=f"weak {k}")
    axes[0].axhline(0, color="0.7", lw=0.5)
    axes[0].set_ylabel("anisotropy")
    for k, col in (("strong", "C3"), ("weak", "C0"), ("wall", "0.5")):
        if f"{k}_qp" in df:
            axes[1].plot(x, df[f"{k}_qp"], "-o", ms=3, color=col, label=f"{k} network")
    axes[1].plot(x, df["q_axial_over_p"], "k-", lw=1, label="total")
    axes[1].set_ylabel(r"share of $q/p$ (axial)")
    for ax in axes:
        ax.set_xlabel(xl)
        ax.legend(fontsize=7)
    fig.suptitle(label, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


def _criterion(df):
    """(name of the criterion, its band) of a summary's contact types."""
    method = df["ct_method"].iloc[0] if "ct_method" in df else "angular"
    if method == "points":
        a = df["ct_threshold"].iloc[0]
        return f"contact points, tolerance {a:g} V/area", f"{a / 2:g} to {2 * a:g} V/area"
    if method == "footprint":
        t = df["ct_threshold"].iloc[0]
        return f"footprint threshold {t:g} d", f"{t / 2:g} d to {2 * t:g} d"
    theta = df["ct_theta_deg"].iloc[0]
    return f"angular tolerance {theta:g} deg", f"{theta / 2:g} to {2 * theta:g} deg"


def plot_contact_types(df, path, label=""):
    """Contact types of polyhedra against eps_q (seed figs. 10-12, claim 6):
    proportions of simple/double/triple contacts (bands: the criterion's
    parameter, footprint threshold or angular tolerance, halved and
    doubled), their mean normal force over the overall mean, the signed
    branch anisotropy of each pair type and each type's share of q/p."""
    plt = _plt()
    x, xl = _xaxis(df)
    fig, axes = plt.subplots(1, 4, figsize=(17, 4))
    for g in ("simple", "double", "triple"):
        c = _CLASS_COLOURS[g]
        axes[0].plot(x, df[f"ct_frac_{g}"], "-o", ms=3, color=c, label=g)
        lo, hi = df[f"ct_frac_{g}_lo"], df[f"ct_frac_{g}_hi"]
        axes[0].fill_between(x, np.minimum(lo, hi), np.maximum(lo, hi), color=c, alpha=0.15, lw=0)
        axes[1].plot(x, df[f"ct_fratio_{g}"], "-o", ms=3, color=c, label=g)
    what = _criterion(df)
    axes[0].set_ylabel(f"proportion (bands: {what[1]})")
    axes[1].axhline(1, color="0.7", lw=0.5)
    axes[1].set_ylabel(r"$\langle f_n\rangle_{type}/\langle f_n\rangle$")
    for t in ("VF", "EE", "EF", "FF"):
        c = _CLASS_COLOURS[t]
        axes[2].plot(x, df[f"ct_fabric_{t}"], "-o", ms=3, color=c, label=t)
        axes[3].plot(x, df[f"ct_qp_{t}"], "-o", ms=3, color=c, label=t)
    axes[2].axhline(0, color="0.7", lw=0.5)
    axes[2].set_ylabel("signed branch anisotropy of the type")
    axes[3].plot(x, df["q_axial_over_p"], "k-", lw=1, label="total")
    axes[3].set_ylabel(r"share of $q/p$ (axial)")
    for ax in axes:
        ax.set_xlabel(xl)
        ax.legend(fontsize=7)
    fig.suptitle(f"{label}: contact types, {what[0]}", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


TYPE_COLOURS = {"simple": "#4477aa", "double": "#ee6677", "triple": "#228833"}


def plot_slabs(panels, path, colour="force", title=""):
    """Slabs side by side (the seed's force-network figures, in 2-D): each
    panel a (label, slab dict of :func:`postproc.slab.slab`). Grain sections
    filled light grey, contacts as segments between centres, width
    proportional to f_n / <f_n> of the panel (capped at 4) and coloured by
    it (``colour="force"``) or by contact type (``colour="type"``, the
    slab's labels: simple, double, triple)."""
    # matplotlib only through _plt (the Agg backend first)
    from matplotlib.collections import LineCollection, PatchCollection, PolyCollection
    from matplotlib.patches import Circle  # idem

    plt = _plt()
    fig, axes = plt.subplots(1, len(panels), figsize=(4.6 * len(panels) + 0.8, 6.4), squeeze=False,
                             gridspec_kw={"wspace": 0.35})
    cmap = plt.get_cmap("inferno_r")
    for ax, (label, s) in zip(axes[0], panels):
        if s["polygons"]:
            ax.add_collection(PolyCollection(s["polygons"], facecolor="0.88", edgecolor="0.55", linewidths=0.4))
        centres, radii = s["discs"]
        if len(radii):
            ax.add_collection(PatchCollection([Circle(c, r) for c, r in zip(centres, radii)],
                                              facecolor="0.88", edgecolor="0.55", linewidths=0.4))
        fn, seg = np.asarray(s["fn"], float), s["segments"]
        if len(fn) and fn.mean() > 0:
            w = fn / fn.mean()
            order = np.argsort(w)
            if colour == "type" and s["labels"] is not None:
                cols = [TYPE_COLOURS.get(str(x), "0.3") for x in np.asarray(s["labels"])[order]]
            else:
                cols = cmap(np.clip(w[order] / 3, 0, 1))
            ax.add_collection(LineCollection(seg[order], colors=cols, linewidths=0.3 + 1.1 * np.clip(w[order], 0, 4),
                                             capstyle="round"))
        (x0, y0), (x1, y1) = s["extent"]
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
        ax.set_aspect("equal")
        names = "xyz"
        ax.set_xlabel(f"{names[s['axes'][0]]} (m)")
        ax.set_ylabel(f"{names[s['axes'][1]]} (m)")
        ax.set_title(f"{label}\n{len(fn)} contacts in a slab {s['thickness'] * 1e3:.0f} mm thick", fontsize=9)
    if colour == "type":
        from matplotlib.lines import Line2D  # idem

        axes[0][-1].legend(handles=[Line2D([], [], color=c, lw=2, label=k) for k, c in TYPE_COLOURS.items()],
                           fontsize=8, loc="upper right")
    else:
        sm = plt.cm.ScalarMappable(cmap=cmap, norm=plt.Normalize(0, 3))
        fig.colorbar(sm, ax=list(axes[0]), shrink=0.6, label=r"$f_n/\langle f_n\rangle$ (width too)")
    if title:
        fig.suptitle(title, fontsize=10)
    fig.savefig(path, dpi=130, bbox_inches="tight")
    plt.close(fig)
    return fig


_SAMPLE_STYLE = {"polyhedra": ("C3", "S1 polyhedra"), "spheres": ("C0", "S2 spheres")}


def _shear(df):
    return df[df["stage"] == "shear"]


def plot_report_qp(summaries, published, path):
    """q/p against eps_q for S1 and S2, one line per seed, with the
    published plateau values dashed (seed fig. 3). summaries {sample: [df]}."""
    plt = _plt()
    fig, ax = plt.subplots(figsize=(6, 4))
    for s, frames in summaries.items():
        col, lab = _SAMPLE_STYLE.get(s, ("k", s))
        for k, df in enumerate(frames):
            sh = _shear(df)
            ax.plot(sh["eps_q"], sh["q_over_p"], "-", color=col, lw=1.2, alpha=0.8,
                    label=lab if k == 0 else None)
        if published.get(s) is not None:
            ax.axhline(published[s], color=col, ls="--", lw=1, label=f"{lab}, published plateau")
    ax.set_xlabel(r"$\varepsilon_q$")
    ax.set_ylabel("q/p")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


def _mean_over_seeds(frames, col):
    grid = None
    curves = []
    for df in frames:
        sh = _shear(df)
        x, y = sh["eps_q"].to_numpy(float), sh[col].to_numpy(float)
        if grid is None:
            grid = x
        ok = np.isfinite(x) & np.isfinite(y)
        if ok.sum() >= 2:
            o = np.argsort(x[ok])
            curves.append(np.interp(grid, x[ok][o], y[ok][o], left=np.nan, right=np.nan))
    if not curves:
        return np.array([]), np.array([])
    return grid, np.nanmean(curves, axis=0)


def plot_report_anisotropies(summaries, path):
    """a, a_l, a_n, a_t against eps_q, S1 and S2 side by side (mean over
    seeds; seed figs. 6 and 7)."""
    plt = _plt()
    samples = [s for s in ("polyhedra", "spheres") if summaries.get(s)]
    fig, axes = plt.subplots(1, max(len(samples), 1), figsize=(5.5 * max(len(samples), 1), 4),
                             sharey=True, squeeze=False)
    for ax, s in zip(axes[0], samples):
        for k, col in zip(("a", "a_l", "a_n", "a_t"), ("C0", "C1", "C2", "C3")):
            x, y = _mean_over_seeds(summaries[s], k)
            ax.plot(x, y, "-o", ms=2.5, color=col, label=k)
        ax.axhline(0, color="0.7", lw=0.5)
        ax.set_title(_SAMPLE_STYLE[s][1] + f" ({len(summaries[s])} seed(s))", fontsize=10)
        ax.set_xlabel(r"$\varepsilon_q$")
        ax.legend(fontsize=8)
    axes[0][0].set_ylabel("anisotropy")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


def plot_report_sff(summaries, path):
    """q_axial/p against (2/5)(a+a_l+a_n+a_t), every shear snapshot of
    every seed, with the line of equality (seed fig. 8)."""
    plt = _plt()
    fig, ax = plt.subplots(figsize=(4.8, 4.5))
    top = 0.1
    for s, frames in summaries.items():
        col, lab = _SAMPLE_STYLE.get(s, ("k", s))
        for k, df in enumerate(frames):
            sh = _shear(df)
            ax.plot(sh["sff"], sh["q_axial_over_p"], "o", ms=3, color=col, alpha=0.7,
                    label=lab if k == 0 else None)
            top = max(top, np.nanmax(np.r_[sh["sff"], sh["q_axial_over_p"], 0]))
    ax.plot([0, top * 1.05], [0, top * 1.05], "k-", lw=0.8, label="equality")
    ax.set_xlabel(r"$\frac{2}{5}(a+a_l+a_n+a_t)$")
    ax.set_ylabel(r"$q/p$ (signed, axial)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


def plot_report_polar(polar, path):
    """P_Omega(theta) and <l>(theta) with their harmonic fits, one row per
    sample (seed figs. 5 and 7). polar {sample: (AngularFunctions, fits, caption)}."""
    plt = _plt()
    fig, axes = plt.subplots(len(polar), 2, subplot_kw={"projection": "polar"},
                             figsize=(7, 3.4 * len(polar)), squeeze=False)
    tt = np.linspace(0, 2 * np.pi, 361)
    for row, (s, (af, fits, caption)) in zip(axes, polar.items()):
        th = af.centers
        full = np.concatenate([th, np.pi - th[::-1], np.pi + th, 2 * np.pi - th[::-1]])
        curves = harmonic_curves(fits, tt)
        for ax, key, data, title in ((row[0], "P", af.P, r"$P_\Omega(\theta)$"),
                                     (row[1], "l", af.l_mean, r"$\langle\ell\rangle(\theta)$")):
            ax.set_theta_zero_location("N")
            m = np.concatenate([data, data[::-1], data, data[::-1]])
            ax.plot(full, m, "o", ms=3, color="k")
            ax.plot(tt, curves[key], "r-", lw=1)
            ax.set_title(f"{_SAMPLE_STYLE.get(s, ('', s))[1]}: {title}\n{caption}", fontsize=8)
            ax.tick_params(labelsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


def plot_front(runs, path):
    """Wall time against error, one panel per sample: the largest of the
    plateau errors of q/p, a, a_n, a_t against the reference run (big
    markers, Pareto points filled) and each error (small markers), with the
    reference run's own one-seed noise (2 batch-means s.e. of q/p) shaded."""
    plt = _plt()
    samples = list(dict.fromkeys(runs["sample"]))
    fig, axes = plt.subplots(1, len(samples), figsize=(6 * len(samples), 4.5), squeeze=False)
    marks = {"err_q_over_p": ("s", "q/p"), "err_a": ("^", "a"), "err_a_n": ("v", "a_n"),
             "err_a_t": ("D", "a_t")}
    for ax, s in zip(axes[0], samples):
        g = runs[runs["sample"] == s]
        x = g["wall_seconds"].to_numpy(float)
        for col, (m, lab) in marks.items():
            ax.plot(x, g[col], m, ms=4, alpha=0.5, label=lab)
        ax.scatter(x, g["err_max"], s=60, facecolors=np.where(g["pareto"], "k", "none"),
                   edgecolors="k", zorder=3, label="largest (filled: Pareto)")
        for xi, yi, name in zip(x, g["err_max"], g["run"]):
            ax.annotate(name, (xi, yi), fontsize=6, xytext=(3, 3), textcoords="offset points")
        ref = g[g["ref"]]
        if len(ref) and np.isfinite(ref["q_over_p_se"].iloc[0]):
            ax.axhspan(0, 2 * ref["q_over_p_se"].iloc[0], color="0.85", zorder=0,
                       label="2 s.e. of the reference q/p (one seed)")
        ax.set_xscale("log")
        ax.set_xlabel("wall time of the run (s)")
        ax.set_ylabel("|plateau - reference plateau|")
        ax.set_title(s, fontsize=10)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


TREND_PANELS = (("qp_plateau", "q/p plateau"), ("qp_peak", "q/p peak"), ("psi_peak_deg", "dilatancy angle at peak (deg)"),
                ("a", "a"), ("a_n", "a_n"), ("a_t", "a_t"), ("z", "z"), ("phi_iso", "solid fraction (isotropic)"),
                ("ct_simple", "simple contacts (fraction)"))


def plot_front_trends(points, fits, path, kappa_d, inertial_d):
    """The kappa and I trends of the front, one row per sample, one panel per
    quantity (kappa_d, inertial_d: the default point, the fit's units;
    postproc.study.front.FRONT_KAPPA, FRONT_I; a sample whose fit rows name
    their own, columns ``kappa_d`` and ``inertial_d``, uses those): point means over seeds with
    their 95 % intervals against
    x = kappa_d / kappa (kappa sweep at I_d, circles) and x = I / I_d (I sweep
    at kappa_d, squares), the fitted lines X0 + A x + B and X0 + A + B x
    (postproc.study.front.fit_rigid_quasistatic, in the form fit_table chose:
    x^alpha and x^beta) and the extrapolated X0 at x = 0
    (star, with its interval); other points (the corner) as crosses."""
    plt = _plt()
    samples = list(dict.fromkeys(points["sample"]))
    panels = [p for p in TREND_PANELS if p[0] in points]
    fig, axes = plt.subplots(len(samples), len(panels), figsize=(2.6 * len(panels), 2.7 * len(samples)),
                             squeeze=False)
    k_all, i_all = kappa_d, inertial_d
    for r, s in enumerate(samples):
        fs = fits[fits["sample"] == s]
        kappa_d, inertial_d = ((float(fs["kappa_d"].iloc[0]), float(fs["inertial_d"].iloc[0]))
                               if "kappa_d" in fs and len(fs) else (k_all, i_all))
        g = points[points["sample"] == s]
        base_n = g["n_particles"].mode().iloc[0] if "n_particles" in g else None
        if base_n is not None:
            g = g[g["n_particles"] == base_n]
        kap = np.isclose(g["inertial_number"], inertial_d)
        rate = np.isclose(g["kappa"], kappa_d)
        for c, (q, label) in enumerate(panels):
            ax = axes[r, c]
            for sel, x, m, lab in ((kap, kappa_d / g["kappa"], "o", "x = κd/κ"),
                                   (rate & ~kap, g["inertial_number"] / inertial_d, "s", "x = I/Id"),
                                   (~kap & ~rate, kappa_d / g["kappa"], "x", "corner (x = κd/κ)")):
                if sel.any():
                    ax.errorbar(x[sel], g.loc[sel, q], yerr=g.loc[sel, q + "_ci"].fillna(0), fmt=m,
                                ms=4, capsize=2, label=lab)
            if not np.isfinite(g[q].to_numpy(float)).any():     # e.g. contact types of spheres
                ax.set_axis_off()
                continue
            f = fits[(fits["sample"] == s) & (fits["quantity"] == q)]
            if len(f) and np.isfinite(f["X0"].iloc[0]):
                f = f.iloc[0]
                xmax = max(float(np.max(kappa_d / g["kappa"])), float(np.max(g["inertial_number"] / inertial_d)))
                xs = np.linspace(0, 1.03 * xmax, 64)
                ax.plot(xs, f["X0"] + f["A"] * xs ** f["alpha"] + f["B"], "C0-", lw=0.8)
                ax.plot(xs, f["X0"] + f["A"] + f["B"] * xs ** f["beta"], "C1-", lw=0.8)
                ax.errorbar([0], [f["X0"]], yerr=[f["ci_X0"]] if np.isfinite(f["ci_X0"]) else None,
                            fmt="*", color="k", ms=8, capsize=2, label="κ→∞, I→0")
            ax.set_title(f"{s} (κd {kappa_d:g}, Id {inertial_d:g}): {label}", fontsize=7)
            ax.tick_params(labelsize=7)
            if r == len(samples) - 1:
                ax.set_xlabel("κd/κ or I/Id (default at 1)", fontsize=7)
            if r == 0 and c == 0:
                ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return fig


#: the size front's panels: quantity (the count's columns without their
#: "<count>:" prefix; every count is drawn in the same panel) and title
SIZE_PANELS = (("q_over_p", f"{column_label('q_over_p')} plateau"),
               *((k, column_label(k)) for k in ("a", "a_l", "a_n", "a_t")),
               ("sff_rel_residual", "(q/p − (2/5)Σa)/(q/p)"), ("z", column_label("z")), ("phi_iso", "solid fraction"),
               *((k, f"{column_label(k)} (S1)") for k in ("ct_frac_triple", "ct_fratio_FF", "ct_fabric_VF",
                                                          "ct_fabric_EE")))


def plot_size_front(table, path, published=None):
    """The size front: one panel per quantity of SIZE_PANELS, its mean over
    seeds with the 95 % interval against the number of grains N (log
    axis), S1 (circles; per contact count: circles for the first count,
    squares, triangles for the next) and S2 (diamonds), each with its
    straight line in N^(-1/3) through the means (:func:`postproc.study.
    sizefront.size_table`: the ``extrapolated`` and ``slope`` columns) and
    the published value dashed. ``table`` is the long table of size_table;
    ``published`` {(sample, quantity): value or None}. Returns what was
    drawn: [(panel title, series label, N (K,), means (K,))]."""
    plt = _plt()
    from matplotlib.ticker import NullFormatter

    published = published or {}
    drawn = []
    panels = [(q, lab) for q, lab in SIZE_PANELS
              if any(t == q or t.endswith(":" + q) for t in table["quantity"].unique())]
    ncol = 4
    nrow = max(1, -(-len(panels) // ncol))
    fig, axes = plt.subplots(nrow, ncol, figsize=(3.1 * ncol, 2.6 * nrow), squeeze=False)
    markers = ("o", "s", "^", "v")
    for k, (q, title) in enumerate(panels):
        ax = axes[k // ncol, k % ncol]
        series = [t for t in table["quantity"].unique() if t == q or t.endswith(":" + q)]
        for sample, colour in (("polyhedra", "C0"), ("spheres", "C3")):
            for j, name in enumerate(sorted(series)):
                g = table[(table["quantity"] == name) & (table["sample"] == sample)].sort_values("n_particles")
                if not len(g) or not np.isfinite(g["mean"].to_numpy(float)).any():
                    continue
                n = g["n_particles"].to_numpy(float)
                m = g["mean"].to_numpy(float)
                err = np.vstack([m - g["ci_low"].to_numpy(float), g["ci_high"].to_numpy(float) - m])
                lab = ("S1" if sample == "polyhedra" else "S2") + (f" {name.split(':')[0]}" if ":" in name else "")
                marker = "D" if sample == "spheres" else markers[j % len(markers)]
                ax.errorbar(n, m, yerr=np.nan_to_num(err), fmt=marker, color=colour if j == 0 else f"C{j + 1}",
                            ms=4, capsize=2, label=lab)
                drawn.append((title, lab, n, m))
                y0, c = g["extrapolated"].iloc[0], g["slope"].iloc[0]
                if np.isfinite(y0) and np.isfinite(c):
                    xs = np.geomspace(n.min() / 1.5, 4e4, 50)
                    ax.plot(xs, y0 + c * xs ** (-1 / 3), "-", lw=0.7, color=colour if j == 0 else f"C{j + 1}")
            pub = published.get((sample, q))
            if pub is not None and np.isfinite(pub):
                ax.axhline(pub, color=colour, ls="--", lw=0.8)
        ax.set_xscale("log")
        ns = sorted({int(x) for x in table["n_particles"]})
        if ns:                                                # the sizes run, in plain numbers
            ax.set_xticks(ns)
            ax.set_xticklabels([str(x) for x in ns])
            ax.xaxis.set_minor_formatter(NullFormatter())
            ax.set_xlim(ns[0] / 1.6, ns[-1] * 1.6)
        ax.set_title(title, fontsize=8)
        ax.tick_params(labelsize=7)
        ax.set_xlabel("N (grains per sample)", fontsize=7)
        if k == 0 or len(series) > 1:
            ax.legend(fontsize=6)
    for k in range(len(panels), nrow * ncol):
        axes[k // ncol, k % ncol].set_axis_off()
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return drawn


SHAPE_PANELS = (("q_over_p", f"{column_label('q_over_p')} plateau"),
                *((k, column_label(k)) for k in ("a", "a_l", "a_n", "a_t", "z")), ("phi_iso", "solid fraction"),
                *((k, column_label(k)) for k in ("ct_frac_simple", "ct_frac_double", "ct_frac_triple", "ct_fabric_VF",
                                          "ct_fabric_EE")))


def plot_shape_front(table, labels, path):
    """The shape front: one panel per quantity of SHAPE_PANELS, S1's mean
    over seeds with its 95 % interval for each study (x = the study, in the
    order of ``labels``), one series per contact count for the count
    quantities (circles, squares, triangles), and the paper's value dashed.
    ``table`` is :func:`postproc.study.shapefront.shape_table`'s. Returns
    what was drawn: [(panel title, series label, means (len(labels),))]."""
    plt = _plt()
    s1 = table[table["sample"] == "polyhedra"]
    panels = [(q, t) for q, t in SHAPE_PANELS if any(x == q or x.endswith(":" + q) for x in s1["quantity"])]
    ncol = 4
    nrow = max(1, -(-len(panels) // ncol))
    fig, axes = plt.subplots(nrow, ncol, figsize=(3.1 * ncol, 2.6 * nrow), squeeze=False)
    drawn = []
    x = np.arange(len(labels))
    for k, (q, title) in enumerate(panels):
        ax = axes[k // ncol, k % ncol]
        rows = s1[(s1["quantity"] == q) | s1["quantity"].str.endswith(":" + q)].sort_values("quantity")
        for j, (_, r) in enumerate(rows.iterrows()):
            m = np.array([r[f"mean:{lab}"] for lab in labels], float)
            err = np.vstack([m - np.array([r[f"low:{lab}"] for lab in labels], float),
                             np.array([r[f"high:{lab}"] for lab in labels], float) - m])
            name = r["quantity"].split(":")[0] if ":" in r["quantity"] else "S1"
            ax.errorbar(x + 0.12 * (j - (len(rows) - 1) / 2), m, yerr=np.nan_to_num(err), fmt="os^v"[j % 4],
                        color=f"C{j}", ms=4, capsize=2, label=name)
            drawn.append((title, name, m))
        paper = rows["paper"].to_numpy(float)
        if len(paper) and np.isfinite(paper[0]):
            ax.axhline(paper[0], color="k", ls="--", lw=0.8, label="paper")
        ax.set_xticks(x)
        ax.set_xticklabels(labels, fontsize=6)
        ax.set_xlim(-0.5, len(labels) - 0.5)
        ax.set_title(title + " (S1)", fontsize=8)
        ax.tick_params(labelsize=7)
        if len(rows) > 1 or k == 0:
            ax.legend(fontsize=6)
    for k in range(len(panels), nrow * ncol):
        axes[k // ncol, k % ncol].set_axis_off()
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return drawn


def plot_analysis_front(table, path):
    """Analysis estimators: RMS error (largest over a, a_l, a_n, a_t)
    against contacts per set, and time per set against RMS error."""
    plt = _plt()
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for name, g in table.groupby("estimator", sort=False):
        axes[0].loglog(g["n"], g["rms_max"], "-o", ms=3, label=name)
        axes[1].loglog(g["seconds"], g["rms_max"], "-o", ms=3, label=name)
    n = np.array(sorted(set(table["n"])))
    t = table[table["estimator"] == "tensors"].sort_values("n")
    if len(t):
        axes[0].loglog(n, t["rms_max"].iloc[0] * np.sqrt(n[0] / n), "k:", lw=1, label=r"$\propto n^{-1/2}$")
    axes[0].set_xlabel("contacts per set")
    axes[0].set_ylabel("RMS error (largest of a, a_l, a_n, a_t)")
    axes[1].set_xlabel("time per set (s)")
    axes[1].set_ylabel("RMS error")
    for ax in axes:
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


def plot_group_polar(data, caption, path):
    """Polar densities P_Omega(theta) of the branch vectors of simple and
    triple contacts (the paper's claim-6 figure), theta from the compression
    axis (up), mirrored to the full circle. data {group: AngularFunctions}."""
    plt = _plt()
    fig, ax = plt.subplots(subplot_kw={"projection": "polar"}, figsize=(4.6, 4.6))
    ax.set_theta_zero_location("N")
    for g, af in data.items():
        th = af.centers
        full = np.concatenate([th, np.pi - th[::-1], np.pi + th, 2 * np.pi - th[::-1]])
        m = np.concatenate([af.P, af.P[::-1], af.P, af.P[::-1]])
        ax.plot(np.append(full, full[0]), np.append(m, m[0]), "-o", ms=3,
                color=_CLASS_COLOURS.get(g, None), label=g)
    tt = np.linspace(0, 2 * np.pi, 181)
    ax.plot(tt, np.full_like(tt, 1 / (4 * np.pi)), "k:", lw=0.8, label="isotropic")
    ax.set_title(f"branch directions $P_\\Omega(\\theta)$\n{caption}", fontsize=8)
    ax.tick_params(labelsize=6)
    ax.legend(fontsize=7, loc="lower right", bbox_to_anchor=(1.15, -0.1))
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


def plot_footprint(extents, threshold, path, label=""):
    """Distributions of the footprint extents L1/d and L2/d (log bins) of
    the force-bearing polyhedra pairs, with the threshold t and t/2, 2t:
    simple L1 < t, double L1 >= t > L2, triple L2 >= t. extents (P, 2)
    L1 >= L2 over the pair size (NaN rows: no overlap, left out)."""
    plt = _plt()
    x = np.asarray(extents, float)
    x = x[np.isfinite(x).all(axis=1) & (x[:, 1] > 0)]
    fig, ax = plt.subplots(figsize=(6.4, 4))
    if not len(x):       # no pair overlaps (a rigid Contact Dynamics packing): nothing to bin
        ax.text(0.5, 0.5, "no overlapping force-bearing pair: no footprint", ha="center", va="center",
                transform=ax.transAxes)
        ax.set_axis_off()
        fig.savefig(path, dpi=120)
        plt.close(fig)
        return fig
    bins = np.geomspace(max(x.min(), 1e-5), x.max() * 1.0001, 41)
    for j, name, c in ((0, "$L_1/d$ (simple below t)", "C0"), (1, "$L_2/d$ (triple above t)", "C3")):
        h, _ = np.histogram(x[:, j], bins)
        ax.stairs(h / (len(x) * np.diff(np.log(bins))), bins, color=c, label=name)
    for f, ls in ((0.5, ":"), (1.0, "-"), (2.0, ":")):
        ax.axvline(threshold * f, color="k", ls=ls, lw=0.8)
    ax.set_xscale("log")
    ax.set_xlabel(f"footprint extent / pair size d (lines: t = {threshold:g}, t/2, 2t)")
    ax.set_ylabel("density per unit ln(L/d)")
    ax.set_title(f"{label}: {len(x)} contacts", fontsize=9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig


def plot_leanings_by_tolerance(tolerances, leanings, path, criterion="", unit=""):
    """The stability test of claim 6's leanings: every seed's signed branch
    anisotropy of vertex-face and edge-edge contacts (the anisotropy a of the
    seed's P_Omega(theta) fit, restricted to one contact type, i.e.
    (5/2)(F_3 - F_1) of that type's fabric tensor,
    :func:`postproc.pertype.class_statistics`; negative is lateral, toward
    the minor principal direction) against the contact-type criterion's
    tolerance, one panel per type.

    tolerances: (T,) tolerance values (the criterion's units, e.g. tau x the
    radius for LMGC90's band), drawn on a log axis; leanings: {"VF": (T, S),
    "EE": (T, S)} steady-window means per tolerance and seed (S seeds, the
    same seeds in every row; NaN skipped). Thin grey lines join one seed
    across tolerances; black: the mean over seeds with its 95 % Student's t
    interval. Writes a PNG to path.
    """
    plt = _plt()
    tol = np.asarray(tolerances, float)
    fig, axes = plt.subplots(1, len(leanings), figsize=(4.4 * len(leanings), 3.8), sharey=True, squeeze=False)
    for ax, (name, values) in zip(axes[0], leanings.items()):
        v = np.asarray(values, float)
        ax.plot(tol, v, "-", color="0.75", lw=0.7)
        est = [plateau_estimate([[x] for x in row]) for row in v]
        m = np.array([e.mean for e in est])
        h = np.array([e.ci()[1] - e.mean for e in est])
        ax.errorbar(tol, m, yerr=h, fmt="-o", color="k", capsize=3, ms=4, label="mean, 95 % over seeds")
        ax.axhline(0, color="C3", lw=0.8)
        ax.set_xscale("log")
        ax.set_xticks(tol)
        ax.set_xticklabels([f"{x:g}" for x in tol])
        ax.minorticks_off()
        ax.set_xlabel(f"tolerance{(' ' + unit) if unit else ''}")
        ax.set_title(f"{name} leaning, {v.shape[1]} seeds", fontsize=10)
        ax.legend(fontsize=7, loc="lower left")
    axes[0][0].set_ylabel("signed branch anisotropy (negative: lateral)")
    fig.suptitle(f"claim 6 against the tolerance of {criterion}" if criterion else "claim 6 against the tolerance",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return fig
