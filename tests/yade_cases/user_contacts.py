"""Hand-built user scenes on ``PolyhedraContactEngine`` (one YADE process, no
YADE_PREFIX: the script loads the plugin itself). Prints one line
``RESULT {json}`` with what tests/test_user_contacts.py checks.

    yade -n -x user_contacts.py ROOT TMP          (TMP: a folder for the VTK file)

facet:   a 2 cm cube 0.1 mm into a large facet (E = 2e8, so k_n = 1e8);
         O.interactions cleared after the first step, the second step's.
moving:  a facet rising at 1 m/s under a held cube 0.1 mm above it.
tilted:  a rotated cube into a plane tilted by 0.3 rad about x and 0.2 rad
         about y (contacts.plane_body); its world vertices, the slab's, the plane.
wall:    a rotated cube into a Wall of axis y, sense -1.
stress:  12 random polyhedra dropped into a facetBox, 5000 steps (0.5 s);
         getStress(V) and the kernel's contacts of the last step; the
         interactions exported by export.VTKExporter.exportInteractions.
added:   two cubes sliding on a facet for 20 steps; at step 10 a third cube
         is added far away, then dropped on the facet; the sliding cubes'
         forces, with and without the addition.
refused: a periodic cell, a Sphere in the scene, a class layout other than
         the plugin expects, a plugin of other sources (the one-line messages).
"""
import json
import math
import sys

root, tmp = sys.argv[1], sys.argv[2]
sys.path.insert(0, root)
import os  # noqa: E402
import numpy as np  # noqa: E402
from yade import log, polyhedra_utils, utils, geom  # noqa: E402

from yade_scripts.yadeplugin.contacts import PolyhedraContactEngine, SCENES, plane_body  # noqa: E402

log.setLevel("Polyhedra_support.cpp", log.ERROR)
log.setLevel("Shop", log.ERROR)
A, E = 0.02, 2e8
CUBE = [(x, y, z) for x in (-A / 2, A / 2) for y in (-A / 2, A / 2) for z in (-A / 2, A / 2)]
out = {}


def new_scene(young=E, poisson=0.5, friction=0.5):
    O.reset()
    m = PolyhedraMat(young=young, poisson=poisson, frictionAngle=friction, density=2000)
    O.materials.append(m)
    O.dt = 1e-6
    return m


def engines(label, fill=1, gravity=(0, 0, 0), damping=0.0):
    O.engines = [ForceResetter(), PolyhedraContactEngine(fillEvery=fill, label=label),
                 NewtonIntegrator(gravity=gravity, damping=damping)]
    return O.engines[1]


def cube(m, pos, ori=None, v=CUBE):
    b = polyhedra_utils.polyhedra(m, v=v)
    b.state.pos = pos
    if ori is not None:
        b.state.ori = ori
    return O.bodies.append(b)


def world(i):
    b = O.bodies[i]
    return [tuple(b.state.pos + b.state.ori * x) for x in b.shape.v]


def inter(i):
    return {"id1": i.id1, "id2": i.id2, "normal": tuple(i.geom.normal), "point": tuple(i.geom.contactPoint),
            "volume": i.geom.penetrationVolume, "fn": tuple(i.phys.normalForce), "ft": tuple(i.phys.shearForce),
            "kn": i.phys.kn, "ks": i.phys.ks, "mu": i.phys.tangensOfFrictionAngle}


def kernel_contacts(label):
    c = SCENES[label].contacts()
    return {k: np.asarray(v).tolist() for k, v in c.items()}


# ---------------------------------------------------------------- facet
m = new_scene()
c0 = cube(m, (0.001, 0.002, A / 2 - 1e-4))
O.bodies[c0].state.blockedDOFs = "xyzXYZ"       # held: both steps see the same overlap
f0 = O.bodies.append(utils.facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)], material=m, fixed=True))
engines("facet")
O.step()
O.interactions.clear()                     # a user's clear(): the next fill writes the contact again
O.step()
out["facet"] = {"force": tuple(O.forces.f(c0)), "torque": tuple(O.forces.t(c0)), "facet_force": tuple(O.forces.f(f0)),
                "inter": [inter(i) for i in O.interactions], "count": O.interactions.countReal(),
                "kernel": kernel_contacts("facet"), "error": O.engines[1].error}

# ---------------------------------------------------------------- a moving facet
m = new_scene()
c3 = cube(m, (0, 0, A / 2 + 1e-4))               # 0.1 mm above the facet, held
O.bodies[c3].state.blockedDOFs = "xyzXYZ"
f3 = O.bodies.append(utils.facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)], material=m, fixed=True))
O.bodies[f3].state.vel = (0, 0, 1.0)             # rising at 1 m/s: 1 um a step (dt = 1e-6)
engines("moving")
vols = []
for k in range(300):
    O.step()
    vols.append(sum(i.geom.penetrationVolume for i in O.interactions))
out["moving"] = {"volumes": vols, "dt": O.dt, "facet_z": O.bodies[f3].state.pos[2]}

# ---------------------------------------------------------------- tilted slab
m = new_scene()
q = Quaternion((1, 0, 0), 0.3) * Quaternion((0, 1, 0), 0.2)
T = 0.05
nrm = q * Vector3(0, 0, 1)
s0 = O.bodies.append(plane_body(tuple(nrm * T), tuple(nrm), 0.5, m, thickness=0.1))
c1 = cube(m, tuple(nrm * (T + A / 2 - 3e-4)), Quaternion(Vector3(1, 2, 3).normalized(), 0.7))
engines("tilted")
before = world(c1), world(s0)             # the poses the engine reads (Newton moves the cube in the step)
O.step()
out["tilted"] = {"cube": before[0], "slab": before[1], "plane_normal": tuple(nrm), "plane_point": tuple(nrm * T),
                 "force": tuple(O.forces.f(c1)), "inter": [inter(i) for i in O.interactions],
                 "kernel": kernel_contacts("tilted")}

# ---------------------------------------------------------------- axis wall
m = new_scene()
w0 = O.bodies.append(utils.wall(0.1, axis=1, sense=-1, material=m))
c2 = cube(m, (0, 0.1 - A / 2 + 2e-4, 0), Quaternion(Vector3(1, 1, 0).normalized(), 0.4))
engines("wall")
before = world(c2)
O.step()
out["wall"] = {"cube": before, "wall": 0.1, "force": tuple(O.forces.f(c2)), "wall_force": tuple(O.forces.f(w0)),
               "inter": [inter(i) for i in O.interactions]}

# ---------------------------------------------------------------- a wall across a facet's prism
m = new_scene()
f1 = O.bodies.append(utils.facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)], material=m, fixed=True))
w1 = O.bodies.append(utils.wall(0.05, axis=0, sense=-1, material=m))
c3 = cube(m, (0.05 - A / 2 + 1e-4, 0, A / 2 - 1e-4))
O.bodies[c3].state.blockedDOFs = "xyzXYZ"
engines("wallfacet")
O.step()
out["wallfacet"] = {"cube": c3, "wall": w1, "facet": f1, "force": tuple(O.forces.f(c3)),
                    "wall_force": tuple(O.forces.f(w1)), "facet_force": tuple(O.forces.f(f1)),
                    "inter": [inter(i) for i in O.interactions]}

# ---------------------------------------------------------------- getStress on a deposited packing
m = new_scene(young=1e7, friction=0.4)
O.dt = 1e-4
O.bodies.append(geom.facetBox((0, 0, 0.05), (0.05, 0.05, 0.05), material=m, wallMask=31))
rng = np.random.RandomState(3)
for k in range(12):
    b = polyhedra_utils.polyhedra(m, size=(0.02, 0.02, 0.02), seed=k + 1)
    b.state.pos = (rng.uniform(-0.03, 0.03), rng.uniform(-0.03, 0.03), 0.012 + 0.022 * k / 2)
    O.bodies.append(b)
engines("stress", gravity=(0, 0, -9.81), damping=0.5)
O.run(5000, True)
V = 0.1 * 0.1 * 0.1
st = utils.getStress(V)
from yade import export  # noqa: E402

vtk = export.VTKExporter(os.path.join(tmp, "packing"))
vtk.exportInteractions(what=dict(forceN="i.phys.normalForce.norm()", volume="i.geom.penetrationVolume"))
out["stress"] = {"getStress": [[st[a, b] for b in range(3)] for a in range(3)], "volume": V,
                 "pos": {b.id: tuple(b.state.pos) for b in O.bodies}, "kernel": kernel_contacts("stress"),
                 "count": O.interactions.countReal(), "unbalanced": utils.unbalancedForce(),
                 "pairs": SCENES["stress"].kernel.state()["pair_ids"].tolist(), "rows": SCENES["stress"].rows,
                 "n_grains": SCENES["stress"].e.nGrains,
                 "facets": {b.id: [tuple(b.state.pos + b.state.ori * v) for v in b.shape.vertices]
                            for b in O.bodies if type(b.shape).__name__ == "Facet"},
                 "vtk": sorted(os.path.join(tmp, f) for f in os.listdir(tmp) if f.endswith(".vtk"))}

# ---------------------------------------------------------------- bodies added mid-run


def sliding(add):
    m = new_scene(young=1e8, friction=0.5)
    O.dt = 1e-5
    f = O.bodies.append(utils.facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)], material=m, fixed=True))
    ids = [cube(m, (-0.05, 0, A / 2 - 1e-4)), cube(m, (0.05, 0, A / 2 - 1e-4))]
    for i, v in zip(ids, (0.01, -0.01)):
        O.bodies[i].state.vel = (v, 0, 0)
        O.bodies[i].state.blockedDOFs = "xyzXYZ"
    engines("added%d" % add)
    forces, new = [], None
    for k in range(20):
        if add and k == 10:
            new = cube(m, (0, 0.3, A / 2 - 5e-5))
            O.bodies[new].state.blockedDOFs = "xyzXYZ"
        O.step()
        forces.append([tuple(O.forces.f(i)) for i in ids])
    res = {"forces": forces, "facet": f, "n_inter": O.interactions.countReal()}
    if new is not None:
        res["new_force"] = tuple(O.forces.f(new))
        res["new_inter"] = [inter(i) for i in O.interactions if new in (i.id1, i.id2)]
        res["scans"] = SCENES["added1"].scans
    return res


out["added"] = {"with": sliding(1), "without": sliding(0)}
# an erased body: its contacts leave O.interactions and the kernel
O.bodies.erase(2)
O.step()
out["added"]["after_erase"] = {"n_inter": O.interactions.countReal(), "ids": list(O.engines[1].ids)}

# ---------------------------------------------------------------- refused
refused = {}
m = new_scene()
O.periodic = True
try:
    engines("periodic")
    refused["periodic"] = None
except Exception as exc:  # noqa: BLE001 - the message is the result
    refused["periodic"] = f"{type(exc).__name__}: {exc}"
m = new_scene()
cube(m, (0, 0, 0))
O.bodies.append(utils.sphere((0, 0, 1), 0.01, material=m))
engines("sphere")
try:
    O.step()
    refused["sphere"] = None
except Exception as exc:  # noqa: BLE001
    refused["sphere"] = f"{type(exc).__name__}: {exc}"
# another YADE's layout: a field not found where the plugin would write it
from yade_scripts.yadeplugin import contacts as C, load as L  # noqa: E402


class Elsewhere:
    @staticmethod
    def fieldOffsets(obj, size, value):
        return []


try:
    C.field_offsets(Elsewhere, PolyhedraGeom(), 208, C.GEOM_FIELDS)
    refused["layout"] = None
except Exception as exc:  # noqa: BLE001
    refused["layout"] = f"{type(exc).__name__}: {exc}"
# a plugin built from other sources than this copy's
ours, L.source_hash = L.source_hash, lambda: "0123456789ab"
try:
    L.engine_class()
    refused["sources"] = None
except Exception as exc:  # noqa: BLE001
    refused["sources"] = f"{type(exc).__name__}: {exc}"
L.source_hash = ours
out["refused"] = refused
print("RESULT " + json.dumps(out), flush=True)

os._exit(0)
