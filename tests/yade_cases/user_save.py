"""O.save / O.load of a user's scene on ``PolyhedraContactEngine`` (no
YADE_PREFIX: the script loads the plugin itself). Prints one line
``RESULT {json}`` with what tests/test_user_save.py checks.

    yade -n -x user_save.py ROOT MODE FILE

The scene: three of YADE's random polyhedra (2 cm) on a large facet, two
thrown at each other, the third sliding on the facet and pressed into a
Wall of axis y, from which it is pushed off (that contact ends after the
save); gravity, no damping; N = 200 steps of 1e-5 s before the save and
after it. The rows recorded, one per step: every body's force and torque.

save:     built, stepped N, O.save(FILE) and O.save(FILE.xml.bz2), O.saveTmp;
          then "cont": N more steps; "tmp": O.loadTmp, N steps; "xml":
          O.load of the XML file, N steps; "fresh": O.loadTmp with the
          engine replaced by a new one (no saved state), N steps; "live": the
          SceneContacts of the label left after 20 more O.loadTmp and steps.
load:     contacts.load_plugin(), O.load(FILE), "loaded": N steps.
nostep:   built, O.save(FILE) before any step, O.load(FILE), no step.
loadonly: contacts.load_plugin(), O.load(FILE), no step.
saveadd:  built, stepped N, O.save(FILE); "added": a held cube appended on
          the facet far from the grains, N steps.
loadadd:  contacts.load_plugin(), O.load(FILE), the same cube appended before
          the first step, "added": N steps.
"""
import gc
import json
import sys

root, mode, path = sys.argv[1], sys.argv[2], sys.argv[3]
sys.path.insert(0, root)
from yade import log, polyhedra_utils, utils  # noqa: E402

from yade_scripts.yadeplugin import contacts  # noqa: E402

log.setLevel("Polyhedra_support.cpp", log.ERROR)
A, N, LABEL = 0.02, 200, "grains"


def build():
    O.reset()
    m = PolyhedraMat(young=1e8, poisson=0.5, frictionAngle=0.5, density=2000)
    O.materials.append(m)
    O.dt = 1e-5
    O.bodies.append(utils.facet([(-1, -1, 0), (1, -1, 0), (0, 1, 0)], material=m, fixed=True))
    grains = []
    for k, (x, y, v) in enumerate(((-0.011, 0.0, (0.5, 0.05, 0)), (0.011, 0.002, (-0.5, 0, 0)),
                                   (0.0, 0.05, (0.2, -0.05, 0)))):
        b = polyhedra_utils.polyhedra(m, size=(A, A, A), seed=k + 1)
        b.state.pos = (x, y, -min(p[2] for p in b.shape.v) - 1e-4)
        b.state.vel = v
        grains.append(O.bodies.append(b))
    g = O.bodies[grains[2]]
    top = max((g.state.pos + g.state.ori * p)[1] for p in g.shape.v)
    O.bodies.append(utils.wall(top - 2e-4, axis=1, sense=-1, material=m))
    O.engines = [ForceResetter(), contacts.PolyhedraContactEngine(fillEvery=1, label=LABEL),
                 NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.0)]


def run(n):
    rows, counts = [], []
    for _ in range(n):
        O.step()
        rows.append([tuple(O.forces.f(i)) + tuple(O.forces.t(i)) for i in range(len(O.bodies))])
        counts.append(O.interactions.countReal())
    inter = sorted((i.id1, i.id2, tuple(i.phys.normalForce), tuple(i.phys.shearForce), i.geom.penetrationVolume)
                   for i in O.interactions if i.isReal)
    return {"forces": rows, "counts": counts, "inter": inter, "iter": O.iter}


def add_cube():
    cube = [(x, y, z) for x in (-A / 2, A / 2) for y in (-A / 2, A / 2) for z in (-A / 2, A / 2)]
    b = polyhedra_utils.polyhedra(O.materials[0], v=cube)
    b.state.pos = (0.5, 0.5, A / 2 - 5e-5)
    b.state.blockedDOFs = "xyzXYZ"
    return O.bodies.append(b)


def engine_before_step():
    e = O.engines[1]
    return {"class": type(e).__name__, "hasScan": e.hasScan, "saved": len(e.savedState), "label": e.label,
            "fillEvery": e.fillEvery}


out = {"file": path}
if mode == "save":
    build()
    out["before"] = run(N)
    O.save(path)
    O.save(path + ".xml.bz2")
    O.saveTmp()
    out["cont"] = run(N)
    O.loadTmp()
    out["tmp_engine"] = engine_before_step()
    out["tmp"] = run(N)
    out["tmp_scans"] = contacts.SCENES[LABEL].scans
    O.load(path + ".xml.bz2")
    out["xml"] = run(N)
    O.loadTmp()
    O.engines = [O.engines[0], contacts.PolyhedraContactEngine(fillEvery=1, label="fresh"), O.engines[2]]
    out["fresh"] = run(N)
    for _ in range(20):          # a loop of loads: each replaced engine and its kernel are freed
        O.loadTmp()
        O.step()
    gc.collect()
    out["live"] = sum(1 for o in gc.get_objects() if isinstance(o, contacts.SceneContacts) and o.e.label == LABEL)
elif mode == "load":
    contacts.load_plugin()
    O.load(path)
    out["engine"] = engine_before_step()
    out["loaded"] = run(N)
    out["scans"] = contacts.SCENES[LABEL].scans
elif mode in ("saveadd", "loadadd"):
    if mode == "saveadd":
        build()
        run(N)
        O.save(path)
    else:
        contacts.load_plugin()
        O.load(path)
    add_cube()
    out["added"] = run(N)
    out["scans"] = contacts.SCENES[LABEL].scans
elif mode == "nostep":
    build()
    O.save(path)
    O.load(path)
    out["engine"] = engine_before_step()
elif mode == "loadonly":
    contacts.load_plugin()
    O.load(path)
    out["engine"] = engine_before_step()
print("RESULT " + json.dumps(out))
