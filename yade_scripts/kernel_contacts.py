"""Polyhedra contacts from the compiled kernel, driven from a YADE PyRunner.

YADE keeps the bodies (``Polyhedra`` shapes, ``PolyhedraMat``), the walls, the
servo, ``NewtonIntegrator`` and the dumps; no collider and no
``InteractionLoop`` run, so no polyhedra pair ever reaches YADE's CGAL code.
Every step, :class:`KernelContacts` (called by one ``PyRunner`` between
``ForceResetter`` and ``NewtonIntegrator``):

1. reads every particle's position and orientation (``__getinitargs__`` of
   YADE's Vector3/Quaternion: 0.44 us per body, the cheapest of the ways
   timed by ``benchmarks/bench_roundtrip.py``) and the wall positions;
2. calls the engine once (``shapes/engine.py`` on ``polycontact.c``: Verlet neighbour
   list on bounding spheres, early-outs, exact overlap, YADE's volumetric
   normal law F_n = k_V V n at the overlap centroid, the incremental Coulomb
   tangential law with per-pair history; OpenMP);
3. adds each particle's force and torque and each wall's force to
   ``O.forces`` (the bound ``addF``/``addT`` mapped over the rows as lists:
   0.37 us per body, 1.2x cheaper than a loop over tuples). YADE 2023.02a's
   Python has no bulk accessor of states or forces, so these per-body calls
   are the floor of the round trip.

Conventions as in the dump schema: contact forces on id2 by id1, normals from
id1 to id2; a wall contact has the wall as id1 and its normal points into the
box. numpy + ctypes only (runs on YADE's Python).
"""
from __future__ import annotations

import os
import time

import numpy as np

from shapes.engine import ContactEngine, EngineError


class KernelError(RuntimeError):
    """The kernel refused a step (non-finite positions, out of memory)."""


class KernelContacts:
    """The kernel's contacts for one YADE scene (a ``PyRunner`` calls it
    every step).

    O : YADE's Omega. particles : (N,) body ids of the polyhedra. walls :
    six wall body ids in the order x-, x+, y-, y+, z-, z+, or None for a
    scene without walls. vertices, triangles : per particle, local vertices
    (V, 3) m and outward triangles (T, 3) as YADE holds them
    (``yadedump.polyhedra_shapes``). sizes : (N,) m. k_v : N/m^3 volumetric
    stiffness. kt_coef : N/m^3, k_t = kt_coef * d_pair^2 with d_pair = 2 d1
    d2 / (d1 + d2) (d of the particle for a wall). mu, mu_wall : friction
    coefficients. skin : m, Verlet margin of the neighbour list. threads :
    OpenMP threads (0: every core). See :mod:`shapes.engine`.
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
        self.threads = int(threads) if threads else (os.cpu_count() or 1)
        self.engine = ContactEngine(vertices, triangles, np.arange(len(self.particles)), sizes, k_v, kt_coef,
                                    mu, mu_wall, skin, walls=bool(self.walls), threads=self.threads)
        self.wall_pos = np.zeros(6)
        self.seconds = {"read": 0.0, "kernel": 0.0, "apply": 0.0}
        self.calls = 0
        self.touch_steps = 0          # sum over steps of touching contacts (pairs + walls)

    def rebind(self):
        """Take the body states from the scene now in ``O`` (after ``O.load``
        of a checkpoint the old State objects belong to the discarded scene)."""
        self.states = [self.O.bodies[int(i)].state for i in self.particles]
        self.wall_states = [self.O.bodies[w].state for w in self.walls]

    def counters(self):
        """The counters a checkpoint carries (timing, calls, touch steps)."""
        return {"seconds": dict(self.seconds), "calls": self.calls, "touch_steps": self.touch_steps}

    def set_counters(self, c):
        self.seconds = {k: float(v) for k, v in c["seconds"].items()}
        self.calls, self.touch_steps = int(c["calls"]), int(c["touch_steps"])

    def _read(self):
        rows = [s.pos.__getinitargs__() + s.ori.__getinitargs__() for s in self.states]
        a = np.array(rows, float).reshape(-1, 7)
        for k, s in enumerate(self.wall_states):
            self.wall_pos[k] = s.pos[k // 2]
        return a[:, :3], a[:, 3:7]                      # quaternion (w, x, y, z)

    def __call__(self):
        t0 = time.perf_counter()
        pos, quat = self._read()
        t1 = time.perf_counter()
        try:
            force, torque, wall_force = self.engine.step(pos, quat, self.wall_pos)
        except EngineError as exc:
            raise KernelError(str(exc)) from None
        t2 = time.perf_counter()
        forces = self.O.forces
        active = np.flatnonzero(np.any(force != 0, axis=1) | np.any(torque != 0, axis=1))
        ids = self.particles[active].tolist()
        list(map(forces.addF, ids, force[active].tolist()))
        list(map(forces.addT, ids, torque[active].tolist()))
        list(map(forces.addF, self.walls, wall_force.tolist()))
        t3 = time.perf_counter()
        s = self.seconds
        s["read"] += t1 - t0
        s["kernel"] += t2 - t1
        s["apply"] += t3 - t2
        self.calls += 1
        self.touch_steps += self.n_contacts

    # ------------------------------------------------------------ summaries
    @property
    def n_contacts(self):
        """Touching contacts of the last step (particle pairs + wall contacts)."""
        return self.engine.n_pair_contacts + self.engine.n_wall_contacts

    @property
    def n_pairs(self):
        """Pairs in the neighbour list (touching or not)."""
        return self.engine.n_pairs

    def unbalanced(self):
        """YADE's unbalanced-force ratio from the kernel's sums (NaN without contacts)."""
        return self.engine.unbalanced()

    def memory_bytes(self):
        return self.engine.memory_bytes()

    def contacts(self):
        """The contacts of the last step as the dump's ``contacts`` dict
        (ids are YADE body ids), with the footprint."""
        c = self.engine.contacts()
        walls = np.asarray(self.walls or [-1], np.int64)
        i = c["i"]
        id1 = np.where(i >= 0, self.particles[np.maximum(i, 0)], walls[np.clip(-1 - i, 0, len(walls) - 1)])
        return {"id1": id1.astype(np.int64), "id2": self.particles[c["j"]], "point": c["point"],
                "normal": c["normal"], "force_normal": c["force_normal"],
                "force_tangential": c["force_tangential"], "overlap": c["volume"],
                "footprint": c["footprint"], "footprint_area": c["area"]}

    def timing(self):
        """Seconds spent reading states, in the kernel, and applying forces."""
        return dict(self.seconds, calls=self.calls)
