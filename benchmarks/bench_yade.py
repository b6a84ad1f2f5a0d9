"""Speed of the YADE scenes: steps/s, contact-steps/s and where the time goes.

    python benchmarks/bench_yade.py [RUN_DIR ...]     (default: runs/study/*)

Reads what each finished run recorded (``run.info.json``: engine times with
``timing=True``, contact-steps counted every ``log_every`` steps)
and prints one block per run. Run ``make study`` first (the default preset),
or point it at any run folders. The cost split separates YADE's contact
detection and laws (InteractionLoop: for polyhedra the CGAL intersection of
every pair of overlapping bounding boxes) from our per-contact tangential law
(the "tangential" PyRunner) and the Python controller (servo, dumps, checks).
With the compiled kernel (``contact_engine = "kernel"``) the contacts are the
"kernel_contacts" PyRunner, split into reading the poses, the C kernel and
adding the forces; its contact-steps are counted exactly, every step.
"""
import glob
import json
import os
import sys


def summarize(folder):
    info = json.load(open(os.path.join(folder, "run.info.json")))
    params = json.load(open(os.path.join(folder, "params.json")))
    eng = info.get("engine_seconds", {})
    total = sum(eng.values()) or info["wall_seconds"]
    steps = info["steps"]
    lines = [f"{folder}: {params['n_particles']} {params['sample']} ({params.get('preset', '?')} preset), "
             f"kappa {params['kappa']:g}, I {params['inertial_number']:g}",
             f"  {steps} steps in {info['wall_seconds']:.0f} s: {steps / info['wall_seconds']:.1f} steps/s; "
             f"{info['contact_steps'] / info['wall_seconds']:.3g} contact-steps/s "
             f"({info['wall_seconds'] / max(info['contact_steps'], 1) * 1e6:.1f} us per contact-step, "
             f"{info['wall_seconds'] / max(info['interaction_steps'], 1) * 1e6:.1f} us per interaction-step)",
             f"  dt {info['dt']:.3g} s, solid fraction after isotropic compression "
             f"{info['solid_fraction_isotropic']:.3f}"]
    for name, sec in sorted(eng.items(), key=lambda kv: -kv[1]):
        lines.append(f"    {name:24s} {sec:9.1f} s  {100 * sec / total:5.1f} %  "
                     f"{sec / steps * 1e3:8.3f} ms/step")
    k = info.get("kernel")
    if k:
        lines.append(f"  kernel ({k['threads']} threads, {k['memory_bytes'] / 1e6:.1f} MB): "
                     + ", ".join(f"{part} {k[part]:.1f} s" for part in ("read", "kernel", "apply"))
                     + f"; {k['touch_steps']:.3g} contact-steps exactly, "
                     f"{info['wall_seconds'] / max(k['touch_steps'], 1) * 1e6:.2f} us per contact-step")
    return "\n".join(lines)


def main(argv):
    folders = argv or sorted(glob.glob("runs/study/*/"))
    done = [f for f in folders if os.path.exists(os.path.join(f, "run.info.json"))]
    if not done:
        print("bench_yade: no finished run (run 'make study' first)", file=sys.stderr)
        return 2
    for f in done:
        print(summarize(f.rstrip("/")))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
