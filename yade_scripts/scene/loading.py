"""The loading program of the triaxial test (numpy only): isotropic
compression to sigma0 by the wall servo, then shear with the top wall at
constant speed and the lateral walls at sigma0; when to take snapshots and
when to stop.

The scene (``triaxial.py``) measures the box and the wall forces each step
and applies what :class:`TriaxialLoading` returns; everything the program
remembers between steps is in the object, and :meth:`TriaxialLoading.saved`
/ :meth:`TriaxialLoading.restore` carry it through a checkpoint. Stresses
are compression positive (Pa), strains are logarithmic and compression
positive, ``L`` is the (3,) box size in m, walls in the dump schema's order
x-, x+, y-, y+, z-, z+.
"""
from __future__ import annotations

import numpy as np

from . import servo

#: the compaction tests for the isotropic state every this many steps (the
#: unbalanced force costs a pass over the contacts)
ISO_CHECK_EVERY = 50
#: the program's state carried by a checkpoint
SAVED_KEYS = ("stage", "H0", "L0", "eps_1", "next_dump", "phi_iso", "integral", "v_top", "contact_steps",
              "interaction_steps", "shear_start_step", "shear_start_wall", "approached")
#: the compaction's approach (faster by ``approach_factor``) ends when the
#: mean wall stress first reaches this fraction of sigma0
APPROACH_STRESS = 0.5
LOG_HEADER = ("step,time,stage,eps_1,eps_2,eps_3,eps_v,s_xx,s_yy,s_zz,q_over_p,phi,unbalanced,n_interactions,"
              "n_contacts,steps_per_s\n")


class TriaxialLoading:
    """Stage ``compaction``, then ``shear``, then ``done``.

    sigma0 (Pa) target stress; rate_compaction, rate_shear (1/s) the
    compaction's fastest wall strain rate and the shear strain rate;
    approach_factor (>= 1) how much faster the compaction runs until the
    mean wall stress first reaches APPROACH_STRESS x sigma0 (the loose
    granular gas and its first contacts, far from the isotropic state);
    wall_speed (m/s) the top wall's speed in shear (0: rate_shear times the
    height at the isotropic state); servo_gain, servo_time, kappa and dt as
    in :func:`servo.servo_rates` and :meth:`stable_gain`; compaction_gain
    the servo gain of the compaction (0: servo_gain); iso_tolerance and
    unbalanced_tolerance define the isotropic state; dump_strain and
    final_strain the snapshots in shear (every dump_strain of eps_1) and the
    end."""

    def __init__(self, sigma0, rate_compaction, rate_shear, wall_speed, servo_gain, servo_time, kappa, dt,
                 iso_tolerance, unbalanced_tolerance, dump_strain, final_strain, approach_factor=1.0,
                 compaction_gain=0.0):
        self.sigma0, self.rate_compaction, self.rate_shear = sigma0, rate_compaction, rate_shear
        self.wall_speed, self.servo_gain, self.servo_time = wall_speed, servo_gain, servo_time
        self.kappa, self.dt = kappa, dt
        self.iso_tolerance, self.unbalanced_tolerance = iso_tolerance, unbalanced_tolerance
        self.dump_strain, self.final_strain = dump_strain, final_strain
        self.stage, self.H0, self.L0, self.eps_1, self.next_dump = "compaction", None, None, 0.0, 0.0
        self.phi_iso, self.integral, self.v_top = None, np.zeros(3), None
        self.contact_steps = self.interaction_steps = 0
        self.shear_start_step = self.shear_start_wall = None
        self.approach_factor, self.approached = approach_factor, approach_factor <= 1.0
        self.compaction_gain = compaction_gain if compaction_gain > 0 else servo_gain

    def stable_gain(self, max_rate, gain=None):
        """The servo gain (``gain``, default servo_gain), lowered if needed
        so that one step changes the wall stress by at most 20 % of the
        error: kappa * max_rate * gain * dt <= 0.2 (gain 20 at kappa *
        max_rate * dt = 0.02 oscillated here)."""
        return min(self.servo_gain if gain is None else gain, 0.2 / (self.kappa * max_rate * self.dt))

    # ------------------------------------------------------------ compaction
    def compaction_velocities(self, sig, L):
        """(6, 3) m/s wall velocities that bring the (3,) wall stresses
        ``sig`` to sigma0 on all three axes (updates the servo's integral).
        The fastest rate is approach_factor x rate_compaction until the
        mean stress first reaches APPROACH_STRESS x sigma0, rate_compaction
        from then on."""
        if not self.approached and np.mean(sig) >= APPROACH_STRESS * self.sigma0:
            self.approached = True
        rate = self.rate_compaction * (1.0 if self.approached else self.approach_factor)
        rates = servo.servo_rates(sig, self.sigma0, rate, self.stable_gain(rate, self.compaction_gain),
                                  self.integral, self.dt, self.servo_time / self.rate_compaction)
        return servo.wall_velocities(rates, L)

    def isotropic(self, step, sig, unbalanced):
        """True when the isotropic state is reached at ``step``: every
        ISO_CHECK_EVERY steps, all wall stresses within iso_tolerance of
        sigma0 and then ``unbalanced()`` (a callable: it costs a pass over
        the contacts) below unbalanced_tolerance."""
        return (step % ISO_CHECK_EVERY == 0 and bool(np.all(np.abs(sig - self.sigma0) < self.iso_tolerance * self.sigma0))
                and unbalanced() < self.unbalanced_tolerance)

    def start_shear(self, L, phi, step, wall_seconds):
        """Switch to shear from the box ``L`` (m) with solid fraction
        ``phi``: the strains count from here, the first shear snapshot is at
        eps_1 = dump_strain, the servo's integral restarts, and the top wall
        speed is fixed (returned, m/s)."""
        self.phi_iso = phi
        self.stage, self.H0, self.L0, self.next_dump = "shear", L[2], L.copy(), self.dump_strain
        self.integral = np.zeros(3)
        self.shear_start_step, self.shear_start_wall = step, wall_seconds
        self.v_top = self.wall_speed if self.wall_speed > 0 else self.rate_shear * L[2]
        return self.v_top

    # ------------------------------------------------------------ shear
    def strains(self, L):
        """(3,) logarithmic strains ln(L0 / L) since the isotropic state
        (zeros before it): the paper's cumulative strains, e.g. eps_1 =
        integral from H0 to H of dH'/H' (Azema, Radjai & Saussine 2009,
        "Shear strength"), with the sign turned so that compression is
        positive."""
        return np.log(self.L0 / L) if self.H0 else np.zeros(3)

    def shear_velocities(self, sig, L):
        """(6, 3) m/s: the lateral walls hold sigma0, the bottom wall is
        fixed, the top wall moves down at v_top. Updates eps_1."""
        eps = np.log(self.L0 / L)
        self.eps_1 = eps[2]
        rate_1 = self.v_top / L[2]
        rates = servo.servo_rates(sig, self.sigma0, 2 * rate_1, self.stable_gain(2 * rate_1), self.integral,
                                  self.dt, self.servo_time / rate_1)
        vel = servo.wall_velocities(rates, L)
        vel[4] = 0.0                              # bottom wall fixed
        vel[5] = (0.0, 0.0, -self.v_top)          # top wall at constant speed
        return vel

    def snapshot_due(self):
        """True when eps_1 has reached the next snapshot (or the end);
        the next one is then dump_strain further on."""
        if self.eps_1 >= self.next_dump - 1e-12 or self.eps_1 >= self.final_strain:
            self.next_dump += self.dump_strain
            return True
        return False

    def finished(self):
        """True (and stage ``done``) once eps_1 reaches final_strain."""
        if self.eps_1 >= self.final_strain:
            self.stage = "done"
        return self.stage == "done"

    def seconds_left(self, L, steps_per_second):
        """Wall-clock seconds left in shear at this speed (s)."""
        return (self.final_strain - self.eps_1) * L[2] / self.v_top / self.dt / max(steps_per_second, 1e-9)

    # ------------------------------------------------------------ bookkeeping
    def count(self, n_interactions, n_contacts, steps):
        """Add ``steps`` steps of these counts to the cost totals."""
        self.contact_steps += n_contacts * steps
        self.interaction_steps += n_interactions * steps

    def log_row(self, step, time, sig, L, phi, unbalanced, n_interactions, n_contacts, steps_per_second):
        """One row of OUT.log.csv (columns :data:`LOG_HEADER`). Its
        ``q_over_p`` is the walls': (s1 - s3) / (s1 + 2 s3) with s1 the
        axial (z) wall stress and s3 the mean of the lateral ones, i.e. the
        paper's q = (sigma1 - sigma3) / 3 over p = (sigma1 + 2 sigma3) / 3
        (Azema, Radjai & Saussine 2009, "Shear strength"); NaN before any
        wall is touched."""
        eps = self.strains(L)
        s1, s3 = sig[2], 0.5 * (sig[0] + sig[1])
        qp = (s1 - s3) / (s1 + 2 * s3) if s1 + 2 * s3 != 0 else float("nan")     # no wall touched yet
        return (f"{step},{time:.6g},{self.stage},{eps[2]:.6g},{eps[0]:.6g},{eps[1]:.6g},{eps.sum():.6g},"
                f"{sig[0]:.6g},{sig[1]:.6g},{sig[2]:.6g},{qp:.6g},"
                f"{phi:.6g},{unbalanced:.4g},{n_interactions},{n_contacts},{steps_per_second:.4g}\n")

    def saved(self):
        """The program's state as JSON-able values (for a checkpoint)."""
        return {k: (v.tolist() if isinstance(v, np.ndarray) else (float(v) if isinstance(v, np.floating) else v))
                for k, v in vars(self).items() if k in SAVED_KEYS}

    def restore(self, saved):
        """Back to the state :meth:`saved` returned."""
        for k in SAVED_KEYS:
            if k in saved:
                v = saved[k]
                setattr(self, k, np.array(v, float) if k in ("L0", "integral") and v is not None else v)
