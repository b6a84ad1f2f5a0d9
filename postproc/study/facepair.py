"""Do face-face contacts vanish as the grains stiffen? The face-pair tilt
against the overlap thickness, at kappa = 300, 1000, 3000 and 10 000.

    python -m yade_scripts.campaign.facepair_sweep [--out runs/facepair] [--jobs 2] [--from-eps1 0.1]
        [--figure docs/figures/facepair-tilt.png]
    postproc investigate facepair-tilt OUT DUMP.h5 [DUMP.h5 ...] [--from-eps1 0.1] [--figure PNG]

The first runs the ``facepair`` plan of :mod:`yade_scripts.campaign.sweeps` (S1 on
the default preset, 200 grains, I = 5e-3, sheared to eps_1 = 0.15, seeds
1-3; a seed starts from the same grains and positions at every kappa;
finished runs are not run again), then analyses its dumps as the second
analyses any (:func:`write_facepair`). On each shear snapshot with eps_1 >= --from-eps1, every
polyhedron pair gets (:mod:`postproc.facetilt`) its face-pair tilt phi and
rise min(L_A, L_B) sin(phi), its overlap's mean thickness h = V / area
(dumped by the kernel), and its class under the overlap-based point count
(``points``, alpha = 0.1) and LMGC90's common plane (``commonplane``,
tau = 0.1).

Writes OUT/facepair_tilt.csv.gz (one row per contact and snapshot),
OUT/facepair_tilt.csv (per kappa and seed: contacts, the medians of h / d,
of tau ref / d and of the smaller contact face's diameter, the quartiles
and 15th percentile of phi (the face-face tolerance at which a tilt
criterion gives the paper's triple share of 0.15), the fractions with phi
below 1, 2, 5 and 10 deg, the triple share of each criterion, and the
shares whose rise is below h (the point count's scale) and below tau ref
(the common plane's)), OUT/facepair_tilt.md (per kappa, the main columns as
mean [95 % Student's t interval] over seeds, and each kappa's paired
difference from the stiffest; a last row gives the tilt of random contacts
between the same grains, the geometric chance), and the figure: (a) phi against h / d for
every contact, coloured by kappa; (b) the distribution of phi per kappa;
(c) the distribution of h / d per kappa; (d) for the tilt criterion
"face-face when phi < theta", its face-face share against its move at
theta / 2 and 2 theta, per kappa.
If phi's distribution does not lose its flush pairs as kappa grows while h
shrinks, the face-face contacts of the grains do not vanish as they stiffen:
only a count whose band is the overlap loses them.
"""
from __future__ import annotations

import os

import numpy as np
import pandas as pd

from ..classify import Classifier
from ..commonplane import DEFAULT_NEIGHBOR
from ..contactpoints import DEFAULT_ALPHA
from ..contactset import lookup
from ..contacttypes import shape_tables
from ..errors import InputError
from ..facetilt import face_pair_tilt, tolerance_moves
from ..footprint import pair_size
from ..pipeline import open_source
from ..schema import DumpReader
from ..statistics import plateau_estimate
from .typeskappa import shear_snapshots

THRESHOLDS_DEG = (1.0, 2.0, 5.0, 10.0)
STABILITY = 0.03                                   # the largest move allowed at half and twice a tolerance
TOLERANCES_DEG = np.logspace(-1, 1.5, 126)         # 0.1 to 31.6 deg


def contacts_of(dump, from_eps1):
    """The face-pair tilt and overlap of every polyhedron pair of a dump's
    shear snapshots.

    Parameters
    ----------
    dump : str
        A kernel S1 dump (its parameters hold kappa and seed; its contacts
        the overlap volume and footprint area).
    from_eps1 : float
        The least eps_1 of the snapshots used.

    Returns
    -------
    pandas.DataFrame
        One row per polyhedron pair and shear snapshot with eps_1 >=
        from_eps1: kappa, seed, step, eps_1, phi (deg), tilt1/tilt2 (deg),
        rise / d, h / d, the smaller contact face's diameter / d, tau ref /
        d, and the pair type under each criterion (``points``,
        ``commonplane``); d the pair's size (the harmonic mean of the two
        grains' d, the kernel's d_pair).

    Raises
    ------
    InputError
        No shear snapshot with eps_1 >= from_eps1, or one that cannot be
        read.
    """
    with DumpReader(dump) as r:
        kappa, seed = float(r.parameters["kappa"]), int(r.parameters["seed"])
    count, snaps, close, shapes = open_source(dump)
    rows = []
    try:
        points = Classifier(shapes, "points")
        plane = Classifier(shapes, "commonplane")
        tables = points.tables
        radius = plane.plane_tables.radius          # the common plane's ref: centre to extreme vertex
        for snap, eps1 in shear_snapshots(dump, snaps, from_eps1):
            lab_p = points.classify(snap, variants=False)
            lab_c = plane.classify(snap, variants=False)
            poly = lab_p.poly
            i1, i2 = lookup(snap.id1[poly], snap.body_ids), lookup(snap.id2[poly], snap.body_ids)
            s1, s2 = snap.shape_index[i1], snap.shape_index[i2]
            ft = face_pair_tilt(tables, s1, snap.orientations[i1], s2, snap.orientations[i2], snap.normal[poly])
            area = np.asarray(snap.footprint_area, float)[poly]
            vol = np.asarray(snap.overlap, float)[poly]
            h = np.where(area > 0, vol / np.where(area > 0, area, 1.0), np.nan)
            d = pair_size(snap.sizes[i1], snap.sizes[i2])
            rows.append(pd.DataFrame({
                "kappa": kappa, "seed": seed, "step": snap.step, "eps_1": eps1,
                "phi_deg": np.degrees(ft.tilt), "tilt1_deg": np.degrees(ft.tilt1),
                "tilt2_deg": np.degrees(ft.tilt2), "rise_d": ft.rise / d, "h_d": h / d,
                "face_d": np.minimum(ft.size1, ft.size2) / d,
                "band_cp_d": DEFAULT_NEIGHBOR * np.minimum(radius[s1], radius[s2]) / d,
                "points": lab_p.labels[poly], "commonplane": lab_c.labels[poly]}))
    finally:
        close()
    if not rows:
        raise InputError(f"{dump}: no shear snapshot with eps_1 >= {from_eps1}")
    return pd.concat(rows, ignore_index=True)


def random_tilts(dump, n=20000, seed=0):
    """The face-pair tilt of random contacts between the dump's grains:
    shapes drawn uniformly, orientations uniform (normalised Gaussian
    quaternions), normals uniform on the sphere. The geometric chance of a
    flush pair, against which the packing's selection shows.

    Parameters
    ----------
    dump : str
        A polyhedra dump (its shapes are used).
    n : int
        Random contacts.
    seed : int
        Seed of the draws.

    Returns
    -------
    ndarray
        The n tilts phi (deg).
    """
    count, snaps, close, shapes = open_source(dump)
    close()
    tables = shape_tables(*shapes)
    rng = np.random.default_rng(seed)
    S = len(tables.vertices)
    normal = rng.normal(size=(n, 3))
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    ft = face_pair_tilt(tables, rng.integers(0, S, n), rng.normal(size=(n, 4)), rng.integers(0, S, n),
                        rng.normal(size=(n, 4)), normal)
    return np.degrees(ft.tilt)


def summary(df):
    """The per-run table of facepair_tilt.csv.

    Parameters
    ----------
    df : pandas.DataFrame
        Rows of :func:`contacts_of`.

    Returns
    -------
    pandas.DataFrame
        One row per kappa and seed: the table's columns (see the module
        docstring; tilts in deg, lengths over d, shares dimensionless).
    """
    out = []
    for (kappa, seed), g in df.groupby(["kappa", "seed"]):
        phi = g["phi_deg"].to_numpy()
        row = {"kappa": kappa, "seed": seed, "snapshots": g["step"].nunique(), "contacts": len(g),
               "h_d_median": float(np.nanmedian(g["h_d"])),
               "band_cp_d_median": float(np.median(g["band_cp_d"])),
               "face_d_median": float(np.median(g["face_d"])),
               "phi_q25": float(np.percentile(phi, 25)), "phi_median": float(np.median(phi)),
               "phi_q75": float(np.percentile(phi, 75)),
               # the tilt below which 15 % of the contacts lie: the face-face
               # tolerance at which a tilt criterion gives the paper's triple share
               "phi_q15": float(np.percentile(phi, 15))}
        for t in THRESHOLDS_DEG:
            row[f"phi_below_{t:g}"] = float(np.mean(phi < t))
        F, move = tolerance_moves(phi, TOLERANCES_DEG)
        ok = move <= STABILITY
        # the largest face-face share a stable tilt criterion gives, and the
        # move of the one that gives the paper's 0.15
        row["stable_share_max"] = float(F[ok].max()) if ok.any() else 0.0
        _, m15 = tolerance_moves(phi, np.array([row["phi_q15"]]))
        row["move_at_015"] = float(m15[0])
        row["triple_points"] = float(np.mean(g["points"] == "FF"))
        row["triple_commonplane"] = float(np.mean(g["commonplane"] == "FF"))
        row["rise_below_h"] = float(np.mean(g["rise_d"] < g["h_d"]))
        row["rise_below_band_cp"] = float(np.mean(g["rise_d"] < g["band_cp_d"]))
        out.append(row)
    return pd.DataFrame(out)


COLUMNS = {  # column: (heading, digits)
    "h_d_median": ("h/d, median", None), "phi_median": ("φ median (deg)", 1),
    "phi_q15": ("φ of the lowest 15 % (deg)", 1), "phi_below_2": ("φ < 2°", 3),
    "phi_below_5": ("φ < 5°", 3), "move_at_015": ("move of φ < θ at share 0.15", 3),
    "stable_share_max": ("largest share with move ≤ 0.03", 3), "rise_below_h": ("rise < h", 4),
    "rise_below_band_cp": ("rise < τ ref", 3), "triple_points": ("triple, point count", 3),
    "triple_commonplane": ("triple, common plane", 3)}


def _est(values):
    """Mean over seeds with its 95 % Student's t interval (one value per seed)."""
    return plateau_estimate([[v] for v in values])


def _cell(e, digits):
    if digits is None:
        lo, hi = e.ci()
        return f"{e.mean:.2e} [{lo:.2e}, {hi:.2e}]" if np.isfinite(lo) else f"{e.mean:.2e}"
    return e.text(digits)


def over_seeds(tab):
    """Means over seeds per kappa.

    Parameters
    ----------
    tab : pandas.DataFrame
        Rows of :func:`summary`.

    Returns
    -------
    list of dict
        Per kappa: kappa, seeds, contacts, and for every column c of
        :data:`COLUMNS` its :class:`postproc.statistics.Estimate` over
        seeds (mean and 95 % interval) and ``c_minus_stiffest``, the
        paired difference (same seed) from the stiffest kappa.
    """
    stiff = tab[tab["kappa"] == tab["kappa"].max()].set_index("seed")
    rows = []
    for kappa, g in tab.groupby("kappa"):
        g = g.set_index("seed")
        row = {"kappa": kappa, "seeds": len(g), "contacts": int(g["contacts"].sum())}
        for c in COLUMNS:
            row[c] = _est(g[c].to_numpy())
            common = g.index.intersection(stiff.index)
            row[f"{c}_minus_stiffest"] = _est((g.loc[common, c] - stiff.loc[common, c]).to_numpy())
        rows.append(row)
    return rows


def markdown(tab, random_phi=None):
    """The text of facepair_tilt.md.

    Parameters
    ----------
    tab : pandas.DataFrame
        Rows of :func:`summary`.
    random_phi : ndarray, optional
        Tilts of random contacts (:func:`random_tilts`, deg): a last row
        of the first table.

    Returns
    -------
    str
        Markdown: per kappa the main columns over seeds (:func:`over_seeds`),
        then each kappa's paired difference from the stiffest.
    """
    rows = over_seeds(tab)
    stiffest = max(r["kappa"] for r in rows)
    head = "| κ | seeds | contacts | " + " | ".join(h for h, _ in COLUMNS.values()) + " |"
    lines = [head, "|" + "---|" * (3 + len(COLUMNS))]
    for r in rows:
        lines.append(f"| {r['kappa']:g} | {r['seeds']} | {r['contacts']} | "
                     + " | ".join(_cell(r[c], d) for c, (_, d) in COLUMNS.items()) + " |")
    if random_phi is not None:
        cells = {"phi_median": f"{np.median(random_phi):.1f}", "phi_q15": f"{np.percentile(random_phi, 15):.1f}",
                 "phi_below_2": f"{np.mean(random_phi < 2):.4f}", "phi_below_5": f"{np.mean(random_phi < 5):.4f}"}
        lines.append(f"| random orientations | | {len(random_phi)} | "
                     + " | ".join(cells.get(c, "") for c in COLUMNS) + " |")
    lines += ["", f"Paired by seed, each κ minus κ = {stiffest:g} (mean [95 % interval]):", "",
              "| κ | " + " | ".join(h for h, _ in COLUMNS.values()) + " |", "|" + "---|" * (1 + len(COLUMNS))]
    for r in rows:
        if r["kappa"] != stiffest:
            lines.append(f"| {r['kappa']:g} | "
                         + " | ".join(_cell(r[f"{c}_minus_stiffest"], d) for c, (_, d) in COLUMNS.items())
                         + " |")
    return "\n".join(lines) + "\n"


def figure(df, tab, path, random_phi=None):
    """The figure (PNG): (a) phi against h / d for every contact, coloured
    by kappa; (b) the distribution of phi per kappa; (c) that of h / d;
    (d) the face-face share of the tilt criterion "phi < theta" against its
    move at theta / 2 and 2 theta.

    Parameters
    ----------
    df : pandas.DataFrame
        Rows of :func:`contacts_of`.
    tab : pandas.DataFrame
        Rows of :func:`summary` (not used in the drawing).
    path : str
        The PNG to write (its folder is made).
    random_phi : ndarray, optional
        Tilts of random contacts (deg), drawn in (b).

    Returns
    -------
    None
    """
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    kappas = sorted(df["kappa"].unique())
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(kappas)))
    fig, ax = plt.subplots(2, 2, figsize=(12, 9.5))
    ax = ax.ravel()
    rng = np.random.default_rng(0)
    for k, c in zip(kappas, colours):
        g = df[df["kappa"] == k]
        g = g.iloc[rng.permutation(len(g))[:4000]]
        ax[0].scatter(g["h_d"], np.maximum(g["phi_deg"], 1e-3), s=2, color=c, alpha=0.35, lw=0,
                      label=f"κ = {k:g}")
    # the point count keeps a face flat while its rise stays within about
    # (1 + alpha) h: phi = asin((1 + alpha) h / L) for the median face size
    L = float(np.median(df["face_d"]))
    hh = np.logspace(np.log10(np.nanpercentile(df["h_d"], 0.5)), np.log10(np.nanpercentile(df["h_d"], 99.5)), 50)
    ax[0].plot(hh, np.degrees(np.arcsin(np.clip((1 + DEFAULT_ALPHA) * hh / L, 0, 1))), "k-",
               label=f"rise = (1 + α) h, face {L:.2f} d")
    cp = float(np.median(df["band_cp_d"]))
    ax[0].axhline(np.degrees(np.arcsin(min(1.0, cp / L))), color="k", ls="--",
                  label=f"rise = τ ref = {cp:.3f} d")
    ax[0].set(xscale="log", yscale="log", xlabel="overlap thickness h / d (V / area)",
              ylabel="face-pair tilt φ (deg)", title="(a) contacts at ε1 ≥ 0.1 (up to 4000 per κ)")
    ax[0].set_ylim(1e-2, 100)
    ax[0].legend(fontsize=7, markerscale=4, loc="lower right")
    for k, c in zip(kappas, colours):
        g = df[df["kappa"] == k]
        phi = np.sort(g["phi_deg"].to_numpy())
        ax[1].plot(np.maximum(phi, 1e-3), np.arange(1, len(phi) + 1) / len(phi), color=c, label=f"κ = {k:g}")
        h = np.sort(g["h_d"].dropna().to_numpy())
        ax[2].plot(h, np.arange(1, len(h) + 1) / len(h), color=c, label=f"κ = {k:g}")
    if random_phi is not None:
        r = np.sort(random_phi)
        ax[1].plot(np.maximum(r, 1e-3), np.arange(1, len(r) + 1) / len(r), color="0.5", ls="--",
                   label="random orientations")
    ax[1].axhline(0.15, color="k", ls=":", lw=1, label="the paper's triple share, 0.15")
    ax[1].set(xscale="log", xlabel="face-pair tilt φ (deg)", ylabel="fraction of contacts below",
              title="(b) the face-pair tilt per κ")
    ax[1].set_xlim(1e-2, 100)
    ax[2].axvline(cp, color="k", ls="--", lw=1, label=f"τ ref = {cp:.3f} d")
    ax[2].set(xscale="log", xlabel="overlap thickness h / d", ylabel="fraction of contacts below",
              title="(c) the overlap thickness per κ")
    for k, c in zip(kappas, colours):
        F, move = tolerance_moves(df.loc[df["kappa"] == k, "phi_deg"], TOLERANCES_DEG)
        ax[3].plot(F, move, color=c, label=f"κ = {k:g}")
    ax[3].axhline(STABILITY, color="k", ls="--", lw=1, label=f"stability target {STABILITY}")
    ax[3].axvline(0.15, color="k", ls=":", lw=1, label="the paper's triple share, 0.15")
    ax[3].set(xlabel="face-face share of the criterion φ < θ", ylabel="its move at θ/2 and 2θ",
              title="(d) a tilt tolerance against its stability", xlim=(0, 0.6), ylim=(0, 0.4))
    for a in ax[1:]:
        a.legend(fontsize=8)
        a.grid(alpha=0.3)
    fig.tight_layout()
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def write_facepair(out, dumps, from_eps1=0.1, figure_path=None):
    """The face-pair tilt of a set of dumps, tabulated and drawn: writes
    OUT/facepair_tilt.csv.gz (:func:`contacts_of`), OUT/facepair_tilt.csv
    (:func:`summary`), OUT/facepair_tilt.md (:func:`markdown`, with the
    random contacts of the first dump's grains) and the figure
    (:func:`figure`).

    Parameters
    ----------
    out : str
        Output folder.
    dumps : list of str
        Kernel S1 dumps (one per kappa and seed).
    from_eps1 : float
        The least eps_1 of the shear snapshots used.
    figure_path : str, optional
        The figure's PNG (default OUT/facepair-tilt.png).

    Returns
    -------
    str
        The text of facepair_tilt.md.
    """
    df = pd.concat([contacts_of(d, from_eps1) for d in dumps], ignore_index=True)
    os.makedirs(out, exist_ok=True)
    df.to_csv(os.path.join(out, "facepair_tilt.csv.gz"), index=False)
    tab = summary(df)
    tab.to_csv(os.path.join(out, "facepair_tilt.csv"), index=False)
    random_phi = random_tilts(dumps[0])
    md = markdown(tab, random_phi)
    with open(os.path.join(out, "facepair_tilt.md"), "w") as fh:
        fh.write(md)
    figure(df, tab, figure_path or os.path.join(out, "facepair-tilt.png"), random_phi)
    return md
