"""Polyhedra contacts from the compiled kernel, driven from a YADE PyRunner.

YADE keeps the bodies (``Polyhedra`` shapes, ``PolyhedraMat``), the walls, the
servo, ``NewtonIntegrator`` and the dumps; no collider and no
``InteractionLoop`` run, so no polyhedra pair ever reaches YADE's CGAL code.
Every step, :class:`KernelContacts` (called by one ``PyRunner`` between
``ForceResetter`` and ``NewtonIntegrator``):

1. reads every particle's position and orientation (``__getinitargs__`` of
   YADE's Vector3/Quaternion: about 1 us per body, 8x cheaper than
   ``tuple()``) and the wall positions;
2. calls ``pc_engine_step`` once (``shapes/polycontact.c``: Verlet neighbour
   list on bounding spheres, early-outs, exact overlap, YADE's volumetric
   normal law F_n = k_V V n at the overlap centroid, the incremental Coulomb
   tangential law with per-pair history; OpenMP);
3. adds each particle's force and torque and each wall's force to
   ``O.forces`` (tuples: 0.45 us per call).

Conventions as in the dump schema: contact forces on id2 by id1, normals from
id1 to id2; a wall contact has the wall as id1 and its normal points into the
box. numpy + ctypes only (runs on YADE's Python).
"""
from __future__ import annotations

import os
import time

import numpy as np

try:
    from shapes import ckernel
except ImportError:           # run folder: lib/ckernel.py
    import ckernel  # type: ignore


class KernelError(RuntimeError):
    """The kernel refused a step (non-finite positions, out of memory)."""


class KernelContacts:
    """The kernel's contacts for one YADE scene.

    O : YADE's Omega. particles : (N,) body ids of the polyhedra. walls :
    six wall body ids in the order x-, x+, y-, y+, z-, z+, or None for a
    scene without walls. vertices,
    triangles : per particle, local vertices (V, 3) m and outward triangles
    (T, 3) as YADE holds them (``yadedump.polyhedra_shapes``). sizes : (N,)
    m. k_v : N/m^3 volumetric stiffness. kt_coef : N/m^3, k_t = kt_coef *
    d_pair^2 with d_pair = 2 d1 d2 / (d1 + d2) (d of the particle for a wall).
    mu, mu_wall : friction coefficients. skin : m, Verlet margin of the
    neighbour list. threads : OpenMP threads (0: every core). A step with
    fewer than 400 pairs and wall tests runs on one thread anyway.
    """

    def __init__(self, O, particles, walls, vertices, triangles, sizes, k_v, kt_coef, mu, mu_wall,
                 skin, threads=0):
        self.O = O
        self.particles = np.asarray(particles, np.int64)
        self.walls = [int(w) for w in walls] if walls is not None else []
        if len(self.walls) not in (0, 6):
            raise ValueError("six walls expected (x-, x+, y-, y+, z-, z+), or None")
        self.states = [O.bodies[int(i)].state for i in self.particles]
        self.wall_states = [O.bodies[w].state for w in self.walls]
        n = len(self.particles)
        self.voff = ckernel.i32(np.concatenate([[0], np.cumsum([len(v) for v in vertices])]))
        self.toff = ckernel.i32(np.concatenate([[0], np.cumsum([len(t) for t in triangles])]))
        self.v = ckernel.f64(np.concatenate([np.asarray(v, float) for v in vertices]))
        self.t = ckernel.i32(np.concatenate([np.asarray(t) for t in triangles]))
        self.shape = ckernel.i32(np.arange(n))
        self.size = ckernel.f64(sizes)
        self.wall_axis = ckernel.i32([0, 0, 1, 1, 2, 2])
        self.wall_sign = ckernel.f64([1, -1, 1, -1, 1, -1])    # inward normals
        self.threads = int(threads) if threads else (os.cpu_count() or 1)
        self.lib = ckernel.load()
        self.handle = self.lib.pc_engine_new(
            n, ckernel.iptr(self.voff), ckernel.dptr(self.v), ckernel.iptr(self.toff), ckernel.iptr(self.t),
            n, ckernel.iptr(self.shape), ckernel.dptr(self.size), len(self.walls), ckernel.iptr(self.wall_axis),
            ckernel.dptr(self.wall_sign), float(k_v), float(kt_coef), float(mu), float(mu_wall), float(skin),
            self.threads)
        if not self.handle:
            raise KernelError("could not create the contact kernel (out of memory?)")
        self.force = np.zeros((n, 3))
        self.torque = np.zeros((n, 3))
        self.wall_force = np.zeros((max(len(self.walls), 1), 3))
        self.stat = np.zeros(8)
        self.wall_pos = np.zeros(6)
        self.seconds = {"read": 0.0, "kernel": 0.0, "apply": 0.0}
        self.calls = 0
        self.touch_steps = 0          # sum over steps of touching contacts (pairs + walls)

    def __del__(self):
        if getattr(self, "handle", None):
            self.lib.pc_engine_free(self.handle)
            self.handle = None

    def _read(self):
        rows = [s.pos.__getinitargs__() + s.ori.__getinitargs__() for s in self.states]
        a = np.array(rows, float)
        pos = np.ascontiguousarray(a[:, :3])
        quat = np.ascontiguousarray(a[:, 3:7])        # (w, x, y, z)
        for k, s in enumerate(self.wall_states):
            self.wall_pos[k] = s.pos[k // 2]
        return pos, quat

    def __call__(self):
        t0 = time.perf_counter()
        pos, quat = self._read()
        t1 = time.perf_counter()
        err = self.lib.pc_engine_step(self.handle, ckernel.dptr(pos), ckernel.dptr(quat),
                                      ckernel.dptr(self.wall_pos), ckernel.dptr(self.force),
                                      ckernel.dptr(self.torque), ckernel.dptr(self.wall_force),
                                      ckernel.dptr(self.stat))
        t2 = time.perf_counter()
        if err == -2:
            raise KernelError("particle positions are not finite")
        if err:
            raise KernelError(f"contact kernel step failed (code {err}: out of memory)")
        forces = self.O.forces
        active = np.flatnonzero(np.any(self.force != 0, axis=1) | np.any(self.torque != 0, axis=1))
        for b, f, t in zip(self.particles[active].tolist(), self.force[active].tolist(),
                           self.torque[active].tolist()):
            forces.addF(b, tuple(f))
            forces.addT(b, tuple(t))
        for w, f in zip(self.walls, self.wall_force.tolist()):
            forces.addF(w, tuple(f))
        t3 = time.perf_counter()
        s = self.seconds
        s["read"] += t1 - t0
        s["kernel"] += t2 - t1
        s["apply"] += t3 - t2
        self.calls += 1
        self.touch_steps += int(self.stat[0] + self.stat[1])

    # ------------------------------------------------------------ summaries
    @property
    def n_contacts(self):
        """Touching contacts of the last step (particle pairs + wall contacts)."""
        return int(self.stat[0] + self.stat[1])

    @property
    def n_pairs(self):
        """Pairs in the neighbour list (touching or not)."""
        return int(self.stat[2])

    def unbalanced(self):
        """YADE's unbalanced-force ratio from the kernel's sums: mean |net
        force| over the particles / mean |contact force| (NaN without
        contacts)."""
        n = self.n_contacts
        if n == 0:
            return float("nan")
        return float((self.stat[6] / len(self.particles)) / (self.stat[4] / n))

    def memory_bytes(self):
        return int(self.lib.pc_engine_memory(self.handle))

    def contacts(self):
        """The contacts of the last step as the dump's ``contacts`` dict
        (ids are YADE body ids), with the footprint."""
        n = int(self.lib.pc_engine_count(self.handle))
        i1 = np.zeros(n, np.int32)
        i2 = np.zeros(n, np.int32)
        point, normal, fnrm, ftan = (np.zeros((n, 3)) for _ in range(4))
        vol, area = np.zeros(n), np.zeros(n)
        fp = np.zeros((n, 2))
        m = self.lib.pc_engine_contacts(self.handle, n, ckernel.iptr(i1), ckernel.iptr(i2), ckernel.dptr(point),
                                        ckernel.dptr(normal), ckernel.dptr(fnrm), ckernel.dptr(ftan),
                                        ckernel.dptr(vol), ckernel.dptr(fp), ckernel.dptr(area))
        walls = np.asarray(self.walls or [-1], np.int64)
        id1 = np.where(i1[:m] >= 0, self.particles[np.maximum(i1[:m], 0)],
                       walls[np.clip(-1 - i1[:m], 0, len(walls) - 1)])
        id2 = self.particles[i2[:m]]
        return {"id1": id1.astype(np.int64), "id2": id2.astype(np.int64), "point": point[:m],
                "normal": normal[:m], "force_normal": fnrm[:m], "force_tangential": ftan[:m],
                "overlap": vol[:m], "footprint": fp[:m], "footprint_area": area[:m]}

    def timing(self):
        """Seconds spent reading states, in the kernel, and applying forces."""
        return dict(self.seconds, calls=self.calls)
