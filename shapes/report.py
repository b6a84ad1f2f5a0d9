"""Statistics and figures of a shape library against the published ranges."""
from __future__ import annotations

import json
import os

import numpy as np

# paper-values.md: 8-37 vertices (mean 20), 12-70 faces (mean 35)
PUBLISHED = {"n_vertices": (8, 37, 20.0), "n_faces": (12, 70, 35.0)}


def library_stats(lib):
    """dict of summary statistics of a ShapeLibrary (counts, ratios,
    sphericity), each with min / mean / max and percentiles."""
    out = {}
    ratios = {"elongation_I_over_L": lib.dims[:, 1] / lib.dims[:, 0],
              "flatness_S_over_I": lib.dims[:, 2] / lib.dims[:, 1],
              "S_over_L": lib.dims[:, 2] / lib.dims[:, 0]}
    series = {"n_vertices": lib.n_vertices, "n_faces": lib.n_faces, "n_edges": lib.n_edges,
              "sphericity": lib.sphericity, "volume_d3": lib.volume, **ratios}
    for k, x in series.items():
        x = np.asarray(x, float)
        out[k] = {"min": float(x.min()), "mean": float(x.mean()), "max": float(x.max()),
                  "p05": float(np.percentile(x, 5)), "p50": float(np.percentile(x, 50)),
                  "p95": float(np.percentile(x, 95))}
    for k, (lo, hi, mean) in PUBLISHED.items():
        out[k]["published"] = {"min": lo, "max": hi, "mean": mean}
        out[k]["mean_rel_diff"] = out[k]["mean"] / mean - 1
    return out


def write_report(lib, outdir, rejections=None, seconds=None, n_sheet=12):
    """Write ``stats.json``, ``report.md``, ``counts.png``, ``shape_ratios.png``
    and ``sheet.png`` (a dozen grains in 3D) into ``outdir``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    os.makedirs(outdir, exist_ok=True)
    st = library_stats(lib)
    st["n_shapes"] = len(lib)
    st["rejections"] = dict(rejections or {})
    st["build_seconds"] = seconds
    with open(os.path.join(outdir, "stats.json"), "w") as fh:
        json.dump(st, fh, indent=1)

    fig, axes = plt.subplots(1, 2, figsize=(9, 3.5))
    for ax, key, label in zip(axes, ("n_vertices", "n_faces"), ("vertices", "geometric faces")):
        x = getattr(lib, key)
        lo, hi, mean = PUBLISHED[key]
        ax.hist(x, bins=np.arange(x.min() - 0.5, x.max() + 1.5), color="0.6")
        ax.axvspan(lo, hi, color="tab:green", alpha=0.1, label=f"published range {lo}-{hi}")
        ax.axvline(mean, color="tab:green", label=f"published mean {mean:g}")
        ax.axvline(x.mean(), color="k", ls="--", label=f"library mean {x.mean():.1f}")
        ax.set_xlabel(label)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "counts.png"), dpi=110)
    plt.close(fig)

    fig, axes = plt.subplots(1, 2, figsize=(9, 3.8))
    e, f = lib.dims[:, 1] / lib.dims[:, 0], lib.dims[:, 2] / lib.dims[:, 1]
    axes[0].scatter(e, f, s=4, alpha=0.5)
    axes[0].set_xlim(0, 1)
    axes[0].set_ylim(0, 1)
    axes[0].set_xlabel("elongation I/L")
    axes[0].set_ylabel("flatness S/I")
    axes[0].set_title("Zingg diagram", fontsize=9)
    axes[1].hist(lib.sphericity, bins=30, color="0.6")
    axes[1].set_xlabel("Wadell sphericity")
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "shape_ratios.png"), dpi=110)
    plt.close(fig)

    n = min(n_sheet, len(lib))
    fig = plt.figure(figsize=(12, 9))
    for k in range(n):
        v, t, tf = lib[k]
        ax = fig.add_subplot(3, 4, k + 1, projection="3d")
        rng = np.random.default_rng(tf.max())
        shade = rng.uniform(0.45, 0.85, tf.max() + 1)[tf]
        coll = Poly3DCollection(v[t], facecolors=plt.cm.copper(shade), edgecolors="k", linewidths=0.3)
        ax.add_collection3d(coll)
        r = 0.42
        ax.set_xlim(-r, r)
        ax.set_ylim(-r, r)
        ax.set_zlim(-r, r)
        ax.set_box_aspect((1, 1, 1))
        ax.view_init(elev=25, azim=35 + 20 * k)
        ax.set_axis_off()
        ax.set_title(f"#{k}: {lib.n_vertices[k]} v, {lib.n_faces[k]} f", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "sheet.png"), dpi=100)
    plt.close(fig)

    lines = ["# Shape library report", "",
             f"{len(lib)} shapes, seed {lib.attrs.get('seed')}, file `{lib.path}`"
             + (f", built in {seconds:.1f} s" if seconds else ""), "",
             "| quantity | min | mean | max | published |", "|---|---|---|---|---|"]
    for k in ("n_vertices", "n_faces", "n_edges", "elongation_I_over_L", "flatness_S_over_I",
              "S_over_L", "sphericity"):
        s = st[k]
        pub = s.get("published")
        pub_txt = f"{pub['min']}-{pub['max']}, mean {pub['mean']:g} ({s['mean_rel_diff']:+.1%})" if pub else ""
        lines.append(f"| {k} | {s['min']:.3g} | {s['mean']:.3g} | {s['max']:.3g} | {pub_txt} |")
    lines += ["", f"Redrawn attempts by reason: {st['rejections'] or 'none'}", "",
              "![counts](counts.png)", "", "![ratios](shape_ratios.png)", "", "![sheet](sheet.png)", ""]
    with open(os.path.join(outdir, "report.md"), "w") as fh:
        fh.write("\n".join(lines))
    return st
