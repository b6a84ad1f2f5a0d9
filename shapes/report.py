"""Statistics and figures of a shape library against the published ranges,
its descriptors (:mod:`shapes.descriptors`), two libraries side by side
(:func:`write_comparison`), and the library section of the study report
(:func:`study_section`)."""
from __future__ import annotations

import json
import os

import numpy as np

# paper-values.md: 8-37 vertices (mean 20), 12-70 faces (mean 35)
PUBLISHED = {"n_vertices": (8, 37, 20.0), "n_faces": (12, 70, 35.0)}


def library_stats(lib):
    """Summary statistics of a library's counts, proportions, sphericity and
    volume, with the published vertex and face counts beside them.

    Parameters
    ----------
    lib : shapes.library.ShapeLibrary
        The library.

    Returns
    -------
    dict
        Per series (``n_vertices``, ``n_faces``, ``n_edges``,
        ``sphericity``, ``volume_d3`` (volume in units of d^3),
        ``elongation_I_over_L``, ``flatness_S_over_I``, ``S_over_L``) a
        dict of ``min``, ``mean``, ``max`` and the percentiles ``p05``,
        ``p50``, ``p95``; ``n_vertices`` and ``n_faces`` also hold
        ``published`` (min, max and mean of ``PUBLISHED``) and
        ``mean_rel_diff`` (library mean / published mean - 1).

    Examples
    --------
    A library of a cube and a 1 x 1 x 2 box:

    >>> import itertools, tempfile
    >>> from shapes.library import ShapeLibrary, write_library
    >>> from shapes.polyhedron import polyhedron_from_points
    >>> cube, box = (polyhedron_from_points(np.array(list(itertools.product((0, 1), (0, 1), (0, h))), float))
    ...              for h in (1, 2))
    >>> path = os.path.join(tempfile.mkdtemp(), "blocks.h5")
    >>> write_library(path, [cube, box], seed=0, recipe={}, tolerances={})
    >>> lib = ShapeLibrary(path)
    >>> st = library_stats(lib)
    >>> st["n_vertices"]["mean"], st["n_faces"]["max"], st["n_vertices"]["published"]
    (8.0, 6.0, {'min': 8, 'max': 37, 'mean': 20.0})
    >>> round(st["n_vertices"]["mean_rel_diff"], 6), st["elongation_I_over_L"]["min"]
    (-0.6, 0.5)
    """
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


def write_report(lib, outdir, rejections=None, seconds=None, n_sheet=12, refused=None, notes=(), missed=None,
                 target=None):
    """Write a library's report into a folder (what ``python -m shapes
    build``, ``import`` and ``report`` write): ``stats.json``, ``report.md``
    (the descriptor table beside the published ranges), ``counts.png``
    (vertex and face counts against the published ranges),
    ``shape_ratios.png`` (Zingg diagram and sphericity),
    ``descriptors.png`` (:func:`plot_descriptors`) and ``sheet.png`` (the
    first grains in 3D).

    Parameters
    ----------
    lib : shapes.library.ShapeLibrary
        The library.
    outdir : str
        The folder (made when missing); the files in it are replaced.
    rejections : dict, optional
        Redrawn attempts of the generator by reason, listed in the report.
    seconds : float, optional
        s, the time the library took to make, quoted in the report.
    n_sheet : int
        The number of grains drawn in ``sheet.png`` (at most 12, the
        sheet's 3 x 4 panels; default 12).
    refused : list of (str, str), optional
        (file, reason) of the meshes an import refused, listed in the
        report.
    notes : sequence of str
        Extra lines for the report, each written as a list item.
    missed : list of tuple, optional
        (source, vertices, reduction error / d, volume change, why) of
        the imported grains above their error target, listed in a table.
    target : float, optional
        The import's error target (relative to d), quoted in that table.

    Returns
    -------
    dict
        What ``stats.json`` holds: :func:`library_stats`, and
        ``n_shapes``, ``rejections``, ``build_seconds``, ``descriptors``
        (per descriptor min, mean, max, p10, p50, p90), ``refused`` and
        ``missed``.

    Examples
    --------
    Skipped when the examples are tested: drawing the five figures takes
    a few seconds.

    >>> from shapes.library import ShapeLibrary
    >>> st = write_report(ShapeLibrary("LIB.h5"), "LIB-report")    # doctest: +SKIP
    >>> sorted(os.listdir("LIB-report"))                           # doctest: +SKIP
    ['counts.png', 'descriptors.png', 'report.md', 'shape_ratios.png', 'sheet.png', 'stats.json']
    """
    from .descriptors import library_descriptors
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    os.makedirs(outdir, exist_ok=True)
    st = library_stats(lib)
    st["n_shapes"] = len(lib)
    st["rejections"] = dict(rejections or {})
    st["build_seconds"] = seconds
    desc = library_descriptors(lib)
    st["descriptors"] = {k: _summary(x) for k, x in desc.items()}
    st["refused"] = [list(r) for r in (refused or [])]
    st["missed"] = [list(m) for m in (missed or [])]
    with open(os.path.join(outdir, "stats.json"), "w") as fh:
        json.dump(st, fh, indent=1)
    plot_descriptors({lib.name: (lib, desc)}, os.path.join(outdir, "descriptors.png"))

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

    lines = [f"# Shape library report: {lib.name}", "",
             f"{len(lib)} shapes, file `{lib.path}`, made by `{lib.attrs.get('created_by')}`"
             + (f" (seed {lib.attrs.get('seed')})" if lib.attrs.get("seed", -1) >= 0 else "")
             + (f" in {seconds:.1f} s" if seconds else ""), ""]
    lines += descriptor_table({lib.name: desc})
    lines += [f"* {x}" for x in notes]
    if missed:
        lines += ["", f"Above the error target{f' {target} d' if target is not None else ''} ({len(missed)}):", "",
                  "| grain | vertices | error / d | x target | volume change | why |", "|---|---|---|---|---|---|"]
        lines += [f"| `{s}` | {n} | {e:.3g} | {e / target:.2f} | {dv:+.3f} | {why} |" if target else
                  f"| `{s}` | {n} | {e:.3g} | | {dv:+.3f} | {why} |" for s, n, e, dv, why in missed]
    if refused:
        lines += ["", f"Refused ({len(refused)}):", ""] + [f"* `{f}`: {r}" for f, r in refused]
    lines += ["", f"Redrawn attempts by reason: {st['rejections'] or 'none'}", "",
              "![counts](counts.png)", "", "![ratios](shape_ratios.png)", "",
              "![descriptors](descriptors.png)", "", "![sheet](sheet.png)", ""]
    with open(os.path.join(outdir, "report.md"), "w") as fh:
        fh.write("\n".join(lines))
    return st


# ---------------------------------------------------------------- descriptors

#: table labels of the descriptors (shapes.descriptors.NAMES)
LABELS = {"n_vertices": "vertices", "n_faces": "faces", "n_edges": "edges",
          "elongation": "elongation I/L", "flatness": "flatness S/I", "s_over_l": "S/L",
          "sphericity": "Wadell sphericity", "angularity_deg": "angularity (deg)",
          "sharpest_edge_deg": "sharpest edge (deg)", "convexity_deficit": "convexity deficit",
          "reduction_hausdorff": "reduction Hausdorff / d", "reduction_volume_change": "reduction volume change"}


def _summary(x):
    x = np.asarray(x, float)
    return {"min": float(x.min()), "mean": float(x.mean()), "max": float(x.max()),
            "p10": float(np.percentile(x, 10)), "p50": float(np.percentile(x, 50)),
            "p90": float(np.percentile(x, 90))}


def _fmt(x):
    return f"{x:.3g}" if abs(x) >= 1e-3 or x == 0 else f"{x:.2e}"


def descriptor_table(tables, stats=None):
    """The Markdown table of the reports: one row per descriptor, one
    column per library.

    Parameters
    ----------
    tables : dict
        label -> descriptor table (name -> array, e.g.
        :func:`shapes.descriptors.library_descriptors`), every name of
        ``shapes.descriptors.NAMES`` in each.
    stats : dict, optional
        :func:`shapes.descriptors.compare` of the first two tables: adds a
        column of the KS statistic D with its 95 % critical value.

    Returns
    -------
    list of str
        The table's lines: header, rule, then per descriptor each library's
        min / mean / max (3 significant digits) and the published range
        where there is one (``PUBLISHED``).

    Examples
    --------
    >>> import itertools, tempfile
    >>> from shapes.library import ShapeLibrary, write_library
    >>> from shapes.polyhedron import polyhedron_from_points
    >>> cube, box = (polyhedron_from_points(np.array(list(itertools.product((0, 1), (0, 1), (0, h))), float))
    ...              for h in (1, 2))
    >>> path = os.path.join(tempfile.mkdtemp(), "blocks.h5")
    >>> write_library(path, [cube, box], seed=0, recipe={}, tolerances={})
    >>> lib = ShapeLibrary(path)
    >>> from shapes.descriptors import library_descriptors
    >>> lines = descriptor_table({"blocks": library_descriptors(lib)})
    >>> for line in lines[:5]:
    ...     print(line)
    | descriptor | blocks: min / mean / max | published |
    |---|---|---|
    | vertices | 8 / 8 / 8 | 8–37, mean 20 |
    | faces | 6 / 6 / 6 | 12–70, mean 35 |
    | edges | 12 / 12 / 12 | – |
    """
    from .descriptors import NAMES

    labels = list(tables)
    head = "| descriptor | " + " | ".join(f"{lab}: min / mean / max" for lab in labels) + " | published |"
    if stats:
        head += " KS D (95 % crit.) |"
    lines = [head, "|" + "---|" * (len(labels) + 2 + bool(stats))]
    for k in NAMES:
        cells = []
        for lab in labels:
            x = np.asarray(tables[lab][k], float)
            cells.append(f"{_fmt(x.min())} / {_fmt(x.mean())} / {_fmt(x.max())}")
        pub = PUBLISHED.get(k)
        row = f"| {LABELS[k]} | " + " | ".join(cells) + f" | {f'{pub[0]}–{pub[1]}, mean {pub[2]:g}' if pub else '–'} |"
        if stats:
            row += f" {stats[k]['ks_D']:.3f} ({stats[k]['ks_D_crit95']:.3f}) |"
        lines.append(row)
    return lines


def plot_descriptors(libs, path):
    """One figure of histograms of the descriptors, the libraries overlaid
    as densities: vertex and face counts (published range shaded),
    elongation, flatness, sphericity, angularity per grain, the exterior
    dihedral angle of every edge (length-weighted), convexity deficit and
    reduction error.

    Parameters
    ----------
    libs : dict
        label -> (ShapeLibrary, its descriptor table from
        :func:`shapes.descriptors.library_descriptors`). Only the first
        four are drawn, one colour each (the histograms pair the libraries
        with four colours).
    path : str
        The image file to write (its format from the extension, e.g. PNG).

    Returns
    -------
    None

    Examples
    --------
    Skipped when the examples are tested: drawing the figure takes a few
    seconds.

    >>> from shapes.descriptors import library_descriptors
    >>> from shapes.library import ShapeLibrary
    >>> lib = ShapeLibrary("LIB.h5")                                                       # doctest: +SKIP
    >>> plot_descriptors({lib.name: (lib, library_descriptors(lib))}, "descriptors.png")   # doctest: +SKIP
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from .descriptors import library_edge_angles

    keys = ["n_vertices", "n_faces", "elongation", "flatness", "sphericity", "angularity_deg",
            "edges", "convexity_deficit", "reduction_hausdorff"]
    fig, axes = plt.subplots(3, 3, figsize=(11, 8.5))
    colours = ["0.35", "tab:orange", "tab:blue", "tab:green"]
    for ax, k in zip(axes.ravel(), keys):
        if k == "edges":
            data = {lab: library_edge_angles(lib) for lab, (lib, _) in libs.items()}
            bins = np.linspace(0, 180, 37)
            for (lab, (a, w)), col in zip(data.items(), colours):
                ax.hist(a, bins=bins, weights=w, density=True, histtype="step", lw=1.4, color=col, label=lab)
            ax.set_xlabel("exterior dihedral angle at edges (deg), by length")
            continue
        xs = {lab: np.asarray(d[k], float) for lab, (_, d) in libs.items()}
        allx = np.concatenate(list(xs.values()))
        if k in ("n_vertices", "n_faces"):
            step = max(1, int(np.ptp(allx) // 40) + 1)     # the last bin holds the largest count too
            bins = np.arange(allx.min() - 0.5, allx.max() + 0.5 + step, step)
            lo, hi, mean = PUBLISHED[k]
            ax.axvspan(lo, hi, color="tab:green", alpha=0.08)
            ax.axvline(mean, color="tab:green", lw=1, label=f"published {lo}–{hi}, mean {mean:g}")
        else:
            span = np.ptp(allx)
            bins = np.linspace(allx.min() - 0.05 * span - 1e-9, allx.max() + 0.05 * span + 1e-9, 31)
        for (lab, x), col in zip(xs.items(), colours):
            ax.hist(x, bins=bins, density=True, histtype="step", lw=1.4, color=col, label=lab)
        ax.set_xlabel(LABELS[k])
    for ax in axes.ravel():
        ax.set_yticks([])
    axes[0, 0].legend(fontsize=7)
    axes[0, 1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def write_comparison(lib_a, lib_b, outdir, label_a=None, label_b=None, matched=None):
    """Two libraries side by side in a folder (what ``python -m shapes
    report --against`` and ``build --like`` write).

    Writes ``compare.md`` (:func:`descriptor_table` of both, the published
    ranges and the KS statistics; the quantile differences),
    ``compare.json`` (the two libraries and the statistics) and
    ``compare.png`` (:func:`plot_descriptors`).

    Parameters
    ----------
    lib_a, lib_b : shapes.library.ShapeLibrary
        The two libraries.
    outdir : str
        The folder (made when missing).
    label_a, label_b : str, optional
        Their labels (default: their names; equal labels get " (a)" and
        " (b)" added).
    matched : sequence of str, optional
        The descriptors b was made to match a's (``build --like``):
        compare.md then says which are matched and which are not, with
        each one's KS D against its critical value.

    Returns
    -------
    dict
        :func:`shapes.descriptors.compare` of a's descriptors and b's
        (differences b - a).

    Examples
    --------
    Skipped when the examples are tested: drawing the figure takes a few
    seconds.

    >>> from shapes.library import ShapeLibrary
    >>> st = write_comparison(ShapeLibrary("A.h5"), ShapeLibrary("B.h5"), "A-vs-B")   # doctest: +SKIP
    >>> sorted(os.listdir("A-vs-B"))                                                  # doctest: +SKIP
    ['compare.json', 'compare.md', 'compare.png']
    """
    from .descriptors import compare, library_descriptors

    os.makedirs(outdir, exist_ok=True)
    la, lb = label_a or lib_a.name, label_b or lib_b.name
    if la == lb:
        la, lb = f"{la} (a)", f"{lb} (b)"
    da, db = library_descriptors(lib_a), library_descriptors(lib_b)
    stats = compare(da, db)
    with open(os.path.join(outdir, "compare.json"), "w") as fh:
        json.dump({"a": {"name": la, "file": str(lib_a.path), "n": len(lib_a)},
                   "b": {"name": lb, "file": str(lib_b.path), "n": len(lib_b)}, "stats": stats}, fh, indent=1)
    plot_descriptors({la: (lib_a, da), lb: (lib_b, db)}, os.path.join(outdir, "compare.png"))
    lines = [f"# Shape libraries side by side: {la} and {lb}", "",
             f"* {la}: `{lib_a.path}`, {len(lib_a)} grains, made by `{lib_a.attrs.get('created_by')}`",
             f"* {lb}: `{lib_b.path}`, {len(lib_b)} grains, made by `{lib_b.attrs.get('created_by')}`", "",
             "KS D: two-sample Kolmogorov–Smirnov statistic of each descriptor; the two libraries' "
             "distributions differ at the 5 % level when D exceeds its critical value.", ""]
    if matched is not None:
        def ks(k):
            s = stats[k]
            return (f"{LABELS[k]} D = {s['ks_D']:.3f} (p = {s['ks_p']:.2g}, "
                    f"{'differs' if s['ks_D'] > s['ks_D_crit95'] else 'alike'})")
        crit = stats[matched[0]]["ks_D_crit95"]
        rest = [k for k in stats if k not in matched]
        lines += [f"Matched by construction ({lb} draws these from {la}): "
                  + "; ".join(ks(k) for k in matched) + f". 95 % critical value {crit:.3f}.", "",
                  "Not matched (the generator's for those proportions and counts; they need not follow): "
                  + "; ".join(ks(k) for k in rest) + ".", ""]
    lines += descriptor_table({la: da, lb: db}, stats)
    lines += ["", f"Quantile differences ({lb} − {la}):", "",
              "| descriptor | p10 | p50 | p90 | KS p-value |", "|---|---|---|---|---|"]
    for k, st in stats.items():
        lines.append(f"| {LABELS[k]} | {_fmt(st['dq10'])} | {_fmt(st['dq50'])} | {_fmt(st['dq90'])} | "
                     f"{st['ks_p']:.3g} |")
    lines += ["", "![descriptors of both libraries](compare.png)", ""]
    with open(os.path.join(outdir, "compare.md"), "w") as fh:
        fh.write("\n".join(lines))
    return stats


def budget_text(b):
    """A vertex budget in words, for the reports.

    Parameters
    ----------
    b : dict
        A budget as :meth:`shapes.hullreduce.Budget.as_dict` gives it (an
        imported library's ``recipe["budget"]``); may be empty.

    Returns
    -------
    str
        The budget in words.

    Examples
    --------
    >>> budget_text({"vertices": 12, "max_error": None, "max_vertices": None})
    'reduced to 12 vertices'
    >>> budget_text({"vertices": None, "max_error": 0.02, "max_vertices": 37})
    'reduced to within 0.02 d of the hull, at most 37 vertices'
    >>> budget_text({})
    'budget not recorded'
    """
    if b.get("vertices") is not None:
        return f"reduced to {b['vertices']} vertices"
    if b.get("max_error") is not None:
        return f"reduced to within {b['max_error']:g} d of the hull, at most {b.get('max_vertices')} vertices"
    return "budget not recorded"


def study_section(library_path, outdir, figure="library_descriptors.png"):
    """The study report's section on the grains of S1: the library's name
    and origin, its descriptors beside the published ranges (8–37
    vertices, mean 20; 12–70 faces, mean 35) and, unless ``figure`` is
    None, a figure.

    Parameters
    ----------
    library_path : str
        The library file S1 ran on.
    outdir : str
        The report's folder: the figure is written there.
    figure : str or None
        The figure's file name (default ``library_descriptors.png``; None:
        no figure).

    Returns
    -------
    list of str
        Markdown lines, starting with a blank line and the heading "The
        grains of S1". A library that cannot be read gives a one-line note
        instead of the table; a figure that cannot be drawn, a note instead
        of the figure.

    Examples
    --------
    A missing library (the full section draws a figure, which takes a few
    seconds):

    >>> for line in study_section("missing.h5", "."):
    ...     print(line)
    <BLANKLINE>
    ## The grains of S1
    <BLANKLINE>
    The shape library `missing.h5` could not be read: missing.h5: no such shape library (build it with 'make shapes')
    <BLANKLINE>
    """
    from .descriptors import library_descriptors
    from .library import LibraryError, ShapeLibrary

    lines = ["", "## The grains of S1", ""]
    try:
        lib = ShapeLibrary(library_path)
        desc = library_descriptors(lib)
    except (LibraryError, KeyError, ValueError) as exc:
        return lines + [f"The shape library `{library_path}` could not be read: {exc}", ""]
    origin = f"made by `{lib.attrs.get('created_by')}`"
    try:
        recipe = json.loads(lib.attrs.get("recipe", "{}"))
    except ValueError:
        recipe = {}
    if "source" in lib.data:
        origin += f", imported from {len(lib)} meshes ({budget_text(recipe.get('budget') or {})})"
    elif lib.attrs.get("seed", -1) >= 0:
        origin += f", seed {lib.attrs.get('seed')}"
    if recipe.get("like"):
        origin += f", drawn to match `{recipe['like']}`"
    lines += [f"Library **{lib.name}**: {len(lib)} grains, {origin}. Each grain is placed at a size "
              "class of the study (50 / 34 / 16 % of d = 2.5 / 3.75 / 5 cm); S2's spheres have the "
              "same classes.", ""]
    lines += descriptor_table({lib.name: desc})
    if figure is None:
        return lines
    try:
        plot_descriptors({lib.name: (lib, desc)}, os.path.join(outdir, figure))
    except Exception as exc:            # a figure that cannot be drawn is reported, not fatal
        return lines + ["", f"(figure {figure} not drawn: {exc.__class__.__name__}: {exc})", ""]
    cap = "descriptors of S1's grains (published ranges shaded)"
    lines += ["", f"![{cap}]({figure})", "", f"*{cap}*", ""]
    return lines
