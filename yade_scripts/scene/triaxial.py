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
(yade_scripts/scene/parameters.py). The script reads as YADE's triax-tutorial:
parameters, grains, materials, bodies, the time step, one engine list, the run.
Its parts: the grains drawn and made bodies (yade_scripts/scene/grains.py), the
controller the PyRunner calls every step and its state
(yade_scripts/scene/controller.py), the loading program it follows (servo,
shear, when to take snapshots and stop: yade_scripts/scene/loading.py).
Checkpoints and resume (yade_scripts/runs/attempt.py): every ``checkpoint_seconds`` of wall time, and
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
import math
import os
import sys

import numpy as np
from yade import log

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
from postproc.schema import DumpWriter  # noqa: E402
from yade_scripts.runs.attempt import Attempt, Progress, remove_scratch_at_exit  # noqa: E402
from yade_scripts.runs.noremote import close_servers  # noqa: E402
from yade_scripts.runs.runlock import RunBusy  # noqa: E402
from yade_scripts.runs.runstate import EXIT_BUSY, EXIT_CONFIG, EXIT_DONE  # noqa: E402
from yade_scripts.scene import loading, timestep, yadedump  # noqa: E402
from yade_scripts.scene.controller import TriaxialController  # noqa: E402
from yade_scripts.scene.grains import add_particles, add_walls, draw_grains  # noqa: E402
from yade_scripts.scene.kernel_contacts import KernelContacts  # noqa: E402
from yade_scripts.scene.parameters import DEFAULTS, ConfigError, check  # noqa: E402
from yade_scripts.scene.tangential import TangentialLaw  # noqa: E402

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

# ------------------------------------------------------------ grains: sizes, shapes, orientations, places
grains = draw_grains(n_particles, seed, POLY, os.path.join(HERE, library), placement, initial_fraction, aspect)
d, d_mean, box0 = grains.d, grains.d_mean, grains.box0

# ------------------------------------------------------------ materials and stiffness
if POLY:
    k_v = kappa * sigma0 / (grains.a_face * d_mean)          # N/m^3, volumetric law F = k_v V
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

# ------------------------------------------------------------ bodies: 6 walls, then the particles
walls = add_walls(O, box0, wallmat)
particles = add_particles(O, grains, grain, density, KERNEL)

# ------------------------------------------------------------ time step and loading rates
if POLY:
    k_contact = k_v * grains.max_face[grains.shape_of] * d ** 2      # stiffest face contact of each grain
    k_contact = np.maximum(k_contact, tangential_ratio * k_v * grains.a_face * d ** 2)
    m_eff = density * d ** 3 * grains.rot_mass[grains.shape_of]
else:
    masses = np.array([O.bodies[i].state.mass for i in particles.tolist()])    # kg
    k_contact = 2 * young * (d / 2) * max(1.0, tangential_ratio)  # kn <= 2 E R
    m_eff = 0.4 * masses                                          # I / R^2 of a sphere
dt_crit = timestep.critical_time_step(m_eff, k_contact)
O.dt = safety * dt_crit
rate_shear = timestep.inertial_strain_rate(inertial_number, d_mean, density, sigma0)
rate_compact = timestep.inertial_strain_rate(compaction_inertial_number, d_mean, density, sigma0)

# ------------------------------------------------------------ contacts and engines
kernel = tangential_law = None
if KERNEL:
    # Every polyhedra-polyhedra and polyhedra-wall contact comes from the
    # compiled kernel (kernel_contacts.py): no collider, no InteractionLoop.
    # It steps inside YADE's C++ loop (the PolyhedraKernelEngine plugin,
    # where YADE was started with its YADE_PREFIX), else from a PyRunner.
    kernel = KernelContacts(O, particles, walls, grains.vertices(), grains.triangles(), d, k_v,
                            tangential_ratio * k_v * grains.a_face, compaction_friction, wall_friction,
                            verlet_skin * d_mean, kernel_threads or O.numThreads)
    if kernel.threads > 1 and os.environ.get("OMP_WAIT_POLICY", "").lower() != "passive":
        say("note: OMP_WAIT_POLICY=PASSIVE is not set; with other jobs on the same cores, "
            "OpenMP's spinning threads can slow the kernel down many times")
    contacts = kernel.yade_engines("kernel_step()", "kernel_check()", plugin=kernel_plugin)   # labelled kernel_contacts
    run.scene_saving = kernel.portable          # checkpoints hold the PyRunner form: they resume on either path
elif POLY:
    d_of = np.zeros(int(particles.max()) + 1)
    d_of[particles] = d

    def kt_of(id1, id2, kn):
        """Tangential stiffness (N/m) of polyhedra pairs: ratio k_v a_f d_pair^2."""
        d1, d2 = d_of[id1], d_of[id2]
        dp = np.where((d1 > 0) & (d2 > 0), 2 * d1 * d2 / np.where(d1 + d2 > 0, d1 + d2, 1), np.maximum(d1, d2))
        return tangential_ratio * kn * grains.a_face * dp ** 2

    tangential_law = TangentialLaw(O, Vector3, kt_of)
    contacts = [InsertionSortCollider([Bo1_Polyhedra_Aabb(), Bo1_Wall_Aabb()], verletDist=0.0),
                InteractionLoop([Ig2_Polyhedra_Polyhedra_PolyhedraGeom(), Ig2_Wall_Polyhedra_PolyhedraGeom()],
                                [Ip2_PolyhedraMat_PolyhedraMat_PolyhedraPhys()],
                                [Law2_PolyhedraGeom_PolyhedraPhys_Volumetric()]),
                PyRunner(command="tangential_law()", iterPeriod=1, label="tangential")]
else:
    contacts = [InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
                InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                                [Ip2_FrictMat_FrictMat_FrictPhys()],
                                [Law2_ScGeom_FrictPhys_CundallStrack()])]
newton = NewtonIntegrator(damping=compaction_damping, label="newton")
O.engines = [
    ForceResetter(),
    *contacts,
    PyRunner(command="control()", iterPeriod=1, label="controller"),
    newton,
]

# ------------------------------------------------------------ dump and log
derived = {
    "dt": O.dt, "dt_crit": dt_crit, "rate_shear": rate_shear, "rate_compaction": rate_compact,
    "d_mean": d_mean, "kn_volumetric": k_v if POLY else None, "young": 2 * k_v if POLY else young,
    "a_face": grains.a_face if POLY else None, "contact_engine": contact_engine if POLY else "yade",
}
if run.resumed:                                           # as the first attempt computed them
    derived = {k: run.resumed.dump_parameters.get(k, v) for k, v in derived.items()}


def new_dump():
    """The dump of a run that starts afresh, with the grains' shapes."""
    writer = DumpWriter(os.path.join(HERE, out), sample, {**PARAMS, **derived},
                        overlap_kind="volume" if POLY else "depth")
    if KERNEL:      # the kernel's grains: the library's, scaled
        writer.write_shapes(grains.vertices(), grains.triangles(), [grains.lib[int(s_k)][2] for s_k in grains.shape_of])
    elif POLY:
        writer.write_shapes(*yadedump.polyhedra_shapes(O, particles))
    return writer


writer = run.open_dump(new_dump)
log_file = run.open_log(loading.LOG_HEADER)
if run.resumed:                                           # as the first attempt measured them
    particle_volumes = run.resumed.arrays["particle_volumes"]
elif KERNEL:
    particle_volumes = grains.volumes()
else:
    particle_volumes = np.array([O.bodies[int(i)].shape.GetVolume() if POLY else
                                 4 / 3 * math.pi * O.bodies[int(i)].shape.radius ** 3 for i in particles])

# ------------------------------------------------------------ the controller (every step) and its state
program = loading.TriaxialLoading(sigma0, rate_compact, rate_shear, wall_speed, servo_gain, servo_time, kappa, O.dt,
                                  iso_tolerance, unbalanced_tolerance, dump_strain, final_strain, approach_factor,
                                  compaction_gain)
controller = TriaxialController(O, run, program, Progress(report_seconds), writer, log_file, walls, particles, d,
                                particle_volumes, PARAMS, box0, newton, kernel, tangential_law, say)
control, kernel_step, kernel_check = controller.step, controller.kernel_step, controller.kernel_check  # the PyRunners'

# ------------------------------------------------------------ run
say(f"{n_particles} {sample}, dt = {O.dt:.3g} s ({safety} x {dt_crit:.3g}), "
    f"shear rate {rate_shear:.3g} 1/s, box {np.round(box0, 4)} m")
run.start()
if run.resumed:
    run.restore(controller.set_scene_state, controller.stage_and_strain)
    controller.newton = [e for e in O.engines if isinstance(e, NewtonIntegrator)][0]   # the loaded scene's own engine
if KERNEL:
    say(f"polyhedra contacts: the kernel steps {'inside YADE (plugin)' if kernel.path == 'plugin' else 'from a PyRunner'}: "
        f"{kernel.path_note}")
O.timingEnabled = bool(timing)
outcome = run.loop(done=lambda: program.stage == "done", get_state=controller.scene_state,
                   where=controller.stage_and_strain)
controller.finish(outcome, derived, SCRATCH)        # closes the dump, writes OUT.info.json and leaves
