"""A per-contact tangential law for YADE's polyhedra.

Why: in Debian's YADE 2023.02a, ``Law2_PolyhedraGeom_PolyhedraPhys_Volumetric``
keeps the tangential force in one member of the law functor, so every contact
starts from the shear force of the contact processed before it (a contact at
rest picks up a sliding neighbour's force). We keep YADE's volumetric normal
law, give it zero shear stiffness (poisson = 0, so ks = 0 and its shear force
stays zero), and apply an incremental Coulomb law per contact here, with its
own history:

    f_t <- rotate(f_t)                 (YADE's PolyhedraGeom::rotate, with the
                                        orthonormal and twist axes of the step)
    f_t <- f_t - k_t * shearInc         (shearInc = tangential relative
                                        displacement of the step, from YADE)
    |f_t| <= mu |f_n|                   (Coulomb; mu = tan of the smaller
                                        friction angle of the pair)

f_t is the force on id2 by id1; id1 receives -f_t. Torques use the contact
point. A contact whose overlap volume is zero has no history. The force is
written back into ``phys.shearForce`` so that dumps and YADE tools see it.

:func:`update_shear` is the pure numpy kernel; :class:`TangentialLaw` is the
YADE side (a ``PyRunner`` calls it every step, after the InteractionLoop and
before NewtonIntegrator).
"""
from __future__ import annotations

import numpy as np


def update_shear(fs, normal, orth, twist, inc, kt, mu, fn):
    """One step of the incremental Coulomb law for many contacts.

    fs (C, 3) N previous shear force (zeros for new contacts); normal (C, 3)
    unit, id1 -> id2; orth, twist (C, 3) rotation vectors of the step;
    inc (C, 3) m tangential relative displacement of id2 w.r.t. id1;
    kt (C,) N/m; mu (C,) friction coefficient; fn (C,) N normal force
    magnitude. Returns (new shear forces (C, 3), (C,) bool sliding).
    """
    fs = fs - np.cross(fs, orth)
    fs = fs - np.cross(fs, twist)
    fs = fs - np.einsum("ij,ij->i", fs, normal)[:, None] * normal
    fs = fs - kt[:, None] * inc
    cap = mu * fn
    mag = np.sqrt(np.einsum("ij,ij->i", fs, fs))
    slide = mag > cap
    scale = np.where(slide, cap / np.where(mag > 0, mag, 1.0), 1.0)
    return fs * scale[:, None], slide


class TangentialLaw:
    """Per-contact tangential forces for polyhedra in a YADE scene.

    O : YADE's Omega; Vector3 : yade's Vector3 type.
    kt_of : callable (id1 array, id2 array, kn array) -> kt array (N/m).
    """

    def __init__(self, O, Vector3, kt_of):
        self.O = O
        self.Vector3 = Vector3
        self.kt_of = kt_of
        self.history = {}
        self.n_sliding = 0
        self.n_active = 0

    def __call__(self):
        O = self.O
        keys, rows, physs = [], [], []
        for i in O.interactions:
            if not i.isReal:
                continue
            p = i.phys
            mu = p.tangensOfFrictionAngle
            g = i.geom
            if mu <= 0 or not (g.penetrationVolume > 0):
                continue
            keys.append((i.id1, i.id2))
            physs.append(p)
            rows.append((*g.normal, *g.orthonormal_axis, *g.twist_axis, *g.shearInc,
                         *g.contactPoint, p.normalForce.norm(), mu, p.kn))
        history = self.history
        if not keys:
            self.history = {}
            self.n_active = self.n_sliding = 0
            return
        a = np.array(rows, float)
        ids = np.array(keys, np.int64)
        fs0 = np.array([history.get(k, (0.0, 0.0, 0.0)) for k in keys], float)
        kt = self.kt_of(ids[:, 0], ids[:, 1], a[:, 17])
        fs, slide = update_shear(fs0, a[:, 0:3], a[:, 3:6], a[:, 6:9], a[:, 9:12], kt,
                                 a[:, 16], a[:, 15])
        self.history = dict(zip(keys, map(tuple, fs)))
        self.n_active, self.n_sliding = len(keys), int(slide.sum())
        # forces and torques, summed per body
        cp = a[:, 12:15]
        bodies, inverse = np.unique(ids, return_inverse=True)
        i1, i2 = inverse.reshape(-1, 2).T
        pos = np.array([tuple(O.bodies[int(b)].state.pos) for b in bodies])
        F = np.zeros((len(bodies), 3))
        T = np.zeros((len(bodies), 3))
        np.add.at(F, i2, fs)
        np.add.at(F, i1, -fs)
        np.add.at(T, i2, np.cross(cp - pos[i2], fs))
        np.add.at(T, i1, np.cross(cp - pos[i1], -fs))
        V3 = self.Vector3
        forces = O.forces
        for b, f, t in zip(bodies.tolist(), F.tolist(), T.tolist()):
            forces.addF(b, V3(*f))
            forces.addT(b, V3(*t))
        for p, f in zip(physs, fs.tolist()):
            p.shearForce = V3(*f)
