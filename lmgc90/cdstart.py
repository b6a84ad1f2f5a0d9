"""Starting states of the CD scene: a YADE snapshot, or a loose random gas.

Both give a :class:`Start`: the grains' shapes (local frame, m), their
poses, the box, the grains' and walls' dump ids, and the ``/shapes`` the
dump stores. Pure numpy (and h5py through the dump reader).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from postproc.schema import DumpReader

from .grains import bounding_size


class StartError(ValueError):
    """A starting state that cannot be used (one line).

    Attributes
    ----------
    args : tuple
        The one-line message.
    """


@dataclass
class Start:
    """The grains and box a CD run starts from.

    Attributes
    ----------
    kind : {"polyhedra", "spheres"}
    ids : (N,) int64, the grains' dump ids.
    wall_ids : (6,) int64, the walls' dump ids (x-, x+, y-, y+, z-, z+).
    positions : (N, 3) m, centres of mass.
    orientations : (N, 4) (w, x, y, z).
    shape_index : (N,) int, row of ``shapes`` (-1 for spheres).
    sizes : (N,) m, d (twice the largest centre-vertex distance, or the diameter).
    volumes : (N,) m^3.
    shapes : (vertices, triangles, faces) lists, in the local frame (m), or None.
    lo, hi : (3,) m, the box.
    source : str, what it was taken from.
    """

    kind: str
    ids: np.ndarray
    wall_ids: np.ndarray
    positions: np.ndarray
    orientations: np.ndarray
    shape_index: np.ndarray
    sizes: np.ndarray
    volumes: np.ndarray
    shapes: tuple
    lo: np.ndarray
    hi: np.ndarray
    source: str


def from_dump(path, stage="isotropic"):
    """The first snapshot of ``stage`` in a project dump (a YADE run's isotropic state).

    Parameters
    ----------
    path : str
        A dump (``postproc.schema``), e.g. a YADE run's ``run.h5``.
    stage : str
        The snapshot's stage.

    Returns
    -------
    Start
        The same grains, positions and orientations, the dump's ids and box.

    Raises
    ------
    StartError
        (one line) when the dump has no snapshot of that stage or no walls.
    """
    with DumpReader(path) as r:
        kind = r.sample_kind
        shapes = r.shapes()
        for k in range(len(r)):
            snap = r.read(k)
            if snap.stage == stage:
                break
        else:
            raise StartError(f"{path}: no snapshot of stage {stage!r}")
    if len(snap.wall_ids) != 6:
        raise StartError(f"{path}: snapshot {snap.name} has {len(snap.wall_ids)} walls, not 6 (a periodic cell?)")
    if kind == "polyhedra" and shapes is None:
        raise StartError(f"{path}: a polyhedra dump without /shapes")
    return Start(kind, np.asarray(snap.body_ids, np.int64), np.asarray(snap.wall_ids, np.int64),
                 np.asarray(snap.positions, float), np.asarray(snap.orientations, float),
                 np.asarray(snap.shape_index, np.int64), np.asarray(snap.sizes, float),
                 np.asarray(snap.volumes, float), shapes, np.asarray(snap.box_lo, float),
                 np.asarray(snap.box_hi, float), f"{path} snapshot {snap.name} (step {snap.step}, {stage})")


def loose(library, n, seed, initial_fraction=0.25, aspect=2.0, kind="polyhedra"):
    """A loose random state drawn as the YADE scene draws it for the same seed.

    The same draws in the same order as ``yade_scripts/scene/triaxial.py`` with
    ``placement='grains'``: sizes (exact class counts), shapes, orientations,
    then random sequential addition of the grains tested exactly
    (:func:`yade_scripts.scene.sample.place_exact_in_box`), so seed k gives the
    grains and the loose box of the YADE run of seed k. Spheres: the
    bounding spheres placed as in YADE's S2.

    Parameters
    ----------
    library : shapes.library.ShapeLibrary or None
        d = 1 shapes (polyhedra).
    n, seed : int
    initial_fraction, aspect : float
        The solid fraction of the loose box and its height over its side.
    kind : {"polyhedra", "spheres"}

    Returns
    -------
    Start
        ids 6..n+5 (walls 0..5), box [0, box].
    """
    from shapes import sizes
    from yade_scripts.scene import sample as sampling

    rng = np.random.default_rng(seed)
    d = sizes.sample_diameters(n, rng)
    if kind == "polyhedra":
        from shapes.overlap import OrientedGrains

        shape_of = rng.integers(len(library), size=n)
        quats = sampling.random_quaternions(n, rng)
        grains = OrientedGrains([(library[s][0] * d[k], library[s][1]) for k, s in enumerate(shape_of)], quats)
        box, centres = sampling.place_exact_in_box(d ** 3 * library.volume[shape_of], d / 2, initial_fraction,
                                                   aspect, rng, grains.overlaps)
        verts = [library[int(s)][0] * d[k] for k, s in enumerate(shape_of)]
        shapes = (verts, [library[int(s)][1] for s in shape_of], [library[int(s)][2] for s in shape_of])
        index = np.arange(n)
        volumes = d ** 3 * library.volume[shape_of]
        sz = np.array([bounding_size(v) for v in verts])
    else:
        box, centres = sampling.place_in_box(d, initial_fraction, aspect, rng)
        quats = np.tile([1.0, 0.0, 0.0, 0.0], (n, 1))
        shapes, index, volumes, sz = None, np.full(n, -1), np.pi / 6 * d ** 3, d
    return Start(kind, np.arange(6, n + 6, dtype=np.int64), np.arange(6, dtype=np.int64), np.asarray(centres, float),
                 np.asarray(quats, float), index, np.asarray(sz, float), np.asarray(volumes, float), shapes,
                 np.zeros(3), np.asarray(box, float), f"loose random state, seed {seed}, fraction {initial_fraction}")
