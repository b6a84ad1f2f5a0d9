# -*- encoding=utf-8 -*-
# Clumps of polyhedra deposited in waves, with exact polyhedra contacts:
#   1. each clump is two random convex polyhedra (polyhedra_utils.polyhedra)
#      overlapping by half their size, made one rigid body by
#      O.bodies.appendClumped;
#   2. the clumps rain into an open facetBox in waves: a new wave is appended
#      above the pile while the earlier ones are still settling (the engine
#      picks each wave up by itself);
#   3. once at rest, the box's reaction (averaged over 0.05 s) is printed
#      beside the clumps' weight, and the pile's height, its contacts and the
#      contacts between members of one clump (none: YADE never makes them)
#      are written to clump-deposit.txt, one line per wave.
#
# The contacts are computed by PolyhedraContactEngine (this project's
# compiled kernel) in place of YADE's collider and InteractionLoop.
#
#   yade clump_deposition.py                 (the sizes below)
#   yade -n -x clump_deposition.py 8 2       (8 clumps a wave, 2 waves: the tests' tiny size)
#
# Run from a clone of the project (or with it on PYTHONPATH); the script loads
# the plugin itself: no YADE_PREFIX needed.
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), ".."))   # the clone (yade runs the script with its own __file__)
from yade import geom, polyhedra_utils, utils  # noqa: E402
from yade_scripts.yadeplugin.contacts import PolyhedraContactEngine, SCENES  # noqa: E402

perWave = int(sys.argv[1]) if len(sys.argv) > 1 else 32
nWaves = int(sys.argv[2]) if len(sys.argv) > 2 else 4
d = 0.02                          # member size (m)
young = 2e8                       # PolyhedraMat: k_n = young / 2 (N/m^3) for two equal materials
# poisson = d^2 puts the tangential stiffness at the normal stiffness of a face contact (k_n d^2)
mat = PolyhedraMat(young=young, poisson=d * d, frictionAngle=math.radians(30), density=2650)
O.materials.append(mat)

side = 8 * d                      # the box: open at the top (wallMask 31: every side but z+)
boxIds = O.bodies.append(geom.facetBox((0, 0, side), (side / 2, side / 2, side), wallMask=31, material=mat))
clumps = []


def wave(k, floor):
    """Append perWave clumps on a grid, the lowest at height floor (m)."""
    perRow = 3
    for c in range(perWave):
        i, j, layer = c % perRow, (c // perRow) % perRow, c // (perRow * perRow)
        x, y, z = (i - 1) * 2.2 * d, (j - 1) * 2.2 * d, floor + layer * 1.4 * d
        seed = 2 * (k * perWave + c) + 1
        a = polyhedra_utils.polyhedra(mat, size=(d, d, d), seed=seed)
        b = polyhedra_utils.polyhedra(mat, size=(d, d, d), seed=seed + 1)
        a.state.pos, b.state.pos = (x - d / 4, y, z), (x + d / 4, y, z)
        cid, _ = O.bodies.appendClumped([a, b])
        clumps.append(cid)


def members(cid):
    return [i for i in O.bodies[cid].shape.members.keys()]


def top():
    return max(O.bodies[m].state.pos[2] for c in clumps for m in members(c)) + d / 2


wave(0, d)
m = min(O.bodies[members(c)[0]].state.mass for c in clumps)
O.dt = 0.1 * math.sqrt(m / (young / 2 * d * d))          # 0.1 / omega of the stiffest face contact
O.engines = [
    ForceResetter(),
    PolyhedraContactEngine(fillEvery=10, label="contacts"),
    NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.3),
]


def within():
    """Interactions between members of one clump in O.interactions (YADE never makes them)."""
    return sum(1 for i in O.interactions if O.bodies[i.id1].clumpId >= 0
               and O.bodies[i.id1].clumpId == O.bodies[i.id2].clumpId)


rows = []
for k in range(nWaves):
    if k:
        wave(k, top() + d)                                 # the next wave above the pile, still settling
    O.run(int(0.15 / O.dt), True)
    rows.append((k + 1, len(clumps), top(), O.interactions.countReal(), within()))
    print(f"wave {k + 1}: {len(clumps)} clumps, top at {rows[-1][2]:.4f} m, {rows[-1][3]} contacts, "
          f"{rows[-1][4]} between members of one clump, {SCENES['contacts'].scans} scans")
for _ in range(40):                                        # settle: the floor carrying the clumps' weight
    O.run(int(0.05 / O.dt), True)
    if utils.unbalancedForce() < 0.05:
        break
react = []


def reactions():
    react.append(-sum(O.forces.f(i, True)[2] for i in boxIds))


O.engines = O.engines[:2] + [PyRunner(command="reactions()", iterPeriod=1)] + O.engines[2:]
O.run(int(0.05 / O.dt), True)
weight = sum(O.bodies[c].state.mass for c in clumps) * 9.81
print(f"at rest: box reaction {sum(react) / len(react):.4g} N, weight of the clumps {weight:.4g} N")
with open("clump-deposit.txt", "w") as fh:
    fh.write("# wave clumps top_m contacts contacts_within_a_clump\n")
    for r in rows:
        fh.write("%d %d %.6e %d %d\n" % r)
print("clumps: wrote clump-deposit.txt")
