# -*- encoding=utf-8 -*-
"""Triaxial compression of a granular sample: S1 (polyhedra) or S2 (spheres).

After Azema, Radjai & Saussine (2009): a sample in a box of Wall bodies, zero
gravity, friction 0.5 between particles and 0 at the walls, is compressed
isotropically to sigma0, then sheared: the top wall moves down at constant
speed, the bottom wall is fixed and the four lateral walls hold sigma0 on
their current area. Snapshots of every contact go to an HDF5 dump
(postproc/schema.py), wall stresses to OUT.log.csv and a summary (solid
fraction, time step, costs, the host) to OUT.info.json, where OUT is the dump
name without .h5 (run.h5 by default).

This file is a template: ``python -m yade_scripts.campaign.generate`` copies it into a
run folder with the parameters below set from a preset, next to ``pkg/`` (a
copy of this repository's packages ``yade_scripts``, ``shapes`` and
``postproc``, imported under their own names) and, for polyhedra,
shapes.h5. Run it there with

    yade -x triaxial.py            (or OMP_WAIT_POLICY=PASSIVE yade -j2 -x triaxial.py:
                                    the polyhedra kernel then uses 2 threads)
    python -m yade_scripts.launch.batch FOLDER --jobs 2    (every line of table.txt; or yade-batch)

A table line (``YADE_BATCH=table.txt:LINE``, as yade-batch sets it)
overrides any parameter by its name; the parameters are checked first
(yade_scripts/scene/parameters.py). The loading program (servo, shear, when to
take snapshots and stop) is yade_scripts/scene/loading.py. Checkpoints and resume
(yade_scripts/runs/attempt.py): every ``checkpoint_seconds`` of wall time, and
when the process receives SIGTERM (what SLURM and most schedulers send
before a kill), the run writes OUT.ckpt atomically, keeping the previous one
as OUT.ckpt.prev. Run the same command again in the folder and it resumes
from the newest usable checkpoint, appending to the same dump
(``resume=False`` starts afresh). Exit codes (yade_scripts/runs/runstate.py): 0
done (or already complete), 2 invalid parameters, 3 stopped on a blow-up or
max_steps (message printed, snapshots kept), 4 another process is writing
the run (its lock, yade_scripts/runs/runlock.py: nothing touched), 75 checkpoint written after
SIGTERM (run again to resume), anything else a crash (run again to resume
from the last periodic checkpoint).
"""
import json
import math
import os
import sys
import time

import numpy as np
from yade import log, polyhedra_utils, utils

# ------------------------------------------------------------ parameters
# --- parameters (generated from yade_scripts/scene/parameters.py) ---
readParamsFromTable(
    sample='polyhedra',              # "polyhedra" (S1) or "spheres" (S2)
    n_particles=1000,                # number of particles
    seed=1,                          # sample seed (sizes, shapes, orientations, positions)
    sigma0=10000.0,                  # Pa, confining stress
    friction=0.5,                    # particle-particle friction coefficient (shear)
    compaction_friction=0.5,         # ... during the isotropic compression (0: the dense state; = friction: loose)
    wall_friction=0.0,               # particle-wall friction coefficient
    density=2700.0,                  # kg/m^3 (granite ballast)
    kappa=3000.0,                    # stiffness level: typical contact stiffness / (sigma0 d)
    tangential_ratio=1.0,            # tangential / normal stiffness of a typical contact
    inertial_number=0.005,           # shear: I = rate d sqrt(rho/sigma0) (ignored if wall_speed > 0)
    wall_speed=0.0,                  # m/s, top wall speed during shear (0: from inertial_number)
    compaction_inertial_number=0.1,  # max rate of the isotropic compression
    approach_factor=1.0,             # ... times this until the mean wall stress first reaches sigma0 / 2
    damping=0.2,                     # NewtonIntegrator's local damping during shear
    compaction_damping=0.2,          # ... and during the isotropic compression
    safety=0.45,                     # dt = safety * critical time step
    servo_gain=10.0,                 # proportional gain of the wall servo (lowered if unstable)
    compaction_gain=0.0,             # ... during the isotropic compression (0: servo_gain; lowered if unstable)
    servo_time=0.01,                 # integral time of the servo, as the strain (of the loading rate) it spans
    placement='grains',              # start: random sequential addition of the bounding spheres, or of the grains tested exactly (kernel)
    initial_fraction=0.25,           # packing fraction at the start: of the bounding spheres, or of the grains (placement grains)
    aspect=2.0,                      # H/L of the initial box
    iso_tolerance=0.01,              # isotropic state: |sigma - sigma0| < tol sigma0 on all walls
    unbalanced_tolerance=0.02,       # ... and unbalanced force ratio below this
    dump_strain=0.01,                # a snapshot every delta eps_1 during shear
    final_strain=0.3,                # eps_1 at the end of shear
    max_steps=0,                     # stop (as a failure) after this many steps (0: no limit)
    library='shapes.h5',             # polyhedra library (d = 1 grains)
    out='run.h5',                    # dump file
    log_every=200,                   # steps between log.csv rows
    check_every=200,                 # steps between blow-up checks
    report_seconds=10.0,             # seconds between progress lines
    timing=True,                     # record the time of each engine (run.info.json)
    contact_engine='kernel',         # polyhedra contacts: "kernel" (compiled, exact) or "yade" (stock Ig2/Law2)
    kernel_threads=0,                # OpenMP threads of the kernel (0: YADE's own, i.e. yade -jN)
    kernel_plugin=True,              # step the kernel inside YADE's C++ loop by the plugin where YADE loaded it (False: the PyRunner)
    verlet_skin=0.1,                 # kernel neighbour-list margin, in units of the mean d
    checkpoint_seconds=300.0,        # s of wall time between checkpoints (0: only on SIGTERM)
    resume=True,                     # continue from OUT.ckpt when there is one (False: start afresh)
    noTableOk=True,
)
from yade.params.table import (  # noqa: E402
    sample, n_particles, seed, sigma0, friction, compaction_friction, wall_friction,
    density, kappa, tangential_ratio, inertial_number, wall_speed,
    compaction_inertial_number, approach_factor, damping, compaction_damping, safety,
    servo_gain, compaction_gain, servo_time, placement, initial_fraction, aspect,
    iso_tolerance, unbalanced_tolerance, dump_strain, final_strain, max_steps, library,
    out, log_every, check_every, report_seconds, timing, contact_engine, kernel_threads,
    kernel_plugin, verlet_skin, checkpoint_seconds, resume,
)
# --- end of parameters ---

HERE = os.path.dirname(os.path.abspath(sys.argv[0]))
sys.path.insert(0, os.path.join(HERE, "pkg"))      # this run's copy of the repository's packages
from postproc.schema import DumpFormatError, DumpWriter  # noqa: E402
from shapes import sizes  # noqa: E402
from shapes.library import ShapeLibrary  # noqa: E402
from yade_scripts.runs import host  # noqa: E402
from yade_scripts.scene import loading, servo, timestep, yadedump  # noqa: E402
from yade_scripts.scene import sample as sampling  # noqa: E402
from yade_scripts.runs.attempt import Attempt, Progress, leave, remove_scratch_at_exit  # noqa: E402
from yade_scripts.runs.noremote import close_servers  # noqa: E402
from yade_scripts.scene.parameters import DEFAULTS, ConfigError, check  # noqa: E402
from yade_scripts.runs.runlock import RunBusy  # noqa: E402
from yade_scripts.runs.runstate import EXIT_BUSY, EXIT_CONFIG, EXIT_DONE, EXIT_FAILED, EXIT_TERM  # noqa: E402

SCRATCH = remove_scratch_at_exit(O.tmpFilename())   # YADE's scratch /tmp/yade-XXXXXX, which it leaves behind


def say(message):
    """Print one line of the scene, ``triaxial.py: <message>``, at once
    (the launchers relay the lines with this prefix)."""
    print(f"triaxial.py: {message}", flush=True)


CLOSED = close_servers()          # the yade launcher's remote servers; the project's launchers open none
if CLOSED:
    say(f"closed YADE's remote prompt and XMLRPC server (ports {', '.join(map(str, CLOSED))}), which the yade "
        f"launcher opened: this run listens on no port")


PARAMS = {k: v for k, v in vars(sys.modules["yade.params.table"]).items() if not k.startswith("_")}
try:
    check({k: v for k, v in PARAMS.items() if k in DEFAULTS})
except ConfigError as exc:
    say(f"invalid parameter: {exc}")
    sys.exit(EXIT_CONFIG)
POLY = sample == "polyhedra"
KERNEL = POLY and contact_engine == "kernel"
# Polyhedra_support.cpp can print gigabytes of "Unhandled switch case"
# warnings; keep its errors, drop its warnings.
log.setLevel("Polyhedra_support.cpp", log.ERROR)
os.chdir(HERE)

# ------------------------------------------------------------ this attempt: resume, or start afresh
try:                  # the run's only writer, or nothing is touched
    run = Attempt(O, os.path.join(HERE, out), PARAMS, checkpoint_seconds, resume, timing, say)
except RunBusy as exc:
    say(f"refused: {exc}")
    sys.exit(EXIT_BUSY)
if run.complete:
    say(f"{out} is complete already; nothing to do (delete it to run again)")
    sys.exit(EXIT_DONE)
# from here on SIGTERM stops the run at the end of a step, with a checkpoint

# ------------------------------------------------------------ sample
rng = np.random.default_rng(seed)
d = sizes.sample_diameters(n_particles, rng)               # m, exact class counts
d_mean = float(d.mean())
if POLY:
    lib = ShapeLibrary(os.path.join(HERE, library))
    shape_of = rng.integers(len(lib), size=n_particles)
    quats = sampling.random_quaternions(n_particles, rng)
    face_area = []                                          # per library shape, d = 1
    for s in range(len(lib)):
        v, t, _ = lib[s]
        face_area.append(0.5 * np.linalg.norm(np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]]), axis=1))
    a_face = float(np.mean(np.concatenate(face_area)))     # mean face area, d = 1
    max_face = np.array([a.max() for a in face_area])
    rot_mass = np.array([timestep.rotational_mass(lib.volume[s], np.diag(lib.inertia[s]), lib[s][0])
                         for s in range(len(lib))])       # d = 1, unit density
if POLY and placement == "grains":        # the grains themselves never overlap (exact test, shapes/overlap.py)
    from shapes.overlap import OrientedGrains  # noqa: E402

    grains = OrientedGrains([(lib[s][0] * d[k], lib[s][1]) for k, s in enumerate(shape_of)], quats)
    box0, centres = sampling.place_exact_in_box(d ** 3 * lib.volume[shape_of], d / 2, initial_fraction, aspect, rng,
                                                grains.overlaps)
else:                                     # bounding spheres never overlap
    box0, centres = sampling.place_in_box(d, initial_fraction, aspect, rng)

# ------------------------------------------------------------ materials and stiffness
if POLY:
    k_v = kappa * sigma0 / (a_face * d_mean)                 # N/m^3, volumetric law F = k_v V
    # Ip2 takes kn = E1 E2 / (E1 + E2): E = 2 k_v gives kn = k_v; poisson ~ 0
    # gives YADE's own (shared-history) shear stiffness ~ 0: see tangential.py
    POISSON_OFF = 1e-20
    grain = PolyhedraMat(young=2 * k_v, poisson=POISSON_OFF, frictionAngle=math.atan(compaction_friction),
                         density=density)
    wallmat = PolyhedraMat(young=2 * k_v, poisson=POISSON_OFF, frictionAngle=math.atan(wall_friction), density=density)
else:
    young = 2 * kappa * sigma0                               # kn = E R for equal spheres = kappa sigma0 d
    grain = FrictMat(young=young, poisson=tangential_ratio, frictionAngle=math.atan(compaction_friction),
                     density=density)
    wallmat = FrictMat(young=young, poisson=tangential_ratio, frictionAngle=math.atan(wall_friction), density=density)
O.materials.append(grain)
O.materials.append(wallmat)

# ------------------------------------------------------------ bodies: 6 walls, then particles
walls = []
for axis in range(3):
    for side, pos in ((-1, 0.0), (1, box0[axis])):
        w = utils.wall(pos, axis=axis, sense=0, material=wallmat)
        w.state.blockedDOFs = "xyzXYZ"
        walls.append(O.bodies.append(w))
particles = []
for k in range(n_particles):
    if POLY:
        s_k = int(shape_of[k])
        v, _, _ = lib[s_k]
        b = polyhedra_utils.polyhedra(grain, v=[tuple(x) for x in v * d[k]])
        w, x, y, z = quats[k]
        if KERNEL:
            # The kernel takes the grain from the library, in its own frame
            # (centre of mass, principal axes) and vertex order: YADE re-hulls
            # each Polyhedra with CGAL, which gives another vertex order and
            # frame from process to process, so the body's pose, mass and
            # inertia come from the library too, and the same seed gives the
            # same run, bit for bit.
            b.state.ori = Quaternion(w, x, y, z)
            b.state.mass = density * d[k] ** 3 * float(lib.volume[s_k])
            b.state.inertia = Vector3(*(density * d[k] ** 5 * np.diag(lib.inertia[s_k])))
        else:
            b.state.ori = Quaternion(w, x, y, z) * b.state.ori
    else:
        b = utils.sphere((0, 0, 0), d[k] / 2, material=grain)
    b.state.pos = tuple(centres[k])
    particles.append(O.bodies.append(b))
particles = np.array(particles)

# ------------------------------------------------------------ time step and loading rates
particle_list = particles.tolist()
masses = np.array([O.bodies[i].state.mass for i in particle_list])      # kg, as every checkpoint keeps them
if POLY:
    k_contact = k_v * max_face[shape_of] * d ** 2                 # stiffest face contact of each grain
    k_contact = np.maximum(k_contact, tangential_ratio * k_v * a_face * d ** 2)
    m_eff = density * d ** 3 * rot_mass[shape_of]
else:
    k_contact = 2 * young * (d / 2) * max(1.0, tangential_ratio)  # kn <= 2 E R
    m_eff = 0.4 * masses                                          # I / R^2 of a sphere
dt_crit = timestep.critical_time_step(m_eff, k_contact)
O.dt = safety * dt_crit
rate_shear = timestep.inertial_strain_rate(inertial_number, d_mean, density, sigma0)
rate_compact = timestep.inertial_strain_rate(compaction_inertial_number, d_mean, density, sigma0)



def kt_of(id1, id2, kn):
    """Tangential stiffness (N/m) of polyhedra pairs: ratio k_v a_f d_pair^2."""
    d1, d2 = d_of[id1], d_of[id2]
    dp = np.where((d1 > 0) & (d2 > 0), 2 * d1 * d2 / np.where(d1 + d2 > 0, d1 + d2, 1), np.maximum(d1, d2))
    return tangential_ratio * kn * a_face * dp ** 2


d_of = np.zeros(int(particles.max()) + 1)
d_of[particles] = d

# ------------------------------------------------------------ engines
if KERNEL:
    # Every polyhedra-polyhedra and polyhedra-wall contact comes from the
    # compiled kernel (kernel_contacts.py): no collider, no InteractionLoop.
    # It steps inside YADE's C++ loop (the PolyhedraKernelEngine plugin,
    # where YADE was started with its YADE_PREFIX), else from a PyRunner.
    from yade_scripts.scene.kernel_contacts import KernelContacts, KernelError  # noqa: E402

    # the library's grains (d = 1) scaled to each particle, in the library's order
    shape_v = [lib[int(s_k)][0] * d_k for s_k, d_k in zip(shape_of, d)]
    shape_t = [lib[int(s_k)][1] for s_k in shape_of]
    kernel = KernelContacts(O, particles, walls, shape_v, shape_t, d, k_v, tangential_ratio * k_v * a_face,
                            compaction_friction, wall_friction, verlet_skin * d_mean, kernel_threads or O.numThreads)
    if kernel.threads > 1 and os.environ.get("OMP_WAIT_POLICY", "").lower() != "passive":
        say("note: OMP_WAIT_POLICY=PASSIVE is not set; with other jobs on the same cores, "
            "OpenMP's spinning threads can slow the kernel down many times")
    O.engines = [
        ForceResetter(),
        *kernel.yade_engines("kernel_step()", "kernel_check()", plugin=kernel_plugin),   # labelled kernel_contacts
        PyRunner(command="control()", iterPeriod=1, label="controller"),
        NewtonIntegrator(damping=compaction_damping, label="newton"),
    ]
    run.scene_saving = kernel.portable          # checkpoints hold the PyRunner form: they resume on either path
elif POLY:
    from yade_scripts.scene.tangential import TangentialLaw  # noqa: E402

    tangential_law = TangentialLaw(O, Vector3, kt_of)
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Polyhedra_Aabb(), Bo1_Wall_Aabb()], verletDist=0.0),
        InteractionLoop(
            [Ig2_Polyhedra_Polyhedra_PolyhedraGeom(), Ig2_Wall_Polyhedra_PolyhedraGeom()],
            [Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()],
            [Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()],
        ),
        PyRunner(command="tangential_law()", iterPeriod=1, label="tangential"),
        PyRunner(command="control()", iterPeriod=1, label="controller"),
        NewtonIntegrator(damping=compaction_damping, label="newton"),
    ]
else:
    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
        InteractionLoop(
            [Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
            [Ip2_FrictMat_FrictMat_FrictPhys()],
            [Law2_ScGeom_FrictPhys_CundallStrack()],
        ),
        PyRunner(command="control()", iterPeriod=1, label="controller"),
        NewtonIntegrator(damping=compaction_damping, label="newton"),
    ]

# ------------------------------------------------------------ dump and log
derived = {
    "dt": O.dt, "dt_crit": dt_crit, "rate_shear": rate_shear, "rate_compaction": rate_compact,
    "d_mean": d_mean, "kn_volumetric": k_v if POLY else None, "young": 2 * k_v if POLY else young,
    "a_face": a_face if POLY else None, "contact_engine": contact_engine if POLY else "yade",
}
if run.resumed:                                           # as the first attempt computed them
    derived = {k: run.resumed.dump_parameters.get(k, v) for k, v in derived.items()}
shape_index = np.arange(n_particles) if POLY else np.full(n_particles, -1)


def new_dump():
    """The dump of a run that starts afresh, with the grains' shapes."""
    writer = DumpWriter(os.path.join(HERE, out), sample, {**PARAMS, **derived},
                        overlap_kind="volume" if POLY else "depth")
    if KERNEL:      # the kernel's grains: the library's, scaled
        writer.write_shapes(shape_v, shape_t, [lib[int(s_k)][2] for s_k in shape_of])
    elif POLY:
        writer.write_shapes(*yadedump.polyhedra_shapes(O, particles))
    return writer


writer = run.open_dump(new_dump)
log_file = run.open_log(loading.LOG_HEADER)
if run.resumed:                                           # as the first attempt measured them
    particle_volumes = run.resumed.arrays["particle_volumes"]
elif KERNEL:
    particle_volumes = d ** 3 * lib.volume[shape_of]
else:
    particle_volumes = np.array([O.bodies[int(i)].shape.GetVolume() if POLY else
                                 4 / 3 * math.pi * O.bodies[int(i)].shape.radius ** 3 for i in particles])
volume_particles = float(sum(particle_volumes))


wall_states = [O.bodies[w].state for w in walls]      # taken again after O.load of a checkpoint


def box():
    """(lo, hi) of the box from the wall positions."""
    p = [s.pos for s in wall_states]
    return (np.array([p[0][0], p[2][1], p[4][2]]), np.array([p[1][0], p[3][1], p[5][2]]))


def wall_forces():
    """(6, 3) N: the force on each wall by the particles this step, walls in
    the dump's order x-, x+, y-, y+, z-, z+."""
    f = O.forces.f
    return np.array([f(w).__getinitargs__() for w in walls])


def set_wall_velocities(vel):
    """Give the six walls the velocities ``vel`` (6, 3) m/s, in the dump's
    wall order (:func:`yade_scripts.scene.servo.wall_velocities`)."""
    for s, v in zip(wall_states, vel.tolist()):
        s.vel = v


def set_friction(mu):
    """Particle-particle friction from now on (the walls keep wall_friction):
    the grain material (O.materials[0]) for new contacts, and every touching
    particle pair (the kernel's coefficient, or the YADE interactions'
    Coulomb cap)."""
    O.materials[0].frictionAngle = math.atan(mu)
    if KERNEL:
        kernel.engine.set_friction(mu, wall_friction)
        return
    wall_set = set(walls)
    for i in O.interactions:
        if i.isReal and i.id1 not in wall_set and i.id2 not in wall_set:
            i.phys.tangensOfFrictionAngle = mu


def kernel_step():
    """One kernel step; a refused step (NaN positions) stops the run cleanly."""
    try:
        kernel()
    except KernelError as exc:
        fail(f"contact kernel: {exc}")


def kernel_check():
    """The plugin's first step of this attempt, checked against YADE's Python
    (a one-shot engine right after it); a refusal falls back to the PyRunner."""
    refused = kernel.verify()
    if refused:
        say(f"warning: the kernel plugin was refused at step {O.iter}: {refused}; "
            "the step was redone and the run goes on with the PyRunner")


def unbalanced():
    """YADE's unbalanced-force ratio (from the kernel's sums with the kernel,
    which leaves YADE no interactions to average over)."""
    return kernel.unbalanced() if KERNEL else utils.unbalancedForce()


def counts():
    """(interactions or neighbour pairs, touching contacts) now."""
    if KERNEL:
        return kernel.n_pairs, kernel.n_contacts
    return len(O.interactions), O.interactions.countReal()


dump_seconds = [0.0]     # wall time of the snapshots (gathering and writing), part of the controller's


def snapshot(stage):
    """Append a snapshot of the box, the wall forces, the particles and
    every contact to the dump, as ``stage`` ("isotropic" or "shear"); its
    time goes to the dump's cost (``dump_seconds``)."""
    t0 = time.perf_counter()
    lo, hi = box()
    writer.write_snapshot(
        step=O.iter, time=O.time, stage=stage, box_lo=lo, box_hi=hi, wall_ids=walls,
        wall_forces=wall_forces(),
        bodies=yadedump.gather_bodies(O, particles, 1 if POLY else 0, shape_index, d, particle_volumes),
        contacts=kernel.contacts() if KERNEL else yadedump.gather_contacts(O, POLY))
    dump_seconds[0] += time.perf_counter() - t0


def fail(reason):
    """Stop on a blow-up: say why, keep every snapshot written so far."""
    say(f"STOPPED at step {O.iter} ({program.stage}, eps_1 = {program.eps_1:.4f}): {reason}. "
        f"The {writer.n_snapshots} snapshot(s) written before are kept in {out}.")
    run.fail(reason)


def check_blowup(lo, hi, F):
    """None, or why the run has blown up (NaN, a particle out of the box,
    runaway kinetic energy)."""
    if not np.all(np.isfinite(F)):
        return "wall forces are NaN"
    states = [O.bodies[i].state for i in particle_list]
    pos = np.array([s.pos.__getinitargs__() for s in states])
    vel = np.array([s.vel.__getinitargs__() for s in states])
    if not (np.all(np.isfinite(pos)) and np.all(np.isfinite(vel))):
        return "particle positions or velocities are NaN"
    out_of_box = np.any((pos < lo - d.max()) | (pos > hi + d.max()), axis=1)
    if out_of_box.any():
        return f"particle {int(particles[np.argmax(out_of_box)])} left the box"
    m = masses
    v_rms = math.sqrt(np.sum(m * np.sum(vel ** 2, axis=1)) / m.sum())
    v_ref = max(approach_factor * rate_compact, rate_shear) * box0.max()   # fastest wall speed of the run
    if v_rms > 50 * v_ref and v_rms > 0.05:
        return f"runaway kinetic energy (rms speed {v_rms:.3g} m/s, 50 x the wall speed is {50 * v_ref:.3g})"
    return None


def report(sig, L):
    """A progress line every report_seconds of wall time."""
    sps = progress.tick(O.iter)
    if sps is None:
        return
    left = None
    if program.stage == "shear":
        s1, s3 = sig[2], 0.5 * (sig[0] + sig[1])
        qp = (s1 - s3) / (s1 + 2 * s3) if s1 + 2 * s3 > 0 else float("nan")
        where = f"eps_1 {program.eps_1:.4f}, q/p (walls) {qp:.3f}"
        left = program.seconds_left(L, sps)
        eta = f"about {left / 60:.1f} min left"
    else:
        where = f"sigma/sigma0 {np.round(sig / sigma0, 3)}"
        eta = "time left known once shear starts"
    say(f"step {O.iter} {program.stage}: {where}, {counts()[0]} interactions, {sps:.0f} steps/s, {eta}")
    run.progress(step=O.iter, stage=program.stage, eps_1=float(program.eps_1), steps_per_second=sps,
                 seconds_left=None if left is None else float(left))


# ------------------------------------------------------------ the controller (every step)
program = loading.TriaxialLoading(sigma0, rate_compact, rate_shear, wall_speed, servo_gain, servo_time, kappa, O.dt,
                                  iso_tolerance, unbalanced_tolerance, dump_strain, final_strain, approach_factor,
                                  compaction_gain)
progress = Progress(report_seconds)


def control():
    """The controller, run by a PyRunner every step: the loading program
    (:class:`yade_scripts.scene.loading.TriaxialLoading`) from the wall stresses
    (compaction to the isotropic state, its snapshot and the switch to
    shear; then shear, its snapshots and the end), the log row every
    ``log_every`` steps, the blow-up and ``max_steps`` checks every
    ``check_every`` steps, and the progress line. It first lets a due
    checkpoint end the run after this step
    (:meth:`yade_scripts.runs.attempt.Attempt.end_of_step`) and, on the plugin
    path, stops the run on an error of the kernel's step."""
    run.end_of_step()
    if KERNEL and kernel.path == "plugin":
        problem = kernel.step_error()
        if problem:
            fail(f"contact kernel: {problem}")
            return
    lo, hi = box()
    L = hi - lo
    F = wall_forces()
    sig = servo.wall_stresses(F, L)
    if program.stage == "compaction":
        set_wall_velocities(program.compaction_velocities(sig, L))
        if program.isotropic(O.iter, sig, unbalanced):
            phi = volume_particles / np.prod(L)
            say(f"isotropic state at step {O.iter}: sigma/sigma0 = {np.round(sig / sigma0, 4)}, "
                f"solid fraction {phi:.4f}, unbalanced force {unbalanced():.2e}")
            snapshot("isotropic")
            v_top = program.start_shear(L, phi, O.iter, run.wall_seconds())
            newton.damping = damping
            if compaction_friction != friction:
                set_friction(friction)
                say(f"friction {compaction_friction:g} -> {friction:g} for shear")
            writer.update_parameters(top_wall_speed=v_top, solid_fraction_isotropic=phi, box_isotropic=L.tolist())
            say(f"shear: top wall at {v_top:.4g} m/s")
    else:
        set_wall_velocities(program.shear_velocities(sig, L))
        if program.snapshot_due():
            snapshot("shear")
        if program.finished():
            O.pause()
            return
    if O.iter % log_every == 0:
        n_inter, n_real = counts()
        program.count(n_inter, n_real, log_every)
        log_file.write(program.log_row(O.iter, O.time, sig, L, volume_particles / np.prod(L), unbalanced(),
                                       n_inter, n_real, progress.steps_per_second))
        log_file.flush()
    if O.iter % check_every == 0:
        problem = check_blowup(lo, hi, F)
        if problem:
            fail(problem)
            return
        if max_steps and O.iter >= max_steps:
            fail(f"max_steps = {max_steps} reached before the end")
            return
    report(sig, L)


# ------------------------------------------------------------ checkpoints
# Taken between two steps (the attempt stops YADE at the end of a step
# first), so that every part of the state belongs to the same instant. YADE's
# scene goes through O.save (bodies with their masses, inertias, poses and
# velocities, the interactions with their histories, materials, engines,
# iteration and time); the rest is below. YADE re-initialises Polyhedra
# shapes on O.load (vertex order and round-off change); the kernel's grains
# come from the library, the same on every attempt, and the dump's /shapes
# stay those of the first attempt.
def scene_state():
    """What a checkpoint keeps beside YADE's scene: (JSON-able dict, arrays)."""
    state = {"state": program.saved(), "friction": math.tan(O.materials[0].frictionAngle),
             "dump_seconds": dump_seconds[0]}
    arrays = {"particle_volumes": particle_volumes}
    if KERNEL:
        arrays.update({f"kernel/{k}": v for k, v in kernel.engine.state().items()})
        state["kernel_counters"] = kernel.counters()
    elif POLY:
        keys = list(tangential_law.history)
        arrays["tangential_ids"] = np.array(keys, np.int64).reshape(-1, 2)
        arrays["tangential_force"] = np.array([tangential_law.history[k] for k in keys], float).reshape(-1, 3)
    return state, arrays


def set_scene_state(state, arrays):
    """Put back what :func:`scene_state` kept (YADE's scene is loaded already)."""
    wall_states[:] = [O.bodies[w].state for w in walls]
    dump_seconds[0] = float(state.get("dump_seconds", 0.0))     # checkpoints of older code lack it
    program.restore(state["state"])
    progress.restart(O.iter)
    if KERNEL:
        kernel.rebind()
        kernel.engine.set_state({k[len("kernel/"):]: v for k, v in arrays.items() if k.startswith("kernel/")})
        kernel.set_counters(state["kernel_counters"])
        kernel.install("kernel_step()", "kernel_check()", kernel_plugin)     # the loaded scene holds the PyRunner form
    elif POLY:
        tangential_law.history = {(int(a), int(b)): tuple(f) for (a, b), f in
                                  zip(arrays["tangential_ids"].tolist(), arrays["tangential_force"].tolist())}


def stage_and_strain():
    """(stage, eps_1) now, for the checkpoint lines."""
    return program.stage, program.eps_1


# ------------------------------------------------------------ run
say(f"{n_particles} {sample}, dt = {O.dt:.3g} s ({safety} x {dt_crit:.3g}), "
    f"shear rate {rate_shear:.3g} 1/s, box {np.round(box0, 4)} m")
run.start()
if run.resumed:
    run.restore(set_scene_state, stage_and_strain)
    newton = [e for e in O.engines if isinstance(e, NewtonIntegrator)][0]     # the loaded scene's own engine
if KERNEL:
    say(f"polyhedra contacts: the kernel steps {'inside YADE (plugin)' if kernel.path == 'plugin' else 'from a PyRunner'}: "
        f"{kernel.path_note}")
O.timingEnabled = bool(timing)
outcome = run.loop(done=lambda: program.stage == "done", get_state=scene_state, where=stage_and_strain)
if outcome == "stalled":
    fail("an exception in the scene's own engines stopped the simulation (its traceback is above)")
log_file.close()
if outcome == "paused":
    say(f"paused from outside at step {O.iter} (a stop the scene did not ask for); the checkpoint and the "
        f"{writer.n_snapshots} snapshot(s) are kept: run again in this folder to resume (exit {EXIT_TERM})")
    leave(EXIT_TERM)
if outcome == "terminated":
    say(f"stopped on SIGTERM at step {O.iter}; the checkpoint and the {writer.n_snapshots} snapshot(s) are kept: "
        f"run again in this folder to resume (exit {EXIT_TERM})")
    leave(EXIT_TERM)
try:                              # packing checks every snapshot against what was recorded when it was written
    if run.failed:
        writer.close(pack=True, complete=False)
        run.finish()              # a blow-up replays identically from a checkpoint: nothing to resume
        leave(EXIT_FAILED)
    writer.close(pack=True)
except DumpFormatError as exc:    # the parts do not add up (a second writer?): kept as they are, never complete
    say(f"the dump cannot be closed: {exc}")
    leave(EXIT_FAILED)
run.finish()
history = run.history()
info = {"steps": O.iter, "time": O.time, "wall_seconds": history["wall_seconds"],
        "solid_fraction_isotropic": program.phi_iso, "snapshots": writer.n_snapshots,
        "contact_steps": program.contact_steps, "interaction_steps": program.interaction_steps,
        "shear_start_step": program.shear_start_step, "shear_start_wall_seconds": program.shear_start_wall,
        "engine_seconds": history["engine_seconds"], "dump_seconds": dump_seconds[0], "resumes": history["resumes"],
        **derived,
        "host": host.host_info(), "yade_scratch": SCRATCH}
if KERNEL:   # the kernel's own split and exact touching contact-steps
    info["kernel"] = {**kernel.timing(), "touch_steps": kernel.touch_steps, "threads": kernel.threads,
                      "memory_bytes": kernel.memory_bytes(), "path": kernel.path, "path_note": kernel.path_note}
with open(run.files.info, "w") as fh:
    json.dump(info, fh, indent=1)
say(f"done in {run.wall_seconds() - run.earlier_wall_seconds:.0f} s, {O.iter} steps; dump {out}")
leave(0)                          # all written: out without YADE's static destructors (attempt.leave)
