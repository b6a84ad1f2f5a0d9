# -*- encoding=utf-8 -*-
# YADE's triaxial tutorial (examples/triax-tutorial/script-session1.py), for
# polyhedra with exact contacts: the same three stages on the same kind of
# sample, with polyhedral grains in place of spheres.
#
#   1. a loose cloud of random polyhedra in a box of six walls, confined
#      isotropically to 10 kPa by the walls (the tutorial grows the spheres
#      instead: a polyhedron cannot be grown exactly, so the walls move);
#   2. the friction lowered step by step while the porosity is above its
#      target (the tutorial's REFD compaction);
#   3. deviatoric loading: a constant strain rate on y, 10 kPa kept on x and z;
#      e11, e22, e33, ev, s11, s22, s33 recorded every 20 steps with yade.plot
#      and saved to results_triax_polyhedra.txt.
#
# The contacts are those of PolyhedraContactEngine (this project's compiled
# kernel) in place of the collider and the InteractionLoop; they are in
# O.interactions every `fillEvery` steps. The walls are servo-controlled by
# a PyRunner (TriaxialStressController takes a stiffness in N/m from the
# interactions' kn, which for the volumetric law is in N/m^3).
#
#   yade triax_polyhedra.py                  (the sizes below)
#   yade -n -x triax_polyhedra.py 24 3000    (24 grains, at most 3000 steps a stage: the tests)
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), ".."))   # the clone (yade runs the script with its own __file__)
from yade import plot, polyhedra_utils, utils  # noqa: E402
from yade_scripts.yadeplugin.contacts import SCENES, PolyhedraContactEngine  # noqa: E402

############################################
###   DEFINING VARIABLES AND MATERIALS   ###
############################################
num_grains = int(sys.argv[1]) if len(sys.argv) > 1 else 500
max_steps = int(sys.argv[2]) if len(sys.argv) > 2 else 200000      # per stage
key = "_triax_polyhedra"
targetPorosity = 0.40             # the porosity we want for the packing
compFricDegree = 30.0             # contact friction during the confining phase
finalFricDegree = 30.0            # contact friction during the deviatoric loading
rate = -0.02                      # strain rate on y (1/s), negative: compression
damp = 0.2
stabilityThreshold = 0.01
sigma0 = 1e4                      # confining stress (Pa)
d = 0.04                          # grain size (m)
young = 2 * 1000 * sigma0 / d     # k_n = young/2 = 1000 sigma0 / d: overlaps of about d/1000
O.materials.append(PolyhedraMat(young=young, poisson=d * d, frictionAngle=math.radians(compFricDegree),
                                density=2600, label="grains"))
O.materials.append(PolyhedraMat(young=young, poisson=d * d, frictionAngle=0, density=0, label="walls"))

## six walls around the cloud (x-, x+, y-, y+, z-, z+), then the grains on a grid
n = int(math.ceil(num_grains ** (1 / 3.0)))
L = n * 1.25 * d
wallIds = []
for axis in range(3):
    for pos, sense in ((0.0, 1), (L, -1)):
        w = utils.wall(pos, axis=axis, sense=sense, material="walls")
        w.state.blockedDOFs = "xyzXYZ"
        wallIds.append(O.bodies.append(w))
for k in range(num_grains):
    i, j, l = k % n, (k // n) % n, k // (n * n)
    b = polyhedra_utils.polyhedra(O.materials["grains"], size=(d, d, d), seed=k + 1)
    b.state.pos = ((i + 0.5) * 1.25 * d, (j + 0.5) * 1.25 * d, (l + 0.5) * 1.25 * d)
    O.bodies.append(b)
grains = [b.id for b in O.bodies if type(b.shape).__name__ == "Polyhedra"]
solid = sum(O.bodies[i].shape.GetVolume() for i in grains)

############################
###   DEFINING ENGINES   ###
############################
goal = [sigma0, sigma0, sigma0]   # stress goals (Pa, compression positive), or None for a strain-controlled axis
strainRate = [0.0, 0.0, 0.0]


def box():
    lo = [O.bodies[wallIds[2 * a]].state.pos[a] for a in range(3)]
    hi = [O.bodies[wallIds[2 * a + 1]].state.pos[a] for a in range(3)]
    return lo, hi


def stresses():
    """The walls' stresses (Pa, compression positive): the mean of the two
    walls' normal forces over the face area."""
    lo, hi = box()
    size = [h - l for l, h in zip(lo, hi)]
    out = []
    for a in range(3):
        area = size[(a + 1) % 3] * size[(a + 2) % 3]
        f = O.forces.f(wallIds[2 * a + 1], True)[a] - O.forces.f(wallIds[2 * a], True)[a]
        out.append(0.5 * f / area)
    return out


def porosity():
    lo, hi = box()
    return 1 - solid / ((hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]))


def servo():
    """Each pair of walls moves at a strain rate proportional to its stress
    error (at most 0.5 /s), or at strainRate for a strain-controlled axis."""
    lo, hi = box()
    s = stresses()
    for a in range(3):
        if goal[a] is None:
            e = strainRate[a]
        else:
            e = max(-0.5, min(0.5, -2.0 * (goal[a] - s[a]) / goal[a]))
        v = 0.5 * e * (hi[a] - lo[a])
        O.bodies[wallIds[2 * a]].state.vel = tuple(-v if c == a else 0 for c in range(3))
        O.bodies[wallIds[2 * a + 1]].state.vel = tuple(v if c == a else 0 for c in range(3))


newton = NewtonIntegrator(damping=damp)
O.engines = [
    ForceResetter(),
    PolyhedraContactEngine(fillEvery=20, label="contacts"),
    PyRunner(command="servo()", iterPeriod=1, label="controller"),
    newton,
]
m = min(O.bodies[i].state.mass for i in grains)
O.dt = 0.2 * math.sqrt(m / (young / 2 * d * d))

#######################################
###   APPLYING CONFINING PRESSURE   ###
#######################################
reached = False
while O.iter < max_steps and not reached:
    O.run(500, True)
    s = stresses()
    unb = utils.unbalancedForce()
    print("unbalanced force:", unb, " mean stress:", sum(s) / 3)
    reached = unb < stabilityThreshold and all(abs(x - sigma0) / sigma0 < 0.01 for x in s)
print("###      Isotropic state %s      ###  porosity" % ("reached" if reached else "not reached (max_steps)"),
      porosity())

###################################################
###   REACHING A SPECIFIED POROSITY PRECISELY   ###
###################################################
start = O.iter
while porosity() > targetPorosity and O.iter - start < max_steps:
    ## lower the friction of every material and contact, and let the walls follow
    compFricDegree = 0.95 * compFricDegree
    SCENES["contacts"].set_friction(math.radians(compFricDegree), 0.0)
    print("\r Friction: ", compFricDegree, " porosity:", porosity(), end="")
    sys.stdout.flush()
    O.run(500, True)
print("\n###    Compacted state      ### porosity", porosity())

##############################
###   DEVIATORIC LOADING   ###
##############################
SCENES["contacts"].set_friction(math.radians(finalFricDegree), 0.0)
goal = [sigma0, None, sigma0]
strainRate = [0.0, rate, 0.0]
newton.damping = 0.1
lo0, hi0 = box()
size0 = [h - l for l, h in zip(lo0, hi0)]


def history():
    lo, hi = box()
    e = [math.log((h - l) / s0) for l, h, s0 in zip(lo, hi, size0)]
    s = stresses()
    plot.addData(e11=-e[0], e22=-e[1], e33=-e[2], ev=-e[0] - e[1] - e[2], s11=s[0], s22=s[1], s33=s[2],
                 porosity=porosity(), contacts=O.interactions.countReal(), i=O.iter, t=O.time)


O.engines = O.engines + [PyRunner(iterPeriod=20, command="history()", label="recorder")]
steps = min(max_steps, int(0.05 / abs(rate) / O.dt))        # to 5 % axial strain
O.run(steps, True)
plot.saveDataTxt("results" + key + ".txt")
print("###    Deviatoric loading done: e22 = %.4f, q/p = %.3f" % (
    plot.data["e22"][-1], (plot.data["s22"][-1] - plot.data["s11"][-1]) /
    ((plot.data["s11"][-1] + plot.data["s22"][-1] + plot.data["s33"][-1]) / 3)))
