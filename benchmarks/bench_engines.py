"""End to end in YADE: the stock polyhedra contacts against the compiled kernel,
on the same dense packing, in one run.

    yade -j2 -n -x benchmarks/bench_engines.py RUN.h5 [SNAPSHOT [KERNEL_STEPS [STOCK_STEPS [BLOCKS]]]]

(run it with OMP_WAIT_POLICY=PASSIVE in the environment, and with the kernel
plugin's YADE_PREFIX, ``$(python -m yade_scripts.yadeplugin prefix)``, to time
the plugin's path too). RUN.h5 is a polyhedra
dump (for example the isotropic snapshot of a kernel run); its parameters give
k_V, k_t, friction, dt and the damping. The script builds the packing in
YADE (the dumped shapes and poses, the six walls at the box), saves it in
memory, then alternates blocks: reload, run STOCK_STEPS with YADE's
collider + InteractionLoop (Ig2_Polyhedra_Polyhedra_PolyhedraGeom,
Ig2_Wall_Polyhedra_PolyhedraGeom, the volumetric law) and our per-contact
tangential law; reload, run KERNEL_STEPS with the kernel's PyRunner; and, when
YADE loaded the kernel plugin, reload, run KERNEL_STEPS with the plugin. Walls
are fixed (no servo: it is the same Python in both scenes). Each block
starts with 2 untimed steps (the stock collider creates its interactions).

Printed per engine (medians over blocks): steps/s, touching contacts,
us per contact-step, and the split of a step: YADE engines from
O.timingEnabled; for the kernel, its split into reading the states, the C
kernel and adding the forces; the ratios stock/kernel per contact-step, for
the PyRunner and for the plugin (medians of the per-block ratios). JSON next
to the dump: RUN.bench_engines.json.
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
from yade_scripts.scene.kernel_contacts import KernelContacts  # noqa: E402
from yade_scripts.scene.tangential import TangentialLaw  # noqa: E402

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
    """Reload the packing and set the engines of ``kind`` ("yade", "kernel":
    the PyRunner path, "plugin"); returns the kernel or None."""
    global law
    O.loadTmp("init")
    O.dt = P["dt"]
    if kind in ("kernel", "plugin", "framework"):
        k = KernelContacts(O, particles, walls, shape_v, shape_t, d, k_v, P["tangential_ratio"] * k_v * a_face,
                                mu, mu_w, P.get("verlet_skin", 0.1) * P["d_mean"], O.numThreads)
        # framework: the plugin, and beside it YADE's collider and an
        # InteractionLoop over the same grains whose functors match no
        # polyhedra pair: what YADE's own machinery costs per step before any
        # geometry (the floor of a functor pair fed by the collider)
        framework = [InsertionSortCollider([Bo1_Polyhedra_Aabb(), Bo1_Wall_Aabb()], label="collider"),
                     InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_FrictMat_FrictMat_FrictPhys()],
                                     [Law2_ScGeom_FrictPhys_CundallStrack()], label="interactionLoop")]
        O.engines = ([ForceResetter()] + (framework if kind == "framework" else [])
                     + k.yade_engines("kernel()", "kernel.verify()", plugin=kind != "kernel")
                     + [NewtonIntegrator(damping=P["damping"], label="newton")])
        if k.path != ("pyrunner" if kind == "kernel" else "plugin"):
            raise SystemExit(f"bench_engines: no {kind} path: {k.path_note}")
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
        res["pairs_yade"] = len(O.interactions)
        res["memory_bytes"] = kernel.memory_bytes()
        kernel.close()
    else:
        res["pairs"] = len(O.interactions)
    return res


kernel = None
from yade_scripts.yadeplugin import load as plugin_load  # noqa: E402

KINDS = ("yade", "kernel") + (("plugin", "framework") if plugin_load.loaded_class()[0] is not None else ())
results = {k: [] for k in KINDS}
for b in range(BLOCKS):
    for kind in KINDS:
        results[kind].append(block(kind, K_STOCK if kind == "yade" else K_KERNEL))
    print(f"block {b}: " + ", ".join(f"{k} {results[k][-1]['us_per_contact_step']:.2f}" for k in KINDS)
          + " us/contact-step", flush=True)


def med(kind, key):
    return float(np.median([r[key] for r in results[kind]]))


def ratio_to(kind):
    return float(np.median([a["us_per_contact_step"] / b["us_per_contact_step"]
                            for a, b in zip(results["yade"], results[kind])]))


ratio = ratio_to("kernel")
summary = {"dump": DUMP, "snapshot": SNAP, "particles": len(particles), "threads": O.numThreads,
           "omp_wait_policy": os.environ.get("OMP_WAIT_POLICY"), "ratio_stock_over_kernel": ratio,
           "blocks": results}
if "plugin" in results:
    summary["ratio_stock_over_plugin"] = ratio_to("plugin")
    summary["ratio_pyrunner_over_plugin"] = float(np.median([a["us_per_contact_step"] / b["us_per_contact_step"]
                                                             for a, b in zip(results["kernel"], results["plugin"])]))
    fw = results["framework"]
    summary["framework_ms_per_step"] = {
        e: float(np.median([r["engines_ms_per_step"][e] for r in fw])) for e in ("collider", "interactionLoop")}
    summary["framework_interactions"] = float(np.median([r["pairs_yade"] for r in fw]))
    summary["plugin_glue_ms_per_step"] = float(np.median([r["kernel_split_ms_per_step"]["read"]
                                                          + r["kernel_split_ms_per_step"]["apply"]
                                                          for r in results["plugin"]]))
print(f"\n{len(particles)} polyhedra, yade -j{O.numThreads}, {BLOCKS} blocks (medians)")
print(f"{'engine':>7} {'steps/s':>9} {'contacts':>9} {'pairs':>7} {'us/contact-step':>16}")
for kind in KINDS:
    print(f"{kind:>7} {med(kind, 'steps_per_s'):9.2f} {med(kind, 'touching'):9.0f} {med(kind, 'pairs'):7.0f} "
          f"{med(kind, 'us_per_contact_step'):16.2f}")
print(f"stock / kernel (PyRunner) per contact-step: {ratio:.1f}x")
if "plugin" in results:
    print(f"stock / kernel (plugin) per contact-step: {summary['ratio_stock_over_plugin']:.1f}x; "
          f"PyRunner / plugin: {summary['ratio_pyrunner_over_plugin']:.2f}x")
    fwm = summary["framework_ms_per_step"]
    print(f"YADE's collider + InteractionLoop over the same grains, no geometry: {fwm['collider']:.3f} + "
          f"{fwm['interactionLoop']:.3f} ms/step ({summary['framework_interactions']:.0f} interactions), "
          f"against the plugin's reading and adding: {summary['plugin_glue_ms_per_step']:.3f} ms/step")
for kind in KINDS:
    last = results[kind][-1]
    parts = ", ".join(f"{k} {v:.2f}" for k, v in last["engines_ms_per_step"].items())
    print(f"{kind} ms/step by engine (last block): {parts}")
for kind in KINDS[1:]:
    k = results[kind][-1]
    print(f"{kind} split ms/step (last block): "
          + ", ".join(f"{a} {b:.3f}" for a, b in k["kernel_split_ms_per_step"].items())
          + f"; kernel memory {k['memory_bytes'] / 1e6:.2f} MB")
with open(DUMP[:-3] + ".bench_engines.json", "w") as fh:
    json.dump(summary, fh, indent=1)
sys.exit(0)
