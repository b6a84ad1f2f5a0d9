"""SLURM job arrays for the lines of a yade-batch table.

    python -m yade_scripts.generate --preset paper --sample polyhedra \
        --out runs/paper-s1 --seeds 1 2 3 4 --slurm [--slurm-cpus 8 --slurm-time 7-00:00:00]

writes ``slurm.sh`` next to ``table.txt``: one array task per table line.
Task k makes the folder ``<description of line k>/`` (links to the scene,
``pkg/`` and the shape library), runs ``yade -x triaxial.py`` there with
that line's parameters (``YADE_BATCH=table.txt:LINE``, as yade-batch does),
and keeps its log (``triaxial.log``) and dump in that folder. A task whose
dump is already complete exits at once, so the array can be resubmitted
after failures or time-outs (an unfinished line starts afresh, or resumes
once the scene writes checkpoints). ``python -m yade_scripts.study --collect FOLDER``
then analyses whatever has finished.

Run a task by hand (no SLURM): ``SLURM_ARRAY_TASK_ID=2 bash slurm.sh``.

Cost model: core-hours = steps x contacts x (µs per contact-step on one
core) / 3.6e9, see :func:`estimate`.
"""
from __future__ import annotations

import math
import os
import shlex

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
#: wall time per contact-step on one core (µs): polyhedra, the whole
#: 1000-grain S1 at the reference point over its steps x the contacts of the
#: model (26.7 core-min for 459 860 steps on a quiet core, 2026-11-24: the
#: kernel, poses, forces, Newton, controller); YADE's own sphere loop for S2
#: (the default front's sphere runs, median)
US_PER_CONTACT_STEP = {"polyhedra": 1.41, "spheres": 0.33}
#: touching contacts per grain in a large sample: polyhedra 2.47 at the
#: isotropic state of the reference run (a face-face pair counting once);
#: spheres z / 2 of the 1000-sphere default study (3.96 / 2)
CONTACTS_PER_GRAIN = {"polyhedra": 2.47, "spheres": 2.0}


def estimate(params):
    """Cost of one run on one core from its parameters: dict with
    compaction_steps, shear_steps, steps, contacts, contact_steps,
    core_hours.

    With the sample's REFERENCE point r: compaction steps =
    COMPACTION_STEPS x sqrt(kappa / r.kappa) (the time step goes as
    kappa^-1/2) x (r.I_c / I_c)^COMPACTION_IC_EXPONENT x the placement's
    factor relative to r's (polyhedra only); shear steps = SHEAR_STEPS x
    sqrt(kappa / r.kappa) x (r.I / I) (the shear rate goes as I) x
    (1 - exp(-final_strain)) / (1 - exp(-r.final_strain)) (the top wall moves
    at a constant speed); both also x r.safety / safety (dt = safety x the
    critical step); contacts = grains x CONTACTS_PER_GRAIN; core-hours =
    steps x contacts x US_PER_CONTACT_STEP / 3.6e9. Steps do not depend on
    the number of grains (rate and time step are per grain), except that
    large frictionless sphere packings take longer to settle (the front's
    4000-sphere compactions: 65 400 steps and two not settled after 115 000).
    The kernel's speed-up on more threads is not in the model."""
    s = params["sample"]
    r = REFERENCE[s]
    # steps per unit of simulated time, relative to r's: 1 / dt, dt = safety x dt_crit ~ kappa^-1/2
    step_scale = math.sqrt(params["kappa"] / r["kappa"]) * r["safety"] / params.get("safety", r["safety"])
    place = PLACEMENT_FACTOR[params.get("placement", r["placement"])] / PLACEMENT_FACTOR[r["placement"]] \
        if s == "polyhedra" else 1.0
    comp = (COMPACTION_STEPS[s] * step_scale * (r["compaction_inertial_number"] / params["compaction_inertial_number"])
            ** COMPACTION_IC_EXPONENT * place)
    shear = (SHEAR_STEPS[s] * step_scale * r["inertial_number"] / params["inertial_number"]
             * (1 - math.exp(-params["final_strain"])) / (1 - math.exp(-r["final_strain"])))
    steps = comp + shear
    contacts = params["n_particles"] * CONTACTS_PER_GRAIN[s]
    cs = steps * contacts
    return {"compaction_steps": comp, "shear_steps": shear, "steps": steps, "contacts": contacts,
            "contact_steps": cs, "core_hours": cs * US_PER_CONTACT_STEP[s] / 3.6e9}


def write_slurm(folder, params, rows, cpus=2, time="24:00:00", partition=None, name=None):
    """Write ``folder/slurm.sh`` for the table rows ``rows`` = [(file line,
    {column: raw value})] (:func:`yade_scripts.batch.read_table`). Returns
    its path."""
    from .batch import dump_of

    if not rows:
        raise ValueError("the table has no lines")
    descs = [r["description"] for _, r in rows]
    lines = [str(k) for k, _ in rows]
    outs = [os.path.basename(dump_of(folder, r)) for _, r in rows]
    est = estimate(params)
    links = ["triaxial.py", "pkg"] + ([params["library"]] if params["sample"] == "polyhedra" else [])
    part = f"#SBATCH --partition={partition}\n" if partition else ""
    text = f"""#!/bin/bash
#SBATCH --job-name={name or os.path.basename(os.path.abspath(folder))}
#SBATCH --array=1-{len(rows)}
#SBATCH --cpus-per-task={int(cpus)}
#SBATCH --time={time}
#SBATCH --output=slurm-%A_%a.out
{part}# Generated by python -m yade_scripts.generate --slurm: one array task per line of
# table.txt ({len(rows)} lines). Submit from this folder: sbatch slurm.sh
# By hand, one task: SLURM_ARRAY_TASK_ID=1 bash slurm.sh
#
# Cost model (yade_scripts/slurm.py, docs/scenes.md): steps x contacts x us per contact-step
#   {params['sample']}, {params['n_particles']} grains, kappa={params['kappa']:g}, I={params['inertial_number']:g}:
#   ~{est['steps']:.3g} steps x ~{est['contacts']:.3g} contacts x {US_PER_CONTACT_STEP[params['sample']]} us
#   (one core) = ~{est['core_hours']:.3g} core-hours per line
set -euo pipefail
HERE="${{RUN_DIR:-${{SLURM_SUBMIT_DIR:-$(cd "$(dirname "$0")" && pwd)}}}}"
LINES=({' '.join(lines)})
DESCS=({' '.join(shlex.quote(d) for d in descs)})
OUTS=({' '.join(shlex.quote(o) for o in outs)})
task="${{SLURM_ARRAY_TASK_ID:?SLURM_ARRAY_TASK_ID is not set (sbatch sets it)}}"
if ! [[ "$task" =~ ^[0-9]+$ ]] || (( task < 1 || task > ${{#LINES[@]}} )); then
    echo "slurm.sh: task $task: no such line (1..${{#LINES[@]}})" >&2; exit 2
fi
i=$((task - 1))
dir="$HERE/${{DESCS[$i]}}"
mkdir -p "$dir"
for f in {' '.join(shlex.quote(x) for x in links)}; do ln -sfn "../$f" "$dir/$f"; done
dump="$dir/${{OUTS[$i]}}"
complete() {{  # the dump's attribute complete=1, read by a Python that has h5py
    local py
    for py in /usr/bin/python3 python3; do
        if "$py" -c 'import h5py' 2>/dev/null; then
            "$py" -c 'import h5py, sys; sys.exit(0 if h5py.File(sys.argv[1], "r").attrs.get("complete", 0) else 1)' "$1" 2>/dev/null
            return $?
        fi
    done
    return 1
}}
if [[ -f "$dump" ]] && complete "$dump"; then
    echo "slurm.sh: ${{DESCS[$i]}}: $dump is complete, nothing to do"; exit 0
fi
cd "$dir"
export YADE_BATCH="$HERE/table.txt:${{LINES[$i]}}"
export OMP_WAIT_POLICY=PASSIVE
echo "slurm.sh: task $task = table line ${{LINES[$i]}} (${{DESCS[$i]}}) in $dir on ${{SLURM_CPUS_PER_TASK:-1}} core(s)"
set +e
yade -j "${{SLURM_CPUS_PER_TASK:-1}}" -n -x triaxial.py > "$dir/triaxial.log" 2>&1
status=$?
echo "slurm.sh: ${{DESCS[$i]}}: yade exit status $status (log $dir/triaxial.log)"
exit $status
"""
    path = os.path.join(folder, "slurm.sh")
    with open(path, "w") as fh:
        fh.write(text)
    os.chmod(path, 0o755)
    return path
