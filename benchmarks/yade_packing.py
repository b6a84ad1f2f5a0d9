"""A dumped polyhedra packing rebuilt in YADE (for the benchmarks run inside
YADE: bench_engines.py, bench_scale_dense.py).

    from yade_packing import build_packing
    pk = build_packing(O, "RUN.h5", snapshot)

The dumped shapes and poses become YADE ``Polyhedra`` bodies of the run's
material (its volumetric stiffness k_V, density and friction), the six walls
(ids first) sit at the snapshot's box, fixed, and ``O.dt`` is the run's.
Returns a dict: particles and walls (body ids), vertices and triangles per
particle as YADE holds them (``yadedump.polyhedra_shapes``), sizes (m), the
run's parameters P and the snapshot.
"""
import math
import os
import sys

import numpy as np
from yade import polyhedra_utils, utils
from yade.wrapper import PolyhedraMat

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)
from postproc.schema import DumpReader  # noqa: E402
from yade_scripts.scene.yadedump import polyhedra_shapes  # noqa: E402


def build_packing(O, dump, snapshot=0):
    """Rebuild snapshot ``snapshot`` of the polyhedra dump ``dump`` in the
    (empty) scene O; see the module docstring."""
    from yade.minieigenHP import Quaternion

    with DumpReader(dump) as r:
        v, _, _ = r.shapes()
        s = r.read(snapshot)
        P = r.parameters
    k_v = P["kn_volumetric"]
    grain = PolyhedraMat(young=2 * k_v, poisson=1e-20, frictionAngle=math.atan(P["friction"]), density=P["density"])
    wallmat = PolyhedraMat(young=2 * k_v, poisson=1e-20, frictionAngle=math.atan(P["wall_friction"]),
                           density=P["density"])
    O.materials.append(grain)
    O.materials.append(wallmat)
    walls = []
    for axis in range(3):
        for pos in (s.box_lo[axis], s.box_hi[axis]):
            w = utils.wall(float(pos), axis=axis, sense=0, material=wallmat)
            w.state.blockedDOFs = "xyzXYZ"
            walls.append(O.bodies.append(w))
    particles = []
    for k in range(len(s.body_ids)):
        b = polyhedra_utils.polyhedra(grain, v=[tuple(x) for x in v[int(s.shape_index[k])]])
        w_, x_, y_, z_ = s.orientations[k]
        b.state.ori = Quaternion(w_, x_, y_, z_) * b.state.ori
        b.state.pos = tuple(s.positions[k])
        particles.append(O.bodies.append(b))
    O.dt = P["dt"]
    shape_v, shape_t, _ = polyhedra_shapes(O, particles)
    return {"particles": particles, "walls": walls, "vertices": shape_v, "triangles": shape_t,
            "sizes": np.asarray(s.sizes, float), "P": P, "snapshot": s}
