"""Generated grains that match a given library: ``python -m shapes build --like LIB.h5``.

A user with 50 scans wants 1000 grains of the same family. The target's
joint distribution of (elongation I/L, flatness S/I, vertex count) is
resampled and each draw is realised by the generator of
:mod:`shapes.generate`:

1. a target grain i is drawn uniformly (bootstrap, with replacement); its
   vertex count V_i is kept as it is (a discrete distribution), its
   (e_i, f_i) are smoothed with the variance-preserving smoothed bootstrap
   (Silverman 1986, section 6.4.1):
   x* = m + (x_i - m + h eps) / sqrt(1 + h^2 / s^2), eps ~ N(0, 1), with m
   and s the target's mean and standard deviation and h = 1.06 s n^(-1/5)
   (Silverman's rule), so that 1000 grains drawn from 50 do not sit on 50
   points and the mean and variance stay the target's; clipped to
   [0.05, 1];
2. the generator draws a grain with exactly V_i vertices on a base ellipsoid
   of axes (1, e*, e* f*); the jitter of its points moves its measured
   extents (L, I, S) away from the base ellipsoid's, so the grain is then
   stretched along its principal axes by (1, a, b) with a = e* L / I and
   b = f* a I / S. A stretch along principal axes keeps them principal (the
   products of inertia stay zero) and maps the extents to (L, e* L,
   e* f* L): the grain has the drawn elongation and flatness exactly. An
   affine map keeps the hull convex and its faces planar; the stretched
   grain is checked again (:func:`shapes.polyhedron.check_polyhedron`) and
   redrawn (same V) when the stretch made it invalid;
3. the generator's near-sphere rejection (S/L > 0.8) is off: the target
   decides.

The match is measured, not assumed: :func:`shapes.descriptors.compare`
gives the two-sample Kolmogorov-Smirnov statistic of each descriptor with
its 95 % critical value, and the quantile differences.
"""
from __future__ import annotations

import dataclasses
from collections import Counter

import numpy as np

from .generate import Recipe, generate_shape
from .polyhedron import ShapeError, check_polyhedron, normalise


def smoothed_bootstrap(x, idx, rng):
    """Silverman's variance-preserving smoothed bootstrap of the sample x
    (n,) at the drawn indices idx (k,): (k,) values (module docstring)."""
    x = np.asarray(x, float)
    m, s = x.mean(), x.std(ddof=1) if len(x) > 1 else 0.0
    if s == 0:
        return np.full(len(idx), m)
    h = 1.06 * s * len(x) ** (-0.2)
    eps = rng.normal(size=len(idx))
    return m + (x[idx] - m + h * eps) / np.sqrt(1 + h * h / (s * s))


def generate_like(target, n, seed=0, recipe=Recipe(), max_tries=200):
    """``n`` grains whose (elongation, flatness, vertex count) follow the
    descriptor table ``target`` (dict with arrays ``elongation``,
    ``flatness``, ``n_vertices``; e.g. :func:`shapes.descriptors.library_descriptors`).

    Returns (list of Polyhedron with d = 1, Counter of redrawn grains by
    reason). Reproducible from ``seed``.
    """
    rng = np.random.default_rng(seed)
    e_t = np.asarray(target["elongation"], float)
    f_t = np.asarray(target["flatness"], float)
    v_t = np.asarray(target["n_vertices"], int)
    idx = rng.integers(len(e_t), size=n)
    e_star = np.clip(smoothed_bootstrap(e_t, idx, rng), 0.05, 1.0)
    f_star = np.clip(smoothed_bootstrap(f_t, idx, rng), 0.05, 1.0)
    events = Counter()
    shapes = []
    for k in range(n):
        V = int(max(4, v_t[idx[k]]))
        r = dataclasses.replace(recipe, v_min=V, v_max=V, elongation=(e_star[k],) * 2,
                                flatness=(f_star[k],) * 2, max_s_over_l=1.0)
        for _ in range(max_tries):
            try:
                poly = stretch_to(generate_shape(rng, r, events), e_star[k], f_star[k])
                break
            except ShapeError as exc:
                events[f"stretched: {str(exc).split(':')[0]}"] += 1
        else:
            raise ShapeError(f"no valid grain with {V} vertices, elongation {e_star[k]:.3f} and "
                             f"flatness {f_star[k]:.3f} in {max_tries} draws: {dict(events)}")
        shapes.append(poly)
    return shapes, events


def stretch_to(poly, elongation, flatness):
    """The grain ``poly`` (a normalised Polyhedron) stretched along its
    principal axes so that its extents have I/L = elongation and S/I =
    flatness (module docstring, step 2), checked and normalised again
    (d = 1). Raises ShapeError when the stretched grain is invalid."""
    v = poly.vertices
    ext = v.max(axis=0) - v.min(axis=0)         # along the frame's axes (principal)
    order = np.argsort(-ext)                    # L, I, S axes
    L, I, S = ext[order]
    a = elongation * L / I
    b = flatness * a * I / S
    scale = np.ones(3)
    scale[order[1]], scale[order[2]] = a, b
    w = v * scale
    check_polyhedron(w, poly.triangles)
    return normalise(w, poly.triangles)
