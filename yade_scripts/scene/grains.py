"""The scene's grains: drawn (sizes, shapes, orientations, places in the
initial box) by :func:`draw_grains`, numpy only, then made YADE bodies, six
walls first and the particles after them, by :func:`add_walls` and
:func:`add_particles` (YADE's Python only).

The draws come from one generator seeded by the run's ``seed``, in a fixed
order (sizes, then for polyhedra the shapes and orientations, then the
places), so that a seed gives the same sample, bit for bit, on every run.
Lengths are in m, the library's grains have d = 1 (Azema, Radjai & Saussine
2009: the sizes of S1 and S2 are the same distribution).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from shapes import sizes
from shapes.library import ShapeLibrary
from shapes.overlap import OrientedGrains

from . import sample, timestep


@dataclass
class Grains:
    """A drawn sample of ``n`` grains (polyhedra or spheres).

    Attributes
    ----------
    d : numpy.ndarray
        (n,) m, the grains' sizes (:func:`shapes.sizes.sample_diameters`).
    d_mean : float
        m, their mean.
    box0 : numpy.ndarray
        (3,) m, the initial box's lengths (its corner at the origin).
    centres : numpy.ndarray
        (n, 3) m, the grains' initial centres.
    lib : shapes.library.ShapeLibrary or None
        The polyhedra's library (d = 1); None for spheres.
    shape_of : numpy.ndarray or None
        (n,) int, each grain's shape in ``lib``.
    quats : numpy.ndarray or None
        (n, 4) unit quaternions (w, x, y, z), each grain's orientation.
    a_face : float or None
        The mean face area of the library's shapes (d = 1, so in d^2).
    max_face : numpy.ndarray or None
        (len(lib),) the largest face area of each shape (d = 1).
    rot_mass : numpy.ndarray or None
        (len(lib),) each shape's rotational mass factor
        (:func:`yade_scripts.scene.timestep.rotational_mass`; d = 1, unit
        density).
    """

    d: np.ndarray
    d_mean: float
    box0: np.ndarray
    centres: np.ndarray
    lib: ShapeLibrary | None = None
    shape_of: np.ndarray | None = None
    quats: np.ndarray | None = None
    a_face: float | None = None
    max_face: np.ndarray | None = None
    rot_mass: np.ndarray | None = None

    @property
    def poly(self):
        """True for polyhedra (S1).

        Returns
        -------
        bool
        """
        return self.lib is not None

    def volumes(self):
        """The polyhedra's volumes, from the library, scaled.

        Returns
        -------
        numpy.ndarray
            (n,) m^3: d^3 times the shape's volume at d = 1.
        """
        return self.d ** 3 * self.lib.volume[self.shape_of]

    def vertices(self):
        """The polyhedra's vertices in the library's frame, scaled.

        Returns
        -------
        list of numpy.ndarray
            Per grain, (V, 3) m: the library shape's vertices (d = 1, centre
            of mass at the origin, principal axes) times the grain's d.
        """
        return [self.lib[int(s_k)][0] * d_k for s_k, d_k in zip(self.shape_of, self.d)]

    def triangles(self):
        """The polyhedra's triangles, as the library holds them.

        Returns
        -------
        list of numpy.ndarray
            Per grain, (T, 3) int: vertex indices of :meth:`vertices`.
        """
        return [self.lib[int(s_k)][1] for s_k in self.shape_of]


def draw_grains(n, seed, polyhedra, library=None, placement="grains", initial_fraction=0.25, aspect=2.0):
    """Draw a sample: sizes, then (polyhedra) shapes and orientations, then
    places in the initial box.

    Parameters
    ----------
    n : int
        Number of grains.
    seed : int
        The generator's seed (``numpy.random.default_rng``).
    polyhedra : bool
        True for S1 (polyhedra of ``library``), False for S2 (spheres).
    library : str, optional
        The polyhedra's shape library (an HDF5 file of
        :mod:`shapes.library`); not read for spheres.
    placement : {"grains", "spheres"}
        "grains": random sequential addition of the polyhedra themselves,
        tested exactly (:func:`yade_scripts.scene.sample.place_exact_in_box`);
        "spheres" (and every sphere sample): of their bounding spheres
        (:func:`yade_scripts.scene.sample.place_in_box`).
    initial_fraction : float
        The packing fraction at the start: of the grains (placement
        "grains") or of the bounding spheres.
    aspect : float
        H / L of the initial box.

    Returns
    -------
    Grains
        The drawn sample.

    Examples
    --------
    >>> g = draw_grains(30, 4, False, initial_fraction=0.3)
    >>> g.d.shape, g.centres.shape, g.box0[2] / g.box0[0], g.lib is None
    ((30,), (30, 3), 2.0, True)
    >>> bool(np.all(g.centres > 0) and np.all(g.centres < g.box0))
    True
    """
    rng = np.random.default_rng(seed)
    d = sizes.sample_diameters(n, rng)               # m, exact class counts
    d_mean = float(d.mean())
    if not polyhedra:
        box0, centres = sample.place_in_box(d, initial_fraction, aspect, rng)
        return Grains(d, d_mean, box0, centres)
    lib = ShapeLibrary(library)
    shape_of = rng.integers(len(lib), size=n)
    quats = sample.random_quaternions(n, rng)
    face_area = []                                          # per library shape, d = 1
    for s in range(len(lib)):
        v, t, _ = lib[s]
        face_area.append(0.5 * np.linalg.norm(np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]]), axis=1))
    a_face = float(np.mean(np.concatenate(face_area)))     # mean face area, d = 1
    max_face = np.array([a.max() for a in face_area])
    rot_mass = np.array([timestep.rotational_mass(lib.volume[s], np.diag(lib.inertia[s]), lib[s][0])
                         for s in range(len(lib))])       # d = 1, unit density
    if placement == "grains":         # the grains themselves never overlap (exact test, shapes/overlap.py)
        oriented = OrientedGrains([(lib[s][0] * d[k], lib[s][1]) for k, s in enumerate(shape_of)], quats)
        box0, centres = sample.place_exact_in_box(d ** 3 * lib.volume[shape_of], d / 2, initial_fraction, aspect,
                                                  rng, oriented.overlaps)
    else:                             # bounding spheres never overlap
        box0, centres = sample.place_in_box(d, initial_fraction, aspect, rng)
    return Grains(d, d_mean, box0, centres, lib, shape_of, quats, a_face, max_face, rot_mass)


def add_walls(O, box0, material):
    """Six walls of the box [0, box0], fixed in every degree of freedom
    (the controller gives them velocities), in the dump's order x-, x+,
    y-, y+, z-, z+ (YADE's Python only).

    Parameters
    ----------
    O : yade.wrapper.Omega
        YADE's scene.
    box0 : numpy.ndarray
        (3,) m, the box's lengths.
    material : yade.wrapper.Material
        The walls' material.

    Returns
    -------
    list of int
        The walls' body ids, in that order.
    """
    from yade import utils

    walls = []
    for axis in range(3):
        for side, pos in ((-1, 0.0), (1, box0[axis])):
            w = utils.wall(pos, axis=axis, sense=0, material=material)
            w.state.blockedDOFs = "xyzXYZ"
            walls.append(O.bodies.append(w))
    return walls


def add_particles(O, grains, material, density, kernel):
    """The grains as YADE bodies, at their centres and orientations (YADE's
    Python only).

    With the compiled kernel (``kernel``), a polyhedron's pose, mass and
    inertia come from the library, in its own frame (centre of mass,
    principal axes) and vertex order: YADE re-hulls each Polyhedra with
    CGAL, which gives another vertex order and frame from process to
    process, so that the same seed gives the same run, bit for bit. On
    YADE's own contact path the orientation is composed with the frame
    YADE chose.

    Parameters
    ----------
    O : yade.wrapper.Omega
        YADE's scene.
    grains : Grains
        The drawn sample.
    material : yade.wrapper.Material
        The grains' material.
    density : float
        kg/m^3.
    kernel : bool
        The polyhedra's contacts come from the compiled kernel.

    Returns
    -------
    numpy.ndarray
        (n,) int, the particles' body ids, in the grains' order.
    """
    from yade import polyhedra_utils, utils
    from yade.minieigenHP import Quaternion, Vector3

    d, lib = grains.d, grains.lib
    particles = []
    for k in range(len(d)):
        if grains.poly:
            s_k = int(grains.shape_of[k])
            v, _, _ = lib[s_k]
            b = polyhedra_utils.polyhedra(material, v=[tuple(x) for x in v * d[k]])
            w, x, y, z = grains.quats[k]
            if kernel:
                b.state.ori = Quaternion(w, x, y, z)
                b.state.mass = density * d[k] ** 3 * float(lib.volume[s_k])
                b.state.inertia = Vector3(*(density * d[k] ** 5 * np.diag(lib.inertia[s_k])))
            else:
                b.state.ori = Quaternion(w, x, y, z) * b.state.ori
        else:
            b = utils.sphere((0, 0, 0), d[k] / 2, material=material)
        b.state.pos = tuple(grains.centres[k])
        particles.append(O.bodies.append(b))
    return np.array(particles)
