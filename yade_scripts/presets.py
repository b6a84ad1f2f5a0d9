"""Presets of the triaxial scene: named parameter sets per sample.

``tiny``     the test suite: a few dozen particles, a few percent of strain,
             well under 3 minutes per sample on this machine.
``default``  the main job of ``make study`` (see the README for its cost and
             how it was chosen), prepared as published: solid fraction about
             0.6 after isotropic compaction for both samples, reached with the
             interparticle friction of the compaction (``compaction_friction``:
             0.5 for polyhedra, 0 for spheres); friction 0.5 for both in shear.
``loose``    the default with both samples compacted at friction 0.5.
``dense``    the default with both samples compacted frictionless.
``intermediate``  5000 polyhedra at kappa = 3000, I = 5e-3 (stiffer and
             slower than the default: the kernel front puts the default's
             stiffness bias on z and the contact types), 1000 spheres (the
             same box: a sphere of size d has 5.2 x the volume of our
             polyhedra); one 16-core node through yade-batch, e.g.
             ``make study PRESET=intermediate ENSEMBLE=16 JOBS=16``: about
             14 core-hours per S1 seed (yade_scripts.slurm.estimate).
``paper``    the published samples (36 933 polyhedra, 19 998 spheres), for a
             cluster through yade-batch; not run here.

Every key is a parameter of ``triaxial.py`` (its ``readParamsFromTable``
block holds the full list with units).
"""
from __future__ import annotations

COMMON = {
    "sigma0": 1.0e4, "friction": 0.5, "compaction_friction": 0.0, "wall_friction": 0.0, "density": 2700.0,
    "tangential_ratio": 1.0, "damping": 0.2, "compaction_damping": 0.2, "safety": 0.3, "servo_gain": 10.0, "servo_time": 0.01,
    "initial_fraction": 0.25, "aspect": 2.0, "iso_tolerance": 0.01,
    "unbalanced_tolerance": 0.01, "wall_speed": 0.0, "library": "shapes.h5", "out": "run.h5",
    "contact_engine": "kernel", "kernel_threads": 0, "verlet_skin": 0.1,
}

PRESETS = {
    "tiny": {
        "common": {"kappa": 150.0, "inertial_number": 1e-2, "compaction_inertial_number": 1e-1,
                   "initial_fraction": 0.3, "dump_strain": 0.01, "final_strain": 0.02,
                   "unbalanced_tolerance": 0.05, "iso_tolerance": 0.02, "log_every": 50,
                   "check_every": 50, "compaction_damping": 0.5, "servo_time": 0.003},
        "polyhedra": {"n_particles": 20},
        "spheres": {"n_particles": 40},
    },
    "default": {
        "common": {"kappa": 300.0, "inertial_number": 2e-2, "compaction_inertial_number": 5e-2,
                   "dump_strain": 0.01, "final_strain": 0.3, "unbalanced_tolerance": 0.02},
        # solid fraction after compaction about 0.6 for both, as published:
        # polyhedra compacted with mu = 0.5 (0.587 at 1000 grains, 0.602 at
        # 3000; frictionless gives 0.71), spheres frictionless (0.61)
        "polyhedra": {"n_particles": 1000, "compaction_friction": 0.5},
        "spheres": {"n_particles": 1000, "compaction_friction": 0.0},
    },
    "intermediate": {
        "common": {"kappa": 3000.0, "inertial_number": 5e-3, "compaction_inertial_number": 5e-2,
                   "dump_strain": 0.01, "final_strain": 0.3, "unbalanced_tolerance": 0.02},
        "polyhedra": {"n_particles": 5000, "compaction_friction": 0.5},
        "spheres": {"n_particles": 1000, "compaction_friction": 0.0},
    },
    "paper": {
        "common": {"kappa": 1.0e4, "inertial_number": 1e-3, "compaction_inertial_number": 1e-2,
                   "dump_strain": 0.005, "final_strain": 0.3},
        "polyhedra": {"n_particles": 36933},
        "spheres": {"n_particles": 19998},
    },
}

# The default's loose and dense twins: both samples compacted with the
# shear friction 0.5 (loose start) or frictionless (densest start).
for _name, _mu in (("loose", 0.5), ("dense", 0.0)):
    PRESETS[_name] = {"common": dict(PRESETS["default"]["common"]),
                      **{s: {**PRESETS["default"][s], "compaction_friction": _mu} for s in ("polyhedra", "spheres")}}

# type and allowed range of every parameter a user may set
SCHEMA = {
    "sample": (str, ("polyhedra", "spheres")),
    "n_particles": (int, (2, 10_000_000)),
    "seed": (int, (0, 2**63 - 1)),
    "sigma0": (float, (1e-3, 1e12)),
    "friction": (float, (0.0, 10.0)),
    "compaction_friction": (float, (0.0, 10.0)),
    "wall_friction": (float, (0.0, 10.0)),
    "density": (float, (1e-3, 1e6)),
    "kappa": (float, (1.0, 1e9)),
    "tangential_ratio": (float, (1e-6, 10.0)),
    "inertial_number": (float, (1e-7, 1.0)),
    "wall_speed": (float, (0.0, 1e3)),
    "compaction_inertial_number": (float, (1e-7, 1.0)),
    "damping": (float, (0.0, 0.99)),
    "compaction_damping": (float, (0.0, 0.99)),
    "safety": (float, (1e-3, 1.0)),
    "servo_gain": (float, (1e-3, 1e3)),
    "servo_time": (float, (1e-6, 10.0)),
    "initial_fraction": (float, (0.01, 0.33)),
    "aspect": (float, (0.1, 20.0)),
    "iso_tolerance": (float, (1e-6, 0.5)),
    "unbalanced_tolerance": (float, (1e-6, 1.0)),
    "dump_strain": (float, (1e-6, 1.0)),
    "final_strain": (float, (1e-6, 2.0)),
    "max_steps": (int, (0, 10**12)),
    "library": (str, None),
    "out": (str, None),
    "log_every": (int, (1, 10**9)),
    "check_every": (int, (1, 10**9)),
    "report_seconds": (float, (0.0, 1e6)),
    "timing": (bool, None),
    "contact_engine": (str, ("kernel", "yade")),
    "kernel_threads": (int, (0, 1024)),
    "verlet_skin": (float, (1e-4, 10.0)),
    "checkpoint_seconds": (float, (0.0, 1e7)),
    "resume": (bool, None),
}


class ConfigError(ValueError):
    """A preset or override that does not make a valid scene."""


def coerce(key, value):
    """Check one parameter against SCHEMA; returns the typed value."""
    if key not in SCHEMA:
        import difflib

        close = difflib.get_close_matches(key, SCHEMA, n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise ConfigError(f"unknown parameter {key!r}{hint}")
    typ, allowed = SCHEMA[key]
    if typ is bool:
        text = str(value).strip().lower()
        if text in ("true", "1", "yes"):
            return True
        if text in ("false", "0", "no"):
            return False
        raise ConfigError(f"{key} = {value!r} is not true or false")
    try:
        if typ is int and isinstance(value, str):
            value = int(float(value)) if float(value).is_integer() else value
        v = typ(value)
    except (TypeError, ValueError):
        raise ConfigError(f"{key} = {value!r} is not a {typ.__name__}") from None
    if typ is int and isinstance(value, float) and not value.is_integer():
        raise ConfigError(f"{key} = {value!r} is not an integer")
    if isinstance(allowed, tuple) and typ is str:
        if v not in allowed:
            raise ConfigError(f"{key} must be one of {allowed}, got {v!r}")
    elif allowed is not None:
        lo, hi = allowed
        if not (lo <= v <= hi) or v != v:
            raise ConfigError(f"{key} = {v!r} is outside [{lo:g}, {hi:g}]")
    return v


def resolve(preset, sample, overrides=None):
    """The full, checked parameter dict of a preset for one sample, with
    ``overrides`` (dict of name -> value or string) applied last."""
    if preset not in PRESETS:
        raise ConfigError(f"unknown preset {preset!r}; choose one of {sorted(PRESETS)}")
    if sample not in ("polyhedra", "spheres"):
        raise ConfigError(f"sample must be 'polyhedra' or 'spheres', got {sample!r}")
    p = {"sample": sample, "seed": 1, **COMMON, **PRESETS[preset]["common"], **PRESETS[preset][sample]}
    for k, v in (overrides or {}).items():
        p[k] = v
    p = {k: coerce(k, v) for k, v in p.items()}
    if p["dump_strain"] > p["final_strain"]:
        raise ConfigError(f"dump_strain {p['dump_strain']} is larger than final_strain {p['final_strain']}")
    return p
