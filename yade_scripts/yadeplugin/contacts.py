"""Exact polyhedra contacts for a YADE user's own scene.

In a YADE script, in place of a collider and an ``InteractionLoop``::

    from yade_scripts.yadeplugin.contacts import PolyhedraContactEngine
    O.engines = [ForceResetter(),
                 PolyhedraContactEngine(fillEvery=1, label="contacts"),
                 NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.3)]

The engine (``PolyhedraContactEngine.cpp``, a YADE ``GlobalEngine`` in C++)
steps the compiled kernel (``shapes/polycontact.c``) on every body of the
scene:

* ``Polyhedra`` bodies (``polyhedra_utils.polyhedra``, ``polyhedralBall``,
  from a mesh): their vertices ``shape.v`` in the body frame and outward
  triangles (``shape.GetSurfaceTriangulation()`` turned outward);
* ``Facet`` bodies (``utils.facet``, ``geom.facetBox``, an STL boundary,
  moving facets): each is a prism of thickness ``facetThickness`` behind its
  face, on the side away from the polyhedra, posed from the facet's state;
* ``Wall`` bodies (any axis; ``sense`` 1 or -1, or 0 with every polyhedron
  on one side): a half-space beyond the plane. A plane at an angle is a
  large fixed ``Polyhedra`` slab (:func:`plane_body`), or two facets.

Clumps (``O.bodies.appendClumped``, ``O.bodies.clump``) of polyhedra or
facets: the ``Clump`` body itself is not computed, its members are ordinary
bodies that are never a pair with each other (each member's group, its
``clumpId``, is given to the kernel, as YADE's collider never makes an
interaction between members of one clump); their contact forces go on the
members, which ``NewtonIntegrator`` sums into the clump. A clumped wall is
refused in one line. Two facets are never a pair, and no wall pushes a
facet (YADE has neither a facet-facet nor a wall-facet functor).

Bodies added or erased during the run are picked up at the next step (the
engine notices, and this module's scan rebuilds the kernel's engine with the
pairs' shear histories carried over), as are bodies clumped or released from
their clump (their ``clumpId`` changed). A periodic cell is refused in one
line.

The contact law is YADE's volumetric law with the exact overlap (the law of
the project's own scene, shapes/engine.py): F_n = k_n V n on the overlap's
centroid, V the overlap volume, n = -dV/dx of the second body; the
incremental Coulomb tangential law, f_t -= k_s du_t, |f_t| <= mu |F_n|, with
the history turned into the new tangent plane. From the bodies' materials
(``PolyhedraMat`` or ``FrictMat``) as YADE's
``Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys`` makes them:
k_n = E1 E2 / (E1 + E2) (N/m^3), k_s = E1 nu1 E2 nu2 / (E1 nu1 + E2 nu2)
(N/m), mu = tan(min(phi1, phi2)). The kernel holds one (k_n, k_s, mu) for
pairs (polyhedra and facets) and one mu for walls: a scene whose materials
give several is refused in one line.

Every ``fillEvery`` steps (0: never) the touching contacts are written to
``O.interactions`` as YADE's ``PolyhedraGeom`` (``normal`` from id1 to id2,
``contactPoint``, ``penetrationVolume``) and ``PolyhedraPhys``
(``normalForce``, ``shearForce`` on id2, ``kn``, ``ks``,
``tangensOfFrictionAngle``), so ``utils.getStress()``,
``export.VTKExporter.exportInteractions``, ``O.interactions.countReal()`` and
a user's force-chain script see them. The fields are written at byte offsets
measured on objects of the installed YADE (:func:`field_offsets`): a YADE
whose classes differ is refused, never written wrong.

``O.save`` / ``O.load`` (and ``O.saveTmp``, ``O.loadTmp``, ``O.reload``) take
the engine with the scene: O.save keeps the kernel's state (the shear
histories), the shapes and the scan's choices in the engine's
``savedState`` (:meth:`SceneContacts.saved`); the loaded engine's first
step calls :func:`adopt`, and the scene steps on bit for bit. In a new
process call :func:`load_plugin` before ``O.load`` (or start YADE with
``YADE_PREFIX``).

numpy + ctypes (YADE's Python).
"""
from __future__ import annotations

import base64
import io
import json
import math
import os

import numpy as np

from shapes import ckernel
from shapes.engine import ContactEngine, EngineError

from ..scene.yadedump import outward_triangles
from . import load

#: kernel body state for a body that is new: far from its neighbour-list position, so the list is rebuilt
_FAR = 1e30


class SceneError(ValueError):
    """The scene cannot be computed by the engine (one line says why)."""


def law_of(m1, m2):
    """(k_n N/m^3, k_s N/m, mu) of two materials, as YADE's
    ``Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys``: k_n = E1 E2/(E1+E2),
    k_s = E1 nu1 E2 nu2/(E1 nu1 + E2 nu2) (0 if a product is 0),
    mu = tan(min(phi1, phi2)).

    Examples
    --------
    >>> class M:
    ...     def __init__(self, E, nu, phi): self.young, self.poisson, self.frictionAngle = E, nu, phi
    >>> law_of(M(2e8, 0.5, 0.5), M(2e8, 0.5, 0.3))
    (100000000.0, 50000000.0, 0.30933624960962325)
    """
    e1, e2 = float(m1.young), float(m2.young)
    s1, s2 = e1 * float(m1.poisson), e2 * float(m2.poisson)
    kn = e1 * e2 / (e1 + e2) if e1 + e2 > 0 else 0.0
    ks = s1 * s2 / (s1 + s2) if s1 > 0 and s2 > 0 else 0.0
    return kn, ks, math.tan(min(float(m1.frictionAngle), float(m2.frictionAngle)))


def facet_prism(vertices, normal, thickness, side):
    """(6, 3) vertices and (8, 3) outward triangles of the prism of a facet:
    its triangle ``vertices`` (3, 3) m and the same moved by ``-side *
    thickness * normal`` (``normal`` (3,) unit, ``side`` +1 or -1: the
    polyhedra lie on the ``side * normal`` side of the face). The body-frame
    origin (the facet's position) stays the origin.

    Examples
    --------
    >>> v, t = facet_prism(np.array([[0., 0, 0], [1, 0, 0], [0, 1, 0]]), np.array([0., 0, 1]), 0.5, 1)
    >>> v[3:, 2].tolist(), t.shape
    ([-0.5, -0.5, -0.5], (8, 3))
    """
    v = np.asarray(vertices, float).reshape(3, 3)
    n = np.asarray(normal, float) * (side / np.linalg.norm(normal))
    back = v - thickness * n
    pts = np.vstack([v, back])
    tris = np.array([[0, 1, 2], [3, 5, 4], [0, 3, 4], [0, 4, 1], [1, 4, 5], [1, 5, 2], [2, 5, 3], [2, 3, 0]])
    c = pts.mean(axis=0)
    out = []
    for a, b, d in tris:               # turn each triangle outward (the prism is convex)
        nn = np.cross(pts[b] - pts[a], pts[d] - pts[a])
        out.append((a, b, d) if np.dot(nn, pts[a] - c) > 0 else (a, d, b))
    return pts, np.array(out, np.int64)


def plane_corners(point, normal, extent, thickness):
    """(8, 3) corners (m) of the slab that stands for a plane at an angle:
    its top face, a square of half side ``extent`` centred on ``point``,
    lies in the plane with outward normal ``normal``; it is ``thickness``
    deep behind the plane.

    Examples
    --------
    >>> c = plane_corners((0, 0, 1), (0, 0, 2), 3.0, 0.5)
    >>> sorted(set(np.round(c[:, 2], 12).tolist())), float(np.abs(c[:, 0]).max())
    ([0.5, 1.0], 3.0)
    """
    n = np.asarray(normal, float)
    n = n / np.linalg.norm(n)
    u = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 else [0, 1.0, 0])
    u /= np.linalg.norm(u)
    w = np.cross(n, u)
    p = np.asarray(point, float)
    return np.array([p + a * extent * u + b * extent * w - c * thickness * n
                     for a in (-1, 1) for b in (-1, 1) for c in (0, 1)])


def plane_body(point, normal, extent, material, thickness=None):
    """A fixed ``Polyhedra`` body (append it to ``O.bodies``) for a plane at
    an angle, which YADE's ``Wall`` (axis-aligned) cannot be: the slab of
    :func:`plane_corners` (``thickness`` default ``extent / 10``). Its overlap
    with a grain is exactly the grain's part beyond the plane while the grain
    stays within ``extent`` of ``point`` and less than ``thickness`` deep."""
    from yade import polyhedra_utils

    thickness = extent / 10 if thickness is None else thickness
    corners = plane_corners(point, normal, extent, thickness)
    return polyhedra_utils.polyhedra(material, v=[tuple(c) for c in corners], fixed=True)


class _Kernel(ContactEngine):
    """A :class:`shapes.engine.ContactEngine` with walls of any axis and
    sign (the base class has six box walls or none)."""

    def __init__(self, vertices, triangles, k_v, kt, mu, mu_wall, skin, wall_axis, wall_sign, threads):
        self.layout = __import__("shapes.engine", fromlist=["layout"]).layout()
        n = len(vertices)
        self.n = n
        self.voff = ckernel.i32(np.concatenate([[0], np.cumsum([len(v) for v in vertices])]))
        self.toff = ckernel.i32(np.concatenate([[0], np.cumsum([len(t) for t in triangles])]))
        self.v = ckernel.f64(np.concatenate([np.asarray(v, float) for v in vertices]))
        self.t = ckernel.i32(np.concatenate([np.asarray(t) for t in triangles]))
        self.shape = ckernel.i32(np.arange(n))
        self.size = ckernel.f64(np.ones(n))             # k_t = kt_coef * 1^2 = k_s of the materials
        self.nw = len(wall_axis)
        if self.nw > self.layout["max_walls"]:
            raise SceneError(f"PolyhedraContactEngine: {self.nw} walls, the kernel takes at most "
                             f"{self.layout['max_walls']}")
        self.wall_axis = ckernel.i32(np.asarray(wall_axis, np.int32).reshape(-1) if self.nw else np.zeros(1, np.int32))
        self.wall_sign = ckernel.f64(np.asarray(wall_sign, float).reshape(-1) if self.nw else np.zeros(1))
        self.threads = int(threads)
        self.lib = ckernel.load()
        self.handle = self.lib.pc_engine_new(
            n, ckernel.iptr(self.voff), ckernel.dptr(self.v), ckernel.iptr(self.toff), ckernel.iptr(self.t), n,
            ckernel.iptr(self.shape), ckernel.dptr(self.size), self.nw, ckernel.iptr(self.wall_axis),
            ckernel.dptr(self.wall_sign), float(k_v), float(kt), float(mu), float(mu_wall), float(skin), self.threads)
        if not self.handle:
            raise EngineError("could not create the contact engine (out of memory?)")
        self.lib.pc_engine_set_mode(self.handle, 1)
        self.fast = True
        self.groups = None
        self.force = np.zeros((n, 3))
        self.torque = np.zeros((n, 3))
        self.wall_force = np.zeros((max(self.nw, 1), 3))
        self.stat = np.zeros(len(self.layout["stat_names"]))
        self._stat_index = {k: i for i, k in enumerate(self.layout["stat_names"])}
        self._no_walls = np.zeros(1)
        self.wall_pos = np.zeros(max(self.nw, 1))
        self.pos = np.zeros((n, 3))
        self.quat = np.zeros((n, 4))


#: the fields the engine writes: (class attribute, offset list index, 3 for a vector, 1 for a scalar)
GEOM_FIELDS = (("normal", 3), ("contactPoint", 3), ("penetrationVolume", 1))
PHYS_FIELDS = (("normalForce", 3), ("shearForce", 3), ("kn", 1), ("ks", 1), ("tangensOfFrictionAngle", 1))


def field_offsets(cls, obj, size, fields):
    """Byte offsets of ``fields`` ((name, 3 or 1) pairs) in the C++ object
    of the YADE Python object ``obj`` of ``size`` bytes: each field is set
    to distinct values from Python and found, once and only once, in the
    object's memory by the plugin's ``fieldOffsets``. Raises
    :class:`SceneError` (one line) when a field is not found exactly once or
    a vector's components do not follow each other."""
    from yade import Vector3

    out = []
    for k, (name, width) in enumerate(fields):
        vals = [1.2345678901234567e-7 * (k + 1) + 3.1e-11 * c + 7.7e-3 for c in range(width)]
        setattr(obj, name, Vector3(*vals) if width == 3 else vals[0])
        hits = [list(cls.fieldOffsets(obj, int(size), v)) for v in vals]
        if any(len(h) != 1 for h in hits) or any(hits[c][0] != hits[0][0] + 8 * c for c in range(width)):
            raise SceneError(f"PolyhedraContactEngine: {type(obj).__name__}.{name} is not where this plugin "
                             f"can write it (found at {hits}): another YADE build")
        out.append(hits[0][0])
    return out


class SceneContacts:
    """What the engine computes for the scene in ``O`` (made by
    :func:`PolyhedraContactEngine`; the engine calls :meth:`scan`)."""

    def __init__(self, O, engine, facet_thickness=None, skin=None, threads=0):
        self.O, self.e = O, engine
        self.facet_thickness, self.skin_given, self.threads = facet_thickness, skin, int(threads)
        self.kernel = None
        self.rows = []            # body ids of the kernel rows (grains, then facets)
        self.walls = []
        self.wall_sign = {}       # wall id -> +1 / -1, once decided
        self.facet_side = {}      # facet id -> +1 / -1, once decided
        self.shapes = {}          # body id -> (vertices, triangles) in the body frame
        self.group_of = {}        # body id -> its clump id (-1: none) at the last scan
        self.scans = 0
        self.note = ""
        self._restore = None      # after O.load: the saved kernel state, given to the first kernel built

    # ------------------------------------------------------------ O.save / O.load
    def saved(self):
        """What O.save keeps in the engine's ``savedState`` (the engine
        calls this while O.save runs): base64 of an npz holding the options
        (facet thickness, skin, threads), the scan's choices (each facet's
        side, each wall's sign), the kernel rows' and walls' body ids, the
        grains' shapes (vertices m and triangles, body frame) and the kernel's
        state (:meth:`shapes.engine.ContactEngine.state`: poses, neighbour
        list with every pair's shear history, wall contacts, counters)."""
        meta = {"format": 1, "facet_thickness": self.facet_thickness, "skin": self.skin_given,
                "threads": self.threads, "facet_side": sorted(self.facet_side.items()),
                "wall_sign": sorted(self.wall_sign.items()), "rows": [], "walls": [], "kernel": False}
        arrays = {}
        if self.kernel is not None:
            meta.update(rows=[int(i) for i in self.rows], walls=[int(w) for w in self.walls], kernel=True,
                        nw=int(self.kernel.nw))
            arrays.update({f"state/{k}": v for k, v in self.kernel.state().items()})
        for i in self.rows if self.kernel is not None else []:      # the grains' (facets are scanned again)
            if i in self.shapes:
                v, t = self.shapes[i]
                arrays[f"shape/{i}/v"], arrays[f"shape/{i}/t"] = np.asarray(v, float), np.asarray(t, np.int64)
        arrays["meta"] = np.frombuffer(json.dumps(meta).encode(), np.uint8)
        buf = io.BytesIO()
        np.savez(buf, **arrays)
        return base64.b64encode(buf.getvalue()).decode("ascii")

    def restore(self, text):
        """Take back what :meth:`saved` wrote (an engine read by O.load):
        options, the scan's choices and shapes now; the kernel's state at the
        next scan, carried by body id like a rescan's. Raises
        :class:`SceneError` (one line) for a state this code cannot read."""
        try:
            with np.load(io.BytesIO(base64.b64decode(text.encode("ascii"), validate=True))) as z:
                arrays = {k: z[k] for k in z.files}
            meta = json.loads(arrays.pop("meta").tobytes().decode())
        except (ValueError, KeyError, OSError) as exc:
            raise SceneError(f"PolyhedraContactEngine: the saved state cannot be read ({exc})") from None
        if meta.get("format") != 1:
            raise SceneError(f"PolyhedraContactEngine: a saved state of format {meta.get('format')!r}, "
                             "this code reads format 1")
        self.facet_thickness, self.skin_given, self.threads = meta["facet_thickness"], meta["skin"], meta["threads"]
        self.facet_side = {int(k): float(v) for k, v in meta["facet_side"]}
        self.wall_sign = {int(k): float(v) for k, v in meta["wall_sign"]}
        for k in arrays:
            if k.startswith("shape/") and k.endswith("/v"):
                i = int(k.split("/")[1])
                self.shapes[i] = (arrays[k], arrays[f"shape/{i}/t"])
        if meta["kernel"]:
            st = {k[len("state/"):]: v for k, v in arrays.items() if k.startswith("state/")}
            self._restore = (st, list(meta["rows"]), list(meta["walls"]), int(meta["nw"]))

    # ------------------------------------------------------------ the scene's bodies
    def _classify(self):
        O = self.O
        if O.periodic:
            raise SceneError("PolyhedraContactEngine: periodic cells are not supported (O.periodic is True); "
                             "bound the sample with walls or facets")
        grains, facets, walls = [], [], []
        for b in O.bodies:
            if b is None:
                continue
            kind = type(b.shape).__name__
            if kind == "Polyhedra":
                grains.append(b)
            elif kind == "Facet":
                facets.append(b)
            elif kind == "Wall":
                if b.isClumpMember:
                    raise SceneError(f"PolyhedraContactEngine: wall {b.id} is a member of clump {b.clumpId}; "
                                     "walls cannot be clumped here (clump polyhedra, or facets)")
                walls.append(b)
            elif kind != "Clump":            # a clump is its members (ordinary bodies here); it moves them
                raise SceneError(f"PolyhedraContactEngine: body {b.id} is a {kind}; this engine computes "
                                 "Polyhedra, Facet and Wall bodies only")
        return grains, facets, walls

    def _grain_shape(self, b):
        if b.id not in self.shapes:
            v = np.array([tuple(x) for x in b.shape.v], float)
            if len(v) < 4:
                raise SceneError(f"PolyhedraContactEngine: polyhedron {b.id} has {len(v)} vertices")
            self.shapes[b.id] = (v, outward_triangles(v, b.shape.GetSurfaceTriangulation()))
        return self.shapes[b.id]

    def _law(self, grains, facets, walls):
        gm = list({id(b.material): b.material for b in grains}.values())
        keys = {law_of(a, c) for a in gm for c in gm} | {law_of(a, f.material) for a in gm for f in facets}
        if len(keys) > 1:
            raise SceneError("PolyhedraContactEngine: the materials give several contact laws for polyhedra and "
                             f"facets ((kn, ks, mu) = {sorted(keys)[:3]}); give them one material")
        kn, ks, mu = keys.pop()
        wl = {law_of(a, w.material) for a in gm for w in walls}
        if any((k, s) != (kn, ks) for k, s, _ in wl) or len({m for _, _, m in wl}) > 1:
            raise SceneError("PolyhedraContactEngine: the walls' materials give another stiffness than the "
                             "polyhedra's, or several friction angles; give the walls one material with the "
                             "polyhedra's young and poisson")
        mu_wall = next(iter(wl))[2] if wl else mu
        return kn, ks, mu, mu_wall

    def _sides(self, grains, facets, walls):
        centres = np.array([tuple(b.state.pos) for b in grains], float).reshape(-1, 3)
        for f in facets:
            if f.id in self.facet_side:
                continue
            n = np.array(tuple(f.state.ori * f.shape.normal))
            s = np.sign((centres - np.array(tuple(f.state.pos))) @ n)
            self.facet_side[f.id] = -1.0 if np.sum(s < 0) > np.sum(s > 0) else 1.0
        for w in walls:
            if w.id in self.wall_sign:
                continue
            if w.shape.sense != 0:
                self.wall_sign[w.id] = float(np.sign(w.shape.sense))
                continue
            s = np.sign(centres[:, w.shape.axis] - w.state.pos[w.shape.axis])
            if np.any(s > 0) and np.any(s < 0):
                raise SceneError(f"PolyhedraContactEngine: wall {w.id} (sense 0) has polyhedra on both sides; "
                                 "give it sense=1 or -1")
            self.wall_sign[w.id] = -1.0 if np.any(s < 0) else 1.0

    def scan(self):
        """Read the scene's bodies and materials, build the kernel's engine
        (the old one's state carried over, by body id) and bind it to the
        engine. Called by the engine at its first step and when the bodies
        changed; raises :class:`SceneError` (one line) for a scene it
        cannot compute."""
        O, e = self.O, self.e
        grains, facets, walls = self._classify()
        self.scans += 1
        if not grains:
            self._drop()
            e.bindIdle()
            return
        kn, ks, mu, mu_wall = self._law(grains, facets, walls)
        self._sides(grains, facets, walls)
        verts, tris = [], []
        for b in grains:
            v, t = self._grain_shape(b)
            verts.append(v)
            tris.append(t)
        sizes = [2 * np.max(np.linalg.norm(v, axis=1)) for v in verts]
        d = float(np.mean(sizes))
        thick = self.facet_thickness if self.facet_thickness is not None else d
        for f in facets:
            v, t = facet_prism([tuple(x) for x in f.shape.vertices], tuple(f.shape.normal), thick,
                               self.facet_side[f.id])
            verts.append(v)
            tris.append(t)
        skin = self.skin_given if self.skin_given is not None else 0.1 * d
        rows = [b.id for b in grains] + [f.id for f in facets]
        wids = [w.id for w in walls]
        kern = _Kernel(verts, tris, kn, ks, mu, mu_wall, skin, [w.shape.axis for w in walls],
                       [self.wall_sign[w.id] for w in walls], self.threads or 0)
        # members of one clump are never a pair (YADE's Collider::mayCollide)
        groups = [b.clumpId if b.isClumpMember else -1 for b in grains + facets]
        if self.kernel is not None:
            old = self.kernel
            self._carry(kern, rows, wids, grains + facets, old.state(), self.rows, self.walls, old.nw, groups)
        elif self._restore is not None:          # the first scan after O.load: the saved state
            st, orows, owalls, onw = self._restore
            self._restore = None
            if (orows, owalls, onw) == (rows, wids, len(wids)):
                kern.set_state(st)               # the same bodies: the state as it was, whole
            else:
                self._carry(kern, rows, wids, grains + facets, st, orows, owalls, onw, groups)
        if any(g >= 0 for g in groups):
            kern.set_groups(groups)
        if facets:       # two facets never a pair, no wall pushes a facet (YADE has neither functor: a
            kern.set_facets(len(grains))       # facetBox's prisms overlap at its corners, a wall may cross one)
        self.group_of = dict(zip(rows, groups))
        self._drop()
        self.kernel, self.rows, self.walls = kern, rows, wids
        e.ids, e.walls, e.wallAxis, e.nGrains = rows, wids, [w.shape.axis for w in walls], len(grains)
        e.law = [kn, ks, mu, mu_wall]
        if e.fillEvery and len(e.geomOffsets) != 3:
            self._measure()
        e.bind(kern.lib._name, int(kern.handle), kern.pos.ctypes.data, kern.quat.ctypes.data,
               kern.wall_pos.ctypes.data, kern.force.ctypes.data, kern.torque.ctypes.data,
               kern.wall_force.ctypes.data, kern.stat.ctypes.data)

    def release(self):
        """Free the kernel and part from the engine, whose scan and save
        are unset (an engine of a scene that O.load or O.reset replaced:
        the engine and this object, which hold each other through C++, are
        then freed); if that engine steps again it stops with "no scan
        function"."""
        self._drop()
        self.e.setScan(None)
        self.e.setSave(None)

    def _drop(self):
        if self.kernel is not None:
            self.e.unbind()
            self.kernel.close()
            self.kernel = None

    def _measure(self):
        from yade.wrapper import PolyhedraGeom, PolyhedraPhys

        sizes = load.measured_sizes()
        cls = type(self.e)
        self.e.geomOffsets = field_offsets(cls, PolyhedraGeom(), sizes["PolyhedraGeom"], GEOM_FIELDS)
        self.e.physOffsets = field_offsets(cls, PolyhedraPhys(), sizes["PolyhedraPhys"], PHYS_FIELDS)

    def _carry(self, new, rows, wids, bodies, st, old_rows, old_walls, old_nw, groups):
        """Give ``new`` the kernel state ``st`` of an engine whose rows
        were the bodies ``old_rows`` and whose ``old_nw`` walls ``old_walls``
        (the kernel replaced, or the one saved by O.save), row by body id:
        poses, neighbour list with the shear histories, wall contacts; a new
        body starts from its pose now, with the neighbour list rebuilt, as
        does one whose clump changed (``groups``: each row's kernel group;
        a body released from a clump gets its pairs with the clump's other
        members back)."""
        orow = {b: k for k, b in enumerate(old_rows)}
        owall = {w: k for k, w in enumerate(old_walls)}
        n, nw, onw = len(rows), len(wids), max(old_nw, 1)
        mp = np.array([orow.get(b, -1) for b in rows])
        wmp = np.array([owall.get(w, -1) for w in wids], int)
        x = np.zeros((n, 3))
        R = np.zeros((n, 9))
        xb = np.zeros((n, 3))
        mo = np.zeros(n)
        for k, b in enumerate(bodies):
            if mp[k] >= 0:
                x[k], R[k], xb[k], mo[k] = st["x"][mp[k]], st["R"][mp[k]], st["xbuild"][mp[k]], st["motion"][mp[k]]
                if self.group_of.get(b.id, groups[k]) != groups[k]:
                    xb[k] = x[k] + _FAR
            else:
                x[k] = tuple(b.state.pos)
                w, qx, qy, qz = b.state.ori.__getinitargs__()
                R[k] = _quat_matrix(w, qx, qy, qz).ravel()
                xb[k] = x[k] + _FAR
        inv = {int(o): k for k, o in enumerate(mp) if o >= 0}
        keep = [(inv[i], inv[j], r) for (i, j), r in zip(st["pair_ids"].tolist(), st["pair_records"])
                if i in inv and j in inv]
        keep = [(min(a, b), max(a, b), r) for a, b, r in keep]
        keep.sort(key=lambda t: (t[0], t[1]))
        L = new.layout
        W = max(nw, 1)
        ws, wr, wt = np.zeros((n * W, 3)), np.zeros((n * W, L["wall_doubles"])), np.zeros(n * W, np.int32)
        for k in range(n):
            for c in range(nw):
                if mp[k] >= 0 and wmp[c] >= 0:
                    src = mp[k] * onw + wmp[c]
                    ws[k * W + c], wr[k * W + c], wt[k * W + c] = (st["wall_shear"][src], st["wall_results"][src],
                                                                   st["wall_touching"][src])
        sc = np.zeros(L["scalars"])
        sc[0], sc[1] = st["scalars"][0], st["scalars"][1]
        for c in range(nw):
            if wmp[c] >= 0:
                sc[2 + c] = st["scalars"][2 + wmp[c]]
        new.set_state({"x": x, "R": R, "xbuild": xb, "motion": mo,
                       "pair_ids": np.array([(a, b) for a, b, _ in keep], np.int32).reshape(-1, 2),
                       "pair_records": np.array([r for _, _, r in keep]).reshape(-1, L["pair_doubles"]),
                       "wall_shear": ws, "wall_results": wr, "wall_touching": wt, "scalars": sc,
                       "friction": np.array(st["friction"])})

    def set_friction(self, angle, wall_angle=None):
        """Set the friction angle (rad) of every polyhedron's and facet's
        material (and of the walls', ``wall_angle``, default ``angle``), and
        the kernel's mu = tan(angle) at once (YADE's setContactFriction does
        the same to its interactions); shear histories above the new cap
        are cut to it at the next step."""
        wall_angle = angle if wall_angle is None else wall_angle
        for b in self.O.bodies:
            if b is None:
                continue
            kind = type(b.shape).__name__
            if kind in ("Polyhedra", "Facet"):
                b.material.frictionAngle = angle
            elif kind == "Wall":
                b.material.frictionAngle = wall_angle
        mu, mu_wall = math.tan(angle), math.tan(min(angle, wall_angle))
        if self.kernel is not None:
            self.kernel.set_friction(mu, mu_wall)
        law = list(self.e.law)
        self.e.law = law[:2] + [mu, mu_wall]

    # ------------------------------------------------------------ what Python reads
    def contacts(self):
        """The kernel's touching contacts of the last step (without facet–facet
        ones): dict of ``id1``, ``id2`` (N,) body ids, ``point``, ``normal``
        (id1 to id2), ``force_normal``, ``force_tangential`` (on id2) (N, 3)
        and ``volume`` (N,) m^3."""
        if self.kernel is None:
            z = np.zeros((0, 3))
            return {"id1": np.zeros(0, int), "id2": np.zeros(0, int), "point": z, "normal": z,
                    "force_normal": z, "force_tangential": z, "volume": np.zeros(0)}
        c = self.kernel.contacts()
        rows, walls = np.asarray(self.rows), np.asarray(self.walls or [-1])
        i, j = c["i"], c["j"]
        ng = int(self.e.nGrains)
        ok = i < ng
        id1 = np.where(i >= 0, rows[np.maximum(i, 0)], walls[np.clip(-1 - i, 0, len(walls) - 1)])
        return {"id1": id1[ok], "id2": rows[j][ok], "point": c["point"][ok], "normal": c["normal"][ok],
                "force_normal": c["force_normal"][ok], "force_tangential": c["force_tangential"][ok],
                "volume": c["volume"][ok]}

    def timing(self):
        """Seconds reading poses, in the kernel, adding forces, filling
        O.interactions, and the numbers of steps and fills."""
        c = list(self.e.counters)
        return {"read": c[0], "kernel": c[1], "apply": c[2], "fill": c[3], "steps": int(c[4]), "fills": int(c[5])}


def _quat_matrix(w, x, y, z):
    """(3, 3) rotation matrix of the unit quaternion (w, x, y, z)."""
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


#: the SceneContacts of each engine made here, by label (what scripts and tests read)
SCENES = {}


def PolyhedraContactEngine(fillEvery=1, label="polyhedraContacts", facetThickness=None, skin=None, threads=0,
                           O=None):
    """The engine for ``O.engines`` (between ``ForceResetter`` and
    ``NewtonIntegrator``, with no collider and no ``InteractionLoop``).

    Parameters
    ----------
    fillEvery : int
        Write the contacts to ``O.interactions`` every this many steps (1:
        every step; 0: never).
    label : str
        The engine's label; :data:`SCENES` [label] is its
        :class:`SceneContacts` (contacts, timing).
    facetThickness : float, optional
        m, the thickness of the prism behind each facet (default: the mean
        polyhedron size, twice its largest vertex distance).
    skin : float, optional
        m, the kernel's Verlet margin (default 0.1 of that size).
    threads : int
        OpenMP threads of the kernel (0: YADE's ``-j``).
    O : Omega, optional
        Default: YADE's.

    Returns
    -------
    yade.wrapper.PolyhedraContactEngine
        The C++ engine, with its scan set (it reads the bodies at its first
        step). Raises :class:`load.PluginError` (one line) when the plugin
        is not built for this YADE, :class:`SceneError` for a periodic cell.
    """
    if int(fillEvery) != fillEvery or fillEvery < 0:
        raise ValueError(f"PolyhedraContactEngine: fillEvery must be a whole number of steps >= 0, got {fillEvery!r}")
    if facetThickness is not None and not facetThickness > 0:
        raise ValueError(f"PolyhedraContactEngine: facetThickness must be > 0 (m), got {facetThickness!r}")
    if skin is not None and not skin > 0:
        raise ValueError(f"PolyhedraContactEngine: skin must be > 0 (m), got {skin!r}")
    if O is None:
        from yade import O
    if O.periodic:
        raise SceneError("PolyhedraContactEngine: periodic cells are not supported (O.periodic is True); "
                         "bound the sample with walls or facets")
    cls = load.engine_class()
    e = cls(label=label, fillEvery=int(fillEvery))
    sc = SceneContacts(O, e, facetThickness, skin, threads)
    e.setScan(sc.scan)
    e.setSave(sc.saved)
    _replace(label, sc)
    return e


def _replace(label, sc):
    """SCENES[label] = sc; the SceneContacts it replaces is released when
    its engine is no longer in the scene (after O.reset or O.load)."""
    old = SCENES.get(label)
    if old is not None and old is not sc and not old.e.inCurrentScene:
        old.release()
    SCENES[label] = sc


def load_plugin():
    """Load the plugin into this YADE if it is not (a script started
    without ``YADE_PREFIX``): call it before ``O.load`` of a scene holding
    the engine, which YADE reads only once it knows the class. Returns the
    class; raises :class:`load.PluginError` (one line) when the plugin is
    not built for this YADE and these sources."""
    return load.engine_class()


def adopt(O=None):
    """Give each ``PolyhedraContactEngine`` of ``O.engines`` that has no
    scan (read by O.load, or made as ``yade.wrapper.PolyhedraContactEngine()``)
    its :class:`SceneContacts`, in :data:`SCENES` under its label, with what
    O.save kept (``savedState``): the engine's first step calls this, so
    after O.load the scene steps on with the kernel's state as it was saved
    (the pairs' shear histories, the neighbour list), bit for bit. Call it
    yourself to read ``SCENES[label]`` before that step. Returns the
    engines adopted (list)."""
    if O is None:
        from yade import O
    cls = load.engine_class()
    out = []
    for e in O.engines:
        if not isinstance(e, cls) or e.hasScan:
            continue
        sc = SceneContacts(O, e)
        if e.savedState:
            sc.restore(e.savedState)
        e.setScan(sc.scan)
        e.setSave(sc.saved)
        _replace(e.label, sc)
        out.append(e)
    return out
