"""The kernel plugin's refusal, fallback and errors, on the small box of
yade_scripts/yadeplugin/scene.py. Prints one line RESULT {json}.

    YADE_PREFIX=PREFIX yade -n -x plugin_cases.py refuse ROOT
    yade -n -x plugin_cases.py absent ROOT          (no YADE_PREFIX)
    YADE_PREFIX=PREFIX yade -n -x plugin_cases.py error ROOT

refuse: the plugin reads every pose, then, before the start-up check, a
        PyRunner moves one body by one ulp along x: to the check the plugin
        has read a position YADE does not hold, as a plugin with a wrong
        layout would. It must refuse, restore the kernel, redo the step on
        the PyRunner path and keep it; the run is then the same, bit for
        bit, as a PyRunner run in which the body moved by that ulp before
        the kernel's first step.
absent: YADE started without the plugin's prefix: the scene loads the plugin itself.
error:  a body's position set to NaN: the plugin's step stops before adding
        forces and says why in the kernel's words.
"""
import json
import math
import sys

mode, root = sys.argv[1], sys.argv[2]
sys.path.insert(0, root)
from yade_scripts.yadeplugin.scene import compare_paths, small_box, snapshot, step_path  # noqa: E402
from yade_scripts.runs.attempt import remove_scratch_at_exit  # noqa: E402

remove_scratch_at_exit(O.tmpFilename())      # YADE's /tmp/yade-XXXXXX of this process

STEPS = 12
NUDGED = 13              # a body of the box's middle layer (ids 0-5 are the walls)
out = {"mode": mode}


def nudge():
    """Move body NUDGED by one ulp along x (first step only)."""
    if O.iter == 0:
        s = O.bodies[NUDGED].state
        x = s.pos
        s.pos = Vector3(math.nextafter(x[0], math.inf), x[1], x[2])


if mode == "refuse":
    built = small_box(O)
    O.saveTmp("box")
    verdicts = []
    check = lambda: verdicts.append(kernel.verify())  # noqa: E731
    kernel = step_path(O, built, True)
    out["path_at_start"] = kernel.path
    engines = list(O.engines)
    O.engines = engines[:2] + [PyRunner(command="nudge()", iterPeriod=1, initRun=True, label="nudger")] + engines[2:]
    O.run(STEPS, True)
    out.update(refused=verdicts[0], later=verdicts[1:], path=kernel.path, note=kernel.path_note,
               engine=type([e for e in O.engines if e.label == "kernel_contacts"][0]).__name__,
               calls=kernel.calls)
    first = snapshot(O)
    O.loadTmp("box")
    kernel = step_path(O, built, False)
    engines = list(O.engines)
    O.engines = engines[:1] + [PyRunner(command="nudge()", iterPeriod=1, initRun=True, label="nudger")] + engines[1:]
    O.run(STEPS, True)
    out["same_as_pyrunner_run"] = snapshot(O) == first
    out["touch_steps"] = kernel.touch_steps
elif mode == "absent":
    built = small_box(O)
    verdicts = []
    check = lambda: verdicts.append(kernel.verify())  # noqa: E731
    kernel = step_path(O, built, True)
    O.run(STEPS, True)
    out.update(path=kernel.path, note=kernel.path_note, calls=kernel.calls,
               engine=type([e for e in O.engines if e.label == "kernel_contacts"][0]).__name__)
elif mode == "error":
    built = small_box(O)
    check = lambda: kernel.verify()  # noqa: E731
    kernel = step_path(O, built, True)
    O.run(2, True)
    ok_error = kernel.step_error()
    O.bodies[NUDGED].state.pos = Vector3(float("nan"), 0, 0)
    forces_before = kernel.touch_steps
    O.run(1, True)
    out.update(path=kernel.path, before=ok_error, after=kernel.step_error(), code=kernel.plugin.error,
               touch_steps_unchanged=kernel.touch_steps == forces_before,
               force_on_nudged=tuple(O.forces.f(NUDGED)))
elif mode == "compare":
    ok, why, details = compare_paths(O, globals())
    out.update(ok=ok, why=why, **details)
print("RESULT " + json.dumps(out), flush=True)
sys.exit(0)
