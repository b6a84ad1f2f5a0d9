"""The contact engine of the compiled kernel: contacts and forces of many
polyhedra (and six box walls), step after step, with per-pair history.

One :meth:`ContactEngine.step` takes every body's pose and the wall
positions and returns the contact forces, with everything kept between
steps inside the C engine (``polycontact.c``):

* a Verlet neighbour list on bounding spheres (cell grid), rebuilt only when
  a body has moved more than ``skin / 2`` since the last build; the pairs'
  histories are carried over a rebuild;
* per pair, the cheapest exact proof that it does not touch: bounding
  spheres; a separating axis kept from an earlier step whose gap exceeds how
  far the two bodies' vertices can have moved since (a bound summed step by
  step from their displacements and rotations); the same axis re-measured
  with support functions; a separating-axis search (Gilbert's iteration on
  the Minkowski difference, checked over every vertex). Only pairs without a
  proof are clipped (:mod:`shapes.overlap`), and a pair that touched at the
  last step clips only the triangles and planes that can meet the overlap.
  ``fast=False`` keeps the plain path (face tests and full clipping for every
  pair) to check against: the two give the same contacts and forces;
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

from . import ckernel


class EngineError(RuntimeError):
    """The engine refused a step (non-finite positions, out of memory, a
    contact that overflowed the clipping workspace)."""


def layout():
    """The C side's record sizes: a dict with ``pair_doubles`` (a pair's
    record in the engine state), ``wall_doubles`` (a wall contact's
    results), ``stat_names`` (the step counters, in order), ``scalars``
    (state scalars) and ``max_walls``."""
    lib = ckernel.load()
    out = np.zeros(5, np.int32)
    lib.pc_engine_layout(ckernel.iptr(out))
    names = tuple(lib.pc_engine_stat_name(k).decode() for k in range(int(out[2])))
    return {"pair_doubles": int(out[0]), "wall_doubles": int(out[1]), "stat_names": names,
            "scalars": int(out[3]), "max_walls": int(out[4])}


WALL_AXIS = (0, 0, 1, 1, 2, 2)
WALL_SIGN = (1.0, -1.0, 1.0, -1.0, 1.0, -1.0)     # inward normals of x-, x+, y-, y+, z-, z+


class ContactEngine:
    """Contacts and forces of N polyhedra, with or without six box walls:
    the compiled kernel (``shapes/polycontact.c``), exact overlap volumes,
    the normal force k_v V along the overlap's normal, and Coulomb-limited
    tangential forces with their histories. :meth:`step` advances it.

    Parameters
    ----------
    vertices, triangles : list of arrays
        One (V, 3) array (m) and one (T, 3) int array per shape, in the
        shape's local frame (origin at the centre of mass), triangles
        counter-clockwise seen from outside.
    shape_index : (N,) int
        The shape of each body.
    sizes : (N,) float
        m, each body's d (for the tangential stiffness and the neighbour list).
    k_v : float
        N/m^3, the volumetric normal stiffness: |f_n| = k_v V_overlap.
    kt_coef : float
        N/m^3: the tangential stiffness of a pair is kt_coef d_pair^2.
    mu, mu_wall : float
        Friction coefficients between bodies, and with the walls.
    skin : float
        m, the neighbour list's margin.
    walls : bool
        With the six box walls (positions given to :meth:`step`).
    threads : int
        OpenMP threads (0: all; a step with fewer than 400 pair and wall
        tests runs on one thread). The forces do not depend on it.
    fast : bool
        Proofs of separation, culled clipping and shadows computed when
        contacts are asked for (the default); False: the plain path, to
        check against.

    Attributes
    ----------
    n : int
        The number of bodies.
    n_pair_contacts, n_wall_contacts : int
        Touching pairs and body-wall contacts after the last step.

    Examples
    --------
    Two unit cubes overlapping by 1 cm along x: an overlap of 0.01 m^3,
    so a repulsion of k_v x 0.01 = 10 kN, equal and opposite.

    >>> import itertools
    >>> from shapes.polyhedron import hull
    >>> v, t = hull(np.array(list(itertools.product((-0.5, 0.5), repeat=3))))
    >>> eng = ContactEngine([v], [t], shape_index=[0, 0], sizes=[3 ** 0.5] * 2, k_v=1e6, kt_coef=0.0,
    ...                     mu=0.5, mu_wall=0.0, skin=0.1, walls=False, threads=1)
    >>> force, torque, wall_force = eng.step(np.array([[0, 0, 0], [0.99, 0, 0]]), np.array([[1.0, 0, 0, 0]] * 2))
    >>> force.round(6) + 0.0
    array([[-10000.,      0.,      0.],
           [ 10000.,      0.,      0.]])
    >>> eng.n_pair_contacts
    1
    """

    def __init__(self, vertices, triangles, shape_index, sizes, k_v, kt_coef, mu, mu_wall, skin,
                 walls=True, threads=0, fast=True):
        if len(vertices) != len(triangles) or not len(vertices):
            raise ValueError("one triangle array per vertex array, at least one shape")
        for s, (v, t) in enumerate(zip(vertices, triangles)):
            v, t = np.asarray(v), np.asarray(t)
            if v.ndim != 2 or v.shape[1] != 3 or len(v) < 4 or not np.all(np.isfinite(v)):
                raise ValueError(f"shape {s}: vertices must be a finite (V >= 4, 3) array, got shape {v.shape}")
            if t.ndim != 2 or t.shape[1] != 3 or len(t) < 4 or not np.issubdtype(t.dtype, np.integer):
                raise ValueError(f"shape {s}: triangles must be an integer (T >= 4, 3) array, got {t.dtype} {t.shape}")
            if t.min() < 0 or t.max() >= len(v):
                raise ValueError(f"shape {s}: triangle index {int(t.max() if t.max() >= len(v) else t.min())} "
                                 f"outside its {len(v)} vertices")
        self.layout = layout()
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
        self.lib.pc_engine_set_mode(self.handle, int(bool(fast)))
        self.fast = bool(fast)
        self.groups = None
        self.force = np.zeros((self.n, 3))
        self.torque = np.zeros((self.n, 3))
        self.wall_force = np.zeros((max(self.nw, 1), 3))
        self.stat = np.zeros(len(self.layout["stat_names"]))
        self._stat_index = {k: i for i, k in enumerate(self.layout["stat_names"])}
        self._no_walls = np.zeros(1)

    def close(self):
        """Free the C engine's memory (also done when the engine is garbage
        collected). Closing twice does nothing; no other method may be
        called afterwards: each raises EngineError ("the contact engine is closed")."""
        if getattr(self, "handle", None):
            self.lib.pc_engine_free(self.handle)
            self.handle = None

    __del__ = close

    def _live(self):
        """The C engine's handle; EngineError (one line) once :meth:`close`
        has freed it (the C side would be handed a null pointer)."""
        if not getattr(self, "handle", None):
            raise EngineError("the contact engine is closed")
        return self.handle

    def step(self, positions, quaternions, wall_positions=None):
        """One step. positions (N, 3) m; quaternions (N, 4) (w, x, y, z),
        local -> global; wall_positions (6,) m, the coordinate of each wall
        plane along its axis (x-, x+, y-, y+, z-, z+), finite, each low wall
        below its high wall (required with walls, ignored without). Returns
        (force (N, 3) N, torque (N, 3) N m, wall_force (6, 3) N on each
        wall); the arrays are the engine's own, overwritten by the next
        step."""
        pos = ckernel.f64(positions)
        quat = ckernel.f64(quaternions)
        if pos.shape != (self.n, 3) or quat.shape != (self.n, 4):
            raise ValueError(f"positions must be ({self.n}, 3) and quaternions ({self.n}, 4)")
        if self.nw:
            if wall_positions is None:
                raise ValueError("this engine has six walls: give their positions (x-, x+, y-, y+, z-, z+)")
            wp = ckernel.f64(wall_positions)
            if wp.shape != (6,) or not np.all(np.isfinite(wp)):
                raise ValueError(f"wall positions must be 6 finite numbers (x-, x+, y-, y+, z-, z+), got {wp!r}")
            if np.any(wp[0::2] >= wp[1::2]):
                raise ValueError(f"wall positions: each low wall must lie below its high wall, got {wp.tolist()}")
        else:
            wp = self._no_walls
        err = self.lib.pc_engine_step(self._live(), ckernel.dptr(pos), ckernel.dptr(quat), ckernel.dptr(wp),
                                      ckernel.dptr(self.force), ckernel.dptr(self.torque),
                                      ckernel.dptr(self.wall_force), ckernel.dptr(self.stat))
        if err == -5:
            n2 = np.einsum("ij,ij->i", quat, quat)
            k = int(np.flatnonzero(~((n2 >= 1e-200) & (n2 <= 1e200)))[0])
            raise EngineError(f"body {k}: orientation quaternion {quat[k].tolist()} is zero, not finite or out "
                              "of range (a blown-up body?)")
        self.raise_for(err)
        return self.force, self.torque, self.wall_force[:self.nw]

    def raise_for(self, err):
        """Raise the EngineError of the step's return code ``err`` (nothing
        for 0): also what a caller of ``pc_engine_step`` from C (the YADE
        plugin) reports."""
        if err == -2:
            raise EngineError("particle positions are not finite")
        if err == -5:
            raise EngineError("an orientation quaternion is zero, not finite or out of range (a blown-up body?)")
        if err == -4:
            raise EngineError(f"{int(self.stats['workspace_overflows'])} contacts overflowed the clipping workspace "
                              "(their forces would be lost): the shapes have more faces than it was sized for")
        if err:
            raise EngineError(f"contact engine step failed (code {err}: out of memory)")

    @property
    def stats(self):
        """The last step's counters by name (see ``layout()['stat_names']``):
        touching pairs, wall contacts, listed pairs, sliding contacts, sums
        of |F| (N), rebuilds so far, clipped pairs, and the listed pairs
        proved apart by spheres, by the motion bound, by the cached axis and
        by the axis search."""
        return {k: float(self.stat[i]) for k, i in self._stat_index.items()}

    def _count(self, name):
        return int(self.stat[self._stat_index[name]])

    @property
    def n_pair_contacts(self):
        """Touching body pairs after the last step (int)."""
        return self._count("touching_pairs")

    @property
    def n_wall_contacts(self):
        """Body-wall contacts after the last step (int)."""
        return self._count("wall_contacts")

    @property
    def n_pairs(self):
        """Pairs in the neighbour list (touching or not)."""
        return self._count("listed_pairs")

    @property
    def n_rebuilds(self):
        """Builds of the neighbour list so far, the first included (int)."""
        return self._count("rebuilds")

    def unbalanced(self):
        """Mean |net force| over the bodies / mean |contact force| (YADE's
        unbalanced-force ratio), NaN without contacts."""
        st = self.stats
        nc = st["touching_pairs"] + st["wall_contacts"]
        if nc == 0 or self.n == 0:
            return float("nan")
        return float((st["sum_body_force"] / self.n) / (st["sum_contact_force"] / nc))

    def set_workspace_points(self, npts):
        """Shrink every thread's clipping workspace to ``npts`` points (tests:
        a contact that does not fit then stops the step with EngineError)."""
        if self.lib.pc_engine_set_workspace_points(self._live(), int(npts)) != 0:
            raise ValueError(f"workspace points must be 16 to the allocated size, got {npts}")

    def memory_bytes(self):
        """The memory the C engine holds now, in bytes (int): its own
        estimate, the sum of the sizes of its pair list, body and shape
        arrays, wall records and clipping workspaces."""
        return int(self.lib.pc_engine_memory(self._live()))

    def set_history(self, i, j, shear_force):
        """Set the shear history (N, force on j by i) of the listed pair
        i < j; raises KeyError when the pair is not in the neighbour list."""
        f = ckernel.f64(shear_force)
        if self.lib.pc_engine_set_history(self._live(), int(i), int(j), ckernel.dptr(f)) != 0:
            raise KeyError(f"pair ({i}, {j}) is not in the neighbour list")

    def set_friction(self, mu, mu_wall):
        """Set the particle-particle and particle-wall friction coefficients
        from the next step on (e.g. frictionless compaction, then mu before
        shear). Shear histories above the new cap mu |F_n| are cut to it at
        that step."""
        if self.lib.pc_engine_set_friction(self._live(), float(mu), float(mu_wall)) != 0:
            raise ValueError(f"friction coefficients must be finite and >= 0, got {mu!r}, {mu_wall!r}")

    def set_groups(self, groups):
        """Give the bodies groups: ``groups`` (n,) int, one per body row,
        -1 for none (a YADE clump's members share the clump's id). Two bodies
        of one group >= 0 are never a pair from now on (no contact, no
        force between them), those listed are dropped at once; a state
        restored later by :meth:`set_state` is cut the same way. ``None``:
        no groups (a new engine's)."""
        if groups is None:
            self.groups = None
            self.lib.pc_engine_set_groups(self._live(), None)
            return
        g = ckernel.i32(groups)
        if g.shape != (self.n,):
            raise ValueError(f"set_groups: one group per body ({self.n}), got shape {g.shape}")
        if self.lib.pc_engine_set_groups(self._live(), ckernel.iptr(g)) != 0:
            raise EngineError("could not set the groups (out of memory)")
        self.groups = g

    def set_facets(self, first):
        """Body rows ``first`` .. n - 1 are facets from now on (a user
        scene's, after its polyhedra): two facets are never a pair and no
        wall pushes a facet (YADE has neither functor). Their listed pairs
        and wall contacts are dropped at once; a state restored later by
        :meth:`set_state` is cut the same way."""
        if self.lib.pc_engine_set_facets(self._live(), int(first)) != 0:
            raise ValueError(f"set_facets: the first facet row must be within 0 .. {self.n}, got {first!r}")
        self.first_facet = int(first)

    @property
    def friction(self):
        """(mu, mu_wall) now."""
        out = np.zeros(2)
        self.lib.pc_engine_get_friction(self._live(), ckernel.dptr(out))
        return float(out[0]), float(out[1])

    STATE_KEYS = ("x", "R", "xbuild", "motion", "pair_ids", "pair_records", "wall_shear", "wall_results",
                  "wall_touching", "scalars")

    def _state_shapes(self, npairs):
        n, nw, L = self.n, max(self.nw, 1), self.layout
        return {"x": (n, 3), "R": (n, 9), "xbuild": (n, 3), "motion": (n,), "pair_ids": (npairs, 2),
                "pair_records": (npairs, L["pair_doubles"]), "wall_shear": (n * nw, 3),
                "wall_results": (n * nw, L["wall_doubles"]), "wall_touching": (n * nw,), "scalars": (L["scalars"],)}

    def state(self):
        """Everything later steps depend on, as a dict of numpy arrays (for
        a checkpoint): the last poses, the neighbour list with each pair's
        shear history, cached separating axis, touched flag and results, the
        wall contacts' histories, and the counters. An engine built with the
        same shapes, bodies and walls and given this state by
        :meth:`set_state` continues bit for bit like this one."""
        npairs = int(self.lib.pc_engine_npairs(self._live()))
        st = {k: np.zeros(shp, np.int32 if k in ("pair_ids", "wall_touching") else np.float64)
              for k, shp in self._state_shapes(npairs).items()}
        self.lib.pc_engine_get_state(self._live(), ckernel.dptr(st["x"]), ckernel.dptr(st["R"]),
                                     ckernel.dptr(st["xbuild"]), ckernel.dptr(st["motion"]),
                                     ckernel.iptr(st["pair_ids"]),
                                     ckernel.dptr(st["pair_records"]), ckernel.dptr(st["wall_shear"]),
                                     ckernel.dptr(st["wall_results"]), ckernel.iptr(st["wall_touching"]),
                                     ckernel.dptr(st["scalars"]))
        st["friction"] = np.array(self.friction)
        return st

    def set_state(self, st):
        """Restore a :meth:`state` (raises ValueError when it does not fit
        this engine: other body count, wall count or pair ids)."""
        missing = [k for k in self.STATE_KEYS if k not in st]
        if missing:
            raise ValueError(f"engine state lacks {missing} (a state of an older kernel?)")
        a = {k: (ckernel.i32(st[k]) if k in ("pair_ids", "wall_touching") else ckernel.f64(st[k]))
             for k in self.STATE_KEYS}
        npairs = len(a["pair_ids"])
        for k, shp in self._state_shapes(npairs).items():
            if a[k].shape != shp:
                raise ValueError(f"engine state: {k} has shape {a[k].shape}, this engine needs {shp}")
        err = self.lib.pc_engine_set_state(self._live(), ckernel.dptr(a["x"]), ckernel.dptr(a["R"]),
                                           ckernel.dptr(a["xbuild"]), ckernel.dptr(a["motion"]), npairs,
                                           ckernel.iptr(a["pair_ids"]),
                                           ckernel.dptr(a["pair_records"]), ckernel.dptr(a["wall_shear"]),
                                           ckernel.dptr(a["wall_results"]), ckernel.iptr(a["wall_touching"]),
                                           ckernel.dptr(a["scalars"]))
        if err == -3:
            raise ValueError("engine state: pair ids out of range or unsorted, or a malformed pair record (not a state of this engine)")
        if err:
            raise EngineError("could not restore the engine state (out of memory)")
        if "friction" in st:          # states taken before friction was part of them keep the engine's own
            self.set_friction(*np.asarray(st["friction"], float).reshape(2))
        if getattr(self, "groups", None) is not None:     # the restored list holds no pair of one group
            self.set_groups(self.groups)
        if getattr(self, "first_facet", self.n) != self.n:   # nor a pair of two facets, nor a facet's wall contact
            self.set_facets(self.first_facet)

    def contacts(self):
        """The touching contacts of the last step: a dict of arrays. ``i``,
        ``j`` body rows (``i`` = -1 - k for wall k, with ``j`` the body),
        ``point`` (C, 3) m, ``normal`` (C, 3) from i to j, ``force_normal``,
        ``force_tangential`` (C, 3) N on j by i, ``volume`` (C,) m^3,
        ``footprint`` (C, 2) m, ``area`` (C,) m^2."""
        n = int(self.lib.pc_engine_count(self._live()))
        i1, i2 = np.zeros(n, np.int32), np.zeros(n, np.int32)
        point, normal, fnrm, ftan = (np.zeros((n, 3)) for _ in range(4))
        vol, area, fp = np.zeros(n), np.zeros(n), np.zeros((n, 2))
        m = self.lib.pc_engine_contacts(self._live(), n, ckernel.iptr(i1), ckernel.iptr(i2), ckernel.dptr(point),
                                        ckernel.dptr(normal), ckernel.dptr(fnrm), ckernel.dptr(ftan),
                                        ckernel.dptr(vol), ckernel.dptr(fp), ckernel.dptr(area))
        return {"i": i1[:m].astype(np.int64), "j": i2[:m].astype(np.int64), "point": point[:m],
                "normal": normal[:m], "force_normal": fnrm[:m], "force_tangential": ftan[:m],
                "volume": vol[:m], "footprint": fp[:m], "area": area[:m]}
