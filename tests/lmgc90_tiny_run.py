"""A tiny LMGC90 run for tests/test_lmgc90files.py: eight POLYR grains (four
cubes, four random 12-vertex polyhedra, slightly turned) settling under
gravity on the floor of a box of six PLANx walls, 800 steps of 1e-4 s,
LMGC90's text output every 100 steps from step 400 (DATBOX/, OUTBOX/ in the current
folder) and, at the end, LMGC90's own reactions, centres and POLYR vertices
from chipy in reactions.json.

    python tests/lmgc90_tiny_run.py [STEPS] [--spheres]    (run in the folder to fill)

``--spheres``: eight SPHER grains of radii 0.9 R to 1.04 R instead
(interactions SPSPx and SPPLx).
"""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lmgc90.build import import_pylmgc90  # noqa: E402

L, R, T, DT = 0.03, 0.005, 0.002, 1e-4     # m box side, grain radius, wall half thickness; s
WRITE_FROM = 400                            # the grains touch the floor at about step 250


def scene(pre, spheres=False):
    """Write DATBOX/ for the eight grains in the walled box (eight SPHER
    grains of radius R instead with ``spheres``)."""
    os.makedirs("DATBOX", exist_ok=True)
    bodies, mats, mods = pre.avatars(), pre.materials(), pre.models()
    svs, tacts = pre.see_tables(), pre.tact_behavs()
    grain = pre.material(name="PLEXx", materialType="RIGID", density=2600.0)
    wallm = pre.material(name="TDURx", materialType="RIGID", density=2600.0)
    mats.addMaterial(grain)
    mats.addMaterial(wallm)
    mod = pre.model(name="rigid", physics="MECAx", element="Rxx3D", dimension=3)
    mods.addModel(mod)
    rng = np.random.default_rng(1)
    np.random.seed(5)          # pre's random polyhedra draw from numpy's global generator
    k = 0
    for ix in range(2):
        for iy in range(2):
            for iz in range(2):
                c = [0.0075 + 0.015 * ix, 0.0075 + 0.015 * iy, 0.0055 + 0.011 * iz]
                if spheres:
                    b = pre.rigidSphere(r=R * (0.9 + 0.02 * k), center=[c[0], c[1], c[2] + 0.001 * iz],
                                        model=mod, material=grain, color="BLUEx")
                else:
                    b = pre.rigidPolyhedron(radius=R, center=c, generation_type="random" if k % 2 else "regular",
                                            nb_vertices=8 if k % 2 == 0 else 12, model=mod, material=grain,
                                            color="BLUEx")
                    b.rotate(description="axis", alpha=float(rng.uniform(0, 0.3)), axis=list(rng.normal(size=3)),
                             center=c)
                bodies += b
                k += 1
    h = L / 2
    for centre, rot in (([h, h, -T], None), ([h, h, L + T], (np.pi, [1.0, 0, 0])),
                        ([-T, h, h], (0.5 * np.pi, [0, 1.0, 0])), ([L + T, h, h], (-0.5 * np.pi, [0, 1.0, 0])),
                        ([h, -T, h], (-0.5 * np.pi, [1.0, 0, 0])), ([h, L + T, h], (0.5 * np.pi, [1.0, 0, 0]))):
        w = pre.rigidPlan(axe1=L, axe2=L, axe3=T, center=centre, model=mod, material=wallm, color="WALLx")
        if rot is not None:
            w.rotate(description="axis", alpha=rot[0], axis=rot[1], center=w.nodes[1].coor)
        w.imposeDrivenDof(component=[1, 2, 3, 4, 5, 6], dofty="vlocy")
        bodies.addAvatar(w)
    lpp = pre.tact_behav(name="iqsc0", law="IQS_CLB", fric=0.5)
    lpw = pre.tact_behav(name="iqsc1", law="IQS_CLB", fric=0.0)
    tacts += lpp
    tacts += lpw
    cd = "SPHER" if spheres else "POLYR"
    for an, col, law in ((cd, "BLUEx", lpp), ("PLANx", "WALLx", lpw)):
        svs += pre.see_table(CorpsCandidat="RBDY3", candidat=cd, colorCandidat="BLUEx",
                             CorpsAntagoniste="RBDY3", antagoniste=an, colorAntagoniste=col, behav=law,
                             alert=0.1 * R)
    pre.writeDatbox(3, mats, mods, bodies, tacts, svs, gravy=np.array([0.0, 0.0, -9.81]))


def run(chipy, steps, spheres=False):
    chipy.checkDirectories()
    chipy.utilities_DisableLogMes()
    chipy.SetDimension(3)
    chipy.nlgs_3D_DiagonalResolution()
    if not spheres:
        chipy.PRPRx_UseCpCundallDetection(50)
    chipy.TimeEvolution_SetTimeStep(DT)
    chipy.Integrator_InitTheta(0.5)
    chipy.ReadDatbox(deformable=False)
    chipy.ComputeMass()
    for _ in range(steps):
        chipy.IncrementStep()
        chipy.ComputeFext()
        chipy.ComputeBulk()
        chipy.ComputeFreeVelocity()
        chipy.SelectProxTactors()
        chipy.RecupRloc()
        chipy.ExSolver("Stored_Delassus_Loops         ", "QM/16", 1e-6, 1.0, 200, 50)
        chipy.StockRloc()
        chipy.ComputeDof()
        chipy.UpdateStep()
        if chipy.TimeEvolution_GetStep() >= WRITE_FROM:
            chipy.WriteOut(100)
    nb = chipy.RBDY3_GetNbRBDY3()
    out = {"dt": DT, "steps": steps,
           "reac": [list(chipy.RBDY3_GetBodyVector("Reac_", i + 1)) for i in range(nb)],
           "coor": [list(chipy.RBDY3_GetBodyVector("Coor_", i + 1)) for i in range(nb)],
           "vlocy": [list(chipy.RBDY3_GetBodyVector("V____", i + 1)) for i in range(nb)],
           "vertices": [] if spheres else [np.asarray(chipy.POLYR_GetVertex(i + 1)).tolist()
                                           for i in range(chipy.POLYR_GetNbPOLYR())]}
    with open("reactions.json", "w") as fh:
        json.dump(out, fh)
    chipy.Finalize()


if __name__ == "__main__":
    chipy, pre = import_pylmgc90()
    args = [a for a in sys.argv[1:] if a != "--spheres"]
    scene(pre, spheres="--spheres" in sys.argv)
    run(chipy, int(args[0]) if args else 800, spheres="--spheres" in sys.argv)
