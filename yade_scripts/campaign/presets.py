"""Presets of the triaxial scene: named parameter sets per sample.

``tiny``     the test suite: a few dozen particles, a few percent of strain,
             well under 3 minutes per sample on this machine.
``default``  the main job of ``make study`` (docs/scenes.md gives its cost,
             docs/measurements.md how it was chosen): 1000 grains per sample at kappa = 3000,
             I = 5e-3, prepared toward the published solid fraction of about
             0.6 with the interparticle friction of the compaction
             (``compaction_friction``: 0.5 for polyhedra, which reach about
             0.57, 0 for spheres, about 0.60); friction 0.5 for both in
             shear; the spheres are sheared at the paper's I = 1e-3 (their
             q/p is rate-sensitive, and they are cheap). The compaction starts from the grains placed with their
             exact shapes at a solid fraction of 0.25 (``placement``) and
             runs at I_c = 0.1: a third of the steps of the bounding-sphere
             start (docs/scenes.md, "Preparation"). The polyhedra step at
             0.45 of the critical time step (``safety``, the parameter's
             default): 2/3 of the steps of 0.3, with no change the time-step
             sweep could tell from chance (docs/front.md, "The time step",
             and docs/measurements.md);
             the spheres, cheap and not swept, keep 0.3 in every preset.
``soft``     the earlier default: kappa = 300, I = 2e-2, bounding-sphere
             placement, I_c = 5e-2, time step 0.3 of the critical one (ten
             times softer and four times faster than the default; the front
             of docs/front.md was measured on it).
``matched``  the default with the polyhedra compacted at friction 0.58: the
             solid fraction of the earlier bounding-sphere start (about
             0.562, within 0.005 on 3 seeds) in under a third of its steps
             (docs/scenes.md, "Preparation"); the default keeps 0.5, whose
             denser state (about 0.572) is nearer the paper's 0.6.
``loose``    the default with both samples compacted at friction 0.5.
``dense``    the default with both samples compacted frictionless.
``small``    the default with 200 polyhedra and 200 spheres: the small end
             of the size front (``make size-front``).
``intermediate``  the default with 5000 polyhedra and 5000 spheres (the
             same kappa, I and preparation; S2 at the same N as S1, so the
             two samples compare as at 1000; the spheres' compaction servo at
             gain 0.2, ``compaction_gain``, as the default's oscillated in
             their taller box): the large end of the size
             front, e.g. ``make study PRESET=intermediate`` (3 + 3 seeds on
             2 cores) or ``ENSEMBLE=16 JOBS=16`` on one 16-core node
             (yade_scripts.launch.slurm.estimate gives the core-hours).
``paper``    the published samples (36 933 polyhedra, 19 998 spheres) at
             kappa = 1e4, I = 1e-3, I_c = 1e-2, prepared like the default
             (polyhedra compacted at 0.5, spheres frictionless, with the
             intermediate preset's compaction gain 0.2), the
             polyhedra's time step at 0.45 of the critical one as in the
             default, for a cluster (a SLURM array: generate --slurm); not
             run here.

Every key is a parameter of :mod:`yade_scripts.scene.parameters` (names, types,
ranges, units, defaults); a preset lists only what it changes from the
defaults, which are the default preset's polyhedra sample.
"""
from __future__ import annotations

from ..scene.parameters import SAMPLES, ConfigError, check

# What a sample changes from the parameter table's defaults (those of the
# default preset's polyhedra) before any preset: the spheres step at 0.3 of
# the critical time step (cheap, and not swept); the polyhedra at the
# parameter's 0.45, but in ``tiny`` and ``soft``, whose common part sets 0.3.
SAMPLE_DEFAULTS = {"polyhedra": {}, "spheres": {"safety": 0.3}}

PRESETS = {
    "tiny": {
        "common": {"safety": 0.3, "kappa": 150.0, "inertial_number": 1e-2, "compaction_inertial_number": 1e-1,
                   "compaction_friction": 0.0, "initial_fraction": 0.3, "dump_strain": 0.01,
                   "final_strain": 0.02, "unbalanced_tolerance": 0.05, "iso_tolerance": 0.02,
                   "log_every": 50, "check_every": 50, "compaction_damping": 0.5, "servo_time": 0.003},
        "polyhedra": {"n_particles": 20, "initial_fraction": 0.12},
        "spheres": {"n_particles": 40},
    },
    # toward the published solid fraction of about 0.6: polyhedra compacted
    # with mu = 0.5 (about 0.57 from the grains placed with their exact
    # shapes; frictionless they reach about 0.71), spheres frictionless
    # (about 0.60)
    "default": {
        "common": {},
        "polyhedra": {},
        # spheres sheared at the paper's I = 1e-3: their q/p carries a rate
        # bias that falls only as sqrt(I) (docs/front.md: +0.074 at 2e-2, so
        # about +0.017 at 1e-3, inside the seed noise); S1's is within its
        # noise at the common I = 5e-3. Spheres are cheap, so this costs minutes.
        "spheres": {"compaction_friction": 0.0, "inertial_number": 1e-3},
    },
    "soft": {
        "common": {"safety": 0.3, "kappa": 300.0, "inertial_number": 2e-2, "placement": "spheres",
                   "compaction_inertial_number": 5e-2},
        "polyhedra": {},
        "spheres": {"compaction_friction": 0.0},
    },
    # the size front: the default at 200 and at 5000 grains per sample
    "small": {"common": {"n_particles": 200}, "polyhedra": {},
              "spheres": {"compaction_friction": 0.0, "inertial_number": 1e-3}},
    # 5000 frictionless spheres in a box 37 mean diameters high: the default's
    # compaction gain (10, capped at 0.5 by stable_gain) made the top and
    # bottom walls swing between 0.64 and 2.04 sigma0 (docs/measurements.md,
    # "The 5000-sphere compaction"); 0.2 holds them within 0.6 %
    "intermediate": {"common": {"n_particles": 5000}, "polyhedra": {},
                     "spheres": {"compaction_friction": 0.0, "inertial_number": 1e-3, "compaction_gain": 0.2}},
    # prepared like the default: the
    # polyhedra compacted at mu = 0.5 (frictionless they reach 0.71), the
    # spheres frictionless. The polyhedra step at 0.45 of the critical one,
    # as in the default.
    "paper": {
        "common": {"kappa": 1.0e4, "inertial_number": 1e-3, "compaction_inertial_number": 1e-2,
                   "dump_strain": 0.005, "unbalanced_tolerance": 0.01},
        "polyhedra": {"n_particles": 36933},
        "spheres": {"n_particles": 19998, "compaction_friction": 0.0, "compaction_gain": 0.2},
    },
}

# The default's loose and dense twins: both samples compacted with the
# shear friction 0.5 (loose start) or frictionless (densest start).
for _name, _mu in (("loose", 0.5), ("dense", 0.0)):
    PRESETS[_name] = {"common": {"compaction_friction": _mu}, "polyhedra": {}, "spheres": {}}
# The earlier bounding-sphere start's solid fraction (about 0.562) with the
# default's faster preparation: polyhedra compacted at 0.58, the friction
# lowered to 0.5 before shear; the spheres as in the default.
PRESETS["matched"] = {"common": {}, "polyhedra": {"compaction_friction": 0.58},
                      "spheres": dict(PRESETS["default"]["spheres"])}


def resolve(preset, sample, overrides=None):
    """The full, checked parameters of a preset for one sample: the
    defaults, the sample's (:data:`SAMPLE_DEFAULTS`), the preset's common
    changes, its changes for ``sample``, then ``overrides``.

    Parameters
    ----------
    preset : str
        One of :data:`PRESETS` ("tiny", "small", "default", "intermediate",
        "paper" ...).
    sample : {"polyhedra", "spheres"}
        S1 or S2.
    overrides : dict, optional
        name -> value (or its text, as ``--set`` gives it), applied last.

    Returns
    -------
    dict
        Every scene parameter (:mod:`yade_scripts.scene.parameters`), checked by
        name, type and range; raises
        :class:`~yade_scripts.scene.parameters.ConfigError` (one line) otherwise.

    Examples
    --------
    >>> p = resolve("default", "polyhedra", {"seed": 2})
    >>> p["n_particles"], p["kappa"], p["friction"], p["seed"]
    (1000, 3000.0, 0.5, 2)
    >>> resolve("default", "cubes")
    Traceback (most recent call last):
        ...
    yade_scripts.scene.parameters.ConfigError: sample must be one of ('polyhedra', 'spheres'), got 'cubes'
    """
    if preset not in PRESETS:
        raise ConfigError(f"unknown preset {preset!r}; choose one of {sorted(PRESETS)}")
    if sample not in SAMPLES:
        raise ConfigError(f"sample must be one of {SAMPLES}, got {sample!r}")
    return check({**SAMPLE_DEFAULTS[sample], **PRESETS[preset]["common"], **PRESETS[preset][sample], "sample": sample,
                  **(overrides or {})})
