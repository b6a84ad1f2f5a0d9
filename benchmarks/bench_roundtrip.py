"""The Python round trip of the kernel scene, candidate by candidate, in YADE.

    OMP_WAIT_POLICY=PASSIVE yade -j1 -n -x benchmarks/bench_roundtrip.py [N] [REPEAT]

Every step the kernel's PyRunner reads each particle's position and
orientation from YADE and adds each particle's force and torque to
``O.forces``. YADE 2023.02a's Python has no bulk accessor for either (no
numpy view of the states or of the force container), so each candidate is a
way of making the per-body calls. N bodies (default 1000) with random poses;
each candidate is timed REPEAT times (default 7) in turn with the others, and
the median is reported in µs per body. Every reading candidate must give the
same array, bit for bit, as the first; every applying candidate must leave
the same forces and torques in ``O.forces``.
"""
import operator
import sys
import time

import numpy as np

N = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
REPEAT = int(sys.argv[2]) if len(sys.argv) > 2 else 7
rng = np.random.default_rng(0)
ids = [O.bodies.append(utils.sphere(tuple(rng.uniform(0, 1, 3)), 0.01)) for _ in range(N)]
for i in ids:
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)
    O.bodies[i].state.ori = Quaternion(*q)
states = [O.bodies[i].state for i in ids]
for s_ in states:
    s_.blockedDOFs = "xyzXYZ"


def read_initargs():             # the scene's way before
    rows = [s.pos.__getinitargs__() + s.ori.__getinitargs__() for s in states]
    return np.array(rows, float).reshape(-1, 7)


def read_se3():                  # one attribute for both
    rows = [p.__getinitargs__() + q.__getinitargs__() for p, q in map(operator.attrgetter("se3"), states)]
    return np.array(rows, float).reshape(-1, 7)


GET_POS, GET_ORI = operator.attrgetter("pos"), operator.attrgetter("ori")
V_ARGS, Q_ARGS = Vector3.__getinitargs__, Quaternion.__getinitargs__


def read_maps():                 # attribute getters and unbound methods mapped, no Python loop body
    pos = np.array(list(map(V_ARGS, map(GET_POS, states))), float)
    ori = np.array(list(map(Q_ARGS, map(GET_ORI, states))), float)
    return np.hstack([pos, ori])


def read_fromiter():             # one flat float iterator, no intermediate rows
    it = (x for s in states for x in (*s.pos.__getinitargs__(), *s.ori.__getinitargs__()))
    return np.fromiter(it, float, 7 * N).reshape(-1, 7)


force = rng.normal(size=(N, 3))
torque = rng.normal(size=(N, 3))


def apply_loop():                # the scene's way before
    forces = O.forces
    for b, f, t in zip(ids, force.tolist(), torque.tolist()):
        forces.addF(b, tuple(f))
        forces.addT(b, tuple(t))


def apply_lists():               # lists as they come from tolist(): no tuple copies
    forces = O.forces
    for b, f, t in zip(ids, force.tolist(), torque.tolist()):
        forces.addF(b, f)
        forces.addT(b, t)


def apply_map():                 # the bound methods mapped over the rows
    forces = O.forces
    list(map(forces.addF, ids, force.tolist()))
    list(map(forces.addT, ids, torque.tolist()))


CURRENT = [None]


def run_current():
    CURRENT[0]()


def apply_in_a_step(applier):
    """The forces in O.forces after one step whose PyRunner applies them, as
    in the scene (ForceResetter, the PyRunner, NewtonIntegrator, which sums
    the per-thread buffers; every body is blocked, so none moves). Outside
    such a step, O.forces.f() can return a sum not yet made."""
    CURRENT[0] = applier
    O.engines = [ForceResetter(), PyRunner(command="run_current()", iterPeriod=1), NewtonIntegrator()]
    O.step()
    return forces_now()


def forces_now():
    return np.array([tuple(O.forces.f(i)) + tuple(O.forces.t(i)) for i in ids])


readers = [read_initargs, read_se3, read_maps, read_fromiter]
appliers = [apply_loop, apply_lists, apply_map]
ref = read_initargs()
for r in readers:
    assert np.array_equal(r(), ref), f"{r.__name__} reads other numbers"
apply_in_a_step(apply_loop)          # the first step sizes the force container (it reads zeros)
applied = {}
for a in appliers:
    applied[a.__name__] = apply_in_a_step(a)
    assert np.array_equal(applied[a.__name__], applied["apply_loop"]), f"{a.__name__} adds other forces"
assert np.array_equal(applied["apply_loop"], np.hstack([force, torque]))
times = {f.__name__: [] for f in readers + appliers}
for _ in range(REPEAT):
    for f in readers + appliers:
        t0 = time.perf_counter()
        f()
        times[f.__name__].append((time.perf_counter() - t0) / N * 1e6)
print(f"{N} bodies, medians of {REPEAT} (us per body; ratio to the first of its kind, median of per-repeat ratios)")
for group in (readers, appliers):
    base = np.array(times[group[0].__name__])
    for f in group:
        t = np.array(times[f.__name__])
        print(f"  {f.__name__:>14} {np.median(t):7.3f} us   x{np.median(base / t):5.2f}")
sys.exit(0)
