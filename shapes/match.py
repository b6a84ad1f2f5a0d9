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
   points, the mean stays the target's and the variance within a factor
   (n - 1) / n of it (s is taken with the divisor n - 1); clipped to
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
   decides;
4. each grain has a budget of ``max_draws`` generator draws (200 by
   default), and the whole build an optional time limit: a grain that
   cannot be made within them stops the build with one line naming it,
   the target grain it was drawn from and the rejections, rather than
   drawing on (a very flat target grain with many vertices can be out of
   the generator's reach: its nearly flat edges are rejected).

Only elongation, flatness and the vertex count are matched (``MATCHED``).
The other descriptors (faces, sphericity, angularity, sharpest edge) are
the generator's for those proportions and counts, and need not follow the
target's: the generated grains' faces are all triangles (F = 2V - 4),
where a reduced scan has coplanar triangles merged, and their edges are
the generator's. The match is measured, not assumed:
:func:`shapes.descriptors.compare` gives the two-sample
Kolmogorov-Smirnov statistic of each descriptor with its 95 % critical
value, and the quantile differences; ``build --like`` prints the
descriptors that differ.
"""
from __future__ import annotations

import dataclasses
from collections import Counter

import numpy as np

from .generate import Recipe, generate_shape
from .polyhedron import ShapeError, check_polyhedron, normalise

#: the descriptors ``build --like`` matches (shapes.descriptors names); the others are not matched
MATCHED = ("elongation", "flatness", "n_vertices")


def smoothed_bootstrap(x, idx, rng):
    """Silverman's variance-preserving smoothed bootstrap of a sample at
    drawn indices (module docstring, step 1).

    Each value is x* = m + (x[i] - m + h eps) / sqrt(1 + h^2 / s^2), with m
    and s the sample's mean and standard deviation (divisor n - 1), h =
    1.06 s n^(-1/5) (Silverman's rule) and eps ~ N(0, 1). Over uniformly
    drawn indices the values keep the sample's mean, and their variance
    lies between the sample's variances with divisors n and n - 1.

    Parameters
    ----------
    x : (n,) float
        The sample.
    idx : (k,) int
        The drawn indices into ``x`` (e.g. ``rng.integers(n, size=k)``).
    rng : numpy.random.Generator
        The source of eps.

    Returns
    -------
    (k,) float
        The smoothed values; all equal to m when the sample is constant
        (or has one value).

    Examples
    --------
    >>> rng = np.random.default_rng(0)
    >>> x = np.array([0.6, 0.7, 0.8, 0.9])
    >>> y = smoothed_bootstrap(x, rng.integers(len(x), size=100_000), rng)
    >>> round(float(y.mean()), 3), round(float(y.std()), 3)     # x: mean 0.75, std 0.112 (divisor n) or 0.129 (n - 1)
    (0.75, 0.119)
    >>> len(np.unique(y)) > 4                   # not only the four sample values
    True
    >>> smoothed_bootstrap([0.5, 0.5], [0, 1, 1], rng)
    array([0.5, 0.5, 0.5])
    """
    x = np.asarray(x, float)
    m, s = x.mean(), x.std(ddof=1) if len(x) > 1 else 0.0
    if s == 0:
        return np.full(len(idx), m)
    h = 1.06 * s * len(x) ** (-0.2)
    eps = rng.normal(size=len(idx))
    return m + (x[idx] - m + h * eps) / np.sqrt(1 + h * h / (s * s))


#: generator draws allowed per grain of ``build --like`` (module docstring, step 4)
MAX_DRAWS = 200


def generate_like(target, n, seed=0, recipe=Recipe(), max_draws=MAX_DRAWS, max_seconds=None, progress=None,
                  names=None, heartbeat=30.0):
    """``n`` generated grains whose elongation, flatness and vertex count
    follow those of a target table (module docstring; what ``python -m
    shapes build --like`` runs).

    Parameters
    ----------
    target : dict
        Arrays ``elongation`` (I/L), ``flatness`` (S/I) and ``n_vertices``,
        one row per target grain (e.g.
        :func:`shapes.descriptors.library_descriptors` of a library).
    n : int
        The number of grains to draw.
    seed : int
        Seed of ``numpy.random.default_rng``: the same seed, target and
        recipe give the same grains.
    recipe : shapes.generate.Recipe
        The generator's other parameters (jitter, spacing, repair steps);
        its vertex range, proportions, near-sphere limit and tries are
        replaced per grain.
    max_draws : int
        Generator draws allowed per grain (each a grain drawn, repaired
        and stretched, or rejected; default ``MAX_DRAWS``, 200) before
        ShapeError. A draw of a grain the generator can make rarely needs
        more than a few; a draw of a very flat grain with many vertices
        can take seconds.
    max_seconds : float, optional
        s, wall clock allowed for all the grains before ShapeError
        (default: no limit).
    progress : callable, optional
        ``progress(k, n, seconds, note)`` is called after grain k (1-based)
        every ``max(1, n // 20)`` grains and after the last (``note`` None),
        and while a grain takes long, every ``heartbeat`` seconds, with k
        the grains done and ``note`` one line on the slow grain (its
        number, vertex count, proportions, draws so far and their
        rejections).
    names : sequence of str, optional
        The target grains' names (e.g. their source files), quoted in the
        refusal.
    heartbeat : float
        s, the interval of ``progress``'s notes on a slow grain (default 30).

    Returns
    -------
    shapes : list of shapes.polyhedron.Polyhedron
        The grains, in their normalised frame (d = 1); grain k has the
        vertex count of the target grain drawn for it (at least 4) and its
        smoothed elongation and flatness (to round-off).
    events : collections.Counter
        Redrawn attempts by reason (the generator's, and ``"stretched:
        ..."`` for a stretched grain that failed the checks).

    Raises
    ------
    ShapeError
        In one line, when a grain cannot be made within ``max_draws`` draws
        or the time is up: which grain, the target grain it was drawn
        from, its vertex count, elongation and flatness, the draws and
        seconds spent and the rejections by reason.

    Examples
    --------
    >>> target = {"elongation": [0.5, 0.55, 0.6], "flatness": [0.4, 0.45, 0.5], "n_vertices": [10, 12, 14]}
    >>> grains, events = generate_like(target, 4, seed=0)
    >>> [g.n_vertices in (10, 12, 14) for g in grains]
    [True, True, True, True]
    >>> e = [g.dims[1] / g.dims[0] for g in grains]
    >>> bool(0.45 < min(e) and max(e) < 0.65)   # near the target's 0.5-0.6
    True

    A target the generator cannot reach in the draws allowed:

    >>> flat = {"elongation": [0.9], "flatness": [0.05], "n_vertices": [37]}
    >>> generate_like(flat, 2, max_draws=3, names=["slab.stl"])
    Traceback (most recent call last):
    ...
    shapes.polyhedron.ShapeError: grain 1 of 2: no valid grain with 37 vertices, elongation 0.900 and
    flatness 0.050 (drawn from target grain 0, slab.stl: 0.900, 0.050) in 3 draws ...
    """
    import time

    t0 = time.perf_counter()
    rng = np.random.default_rng(seed)
    e_t = np.asarray(target["elongation"], float)
    f_t = np.asarray(target["flatness"], float)
    v_t = np.asarray(target["n_vertices"], int)
    idx = rng.integers(len(e_t), size=n)
    e_star = np.clip(smoothed_bootstrap(e_t, idx, rng), 0.05, 1.0)
    f_star = np.clip(smoothed_bootstrap(f_t, idx, rng), 0.05, 1.0)
    events = Counter()
    shapes = []
    every = max(1, n // 20)
    for k in range(n):
        V = int(max(4, v_t[idx[k]]))
        r = dataclasses.replace(recipe, v_min=V, v_max=V, elongation=(e_star[k],) * 2,
                                flatness=(f_star[k],) * 2, max_s_over_l=1.0, max_tries=1)
        mine = Counter()
        poly, late = None, False
        start = beat = time.perf_counter()
        for draw in range(max_draws):
            now = time.perf_counter()
            if max_seconds is not None and now - t0 > max_seconds:
                late = True
                break
            if progress is not None and now - beat >= heartbeat and draw:
                beat = now
                reasons = ", ".join(f"{why} {c}" for why, c in mine.most_common(3))
                progress(k, n, now - t0, f"grain {k + 1} ({V} vertices, elongation {e_star[k]:.3f}, flatness "
                                         f"{f_star[k]:.3f}): {draw} draws in {now - start:.0f} s, rejected: {reasons}")
            try:
                grain = generate_shape(rng, r, mine)
            except ShapeError:
                continue                            # counted in mine by the generator
            try:
                poly = stretch_to(grain, e_star[k], f_star[k])
                break
            except ShapeError as exc:
                mine[f"stretched: {str(exc).split(':')[0]}"] += 1
        events.update(mine)
        if poly is None:
            i = int(idx[k])
            who = f"target grain {i}" + (f", {names[i]}" if names is not None else "")
            reasons = ", ".join(f"{why} {c}" for why, c in mine.most_common(4)) or "none"
            raise ShapeError(
                f"grain {k + 1} of {n}: no valid grain with {V} vertices, elongation {e_star[k]:.3f} and "
                f"flatness {f_star[k]:.3f} (drawn from {who}: {e_t[i]:.3f}, {f_t[i]:.3f}) in "
                + (f"the time allowed ({max_seconds:g} s; {sum(mine.values())} draws)" if late else
                   f"{max_draws} draws ({time.perf_counter() - t0:.0f} s in all)")
                + f"; rejected: {reasons}; the generator cannot make that grain: remove it from the target, "
                "or allow more draws or time")
        shapes.append(poly)
        if progress is not None and ((k + 1) % every == 0 or k + 1 == n):
            progress(k + 1, n, time.perf_counter() - t0, None)
    return shapes, events


def stretch_to(poly, elongation, flatness):
    """A grain stretched along its principal axes to a given elongation and
    flatness (module docstring, step 2).

    Parameters
    ----------
    poly : shapes.polyhedron.Polyhedron
        A grain in its normalised frame (axes along the principal axes).
    elongation, flatness : float
        The wanted I/L and S/I of the extents along the principal axes.

    Returns
    -------
    shapes.polyhedron.Polyhedron
        The stretched grain, checked
        (:func:`shapes.polyhedron.check_polyhedron`) and normalised again
        (d = 1): its ``dims`` have I/L = elongation and S/I = flatness.

    Raises
    ------
    ShapeError
        When the stretched grain fails the checks (e.g. a sliver face).

    Examples
    --------
    >>> from shapes.generate import Recipe, generate_shape
    >>> grain = generate_shape(np.random.default_rng(1), Recipe(v_min=12, v_max=12))
    >>> flat = stretch_to(grain, 0.6, 0.5)
    >>> L, I, S = flat.dims
    >>> round(float(I / L), 9), round(float(S / I), 9), flat.n_vertices
    (0.6, 0.5, 12)
    """
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
