# -*- encoding=utf-8 -*-
# A ballast box test with exact polyhedra contacts:
#   1. random polyhedral grains (polyhedra_utils.polyhedra) rain under gravity
#      into an open facetBox and settle;
#   2. a sleeper block (one Polyhedra box, free to move vertically only) is put
#      on the ballast and pressed in by a vertical load cycled between
#      loadMin and loadMax;
#   3. the sleeper's settlement at the end of each cycle (at loadMin) is
#      written to ballast-settlement.txt, one line per cycle.
#
# The contacts are computed by PolyhedraContactEngine (this project's
# compiled kernel) in place of YADE's collider and InteractionLoop, and are
# written to O.interactions every `fillEvery` steps for YADE's own tools.
#
#   yade ballast_box.py                 (the sizes below)
#   yade -n -x ballast_box.py 24 3      (24 grains, 3 cycles: the tests' tiny size)
#
# Run from a clone of the project (or with it on PYTHONPATH); the script loads
# the plugin itself: no YADE_PREFIX needed.
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), ".."))   # the clone (yade runs the script with its own __file__)
from yade import geom, polyhedra_utils, utils  # noqa: E402
from yade_scripts.yadeplugin.contacts import PolyhedraContactEngine  # noqa: E402

nGrains = int(sys.argv[1]) if len(sys.argv) > 1 else 300
nCycles = int(sys.argv[2]) if len(sys.argv) > 2 else 10
d = 0.04                          # grain size (m), about ballast's 31.5-50 mm
young = 2e8                       # PolyhedraMat: k_n = young / 2 (N/m^3) for two equal materials
# YADE's Ip2 makes k_s = young * poisson (N/m, halved for two equal materials):
# poisson = d^2 puts the tangential stiffness at the normal stiffness of a face contact (k_n d^2)
ballast = PolyhedraMat(young=young, poisson=d * d, frictionAngle=math.radians(35), density=2650, label="ballast")
steel = PolyhedraMat(young=young, poisson=d * d, frictionAngle=math.radians(35), density=2500, label="sleeper")
O.materials.append([ballast, steel])

# the box: 5 d wide, open at the top (wallMask 31: every side but z+), of the ballast's material
side = 5 * d
boxIds = O.bodies.append(geom.facetBox((0, 0, side), (side / 2, side / 2, side), wallMask=31, material=ballast))

# the grains, on a grid above the floor, each a random convex polyhedron
perRow = 4
for k in range(nGrains):
    i, j, layer = k % perRow, (k // perRow) % perRow, k // (perRow * perRow)
    b = polyhedra_utils.polyhedra(ballast, size=(d, d, d), seed=k + 1)
    b.state.pos = ((i - 1.5) * 1.2 * d, (j - 1.5) * 1.2 * d, d + layer * 1.3 * d)
    O.bodies.append(b)
grains = [b.id for b in O.bodies if type(b.shape).__name__ == "Polyhedra"]

m = min(O.bodies[i].state.mass for i in grains)
O.dt = 0.1 * math.sqrt(m / (young / 2 * d * d))          # 0.1 / omega of the stiffest face contact
O.engines = [
    ForceResetter(),
    PolyhedraContactEngine(fillEvery=10, label="contacts"),
    PyRunner(command="load()", iterPeriod=1, label="loader", dead=True),
    NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.3),
]


def weight():
    return sum(O.bodies[i].state.mass for i in grains) * 9.81


# 1. deposit until the grains rest: the kinetic energy small, the floor carrying their weight
O.run(int(0.4 / O.dt), True)
for _ in range(40):
    O.run(int(0.05 / O.dt), True)
    if utils.unbalancedForce() < 0.05:
        break
top = max(O.bodies[i].state.pos[2] for i in grains) + d / 2
print(f"ballast: {len(grains)} grains deposited in {O.iter} steps, top at {top:.4f} m, "
      f"unbalanced force {utils.unbalancedForce():.3f}")

# 2. the sleeper: a 3 d x 2 d x 1.5 d block on the ballast, free along z only
hx, hy, hz = 1.5 * d, 1.0 * d, 0.75 * d
v = [(x, y, z) for x in (-hx, hx) for y in (-hy, hy) for z in (-hz, hz)]
sleeper = polyhedra_utils.polyhedra(steel, v=v)
sleeper.state.pos = (0, 0, top + hz)
sleeper.state.blockedDOFs = "xyXYZ"
sid = O.bodies.append(sleeper)
loadMin, loadMax = 0.5 * weight(), 2.0 * weight()         # N, a load of the order of the ballast's weight
period = 0.1                                               # s per cycle
t0, z0 = O.time, None


def load():
    """The sleeper's vertical load now: loadMin + (loadMax - loadMin) (1 - cos)/2."""
    ph = max(0.0, (O.time - t0) / period)                 # before t0: loadMin (seating)
    F = loadMin + (loadMax - loadMin) * 0.5 * (1 - math.cos(2 * math.pi * ph))
    O.forces.addF(sid, (0, 0, -F))


# seat the sleeper under loadMin, then cycle
loader.dead = False
t0 = O.time + 1e9                                          # hold loadMin while seating
O.run(int(0.15 / O.dt), True)
react = []                                                  # the box's upward reaction, step by step


def reactions():
    react.append(-sum(O.forces.f(i, True)[2] for i in boxIds))


O.engines = O.engines[:3] + [PyRunner(command="reactions()", iterPeriod=1, label="reacting")] + O.engines[3:]
O.run(int(0.05 / O.dt), True)
O.engines = [e for e in O.engines if e.label != "reacting"]
z0 = O.bodies[sid].state.pos[2]
reaction = sum(react) / len(react)
print(f"seated: box reaction {reaction:.4g} N, weight of ballast and sleeper and loadMin "
      f"{weight() + O.bodies[sid].state.mass * 9.81 + loadMin:.4g} N")
t0 = O.time
rows = []
for c in range(1, nCycles + 1):
    O.run(int(round(period / O.dt)), True)
    z = O.bodies[sid].state.pos[2]
    rows.append((c, z0 - z, O.interactions.countReal()))
    print(f"cycle {c}: settlement {1e3 * (z0 - z):.4f} mm, {rows[-1][2]} contacts")
with open("ballast-settlement.txt", "w") as fh:
    fh.write("# cycle settlement_m contacts (load %.4g to %.4g N, period %g s)\n" % (loadMin, loadMax, period))
    for c, s, n in rows:
        fh.write(f"{c} {s:.9e} {n}\n")
print("ballast: wrote ballast-settlement.txt")
