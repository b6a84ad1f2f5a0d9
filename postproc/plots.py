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
