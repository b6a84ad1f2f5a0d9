"""The study: run S1 and S2, analyse every dump, write the report.

    python -m yade_scripts.study --preset default --out runs/study [--ensemble N]

One seed (default): each sample gets its run folder (``OUT/polyhedra``,
``OUT/spheres``) and both run side by side, YADE's progress lines relayed
with the sample name in front. S1 with the compiled contact kernel runs as
``yade -j2`` (the kernel takes YADE's thread count; S2 is over in seconds,
then S1 has both cores); S2, and S1 on YADE's stock contacts (which crashed
with several threads), run on one thread. ``--ensemble N`` (N >= 2):
each sample gets ``OUT/<sample>-ensemble`` with a yade-batch table of seeds
1..N, and the seeds of both samples run in one schedule on ``--jobs`` cores
(:mod:`yade_scripts.pool`: longest first, no core idle at the end;
``OUT/schedule.json`` holds its attempts and idle core-time). Complete dumps are never run again, so a rerun only does what is
missing. Every dump is analysed (:func:`postproc.pipeline.analyze_path`, what
``postproc analyze`` runs) into an analysis
folder, and every usable S1 dump once more per other contact count
(:func:`postproc.study.counts.analyse_counts`, claim 6's steady window); ``OUT/manifest.json`` lists the runs and their status, and
the report (:func:`postproc.study.report.build_report`) goes to ``OUT/report/``. A failed run is reported and
everything else still builds; the exit code is non-zero when a run failed.
"""
from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import threading

from .batch import MAX_RESUMES, clear_attempt, has_checkpoint, resumable, yade_env
from .generate import DEFAULT_LIBRARY, generate, parse_overrides, write_seed_table
from .presets import ConfigError, resolve
from .resources import check_memory, memory_mb

SAMPLES = ("polyhedra", "spheres")


def finished(folder):
    """True when the folder holds a complete dump and its run.info.json."""
    from .batch import complete

    return os.path.exists(os.path.join(folder, "run.info.json")) and \
        complete(os.path.join(folder, "run.h5"))


def _set_aside_if_changed(folder, preset, sample, overrides):
    """A run folder made with other parameters is renamed FOLDER.old-K, so
    that the run is generated afresh (and never silently reused)."""
    path = os.path.join(folder, "params.json")
    if not os.path.exists(path):
        return
    import json

    with open(path) as fh:
        old = json.load(fh)
    new = {"preset": preset, **resolve(preset, sample, overrides)}
    if old == json.loads(json.dumps(new)):
        return
    k = 1
    while os.path.exists(f"{folder}.old-{k}"):
        k += 1
    os.rename(folder, f"{folder}.old-{k}")
    print(f"[{sample}] parameters changed: previous run kept as {folder}.old-{k}", flush=True)


def _relay(name, proc, logpath):
    with open(logpath, "a") as log:
        for line in proc.stdout:
            log.write(line)
            log.flush()
            if line.startswith("triaxial.py:"):
                print(f"[{name}] {line[len('triaxial.py: '):].rstrip()}", flush=True)


def _threads(sample, preset, overrides):
    """YADE threads of a single run: all cores for the polyhedra kernel, one
    otherwise."""
    p = resolve(preset, sample, overrides)
    if sample == "polyhedra" and p["contact_engine"] == "kernel":
        return os.cpu_count() or 1
    return 1


def _run_with_resumes(name, cmd, folder, result):
    """Run ``cmd`` in ``folder``; a run that crashed or was stopped by SIGTERM
    and left a checkpoint is started again (it resumes from the checkpoint),
    up to MAX_RESUMES times. result[name] = (last exit code, [exit codes])."""
    codes = []
    while True:
        proc = subprocess.Popen(cmd, cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                stdin=subprocess.DEVNULL, text=True, bufsize=1, env=yade_env())
        _relay(name, proc, os.path.join(folder, "yade.log"))
        codes.append(proc.wait())
        if codes[-1] == 0 or not resumable(codes[-1], os.path.join(folder, "run.h5")) \
                or len(codes) > MAX_RESUMES:
            break
        print(f"[{name}] exit {codes[-1]}: resuming from its checkpoint "
              f"(resume {len(codes)} of at most {MAX_RESUMES})", flush=True)
    result[name] = (codes[-1], codes)


def run_samples(out, preset, overrides=None, library=None, samples=SAMPLES, attempts=None):
    """Generate (if needed) and run the samples in parallel; returns
    {sample: return code (0 = done or already done)}. A crashed run is
    resumed from its checkpoint up to MAX_RESUMES times; ``attempts`` (a
    dict), when given, receives {sample: [exit code of each attempt]}."""
    yade = shutil.which("yade")
    if yade is None:
        raise ConfigError("yade is not installed (make installs Debian's yade)")
    procs = {}
    results = {}
    for s in samples:
        folder = os.path.join(out, s)
        _set_aside_if_changed(folder, preset, s, overrides)
        if finished(folder):
            print(f"[{s}] already complete in {folder}, not run again", flush=True)
            continue
        if os.path.exists(os.path.join(folder, "triaxial.py")):
            if has_checkpoint(os.path.join(folder, "run.h5")):
                print(f"[{s}] an unfinished run with a checkpoint: resuming it", flush=True)
            else:
                clear_attempt(os.path.join(folder, "run.h5"))   # an unfinished attempt; its log is kept
        else:
            generate(folder, preset, s, overrides, library=library or DEFAULT_LIBRARY)
        threads = _threads(s, preset, overrides)
        t = threading.Thread(target=_run_with_resumes, daemon=True,
                             args=(s, [yade, "-j", str(threads), "-n", "-x", "triaxial.py"], folder, results))
        t.start()
        procs[s] = t
    codes = {s: 0 for s in samples}
    for s, t in procs.items():
        t.join()
        codes[s], tries = results[s]
        if attempts is not None:
            attempts[s] = tries
        status = "done" if codes[s] == 0 else f"FAILED (exit {codes[s]}, see {os.path.join(out, s, 'yade.log')})"
        print(f"[{s}] {status}" + (f" after {len(tries) - 1} resume(s) (exits {tries})" if len(tries) > 1 else ""),
              flush=True)
    return codes


def run_ensemble(out, preset, n, overrides=None, library=None, jobs=2, samples=SAMPLES, job_threads=None):
    """Seeds 1..n of each sample on ``jobs`` cores through one schedule
    (:func:`yade_scripts.pool.run_pool`: longest runs first, the seeds of
    both samples interleaved, a freed core given to a running polyhedra
    run once none waits; the schedule and its idle core-time go to
    ``OUT/schedule.json``). Returns {sample: [(label, dump path, status)]}
    (status 0 = complete). ``job_threads``: {sample: threads a job starts
    on} (default one each)."""
    from .batch import dump_of, read_table
    from .pool import Job, run_pool
    from .slurm import estimate

    pool, rows = [], {}
    for s in samples:
        folder = os.path.join(out, f"{s}-ensemble")
        _set_aside_if_changed(folder, preset, s, overrides)
        seeds = list(range(1, n + 1))
        if not os.path.exists(os.path.join(folder, "triaxial.py")):
            generate(folder, preset, s, overrides, seeds=seeds, library=library or DEFAULT_LIBRARY)
        else:                      # same parameters, maybe another n: rewrite the table only
            write_seed_table(folder, s, seeds)
        p = resolve(preset, s, overrides)
        cost = estimate(p)["core_hours"] * 3600
        rows[s] = read_table(folder)
        pool += [Job(folder, k, r["description"], dump_of(folder, r), cost, tag=s,
                     widen=(s == "polyhedra" and p["contact_engine"] == "kernel"),
                     threads=min((job_threads or {}).get(s, 1), jobs))
                 for k, r in rows[s]]
    status = run_pool(pool, jobs, record=os.path.join(out, "schedule.json"), echo=lambda m: print(m, flush=True))
    for job in pool:
        if job.exits:
            ATTEMPTS[(job.tag, f"seed {job.description.rsplit('seed', 1)[1]}")] = list(job.exits)
    return {s: [(f"seed {r['seed']}", dump_of(os.path.join(out, f"{s}-ensemble"), r), status[r["description"]])
                for _, r in rows[s]] for s in samples}


#: exit codes of every attempt of the runs of this study, {(sample, label): [codes]}
ATTEMPTS = {}


def partial_progress(dump):
    """How far an unfinished run got: {"eps_1_reached", "final_strain",
    "steady_from_eps_1", "steady_snapshots"} from its dump (eps_1 = ln(H_iso /
    H) of each shear snapshot against the isotropic one), or None when the
    dump is unreadable or has no isotropic snapshot. The steady state starts
    at STEADY_START x final_strain in eps_1 (the report's steady window,
    eps_q >= STEADY_START x its final value, in the axial strain)."""
    import json

    import numpy as np
    from postproc.schema import DumpFormatError, DumpReader
    from postproc.statistics import STEADY_START

    try:
        with DumpReader(dump) as r:
            final = float(r.parameters["final_strain"])
            snaps = [(s.stage, float(s.box_lengths[2])) for s in (r.read(i) for i in range(len(r)))]
    except (DumpFormatError, KeyError, OSError, ValueError, json.JSONDecodeError):
        return None
    iso = [h for stage, h in snaps if stage == "isotropic"]
    if not iso:
        return None
    eps = np.array([np.log(iso[0] / h) for stage, h in snaps if stage == "shear"])
    start = STEADY_START * final
    return {"eps_1_reached": float(eps.max()) if len(eps) else 0.0, "final_strain": final,
            "steady_from_eps_1": start, "steady_snapshots": int(np.sum(eps >= start - 1e-9))}


def analyse_and_report(out, runs, attempts=None):
    """Analyse every dump of ``runs`` = {sample: [(label, dump, status)]},
    write OUT/manifest.json and the report; returns the list of failures.

    A failed run whose dump got past the start of the steady state (two
    shear snapshots or more with eps_1 >= STEADY_START x final_strain, see
    :func:`partial_progress`) is analysed and marked ``partial``: the report
    uses its steady snapshots and says how far it got. ``attempts``
    {(sample, label): [exit code of each attempt]} (default: this study's)
    goes into the manifest when a run was resumed."""
    import json

    from postproc.pipeline import BAD_INPUT, analyze_path
    from postproc.study.counts import analyse_counts
    from postproc.study.report import build_report

    def analyse(dump, analysis):
        """The dump's analysis into ``analysis``; None when it worked (some
        bad snapshots allowed: they are in analysis/errors.txt), else the
        one-line reason."""
        try:
            _, problems = analyze_path(dump, analysis, progress=False)
        except BAD_INPUT as exc:
            print(f"[study] analysis of {dump} failed: {exc}", flush=True)
            return str(exc)
        for line in problems:
            print(f"[study] {dump}: {line}", flush=True)
        return None if os.path.exists(os.path.join(analysis, "summary.csv")) else "no summary.csv written"

    attempts = ATTEMPTS if attempts is None else attempts
    manifest, failed = {}, []
    for s, items in runs.items():
        manifest[s] = []
        for label, dump, status in items:
            stem = os.path.splitext(dump)[0]
            folder = os.path.dirname(dump)
            analysis = os.path.join(folder, "analysis" if os.path.basename(stem) == "run"
                                    else "analysis-" + os.path.basename(stem))
            info = stem + ".info.json"
            extra = {}
            tries = attempts.get((s, label), [])
            if len(tries) > 1:
                extra["attempts"] = tries
                extra["note"] = f"resumed {len(tries) - 1} time(s) from its checkpoint (exits {tries})"
            progress = partial_progress(dump) if status != 0 and os.path.exists(dump) else None
            if status != 0 and progress and progress["steady_snapshots"] >= 2:
                print(f"[{s}] analysing {label} (partial, reached eps_1 = {progress['eps_1_reached']:.3f}): {dump}",
                      flush=True)
                bad = analyse(dump, analysis)
                if bad is None:
                    why = "partial"
                    extra["partial"] = progress
                    extra["note"] = (f"run failed (exit {status}) at eps_1 = {progress['eps_1_reached']:.3f} of "
                                     f"{progress['final_strain']:g}; its {progress['steady_snapshots']} steady "
                                     f"snapshots (eps_1 >= {progress['steady_from_eps_1']:.3f}) are used"
                                     + (f"; {extra['note']}" if "note" in extra else ""))
                else:
                    why = f"run failed ({status}) and its partial dump could not be analysed ({bad})"
                failed.append(f"{s} {label}")
            elif status != 0:
                got = (f"; it reached eps_1 = {progress['eps_1_reached']:.3f}, before the steady state "
                       f"(eps_1 >= {progress['steady_from_eps_1']:.3f})") if progress else ""
                why = f"run failed ({status}){got}; see {folder}"
                failed.append(f"{s} {label}")
            elif not os.path.exists(dump):
                why = "no dump"
                failed.append(f"{s} {label}")
            else:
                print(f"[{s}] analysing {label}: {dump}", flush=True)
                bad = analyse(dump, analysis)
                why = "ok" if bad is None else f"analysis failed ({bad})"
                if why != "ok":
                    failed.append(f"{s} {label}")
            if s == "polyhedra" and why in ("ok", "partial"):     # claim 6 by the other contact counts
                done, bad = analyse_counts(dump, analysis)
                for line in bad:
                    print(f"[study] {line}", flush=True)
                extra["counts"] = {c: os.path.relpath(f, out) for c, f in done.items()}
            manifest[s].append({"label": label, "dump": os.path.relpath(dump, out),
                                "analysis": os.path.relpath(analysis, out),
                                "info": os.path.relpath(info, out), "status": why, **extra})
    with open(os.path.join(out, "manifest.json"), "w") as fh:
        json.dump(manifest, fh, indent=1)
    path = build_report(out)
    print(f"[study] report written to {path} (and report.html)", flush=True)
    return failed


def unusable_samples(out):
    """Samples of OUT/manifest.json with no run that is ok or partial."""
    import json

    with open(os.path.join(out, "manifest.json")) as fh:
        manifest = json.load(fh)
    return [s for s, rs in manifest.items() if not any(r["status"] in ("ok", "partial") for r in rs)]


def collect(folder):
    """Analyse and report whatever has finished in the generated run folders
    at or below ``folder`` (each with a yade-batch ``table.txt``; dumps in
    the line's own folder, as the SLURM array of ``generate --slurm``
    writes them, or next to the table, as yade-batch does). Writes
    FOLDER/manifest.json and FOLDER/report/. Returns (runs analysed as
    {sample: [(label, dump, 0)]}, lines not finished, failures)."""
    import json

    from .batch import complete, dump_of, read_table

    if not os.path.isdir(folder):
        raise ConfigError(f"{folder}: no such folder")
    tables = [folder] if os.path.exists(os.path.join(folder, "table.txt")) else sorted(
        os.path.join(folder, d) for d in os.listdir(folder)
        if os.path.exists(os.path.join(folder, d, "table.txt")))
    if not tables:
        raise ConfigError(f"{folder}: no generated run folder (table.txt) in it or one level below")
    runs, pending = {}, []
    for t in tables:
        try:
            with open(os.path.join(t, "params.json")) as fh:
                sample = json.load(fh)["sample"]
        except (OSError, ValueError, KeyError):
            raise ConfigError(f"{t}: params.json missing or without 'sample'") from None
        for _, r in read_table(t):
            d = r["description"]
            own = os.path.join(t, d, os.path.basename(dump_of(t, r)))
            dump = own if os.path.exists(own) or not os.path.exists(dump_of(t, r)) else dump_of(t, r)
            label = f"seed {r['seed']}" if "seed" in r else d
            if len(tables) > 1:
                label = f"{os.path.basename(t)} {label}"
            if complete(dump):
                runs.setdefault(sample, []).append((label, dump, 0))
            else:
                pending.append(f"{os.path.relpath(os.path.join(t, d), folder)} "
                               f"({'unfinished' if os.path.exists(dump) else 'not started'})")
    for p in pending:
        print(f"study: not finished: {p}", file=sys.stderr)
    if not runs:
        raise ConfigError(f"{folder}: no run has finished yet ({len(pending)} pending)")
    failed = analyse_and_report(folder, runs)
    return runs, pending, failed


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m yade_scripts.study", description=__doc__.splitlines()[0])
    ap.add_argument("--preset", default="default")
    ap.add_argument("--out", help="study folder (required unless --collect)")
    ap.add_argument("--collect", metavar="DIR",
                    help="analyse and report whatever has finished in the run folders of DIR "
                         "(e.g. a SLURM array from generate --slurm), run nothing")
    ap.add_argument("--set", action="append", metavar="NAME=VALUE")
    ap.add_argument("--library")
    ap.add_argument("--ensemble", type=int, default=1, help="seeds per sample (>= 2: one schedule over both samples)")
    ap.add_argument("--jobs", type=int, default=2, help="cores of the schedule (ensembles)")
    ap.add_argument("--job-threads", type=int, default=1,
                    help="YADE threads a polyhedra job of an ensemble starts on (the kernel's OpenMP "
                         "threads; sphere jobs use one): e.g. --jobs 16 --job-threads 2 on a 16-core node")
    args = ap.parse_args(argv)
    if args.collect:
        try:
            runs, pending, failed = collect(args.collect)
        except ConfigError as exc:
            print(f"study: error: {exc}", file=sys.stderr)
            return 2
        n = sum(len(v) for v in runs.values())
        print(f"study: collected {n} finished run(s), {len(pending)} not finished; report in "
              f"{args.collect}/report/report.md", file=sys.stderr)
        return 1 if failed else 0
    if not args.out:
        ap.error("--out is required (unless --collect)")
    try:
        if args.ensemble < 1:
            raise ConfigError(f"--ensemble must be >= 1, got {args.ensemble}")
        overrides = parse_overrides(args.set)
        params = [resolve(args.preset, s, overrides) for s in SAMPLES]
        # at once: both samples (one seed), or --jobs runs of the largest (ensembles)
        check_memory(params if args.ensemble == 1 else
                     [max(params, key=memory_mb)] * min(args.jobs, args.ensemble * len(SAMPLES)))
        os.makedirs(args.out, exist_ok=True)
        if args.ensemble == 1:
            tries = {}
            codes = run_samples(args.out, args.preset, overrides, args.library, attempts=tries)
            ATTEMPTS.update({(s, "seed 1"): t for s, t in tries.items()})
            runs = {s: [("seed 1", os.path.join(args.out, s, "run.h5"), c)] for s, c in codes.items()}
        else:
            if args.jobs < 1 or args.job_threads < 1:
                raise ConfigError(f"--jobs and --job-threads must be >= 1, got {args.jobs} and {args.job_threads}")
            runs = run_ensemble(args.out, args.preset, args.ensemble, overrides, args.library, args.jobs,
                                job_threads={"polyhedra": args.job_threads})
    except ConfigError as exc:
        print(f"study: error: {exc}", file=sys.stderr)
        return 2
    failed = analyse_and_report(args.out, runs)
    missing = unusable_samples(args.out)
    if failed:
        print(f"study: failed: {', '.join(failed)} (the report lists them; partial runs are used)", file=sys.stderr)
    if missing:
        print(f"study: no usable run of {', '.join(missing)}: see the yade.log of its run folder under "
              f"{args.out}; run the same command again to resume from the checkpoints (a blow-up, exit 3, needs "
              f"other parameters, e.g. a smaller safety), or delete the folder to start it afresh", file=sys.stderr)
        return 1
    print(f"study: report in {args.out}/report/report.md (and report.html)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
