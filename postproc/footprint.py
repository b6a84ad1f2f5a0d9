"""Contact groups of polyhedra from the overlap's footprint: simple, double, triple.

The seed paper's contact-dynamics code (LMGC90) counts the contact points
of a pair of polyhedra: one for vertex-face and (crossed) edge-edge
contacts, two for edge-face, three or more for face-face. A soft-contact
(volumetric) model has the same information in the overlap polyhedron of
the pair: its *footprint*, the shadow of the overlap on the contact plane,
is

* a small blob, a few overlap depths h wide in every direction, where a
  vertex or an edge crossing another edge dips into the partner (one point);
* a strip, long in one direction (up to an edge length) and a few h thin
  in the other, where an edge lies on a face (two points at its ends);
* a patch, wide in both directions, where two faces lie on each other
  (three points or more).

Criterion. With L1 >= L2 the principal extents of the footprint (m; the
kernel's ``footprint``, see ``shapes/overlap.py`` and docs/dump-format.md)
and d the pair's size (m, d = 2 d1 d2 / (d1 + d2), the kernel's d_pair, with
d1, d2 the particles' sizes), a particle-particle contact is

    simple   if L1 < t d,
    double   if L1 >= t d > L2,
    triple   if L2 >= t d,

with one threshold t (``DEFAULT_THRESHOLD``, in units of d). It counts the
dimension of the contact set: 0 (a point), 1 (a line), 2 (an area) at the
resolution t d.

The threshold is a convention, not a gap: on the S1 runs measured so far
(kappa = 300, docs/contact-types.md) L1/d and L2/d have broad unimodal
distributions (the overlaps are about 0.005 d thick, V/area, and the blunt
vertices of the library grains spread them over about ten depths, so
vertex contacts already have footprints of 0.03-0.1 d, against edges of
0.15-0.5 d). t = 0.1 d is a third of the mean edge length: a contact counts
as a line or an area when it spans at least that. The proportions depend on
t (the stability columns ``ct_frac_*_lo/_hi`` measure it).

Everything here is a pure function over arrays; :func:`recompute` calls the
compiled kernel (:mod:`shapes.overlap`) for dumps that carry no footprint.
"""
from __future__ import annotations

import numpy as np

from .errors import InputError

SIMPLE, DOUBLE, TRIPLE = 0, 1, 2
GROUPS = ("simple", "double", "triple")
DEFAULT_THRESHOLD = 0.1           # t, in units of the pair size d: a convention (see docs/contact-types.md), no gap


def pair_size(d1, d2):
    """(C,) m, the size of a pair: the harmonic mean 2 d1 d2 / (d1 + d2) of
    the particles' sizes d1, d2 (C,) m (the contact kernel's d_pair).

    Parameters
    ----------
    d1, d2 : array_like, shape (C,)
        m, the sizes of the two particles (a dump's ``bodies/size``: twice
        the largest centre-to-vertex distance of a polyhedron, twice the
        radius of a sphere); any broadcastable shapes.

    Returns
    -------
    ndarray of float, shape (C,)
        m, d = 2 d1 d2 / (d1 + d2) (not checked: sizes summing to 0 give
        NaN or inf).
    """
    d1 = np.asarray(d1, float)
    d2 = np.asarray(d2, float)
    return 2 * d1 * d2 / (d1 + d2)


def check_threshold(threshold, what="--threshold"):
    """The threshold as a float; InputError unless finite and in (0, 1).

    Parameters
    ----------
    threshold : object
        The threshold t, in units of the pair size d: a number or a string
        of one.
    what : str, optional
        The option's name in the message (default "--threshold").

    Returns
    -------
    float
        t, finite, 0 < t < 1.

    Raises
    ------
    InputError
        Not a number, not finite, or outside (0, 1).
    """
    try:
        t = float(threshold)
    except (TypeError, ValueError):
        raise InputError(f"{what} must be a number, got {threshold!r}") from None
    if not (np.isfinite(t) and 0 < t < 1):
        raise InputError(f"{what} must be in (0, 1) (a fraction of the pair size d), got {threshold!r}")
    return t


def relative_extents(extents, d):
    """(C, 2) footprint extents over the pair size, largest first.

    extents (C, 2) m (L1, L2 in any order); d (C,) m, > 0. Raises InputError
    naming the first contact with a non-finite or negative extent, or a
    non-positive or non-finite size.

    Parameters
    ----------
    extents : array_like, shape (C, 2)
        m, the footprint's principal extents L1, L2 in any order (the
        kernel's ``contacts/footprint`` or :func:`recompute`), finite and
        >= 0.
    d : array_like, shape (C,)
        m, the pair sizes (:func:`pair_size`), finite and > 0.

    Returns
    -------
    ndarray of float, shape (C, 2)
        Dimensionless (L1/d, L2/d) with L1 >= L2.

    Raises
    ------
    InputError
        Arrays of other shapes, or as said above (one line).
    """
    x = np.asarray(extents, float)
    d = np.asarray(d, float)
    if x.ndim != 2 or x.shape[1] != 2 or d.shape != (len(x),):
        raise InputError(f"footprint must be (C, 2) with sizes (C,), got {x.shape} and {d.shape}")
    bad = ~np.isfinite(x).all(axis=1) | (x < 0).any(axis=1)
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        raise InputError(f"contact {k}: footprint {x[k].tolist()} is not finite and >= 0")
    bad = ~(np.isfinite(d) & (d > 0))
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        raise InputError(f"contact {k}: pair size {float(d[k])!r} is not finite and > 0")
    r = x / d[:, None]
    return np.sort(r, axis=1)[:, ::-1]


def footprint_groups(rel, threshold=DEFAULT_THRESHOLD):
    """(C,) int8 group (SIMPLE, DOUBLE, TRIPLE) of each contact.

    rel (C, 2) the footprint extents L1 >= L2 over the pair size
    (:func:`relative_extents`); threshold t in units of d. simple: L1 < t;
    triple: L2 >= t; double otherwise. Two comparisons per contact.

    Parameters
    ----------
    rel : array_like, shape (C, 2)
        Dimensionless L1/d >= L2/d (:func:`relative_extents`); a NaN
        compares as below t.
    threshold : float, optional
        t, in units of d (default ``DEFAULT_THRESHOLD`` = 0.1).

    Returns
    -------
    ndarray of int8, shape (C,)
        The number of extents >= t: SIMPLE 0 (L1 < t d: a point, one contact
        point in LMGC90's count), DOUBLE 1 (L1 >= t d > L2: a line, two),
        TRIPLE 2 (L2 >= t d: an area, three or more).
    """
    rel = np.asarray(rel)
    t = rel.dtype.type(threshold)
    return (rel[:, 0] >= t).astype(np.int8) + (rel[:, 1] >= t).astype(np.int8)


class Geometry:
    """The dump's shapes packed for the contact kernel (to recompute
    footprints). vertices, triangles: one (V, 3) m / (T, 3) int array per
    shape, local frames, as in a dump's ``/shapes``.

    Parameters
    ----------
    vertices : sequence of array_like, each of shape (V_s, 3)
        m, each shape's vertices in its local frame.
    triangles : sequence of array_like of int, each of shape (T_s, 3)
        Each shape's outward triangles (vertex indices).

    Attributes
    ----------
    table : shapes.overlap.ShapeTable
        The shapes as the compiled overlap kernel takes them.

    Raises
    ------
    InputError
        Shapes the kernel rejects (its message, prefixed "/shapes: ").
    """

    def __init__(self, vertices, triangles):
        # loads the compiled kernel: only when overlaps must be recomputed
        from shapes.overlap import OverlapError, ShapeTable

        try:
            self.table = ShapeTable(list(zip(vertices, triangles)))
        except OverlapError as exc:
            raise InputError(f"/shapes: {exc}") from None


def recompute(geometry, shape1, pos1, quat1, shape2, pos2, quat2, threads=0):
    """The overlap of each pair from the shapes and poses, as the kernel
    computes it during a run (:func:`shapes.overlap.batch_overlap`; A = id1,
    B = id2).

    geometry :class:`Geometry`; shape1, shape2 (P,) shape rows; pos (P, 3) m;
    quat (P, 4) (w, x, y, z) local -> global. Returns (footprint (P, 2) m,
    largest first; area (P,) m^2; volume (P,) m^3). A pair whose grains do
    not overlap gets volume 0 and footprint (0, 0). Bad poses or indices
    raise InputError.

    Parameters
    ----------
    geometry : Geometry
        The dump's shapes.
    shape1, shape2 : array_like of int, shape (P,)
        The shape rows of A = id1 and B = id2.
    pos1, pos2 : array_like, shape (P, 3)
        m, their centre-of-mass positions.
    quat1, quat2 : array_like, shape (P, 4)
        Their orientations (w, x, y, z), local -> global.
    threads : int, optional
        OpenMP threads of the kernel (0, the default: all cores); the
        results do not depend on it.

    Returns
    -------
    footprint : ndarray, shape (P, 2)
        m, the principal extents L1 >= L2 of the overlap's shadow on the
        contact plane.
    area : ndarray, shape (P,)
        m^2, the area of that shadow.
    volume : ndarray, shape (P,)
        m^3, the overlap volume V (so V / area is its mean thickness).

    Raises
    ------
    InputError
        What the kernel rejects (its message, prefixed "recomputing
        footprints: ").
    """
    # loads the compiled kernel: only when overlaps must be recomputed
    from shapes.overlap import OverlapError, batch_overlap

    try:
        r = batch_overlap(geometry.table, shape1, pos1, quat1, shape2, pos2, quat2, threads=threads)
    except OverlapError as exc:
        raise InputError(f"recomputing footprints: {exc}") from None
    return r["footprint"], r["area"], r["volume"]
