"""SLURM job arrays for the lines of a run folder's table.

    python -m yade_scripts.campaign.generate --preset paper --sample polyhedra \
        --out runs/paper-s1 --seeds 1 2 3 4 --slurm [--slurm-cpus 8 --slurm-time 7-00:00:00]
    sbatch runs/paper-s1/slurm.sh                 # from any folder; or sbatch -D DIR ...
    python -m yade_scripts.campaign.study --collect runs/paper-s1

writes ``slurm.sh`` next to ``table.txt``: one array task per run line.
The script knows its run folder by absolute path (``RUN_DIR`` overrides it;
``python -m yade_scripts.launch.slurm FOLDER`` writes it again for a moved
folder), says in one line when the folder, its table or its scene is
missing, and ``exec``s :mod:`yade_scripts.launch.task` on YADE's own Python: task
K runs table line K in ``FOLDER/<description>/`` (its dump, its log
``triaxial.log``, every attempt appended), checks the line first, skips a
complete dump, and on SIGUSR1, which SLURM sends ``--slurm-signal`` seconds
before the time limit (``--signal=B:USR1@S``), lets YADE write its
checkpoint and requeues itself (``--slurm-requeues`` times at most), so
one ``sbatch`` runs every line to the end. SLURM's own output goes to
``FOLDER/slurm-<job>_<task>.out``, appended across requeues
(``--open-mode=append``). The task's final state and reason are its last
output line, its exit code and its job's ``Comment`` (``sacct``).

Run a task by hand (no SLURM): ``SLURM_ARRAY_TASK_ID=2 bash slurm.sh``.

Cost model: core-hours = steps x contacts x (µs per contact-step on one
core) / 3.6e9, see :func:`estimate`.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import re
import shutil
import sys

from ..scene.parameters import ConfigError
from .batch import read_table

#: Cost model (docs/scenes.md "Paper scale"): steps measured at a reference
#: point per sample, scaled to other parameters, times contacts, times the
#: wall time of one contact-step on one core.
#:
#: Polyhedra: the default (kappa = 3000, I = 5e-3, I_c = 0.1, grains placed
#: with their exact shapes, 1000 grains, eps_1 to 0.3): 34 850 steps to the
#: isotropic state (seed 1, 2026-11-25) and 339 810 of shear (2026-11-24; the
#: same as (1 - exp(-0.3)) / (shear rate x dt)).
#: Spheres: the default (kappa = 3000, I = 1e-3, I_c = 0.1, 1000 spheres;
#: ``make front``, plan ``default``, 2026-11-25, ``front-cost.csv``): medians
#: over the front's 24 sphere runs scaled to it (their frictionless compaction
#: spreads by 37 %, their shear by < 1 %).
REFERENCE = {
    "polyhedra": {"kappa": 3000.0, "inertial_number": 5e-3, "compaction_inertial_number": 0.1,
                  "final_strain": 0.3, "placement": "grains", "safety": 0.3},
    "spheres": {"kappa": 3000.0, "inertial_number": 1e-3, "compaction_inertial_number": 0.1,
                "final_strain": 0.3, "placement": "spheres", "safety": 0.3},
}
COMPACTION_STEPS = {"polyhedra": 34_850, "spheres": 57_400}
SHEAR_STEPS = {"polyhedra": 339_810, "spheres": 194_487}
#: compaction steps go as I_c^-0.55: the same 1000-grain S1 (kappa 3000,
#: grains placed at 0.25) took 51 000 steps at I_c = 0.05 and 34 850 at 0.1
COMPACTION_IC_EXPONENT = 0.55
#: polyhedra placed as their bounding spheres (solid fraction 0.06) against
#: the grains themselves (0.25), same seed, kappa 3000, I_c = 0.05: 118 550
#: against 51 000 steps. Spheres are their own bounding spheres (1).
PLACEMENT_FACTOR = {"grains": 1.0, "spheres": 118_550 / 51_000}
#: wall time per contact-step on one core (µs), the kernel stepped by its
#: YADE plugin. Polyhedra: the whole 1000-grain S1 at the reference point
#: over its steps x the contacts of the model took 1.41 µs on the PyRunner
#: path (26.7 core-min for 459 860 steps on a quiet core, 2026-11-24: the
#: kernel, poses, forces, Newton, controller); on the plugin the whole step
#: (engines and controller) costs 0.670 of that (2026-11-27, dense 1000-grain
#: state stepped on both paths in one run, one thread: 10.04 + 0.64 ms
#: against 14.86 + 1.09, the controller as in whole runs before and after it
#: was made faster): 0.94. Spheres: YADE's own sphere loop (the default
#: front's sphere runs, median).
US_PER_CONTACT_STEP = {"polyhedra": 1.41 * 0.670, "spheres": 0.33}
#: the PyRunner path's cost against the plugin's (where the plugin cannot be
#: built or loaded): the inverse of the plugin's 0.670 above
PYRUNNER_COST = {"polyhedra": 1 / 0.670, "spheres": 1.0}
#: touching contacts per grain in a large sample: polyhedra 2.47 at the
#: isotropic state of the reference run (a face-face pair counting once);
#: spheres z / 2 of the 1000-sphere default study (3.96 / 2)
CONTACTS_PER_GRAIN = {"polyhedra": 2.47, "spheres": 2.0}
#: the reference point's number of grains (COMPACTION_STEPS, US_PER_CONTACT_STEP)
REFERENCE_GRAINS = 1000
#: above REFERENCE_GRAINS the compaction takes more steps, as (N / 1000)^x:
#: polyhedra x = 0.25, the default's S1 reached the isotropic state in 24 700,
#: 23 600 and 28 400 steps at 1000 grains (seeds 1-3) and in 35 800 and
#: 40 050 at 5000 (seeds 1-2), 1.48 x the mean (the same step and I_c; 200
#: grains: 23 950 and 19 750, so no fewer steps below 1000); spheres x =
#: 0.41, the default's S2 in 64 200, 57 400 and 98 000 steps at 1000 (mean
#: 73 200) and the intermediate preset's in 137 200, 114 400 and 172 400 at
#: 5000 (mean 141 300, 1.93 x; its servo gain 0.2 against 0.5; 200 spheres:
#: 36 200, 21 600 and 22 000, not in the model)
COMPACTION_N_EXPONENT = {"polyhedra": 0.25, "spheres": 0.41}
#: the whole step's cost per contact may grow with N while the arrays outgrow
#: the caches: a dense 5000-grain S1 cost 1.11 and 1.06 x the 1000-grain one
#: per grain-step in two runs on the PyRunner path (2026-11-26: the same
#: strain eps_1 = 0.05 of the default's seed 1, stepped side by side in one
#: run on one thread, bench_scale.py --dense), and 0.95 on the plugin (1.01
#: on the PyRunner) in a third (2026-11-27, the isotropic states): 1.04 the
#: mean of the three; the model takes that factor from 5000 grains on and
#: interpolates it in log N between 1000 and 5000 (the paper's 36 933 is not
#: measured dense)
COST_GROWTH = {"polyhedra": (5000, 1.04), "spheres": (5000, 1.0)}
#: the shear's steps follow the time step, which the sample's most limiting
#: grain sets (yade_scripts/scene/timestep.py): N grains drawn from the default
#: library (1000 shapes, seed 0) hold a more limiting one the larger N is.
#: E[1/dt] of N grains relative to 1000 grains, exact order statistics of the
#: draws (python -m yade_scripts.campaign.timestep_draws, 2026-11-27): 200 grains 0.8725, 2000
#: 1.0479, 5000 1.0967, 10 000 1.1089, 36 933 1.1100 (the library's limit,
#: every sample holding its most limiting shape in the smallest class);
#: linear in log N between, constant beyond. Spheres: the smallest class sets
#: the step at any N.
SHEAR_RATE_DRAWS = {"polyhedra": ((200, 0.8725), (1000, 1.0), (2000, 1.0479), (5000, 1.0967), (10_000, 1.1089),
                                  (36_933, 1.1100)),
                    "spheres": ((1000, 1.0),)}
#: the reference run's 1/dt against the expectation at 1000 grains: its dt was
#: 3.953 us, the library's limit 3.276 us = 1/(1.1100 x the expectation), so
#: 3.276 x 1.1100 / 3.953 (SHEAR_STEPS are the reference run's)
REFERENCE_SHEAR_RATE = {"polyhedra": 3.276 * 1.1100 / 3.953, "spheres": 1.0}


def shear_step_factor(sample, n):
    """The shear's steps of N grains against the reference run's: E[1/dt]
    of N grains (:data:`SHEAR_RATE_DRAWS`) over the reference's 1/dt.

    Parameters
    ----------
    sample : {"polyhedra", "spheres"}
        The sample.
    n : int
        Grains.

    Returns
    -------
    float
        The factor on :data:`SHEAR_STEPS`: the table's value at ``n``
        (linear in log N between its points, constant outside them) over
        :data:`REFERENCE_SHEAR_RATE`.

    Raises
    ------
    KeyError
        ``sample`` is neither.
    """
    table = SHEAR_RATE_DRAWS[sample]
    if n <= table[0][0] or len(table) == 1:
        g = table[0][1]
    elif n >= table[-1][0]:
        g = table[-1][1]
    else:
        k = next(i for i in range(1, len(table)) if n <= table[i][0])
        (n0, g0), (n1, g1) = table[k - 1], table[k]
        g = g0 + (g1 - g0) * math.log(n / n0) / math.log(n1 / n0)
    return g / REFERENCE_SHEAR_RATE[sample]


def _grains_factor(n, n_measured, factor):
    """1 up to REFERENCE_GRAINS, ``factor`` from ``n_measured`` on, linear in
    log N between."""
    if n <= REFERENCE_GRAINS:
        return 1.0
    w = min(1.0, math.log(n / REFERENCE_GRAINS) / math.log(n_measured / REFERENCE_GRAINS))
    return 1.0 + (factor - 1.0) * w


def estimate(params, kernel_path="plugin"):
    """Cost of one run on one core from its parameters: dict with
    compaction_steps, shear_steps, steps, contacts, contact_steps,
    core_hours. ``kernel_path``: "plugin" (the polyhedra kernel stepped
    inside YADE) or "pyrunner" (from a PyRunner, PYRUNNER_COST x more).

    With the sample's REFERENCE point r: compaction steps =
    COMPACTION_STEPS x sqrt(kappa / r.kappa) (the time step goes as
    kappa^-1/2) x (r.I_c / I_c)^COMPACTION_IC_EXPONENT x the placement's
    factor relative to r's (polyhedra only); shear steps = SHEAR_STEPS x
    sqrt(kappa / r.kappa) x (r.I / I) (the shear rate goes as I) x
    (1 - exp(-final_strain)) / (1 - exp(-r.final_strain)) (the top wall moves
    at a constant speed); both also x r.safety / safety (dt = safety x the
    critical step); contacts = grains x CONTACTS_PER_GRAIN; core-hours =
    steps x contacts x US_PER_CONTACT_STEP x the cost's growth with N
    (COST_GROWTH) / 3.6e9. The shear's steps follow the expected time step
    of N grains drawn from the library (:func:`shear_step_factor`; a
    polyhedra run's own draw may be up to 1.21 x its reference's); the
    compaction steps grow as (N / 1000)^COMPACTION_N_EXPONENT above 1000
    grains (measured at 5000 for both samples, the time step's growth
    included). The kernel's speed-up on more threads is not in the model.

    Parameters
    ----------
    params : dict
        A run's parameters (:func:`yade_scripts.campaign.presets.resolve`): sample,
        n_particles, kappa, inertial_number, compaction_inertial_number,
        final_strain, safety, placement.
    kernel_path : {"plugin", "pyrunner"}
        The polyhedra kernel stepped inside YADE, or from a PyRunner
        (PYRUNNER_COST x more per contact-step).

    Returns
    -------
    dict
        compaction_steps, shear_steps, steps, contacts, contact_steps,
        us_per_contact_step (µs on one quiet core), core_hours.

    Raises
    ------
    ValueError
        ``kernel_path`` is neither "plugin" nor "pyrunner".

    Examples
    --------
    >>> from yade_scripts.campaign.presets import resolve
    >>> round(estimate(resolve("default", "polyhedra"))["core_hours"], 2)
    0.17
    >>> e = estimate(resolve("paper", "polyhedra"))
    >>> round(e["core_hours"]), round(estimate(resolve("paper", "polyhedra"), "pyrunner")["core_hours"])
    (71, 107)
    """
    s = params["sample"]
    r = REFERENCE[s]
    # steps per unit of simulated time, relative to r's: 1 / dt, dt = safety x dt_crit ~ kappa^-1/2
    step_scale = math.sqrt(params["kappa"] / r["kappa"]) * r["safety"] / params.get("safety", r["safety"])
    place = PLACEMENT_FACTOR[params.get("placement", r["placement"])] / PLACEMENT_FACTOR[r["placement"]] \
        if s == "polyhedra" else 1.0
    n = params["n_particles"]
    comp = (COMPACTION_STEPS[s] * step_scale * (r["compaction_inertial_number"] / params["compaction_inertial_number"])
            ** COMPACTION_IC_EXPONENT * place * max(1.0, n / REFERENCE_GRAINS) ** COMPACTION_N_EXPONENT[s])
    shear = (SHEAR_STEPS[s] * step_scale * r["inertial_number"] / params["inertial_number"]
             * (1 - math.exp(-params["final_strain"])) / (1 - math.exp(-r["final_strain"]))
             * shear_step_factor(s, n))
    steps = comp + shear
    contacts = n * CONTACTS_PER_GRAIN[s]
    cs = steps * contacts
    if kernel_path not in ("plugin", "pyrunner"):
        raise ValueError(f"kernel_path must be 'plugin' or 'pyrunner', got {kernel_path!r}")
    us = US_PER_CONTACT_STEP[s] * _grains_factor(n, *COST_GROWTH[s]) * (
        PYRUNNER_COST[s] if kernel_path == "pyrunner" else 1.0)
    return {"compaction_steps": comp, "shear_steps": shear, "steps": steps, "contacts": contacts,
            "contact_steps": cs, "us_per_contact_step": us, "core_hours": cs * us / 3.6e9}


#: seconds before the time limit that SLURM sends SIGUSR1 to the batch shell (``--signal=B:USR1@S``): YADE
#: stops at the end of its step and writes a checkpoint (0.1 MB in 0.02 s for
#: 20 grains; SLURM's own resolution is up to a minute)
DEFAULT_SIGNAL_SECONDS = 300
#: requeues of one task at most (``--requeues``): each is one job's time limit
DEFAULT_REQUEUES = 10
_TIME = re.compile(r"(?:(\d+)-)?(\d+)(?::(\d+))?(?::(\d+))?")


def time_seconds(text):
    """The seconds of a SLURM time limit.

    Parameters
    ----------
    text : str
        ``MM``, ``MM:SS``, ``HH:MM:SS``, ``D-HH``, ``D-HH:MM`` or
        ``D-HH:MM:SS``, as ``sbatch --time`` takes it.

    Returns
    -------
    int
        s.

    Raises
    ------
    ValueError
        When ``text`` is none of these.

    Examples
    --------
    >>> time_seconds("90"), time_seconds("1:30:00"), time_seconds("2-12"), time_seconds("7-00:00:00")
    (5400, 5400, 216000, 604800)
    """
    m = _TIME.fullmatch(text.strip())
    if not m:
        raise ValueError(f"{text!r} is not a SLURM time (like 24:00:00 or 7-00:00:00)")
    d, a, b, c = m.groups()
    if d is None:
        parts = [int(x) for x in (a, b, c) if x is not None]
        h, mi, sec = ([0] * (3 - len(parts)) + parts) if len(parts) == 3 else \
            ((0, parts[0], 0) if len(parts) == 1 else (0, parts[0], parts[1]))
        return 3600 * h + 60 * mi + sec
    rest = [int(x) for x in (b, c) if x is not None]
    return 86400 * int(d) + 3600 * int(a) + 60 * (rest[0] if rest else 0) + (rest[1] if len(rest) > 1 else 0)


def check_options(cpus=2, time="24:00:00", partition=None, requeues=None, signal_seconds=DEFAULT_SIGNAL_SECONDS):
    """Refuse options of :func:`write_slurm` that do not make a valid array
    script (``generate --slurm`` checks them before it makes the folder).

    Parameters
    ----------
    cpus, time, partition, requeues, signal_seconds
        As :func:`write_slurm` takes them (``requeues`` None: the default).

    Returns
    -------
    None

    Raises
    ------
    ConfigError
        One line: a time that is not a SLURM time, fewer than one core,
        negative requeues, a warning signal not within the time limit, or
        a partition name with characters SLURM does not allow.

    Examples
    --------
    >>> check_options(cpus=8, time="7-00:00:00")
    >>> check_options(time="0:04:00")
    Traceback (most recent call last):
        ...
    yade_scripts.scene.parameters.ConfigError: --slurm-signal 300 s must be ... less than the time limit 0:04:00 (240 s)
    """
    try:
        limit = time_seconds(time)
    except ValueError as exc:
        raise ConfigError(f"--slurm-time: {exc}") from None
    if int(cpus) < 1 or (requeues is not None and requeues < 0):
        raise ConfigError(f"--slurm-cpus must be >= 1 and --slurm-requeues >= 0, got {cpus} and {requeues}")
    if not 0 < signal_seconds < limit:
        raise ConfigError(f"--slurm-signal {signal_seconds} s must be more than 0 and less than the time limit "
                          f"{time} ({limit} s)")
    if partition is not None and not re.fullmatch(r"[\w.,-]+", partition):
        raise ConfigError(f"--slurm-partition {partition!r} is not a partition name")


def task_module(folder):
    """The module that runs one array task, as the run folder's own copy of
    the packages (``folder/pkg``) names it: ``yade_scripts.launch.task``,
    or ``yade_scripts.task`` in a folder made by the code before
    ``yade_scripts`` had its rooms (``slurm.sh`` runs the folder's copy,
    never this checkout's).

    Parameters
    ----------
    folder : str
        A generated run folder.

    Returns
    -------
    str
        The dotted module name for ``python -m``.

    Examples
    --------
    >>> import os, tempfile
    >>> old = tempfile.mkdtemp()
    >>> os.makedirs(os.path.join(old, "pkg", "yade_scripts"))
    >>> open(os.path.join(old, "pkg", "yade_scripts", "task.py"), "w").close()
    >>> task_module(old)
    'yade_scripts.task'
    >>> task_module(tempfile.mkdtemp())
    'yade_scripts.launch.task'
    """
    flat = os.path.join(folder, "pkg", "yade_scripts", "task.py")
    return "yade_scripts.task" if os.path.exists(flat) else "yade_scripts.launch.task"


def write_slurm(folder, cpus=2, time="24:00:00", partition=None, name=None, requeues=None,
                signal_seconds=DEFAULT_SIGNAL_SECONDS):
    """Write ``folder/slurm.sh``: a SLURM job array with one task per run
    line of the folder's table (the module docstring says what a task
    does). The options and the table are checked first; the script's
    comments give the cost of one line by :func:`estimate`.

    Parameters
    ----------
    folder : str
        A generated run folder (``table.txt``, ``triaxial.py``,
        ``params.json``, ``pkg/``); its absolute path, which the script
        holds, may not contain spaces.
    cpus : int
        Cores per task (``--cpus-per-task``; the task runs YADE with as
        many threads: the polyhedra kernel's).
    time : str
        The time limit of one job (``--time``, a SLURM time).
    partition : str, optional
        The SLURM partition (default: the cluster's).
    name : str, optional
        The job's name (default: the folder's name).
    requeues : int, optional
        Requeues of a task at most, each after a time limit (default
        :data:`DEFAULT_REQUEUES`).
    signal_seconds : int
        s: SIGUSR1 this long before the time limit (``--signal=B:USR1@S``),
        so that YADE writes its checkpoint and the task requeues itself.

    Returns
    -------
    str
        The script's path (executable).

    Raises
    ------
    ConfigError
        One line: invalid options (:func:`check_options`), a path with
        spaces, a bad or missing table line, or a table without run lines.

    Examples
    --------
    >>> import os, tempfile
    >>> from yade_scripts.campaign.generate import generate
    >>> out = os.path.join(tempfile.mkdtemp(), "s2")
    >>> _ = generate(out, "tiny", "spheres", seeds=[1, 2, 3])
    >>> path = write_slurm(out, cpus=4, time="2:00:00")
    >>> print("\\n".join(open(path).read().splitlines()[:6]))
    #!/bin/bash
    #SBATCH --job-name=s2
    #SBATCH --array=1-3
    #SBATCH --cpus-per-task=4
    #SBATCH --time=2:00:00
    #SBATCH --signal=B:USR1@300
    """
    folder = os.path.abspath(folder)
    requeues = DEFAULT_REQUEUES if requeues is None else requeues
    check_options(cpus, time, partition, requeues, signal_seconds)
    if re.search(r"\s", folder):
        raise ConfigError(f"{folder}: a run folder for SLURM needs a path without spaces (#SBATCH --output)")
    rows = read_table(folder)
    if not rows:
        raise ConfigError(f"{folder}/table.txt has no run line")
    with open(os.path.join(folder, "params.json")) as fh:
        params = json.load(fh)
    est = estimate(params)
    task = task_module(folder)
    part = f"#SBATCH --partition={partition}\n" if partition else ""
    text = f"""#!/bin/bash
#SBATCH --job-name={name or os.path.basename(folder)}
#SBATCH --array=1-{len(rows)}
#SBATCH --cpus-per-task={int(cpus)}
#SBATCH --time={time}
#SBATCH --signal=B:USR1@{int(signal_seconds)}
#SBATCH --requeue
#SBATCH --open-mode=append
#SBATCH --output={folder}/slurm-%A_%a.out
{part}# Generated by python -m yade_scripts.launch.slurm (or generate --slurm): one array task per run
# line of table.txt ({len(rows)} lines) in the run folder below. Submit from anywhere:
#   sbatch {folder}/slurm.sh          (some lines only: sbatch --array=2,5 ...)
# By hand, one task: SLURM_ARRAY_TASK_ID=1 bash slurm.sh
# Task K runs table line K in the folder <description>/, resuming from its checkpoint;
# SIGUSR1 {int(signal_seconds)} s before the time limit: YADE writes a checkpoint and the
# task requeues itself (at most {requeues} times), so one sbatch runs every line to the end.
# Stop a task for good: scancel JOB_TASK (checkpoint written; resumable: sbatch --array=K ...)
# Stop it now and have it resume (requeued): scancel --batch --signal=USR1 JOB_TASK
#
# Cost model (yade_scripts/launch/slurm.py, docs/scenes.md): steps x contacts x us per contact-step
#   {params['sample']}, {params['n_particles']} grains, kappa={params['kappa']:g}, I={params['inertial_number']:g}:
#   ~{est['steps']:.3g} steps x ~{est['contacts']:.3g} contacts x {US_PER_CONTACT_STEP[params['sample']]} us
#   (one core) = ~{est['core_hours']:.3g} core-hours per line
HERE="${{RUN_DIR:-{folder}}}"
for f in table.txt triaxial.py params.json pkg; do
    if [[ ! -e "$HERE/$f" ]]; then
        echo "slurm.sh: $HERE/$f is missing: not the generated run folder (moved? write slurm.sh again there: python -m yade_scripts.launch.slurm FOLDER)" >&2
        exit 2
    fi
done
YADE=$(command -v yade) || {{ echo "slurm.sh: yade is not on the PATH of $(hostname)" >&2; exit 2; }}
# the Python YADE runs on (it has numpy and h5py), else python3
for PY in "$(head -n 1 "$YADE" | sed -n 's|^#![[:space:]]*\\([^[:space:]]*\\).*|\\1|p')" python3; do
    [[ -n "$PY" ]] && "$PY" -c 'import numpy, h5py' 2>/dev/null && break
    PY=
done
[[ -n "$PY" ]] || {{ echo "slurm.sh: no Python with numpy and h5py for {task}" >&2; exit 2; }}
export PYTHONPATH="$HERE/pkg" OMP_WAIT_POLICY=PASSIVE
cd "$HERE"      # python -m looks in the working folder first: the folder's own pkg/, never a checkout's
# the kernel's YADE plugin for this node's YADE: carried by the folder, else built
# here (about a minute, once); where it cannot be, the scene steps the kernel from a PyRunner
"$PY" -m yade_scripts.yadeplugin build >&2 || true
exec "$PY" -m {task} "$HERE" --requeues {int(requeues)}
"""
    path = os.path.join(folder, "slurm.sh")
    with open(path, "w") as fh:
        fh.write(text)
    mode = os.stat(path).st_mode
    os.chmod(path, mode | (mode & 0o444) >> 2)      # executable where readable: as chmod +x, under the umask
    return path


#: the record of an array's SLURM jobs, beside its table (:func:`record_job`)
JOBS_FILE = "slurm-jobs.json"
#: squeue states of a task that is in the queue or on a node (not ended)
QUEUED = {"PENDING", "REQUEUED", "REQUEUE_HOLD", "REQUEUE_FED", "RESV_DEL_HOLD", "SPECIAL_EXIT"}
ON_A_NODE = {"RUNNING", "CONFIGURING", "COMPLETING", "SUSPENDED", "RESIZING", "STAGE_OUT", "SIGNALING",
             "STOPPED"}


def recorded_jobs(folder):
    """The array job ids recorded for a run folder (:func:`record_job`).

    Parameters
    ----------
    folder : str
        The run folder.

    Returns
    -------
    list of str
        Oldest first; [] when none is recorded or the record is unreadable.

    Examples
    --------
    >>> import tempfile
    >>> recorded_jobs(tempfile.mkdtemp())
    []
    """
    try:
        with open(os.path.join(folder, JOBS_FILE)) as fh:
            rows = json.load(fh)
    except (OSError, ValueError):
        return []
    return [str(r["job"]) for r in rows if isinstance(r, dict) and r.get("job")] if isinstance(rows, list) else []


def record_job(folder, job, how):
    """Add an array job id to a run folder's record of submissions
    (:data:`JOBS_FILE`), once, so that ``--collect`` can ask SLURM about
    its tasks. Written atomically; a folder that cannot be written is left
    alone.

    Parameters
    ----------
    folder : str
        The run folder.
    job : str or int
        The array job id.
    how : str
        Who recorded it: "submit" (:func:`submit`), or "task" for a task
        that found its array unrecorded (an ``sbatch`` by hand).

    Returns
    -------
    None

    Examples
    --------
    >>> import tempfile
    >>> d = tempfile.mkdtemp()
    >>> record_job(d, 41, "submit"); record_job(d, "41", "task"); record_job(d, 42, "task")
    >>> recorded_jobs(d)
    ['41', '42']
    """
    import time as _time

    path = os.path.join(folder, JOBS_FILE)
    try:
        with open(path) as fh:
            rows = json.load(fh)
        rows = rows if isinstance(rows, list) else []
    except (OSError, ValueError):
        rows = []
    if any(isinstance(r, dict) and str(r.get("job")) == str(job) for r in rows):
        return
    rows.append({"job": str(job), "recorded_by": how,
                 "time": _time.strftime("%Y-%m-%dT%H:%M:%SZ", _time.gmtime())})
    tmp = f"{path}.{os.getpid()}.tmp"
    try:
        with open(tmp, "w") as fh:
            json.dump(rows, fh, indent=1)
        os.replace(tmp, path)
    except OSError:
        pass


def submit(folder, array=None, sbatch_args=()):
    """Submit a run folder's array: ``sbatch --parsable [--array=ARRAY]
    FOLDER/slurm.sh``, its job id recorded (:func:`record_job`) so that
    ``--collect`` can ask SLURM which lines are pending or running.

    Parameters
    ----------
    folder : str
        A run folder with its ``slurm.sh`` (:func:`write_slurm`).
    array : str, optional
        The tasks (table lines) to submit, e.g. "2,5" (default: all).
    sbatch_args : sequence of str
        More options for ``sbatch``, before the script.

    Returns
    -------
    str
        The array's job id.

    Raises
    ------
    ConfigError
        One line: no ``slurm.sh``, no ``sbatch`` on the PATH, or sbatch's
        refusal.

    Examples
    --------
    (A real submission needs a SLURM cluster; a folder without its script
    is refused before sbatch is called.)

    >>> import tempfile
    >>> submit(tempfile.mkdtemp())
    Traceback (most recent call last):
        ...
    yade_scripts.scene.parameters.ConfigError: ...: no slurm.sh (generate --slurm, or python -m yade_scripts.launch.slurm FOLDER)
    """
    import subprocess

    script = os.path.join(os.path.abspath(folder), "slurm.sh")
    if not os.path.exists(script):
        raise ConfigError(f"{folder}: no slurm.sh (generate --slurm, or python -m yade_scripts.launch.slurm FOLDER)")
    exe = shutil.which("sbatch")
    if exe is None:
        raise ConfigError("sbatch is not on the PATH (not a SLURM login node?)")
    cmd = [exe, "--parsable", *([f"--array={array}"] if array else []), *sbatch_args, script]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        raise ConfigError(f"sbatch refused: {(r.stderr.strip() or r.stdout.strip()).splitlines()[-1]}")
    job = r.stdout.strip().split(";")[0]
    record_job(os.path.abspath(folder), job, "submit")
    return job


def queue_states(folder):
    """The tasks of a run folder's arrays that SLURM has in its queue or on
    a node now (``squeue -r``): those of the jobs recorded at submission or
    by their tasks (:func:`recorded_jobs`), and of any job whose batch
    script is ``folder/slurm.sh`` (an ``sbatch`` by hand whose tasks have
    not started).

    Parameters
    ----------
    folder : str
        The run folder.

    Returns
    -------
    dict
        task (int, the table's run line) -> (job id, state, reason) as
        squeue gives them; {} without squeue or when it fails. Raises
        nothing.

    Examples
    --------
    >>> import tempfile
    >>> queue_states(tempfile.mkdtemp())        # no job of this folder is queued
    {}
    """
    import subprocess

    exe = shutil.which("squeue")
    if exe is None:
        return {}
    script = os.path.realpath(os.path.join(folder, "slurm.sh"))
    r = subprocess.run([exe, "-h", "-r", "-o", "%i|%T|%r|%o|%K"], capture_output=True, text=True)
    if r.returncode != 0:
        return {}
    ids = set(recorded_jobs(folder))
    out = {}
    for row in r.stdout.splitlines():
        parts = row.strip().split("|")
        if len(parts) != 5:
            continue
        job, state, reason, command, task = parts
        array = job.split("_")[0]
        mine = array in ids or os.path.realpath(command) == script
        if not mine or not task.isdigit():
            continue
        out[int(task)] = (job, state, reason)
    return out


def queue_detail(job, state, reason):
    """The words ``--collect`` says of a task in SLURM's queue
    (:func:`queue_states`): "running: ..." for a state on a node, else
    "pending: ..." with the reason.

    Parameters
    ----------
    job : str
        The task's job id as squeue gives it (``ARRAYJOB_TASK``).
    state : str
        Its squeue state (e.g. "RUNNING", "PENDING").
    reason : str
        squeue's reason; "None", "(null)" or "" are left out.

    Returns
    -------
    str
        ``running: SLURM job JOB, STATE`` for a state in :data:`ON_A_NODE`,
        else ``pending: SLURM job JOB, STATE[, REASON]``.
    """
    if state in ON_A_NODE:
        return f"running: SLURM job {job}, {state}"
    why = f", {reason}" if reason and reason not in ("None", "(null)") else ""
    return f"pending: SLURM job {job}, {state}{why}"


def add_options(ap, prefix="--slurm-"):
    """The options of a SLURM array on ``ap`` (argparse), named ``prefix`` + cpus, time, ...

    Parameters
    ----------
    ap : argparse.ArgumentParser
        The parser the options are added to.
    prefix : str
        Their names' start: ``--slurm-`` (``generate``) or ``--`` (this
        module's command line). The options: cpus (int, default 2), time
        (a SLURM time, default 24:00:00), partition (default None),
        requeues (int, default None: :data:`DEFAULT_REQUEUES`)
        and signal (int, s, default :data:`DEFAULT_SIGNAL_SECONDS`).

    Returns
    -------
    None
    """
    ap.add_argument(prefix + "cpus", type=int, default=2, help="cores per array task (default 2)")
    ap.add_argument(prefix + "time", default="24:00:00", help="time limit of one job (default 24:00:00)")
    ap.add_argument(prefix + "partition", help="SLURM partition (default: the cluster's)")
    ap.add_argument(prefix + "requeues", type=int, default=None,
                    help=f"requeues of a task at most, each after a time limit (default {DEFAULT_REQUEUES})")
    ap.add_argument(prefix + "signal", type=int, default=DEFAULT_SIGNAL_SECONDS,
                    help=f"SIGUSR1 this many seconds before the time limit (default {DEFAULT_SIGNAL_SECONDS})")


def options_of(args, prefix="slurm_"):
    """The keyword arguments of :func:`write_slurm` from parsed :func:`add_options`.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed command line.
    prefix : str
        The options' destination names' start: ``slurm_`` for
        ``add_options(ap, "--slurm-")``, "" for ``add_options(ap, "--")``.

    Returns
    -------
    dict
        "cpus", "time", "partition", "requeues" and "signal_seconds", as
        :func:`write_slurm` (and :func:`check_options`) take them.

    Raises
    ------
    KeyError
        ``args`` lacks one of the options (another ``prefix``).
    """
    g = vars(args)
    return {"cpus": g[prefix + "cpus"], "time": g[prefix + "time"], "partition": g[prefix + "partition"],
            "requeues": g[prefix + "requeues"], "signal_seconds": g[prefix + "signal"]}


def main(argv=None):
    """``python -m yade_scripts.launch.slurm FOLDER [options]``: write the folder's
    ``slurm.sh`` again (:func:`write_slurm`, e.g. for a moved folder), or
    with ``--submit [--array TASKS]`` submit it (:func:`submit`).

    Parameters
    ----------
    argv : list of str, optional
        The command line's arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit code: 0 written or submitted; 2 refused (one line on
        stderr).
    """
    ap = argparse.ArgumentParser(prog="python -m yade_scripts.launch.slurm",
                                 description="Write slurm.sh, a SLURM job array over a run folder's table "
                                             "(or, with --submit, submit it).")
    ap.add_argument("folder", help="a generated run folder (table.txt, triaxial.py, pkg/)")
    ap.add_argument("--submit", action="store_true",
                    help="submit the folder's slurm.sh (sbatch) and record its job id, so that --collect can ask "
                         "SLURM which lines are pending or running; slurm.sh is not written again")
    ap.add_argument("--array", help="with --submit: the tasks (table lines) to submit, e.g. 2,5 (default: all)")
    add_options(ap, "--")
    args = ap.parse_args(argv)
    try:
        if args.submit:
            job = submit(args.folder, args.array)
            print(f"slurm: submitted {os.path.join(os.path.abspath(args.folder), 'slurm.sh')} as job {job} "
                  f"(recorded in {JOBS_FILE})", file=sys.stderr)
            return 0
        if not os.path.exists(os.path.join(args.folder, "pkg")):
            raise ConfigError(f"{args.folder}: no pkg/ (not a run folder of this code; an older folder keeps "
                              f"its own slurm.sh)")
        path = write_slurm(args.folder, **options_of(args, ""))
    except ConfigError as exc:
        print(f"slurm: error: {exc}", file=sys.stderr)
        return 2
    print(f"slurm: {path}; submit with: sbatch {path} (or python -m yade_scripts.launch.slurm {args.folder} --submit, "
          f"which records the job for --collect)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
