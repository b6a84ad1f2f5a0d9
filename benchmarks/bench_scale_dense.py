"""The whole kernel step of dense packings of several sizes, on both kernel
paths, in one YADE run.

    OMP_WAIT_POLICY=PASSIVE YADE_PREFIX=... yade -jT -n -x benchmarks/bench_scale_dense.py OUT.json STEPS BLOCKS \
        RUN1.h5:SNAP RUN2.h5:SNAP ...

Each dump's snapshot (e.g. the same shear strain of a 1000- and a
5000-grain S1 of the study) is rebuilt in YADE (``yade_packing.py``) and
saved in memory. Then BLOCKS rounds: in each, every packing in turn, on each
path (the kernel plugin, when YADE loaded it, then the PyRunner;
BENCH_PATHS="plugin" or "pyrunner" keeps one), is reloaded, given the
kernel's engines (``yade_scripts.scene.kernel_contacts``: the plugin's
PolyhedraKernelEngine or its PyRunner) and NewtonIntegrator with the run's
damping (walls fixed: the controller is the same Python at every size and on
both paths and is timed in the runs themselves), stepped 2 steps untimed
(the neighbour list is built; the plugin's first step is checked), then
STEPS steps timed with ``O.timingEnabled``. Per packing, path and block: ms
per step of each engine, the kernel's split (reading the poses, the C
kernel, adding the forces), touching contacts per step, us per grain-step.
Writes OUT.json ({"threads", "packings": [{dump, snapshot, particles,
blocks: [...]}]}, each block with its "path"); ``bench_scale.py --dense``
runs this and tabulates the medians, the per-grain ratios (each block's
packings against its smallest) and the plugin against the PyRunner.
"""
import json
import os
import sys
import time


sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from yade_packing import build_packing  # noqa: E402
from yade_scripts.scene.kernel_contacts import KernelContacts  # noqa: E402

OUT, STEPS, BLOCKS = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
SPECS = [(a.rsplit(":", 1)[0], int(a.rsplit(":", 1)[1])) for a in sys.argv[4:]]

packings = []
for k, (dump, snap) in enumerate(SPECS):
    O.reset()
    t0 = time.perf_counter()
    pk = build_packing(O, os.path.abspath(dump), snap)
    O.saveTmp(f"p{k}")
    packings.append({"dump": dump, "snapshot": snap, "particles": len(pk["particles"]),
                     "build_s": time.perf_counter() - t0, "pk": pk, "blocks": []})
    print(f"built {dump}:{snap}: {len(pk['particles'])} polyhedra in {packings[-1]['build_s']:.1f} s", flush=True)

PATHS = os.environ.get("BENCH_PATHS", "plugin pyrunner").split()
for b in range(BLOCKS):
    for k, p in enumerate(packings):
        for path in PATHS:
            pk, P = p["pk"], p["pk"]["P"]
            O.loadTmp(f"p{k}")
            k_v = P["kn_volumetric"]
            kernel = KernelContacts(O, pk["particles"], pk["walls"], pk["vertices"], pk["triangles"], pk["sizes"], k_v,
                                    P["tangential_ratio"] * k_v * P["a_face"], P["friction"], P["wall_friction"],
                                    P.get("verlet_skin", 0.1) * P["d_mean"], O.numThreads)
            O.engines = [ForceResetter(), *kernel.yade_engines("kernel()", "kernel.verify()", plugin=path == "plugin"),
                         NewtonIntegrator(damping=P["damping"], label="newton")]
            if kernel.path != path:
                raise SystemExit(f"bench_scale_dense: the {path} path is not available: {kernel.path_note}")
            O.run(2, True)
            if kernel.path != path:
                raise SystemExit(f"bench_scale_dense: the plugin was refused: {kernel.path_note}")
            O.timingEnabled = True
            for e in O.engines:
                e.execTime = 0
            kernel.seconds = {"read": 0.0, "kernel": 0.0, "apply": 0.0}
            touch0 = kernel.touch_steps
            t0 = time.perf_counter()
            O.run(STEPS, True)
            wall = time.perf_counter() - t0
            O.timingEnabled = False
            eng = {(e.label or e.__class__.__name__): e.execTime * 1e-6 / STEPS for e in O.engines}
            split = {key: val * 1e3 / STEPS for key, val in kernel.seconds.items()}
            touching = (kernel.touch_steps - touch0) / STEPS
            p["blocks"].append({"path": path, "wall_ms_per_step": 1e3 * wall / STEPS, "engines_ms_per_step": eng,
                                "kernel_split_ms_per_step": split, "touching": touching,
                                "us_per_grain_step": 1e6 * wall / STEPS / p["particles"],
                                "memory_bytes": kernel.memory_bytes()})
            kernel.close()
            print(f"block {b} {p['dump']} {path}: {1e3 * wall / STEPS:.2f} ms/step, "
                  f"{1e6 * wall / STEPS / p['particles']:.2f} us/grain-step, {touching:.0f} touching", flush=True)

with open(OUT, "w") as fh:
    json.dump({"threads": O.numThreads, "steps": STEPS,
               "packings": [{k: v for k, v in p.items() if k != "pk"} for p in packings]}, fh, indent=1)
sys.exit(0)
