"""Speed against error: a sweep over stiffness, inertial number,
particle count (and, in the older ``quick`` plan, shape detail), for S1 and S2.

    python -m yade_scripts.campaign.sweeps --plan default --out runs/front [--jobs 2]

``make front`` runs the ``default`` plan (the sweep around the default
preset), also this command's default (:data:`DEFAULT_PLAN`).

Each sample gets one run folder ``OUT/<sample>`` (one scene, one table):
every table line overrides ``kappa``, ``inertial_number``, ``n_particles``,
``seed`` (``kernel`` plan: 3 seeds per point, seed-major, the same seed at
every point) and ``library`` (``shapes.h5`` is the standard library, 8-37
vertices, mean 20; ``shapes-low.h5`` holds grains of 8-12 vertices, mean
10, from the same generator). The lines run ``--jobs`` at a time, one
thread each, in table order (:func:`yade_scripts.launch.batch.run_batch`).
Complete dumps are not run again; a finished dump whose parameters differ
from its line's (a plan edited without renaming the line) is reported and
not used. Each dump is analysed (:func:`yade_scripts.campaign.study.analyse_dump`,
without standard errors or figures: the front reads its numbers; ``postproc
analyze DUMP`` draws one run's figures) and :func:`postproc.study.front.write_front`
writes ``OUT/front.csv`` (one row per run: cost and every quantity of the
study's comparison table), ``front-points.csv`` (means and 95 % intervals
over seeds), ``front-fit.csv`` (the extrapolation to kappa -> inf, I -> 0
and the default's bias per quantity), ``front-cost.csv`` (the cost model),
``front.png`` and ``front-trends.png``.
"""
from __future__ import annotations

import argparse
import json
import os
import sys

from ..launch.batch import dump_of, read_table, run_batch
from ..scene.parameters import SAMPLES, ConfigError, changed, coerce
from .generate import DEFAULT_LIBRARY, generate
from .study import analyse_dump

#: the plan ``make front`` and this command run unless told otherwise
DEFAULT_PLAN = "default"

# plan: {sample: [(description, overrides)]}; the first line is the reference
PLANS = {
    # the smoke test: two points per sample on the tiny preset
    "smoke": {"preset": "tiny", "common": {},
              "polyhedra": [("ref", {"kappa": 150.0, "inertial_number": 1e-2}),
                            ("low", {"kappa": 150.0, "inertial_number": 1e-2,
                                     "library": "shapes-low.h5"})],
              "spheres": [("ref", {"kappa": 300.0, "inertial_number": 5e-3}),
                          ("fast", {"kappa": 150.0, "inertial_number": 1e-2})]},
    # the front of docs/front.md: small samples sheared to eps_1 = 0.08
    "quick": {"preset": "soft", "common": {"final_strain": 0.08, "dump_strain": 0.005},
              "polyhedra": [
                  ("ref-k1000-I1e-2", {"kappa": 1000.0, "inertial_number": 1e-2, "n_particles": 24}),
                  ("k300-I1e-2", {"kappa": 300.0, "inertial_number": 1e-2, "n_particles": 24}),
                  ("k300-I2e-2", {"kappa": 300.0, "inertial_number": 2e-2, "n_particles": 24}),
                  ("k150-I2e-2", {"kappa": 150.0, "inertial_number": 2e-2, "n_particles": 24}),
                  ("k300-I2e-2-N12", {"kappa": 300.0, "inertial_number": 2e-2, "n_particles": 12}),
                  ("k300-I2e-2-low", {"kappa": 300.0, "inertial_number": 2e-2, "n_particles": 24,
                                      "library": "shapes-low.h5"})],
              "spheres": [
                  ("ref-k3000-I1e-3", {"kappa": 3000.0, "inertial_number": 1e-3, "n_particles": 1000}),
                  ("k1000-I5e-3", {"kappa": 1000.0, "inertial_number": 5e-3, "n_particles": 1000}),
                  ("k300-I1e-2", {"kappa": 300.0, "inertial_number": 1e-2, "n_particles": 1000}),
                  ("k300-I2e-2", {"kappa": 300.0, "inertial_number": 2e-2, "n_particles": 1000}),
                  ("k150-I2e-2", {"kappa": 150.0, "inertial_number": 2e-2, "n_particles": 1000}),
                  ("k300-I2e-2-N250", {"kappa": 300.0, "inertial_number": 2e-2, "n_particles": 250}),
                  ("k300-I2e-2-N4000", {"kappa": 300.0, "inertial_number": 2e-2, "n_particles": 4000})]},
}


def _grid(points, seeds, n_particles):
    """Plan lines for every (kappa, I[, N]) point and seed, seed-major: every
    point's first seeds come before any point's later seeds, so a plan cut
    short still has whole pairs. Descriptions ``k<kappa>-I<I>[-N<N>]-s<seed>``;
    the same seed at two points starts from the same grains and positions
    (paired differences)."""
    lines = []
    for seed in seeds:
        for p in points:
            kappa, inertial = p[0], p[1]
            n = p[2] if len(p) > 2 else n_particles
            tag = f"k{kappa:g}-I{inertial:g}" + (f"-N{n}" if n != n_particles else "")
            lines.append((f"{tag}-s{seed}", {"kappa": float(kappa), "inertial_number": float(inertial),
                                              "n_particles": n, "seed": seed}))
    return lines


# The front of docs/front.md: the soft preset (the earlier default, prepared as published)
# sheared to eps_1 = 0.3, 3 seeds per point; S1 at 200 grains (plus a
# 500-grain point at the default kappa, I), S2 at 1000 spheres (plus 4000).
# A kappa sweep at the default I, an I sweep at the default kappa and one
# corner (stiff and slow) to test that the two effects add.
KERNEL_POINTS = [(300, 2e-2), (100, 2e-2), (1000, 2e-2), (3000, 2e-2),
                 (300, 4e-2), (300, 1e-2), (300, 5e-3), (1000, 1e-2)]
# The 4000-sphere point has one seed: its frictionless compaction wanders
# (two seeds were stopped unconverged after 115 000 and 170 000 steps).
PLANS["kernel"] = {
    "preset": "soft", "common": {"final_strain": 0.3, "dump_strain": 0.01},
    "polyhedra": _grid(KERNEL_POINTS + [(300, 2e-2, 500)], (1, 2, 3), 200),
    "spheres": _grid(KERNEL_POINTS, (1, 2, 3), 1000) + _grid([(300, 2e-2, 4000)], (1,), 1000),
}
# The time-step sweep (python -m yade_scripts.campaign.timestep_sweep): S1 on the default
# preset (kappa = 3000, I = 5e-3) at 200 grains, the time step at 0.3 (the
# default when it was measured), 0.45 (today's default), 0.6 and 0.9 of the
# critical step, 3 seeds, seed-major; the
# same seed starts from the same grains and positions at every step.
TIMESTEP_SAFETIES = (0.3, 0.45, 0.6, 0.9)
PLANS["timestep"] = {
    "preset": "default", "common": {"n_particles": 200},
    "polyhedra": [(f"dt{s:g}-s{seed}", {"safety": s, "seed": seed})
                  for seed in (1, 2, 3) for s in TIMESTEP_SAFETIES],
    "spheres": [],
}
# The front around the default preset (docs/front.md; measured: docs/measurements.md,
# "The front at the default"): kappa = 3000, S1 at I = 5e-3 with 200 grains, S2 at I = 1e-3
# with 1000 spheres, 3 paired seeds per point. A kappa sweep 300, 1000, 3000,
# 10 000 at the default I, an I sweep at kappa = 3000 (S1 2.5e-3 to 2e-2, S2
# 5e-4 to 5e-3) and one corner per sample. "reference" is each sample's default point, the
# units of the fit (postproc.study.front.write_front). Both this plan and
# "facepair" keep the time step they were measured at (0.3 of the critical
# step, the default's then; the default's polyhedra now step at 0.45, whose
# difference from 0.3 is what the "timestep" plan measures).
MEASURED_SAFETY = 0.3
DEFAULT_FRONT_POINTS = {
    "polyhedra": [(3000, 5e-3), (300, 5e-3), (1000, 5e-3), (10000, 5e-3),
                  (3000, 1e-2), (3000, 2e-2), (1000, 1e-2), (3000, 2.5e-3)],
    "spheres": [(3000, 1e-3), (300, 1e-3), (1000, 1e-3), (10000, 1e-3),
                (3000, 5e-4), (3000, 2e-3), (3000, 5e-3), (1000, 2e-3)],
}
PLANS["default"] = {
    "preset": "default", "common": {"safety": MEASURED_SAFETY},
    "reference": {"polyhedra": [3000.0, 5e-3], "spheres": [3000.0, 1e-3]},
    "polyhedra": _grid(DEFAULT_FRONT_POINTS["polyhedra"], (1, 2, 3), 200),
    "spheres": _grid(DEFAULT_FRONT_POINTS["spheres"], (1, 2, 3), 1000),
}
# The face-pair tilt against the overlap thickness
# (python -m yade_scripts.campaign.facepair_sweep): S1 on the default preset at 200 grains,
# kappa 10 000, 3000, 1000 and 300 at the default I (longest first), sheared to
# eps_1 = 0.15, 3 seeds, seed-major; the same seed starts from the same grains
# and positions at every kappa.
FACEPAIR_KAPPAS = (10000.0, 3000.0, 1000.0, 300.0)
FACEPAIR_SEEDS = (1, 2, 3)
PLANS["facepair"] = {
    "preset": "default", "common": {"n_particles": 200, "final_strain": 0.15, "safety": MEASURED_SAFETY},
    "polyhedra": [(f"k{k:g}-s{seed}", {"kappa": k, "seed": seed})
                  for seed in FACEPAIR_SEEDS for k in FACEPAIR_KAPPAS],
    "spheres": [],
}
LOW_DETAIL = {"v_min": 8, "v_max": 12}


def low_detail_library(path, n=200, seed=0):
    """Write a library of grains with 8-12 vertices (mean 10), else the
    standard recipe: the "shape detail" axis of the front (``shapes-low.h5``
    of the ``smoke`` and ``quick`` plans)."""
    from shapes.generate import Recipe, generate_library
    from shapes.library import write_library

    recipe = Recipe(v_min=LOW_DETAIL["v_min"], v_max=LOW_DETAIL["v_max"])
    shapes, _ = generate_library(n, seed=seed, recipe=recipe)
    write_library(path, shapes, seed, recipe.as_dict(), {})


def write_table(folder, sample, lines):
    """Write a plan's lines for one sample as the run folder's
    ``table.txt``: one line per point, its overrides as columns.

    Parameters
    ----------
    folder : str
        The run folder (it exists).
    sample : {"polyhedra", "spheres"}
        The sample, in front of each description and dump name.
    lines : list of (str, dict)
        (description, {parameter: value}) per point, as in :data:`PLANS`.
        Every line must give every column that one line gives, but
        ``library`` (default ``shapes.h5``).

    Returns
    -------
    None

    Raises
    ------
    ConfigError
        A line without a value for a column, or a value that is not valid
        (:func:`yade_scripts.scene.parameters.coerce`).

    Examples
    --------
    >>> import os, tempfile
    >>> d = tempfile.mkdtemp()
    >>> write_table(d, "spheres", [("ref", {"kappa": 300.0, "inertial_number": 5e-3}),
    ...                            ("fast", {"kappa": "150", "inertial_number": 1e-2})])
    >>> print(open(os.path.join(d, "table.txt")).read(), end="")
    description inertial_number kappa library out
    spheres-ref 0.005 300.0 'shapes.h5' 'spheres-ref.h5'
    spheres-fast 0.01 150.0 'shapes.h5' 'spheres-fast.h5'
    """
    keys = sorted({k for _, o in lines for k in o} | {"library"})
    with open(os.path.join(folder, "table.txt"), "w") as fh:
        fh.write(" ".join(["description"] + keys + ["out"]) + "\n")
        for desc, o in lines:
            vals = []
            for k in keys:
                v = o.get(k, "shapes.h5" if k == "library" else None)
                if v is None:
                    raise ConfigError(f"front line {desc}: no value for {k}")
                if k != "library":
                    v = coerce(k, v)
                vals.append(repr(v))
            fh.write(" ".join([f"{sample}-{desc}"] + vals + [repr(f"{sample}-{desc}.h5")]) + "\n")


def _stale(dump, overrides):
    """The parameters of a finished dump that differ from its line's
    overrides (:func:`yade_scripts.scene.parameters.changed`): a plan edited
    without renaming its line is never silently reused."""
    from postproc.schema import DumpReader

    with DumpReader(dump) as r:
        par = r.parameters
    return changed(par, overrides, names=overrides)


#: the cheap sample first
FRONT_SAMPLES = SAMPLES[::-1]


def run_front(out, plan, jobs=2, library=None, samples=FRONT_SAMPLES):
    """Run a sweep: for each sample, generate its run folder ``OUT/<sample>``
    on the plan's preset (unless it is there), write the plan's lines as its
    table (:func:`write_table`), run the unfinished lines
    (:func:`yade_scripts.launch.batch.run_batch`) and analyse each complete dump
    that has no analysis yet into ``analysis-<description>/``
    (:func:`yade_scripts.campaign.study.analyse_dump`, without standard errors or
    figures). A
    complete dump made with parameters other than its line's is reported
    and not analysed (status "stale dump"). The plan goes to
    ``OUT/front-plan.json``; the front's tables and figures are
    :func:`postproc.study.front.write_front`'s (``main`` calls it).

    Parameters
    ----------
    out : str
        The sweep's folder.
    plan : str
        One of :data:`PLANS` ("default", "kernel", "timestep", "facepair",
        "quick", "smoke").
    jobs : int
        Cores of each sample's schedule (runs at a time, one thread each).
    library : str, optional
        The polyhedra's shape library (default
        :data:`yade_scripts.campaign.generate.DEFAULT_LIBRARY`).
    samples : sequence of str
        The samples to run, in this order (default: spheres, the cheap one,
        first).

    Returns
    -------
    dict
        sample -> {description: status}: 0 complete, else the exit code or
        the reason (:func:`yade_scripts.launch.pool.run_pool`), or "stale dump".

    Raises
    ------
    ConfigError
        An unknown plan, a bad table line, or no ``yade`` on the PATH.

    Examples
    --------
    The ``timestep`` plan sweeps the polyhedra's time step only: for the
    spheres it makes the folder and an empty table, and runs nothing (but
    ``yade`` must be on the PATH).

    >>> import json, os, tempfile
    >>> out = tempfile.mkdtemp()
    >>> run_front(out, "timestep", samples=("spheres",))
    {'spheres': {}}
    >>> sorted(os.listdir(out)), json.load(open(os.path.join(out, "front-plan.json")))["preset"]
    (['front-plan.json', 'spheres'], 'default')
    >>> run_front(out, "fastest")
    Traceback (most recent call last):
        ...
    yade_scripts.scene.parameters.ConfigError: unknown plan 'fastest'; choose from ['default', 'facepair', ...]
    """
    if plan not in PLANS:
        raise ConfigError(f"unknown plan {plan!r}; choose from {sorted(PLANS)}")
    spec = PLANS[plan]
    status = {}
    for s in samples:
        folder = os.path.join(out, s)
        if not os.path.exists(os.path.join(folder, "triaxial.py")):
            generate(folder, spec["preset"], s, spec["common"], library=library or DEFAULT_LIBRARY)
        if s == "polyhedra" and any(o.get("library") == "shapes-low.h5" for _, o in spec[s]):
            low = os.path.join(folder, "shapes-low.h5")
            if not os.path.exists(low):
                low_detail_library(low)
        write_table(folder, s, spec[s])
        st = run_batch(folder, jobs=jobs, tag=s, echo=lambda m: print(m, flush=True))
        status[s] = {}
        overrides = {f"{s}-{desc}": o for desc, o in spec[s]}
        for _, r in read_table(folder):
            dump = dump_of(folder, r)
            d = r["description"]
            stale = st.get(d) == 0 and os.path.exists(dump) and _stale(dump, overrides.get(d, {}))
            if stale:
                print(f"[{s}] {d}: {dump} was made with other parameters ({', '.join(stale)}); "
                      f"delete it to rerun", flush=True)
                st[d] = "stale dump"
            if st.get(d) == 0 and os.path.exists(dump):
                ana = os.path.join(folder, "analysis-" + d)
                if not os.path.exists(os.path.join(ana, "summary.csv")):
                    analyse_dump(dump, ana, errors=False, figures=False)
            status[s][d] = st.get(d)
    with open(os.path.join(out, "front-plan.json"), "w") as fh:
        json.dump({"plan": plan, **{k: v for k, v in spec.items()}}, fh, indent=1)
    return status


def main(argv=None):
    """``python -m yade_scripts.campaign.sweeps --plan PLAN --out OUT [--jobs N]``:
    :func:`run_front`, then :func:`postproc.study.front.write_front`, whose
    table it prints.

    Parameters
    ----------
    argv : list of str, optional
        The command line's arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit code: 0 every run done; 1 a run failed (or its dump is
        stale); 2 invalid options.
    """
    ap = argparse.ArgumentParser(prog="python -m yade_scripts.campaign.sweeps", description=__doc__.splitlines()[0])
    ap.add_argument("--plan", default=DEFAULT_PLAN, help=f"one of {sorted(PLANS)} (default {DEFAULT_PLAN})")
    ap.add_argument("--out", required=True)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--library")
    ap.add_argument("--samples", nargs="+", default=list(FRONT_SAMPLES), choices=SAMPLES)
    args = ap.parse_args(argv)
    from shapes.library import LibraryError

    try:
        status = run_front(args.out, args.plan, args.jobs, args.library, args.samples)
    except (ConfigError, LibraryError) as exc:      # LibraryError: the low-detail library not written
        print(f"front: error: {exc}", file=sys.stderr)
        return 2
    from postproc.study.front import write_front

    table = write_front(args.out)
    print(table.to_string(index=False), flush=True)
    failed = [f"{s} {d}" for s, st in status.items() for d, c in st.items() if c != 0]
    if failed:
        print(f"front: failed runs: {', '.join(failed)}", file=sys.stderr)
        return 1
    print(f"front: {args.out}/front.csv and front.png", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
