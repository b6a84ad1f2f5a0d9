"""What a figure file shows, for tests that run a whole command: every
matplotlib Figure saved while the test runs is kept with the file it was
written to (:func:`record`), so that the test reads back the plotted data
(lines, points, bars, histograms, labels) rather than the file's size; and
the readers of that data shared by several tests."""
import os

import matplotlib.figure
import numpy as np
import pytest

PNG = b"\x89PNG\r\n\x1a\n"


class Saved(list):
    """[(absolute path, Figure)] in the order they were saved."""

    def named(self, name):
        """The figures saved under this file name (any folder), in order."""
        return [fig for path, fig in self if os.path.basename(path) == name]

    def one(self, name):
        """The only figure saved under this file name."""
        figs = self.named(name)
        assert len(figs) == 1, (name, [os.path.basename(p) for p, _ in self])
        return figs[0]

    def at(self, path):
        """The last figure saved to exactly this path."""
        path = os.path.abspath(os.fspath(path))
        figs = [fig for p, fig in self if p == path]
        assert figs, (path, [p for p, _ in self])
        return figs[-1]


def record(monkeypatch):
    """Keep every Figure saved from now on (``Figure.savefig``, which
    ``pyplot.savefig`` calls too): returns the :class:`Saved` list it fills.
    The files are still written as before."""
    saved = Saved()
    original = matplotlib.figure.Figure.savefig

    def savefig(self, fname, *args, **kw):
        out = original(self, fname, *args, **kw)
        saved.append((os.path.abspath(os.fspath(fname)), self))
        return out

    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", savefig)
    return saved


def is_png(path):
    with open(path, "rb") as fh:
        return fh.read(8) == PNG


def legend_texts(ax):
    leg = ax.get_legend()
    return [t.get_text() for t in leg.get_texts()] if leg else []


def line(ax, label):
    """The line of ``ax`` with this legend label."""
    hits = [ln for ln in ax.get_lines() if ln.get_label() == label]
    assert len(hits) == 1, (label, [ln.get_label() for ln in ax.get_lines()])
    return hits[0]


def bars(ax):
    """(left edges, widths, heights) of the bars of ``ax``'s histograms and
    bar charts (its BarContainers; not an axvspan, also a Rectangle)."""
    from matplotlib.container import BarContainer

    rects = [r for c in ax.containers if isinstance(c, BarContainer) for r in c]
    return (np.array([r.get_x() for r in rects]), np.array([r.get_width() for r in rects]),
            np.array([r.get_height() for r in rects]))


def step_histogram(patch):
    """(bin edges, heights) of a histogram drawn with histtype="step": a
    Polygon whose outline runs (e0, 0), (e0, h0), (e1, h0), (e1, h1), ...,
    (eK, h(K-1)), (eK, 0)."""
    xy = np.asarray(patch.get_xy(), float)
    if len(xy) % 2:                                   # closed: the first point again at the end
        xy = xy[:-1]
    x, y = xy[:, 0], xy[:, 1]
    assert y[0] == 0 and y[-1] == 0 and np.all(x[0::2] == x[1::2])
    return x[0::2], y[1:-1:2]


def step_histograms(ax):
    """{label: (bin edges, heights)} of the step histograms of ``ax``."""
    from matplotlib.patches import Polygon

    return {p.get_label(): step_histogram(p) for p in ax.patches if isinstance(p, Polygon)}


def check_descriptor_figure(fig, libs):
    """The figure of :func:`shapes.report.plot_descriptors` shows, for each
    library of ``libs`` ({label: (ShapeLibrary, descriptor dict)}, in that
    order), the density histogram of each descriptor's values (and of its
    edges' dihedral angles, weighted by length), with the published ranges
    of the vertex and face counts."""
    from shapes.descriptors import library_edge_angles
    from shapes.report import LABELS, PUBLISHED

    keys = ["n_vertices", "n_faces", "elongation", "flatness", "sphericity", "angularity_deg",
            "edges", "convexity_deficit", "reduction_hausdorff"]
    assert len(fig.axes) == len(keys)
    for ax, k in zip(fig.axes, keys):
        hists = step_histograms(ax)
        assert list(hists) == list(libs), (k, list(hists))             # one histogram per library
        for lab, (lib, desc) in libs.items():
            edges, heights = hists[lab]
            if k == "edges":
                a, w = library_edge_angles(lib)
                expect, _ = np.histogram(a, bins=edges, weights=w, density=True)
                assert ax.get_xlabel() == "exterior dihedral angle at edges (deg), by length"
            else:
                x = np.asarray(desc[k], float)
                assert x.min() >= edges[0] and x.max() <= edges[-1], k      # every grain in a bin
                expect, _ = np.histogram(x, bins=edges, density=True)
                assert ax.get_xlabel() == LABELS[k]
            np.testing.assert_allclose(heights, expect, rtol=1e-9, atol=1e-12, err_msg=f"{lab}: {k}")
            assert np.sum(heights * np.diff(edges)) == pytest.approx(1.0)
        if k in PUBLISHED:
            lo, hi, mean = PUBLISHED[k]
            published = [ln for ln in ax.get_lines() if ln.get_label().startswith("published")]
            assert len(published) == 1 and list(published[0].get_xdata()) == [mean, mean]
            assert published[0].get_label() == f"published {lo}–{hi}, mean {mean:g}"
    return True



def check_footprint_figure(fig, rel, threshold):
    """The figure of :func:`postproc.plots.plot_footprint` shows the
    footprint extents ``rel`` (N, 2), L1/d >= L2/d of every contact it
    claims (its title's count), each column's histogram holding every
    contact once (density per unit ln(L/d)), with the threshold t and t/2,
    2t marked."""
    (ax,) = fig.axes
    rel = np.asarray(rel, float)
    assert ax.get_title().endswith(f": {len(rel)} contacts"), ax.get_title()
    assert ax.get_xscale() == "log" and ax.get_ylabel() == "density per unit ln(L/d)"
    assert ax.get_xlabel() == f"footprint extent / pair size d (lines: t = {threshold:g}, t/2, 2t)"
    stairs = ax.patches
    assert [p.get_label() for p in stairs] == ["$L_1/d$ (simple below t)", "$L_2/d$ (triple above t)"]
    for j, patch in enumerate(stairs):
        h = patch.get_data()
        edges, density = np.asarray(h.edges), np.asarray(h.values)
        counts = density * len(rel) * np.diff(np.log(edges))
        np.testing.assert_allclose(counts, np.round(counts), atol=1e-6)
        # float error aside (a recomputed footprint), the smallest and largest extents are the end edges
        x = np.clip(rel[:, j], edges[0], edges[-1])
        assert np.allclose(x, rel[:, j], rtol=1e-9, atol=0)
        np.testing.assert_array_equal(np.round(counts), np.histogram(x, edges)[0])
    assert sorted(ln.get_xdata()[0] for ln in ax.get_lines()) == pytest.approx([threshold / 2, threshold,
                                                                                 2 * threshold])
