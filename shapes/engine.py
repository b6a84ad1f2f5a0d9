"""The contact engine of the compiled kernel: contacts and forces of many
polyhedra (and six box walls), step after step, with per-pair history.

One :meth:`ContactEngine.step` takes every body's pose and the wall
positions and returns the contact forces, with everything kept between
steps inside the C engine (``polycontact.c``):

* a Verlet neighbour list on bounding spheres (cell grid), rebuilt only when
  a body has moved more than ``skin / 2`` since the last build; the pairs'
  histories are carried over a rebuild;
* per pair: bounding spheres, then the separating axis cached from the last
  step, then the exact overlap (:mod:`shapes.overlap`);
* YADE's volumetric normal law F_n = k_V V n on B at the overlap centroid,
  and the incremental Coulomb tangential law: the history is projected on the
  new tangent plane (norm kept) and turned by the pair's mean spin about n,
  then f_t -= k_t du_t with du_t the tangential displacement over the step of
  B's material point at the centroid relative to A's, and |f_t| <= mu |F_n|;
  k_t = kt_coef d_pair^2 with d_pair = 2 d_A d_B / (d_A + d_B) (the
  particle's d at a wall);
* walls: six planes, x-, x+, y-, y+, z-, z+, each with its inward normal;
  the overlap is the part of a particle beyond the plane, normal into the box.

Conventions of the dump schema: forces on B (id2) by A (id1), normals A -> B;
for a wall contact the wall is A. Displacements are measured between
successive calls, so call :meth:`step` once per time step. numpy + ctypes
only, so YADE's Python can use it.
"""
from __future__ import annotations

import numpy as np

try:
    from . import ckernel
except ImportError:          # copied into a run folder's lib/ (no package)
    import ckernel  # type: ignore


class EngineError(RuntimeError):
    """The engine refused a step (non-finite positions, out of memory)."""


WALL_AXIS = (0, 0, 1, 1, 2, 2)
WALL_SIGN = (1.0, -1.0, 1.0, -1.0, 1.0, -1.0)     # inward normals of x-, x+, y-, y+, z-, z+


class ContactEngine:
    """Contacts and forces of N polyhedra, with or without six box walls.

    vertices, triangles : one (V, 3) m / (T, 3) int array per shape, local
    frame (origin at the centre of mass), triangles outward. shape_index :
    (N,) row of each body. sizes : (N,) m, the bodies' d. k_v : N/m^3.
    kt_coef : N/m^3 (k_t = kt_coef d_pair^2). mu, mu_wall : friction
    coefficients. skin : m, Verlet margin. walls : with the six box walls.
    threads : OpenMP threads (0: all; a step with fewer than 400 pair and
    wall tests runs on one thread).
    """

    def __init__(self, vertices, triangles, shape_index, sizes, k_v, kt_coef, mu, mu_wall, skin,
                 walls=True, threads=0):
        if len(vertices) != len(triangles) or not len(vertices):
            raise ValueError("one triangle array per vertex array, at least one shape")
        self.n = len(shape_index)
        self.voff = ckernel.i32(np.concatenate([[0], np.cumsum([len(v) for v in vertices])]))
        self.toff = ckernel.i32(np.concatenate([[0], np.cumsum([len(t) for t in triangles])]))
        self.v = ckernel.f64(np.concatenate([np.asarray(v, float) for v in vertices]))
        self.t = ckernel.i32(np.concatenate([np.asarray(t) for t in triangles]))
        self.shape = ckernel.i32(shape_index)
        self.size = ckernel.f64(sizes)
        if self.shape.shape != (self.n,) or self.size.shape != (self.n,):
            raise ValueError("shape_index and sizes must both be (N,)")
        if self.n and (self.shape.min() < 0 or self.shape.max() >= len(vertices)):
            raise ValueError(f"shape index out of range 0..{len(vertices) - 1}")
        self.nw = 6 if walls else 0
        self.wall_axis = ckernel.i32(WALL_AXIS)
        self.wall_sign = ckernel.f64(WALL_SIGN)
        self.threads = int(threads)
        self.lib = ckernel.load()
        self.handle = self.lib.pc_engine_new(
            len(vertices), ckernel.iptr(self.voff), ckernel.dptr(self.v), ckernel.iptr(self.toff),
            ckernel.iptr(self.t), self.n, ckernel.iptr(self.shape), ckernel.dptr(self.size), self.nw,
            ckernel.iptr(self.wall_axis), ckernel.dptr(self.wall_sign), float(k_v), float(kt_coef), float(mu),
            float(mu_wall), float(skin), self.threads)
        if not self.handle:
            raise EngineError("could not create the contact engine (out of memory?)")
        self.force = np.zeros((self.n, 3))
        self.torque = np.zeros((self.n, 3))
        self.wall_force = np.zeros((max(self.nw, 1), 3))
        self.stat = np.zeros(8)
        self._zero_walls = np.zeros(6)

    def close(self):
        if getattr(self, "handle", None):
            self.lib.pc_engine_free(self.handle)
            self.handle = None

    __del__ = close

    def step(self, positions, quaternions, wall_positions=None):
        """One step. positions (N, 3) m; quaternions (N, 4) (w, x, y, z),
        local -> global; wall_positions (6,) m, the coordinate of each wall
        plane along its axis (x-, x+, y-, y+, z-, z+). Returns (force (N, 3)
        N, torque (N, 3) N m, wall_force (6, 3) N on each wall); the arrays
        are the engine's own, overwritten by the next step."""
        pos = ckernel.f64(positions)
        quat = ckernel.f64(quaternions)
        if pos.shape != (self.n, 3) or quat.shape != (self.n, 4):
            raise ValueError(f"positions must be ({self.n}, 3) and quaternions ({self.n}, 4)")
        wp = ckernel.f64(self._zero_walls if wall_positions is None else wall_positions)
        err = self.lib.pc_engine_step(self.handle, ckernel.dptr(pos), ckernel.dptr(quat), ckernel.dptr(wp),
                                      ckernel.dptr(self.force), ckernel.dptr(self.torque),
                                      ckernel.dptr(self.wall_force), ckernel.dptr(self.stat))
        if err == -2:
            raise EngineError("particle positions are not finite")
        if err:
            raise EngineError(f"contact engine step failed (code {err}: out of memory)")
        return self.force, self.torque, self.wall_force[:self.nw]

    @property
    def n_pair_contacts(self):
        return int(self.stat[0])

    @property
    def n_wall_contacts(self):
        return int(self.stat[1])

    @property
    def n_pairs(self):
        """Pairs in the neighbour list (touching or not)."""
        return int(self.stat[2])

    @property
    def n_rebuilds(self):
        return int(self.stat[5])

    def unbalanced(self):
        """Mean |net force| over the bodies / mean |contact force| (YADE's
        unbalanced-force ratio), NaN without contacts."""
        nc = self.stat[0] + self.stat[1]
        if nc == 0 or self.n == 0:
            return float("nan")
        return float((self.stat[6] / self.n) / (self.stat[4] / nc))

    def memory_bytes(self):
        return int(self.lib.pc_engine_memory(self.handle))

    def set_history(self, i, j, shear_force):
        """Set the shear history (N, force on j by i) of the listed pair
        i < j; raises KeyError when the pair is not in the neighbour list."""
        f = ckernel.f64(shear_force)
        if self.lib.pc_engine_set_history(self.handle, int(i), int(j), ckernel.dptr(f)) != 0:
            raise KeyError(f"pair ({i}, {j}) is not in the neighbour list")

    def set_friction(self, mu, mu_wall):
        """Set the particle-particle and particle-wall friction coefficients
        from the next step on (e.g. frictionless compaction, then mu before
        shear). Shear histories above the new cap mu |F_n| are cut to it at
        that step."""
        if self.lib.pc_engine_set_friction(self.handle, float(mu), float(mu_wall)) != 0:
            raise ValueError(f"friction coefficients must be finite and >= 0, got {mu!r}, {mu_wall!r}")

    @property
    def friction(self):
        """(mu, mu_wall) now."""
        out = np.zeros(2)
        self.lib.pc_engine_get_friction(self.handle, ckernel.dptr(out))
        return float(out[0]), float(out[1])

    STATE_KEYS = ("x", "R", "xbuild", "pair_ids", "pair_records", "wall_shear", "wall_results", "wall_touching",
                  "scalars")

    def state(self):
        """Everything later steps depend on, as a dict of numpy arrays (for
        a checkpoint): the last poses, the neighbour list with each pair's
        shear history, cached separating axis, touched flag and results, the
        wall contacts' histories, and the counters. An engine built with the
        same shapes, bodies and walls and given this state by
        :meth:`set_state` continues bit for bit like this one."""
        n, nw = self.n, max(self.nw, 1)
        npairs = int(self.lib.pc_engine_npairs(self.handle))
        st = {"x": np.zeros((n, 3)), "R": np.zeros((n, 9)), "xbuild": np.zeros((n, 3)),
              "pair_ids": np.zeros((npairs, 2), np.int32), "pair_records": np.zeros((npairs, 20)),
              "wall_shear": np.zeros((n * nw, 3)), "wall_results": np.zeros((n * nw, 10)),
              "wall_touching": np.zeros(n * nw, np.int32), "scalars": np.zeros(2)}
        self.lib.pc_engine_get_state(self.handle, ckernel.dptr(st["x"]), ckernel.dptr(st["R"]),
                                     ckernel.dptr(st["xbuild"]), ckernel.iptr(st["pair_ids"]),
                                     ckernel.dptr(st["pair_records"]), ckernel.dptr(st["wall_shear"]),
                                     ckernel.dptr(st["wall_results"]), ckernel.iptr(st["wall_touching"]),
                                     ckernel.dptr(st["scalars"]))
        st["friction"] = np.array(self.friction)
        return st

    def set_state(self, st):
        """Restore a :meth:`state` (raises ValueError when it does not fit
        this engine: other body count, wall count or pair ids)."""
        n, nw = self.n, max(self.nw, 1)
        missing = [k for k in self.STATE_KEYS if k not in st]
        if missing:
            raise ValueError(f"engine state lacks {missing}")
        a = {k: (ckernel.i32(st[k]) if k in ("pair_ids", "wall_touching") else ckernel.f64(st[k]))
             for k in self.STATE_KEYS}
        npairs = len(a["pair_ids"])
        shapes = {"x": (n, 3), "R": (n, 9), "xbuild": (n, 3), "pair_ids": (npairs, 2), "pair_records": (npairs, 20),
                  "wall_shear": (n * nw, 3), "wall_results": (n * nw, 10), "wall_touching": (n * nw,), "scalars": (2,)}
        for k, shp in shapes.items():
            if a[k].shape != shp:
                raise ValueError(f"engine state: {k} has shape {a[k].shape}, this engine needs {shp}")
        err = self.lib.pc_engine_set_state(self.handle, ckernel.dptr(a["x"]), ckernel.dptr(a["R"]),
                                           ckernel.dptr(a["xbuild"]), npairs, ckernel.iptr(a["pair_ids"]),
                                           ckernel.dptr(a["pair_records"]), ckernel.dptr(a["wall_shear"]),
                                           ckernel.dptr(a["wall_results"]), ckernel.iptr(a["wall_touching"]),
                                           ckernel.dptr(a["scalars"]))
        if err == -3:
            raise ValueError("engine state: pair ids out of range or unsorted (not a state of this engine)")
        if err:
            raise EngineError("could not restore the engine state (out of memory)")
        if "friction" in st:          # states taken before friction was part of them keep the engine's own
            self.set_friction(*np.asarray(st["friction"], float).reshape(2))

    def contacts(self):
        """The touching contacts of the last step: a dict of arrays. ``i``,
        ``j`` body rows (``i`` = -1 - k for wall k, with ``j`` the body),
        ``point`` (C, 3) m, ``normal`` (C, 3) from i to j, ``force_normal``,
        ``force_tangential`` (C, 3) N on j by i, ``volume`` (C,) m^3,
        ``footprint`` (C, 2) m, ``area`` (C,) m^2."""
        n = int(self.lib.pc_engine_count(self.handle))
        i1, i2 = np.zeros(n, np.int32), np.zeros(n, np.int32)
        point, normal, fnrm, ftan = (np.zeros((n, 3)) for _ in range(4))
        vol, area, fp = np.zeros(n), np.zeros(n), np.zeros((n, 2))
        m = self.lib.pc_engine_contacts(self.handle, n, ckernel.iptr(i1), ckernel.iptr(i2), ckernel.dptr(point),
                                        ckernel.dptr(normal), ckernel.dptr(fnrm), ckernel.dptr(ftan),
                                        ckernel.dptr(vol), ckernel.dptr(fp), ckernel.dptr(area))
        return {"i": i1[:m].astype(np.int64), "j": i2[:m].astype(np.int64), "point": point[:m],
                "normal": normal[:m], "force_normal": fnrm[:m], "force_tangential": ftan[:m],
                "volume": vol[:m], "footprint": fp[:m], "area": area[:m]}
