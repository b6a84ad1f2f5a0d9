"""A small box of polyhedra stepped on both kernel paths, in YADE.

Used by the plugin's probe (``probe_scene.py``, run by
:func:`yade_scripts.yadeplugin.probe` at build time) and by the tests: 27
random convex grains (hulls of 14 random points, d = 2 cm) in a 3 x 3 x 3
grid whose spacing is 0.9 d, in a box of six walls just as tight, with
random orientations, masses, velocities and spins, so that grains touch
grains and walls and every body has its own pose, mass, force and torque.

:func:`compare_paths` saves the scene, steps it with the plugin (its first
step checked by :meth:`KernelContacts.verify`) and, from the same saved
state, on the PyRunner path, and compares the two bit for bit.
YADE's Python only.
"""
import math

import numpy as np

from yade_scripts.scene.kernel_contacts import KernelContacts
from yade_scripts.scene.yadedump import polyhedra_shapes

D = 0.02            # m
K_V = 2.0e9         # N/m^3
DT = 2.0e-6         # s


def small_box(O, n_side=3, seed=7):
    """Build the box in ``O`` (reset first); returns (particles, walls,
    vertices, triangles, sizes) for :class:`KernelContacts`."""
    from yade import polyhedra_utils, utils
    from yade.minieigenHP import Quaternion, Vector3
    from yade.wrapper import PolyhedraMat

    O.reset()
    rng = np.random.default_rng(seed)
    mat = PolyhedraMat(young=2 * K_V, poisson=1e-20, frictionAngle=math.atan(0.5), density=2700)
    wallmat = PolyhedraMat(young=2 * K_V, poisson=1e-20, frictionAngle=0.0, density=2700)
    O.materials.append(mat)
    O.materials.append(wallmat)
    s = 0.9 * D
    L = n_side * s
    walls = []
    for axis in range(3):
        for pos in (0.0, L):
            w = utils.wall(pos, axis=axis, sense=0, material=wallmat)
            w.state.blockedDOFs = "xyzXYZ"
            walls.append(O.bodies.append(w))
    particles = []
    for i in range(n_side):
        for j in range(n_side):
            for k in range(n_side):
                p = rng.normal(size=(14, 3))
                p = 0.5 * D * p / np.linalg.norm(p, axis=1)[:, None]
                b = polyhedra_utils.polyhedra(mat, v=[tuple(x) for x in p])
                q = rng.normal(size=4)
                q /= np.linalg.norm(q)
                b.state.ori = Quaternion(*q) * b.state.ori
                b.state.pos = ((i + 0.5) * s, (j + 0.5) * s, (k + 0.5) * s)
                b.state.mass = b.state.mass * (0.5 + rng.random())
                b.state.vel = Vector3(*rng.normal(scale=0.02, size=3))
                b.state.angVel = Vector3(*rng.normal(scale=2.0, size=3))
                particles.append(O.bodies.append(b))
    vertices, triangles, _ = polyhedra_shapes(O, particles)
    sizes = np.array([2 * np.linalg.norm(v, axis=1).max() for v in vertices])
    O.dt = DT
    return particles, walls, vertices, triangles, sizes


def snapshot(O):
    """Every body's pose, velocities, force and torque, as exact tuples."""
    out = []
    for b in O.bodies:
        s = b.state
        out.append((tuple(s.pos), s.ori.__getinitargs__(), tuple(s.vel), tuple(s.angVel), tuple(O.forces.f(b.id)),
                    tuple(O.forces.t(b.id))))
    return out


def step_path(O, built, plugin, checker="check()"):
    """The engines of the box on one path (the plugin's first step checked
    by the command ``checker``); returns the :class:`KernelContacts`."""
    particles, walls, v, t, sizes = built
    kernel = KernelContacts(O, particles, walls, v, t, sizes, K_V, 0.5 * K_V * D, 0.5, 0.0, 0.1 * D, 1)
    from yade.wrapper import ForceResetter, NewtonIntegrator

    O.engines = [ForceResetter(), *kernel.yade_engines("kernel()", check=checker, plugin=plugin),
                 NewtonIntegrator(damping=0.2)]
    return kernel


def compare_paths(O, namespace, steps=30):
    """The box stepped ``steps`` steps with the plugin and on the PyRunner
    path from the same state: (ok, why, details). ``namespace``: the
    script's globals (the PyRunners' commands run there)."""
    built = small_box(O)
    O.saveTmp("plugin-probe")
    results = {}
    for path in ("plugin", "pyrunner"):
        O.loadTmp("plugin-probe")
        verdicts = []
        kernel = step_path(O, built, path == "plugin")
        namespace["kernel"] = kernel
        namespace["check"] = lambda: verdicts.append(kernel.verify())
        if path == "plugin" and kernel.path != "plugin":
            return False, f"the plugin is not usable here: {kernel.path_note}", {}
        O.run(steps, True)
        if path == "plugin":
            if kernel.path != "plugin":
                return False, f"the start-up check refused the plugin: {verdicts[0]}", {}
            if verdicts != [None]:
                return False, f"the start-up check ran {len(verdicts)} times, not once in the first step", {}
            if kernel.step_error():
                return False, f"the plugin's step failed: {kernel.step_error()}", {}
        results[path] = {"snap": snapshot(O), "touch_steps": kernel.touch_steps, "calls": kernel.calls,
                         "contacts": kernel.contacts()}
    a, b = results["plugin"], results["pyrunner"]
    details = {"bodies": len(a["snap"]), "steps": steps, "touching_contact_steps": a["touch_steps"]}
    if a["touch_steps"] == 0:
        return False, "the probe box has no touching contacts: it checks nothing", details
    if a["calls"] != steps or b["calls"] != steps:
        return False, f"the kernel ran {a['calls']} and {b['calls']} times in {steps} steps", details
    for k, (x, y) in enumerate(zip(a["snap"], b["snap"])):
        if x != y:
            return False, f"body {k} differs between the plugin and the PyRunner path after {steps} steps", details
    for key in a["contacts"]:
        if not np.array_equal(a["contacts"][key], b["contacts"][key]):
            return False, f"the contacts' {key} differ between the paths", details
    return True, (f"{len(a['snap'])} bodies, {steps} steps, {a['touch_steps']} touching contact-steps: "
                  "equal bit for bit on both paths"), details
