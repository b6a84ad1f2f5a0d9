"""The controller of the triaxial scene: what the scene's ``PyRunner`` does
every step, and the end of the run, with all the state it keeps between
steps in one object (YADE's Python only; YADE's objects are passed in).

Each step (:meth:`TriaxialController.step`) it measures the box and the
wall forces, applies the loading program's wall velocities
(:class:`yade_scripts.scene.loading.TriaxialLoading`: compaction to the
isotropic state, its snapshot and the switch to shear; then shear, its
snapshots and the end), writes a log row every ``log_every`` steps, checks
for a blow-up and ``max_steps`` every ``check_every`` steps and prints a
progress line every ``report_seconds``. A checkpoint keeps what
:meth:`TriaxialController.scene_state` returns beside YADE's scene;
:meth:`TriaxialController.finish` closes the dump and writes
``OUT.info.json``. Stresses are compression positive (Pa), walls in the
dump's order x-, x+, y-, y+, z-, z+.
"""
from __future__ import annotations

import json
import math
import time

import numpy as np

from postproc.schema import DumpFormatError

from ..runs import host
from ..runs.attempt import leave
from ..runs.runstate import EXIT_FAILED, EXIT_TERM
from . import servo, yadedump
from .kernel_contacts import KernelError


class TriaxialController:
    """The scene's controller and its state.

    Parameters
    ----------
    O : yade.wrapper.Omega
        YADE's scene.
    run : yade_scripts.runs.attempt.Attempt
        This attempt at the run (checkpoints, the end of a step, failure).
    program : yade_scripts.scene.loading.TriaxialLoading
        The loading program.
    progress : yade_scripts.runs.attempt.Progress
        The progress lines' clock.
    writer : postproc.schema.DumpWriter
        The dump.
    log_file : file
        OUT.log.csv, open for appending.
    walls : list of int
        The six walls' body ids, x-, x+, y-, y+, z-, z+.
    particles : numpy.ndarray
        (n,) int, the particles' body ids.
    d : numpy.ndarray
        (n,) m, their sizes.
    particle_volumes : numpy.ndarray
        (n,) m^3, their volumes (as the first attempt measured them).
    params : dict
        The scene's parameters (those of
        :mod:`yade_scripts.scene.parameters`: ``sigma0``, ``friction``,
        ``log_every`` ...).
    box0 : numpy.ndarray
        (3,) m, the initial box.
    newton : yade.wrapper.NewtonIntegrator
        The scene's integrator (its damping changes at the start of shear).
    kernel : yade_scripts.scene.kernel_contacts.KernelContacts, optional
        The compiled kernel, when it gives the polyhedra's contacts.
    tangential_law : yade_scripts.scene.tangential.TangentialLaw, optional
        The polyhedra's tangential law on YADE's own contact path.
    say : callable
        Prints one line of the scene.

    Attributes
    ----------
    wall_states : list
        The walls' YADE states (taken again after a checkpoint's O.load).
    masses : numpy.ndarray
        (n,) kg, the particles' masses.
    dump_seconds : float
        s of wall time of the snapshots (gathering and writing).
    poly : bool
        True for polyhedra (S1).
    volume_particles : float
        m^3, the particles' total volume.
    """

    def __init__(self, O, run, program, progress, writer, log_file, walls, particles, d, particle_volumes, params,
                 box0, newton, kernel=None, tangential_law=None, say=print):
        from yade import utils

        self.O, self.run, self.program, self.progress = O, run, program, progress
        self.writer, self.log_file, self.walls, self.particles = writer, log_file, walls, particles
        self.d, self.particle_volumes, self.p, self.box0 = d, particle_volumes, params, box0
        self.newton, self.kernel, self.say, self._utils = newton, kernel, say, utils
        self.poly = params["sample"] == "polyhedra"
        self.particle_list = particles.tolist()
        self.masses = np.array([O.bodies[i].state.mass for i in self.particle_list])   # kg, as every checkpoint keeps them
        self.shape_index = np.arange(len(particles)) if self.poly else np.full(len(particles), -1)
        self.volume_particles = float(sum(particle_volumes))
        self.wall_states = [O.bodies[w].state for w in walls]
        self.dump_seconds = 0.0
        self.tangential_law = tangential_law

    # ------------------------------------------------------------ the box and its walls
    def box(self):
        """The box from the wall positions.

        Returns
        -------
        tuple of numpy.ndarray
            (lo, hi), each (3,) m.
        """
        p = [s.pos for s in self.wall_states]
        return (np.array([p[0][0], p[2][1], p[4][2]]), np.array([p[1][0], p[3][1], p[5][2]]))

    def wall_forces(self):
        """The force on each wall by the particles this step.

        Returns
        -------
        numpy.ndarray
            (6, 3) N, walls in the dump's order.
        """
        f = self.O.forces.f
        return np.array([f(w).__getinitargs__() for w in self.walls])

    def set_wall_velocities(self, vel):
        """Give the six walls their velocities.

        Parameters
        ----------
        vel : numpy.ndarray
            (6, 3) m/s, in the dump's wall order
            (:func:`yade_scripts.scene.servo.wall_velocities`).

        Returns
        -------
        None
        """
        for s, v in zip(self.wall_states, vel.tolist()):
            s.vel = v

    def set_friction(self, mu):
        """Particle-particle friction from now on (the walls keep
        ``wall_friction``): the grain material (O.materials[0]) for new
        contacts, and every touching particle pair (the kernel's
        coefficient, or the YADE interactions' Coulomb cap).

        Parameters
        ----------
        mu : float
            The friction coefficient.

        Returns
        -------
        None
        """
        O = self.O
        O.materials[0].frictionAngle = math.atan(mu)
        if self.kernel is not None:
            self.kernel.engine.set_friction(mu, self.p["wall_friction"])
            return
        wall_set = set(self.walls)
        for i in O.interactions:
            if i.isReal and i.id1 not in wall_set and i.id2 not in wall_set:
                i.phys.tangensOfFrictionAngle = mu

    # ------------------------------------------------------------ the kernel's engines
    def kernel_step(self):
        """One kernel step (the kernel's ``PyRunner``); a refused step (NaN
        positions) stops the run cleanly.

        Returns
        -------
        None
        """
        try:
            self.kernel()
        except KernelError as exc:
            self.fail(f"contact kernel: {exc}")

    def kernel_check(self):
        """The plugin's first step of this attempt, checked against YADE's
        Python (a one-shot engine right after it); a refusal falls back to
        the PyRunner.

        Returns
        -------
        None
        """
        refused = self.kernel.verify()
        if refused:
            self.say(f"warning: the kernel plugin was refused at step {self.O.iter}: {refused}; "
                     "the step was redone and the run goes on with the PyRunner")

    def unbalanced(self):
        """YADE's unbalanced-force ratio (from the kernel's sums with the
        kernel, which leaves YADE no interactions to average over).

        Returns
        -------
        float
        """
        return self.kernel.unbalanced() if self.kernel is not None else self._utils.unbalancedForce()

    def counts(self):
        """The scene's pair counts now.

        Returns
        -------
        tuple of int
            (interactions or the kernel's neighbour pairs, touching contacts).
        """
        if self.kernel is not None:
            return self.kernel.n_pairs, self.kernel.n_contacts
        return len(self.O.interactions), self.O.interactions.countReal()

    # ------------------------------------------------------------ snapshots, failures, progress
    def snapshot(self, stage):
        """Append a snapshot of the box, the wall forces, the particles and
        every contact to the dump; its time goes to :attr:`dump_seconds`.

        Parameters
        ----------
        stage : {"isotropic", "shear"}
            The snapshot's stage.

        Returns
        -------
        None
        """
        O = self.O
        t0 = time.perf_counter()
        lo, hi = self.box()
        self.writer.write_snapshot(
            step=O.iter, time=O.time, stage=stage, box_lo=lo, box_hi=hi, wall_ids=self.walls,
            wall_forces=self.wall_forces(),
            bodies=yadedump.gather_bodies(O, self.particles, 1 if self.poly else 0, self.shape_index, self.d,
                                          self.particle_volumes),
            contacts=self.kernel.contacts() if self.kernel is not None else yadedump.gather_contacts(O, self.poly))
        self.dump_seconds += time.perf_counter() - t0

    def fail(self, reason):
        """Stop on a blow-up: say why, keep every snapshot written so far.

        Parameters
        ----------
        reason : str
            Why (one line).

        Returns
        -------
        None
        """
        program = self.program
        self.say(f"STOPPED at step {self.O.iter} ({program.stage}, eps_1 = {program.eps_1:.4f}): {reason}. "
                 f"The {self.writer.n_snapshots} snapshot(s) written before are kept in {self.p['out']}.")
        self.run.fail(reason)

    def check_blowup(self, lo, hi, F):
        """Whether the run has blown up: NaN, a particle out of the box, or
        a runaway kinetic energy (an rms speed over 50 times the fastest
        wall speed of the run, and over 0.05 m/s).

        Parameters
        ----------
        lo, hi : numpy.ndarray
            (3,) m, the box.
        F : numpy.ndarray
            (6, 3) N, the wall forces.

        Returns
        -------
        str or None
            Why, or None.
        """
        if not np.all(np.isfinite(F)):
            return "wall forces are NaN"
        O, d = self.O, self.d
        states = [O.bodies[i].state for i in self.particle_list]
        pos = np.array([s.pos.__getinitargs__() for s in states])
        vel = np.array([s.vel.__getinitargs__() for s in states])
        if not (np.all(np.isfinite(pos)) and np.all(np.isfinite(vel))):
            return "particle positions or velocities are NaN"
        out_of_box = np.any((pos < lo - d.max()) | (pos > hi + d.max()), axis=1)
        if out_of_box.any():
            return f"particle {int(self.particles[np.argmax(out_of_box)])} left the box"
        m = self.masses
        v_rms = math.sqrt(np.sum(m * np.sum(vel ** 2, axis=1)) / m.sum())
        program = self.program
        v_ref = max(self.p["approach_factor"] * program.rate_compaction, program.rate_shear) * self.box0.max()
        if v_rms > 50 * v_ref and v_rms > 0.05:
            return f"runaway kinetic energy (rms speed {v_rms:.3g} m/s, 50 x the wall speed is {50 * v_ref:.3g})"
        return None

    def report(self, sig, L):
        """A progress line every ``report_seconds`` of wall time, and the
        run's progress record.

        Parameters
        ----------
        sig : numpy.ndarray
            (3,) Pa, the wall stresses.
        L : numpy.ndarray
            (3,) m, the box.

        Returns
        -------
        None
        """
        O, program = self.O, self.program
        sps = self.progress.tick(O.iter)
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
            where = f"sigma/sigma0 {np.round(sig / self.p['sigma0'], 3)}"
            eta = "time left known once shear starts"
        self.say(f"step {O.iter} {program.stage}: {where}, {self.counts()[0]} interactions, {sps:.0f} steps/s, {eta}")
        self.run.progress(step=O.iter, stage=program.stage, eps_1=float(program.eps_1), steps_per_second=sps,
                          seconds_left=None if left is None else float(left))

    # ------------------------------------------------------------ every step
    def step(self):
        """The controller's step, run by a ``PyRunner`` every step: first a
        due checkpoint may end the run after this step
        (:meth:`yade_scripts.runs.attempt.Attempt.end_of_step`) and, on the
        plugin path, an error of the kernel's step stops the run; then the
        loading program, the log row, the checks and the progress line (the
        module docstring).

        Returns
        -------
        None
        """
        O, p, program, kernel = self.O, self.p, self.program, self.kernel
        self.run.end_of_step()
        if kernel is not None and kernel.path == "plugin":
            problem = kernel.step_error()
            if problem:
                self.fail(f"contact kernel: {problem}")
                return
        lo, hi = self.box()
        L = hi - lo
        F = self.wall_forces()
        sig = servo.wall_stresses(F, L)
        if program.stage == "compaction":
            self.set_wall_velocities(program.compaction_velocities(sig, L))
            if program.isotropic(O.iter, sig, self.unbalanced):
                self.start_shear(sig, L)
        else:
            self.set_wall_velocities(program.shear_velocities(sig, L))
            if program.snapshot_due():
                self.snapshot("shear")
            if program.finished():
                O.pause()
                return
        if O.iter % p["log_every"] == 0:
            n_inter, n_real = self.counts()
            program.count(n_inter, n_real, p["log_every"])
            self.log_file.write(program.log_row(O.iter, O.time, sig, L, self.volume_particles / np.prod(L),
                                                self.unbalanced(), n_inter, n_real, self.progress.steps_per_second))
            self.log_file.flush()
        if O.iter % p["check_every"] == 0:
            problem = self.check_blowup(lo, hi, F)
            if problem:
                self.fail(problem)
                return
            if p["max_steps"] and O.iter >= p["max_steps"]:
                self.fail(f"max_steps = {p['max_steps']} reached before the end")
                return
        self.report(sig, L)

    def start_shear(self, sig, L):
        """The isotropic state is reached: its snapshot, then shear (the
        shear's damping and friction, the top wall's speed in the dump).

        Parameters
        ----------
        sig : numpy.ndarray
            (3,) Pa, the wall stresses.
        L : numpy.ndarray
            (3,) m, the box.

        Returns
        -------
        None
        """
        O, p, program = self.O, self.p, self.program
        phi = self.volume_particles / np.prod(L)
        self.say(f"isotropic state at step {O.iter}: sigma/sigma0 = {np.round(sig / p['sigma0'], 4)}, "
                 f"solid fraction {phi:.4f}, unbalanced force {self.unbalanced():.2e}")
        self.snapshot("isotropic")
        v_top = program.start_shear(L, phi, O.iter, self.run.wall_seconds())
        self.newton.damping = p["damping"]
        if p["compaction_friction"] != p["friction"]:
            self.set_friction(p["friction"])
            self.say(f"friction {p['compaction_friction']:g} -> {p['friction']:g} for shear")
        self.writer.update_parameters(top_wall_speed=v_top, solid_fraction_isotropic=phi, box_isotropic=L.tolist())
        self.say(f"shear: top wall at {v_top:.4g} m/s")

    # ------------------------------------------------------------ checkpoints
    def scene_state(self):
        """What a checkpoint keeps beside YADE's scene (taken between two
        steps: YADE's scene goes through O.save, with the bodies' masses,
        poses and velocities, the interactions' histories, materials,
        engines, iteration and time).

        Returns
        -------
        tuple
            (JSON-able dict, {name: numpy.ndarray}): the loading program,
            the friction now, the dump's seconds; the particles' volumes
            and the kernel's state, or the tangential law's history.
        """
        state = {"state": self.program.saved(), "friction": math.tan(self.O.materials[0].frictionAngle),
                 "dump_seconds": self.dump_seconds}
        arrays = {"particle_volumes": self.particle_volumes}
        if self.kernel is not None:
            arrays.update({f"kernel/{k}": v for k, v in self.kernel.engine.state().items()})
            state["kernel_counters"] = self.kernel.counters()
        elif self.poly:
            law = self.tangential_law
            keys = list(law.history)
            arrays["tangential_ids"] = np.array(keys, np.int64).reshape(-1, 2)
            arrays["tangential_force"] = np.array([law.history[k] for k in keys], float).reshape(-1, 3)
        return state, arrays

    def set_scene_state(self, state, arrays):
        """Put back what :meth:`scene_state` kept (YADE's scene is loaded
        already). YADE re-initialises Polyhedra shapes on O.load; the
        kernel's grains come from the library, the same on every attempt.

        Parameters
        ----------
        state : dict
            The checkpoint's metadata.
        arrays : dict
            Its arrays.

        Returns
        -------
        None
        """
        O = self.O
        self.wall_states[:] = [O.bodies[w].state for w in self.walls]
        self.dump_seconds = float(state.get("dump_seconds", 0.0))     # checkpoints of older code lack it
        self.program.restore(state["state"])
        self.progress.restart(O.iter)
        if self.kernel is not None:
            kernel = self.kernel
            kernel.rebind()
            kernel.engine.set_state({k[len("kernel/"):]: v for k, v in arrays.items() if k.startswith("kernel/")})
            kernel.set_counters(state["kernel_counters"])
            kernel.install("kernel_step()", "kernel_check()", self.p["kernel_plugin"])   # the loaded scene holds the PyRunner form
        elif self.poly:
            self.tangential_law.history = {(int(a), int(b)): tuple(f) for (a, b), f in
                                           zip(arrays["tangential_ids"].tolist(), arrays["tangential_force"].tolist())}

    def stage_and_strain(self):
        """The stage and strain now, for the checkpoint lines.

        Returns
        -------
        tuple
            (stage, eps_1).
        """
        return self.program.stage, self.program.eps_1

    # ------------------------------------------------------------ the end
    def finish(self, outcome, derived, scratch):
        """End the attempt after YADE's loop: say how it stopped, close the
        dump (packed; incomplete after a failure) and, for a finished run,
        write OUT.info.json; then leave the process
        (:func:`yade_scripts.runs.attempt.leave`) with the run's exit code.

        Parameters
        ----------
        outcome : str
            :meth:`yade_scripts.runs.attempt.Attempt.loop`'s outcome.
        derived : dict
            The derived quantities the dump records (time step, rates ...),
            copied into OUT.info.json.
        scratch : str or None
            YADE's scratch folder, recorded.

        Returns
        -------
        None
            It does not return: the process ends (exit 0 done, 3 failed,
            75 stopped and resumable).
        """
        O, run, writer, program, kernel, say = self.O, self.run, self.writer, self.program, self.kernel, self.say
        if outcome == "stalled":
            self.fail("an exception in the scene's own engines stopped the simulation (its traceback is above)")
        self.log_file.close()
        if outcome == "paused":
            say(f"paused from outside at step {O.iter} (a stop the scene did not ask for); the checkpoint and the "
                f"{writer.n_snapshots} snapshot(s) are kept: run again in this folder to resume (exit {EXIT_TERM})")
            leave(EXIT_TERM)
        if outcome == "terminated":
            say(f"stopped on SIGTERM at step {O.iter}; the checkpoint and the {writer.n_snapshots} snapshot(s) are "
                f"kept: run again in this folder to resume (exit {EXIT_TERM})")
            leave(EXIT_TERM)
        try:                          # packing checks every snapshot against what was recorded when it was written
            if run.failed:
                writer.close(pack=True, complete=False)
                run.finish()          # a blow-up replays identically from a checkpoint: nothing to resume
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
                "engine_seconds": history["engine_seconds"], "dump_seconds": self.dump_seconds,
                "resumes": history["resumes"], **derived, "host": host.host_info(), "yade_scratch": scratch}
        if kernel is not None:   # the kernel's own split and exact touching contact-steps
            info["kernel"] = {**kernel.timing(), "touch_steps": kernel.touch_steps, "threads": kernel.threads,
                              "memory_bytes": kernel.memory_bytes(), "path": kernel.path, "path_note": kernel.path_note}
        with open(run.files.info, "w") as fh:
            json.dump(info, fh, indent=1)
        say(f"done in {run.wall_seconds() - run.earlier_wall_seconds:.0f} s, {O.iter} steps; dump {self.p['out']}")
        leave(0)                      # all written: out without YADE's static destructors (runs.attempt.leave)
