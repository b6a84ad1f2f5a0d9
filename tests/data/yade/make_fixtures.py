"""Make the real-YADE fixtures of tests/test_yade_fixtures.py.

    cd tests/data/yade && yade -j1 -n -x make_fixtures.py

(Debian's yade 2023.02a; not run by the test suite: its outputs, written
next to this script, are committed.)

A periodic packing of 150 frictional spheres (radii 4 mm +- 30 %, friction
0.5, YADE's FrictMat with Cundall-Strack contacts) is compressed
isotropically to 10 kPa by PeriTriaxController, then sheared by the cell's
velocity gradient (dv_x/dz) while the controller keeps 10 kPa on the
diagonal, so the stress has off-diagonal terms and the cell is tilted. At three states (isotropic; sheared twice) it writes

* ``yade.h5``: the project's own dump (postproc/schema.py's DumpWriter, the
  cell as a (3, 3) matrix, bodies and contacts gathered by
  yade_scripts/scene/yadedump.py, as the scene does);
* ``table-K.csv``: a flat contact table as a YADE user writes it from
  ``O.interactions`` (ids, centres, contact point, force on id2 by id1,
  the branch vector pos2 - pos1 + hSize * cellDist);
* ``reference.json``: YADE's own ``utils.getStress()`` and
  ``utils.fabricTensor()`` beside the cell, its volume and the number of
  contacts carrying a force.
"""
import json
import os
import sys

import numpy as np
from yade import pack, utils

HERE = os.path.dirname(os.path.abspath(sys.argv[0] if sys.argv[0].endswith(".py") else __file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, ROOT)
from postproc.schema import DumpWriter  # noqa: E402
from yade_scripts.scene import yadedump  # noqa: E402

SIGMA0, N, R = 1e4, 150, 0.004
O.periodic = True
L0 = 0.06
O.cell.hSize = Matrix3(L0, 0, 0, 0, L0, 0, 0, 0, L0)
mat = O.materials.append(FrictMat(young=5e7, poisson=0.5, frictionAngle=np.arctan(0.5), density=2600))
sp = pack.SpherePack()
sp.makeCloud((0, 0, 0), (L0, L0, L0), rMean=R, rRelFuzz=0.3, num=N, periodic=True, seed=7)
sp.toSimulation(material=mat)
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb()]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                    [Law2_ScGeom_FrictPhys_CundallStrack()]),
    PeriTriaxController(goal=(-SIGMA0, -SIGMA0, -SIGMA0), stressMask=7, maxUnbalanced=0.01, relStressTol=1e-3,
                        maxStrainRate=(0.5, 0.5, 0.5), dynCell=True, mass=0.2, doneHook="O.pause()",
                        label="triax"),
    NewtonIntegrator(damping=0.3),
]
O.dt = 0.5 * utils.PWaveTimeStep()
O.run(200000, True)
print("isotropic after", O.iter, "steps; stress", utils.getStress().diagonal())

ids = [b.id for b in O.bodies]
radii = np.array([O.bodies[i].shape.radius for i in ids])
out = os.path.join(HERE, "yade.h5")
for f in [out] + [os.path.join(HERE, f) for f in os.listdir(HERE) if f.startswith("table-")]:
    if os.path.exists(f):
        os.remove(f)
writer = DumpWriter(out, "spheres", {"sigma0": SIGMA0, "friction": 0.5, "source": "make_fixtures.py"},
                               overlap_kind="depth")
reference = []


def snapshot(k, stage):
    H = np.array([[O.cell.hSize[a][b] for b in range(3)] for a in range(3)])
    writer.write_snapshot(step=O.iter, time=O.time, stage=stage, box_lo=np.zeros(3), box_hi=np.diag(H).copy(),
                          wall_ids=np.zeros(0, np.int64), wall_forces=np.zeros((0, 3)),
                          bodies=yadedump.gather_bodies(O, ids, 0, np.full(len(ids), -1), 2 * radii),
                          contacts=yadedump.gather_contacts(O, False), cell=H)
    rows = []
    for i in O.interactions:
        if not i.isReal or i.phys.normalForce.squaredNorm() == 0:
            continue
        p1, p2 = O.bodies[i.id1].state.pos, O.bodies[i.id2].state.pos
        shift = O.cell.hSize * Vector3(*[float(c) for c in i.cellDist])
        l = p2 + shift - p1
        f = i.phys.normalForce + i.phys.shearForce
        rows.append("%d,%d,%s" % (i.id1, i.id2, ",".join(repr(float(x)) for x in
                                                          (*p1, *p2, *i.geom.contactPoint, *f, *l))))
    name = os.path.join(HERE, f"table-{k}.csv")
    with open(name, "w") as fh:
        fh.write("id1,id2,x1,y1,z1,x2,y2,z2,cx,cy,cz,fx,fy,fz,lx,ly,lz\n" + "\n".join(rows) + "\n")
    S = utils.getStress()
    F = utils.fabricTensor()
    F = F[0] if isinstance(F, tuple) else F
    reference.append({"step": O.iter, "stage": stage, "table": os.path.basename(name),
                      "getStress": [[S[a][b] for b in range(3)] for a in range(3)],
                      "fabricTensor": [[F[a][b] for b in range(3)] for a in range(3)],
                      "hSize": H.tolist(), "cell_volume": O.cell.volume, "n_contacts": len(rows)})


snapshot(0, "isotropic")
triax.doneHook = ""                                       # keeps sigma0 on the diagonal, no more pauses
g = O.cell.velGrad
O.cell.velGrad = Matrix3(g[0][0], 0, 2.0, 0, g[1][1], 0, 0, 0, g[2][2])     # and dv_x / dz: shear in xz
for k in (1, 2):
    O.run(1500, True)
    snapshot(k, "shear")
writer.close(pack=True)
with open(os.path.join(HERE, "reference.json"), "w") as fh:
    json.dump({"yade": version, "note": "getStress and fabricTensor as returned by YADE", "snapshots": reference},
              fh, indent=1)
print("fixtures:", sorted(os.listdir(HERE)))

