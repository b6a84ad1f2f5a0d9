"""End to end in YADE: the stock polyhedra contacts against the compiled kernel,
on the same dense packing, in one run.

    yade -j2 -n -x benchmarks/bench_engines.py RUN.h5 [SNAPSHOT [KERNEL_STEPS [STOCK_STEPS [BLOCKS]]]]

(run it with OMP_WAIT_POLICY=PASSIVE in the environment). RUN.h5 is a polyhedra
dump (for example the isotropic snapshot of a kernel run); its parameters give
k_V, k_t, friction, dt and the damping. The script builds the packing in
YADE (the dumped shapes and poses, the six walls at the box), saves it in
memory, then alternates blocks: reload, run STOCK_STEPS with YADE's
collider + InteractionLoop (Ig2_Polyhedra_Polyhedra_PolyhedraGeom,
Ig2_Wall_Polyhedra_PolyhedraGeom, the volumetric law) and our per-contact
tangential law; reload, run KERNEL_STEPS with the kernel's PyRunner. Walls
are fixed (no servo: it is the same Python in both scenes). Each block
starts with 2 untimed steps (the stock collider creates its interactions).

Printed per engine (medians over blocks): steps/s, touching contacts,
us per contact-step, and the split of a step: YADE engines from
O.timingEnabled; for the kernel, its PyRunner split into reading the states,
the C kernel and adding the forces; the ratio stock/kernel per contact-step
(median of the block-pair ratios). JSON next to the dump:
RUN.bench_engines.json.
"""
import json
import os
import sys
import time

import numpy as np
from yade import log

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(sys.argv[0])))
sys.path.insert(0, ROOT)
sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from yade_packing import build_packing  # noqa: E402
from yade_scripts.kernel_contacts import KernelContacts  # noqa: E402
from yade_scripts.tangential import TangentialLaw  # noqa: E402

log.setLevel("Polyhedra_support.cpp", log.ERROR)
args = sys.argv[1:]
DUMP = os.path.abspath(args[0])
SNAP = int(args[1]) if len(args) > 1 else 0
K_KERNEL = int(args[2]) if len(args) > 2 else 300
K_STOCK = int(args[3]) if len(args) > 3 else 20
BLOCKS = int(args[4]) if len(args) > 4 else 3

pk = build_packing(O, DUMP, SNAP)
particles, walls, d, P = pk["particles"], pk["walls"], pk["sizes"], pk["P"]
k_v, a_face, mu, mu_w = P["kn_volumetric"], P["a_face"], P["friction"], P["wall_friction"]
d_of = np.zeros(max(particles) + 1)
d_of[particles] = d


def kt_of(id1, id2, kn):
    d1, d2 = d_of[id1], d_of[id2]
    dp = np.where((d1 > 0) & (d2 > 0), 2 * d1 * d2 / np.where(d1 + d2 > 0, d1 + d2, 1), np.maximum(d1, d2))
    return P["tangential_ratio"] * kn * a_face * dp ** 2


O.saveTmp("init")
shape_v, shape_t = pk["vertices"], pk["triangles"]
engines = {}


def scene(kind):
    """Reload the packing and set the engines of ``kind``; returns the kernel or None."""
    global law
    O.loadTmp("init")
    O.dt = P["dt"]
    if kind == "kernel":
        k = KernelContacts(O, particles, walls, shape_v, shape_t, d, k_v, P["tangential_ratio"] * k_v * a_face,
                                mu, mu_w, P.get("verlet_skin", 0.1) * P["d_mean"], O.numThreads)
        O.engines = [ForceResetter(), PyRunner(command="kernel()", iterPeriod=1, initRun=True, label="kernel_contacts"),
                     NewtonIntegrator(damping=P["damping"], label="newton")]
        return k
    law = TangentialLaw(O, Vector3, kt_of)
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Polyhedra_Aabb(), Bo1_Wall_Aabb()], verletDist=0.0, label="collider"),
        InteractionLoop([Ig2_Polyhedra_Polyhedra_PolyhedraGeom(), Ig2_Wall_Polyhedra_PolyhedraGeom()],
                        [Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()],
                        [Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()], label="interactionLoop"),
        PyRunner(command="law()", iterPeriod=1, label="tangential"),
        NewtonIntegrator(damping=P["damping"], label="newton"),
    ]
    return None


counted = [0]


def count():
    counted[0] += kernel.n_contacts if kernel is not None else O.interactions.countReal()


def block(kind, steps):
    global kernel
    kernel = scene(kind)
    O.engines = O.engines[:-1] + [PyRunner(command="count()", iterPeriod=1, label="counter"), O.engines[-1]]
    O.run(2, True)
    O.timingEnabled = True
    for e in O.engines:
        e.execTime = 0
    if kernel is not None:
        kernel.seconds = {"read": 0.0, "kernel": 0.0, "apply": 0.0}
    counted[0] = 0
    t0 = time.perf_counter()
    O.run(steps, True)
    wall = time.perf_counter() - t0
    O.timingEnabled = False
    eng = {(e.label or e.__class__.__name__): e.execTime * 1e-6 / steps for e in O.engines}
    wall -= eng["counter"] * 1e-3 * steps          # the counting is not part of either engine
    touching = counted[0] / steps
    res = {"steps": steps, "seconds": wall, "steps_per_s": steps / wall, "touching": touching,
           "us_per_contact_step": wall / steps / touching * 1e6, "engines_ms_per_step": eng}
    if kernel is not None:
        res["kernel_split_ms_per_step"] = {key: val * 1e3 / steps for key, val in kernel.seconds.items()}
        res["pairs"] = kernel.n_pairs
        res["memory_bytes"] = kernel.memory_bytes()
    else:
        res["pairs"] = len(O.interactions)
    return res


kernel = None
results = {"kernel": [], "yade": []}
for b in range(BLOCKS):
    results["yade"].append(block("yade", K_STOCK))
    results["kernel"].append(block("kernel", K_KERNEL))
    print(f"block {b}: stock {results['yade'][-1]['us_per_contact_step']:.1f} us/contact-step, "
          f"kernel {results['kernel'][-1]['us_per_contact_step']:.2f}", flush=True)


def med(kind, key):
    return float(np.median([r[key] for r in results[kind]]))


ratio = float(np.median([a["us_per_contact_step"] / b["us_per_contact_step"]
                         for a, b in zip(results["yade"], results["kernel"])]))
summary = {"dump": DUMP, "snapshot": SNAP, "particles": len(particles), "threads": O.numThreads,
           "omp_wait_policy": os.environ.get("OMP_WAIT_POLICY"), "ratio_stock_over_kernel": ratio,
           "blocks": results}
print(f"\n{len(particles)} polyhedra, yade -j{O.numThreads}, {BLOCKS} blocks (medians)")
print(f"{'engine':>7} {'steps/s':>9} {'contacts':>9} {'pairs':>7} {'us/contact-step':>16}")
for kind in ("yade", "kernel"):
    print(f"{kind:>7} {med(kind, 'steps_per_s'):9.2f} {med(kind, 'touching'):9.0f} {med(kind, 'pairs'):7.0f} "
          f"{med(kind, 'us_per_contact_step'):16.2f}")
print(f"stock / kernel per contact-step: {ratio:.1f}x")
for kind in ("yade", "kernel"):
    last = results[kind][-1]
    parts = ", ".join(f"{k} {v:.2f}" for k, v in last["engines_ms_per_step"].items())
    print(f"{kind} ms/step by engine (last block): {parts}")
k = results["kernel"][-1]
print("kernel PyRunner split ms/step (last block): "
      + ", ".join(f"{a} {b:.3f}" for a, b in k["kernel_split_ms_per_step"].items())
      + f"; kernel memory {k['memory_bytes'] / 1e6:.2f} MB")
with open(DUMP[:-3] + ".bench_engines.json", "w") as fh:
    json.dump(summary, fh, indent=1)
sys.exit(0)
