"""Triaxial compression of the study's grains by Contact Dynamics (LMGC90).

The paper's own method beside the YADE scene (``yade_scripts/scene/triaxial.py``):
rigid grains, nonsmooth contact laws (IQS_CLB: Signorini and Coulomb, mu =
0.5 between grains, 0 at the walls), NLGS, zero gravity, six rigid walls.
The sample is brought to rest at sigma0 (isotropic stage: the five walls
other than the bottom one pushed by sigma0 times their area), then sheared:
the top wall moves down at constant speed, the bottom wall is fixed and the
four lateral walls are pushed by sigma0 times their current area
(stress control by an external force on a free wall, the route of RBDY3's
``triaxial_loading``: docs/lmgc90.md). Snapshots go to the project's dump
(postproc/schema.py: one ``contacts`` row per pair of bodies, every CD
contact point in ``points``), so ``postproc analyze`` reads it as any
run; one row a step to OUT.log.csv, a summary to OUT.info.json.

    python -m lmgc90.triaxial FOLDER --start yade --source RUN.h5 [--set NAME=VALUE ...]
    python -m lmgc90.triaxial FOLDER --start loose --set seed=1 [--set n_particles=200 ...]

FOLDER is made when missing and is LMGC90's working directory (DATBOX/,
OUTBOX/). Starting states (lmgc90/cdstart.py): ``yade`` takes the first
isotropic snapshot of a project dump (a YADE run's: the same grains,
positions and orientations); ``loose`` draws the grains as the YADE scene
does for the same seed and lets the walls compact them (LMGC90's own
compaction, as the paper's). Run the same command again in the folder (or
only ``python -m lmgc90.triaxial FOLDER``: a checkpoint holds every
parameter) and it resumes from the newest checkpoint (OUT.ckpt, then OUT.ckpt.prev), every
``checkpoint_seconds`` and on SIGTERM. Exit codes as the YADE scene's
(yade_scripts/runs/runstate.py): 0 done (or complete already), 2 invalid
parameters or starting state, 3 stopped on a blow-up or max_steps (the
snapshots kept), 4 another process writes the run (nothing touched), 75
checkpoint written after SIGTERM (run again to resume).
"""
from __future__ import annotations

import argparse
import inspect
import json
import math
import os
import shutil
import signal
import sys
import time

import numpy as np

# ------------------------------------------------------------ parameters
PARAMETERS = dict(
    start="yade",                 # "yade" (a dump's isotropic snapshot, --source) or "loose" (CD compaction)
    source="",                    # the dump of start=yade
    sample="polyhedra",           # "polyhedra" (S1, POLYR) or "spheres" (S2, SPHER)
    n_particles=200,              # grains of start=loose
    seed=1,                       # sample seed of start=loose (the YADE scene's draws)
    library="",                   # shape library of start=loose (default runs/shapes/library.h5)
    initial_fraction=0.25,        # start=loose: solid fraction of the loose box
    aspect=2.0,                   # start=loose: H/L of the loose box
    sigma0=10000.0,               # Pa, confining stress
    friction=0.5,                 # grain-grain Coulomb friction (IQS_CLB)
    wall_friction=0.0,            # grain-wall friction
    density=2700.0,               # kg/m^3
    dt=1e-3,                      # s, time step (docs/front.md, "The CD time step and tolerance")
    theta=0.5,                    # theta method
    nlgs_tol=1e-3,                # NLGS tolerance (LMGC90's QM/16 norm: quadratic mean of the velocity change over the forces, /16)
    nlgs_norm="QM/16",            # LMGC90's check norm
    nlgs_relax=1.0,               # NLGS relaxation
    nlgs_check_every=10,          # NLGS iterations between convergence checks
    nlgs_max_checks=500,          # ... checks before a step is taken unconverged
    nlgs_scramble=1,              # 1: NLGS sweeps the contacts in a shuffled order between checks (LMGC90's quick scramble)
    alert_factor=0.1,             # alert distance = this x the smallest grain radius
    cundall_iterations=50,        # PRPRx common-plane (Cundall) detection iterations
    inertial_number=0.005,        # shear: I = rate d sqrt(rho / sigma0), d the grains' mean size (ignored if shear_rate or wall_speed > 0)
    shear_rate=0.0,               # 1/s, the shear's strain rate (0: from inertial_number); a YADE run's rate_shear gives both methods one rate
    wall_speed=0.0,               # m/s, top wall speed in shear (0: from inertial_number)
    wall_mass_factor=10.0,        # each wall's mass / the sample's mass
    compaction_speed=0.05,        # m/s, the pressed walls' speed cap in the isotropic stage
    iso_tolerance=0.05,           # isotropic: |mean wall stress - sigma0| < tol sigma0 on every wall ...
    iso_window=100,               # ... averaged over this many steps, and
    iso_volume_tolerance=1e-4,    # ... the box's volume changing by less than this over the window
    iso_min_steps=100,            # ... and at least this many isotropic steps
    dump_strain=0.01,             # a snapshot every delta eps_1 in shear (eps_1 = ln(H0 / H), the paper's eq. 3)
    average_steps=20,             # K: a snapshot's contact forces and wall forces are the mean over its last K steps (1: that step's)
    iso_snapshot_steps=0,         # also a snapshot every this many isotropic steps (0: none; a steadiness check)
    final_strain=0.3,             # eps_1 at the end of shear
    max_steps=0,                  # stop (a failure) after this many steps (0: no limit)
    checkpoint_seconds=300.0,     # s of wall time between checkpoints (0: only on SIGTERM)
    checkpoint_steps=0,           # ... or every this many steps (0: by time only)
    report_seconds=30.0,          # s between progress lines
    out="run.h5",                 # the dump, in FOLDER
    lmgc90_build="",              # the folder of a pylmgc90 build (default: lmgc90/_build's, make lmgc90)
)

EXIT_DONE, EXIT_CONFIG, EXIT_FAILED, EXIT_BUSY, EXIT_TERM = 0, 2, 3, 4, 75
LOG_HEADER = ("step,time,stage,Lx,Ly,Lz,s_xm,s_xp,s_ym,s_yp,s_zm,s_zp,v_xm,v_xp,v_ym,v_yp,v_zm,v_zp,"
              "nlgs_iterations,converged,interactions,seconds")


def say(message):
    """One line of the scene, ``lmgc90.triaxial: <message>``, at once."""
    print(f"lmgc90.triaxial: {message}", flush=True)


def newest_checkpoint(stem):
    """The newest complete checkpoint folder of a CD run, or None.

    Parameters
    ----------
    stem : str
        The run's dump path without ``.h5`` (``FOLDER/run``).

    Returns
    -------
    str or None
        ``STEM.ckpt``, else ``STEM.ckpt.prev`` (the one before, kept while
        a new one is written), whichever first holds its ``scene.json``;
        None when neither does.

    Examples
    --------
    >>> newest_checkpoint("/nonexistent/run") is None
    True
    """
    for path in (stem + ".ckpt", stem + ".ckpt.prev"):
        if os.path.exists(os.path.join(path, "scene.json")):
            return path
    return None


def parse(argv):
    """(folder, parameters) from the command line; a bad option is refused in
    one line (SystemExit 2)."""
    ap = argparse.ArgumentParser(prog="python -m lmgc90.triaxial", description=__doc__.split("\n")[0])
    ap.add_argument("folder")
    ap.add_argument("--start", choices=("yade", "loose"))
    ap.add_argument("--source")
    ap.add_argument("--set", action="append", default=[], metavar="NAME=VALUE")
    a = ap.parse_args(argv)
    p = dict(PARAMETERS)
    if a.start:
        p["start"] = a.start
    if a.source:
        p["source"] = os.path.abspath(a.source)
    for item in a.set:
        name, eq, text = item.partition("=")
        if not eq or name not in PARAMETERS:
            ap.error(f"--set {item}: not NAME=VALUE with NAME one of the parameters")
        kind = type(PARAMETERS[name])
        try:
            p[name] = kind(float(text)) if kind in (int, float) else text
        except ValueError:
            ap.error(f"--set {item}: {name} takes a {kind.__name__}")
    folder = os.path.abspath(a.folder)
    stem = p["out"][:-3] if p["out"].endswith(".h5") else p["out"]
    if p["start"] == "yade" and not p["source"] and newest_checkpoint(os.path.join(folder, stem)) is None:
        ap.error("--start yade needs --source DUMP (only a folder with a checkpoint resumes without one)")
    for name in ("sigma0", "dt", "nlgs_tol", "alert_factor", "wall_mass_factor", "dump_strain", "final_strain",
                 "average_steps"):
        if not p[name] > 0:
            ap.error(f"{name} must be > 0, got {p[name]}")
    for name in ("iso_snapshot_steps", "shear_rate", "wall_speed"):
        if not p[name] >= 0:
            ap.error(f"{name} must be >= 0, got {p[name]}")
    return folder, p


def main(argv=None):
    """Run the scene (``python -m lmgc90.triaxial``).

    Parameters
    ----------
    argv : list of str, optional
        The command line without the program (default ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit code (module docstring).
    """
    folder, P = parse(sys.argv[1:] if argv is None else argv)
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    sys.path.insert(0, root)
    from lmgc90.build import LMGC90BuildError, import_pylmgc90
    from postproc.schema import DumpFormatError, DumpWriter
    from yade_scripts.runs.runlock import RunBusy, RunLock, inherited, lock_path

    from lmgc90 import cdaverage, cdcontacts, cdcontrol, cdmodel, cdstart, grains
    from lmgc90.cdsystem import CDSystem

    os.makedirs(folder, exist_ok=True)
    out = os.path.join(folder, P["out"])
    stem = out[:-3] if out.endswith(".h5") else out
    ckpt, ckpt_prev = stem + ".ckpt", stem + ".ckpt.prev"
    reactions_dir = stem + ".reactions"
    # ------------------------------------------------------------ the run's only writer
    # (a launcher that holds the run's lock for it, yade_scripts.launch.pool, says so in the environment)
    if not inherited(lock_path(out)):
        lock = RunLock(lock_path(out), "lmgc90.triaxial")
        try:
            lock.acquire()
        except RunBusy as exc:
            say(f"refused: {exc}")
            return EXIT_BUSY
    info_path = stem + ".info.json"
    if os.path.exists(out) and not os.path.exists(out + ".parts"):
        say(f"{P['out']} is complete already; nothing to do (delete it to run again)")
        return EXIT_DONE
    try:
        chipy, pre = import_pylmgc90(P["lmgc90_build"] or None)
    except LMGC90BuildError as exc:
        say(f"refused: {exc}")
        return EXIT_CONFIG

    # ------------------------------------------------------------ resume, or start afresh
    resumed = newest_checkpoint(stem) if os.path.exists(out + ".parts") else None
    if resumed is None and (os.path.exists(out) or os.path.exists(out + ".parts")):
        say(f"{P['out']} exists without a usable checkpoint; delete it (and {P['out']}.parts) to start afresh")
        return EXIT_CONFIG
    if resumed:
        with open(os.path.join(resumed, "scene.json")) as fh:
            saved = json.load(fh)
        P = {"average_steps": 1, "iso_snapshot_steps": 0, "shear_rate": 0.0, **saved["parameters"]}   # the first attempt's
    # ------------------------------------------------------------ the grains
    try:
        if P["start"] == "yade":
            start = cdstart.from_dump(P["source"])
        else:
            from shapes.library import ShapeLibrary
            lib = ShapeLibrary(P["library"] or os.path.join(root, "runs", "shapes", "library.h5")) \
                if P["sample"] == "polyhedra" else None
            start = cdstart.loose(lib, P["n_particles"], P["seed"], P["initial_fraction"], P["aspect"],
                                  P["sample"])
    except (cdstart.StartError, DumpFormatError, ValueError, OSError, RuntimeError) as exc:
        say(f"invalid starting state: {exc}")
        return EXIT_CONFIG
    POLY = start.kind == "polyhedra"
    N = len(start.ids)
    sizes = start.sizes
    masses0 = P["density"] * start.volumes
    alert = P["alert_factor"] * 0.5 * float(sizes.min())
    half_thick = 0.25 * float(sizes.mean())
    wall_mass = P["wall_mass_factor"] * float(masses0.sum())
    L0 = start.hi - start.lo
    half_size = 0.75 * float(L0.max()) + float(sizes.max())
    if P["wall_speed"] > 0:
        rate_shear = None
    elif P["shear_rate"] > 0:
        rate_shear = P["shear_rate"]
    else:
        rate_shear = P["inertial_number"] / (float(sizes.mean()) * math.sqrt(P["density"] / P["sigma0"]))
    nlgs = {"norm": P["nlgs_norm"].ljust(5)[:5], "tol": P["nlgs_tol"], "relax": P["nlgs_relax"],
            "check_every": P["nlgs_check_every"], "max_checks": P["nlgs_max_checks"]}
    if not resumed:
        posed = []
        for k in range(N):
            if POLY:
                s = int(start.shape_index[k])
                posed.append({"vertices": grains.posed_vertices(start.shapes[0][s], start.orientations[k],
                                                                start.positions[k]),
                              "triangles": start.shapes[1][s]})
            else:
                posed.append({"centre": start.positions[k], "radius": 0.5 * sizes[k]})
        cdmodel.write_datbox(folder, posed, start.lo, start.hi, kind=start.kind, density=P["density"],
                             mu=P["friction"], mu_wall=P["wall_friction"], alert=alert, wall_mass=wall_mass,
                             wall_half_size=half_size, wall_half_thickness=half_thick, pre=pre)
    system = CDSystem(chipy, folder, P["dt"], P["theta"], P["cundall_iterations"], restart=resumed)
    if P["nlgs_scramble"]:
        chipy.nlgs_3D_SetWithQuickScramble()
    if system.n_bodies != N + 6:
        say(f"invalid starting state: LMGC90 read {system.n_bodies} bodies for {N} grains and 6 walls")
        return EXIT_CONFIG
    grain_rows = np.arange(N)
    wall_rows = np.arange(N, N + 6)
    dump_id = np.concatenate([start.ids, start.wall_ids])       # LMGC90 body row -> dump id
    if resumed:
        frame0 = np.load(os.path.join(resumed, "frame0.npy"))
    else:
        frame0 = system.frames(grain_rows)                      # the frames the orientations turn from
    masses = system.masses[grain_rows]

    # ------------------------------------------------------------ the dump
    params_dump = {**P, "method": "contact dynamics (LMGC90)", "alert": alert, "wall_mass": wall_mass,
                   "wall_half_thickness": half_thick, "start_from": start.source, "rate_shear": rate_shear,
                   "walls": "PLANx", "nlgs": "Stored_Delassus_Loops"}
    params_dump["wall_mass_lmgc90"] = float(system.masses[wall_rows[0]])    # kg, as LMGC90 computed it
    if not resumed:
        with open(stem + ".params.json", "w") as fh:
            json.dump(params_dump, fh, indent=1, default=float)
    if resumed:
        writer = DumpWriter.resume(out, saved["n_snapshots"])
    else:
        writer = DumpWriter(out, start.kind, params_dump, overlap_kind="depth")
        if POLY:
            writer.write_shapes(*start.shapes)

    # ------------------------------------------------------------ the loading program
    st = saved["program"] if resumed else {
        "stage": "isotropic", "eps_1": 0.0, "next_dump": P["dump_strain"], "shear_start_step": None,
        "H0": None, "v_top": None, "iso_steps": 0, "phi_iso": None, "wall_seconds": 0.0, "steps": 0,
        "nlgs_iterations": 0, "unconverged_steps": 0, "servo": []}
    window = cdcontrol.StressWindow(P["iso_window"])
    vol_window = []
    pressed_iso = [0, 1, 2, 3, 5]          # every wall but the bottom one
    pressed_shear = [0, 1, 2, 3]
    log_path = stem + ".log.csv"
    kept = [LOG_HEADER + "\n"]
    if resumed and os.path.exists(log_path):      # the rows up to the checkpoint's step
        with open(log_path) as fh:
            rows = fh.readlines()[1:]
        kept += [r for r in rows if r.split(",", 1)[0].isdigit() and int(r.split(",", 1)[0]) <= system.step_number]
    with open(log_path + ".tmp", "w") as fh:
        fh.writelines(kept)
    os.replace(log_path + ".tmp", log_path)
    log = open(log_path, "a")
    with_points = "points" in inspect.signature(DumpWriter.write_snapshot).parameters
    if not with_points:
        say("warning: this postproc.schema has no contact-point group; the dump holds the pair rows only")

    def box():
        c = system.vectors("Coor_", wall_rows)[:, :3]
        return cdcontrol.box_from_walls(c, half_thick)

    def wall_normal_velocities():
        v = system.vectors("V____", wall_rows)
        return [v[k, cdmodel.WALL_AXES[k][0]] for k in range(6)]

    def wall_forces():
        return system.vectors("Reac_", wall_rows)[:, :3]

    K = int(P.get("average_steps", 1))
    forces_window = cdaverage.ForceWindow(K)     # the last K steps' points and wall forces

    def record():
        """This step into the averaging window (after system.step)."""
        if K > 1:
            cd, an, x, uc, r, gap, _, keys = system.interactions(keys=True)
            forces_window.add(keys, cd, an, x, uc, r, gap, system.vectors("Reac_", range(N + 6))[:, :3])

    def snapshot(stage):
        lo, hi = box()
        if K > 1 and len(forces_window):       # the window's mean forces (a resumed run's first window may hold fewer steps)
            cd, an, x, uc, r, gap, reac_mean = forces_window.mean()
        else:
            cd, an, x, uc, r, gap, _ = system.interactions()
            reac_mean = system.vectors("Reac_", range(N + 6))[:, :3]
        walls_f = reac_mean[N:]
        contacts, points = cdcontacts.pairs_and_points(dump_id[cd], dump_id[an], x, uc, r, gap)
        q = grains.orientation_now(start.orientations, frame0, system.frames(grain_rows))
        bodies = {"id": start.ids, "kind": np.full(N, 1 if POLY else 0, np.int8),
                  "position": system.vectors("Coor_", grain_rows)[:, :3], "orientation": q,
                  "volume": start.volumes, "mass": masses, "shape_index": start.shape_index.astype(np.int32),
                  "size": sizes, "velocity": system.vectors("V____", grain_rows)[:, :3]}
        # LMGC90's own per-body reactions beside the dump (its RBDY3 'Reac_': force and moment,
        # grains then walls, by dump id), what the tests check the dumped contacts against
        every = np.arange(N + 6)
        os.makedirs(reactions_dir, exist_ok=True)
        tmp = os.path.join(reactions_dir, f"{writer.n_snapshots:06d}.tmp.npz")
        np.savez(tmp, step=system.step_number, ids=dump_id, reac=system.vectors("Reac_", every),
                 coor=system.vectors("Coor_", every)[:, :3], velocity=system.vectors("V____", every),
                 dt=system.dt, average_steps=K, steps_averaged=max(len(forces_window), 1),
                 reac_mean=reac_mean)
        os.replace(tmp, os.path.join(reactions_dir, f"{writer.n_snapshots:06d}.npz"))
        writer.write_snapshot(step=system.step_number, time=system.time, stage=stage, box_lo=lo, box_hi=hi,
                              wall_ids=start.wall_ids, wall_forces=walls_f, bodies=bodies,
                              contacts=contacts, **({"points": points} if with_points else {}))

    def checkpoint():
        tmp = ckpt + ".tmp"
        if os.path.exists(tmp):
            shutil.rmtree(tmp)
        system.save(tmp)
        np.save(os.path.join(tmp, "frame0.npy"), frame0)
        st["wall_seconds"] = wall_seconds()
        with open(os.path.join(tmp, "scene.json"), "w") as fh:
            json.dump({"parameters": P, "program": st, "n_snapshots": writer.n_snapshots}, fh)
        log.flush()
        if os.path.exists(ckpt):
            if os.path.exists(ckpt_prev):
                shutil.rmtree(ckpt_prev)
            os.replace(ckpt, ckpt_prev)
        os.replace(tmp, ckpt)

    t_attempt = time.perf_counter()
    earlier = st["wall_seconds"]

    def wall_seconds():
        return earlier + time.perf_counter() - t_attempt

    term = []
    signal.signal(signal.SIGTERM, lambda *a: term.append(1))
    progress_path = stem + ".progress.json"

    def progress(**fields):
        """The run's progress record (OUT.progress.json, as the YADE scene's):
        newer than the process once SIGTERM is handled, what a launcher
        waits for before it asks the run to stop (yade_scripts.launch.pool)."""
        with open(progress_path + ".tmp", "w") as fh:
            json.dump({**fields, "seconds_left": None, "time": time.time()}, fh)
        os.replace(progress_path + ".tmp", progress_path)

    progress(step=system.step_number, stage=st["stage"], eps_1=st["eps_1"])

    def fail(reason):
        say(f"STOPPED at step {system.step_number} ({st['stage']}, eps_1 = {st['eps_1']:.4f}): {reason}. "
            f"The {writer.n_snapshots} snapshot(s) written before are kept in {P['out']}.")
        log.close()
        writer.close(pack=True, complete=False)
        return EXIT_FAILED

    def set_stage_walls(stage):
        top = wall_rows[5]
        if stage == "isotropic":
            for k in pressed_iso:
                system.free_dof(wall_rows[k], cdmodel.WALL_AXES[k][0] + 1)
        else:
            system.drive_dof(top, 3, -st["v_top"])
            for k in pressed_shear:
                system.free_dof(wall_rows[k], cdmodel.WALL_AXES[k][0] + 1)

    set_stage_walls(st["stage"])
    say(f"{N} {start.kind} from {start.source}; dt = {P['dt']:g} s, alert {alert:.4g} m, "
        f"walls PLANx of {wall_mass:.4g} kg, NLGS {P['nlgs_norm']} tol {P['nlgs_tol']:g}"
        + (f"; resumed from {os.path.basename(resumed)} at step {system.step_number}" if resumed else ""))
    last_ckpt = last_report = time.perf_counter()
    rms_scale = float(sizes.mean())
    while True:
        lo, hi = box()
        L = hi - lo
        pressed = pressed_iso if st["stage"] == "isotropic" else pressed_shear
        f = cdcontrol.pressing_forces(P["sigma0"], L, pressed)
        if st["stage"] == "isotropic":      # cap the pressed walls' speed while the gas is loose
            for k in pressed:
                v = system.vectors("Vbeg_", [wall_rows[k]])[0]
                a = cdmodel.WALL_AXES[k][0]
                if abs(v[a]) > P["compaction_speed"]:
                    v[a] = math.copysign(P["compaction_speed"], v[a])
                    system.chipy.RBDY3_PutBodyVector("Vbeg_", int(wall_rows[k]) + 1, v)
        t0 = time.perf_counter()
        system.step({int(wall_rows[k]): v for k, v in f.items()}, nlgs)
        seconds = time.perf_counter() - t0
        st["steps"] += 1
        st["nlgs_iterations"] += system.iterations
        st["unconverged_steps"] += int(not system.converged)
        lo, hi = box()
        L = hi - lo
        sig = cdcontrol.wall_stresses(wall_forces(), L)
        n_inter = system.n_interactions()
        record()
        log.write(f"{system.step_number},{system.time:.9g},{st['stage']},{L[0]:.9g},{L[1]:.9g},{L[2]:.9g},"
                  + ",".join(f"{s:.9g}" for s in sig) + ","
                  + ",".join(f"{v:.9g}" for v in wall_normal_velocities())
                  + f",{system.iterations},{int(system.converged)},{n_inter},{seconds:.4f}\n")
        # ---- blow-up checks
        pos = system.vectors("Coor_", grain_rows)[:, :3]
        if not (np.all(np.isfinite(pos)) and np.all(np.isfinite(sig))):
            return fail("positions or wall reactions are NaN")
        outside = np.any((pos < lo - sizes.max()) | (pos > hi + sizes.max()), axis=1)
        if outside.any():
            return fail(f"grain {int(start.ids[np.argmax(outside)])} left the box")
        # ---- the loading program
        if st["stage"] == "isotropic":
            st["iso_steps"] += 1
            window.add(sig)
            vol_window.append(float(np.prod(L)))
            vol_window[:] = vol_window[-P["iso_window"]:]
            if P.get("iso_snapshot_steps", 0) and st["iso_steps"] % P["iso_snapshot_steps"] == 0:
                snapshot("isotropic")
            dv = (vol_window[-1] - vol_window[0]) / vol_window[-1]
            if window.full and st["iso_steps"] >= P["iso_min_steps"] and cdcontrol.isotropic_reached(
                    window.mean(), P["sigma0"], P["iso_tolerance"], dv, P["iso_volume_tolerance"]):
                phi = float(start.volumes.sum() / np.prod(L))
                say(f"isotropic state at step {system.step_number}: mean sigma/sigma0 "
                    f"{np.round(window.mean() / P['sigma0'], 3)}, solid fraction {phi:.4f}")
                snapshot("isotropic")
                forces_window.clear()           # the shear's snapshots average shear steps only
                st.update(stage="shear", shear_start_step=system.step_number, H0=float(L[2]), phi_iso=phi)
                st["v_top"] = P["wall_speed"] if P["wall_speed"] > 0 else rate_shear * float(L[2])
                writer.update_parameters(top_wall_speed=st["v_top"], solid_fraction_isotropic=phi,
                                         box_isotropic=L.tolist())
                set_stage_walls("shear")
                say(f"shear: top wall at {st['v_top']:.4g} m/s")
        else:
            st["eps_1"] = math.log(st["H0"] / float(L[2]))     # the paper's eq. 3, as the YADE scene and postproc.strain
            st["servo"].append([float(s) for s in sig[:4]])
            st["servo"] = st["servo"][-1000:]
            if st["eps_1"] >= st["next_dump"] - 1e-12:
                snapshot("shear")
                st["next_dump"] += P["dump_strain"]
            if st["eps_1"] >= P["final_strain"]:
                st["stage"] = "done"
        if P["max_steps"] and st["steps"] >= P["max_steps"] and st["stage"] != "done":
            return fail(f"max_steps = {P['max_steps']} reached before the end")
        now = time.perf_counter()
        if st["stage"] == "done":
            break
        if term or (P["checkpoint_seconds"] > 0 and now - last_ckpt > P["checkpoint_seconds"]) or \
                (P["checkpoint_steps"] and st["steps"] % P["checkpoint_steps"] == 0):
            checkpoint()
            last_ckpt = now
            if term:
                say(f"stopped on SIGTERM at step {system.step_number}; the checkpoint and the "
                    f"{writer.n_snapshots} snapshot(s) are kept: run again in this folder to resume (exit {EXIT_TERM})")
                log.close()
                return EXIT_TERM
        if now - last_report > P["report_seconds"]:
            last_report = now
            progress(step=system.step_number, stage=st["stage"], eps_1=st["eps_1"])
            where = (f"eps_1 {st['eps_1']:.4f}, sigma_lat/sigma0 {np.round(sig[:4] / P['sigma0'], 3)}, "
                     f"sigma_top/sigma0 {sig[5] / P['sigma0']:.3f}") if st["stage"] == "shear" else \
                f"sigma/sigma0 {np.round(sig / P['sigma0'], 3)}"
            say(f"step {system.step_number} {st['stage']}: {where}, {n_inter} interactions, "
                f"{system.iterations} NLGS iterations, {seconds:.3f} s/step")
    log.close()
    writer.close(pack=True)
    info = {"steps": system.step_number, "time": system.time, "wall_seconds": wall_seconds(),
            "solid_fraction_isotropic": st["phi_iso"], "snapshots": writer.n_snapshots,
            "shear_start_step": st["shear_start_step"], "top_wall_speed": st["v_top"],
            "nlgs_iterations_per_step": st["nlgs_iterations"] / max(st["steps"], 1),
            "unconverged_steps": st["unconverged_steps"], "steps_run": st["steps"]}
    with open(info_path, "w") as fh:
        json.dump(info, fh, indent=1)
    for c in (ckpt, ckpt_prev, progress_path):
        if os.path.isdir(c):
            shutil.rmtree(c)
        elif os.path.exists(c):
            os.remove(c)
    say(f"done: {system.step_number} steps, dump {P['out']}")
    return EXIT_DONE


if __name__ == "__main__":
    sys.exit(main())
