"""Clumps of polyhedra on ``PolyhedraContactEngine`` (one YADE process, the
plugin loaded by the script itself). Prints one line ``RESULT {json}`` with
what tests/test_user_clumps.py checks.

    yade -n -x user_clumps.py ROOT

E = 2e8 for every body (k_n = 1e8 N/m^3), cubes of side 2 cm, density 2000.

rest:    a clump of two cubes overlapping by half their side along x, resting
         on a facet from the moment it touches (bottom at z = 0, at rest),
         gravity 9.81, damping 0.5, dt 1e-5, 4000 steps: the clump's height
         every step, its mass, the members' forces, the clump's frame and the
         members' poses at the start and the end.
pressed: a held clump of two cubes, member A 0.1 mm into a Wall (axis z),
         member B above it (overlapping A by a quarter of a cube, clear of
         the wall), one step: the interactions, forces and torques of the
         members and of the clump, the positions.
added:   a held cube 0.1 mm into a facet; at step 10 a held clump of two
         cubes is appended (member A 0.05 mm into the facet, B above A), one
         more step; then three held cubes overlapping in a row, stepped,
         clumped together (O.bodies.clump), stepped, the third released from
         the clump, stepped: the interactions after each; a facet clumped
         with a cube 0.1 mm into it, another cube 0.05 mm into it, one step;
         a wall clumped with a cube (refused: the message).
"""
import json
import sys

root = sys.argv[1]
sys.path.insert(0, root)
import os  # noqa: E402
from yade import log, polyhedra_utils, utils  # noqa: E402

from yade_scripts.yadeplugin.contacts import PolyhedraContactEngine, SCENES  # noqa: E402

log.setLevel("Polyhedra_support.cpp", log.ERROR)
A, E = 0.02, 2e8
CUBE = [(x, y, z) for x in (-A / 2, A / 2) for y in (-A / 2, A / 2) for z in (-A / 2, A / 2)]
out = {}


def new_scene():
    O.reset()
    m = PolyhedraMat(young=E, poisson=0.5, frictionAngle=0.5, density=2000)
    O.materials.append(m)
    O.dt = 1e-5
    return m


def engines(label, gravity=(0, 0, 0), damping=0.0):
    O.engines = [ForceResetter(), PolyhedraContactEngine(fillEvery=1, label=label),
                 NewtonIntegrator(gravity=gravity, damping=damping)]


def cube(m, pos):
    b = polyhedra_utils.polyhedra(m, v=CUBE)
    b.state.pos = pos
    return b


def clump(m, positions, held=False):
    cid, members = O.bodies.appendClumped([cube(m, p) for p in positions])
    if held:
        O.bodies[cid].state.blockedDOFs = "xyzXYZ"
    return cid, list(members)


def inter():
    return sorted([i.id1, i.id2, i.geom.penetrationVolume, tuple(i.phys.normalForce)] for i in O.interactions)


def pose(i):
    s = O.bodies[i].state
    return {"pos": tuple(s.pos), "ori": tuple(s.ori.__getinitargs__())}


def kernel(label):
    """The kernel's touching contacts (body ids) and its listed pairs (body ids)."""
    sc = SCENES[label]
    c = sc.contacts()
    rows = list(sc.rows)
    listed = [[rows[i], rows[j]] for i, j in sc.kernel.state()["pair_ids"].tolist()]
    return {"id1": c["id1"].tolist(), "id2": c["id2"].tolist(), "listed": listed}


# ---------------------------------------------------------------- a clump at rest on a facet
m = new_scene()
O.bodies.append(utils.facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)], material=m, fixed=True))
cid, (a, b) = clump(m, [(-A / 4, 0, A / 2), (A / 4, 0, A / 2)])
engines("rest", gravity=(0, 0, -9.81), damping=0.5)
start = {"clump": pose(cid), "a": pose(a), "b": pose(b)}
z = []
for k in range(4000):
    O.step()
    z.append(O.bodies[cid].state.pos[2])
out["rest"] = {"z": z, "dt": O.dt, "mass": O.bodies[cid].state.mass, "member_mass": O.bodies[a].state.mass,
               "start": start, "end": {"clump": pose(cid), "a": pose(a), "b": pose(b)},
               "force_a": tuple(O.forces.f(a)), "force_b": tuple(O.forces.f(b)), "force_clump": tuple(O.forces.f(cid)),
               "inter": inter(), "ids": [cid, a, b], "kernel": kernel("rest"), "error": O.engines[1].error}

# ---------------------------------------------------------------- a member pressed into a wall
m = new_scene()
w = O.bodies.append(utils.wall(0, axis=2, sense=0, material=m))
cid, (a, b) = clump(m, [(0, 0, A / 2 - 1e-4), (A / 2, 0, A - 1e-4)], held=True)
engines("pressed")
O.step()
out["pressed"] = {"ids": [w, cid, a, b], "inter": inter(), "kernel": kernel("pressed"),
                  "f": {k: tuple(O.forces.f(i)) for k, i in (("a", a), ("b", b), ("clump", cid))},
                  "t": {k: tuple(O.forces.t(i)) for k, i in (("a", a), ("b", b), ("clump", cid))},
                  "pos": {k: tuple(O.bodies[i].state.pos) for k, i in (("a", a), ("b", b), ("clump", cid))}}

# ---------------------------------------------------------------- a clump appended mid-run; clumped and released
m = new_scene()
f = O.bodies.append(utils.facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)], material=m, fixed=True))
c0 = O.bodies.append(cube(m, (-0.2, 0, A / 2 - 1e-4)))
O.bodies[c0].state.blockedDOFs = "xyzXYZ"
engines("added")
for k in range(10):
    O.step()
before = {"scans": SCENES["added"].scans, "inter": inter()}
cid, (a, b) = clump(m, [(0.2, 0, A / 2 - 5e-5), (0.2 + A / 2, 0, A - 5e-5)], held=True)
O.step()
out["added"] = {"ids": [f, c0, cid, a, b], "before": before, "scans": SCENES["added"].scans, "inter": inter(),
                "kernel": kernel("added"), "f": {k: tuple(O.forces.f(i)) for k, i in (("c0", c0), ("a", a), ("b", b))}}
m = new_scene()
row = [O.bodies.append(cube(m, (k * A / 2, 0, 0.5))) for k in range(3)]
for i in row:
    O.bodies[i].state.blockedDOFs = "xyzXYZ"
engines("clumped")
O.step()
steps = {"free": inter()}
cl = O.bodies.clump(row)
O.bodies[cl].state.blockedDOFs = "xyzXYZ"
O.step()
steps["clumped"] = inter()
steps["clumped_listed"] = kernel("clumped")["listed"]
O.bodies.releaseFromClump(row[2], cl)
O.bodies[row[2]].state.blockedDOFs = "xyzXYZ"
O.step()
steps["released"] = inter()
steps["released_listed"] = kernel("clumped")["listed"]
steps["scans"] = SCENES["clumped"].scans
steps["ids"] = row + [cl]
steps["clump_ids"] = [O.bodies[i].clumpId for i in row]
steps["forces"] = [tuple(O.forces.f(i)) for i in row]
out["clumped"] = steps
# a facet clumped with a cube 0.1 mm into it; another cube, not clumped, 0.05 mm into it
m = new_scene()
fc = O.bodies.append(utils.facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)], material=m))
c1 = O.bodies.append(cube(m, (0, 0, A / 2 - 1e-4)))
c2 = O.bodies.append(cube(m, (0.1, 0, A / 2 - 5e-5)))
O.bodies[c2].state.blockedDOFs = "xyzXYZ"
cl = O.bodies.clump([fc, c1])
O.bodies[cl].state.blockedDOFs = "xyzXYZ"
engines("facetclump")
O.step()
out["facet_clump"] = {"ids": [fc, c1, c2, cl], "inter": inter(), "kernel": kernel("facetclump"),
                      "f": {k: tuple(O.forces.f(i)) for k, i in (("facet", fc), ("c1", c1), ("c2", c2), ("clump", cl))}}
# a wall in a clump: refused
m = new_scene()
w = O.bodies.append(utils.wall(0, axis=2, sense=0, material=m))
c = O.bodies.append(cube(m, (0, 0, 0.5)))
O.bodies.clump([w, c])
engines("wallclump")
try:
    O.step()
    out["wall_clump"] = None
except Exception as exc:  # noqa: BLE001 - the message is the result
    out["wall_clump"] = f"{type(exc).__name__}: {exc}"
print("RESULT " + json.dumps(out), flush=True)

os._exit(0)
