"""The recipe for ballast-like grains.

Crushed stone is angular, with sharp edges and flat facets, and is neither
spherical nor needle-like. The published library (1000 digitised SNCF ballast
grains) has 8-37 vertices (mean 20) and 12-70 faces (mean 35): F = 2V - 4,
the count of a convex polyhedron whose faces are all triangles, so we build
each grain as the convex hull of points in general position:

1. the vertex count V = V_min + round((V_max - V_min) * B), B ~ Beta(alpha, beta),
   with (alpha, beta) chosen so that the mean is 20 on [8, 37];
2. a base ellipsoid with semi-axes 1 >= e >= e f (elongation e = I/L and
   flatness f = S/I drawn uniformly in ``elongation`` and ``flatness``);
3. V points on it, at uniformly random directions, each pushed in or out
   radially by up to ``jitter`` (irregular facets), and at least
   ``min_separation`` x (2 x largest semi-axis) apart; points are added until
   the hull has exactly V vertices (interior points are dropped);
   wherever two adjacent triangles are nearly coplanar (bend below
   ``CREASE_DEG``), one of the two vertices opposite their common edge is
   replaced by a new random point, until every edge is a clear crease, so
   every face is a triangle, as in the published library (F = 2V - 4);
4. the hull is checked (:func:`shapes.polyhedron.check_polyhedron`: no
   duplicate vertices, no sliver faces, no short edges, convex, closed) and
   must not be near-spherical (S/L <= ``max_s_over_l``); a draw that fails
   is redrawn with the same V (so that rejections, more frequent for many
   vertices, do not bias the count distribution), and the reasons are
   counted;
5. the grain is moved to its centre of mass and principal frame and scaled to
   d = 1 (:func:`shapes.polyhedron.normalise`).

Everything comes from one numpy Generator seeded by the caller, so a library
is reproducible from its seed.
"""
from __future__ import annotations

from collections import Counter
from dataclasses import asdict, dataclass

import numpy as np

from .polyhedron import CREASE_DEG, ShapeError, bend_angles, check_polyhedron, hull, normalise


@dataclass(frozen=True)
class Recipe:
    """Parameters of the grain generator (module docstring): an immutable
    record, changed with :func:`dataclasses.replace`. The defaults draw the
    ballast-like grains of ``python -m shapes build``.

    Parameters
    ----------
    v_min, v_max : int
        The range of the vertex count V (default 8 and 37).
    v_beta : (2,) tuple of float
        (alpha, beta) of the Beta law B of V = v_min + round((v_max - v_min)
        B) (default (2.0, 2.83): a mean of 8 + 29 x 2 / 4.83 = 20.0).
    elongation, flatness : (2,) tuple of float
        The uniform ranges of the base ellipsoid's I/L and S/I (default
        (0.55, 0.95) and (0.5, 0.9)).
    jitter : float
        Each point is moved radially by a factor drawn uniformly in
        [1 - jitter, 1 + jitter] (default 0.10).
    min_separation : float
        Least distance between two drawn points, relative to twice the
        largest semi-axis (default 0.09).
    max_s_over_l : float
        Grains with a larger S/L are redrawn as near-spherical (default
        0.8).
    max_tries : int
        Draws of one grain before :func:`generate_shape` gives up with
        ShapeError (default 1000).
    repair_steps_per_vertex : int
        Rounds of hull and repair (of a nearly flat edge, or of points
        dropped inside the hull) allowed per vertex, V x this in all,
        before the draw is redrawn (default 20).

    Attributes
    ----------
    v_min, v_max, v_beta, elongation, flatness
        The parameters, as given.
    jitter, min_separation, max_s_over_l, max_tries, repair_steps_per_vertex
        The parameters, as given.

    Examples
    --------
    >>> import dataclasses
    >>> r = Recipe()
    >>> round(r.v_min + (r.v_max - r.v_min) * r.v_beta[0] / sum(r.v_beta), 2)   # the mean vertex count
    20.01
    >>> few = dataclasses.replace(r, v_min=10, v_max=12)
    >>> few.as_dict()["v_max"], few.as_dict()["elongation"]
    (12, (0.55, 0.95))
    """

    v_min: int = 8
    v_max: int = 37
    v_beta: tuple = (2.0, 2.83)          # mean 8 + 29 * 2/4.83 = 20.0
    elongation: tuple = (0.55, 0.95)     # I/L of the base ellipsoid
    flatness: tuple = (0.5, 0.9)         # S/I of the base ellipsoid
    jitter: float = 0.10
    min_separation: float = 0.09
    max_s_over_l: float = 0.8
    max_tries: int = 1000
    repair_steps_per_vertex: int = 20

    def as_dict(self):
        """The parameters as a dict, name -> value (how a library file
        stores its recipe, as JSON).

        Returns
        -------
        dict
            One entry per field, in the order of the fields.
        """
        return asdict(self)


def _surface_point(rng, axes, recipe):
    """A random point on the base ellipsoid (uniform direction), pushed in or
    out radially by up to ``recipe.jitter``."""
    u = rng.normal(size=3)
    u /= np.linalg.norm(u)
    return axes * u * (1 + recipe.jitter * rng.uniform(-1, 1))


def _draw_points(rng, n, axes, recipe):
    pts = []
    tries = 0
    sep = recipe.min_separation * 2 * axes.max()
    while len(pts) < n:
        tries += 1
        if tries > 100 * n:
            raise ShapeError("could not place points at the minimum separation")
        x = _surface_point(rng, axes, recipe)
        if all(np.linalg.norm(x - p) >= sep for p in pts):
            pts.append(x)
    return pts


def _flat_edge_opposites(v, t, crease):
    """Vertices opposite the edges that bend by less than ``crease`` deg."""
    edges, pairs, bend = bend_angles(v, t)
    bad = bend < crease
    if not bad.any():
        return np.zeros(0, int)
    tri = t[pairs[bad].ravel()]
    e = np.repeat(edges[bad], 2, axis=0)
    opp = tri[(tri != e[:, [0]]) & (tri != e[:, [1]])]
    return np.unique(opp)


def generate_shape(rng, recipe=Recipe(), rejections=None):
    """One valid ballast-like grain, drawn by the recipe of the module
    docstring (steps 1-5).

    Parameters
    ----------
    rng : numpy.random.Generator
        The source of every random number (the grain depends on its state
        only).
    recipe : Recipe
        The generator's parameters (default ``Recipe()``).
    rejections : collections.Counter, optional
        Incremented by one for every redrawn attempt, keyed by its reason
        (the defect's name, e.g. ``"sliver face"``, or ``"near-spherical"``).

    Returns
    -------
    shapes.polyhedron.Polyhedron
        In the normalised frame, d = 1, with V vertices, every face a
        triangle (F = 2V - 4).

    Raises
    ------
    ShapeError
        No valid grain in ``recipe.max_tries`` draws.

    Examples
    --------
    >>> from collections import Counter
    >>> rng, why = np.random.default_rng(0), Counter()
    >>> grains = [generate_shape(rng, Recipe(v_min=10, v_max=10), why) for _ in range(3)]
    >>> [(g.n_vertices, g.n_faces, round(g.size, 12)) for g in grains]
    [(10, 16, 1.0), (10, 16, 1.0), (10, 16, 1.0)]
    >>> dict(why)                           # one draw was redrawn
    {'sliver face': 1}
    """
    rejections = Counter() if rejections is None else rejections
    target = recipe.v_min + int(round((recipe.v_max - recipe.v_min) * rng.beta(*recipe.v_beta)))
    for _ in range(recipe.max_tries):
        # the vertex count is kept across redraws, so that rejections (more
        # frequent for many vertices) do not bias the count distribution
        e = rng.uniform(*recipe.elongation)
        f = rng.uniform(*recipe.flatness)
        axes = np.array([1.0, e, e * f])
        try:
            pts = _draw_points(rng, target, axes, recipe)
            for _ in range(recipe.repair_steps_per_vertex * target):
                v, t = hull(np.array(pts), allow_interior=True)
                if len(v) < target:          # interior points were dropped
                    pts = [*v, *_draw_points_more(rng, v, axes, recipe)]
                    continue
                flat = _flat_edge_opposites(v, t, CREASE_DEG)
                if not len(flat):
                    break
                # a nearly flat edge: move one of the two opposite vertices
                drop = int(rng.choice(flat))
                keep = np.delete(v, drop, axis=0)
                pts = [*keep, *_draw_points_more(rng, keep, axes, recipe)]
            else:
                rejections["nearly flat edge (not repaired)"] += 1
                continue
            check_polyhedron(v, t)
            poly = normalise(v, t)
        except ShapeError as exc:
            rejections[str(exc).split(":")[0]] += 1
            continue
        if poly.dims[2] / poly.dims[0] > recipe.max_s_over_l:
            rejections["near-spherical"] += 1
            continue
        return poly
    raise ShapeError(f"no valid grain in {recipe.max_tries} draws: {dict(rejections)}")


def _draw_points_more(rng, existing, axes, recipe):
    """One more point at the minimum separation from the existing ones."""
    sep = recipe.min_separation * 2 * axes.max()
    for _ in range(1000):
        x = _surface_point(rng, axes, recipe)
        if np.min(np.linalg.norm(np.asarray(existing) - x, axis=1)) >= sep:
            return [x]
    raise ShapeError("could not place points at the minimum separation")


def generate_library(n, seed=0, recipe=Recipe()):
    """``n`` grains drawn by :func:`generate_shape` from one generator
    seeded with ``seed`` (what ``python -m shapes build`` stores).

    Parameters
    ----------
    n : int
        The number of grains.
    seed : int
        Seed of ``numpy.random.default_rng``: the same seed and recipe give
        the same grains.
    recipe : Recipe
        The generator's parameters (default ``Recipe()``).

    Returns
    -------
    shapes : list of shapes.polyhedron.Polyhedron
        The grains, each in its normalised frame (d = 1).
    rejections : collections.Counter
        The redrawn attempts, by reason.

    Examples
    --------
    >>> shapes, rejections = generate_library(3, seed=0)
    >>> [s.n_faces == 2 * s.n_vertices - 4 for s in shapes]          # all faces triangles
    [True, True, True]
    >>> all(8 <= s.n_vertices <= 37 and abs(s.size - 1) < 1e-12 for s in shapes)
    True
    >>> again, _ = generate_library(3, seed=0)
    >>> all(np.array_equal(a.vertices, b.vertices) for a, b in zip(shapes, again))
    True
    """
    rng = np.random.default_rng(seed)
    rejections = Counter()
    shapes = [generate_shape(rng, recipe, rejections) for _ in range(n)]
    return shapes, rejections
