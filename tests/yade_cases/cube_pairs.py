"""Three stacked cube pairs (issue 4): the top cube of pair k slides at
+1 cm/s, -1 cm/s and 0 along x for 20 steps. Prints JSON with the final
shear force (x component, on the top cube) of each pair.

    yade -n -x cube_pairs.py stock|ours|kernel ROOT

stock:  YADE's volumetric law with its own shear (poisson 0.3);
ours:   the same normal law with poisson ~ 0 and yade_scripts.scene.tangential;
kernel: no InteractionLoop; the compiled kernel (yade_scripts.scene.kernel_contacts)
        with the same k_V = young / 2 and k_t.
Cubes of side 2 cm, overlap 0.1 mm, young 1e8, friction 0.5, dt 1e-5.
"""
import json
import math
import sys

import numpy as np
from yade import log, polyhedra_utils

mode, root = sys.argv[1], sys.argv[2]
sys.path.insert(0, root)
from yade_scripts.scene.kernel_contacts import KernelContacts  # noqa: E402
from yade_scripts.scene.tangential import TangentialLaw  # noqa: E402
from yade_scripts.scene.yadedump import polyhedra_shapes  # noqa: E402
from yade_scripts.runs.attempt import remove_scratch_at_exit  # noqa: E402

remove_scratch_at_exit(O.tmpFilename())      # YADE's /tmp/yade-XXXXXX of this process

log.setLevel("Polyhedra_support.cpp", log.ERROR)
OURS = mode == "ours"
KERNEL = mode == "kernel"
KT = 1.0e5  # N/m, our tangential stiffness in this test
mat = PolyhedraMat(young=1e8, poisson=1e-20 if OURS else 0.3, frictionAngle=math.atan(0.5), density=2700)
O.materials.append(mat)
h = 0.01
cube = [(x, y, z) for x in (-h, h) for y in (-h, h) for z in (-h, h)]
speeds = [0.01, -0.01, 0.0]
for k, vx in enumerate(speeds):
    b = polyhedra_utils.polyhedra(mat, v=cube)
    b.state.pos = (0, 0.1 * k, 0)
    b.state.blockedDOFs = "xyzXYZ"
    t = polyhedra_utils.polyhedra(mat, v=cube)
    t.state.pos = (0, 0.1 * k, 2 * h - 1e-4)
    t.state.blockedDOFs = "xyzXYZ"
    t.state.vel = (vx, 0, 0)
    O.bodies.append(b)
    O.bodies.append(t)
law = TangentialLaw(O, Vector3, lambda a, b, kn: np.full(len(a), KT))
if KERNEL:
    ids = list(range(6))
    v, t, _ = polyhedra_shapes(O, ids)
    d = 2 * math.sqrt(3) * h                           # the cube's d: k_t = coef * d^2 = KT
    kernel = KernelContacts(O, ids, None, v, t, np.full(6, d), 0.5e8, KT / d ** 2, 0.5, 0.0, 0.1 * d, 1)
    O.engines = [ForceResetter(), PyRunner(command="kernel()", iterPeriod=1, initRun=True), NewtonIntegrator(damping=0)]
else:
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Polyhedra_Aabb()]),
        InteractionLoop([Ig2_Polyhedra_Polyhedra_PolyhedraGeom()], [Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()],
                        [Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()]),
        PyRunner(command="law()", iterPeriod=1, dead=not OURS),
        NewtonIntegrator(damping=0),
    ]
O.dt = 1e-5
O.run(20, True)
out = {"mode": mode, "kt": KT, "dt": O.dt, "steps": 20, "speeds": speeds, "pairs": []}
if KERNEL:
    c = kernel.contacts()
    out["normal_tilt"] = []
for k in range(3):
    if KERNEL:
        row = int(np.flatnonzero((c["id1"] == 2 * k) & (c["id2"] == 2 * k + 1))[0])
        n = c["normal"][row]
        out["normal_tilt"].append(float(math.atan2(math.hypot(n[0], n[1]), n[2])))
        out["pairs"].append({"shear_x": float(c["force_tangential"][row, 0]),
                             "normal": float(np.linalg.norm(c["force_normal"][row])),
                             "volume": float(c["overlap"][row]), "force_on_top_x": O.forces.f(2 * k + 1)[0]})
        continue
    i = O.interactions[2 * k, 2 * k + 1]
    out["pairs"].append({"shear_x": i.phys.shearForce[0], "normal": i.phys.normalForce.norm(),
                         "force_on_top_x": O.forces.f(2 * k + 1)[0]})
print("RESULT " + json.dumps(out), flush=True)
sys.exit(0)
