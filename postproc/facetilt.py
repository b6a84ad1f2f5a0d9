"""The face-pair tilt of polyhedra contacts: how far from flush the two faces
that meet at a contact are, beside the overlap's thickness.

Claim 6 of the paper (face-face contacts in the strong, axial chains) rests on
counting face-face contacts. A rigid-grain count (LMGC90's common plane,
:mod:`postproc.commonplane`) calls two faces in contact when the tilted one
lies within a band of fixed size (a fraction of the grain) of the other; an
overlap-based count (:mod:`postproc.contactpoints`) when it lies within the
overlap's thickness, which shrinks as the contact stiffness grows. This
module measures the geometry both criteria threshold, so the two can be read
off one distribution.

Definitions, for a contact between polyhedra A (``id1``) and B (``id2``) with
unit normal n from A to B (global frame):

* each side's *contact face*: among the geometric faces that hold the side's
  support vertex (its vertex furthest along u = +n for A, -n for B), the one
  whose outward normal m is closest to u (the face the angular criterion of
  :mod:`postproc.contacttypes` tests);
* the side's *tilt* (rad): the angle between m and u, in [0, pi/2] for a
  support face (a convex body's faces at its support vertex all have
  m . u >= 0 up to round-off);
* the *face-pair tilt* phi (rad): the angle between m_A and -m_B, the two
  contact faces' normals in the global frame, in [0, pi]: 0 when the faces
  are parallel (flush), large for a vertex or an edge on a face;
* the *rise* (m): min(L_A, L_B) sin(phi), with L the faces' diameters (the
  largest distance between two of a face's vertices): how far the smaller
  face's far end stands off the other face's plane when one of its ends
  touches it (sin(min(phi, pi/2)), so the rise grows with phi). A count
  whose band is b calls the pair face-face roughly when the rise is below
  b: b = g + alpha h for the overlap-based point count
  (h = V / area, the overlap's mean thickness; g the penetration), b =
  tau ref for LMGC90's common plane (ref the centre-to-extreme-vertex
  distance, tau = 0.1).

Pure functions over arrays; no file I/O.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from shapes.overlap import rotation_matrices

from .contacttypes import first_degenerate_normal
from .errors import InputError

_BLOCK = 1 << 12


@dataclass
class FaceTilt:
    """Per contact (C,): ``tilt`` phi (rad), the angle between the two contact
    faces' normals; ``tilt1``, ``tilt2`` (rad) each side's contact face
    against its direction to the partner; ``size1``, ``size2`` (m) the two
    faces' diameters; ``rise`` (m) min(size1, size2) sin(min(phi, pi/2))."""

    tilt: np.ndarray
    tilt1: np.ndarray
    tilt2: np.ndarray
    size1: np.ndarray
    size2: np.ndarray
    rise: np.ndarray


def _angle(a, b):
    """(n,) rad, the angle between the rows of a and b (n, 3), from atan2 of
    the cross and dot products (accurate for small angles, unlike arccos)."""
    return np.arctan2(np.linalg.norm(np.cross(a, b), axis=1), np.einsum("ij,ij->i", a, b))


def _contact_face(tables, shape, rot, u):
    """(normal in the global frame (C, 3), tilt (C,) rad, diameter (C,) m) of
    each body's contact face for the unit directions u (C, 3) (global)."""
    local = np.einsum("cji,cj->ci", rot, u)                     # R^T u
    h = np.einsum("cvk,ck->cv", tables.vertices[shape].astype(float), local) + tables.pad[shape]
    top = np.argmax(h, axis=1)                                  # the support vertex
    rows = np.arange(len(shape))
    normals = tables.vertex_normals[shape, top].astype(float)   # (C, Dmax, 3), 0 for padding
    sizes = tables.vertex_face_size[shape, top].astype(float)
    cos = np.einsum("cdk,ck->cd", normals, local)
    cos[sizes == 0] = -np.inf
    best = np.argmax(cos, axis=1)
    m = normals[rows, best]
    m /= np.linalg.norm(m, axis=1)[:, None]
    return np.einsum("cij,cj->ci", rot, m), _angle(m, local), sizes[rows, best]


def face_pair_tilt(tables, shape1, quat1, shape2, quat2, normal):
    """The face-pair tilt of each contact (see the module's definitions).

    tables : :class:`postproc.contacttypes.ShapeTables` (``shape_tables``
    of the dump's shapes); shape1, shape2 (C,) int shape rows of the two
    bodies; quat1, quat2 (C, 4) orientations (w, x, y, z), local -> global;
    normal (C, 3) unit contact normals from body 1 to body 2 (global).
    Returns a :class:`FaceTilt`. Invariant under a common rotation of the
    bodies and the normal, and under swapping the sides (with n -> -n).
    Raises InputError for an unknown shape row, a zero or non-finite
    orientation, or a normal that is not a finite unit vector.
    """
    shape1 = np.asarray(shape1, np.int64)
    shape2 = np.asarray(shape2, np.int64)
    n = np.asarray(normal, float)
    q1 = np.asarray(quat1, float)
    q2 = np.asarray(quat2, float)
    C = len(shape1)
    if not (shape2.shape == (C,) and n.shape == (C, 3) and q1.shape == (C, 4) and q2.shape == (C, 4)):
        raise InputError(f"face_pair_tilt: shapes {shape1.shape}, {shape2.shape}, quaternions {q1.shape}, "
                         f"{q2.shape} and normals {n.shape} do not describe the same {C} contacts")
    S = len(tables.vertices)
    for s in (shape1, shape2):
        bad = (s < 0) | (s >= S)
        if bad.any():
            raise InputError(f"face_pair_tilt: contact {int(np.flatnonzero(bad)[0])} has shape row "
                             f"{int(s[bad][0])}, outside the {S} shapes")
    for q in (q1, q2):
        qn = np.linalg.norm(q, axis=1)
        bad = ~(np.isfinite(qn) & (qn > 0))
        if bad.any():
            raise InputError(f"face_pair_tilt: contact {int(np.flatnonzero(bad)[0])} has a zero or "
                             "non-finite orientation")
    k = first_degenerate_normal(n)
    if k >= 0:
        raise InputError(f"face_pair_tilt: contact {k} has a normal of length "
                         f"{float(np.linalg.norm(n[k]))!r}, not a unit vector")
    out = {k: np.empty(C) for k in ("tilt", "tilt1", "tilt2", "size1", "size2")}
    for s0 in range(0, C, _BLOCK):
        sl = slice(s0, min(s0 + _BLOCK, C))
        m1, t1, l1 = _contact_face(tables, shape1[sl], rotation_matrices(q1[sl]), n[sl])
        m2, t2, l2 = _contact_face(tables, shape2[sl], rotation_matrices(q2[sl]), -n[sl])
        out["tilt"][sl] = _angle(m1, -m2)
        out["tilt1"][sl], out["tilt2"][sl] = t1, t2
        out["size1"][sl], out["size2"][sl] = l1, l2
    rise = np.minimum(out["size1"], out["size2"]) * np.sin(np.minimum(out["tilt"], np.pi / 2))
    return FaceTilt(rise=rise, **out)


def tolerance_moves(tilt, tolerances):
    """The stability of a tilt criterion "face-face when phi < theta".

    tilt (n,) face-pair tilts; tolerances (k,) theta, in the same unit
    (rad or deg). Returns (share (k,), move (k,)): the share F(theta) of
    contacts the criterion calls face-face, and its move, the larger of
    F(2 theta) - F(theta) and F(theta) - F(theta / 2): the stability test of
    the contact types at half and twice the tolerance (target <= 0.03).
    For tilts log-uniform on [a, b] the move is log 2 / log(b / a) wherever
    theta / 2 and 2 theta lie in [a, b]: a criterion is stable only where the
    tilts leave a gap.
    """
    phi = np.sort(np.asarray(tilt, float))
    if phi.ndim != 1 or len(phi) == 0 or not np.all(np.isfinite(phi)):
        raise InputError("tolerance_moves: the tilts must be a non-empty 1-d array of finite values")
    t = np.asarray(tolerances, float)

    def share(x):
        return np.searchsorted(phi, x, side="left") / len(phi)

    F = share(t)
    return F, np.maximum(share(2 * t) - F, F - share(t / 2))
