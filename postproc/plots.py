"""Figures of the seed paper from analysis results (matplotlib, Agg)."""
from __future__ import annotations

import numpy as np

from .angular import AngularFunctions, harmonic_curves


def _plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

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


_CLASS_COLOURS = {"all": "k", "simple": "C0", "double": "C1", "triple": "C3", "VV": "C7",
                  "VE": "C8", "VF": "C0", "EE": "C9", "EF": "C1", "FF": "C3", "sphere": "C2"}


def plot_force_pdf(pdf, path, label=""):
    """Probability densities of f_n/<f_n> for all contacts and each class,
    log-log and lin-log (seed fig. 9 style). ``pdf`` is the long table of
    :func:`postproc.cli.pooled_force_pdf`."""
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


def plot_contact_types(df, path, label=""):
    """Contact types of polyhedra against eps_q (seed figs. 10-12, claim 6):
    proportions of simple/double/triple contacts (bands: tolerance halved
    and doubled), their mean normal force over the overall mean, the signed
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
    theta = df["ct_theta_deg"].iloc[0]
    axes[0].set_ylabel(f"proportion (bands: {theta / 2:g} to {2 * theta:g} deg)")
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
    fig.suptitle(f"{label}: contact types at {theta:g} deg", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
