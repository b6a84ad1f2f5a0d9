"""The parameters of the triaxial scene: one table, the only place they are listed.

Each :class:`Parameter` has its name (the name the scene uses), type, allowed
values, default and a one-line description with its unit. Everything else is
derived from :data:`PARAMETERS`:

* :data:`DEFAULTS`, the default preset's polyhedra sample (S1): the values a
  preset does not change (``yade_scripts.campaign.presets`` lists only the changes);
* :data:`SCHEMA` and :func:`coerce`, the checks of a value a user sets (a
  preset, ``--set NAME=VALUE``, a column of a yade-batch table);
* :func:`render_block`, the scene's parameter block: ``readParamsFromTable``
  with every parameter, then an explicit import of each name from
  ``yade.params.table``, so that a reader can follow ``kappa`` from here to
  the kernel by its name. ``yade_scripts/scene/triaxial.py`` holds the block of the
  defaults (a test checks it), so the bare scene is the default experiment.
"""
from __future__ import annotations

import difflib
import json
import math
from typing import NamedTuple

from postproc.schema import SAMPLE_KINDS

#: the two samples of the study, S1 and S2: the kinds of sample a dump holds
SAMPLES = SAMPLE_KINDS

BLOCK_START = "# --- parameters (generated from yade_scripts/scene/parameters.py) ---"
BLOCK_END = "# --- end of parameters ---"


class ConfigError(ValueError):
    """A preset, override or table column that does not make a valid scene."""


class Parameter(NamedTuple):
    """One scene parameter: a row of :data:`PARAMETERS`.

    Parameters
    ----------
    name : str
        The name the scene, the presets, ``--set NAME=VALUE`` and the
        columns of a run folder's ``table.txt`` all use.
    type : type
        ``str``, ``int``, ``float`` or ``bool``: what :func:`coerce` makes
        of a value.
    allowed : tuple or None
        ``(lo, hi)``, both included, for a number; the choices for a
        string; None: any value of the type.
    default : object
        Its value in the default preset's polyhedra sample (S1), which a
        preset keeps unless it lists the parameter.
    doc : str
        One line: what it sets, with its unit (SI: Pa, m, m/s, s, kg/m^3;
        kappa, inertial numbers, strains and friction coefficients are
        dimensionless).

    Attributes
    ----------
    name : str
        As given.
    type : type
        As given.
    allowed : tuple or None
        As given.
    default : object
        As given.
    doc : str
        As given; :func:`render_block` writes it as the comment of the
        parameter's line in the scene.

    Examples
    --------
    >>> p = next(q for q in PARAMETERS if q.name == "sigma0")
    >>> p.type.__name__, p.allowed, p.default
    ('float', (0.001, 1000000000000.0), 10000.0)
    >>> p.doc
    'Pa, confining stress'
    """
    name: str
    type: type
    allowed: tuple | None   # (lo, hi) for numbers, the choices for strings, None: any
    default: object
    doc: str


PARAMETERS = (
    Parameter("sample", str, SAMPLES, "polyhedra", '"polyhedra" (S1) or "spheres" (S2)'),
    Parameter("n_particles", int, (2, 10_000_000), 1000, "number of particles"),
    Parameter("seed", int, (0, 2**63 - 1), 1, "sample seed (sizes, shapes, orientations, positions)"),
    Parameter("sigma0", float, (1e-3, 1e12), 1.0e4, "Pa, confining stress"),
    Parameter("friction", float, (0.0, 10.0), 0.5, "particle-particle friction coefficient (shear)"),
    Parameter("compaction_friction", float, (0.0, 10.0), 0.5,
              "... during the isotropic compression (0: the dense state; = friction: loose)"),
    Parameter("wall_friction", float, (0.0, 10.0), 0.0, "particle-wall friction coefficient"),
    Parameter("density", float, (1e-3, 1e6), 2700.0, "kg/m^3 (granite ballast)"),
    Parameter("kappa", float, (1.0, 1e9), 3000.0, "stiffness level: typical contact stiffness / (sigma0 d)"),
    Parameter("tangential_ratio", float, (1e-6, 10.0), 1.0, "tangential / normal stiffness of a typical contact"),
    Parameter("inertial_number", float, (1e-7, 1.0), 5e-3,
              "shear: I = rate d sqrt(rho/sigma0) (ignored if wall_speed > 0)"),
    Parameter("wall_speed", float, (0.0, 1e3), 0.0, "m/s, top wall speed during shear (0: from inertial_number)"),
    Parameter("compaction_inertial_number", float, (1e-7, 1.0), 0.1, "max rate of the isotropic compression"),
    Parameter("approach_factor", float, (1.0, 100.0), 1.0,
              "... times this until the mean wall stress first reaches sigma0 / 2"),
    Parameter("damping", float, (0.0, 0.99), 0.2, "NewtonIntegrator's local damping during shear"),
    Parameter("compaction_damping", float, (0.0, 0.99), 0.2, "... and during the isotropic compression"),
    Parameter("safety", float, (1e-3, 1.0), 0.45, "dt = safety * critical time step"),
    Parameter("servo_gain", float, (1e-3, 1e3), 10.0, "proportional gain of the wall servo (lowered if unstable)"),
    Parameter("compaction_gain", float, (0.0, 1e3), 0.0,
              "... during the isotropic compression (0: servo_gain; lowered if unstable)"),
    Parameter("servo_time", float, (1e-6, 10.0), 0.01,
              "integral time of the servo, as the strain (of the loading rate) it spans"),
    Parameter("placement", str, ("spheres", "grains"), "grains",
              'start: random sequential addition of the bounding spheres, or of the grains tested exactly (kernel)'),
    Parameter("initial_fraction", float, (0.01, 0.33), 0.25,
              "packing fraction at the start: of the bounding spheres, or of the grains (placement grains)"),
    Parameter("aspect", float, (0.1, 20.0), 2.0, "H/L of the initial box"),
    Parameter("iso_tolerance", float, (1e-6, 0.5), 0.01, "isotropic state: |sigma - sigma0| < tol sigma0 on all walls"),
    Parameter("unbalanced_tolerance", float, (1e-6, 1.0), 0.02, "... and unbalanced force ratio below this"),
    Parameter("dump_strain", float, (1e-6, 1.0), 0.01, "a snapshot every delta eps_1 during shear"),
    Parameter("final_strain", float, (1e-6, 2.0), 0.3, "eps_1 at the end of shear"),
    Parameter("max_steps", int, (0, 10**12), 0, "stop (as a failure) after this many steps (0: no limit)"),
    Parameter("library", str, None, "shapes.h5", "polyhedra library (d = 1 grains)"),
    Parameter("out", str, None, "run.h5", "dump file"),
    Parameter("log_every", int, (1, 10**9), 200, "steps between log.csv rows"),
    Parameter("check_every", int, (1, 10**9), 200, "steps between blow-up checks"),
    Parameter("report_seconds", float, (0.0, 1e6), 10.0, "seconds between progress lines"),
    Parameter("timing", bool, None, True, "record the time of each engine (run.info.json)"),
    Parameter("contact_engine", str, ("kernel", "yade"), "kernel",
              'polyhedra contacts: "kernel" (compiled, exact) or "yade" (stock Ig2/Law2)'),
    Parameter("kernel_threads", int, (0, 1024), 0, "OpenMP threads of the kernel (0: YADE's own, i.e. yade -jN)"),
    Parameter("kernel_plugin", bool, None, True,
              "step the kernel inside YADE's C++ loop by the plugin where YADE loaded it (False: the PyRunner)"),
    Parameter("verlet_skin", float, (1e-4, 10.0), 0.1, "kernel neighbour-list margin, in units of the mean d"),
    Parameter("checkpoint_seconds", float, (0.0, 1e7), 300.0,
              "s of wall time between checkpoints (0: only on SIGTERM)"),
    Parameter("resume", bool, None, True, "continue from OUT.ckpt when there is one (False: start afresh)"),
)

DEFAULTS = {p.name: p.default for p in PARAMETERS}

#: the largest initial solid fraction random sequential addition reaches
#: (yade_scripts.scene.sample), measured on 1000 grains of the library, seed 1,
#: aspect 2: placed with their exact shapes they fill 0.30 and jam at 0.33
#: (no room for grain 754 after 128 000 trials); as bounding spheres (and
#: S2's spheres) they fill 0.36 and jam at 0.38. The scene would enlarge a
#: jammed box until the grains fit, i.e. start looser than asked after
#: minutes of failed trials, so a fraction above these is refused.
PLACEMENT_LIMIT = {"grains": 0.30, "spheres": 0.36}
#: the largest grain (m), the largest of shapes.sizes.CLASS_DIAMETERS
D_MAX = 0.05
SCHEMA = {p.name: (p.type, p.allowed) for p in PARAMETERS}


def _whole(key, value):
    """``value`` as an int when it is a whole number of any numeric type
    (an int, a float, numpy's, a Decimal, or text such as ``"1e3"``); a
    bool, a fraction, NaN or infinity is refused in one line."""
    if type(value).__name__ in ("bool", "bool_"):       # Python's and numpy's
        raise ConfigError(f"{key} = {value!r} is not an integer (a true/false value)")
    try:
        if isinstance(value, str):
            try:
                return int(value.strip())        # exact, whatever its size (a 64-bit seed)
            except ValueError:
                pass
        number = float(value) if isinstance(value, str) else value
        v = int(number)
        whole = v == number
    except (TypeError, ValueError, OverflowError, ArithmeticError):
        raise ConfigError(f"{key} = {value!r} is not an integer") from None
    if not whole:
        raise ConfigError(f"{key} = {value!r} is not an integer")
    return v


def coerce(key, value):
    """One parameter's value, typed and checked against :data:`SCHEMA`.

    Parameters
    ----------
    key : str
        The parameter's name.
    value : object
        Its value, or its text as ``--set`` or a table column gives it
        (``"300"``). A bool takes ``true``, ``1``, ``yes`` or ``false``,
        ``0``, ``no`` (any case); an int takes a whole number written as a
        float (``"1e3"``).

    Returns
    -------
    object
        The value as the parameter's type: a number within its range
        ``[lo, hi]`` (NaN refused), a string among its choices.

    Raises
    ------
    ConfigError
        One line naming the parameter and the problem: an unknown name
        (with the closest known one), a value that is not of its type, or
        one out of range.

    Examples
    --------
    >>> coerce("kappa", "300"), coerce("n_particles", "1e3"), coerce("resume", "no")
    (300.0, 1000, False)
    >>> coerce("kapa", 300)
    Traceback (most recent call last):
        ...
    yade_scripts.scene.parameters.ConfigError: unknown parameter 'kapa' (did you mean 'kappa'?)
    >>> coerce("friction", -0.1)
    Traceback (most recent call last):
        ...
    yade_scripts.scene.parameters.ConfigError: friction = -0.1 is outside [0, 10]
    """
    if key not in SCHEMA:
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
    if typ is int:
        v = _whole(key, value)
    else:
        try:
            v = typ(value)
        except (TypeError, ValueError):
            raise ConfigError(f"{key} = {value!r} is not a {typ.__name__}") from None
    if isinstance(allowed, tuple) and typ is str:
        if v not in allowed:
            raise ConfigError(f"{key} must be one of {allowed}, got {v!r}")
    elif allowed is not None:
        lo, hi = allowed
        if not (lo <= v <= hi) or v != v:
            raise ConfigError(f"{key} = {v!r} is outside [{lo:g}, {hi:g}]")
    return v


def check(params):
    """The full, typed parameters of one scene, checked.

    ``params`` over :data:`DEFAULTS`, every value through :func:`coerce`,
    then the checks that involve several parameters: polyhedra placed as
    grains (``placement = "grains"``) need ``contact_engine = "kernel"``;
    ``dump_strain`` is at most ``final_strain``; and the grains fit their
    initial box (``initial_fraction`` at most the :data:`PLACEMENT_LIMIT`
    of the placement, and a box wider and higher than the largest grain,
    :data:`D_MAX`).

    Parameters
    ----------
    params : dict
        name -> value (or its text); a name not given takes its default.

    Returns
    -------
    dict
        Every parameter of :data:`PARAMETERS`, typed, in their order.

    Raises
    ------
    ConfigError
        One line naming the parameter(s) and the problem.

    Examples
    --------
    >>> p = check({"sample": "spheres", "n_particles": "40"})
    >>> p["n_particles"], p["sigma0"], p["initial_fraction"]
    (40, 10000.0, 0.25)
    >>> check({"initial_fraction": 0.32})
    Traceback (most recent call last):
        ...
    yade_scripts.scene.parameters.ConfigError: initial_fraction = 0.32: random sequential addition of the grains with ...
    """
    p = {k: coerce(k, v) for k, v in {**DEFAULTS, **params}.items()}
    if p["placement"] == "grains" and p["sample"] == "polyhedra" and p["contact_engine"] != "kernel":
        raise ConfigError("placement 'grains' needs contact_engine 'kernel' (YADE re-hulls its Polyhedra in "
                          "another frame)")
    if p["dump_strain"] > p["final_strain"]:
        raise ConfigError(f"dump_strain {p['dump_strain']} is larger than final_strain {p['final_strain']}")
    _check_box(p)
    return p


def _check_box(p):
    """The grains must fit their initial box: the solid fraction asked for
    is one random sequential addition reaches (:data:`PLACEMENT_LIMIT`),
    and the box, at most the bounding spheres' volume of N grains of the
    largest size over that fraction, is wider and higher than the largest
    grain. Raises ConfigError (one line)."""
    n, frac, aspect = p["n_particles"], p["initial_fraction"], p["aspect"]
    placement = "grains" if p["sample"] == "polyhedra" and p["placement"] == "grains" else "spheres"
    limit = PLACEMENT_LIMIT[placement]
    if frac > limit:
        what = "the grains with their exact shapes" if placement == "grains" else "bounding spheres"
        raise ConfigError(f"initial_fraction = {frac:g}: random sequential addition of {what} jams above "
                          f"{limit:g} (measured), so {n} grains do not fit that box; ask for {limit:g} or less")
    side = (n * math.pi / 6 * D_MAX ** 3 / frac / aspect) ** (1 / 3)
    smallest = min(side, aspect * side)
    if smallest < D_MAX:
        raise ConfigError(f"n_particles = {n} with aspect {aspect:g} and initial_fraction {frac:g} makes a box at "
                          f"most {smallest:.3g} m across, less than the largest grain ({D_MAX:g} m): use more "
                          f"grains or an aspect nearer 1")


def changed(recorded, wanted, names=None):
    """The parameters whose value asked for now differs from the one a run
    was made with: a run is reused only when there are none (the study's
    run folders against their ``params.json``, a sweep's finished dumps
    against their table line).

    Values are compared as :func:`coerce` types them (so ``"300"`` equals
    300.0; a value that is not valid is compared as it is) and as JSON
    gives them back (tuples as lists). A parameter of the table missing
    from ``recorded`` counts as its default: a parameter added later has a
    default that does what the scene did before it existed, so older runs
    are not set aside for it.

    Parameters
    ----------
    recorded : dict
        What the run was made with (read from JSON).
    wanted : dict
        What is asked for now, each value as it would be set.
    names : iterable of str, optional
        The names compared (default: every name of either dict).

    Returns
    -------
    list of str
        The names that differ or are in only one of the two, sorted.

    Examples
    --------
    >>> changed({"kappa": 300.0, "seed": 1}, {"kappa": "300", "seed": 2})
    ['seed']
    >>> changed({}, {"kappa": 3000.0})      # missing: the default, 3000
    []
    """
    def norm(k, v):
        if k in SCHEMA and v is not None:
            try:
                v = coerce(k, v)
            except ConfigError:     # not a valid value (any more): compared as it is
                pass
        return json.loads(json.dumps(v))

    recorded = {**{k: DEFAULTS[k] for k in wanted if k in DEFAULTS and k not in recorded}, **recorded}
    keys = sorted(set(recorded) | set(wanted)) if names is None else sorted(names)
    return [k for k in keys if k not in recorded or k not in wanted or norm(k, recorded[k]) != norm(k, wanted[k])]


def render_block(params):
    """The scene's parameter block (text, from :data:`BLOCK_START` to the
    line before :data:`BLOCK_END`) for the checked ``params``: every
    parameter in the order of :data:`PARAMETERS` with its description, then
    the explicit import of every name from ``yade.params.table`` (where a
    yade-batch table line may have changed it)."""
    p = check(params)
    width = max(len(f"{q.name}={p[q.name]!r},") for q in PARAMETERS) + 1
    lines = [BLOCK_START, "readParamsFromTable("]
    lines += [f"    {f'{q.name}={p[q.name]!r},':<{width}} # {q.doc}" for q in PARAMETERS]
    lines += ["    noTableOk=True,", ")", "from yade.params.table import (  # noqa: E402"]
    names = [q.name for q in PARAMETERS]
    row = "   "
    for n in names:
        if len(row) + len(n) + 2 > 88:
            lines.append(row.rstrip())
            row = "   "
        row += f" {n},"
    lines += [row, ")"]
    return "\n".join(lines) + "\n"


def scene_with_block(text, params):
    """``text`` (a scene with a generated block) with its block set to
    ``params``."""
    try:
        start, end = text.index(BLOCK_START), text.index(BLOCK_END)
    except ValueError:
        raise ConfigError("the scene has no generated parameter block") from None
    return text[:start] + render_block(params) + text[end:]
