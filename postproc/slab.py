"""The force network in a slab: what is drawn of a packing in 2-D.

A slab is the layer of thickness ``thickness`` (m) about the mid-plane of
the box normal to ``axis`` (the y axis by default, so that the picture shows
x across and the compression axis z upwards). It holds

* the sections of the grains by the mid-plane: convex polygons for polyhedra
  (:func:`shapes.sections.polyhedron_section` of each posed grain) and discs
  for spheres; grains the plane misses are not drawn;
* the particle-particle contacts whose contact point lies in the slab, as
  segments between the two centres (x1 and x1 + l, l the branch vector, so
  that a contact across a periodic boundary is drawn whole), with their
  normal force and, when given, their contact-type label.

Coordinates in the picture are the two other axes in increasing order (x, z
for axis = 1), in m.
"""
from __future__ import annotations

import numpy as np

from shapes.sections import polyhedron_section, sphere_section

from .axes import quaternion_matrices
from .contactset import resolve


def slab(snap, shapes=None, axis=1, thickness=None, labels=None):
    """The slab of ``snap`` (see the module docstring).

    Parameters
    ----------
    snap : Snapshot
    shapes : tuple of three lists, optional
        the dump's shapes (per shape: its vertices, triangles and faces);
        needed for polyhedra.
    axis : int
        0, 1 or 2, the slab's normal.
    thickness : float, optional
        m, default 1.5 mean particle sizes.
    labels : array of str, optional
        (C,) labels of the snapshot's contacts (e.g. contact types).

    Returns
    -------
    dict with ``polygons`` (list of (K, 2) m), ``discs`` ((D, 2) centres m,
    (D,) radii m), ``segments`` ((S, 2, 2) m), ``fn`` ((S,) N, normal force),
    ``labels`` ((S,) or None), ``plane`` (m, the mid-plane's coordinate),
    ``thickness`` (m), ``axes`` (the two in-plane axes), ``extent``
    ((2, 2) m: lo and hi of the box in those axes).
    """
    cs = resolve(snap)
    keep = [a for a in range(3) if a != axis]
    lo, hi = np.asarray(snap.box_lo, float), np.asarray(snap.box_hi, float)
    c = 0.5 * (lo[axis] + hi[axis])
    sizes = np.asarray(snap.sizes, float)
    t = 1.5 * float(np.mean(sizes)) if thickness is None else float(thickness)
    n = np.eye(3)[axis]
    point = n * c
    polygons, disc_c, disc_r = [], [], []
    kind = np.asarray(snap.body_kind)
    pos = np.asarray(snap.positions, float)
    near = np.flatnonzero(np.abs(pos[:, axis] - c) < sizes)       # a loose filter: the sections decide
    poly = near[kind[near] == 1]
    if len(poly):
        if shapes is None:
            raise ValueError(f"snapshot {snap.name}: polyhedra but no shapes to cut")
        verts, tris = shapes[0], shapes[1]
        R = quaternion_matrices(np.asarray(snap.orientations)[poly])
        for row, Rb in zip(poly, R):
            s = int(snap.shape_index[row])
            v = np.asarray(verts[s]) @ Rb.T + pos[row]
            sec = polyhedron_section(v, tris[s], point, n)
            if len(sec):
                polygons.append(sec[:, keep])
    for row in near[kind[near] == 0]:
        sec = sphere_section(pos[row], 0.5 * sizes[row], point, n)
        if sec is not None:
            disc_c.append(sec[0][keep])
            disc_r.append(sec[1])
    pp = np.flatnonzero(cs.pp)
    pts = np.asarray(snap.point, float)[pp]
    inside = np.abs(pts[:, axis] - c) <= 0.5 * t
    sel = pp[inside]
    x1 = pos[cs.i1[sel]]
    seg = np.stack([x1[:, keep], (x1 + cs.arm[sel])[:, keep]], axis=1)
    return {"polygons": polygons, "discs": (np.array(disc_c).reshape(-1, 2), np.array(disc_r)),
            "segments": seg, "fn": cs.normal_force[sel],
            "labels": None if labels is None else np.asarray(labels)[sel],
            "plane": c, "thickness": t, "axes": tuple(keep),
            "extent": np.array([lo[keep], hi[keep]])}
