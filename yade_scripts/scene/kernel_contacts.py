"""Polyhedra contacts from the compiled kernel, stepped inside YADE's loop.

YADE keeps the bodies (``Polyhedra`` shapes, ``PolyhedraMat``), the walls, the
servo, ``NewtonIntegrator`` and the dumps; no collider and no
``InteractionLoop`` run, so no polyhedra pair ever reaches YADE's CGAL code.
Every step, one engine between ``ForceResetter`` and ``NewtonIntegrator``,
labelled ``kernel_contacts``:

1. reads every particle's position and orientation and the wall positions;
2. calls the engine once (``shapes/engine.py`` on ``polycontact.c``: Verlet
   neighbour list on bounding spheres, early-outs, exact overlap, YADE's
   volumetric normal law F_n = k_V V n at the overlap centroid, the
   incremental Coulomb tangential law with per-pair history; OpenMP);
3. adds each particle's force and torque and each wall's force to YADE's
   force container.

That engine is one of two (:meth:`KernelContacts.yade_engine`):

* the plugin, ``PolyhedraKernelEngine`` (:mod:`yade_scripts.yadeplugin`), a
  YADE ``GlobalEngine`` in C++ that does the three steps without leaving
  YADE's loop, where YADE was started with the plugin's ``YADE_PREFIX``;
* else a ``PyRunner`` that does them from Python: ``__getinitargs__`` of
  YADE's Vector3/Quaternion (0.44 us per body, the cheapest of the ways timed
  by ``benchmarks/bench_roundtrip.py``) and ``O.forces.addF``/``addT`` mapped
  over the rows (0.37 us per body). YADE 2023.02a's Python has no bulk
  accessor of states or forces, so these per-body calls are that path's floor.

Both call the same kernel library and engine (the plugin is bound to the
engine Python built), read the same numbers and add the same forces to the
same bodies, so a run is the same bit for bit on either. The plugin is
checked at the first step of every attempt (:meth:`KernelContacts.verify`):
the poses and masses it read must equal what YADE's Python reads, and the
forces and torques it added what ``O.forces`` holds, for every body; a
difference restores the kernel's state, redoes the step on the PyRunner path
and keeps that path, with one line saying why.

Conventions as in the dump schema: contact forces on id2 by id1, normals from
id1 to id2; a wall contact has the wall as id1 and its normal points into the
box. numpy + ctypes only (runs on YADE's Python).
"""
from __future__ import annotations

import contextlib
import os
import time

import numpy as np

from shapes.engine import ContactEngine, EngineError

from ..yadeplugin import load as plugin_load

#: the label of the engine that steps the kernel, on either path
LABEL = "kernel_contacts"
#: the plugin's error codes (besides the kernel's own), as the plugin sets them
PLUGIN_ERRORS = {-10: "the plugin is not bound to a kernel", -11: "a body id is not a body of the scene",
                 -12: "wall positions must be finite, each low wall below its high wall"}


class KernelError(RuntimeError):
    """The kernel refused a step (non-finite positions, out of memory)."""


def _quat(q):
    """(w, x, y, z) of a YADE Quaternion."""
    w, x, y, z = q.__getinitargs__()
    return w, x, y, z


class KernelContacts:
    """The kernel's contacts for one YADE scene.

    O : YADE's Omega. particles : (N,) body ids of the polyhedra. walls :
    six wall body ids in the order x-, x+, y-, y+, z-, z+, or None for a
    scene without walls. vertices, triangles : per particle, local vertices
    (V, 3) m and outward triangles (T, 3) as YADE holds them
    (``yadedump.polyhedra_shapes``). sizes : (N,) m. k_v : N/m^3 volumetric
    stiffness. kt_coef : N/m^3, k_t = kt_coef * d_pair^2 with d_pair = 2 d1
    d2 / (d1 + d2) (d of the particle for a wall). mu, mu_wall : friction
    coefficients. skin : m, Verlet margin of the neighbour list. threads :
    OpenMP threads (0: every core). See :mod:`shapes.engine`.

    Put :meth:`yade_engine` in ``O.engines`` after ``ForceResetter``; on the
    PyRunner path its command calls this object (``kernel()`` or a function
    that does).
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
        n = len(self.particles)
        # what a step reads (both paths; the plugin writes them in C++)
        self.pos, self.quat, self.mass = np.zeros((n, 3)), np.zeros((n, 4)), np.zeros(n)
        self.wall_pos = np.zeros(6)
        # read s, kernel s, apply s, calls, touching contact-steps (the plugin adds to it in C++)
        self._counters = np.zeros(5)
        names = self.engine.layout["stat_names"]
        self._touch_stats = (names.index("touching_pairs"), names.index("wall_contacts"))
        self.plugin = None              # the bound PolyhedraKernelEngine, on the plugin path
        self.path, self.path_note = "pyrunner", "not installed yet"
        self._command = None
        self._pending_check = None      # (kernel state before the checked step, step) on the plugin path

    # ------------------------------------------------------------ counters
    @property
    def seconds(self):
        """{read, kernel, apply}: seconds spent reading the poses, in the
        kernel and adding the forces (either path)."""
        c = self._counters
        return {"read": float(c[0]), "kernel": float(c[1]), "apply": float(c[2])}

    @seconds.setter
    def seconds(self, s):
        """Set the three times from a dict like the getter's (a resumed run)."""
        self._counters[:3] = [s["read"], s["kernel"], s["apply"]]

    @property
    def calls(self):
        """Steps the kernel was called for (either path)."""
        return int(self._counters[3])

    @property
    def touch_steps(self):
        """Sum over steps of touching contacts (pairs + walls)."""
        return int(self._counters[4])

    def counters(self):
        """The counters a checkpoint carries (timing, calls, touch steps)."""
        return {"seconds": self.seconds, "calls": self.calls, "touch_steps": self.touch_steps}

    def set_counters(self, c):
        """Put back the counters :meth:`counters` returned (a resumed run)."""
        self.seconds = c["seconds"]
        self._counters[3:] = [int(c["calls"]), int(c["touch_steps"])]

    # ------------------------------------------------------------ the engines in O.engines
    def yade_engines(self, command, check="kernel.verify()", plugin=True, label=LABEL):
        """The engines that step the kernel, for ``O.engines`` right after
        ``ForceResetter``: the plugin's ``PolyhedraKernelEngine`` bound to
        this kernel, followed by a one-shot ``PyRunner(check)`` that must
        call :meth:`verify` (it runs in the plugin's first step and then
        leaves ``O.engines``), when ``plugin`` and YADE loaded the plugin;
        else ``[PyRunner(command)]``, whose command calls this object.
        :attr:`path` ("plugin" or "pyrunner") and :attr:`path_note` (why)
        say which."""
        self._command, self._check, self._label = command, check, label
        cls, why = plugin_load.loaded_class() if plugin else (None, "the plugin is switched off (kernel_plugin=False)")
        if cls is None:
            self.plugin, self.path, self.path_note = None, "pyrunner", why
            return [self._pyrunner()]
        e = cls(label=label, ids=[int(i) for i in self.particles], walls=list(self.walls))
        eng = self.engine
        e.bind(eng.lib._name, int(eng.handle), self.pos.ctypes.data, self.quat.ctypes.data, self.mass.ctypes.data,
               self.wall_pos.ctypes.data, eng.force.ctypes.data, eng.torque.ctypes.data, eng.wall_force.ctypes.data,
               eng.stat.ctypes.data, self._counters.ctypes.data, *self._touch_stats)
        self.plugin, self.path, self.path_note = e, "plugin", why
        # the kernel's state and counters before the checked step, to go back to if the check fails
        self._pending_check = (self.engine.state(), self._counters.copy())
        e.verifyNext = True
        from yade.wrapper import PyRunner

        return [e, PyRunner(command=check, iterPeriod=1, initRun=True, label=label + "_check")]

    def _pyrunner(self):
        from yade.wrapper import PyRunner

        return PyRunner(command=self._command, iterPeriod=1, initRun=True, label=self._label)

    def _replace(self, new):
        """O.engines with the kernel's engine(s) replaced by ``new`` (a list)."""
        engines = list(self.O.engines)
        k = [i for i, e in enumerate(engines) if e.label == self._label]
        if len(k) != 1:
            raise ValueError(f"O.engines holds {len(k)} engines labelled {self._label!r}, not one")
        rest = [e for e in engines[k[0] + 1:] if e.label != self._label + "_check"]
        self.O.engines = engines[:k[0]] + list(new) + rest
        return engines[k[0]]

    def install(self, command, check="kernel.verify()", plugin=True):
        """Put :meth:`yade_engines` in place of the engine labelled
        ``kernel_contacts`` in ``O.engines`` (after ``O.load`` of a
        checkpoint, whose scene holds the PyRunner form)."""
        self._label = getattr(self, "_label", LABEL)
        self._replace(self.yade_engines(command, check, plugin, self._label))

    @contextlib.contextmanager
    def portable(self):
        """While O.save runs: the PyRunner form in place of the plugin, so a
        checkpoint loads in a YADE without the plugin and resumes on either
        path."""
        if self.plugin is None:
            yield
            return
        engines = list(self.O.engines)
        self._replace([self._pyrunner()])
        try:
            yield
        finally:
            self.O.engines = engines

    def rebind(self):
        """Take the body states from the scene now in ``O`` (after ``O.load``
        of a checkpoint the old State objects belong to the discarded scene)."""
        self.states = [self.O.bodies[int(i)].state for i in self.particles]
        self.wall_states = [self.O.bodies[w].state for w in self.walls]

    # ------------------------------------------------------------ the plugin's start-up check
    def verify(self):
        """In the plugin's first step (its check engine calls this, between
        it and NewtonIntegrator): what it read (positions, orientations,
        masses, wall positions) must equal what YADE's Python reads, and
        what it added (forces and torques of every particle, forces of the
        walls) what ``O.forces`` holds, exactly. On a difference: back to
        the kernel's state before the step, the step redone on the PyRunner
        path, which stays; returns the one-line reason then, else None
        (also when there is nothing to check). The check engine leaves
        ``O.engines`` from the next step on."""
        if self._pending_check is None or self.plugin is None:
            return None
        (saved, counters), self._pending_check = self._pending_check, None
        why = self._first_difference()
        if why is None:
            self.path_note = "its first step read and added exactly what YADE's Python sees"
            self._replace([self.plugin])
            return None
        O = self.O
        self.engine.set_state(saved)
        self._counters[:] = counters
        O.forces.f(int(self.particles[0]), True)   # a synced read: the plugin's forces leave the per-thread sums
        O.forces.reset()                            # ... so that this clears them all
        self.plugin.unbind()
        self.plugin, self.path, self.path_note = None, "pyrunner", f"the plugin was refused: {why}"
        self()                          # this step, again, on the PyRunner path
        self._replace([self._pyrunner()])   # from the next step on
        return why

    def _first_difference(self):
        """None, or the first thing the plugin read or added differently from
        what YADE's Python sees (one line)."""
        e, O = self.plugin, self.O
        if e.error in (-10, -11):
            return PLUGIN_ERRORS[e.error]
        if e.verifyNext:
            return "it did not run its checked step (is it between ForceResetter and NewtonIntegrator?)"
        for k, s in enumerate(self.states):
            i = int(self.particles[k])
            if tuple(self.pos[k]) != tuple(s.pos):
                return f"body {i}: position read {tuple(self.pos[k])}, YADE has {tuple(s.pos)}"
            if tuple(self.quat[k]) != _quat(s.ori):
                return f"body {i}: orientation read {tuple(self.quat[k])}, YADE has {_quat(s.ori)}"
            if self.mass[k] != s.mass:
                return f"body {i}: mass read {self.mass[k]!r}, YADE has {s.mass!r}"
        for k, s in enumerate(self.wall_states):
            if self.wall_pos[k] != s.pos[k // 2]:
                return f"wall {self.walls[k]}: position read {self.wall_pos[k]!r}, YADE has {s.pos[k // 2]!r}"
        if e.error:
            return None                 # the kernel refused the step (NaN, memory): a failure, not a mismatch
        force, torque = self.engine.force, self.engine.torque
        for k, i in enumerate(self.particles.tolist()):
            f, t = tuple(O.forces.f(i, True)), tuple(O.forces.t(i, True))     # synced: reset() then clears all
            if f != tuple(force[k]) or t != tuple(torque[k]):
                return (f"body {i}: YADE holds force {f} and torque {t}, the kernel gave {tuple(force[k])} "
                        f"and {tuple(torque[k])}")
        for k, w in enumerate(self.walls):
            f = tuple(O.forces.f(w, True))
            if f != tuple(self.engine.wall_force[k]):
                return f"wall {w}: YADE holds force {f}, the kernel gave {tuple(self.engine.wall_force[k])}"
        return None

    def step_error(self):
        """None, or why the plugin's last step stopped before adding its
        forces (the PyRunner path raises :class:`KernelError` instead)."""
        if self.plugin is None or not self.plugin.error:
            return None
        return self._error_text(self.plugin.error)

    def _error_text(self, err):
        if err in PLUGIN_ERRORS:
            return PLUGIN_ERRORS[err]
        try:
            self.engine.raise_for(err)
        except EngineError as exc:
            return str(exc)
        return f"step failed (code {err})"

    # ------------------------------------------------------------ the PyRunner path
    def _read(self):
        rows = [s.pos.__getinitargs__() + s.ori.__getinitargs__() for s in self.states]
        a = np.array(rows, float).reshape(-1, 7)
        self.pos[:] = a[:, :3]
        self.quat[:] = a[:, 3:7]                        # quaternion (w, x, y, z)
        for k, s in enumerate(self.wall_states):
            self.wall_pos[k] = s.pos[k // 2]

    def __call__(self):
        """One step on the PyRunner path."""
        t0 = time.perf_counter()
        self._read()
        t1 = time.perf_counter()
        try:
            force, torque, wall_force = self.engine.step(self.pos, self.quat, self.wall_pos)
        except (EngineError, ValueError) as exc:
            raise KernelError(str(exc)) from None
        t2 = time.perf_counter()
        forces = self.O.forces
        active = np.flatnonzero(np.any(force != 0, axis=1) | np.any(torque != 0, axis=1))
        ids = self.particles[active].tolist()
        list(map(forces.addF, ids, force[active].tolist()))
        list(map(forces.addT, ids, torque[active].tolist()))
        list(map(forces.addF, self.walls, wall_force.tolist()))
        t3 = time.perf_counter()
        c = self._counters
        c[0] += t1 - t0
        c[1] += t2 - t1
        c[2] += t3 - t2
        c[3] += 1
        c[4] += self.n_contacts

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
        """Bytes the compiled kernel's engine holds now (its own count,
        :meth:`shapes.engine.ContactEngine.memory_bytes`)."""
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

    def close(self):
        """Free the kernel (the plugin, if any, is unbound first: it must not
        step a freed engine)."""
        if self.plugin is not None:
            self.plugin.unbind()
        self.engine.close()

    def timing(self):
        """Seconds spent reading states, in the kernel, and applying forces."""
        return dict(self.seconds, calls=self.calls)
