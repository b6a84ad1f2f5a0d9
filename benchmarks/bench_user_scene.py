"""YADE's stock polyhedra contacts against PolyhedraContactEngine in a
user's scene, side by side in one YADE process.

    yade -j1 -n -x benchmarks/bench_user_scene.py [N_GRAINS] [STEPS] [OUT.json]

The scene: N random polyhedra (``polyhedra_utils.polyhedra``, about 4 cm,
``PolyhedraMat``) deposited under gravity into an open ``facetBox`` (on the
engine, which is fast), then at rest. From that same state (positions,
orientations, velocities restored before each), STEPS steps of:

* ``stock``: ``InsertionSortCollider([Bo1_Polyhedra_Aabb(), Bo1_Facet_Aabb()])``
  and ``InteractionLoop`` with ``Ig2_Polyhedra_Polyhedra_PolyhedraGeom``,
  ``Ig2_Facet_Polyhedra_PolyhedraGeom``, ``Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys``
  and ``Law2_PolyhedraGeom_PolyhedraPhys_Volumetric`` (YADE's idiom);
* ``engine fill 1``, ``engine fill 10``, ``engine fill 0``: the engine, with
  ``O.interactions`` written every step, every 10 steps, never.

The four are interleaved, three times each (each engine variant run five
times in a row there, from the same state, for the median of the five:
its runs take tenths of a second); the engine's ratios are taken to the
stock run of the same repeat, and the medians are reported
(with the repeats' lowest and highest contact-step ratio).

Per variant: the whole step (the sum of every engine's time, YADE's
``O.timingEnabled``: the wall time of ``O.run(STEPS, True)`` is not it, as
the wait for a run's end comes in steps of tens of milliseconds), the
contact engines' own time (YADE's ``O.timingEnabled`` for the stock engines;
the engine's counters), the touching contacts (mean of the first and last
step; for the stock functors those with a positive penetrationVolume, as they
keep an interaction real at zero volume while the bounds overlap) and the
cost of a contact-step (contact time / steps / contacts).
The same in CPU time (``time.process_time``, YADE on one thread), which a
loaded host's other processes disturb less than the wall clock: each
variant's step less the step without contacts (``ForceResetter`` and
``NewtonIntegrator`` alone, run beside them), per touching contact
(``us_per_contact_step_cpu``, ``contact_step_cpu_ratio``).
Prints one line ``RESULT {json}`` and writes it to OUT.json if given.
"""
import json
import math
import sys
import time

sys.path.insert(0, __import__("os").path.join(__import__("os").path.dirname(__import__("os").path.abspath(sys.argv[0])), ".."))
from yade import geom, log, polyhedra_utils, utils  # noqa: E402
from yade_scripts.yadeplugin.contacts import SCENES, PolyhedraContactEngine  # noqa: E402

log.setLevel("Polyhedra_support.cpp", log.ERROR)
N = int(sys.argv[1]) if len(sys.argv) > 1 else 200
STEPS = int(sys.argv[2]) if len(sys.argv) > 2 else 200
OUT = sys.argv[3] if len(sys.argv) > 3 else None
d, young = 0.04, 2e8
mat = PolyhedraMat(young=young, poisson=d * d, frictionAngle=math.radians(35), density=2650)
O.materials.append(mat)
per = max(2, int(math.ceil((N / 3.0) ** 0.5)))
side = per * 1.25 * d
O.bodies.append(geom.facetBox((0, 0, side), (side / 2, side / 2, side), wallMask=31, material=mat))
for k in range(N):
    i, j, layer = k % per, (k // per) % per, k // (per * per)
    b = polyhedra_utils.polyhedra(mat, size=(d, d, d), seed=k + 1)
    b.state.pos = ((i - (per - 1) / 2) * 1.25 * d, (j - (per - 1) / 2) * 1.25 * d, 0.75 * d + layer * 1.3 * d)
    O.bodies.append(b)
grains = [b.id for b in O.bodies if type(b.shape).__name__ == "Polyhedra"]
m = min(O.bodies[i].state.mass for i in grains)
O.dt = 0.1 * math.sqrt(m / (young / 2 * d * d))

# deposit on the engine
O.engines = [ForceResetter(), PolyhedraContactEngine(fillEvery=0, label="deposit"),
             NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.5)]
t = time.time()
O.run(int(0.5 / O.dt), True)
deposit = {"steps": O.iter, "seconds": time.time() - t, "unbalanced": utils.unbalancedForce()}
O.engines[1].clearInteractions()
saved = [(b.id, tuple(b.state.pos), b.state.ori, tuple(b.state.vel), tuple(b.state.angVel)) for b in O.bodies]


def median(xs):
    """The middle value of an odd number of values."""
    xs = sorted(xs)
    return xs[len(xs) // 2]


def restore():
    for i, x, q, v, w in saved:
        s = O.bodies[i].state
        s.pos, s.ori, s.vel, s.angVel = x, q, v, w
    O.interactions.clear()
    O.forces.reset()


def run(name, engines, contact_engines, count):
    restore()
    O.engines = engines
    O.timingEnabled = True
    O.step()                                 # first step: collider's initial sort, the engine's scan
    for e in O.engines:
        e.execTime = 0
        if hasattr(e, "counters"):
            e.counters = [0.0] * len(e.counters)    # the fill's own time from here on
    c0 = count()
    t0, p0 = time.perf_counter(), time.process_time()
    O.run(STEPS, True)
    wall, cpu = time.perf_counter() - t0, time.process_time() - p0
    c1 = count()
    contact = sum(e.execTime for e in O.engines if e.label in contact_engines) * 1e-9
    engines = sum(e.execTime for e in O.engines) * 1e-9
    O.timingEnabled = False
    n = 0.5 * (c0 + c1)
    return {"variant": name, "whole_step_us": 1e6 * engines / STEPS, "run_wall_us": 1e6 * wall / STEPS,
            "whole_step_cpu_us": 1e6 * cpu / STEPS, "contact_us_per_step": 1e6 * contact / STEPS,
            "contacts": n, "us_per_contact_step": 1e6 * contact / STEPS / n if n else float("nan")}


res = {"n_grains": len(grains), "steps": STEPS, "dt": O.dt, "deposit": deposit, "variants": []}


def stock_engines():
    return [ForceResetter(),
            InsertionSortCollider([Bo1_Polyhedra_Aabb(label="bo1p"), Bo1_Facet_Aabb(label="bo1f")], label="collider"),
            InteractionLoop([Ig2_Polyhedra_Polyhedra_PolyhedraGeom(), Ig2_Facet_Polyhedra_PolyhedraGeom()],
                            [Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()],
                            [Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()], label="loop"),
            NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.5)]


REPEAT = 3
ENGINE_RUNS = 5
runs = {}
for rep in range(REPEAT):                    # stock and the engine's variants interleaved, REPEAT times: medians
    # the step without contacts (ForceResetter and NewtonIntegrator over the same bodies): what is not contacts
    bare = [run("no contacts", [ForceResetter(), NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.5)], set(),
                lambda: 0) for k in range(ENGINE_RUNS)]
    bare_cpu = median(x["whole_step_cpu_us"] for x in bare)
    runs.setdefault("bare", []).append(dict(bare[0], whole_step_cpu_us=bare_cpu))
    # YADE's stock functors keep an interaction real at zero volume while the bounds overlap: count the touching ones
    r = run("stock", stock_engines(), {"collider", "loop"},
            lambda: sum(1 for i in O.interactions if i.isReal and i.geom.penetrationVolume > 0))
    runs.setdefault("stock", []).append(r)
    for fill in (1, 10, 0):
        inner = []
        for k in range(ENGINE_RUNS):         # the engine's runs are short (tenths of a second): several, their median
            label = "fill%d_%d_%d" % (fill, rep, k)
            eng = [ForceResetter(), PolyhedraContactEngine(fillEvery=fill, label=label),
                   NewtonIntegrator(gravity=(0, 0, -9.81), damping=0.5)]
            r = run("engine fill %d" % fill, eng, {label}, lambda: len(SCENES[label].contacts()["id1"]))
            tm = SCENES[label].timing()
            r["fill_us_per_fill"] = 1e6 * tm["fill"] / max(tm["fills"], 1)
            r["fill_us_per_contact"] = r["fill_us_per_fill"] / r["contacts"] if r["contacts"] else float("nan")
            inner.append(r)
        r = dict(variant=inner[0]["variant"],
                 **{k: median(x[k] for x in inner) for k in inner[0] if k != "variant"})
        base = runs["stock"][-1]             # the ratios to the stock run of the same repeat
        r["contact_step_ratio"] = base["us_per_contact_step"] / r["us_per_contact_step"]
        r["whole_step_ratio"] = base["whole_step_us"] / r["whole_step_us"]
        r["whole_step_cpu_ratio"] = base["whole_step_cpu_us"] / r["whole_step_cpu_us"]
        runs.setdefault(fill, []).append(r)
    for r in [runs["stock"][-1]] + [runs[f][-1] for f in (1, 10, 0)]:
        # CPU time of the contacts: the step's less the step without contacts, per touching contact
        r["us_per_contact_step_cpu"] = (r["whole_step_cpu_us"] - bare_cpu) / r["contacts"]
    for f in (1, 10, 0):
        runs[f][-1]["contact_step_cpu_ratio"] = (runs["stock"][-1]["us_per_contact_step_cpu"]
                                                 / runs[f][-1]["us_per_contact_step_cpu"])
for key in ("stock", 1, 10, 0):
    rs = runs[key]
    med = {k: median(x[k] for x in rs) for k in rs[0] if k != "variant"}
    if key != "stock":                       # the repeats' ratios, lowest and highest
        for k in ("contact_step_ratio", "contact_step_cpu_ratio"):
            med[k + "_range"] = [min(x[k] for x in rs), max(x[k] for x in rs)]
    res["variants"].append(dict(variant=rs[0]["variant"], repeats=len(rs), **med))
res["no_contacts_cpu_us"] = median(x["whole_step_cpu_us"] for x in runs["bare"])
line = json.dumps(res)
print("RESULT " + line, flush=True)
if OUT:
    with open(OUT, "w") as fh:
        fh.write(line + "\n")
__import__("os")._exit(0)
