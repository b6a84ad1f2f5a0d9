"""The study: run S1 and S2, analyse every dump, write the report.

    python -m yade_scripts.campaign.study --preset default --out runs/study [--ensemble N]

One seed (default): each sample gets its run folder (``OUT/polyhedra``,
``OUT/spheres``) and both run side by side, YADE's lines relayed with the
sample name in front. S1 with the compiled contact kernel runs as ``yade
-jN`` with N every core of the machine (the kernel takes YADE's thread
count; S2 is over in minutes, then S1 has every core); S2, and S1 on YADE's
stock contacts (which crashed with several threads), run on one thread. ``--ensemble N`` (N >= 2): each sample
gets ``OUT/<sample>-ensemble`` with a table of seeds 1..N, and the seeds of
both samples run in one schedule on ``--jobs`` cores (longest first, no
core idle at the end; ``OUT/schedule.json`` holds its attempts and idle
core-time). Both go through :mod:`yade_scripts.launch.pool`, the one loop that
runs, resumes and records every run (:mod:`yade_scripts.runs.runstate`). Complete
dumps are never run again, so a rerun only does what is missing; a folder
made with other parameters is refused (renamed ``.old-K`` and started
afresh only with ``--set-aside``). ``--dry-run`` (ensembles) says what a
study would take from ``--archive`` and what it would run, and runs and
writes nothing. Every dump is analysed
(:func:`analyse_dump`: :func:`postproc.pipeline.analyze_path`, what
``postproc analyze`` runs) into an analysis folder, and every usable S1
dump once more per other contact count (``--counts``, default LMGC90's,
:func:`postproc.study.counts.analyse_counts`, claim 6's steady window):
as soon as its run is complete, on a core that no waiting run needs (the
pool's work after a run, ``--analyse DUMP``), so that the analyses fill
the cores the last runs leave idle; the pass over all dumps at the end
keeps every analysis made from the same dump, options and code
(:mod:`postproc.provenance`), so a rerun analyses only what changed;
``OUT/manifest.json`` lists the runs and their status, and the report
(:func:`postproc.study.report.build_report`) goes to ``OUT/report/``. A
failed run is reported and everything else still builds. Exit codes: 0
when every sample has a usable run (a failed run is then listed in the
report); 1 when a sample has none; 2 for invalid options; 4 when another
process writes the folder or one of its runs, or (``--collect``) its
manifest and report (nothing touched); 75 when
stopped (SIGTERM, Ctrl-C: run the same command again to resume).
"""
from __future__ import annotations

import argparse
import functools
import json
import os
import shutil
import sys

from ..launch.batch import dump_of, read_table, table_lines
from ..launch.pool import Job, run_pool
from ..launch.resources import check_memory, memory_mb
from ..launch.slurm import ON_A_NODE, estimate, queue_detail, queue_states
from ..runs.runlock import RunBusy, RunLock, describe
from ..runs.runstate import EXIT_BUSY, EXIT_TERM, complete, read_attempts, state_of
from ..scene.parameters import SAMPLES, changed
from .archive_store import archived, conflicts, save
from .generate import DEFAULT_LIBRARY, generate, parse_overrides, write_seed_table
from .presets import ConfigError, resolve
from .runfolders import SET_ASIDE, analysis_folder, line_dump, run_folders, whole  # noqa: F401 (names of the study)


#: the status of a run taken from an archive of analysed runs (:mod:`yade_scripts.campaign.archive`)
ARCHIVED = "archived"
#: the lock on a folder's manifest and report (:func:`report_lock`)
REPORT_LOCK = "report.lock"
#: seconds between two tries of a report lock the study waits for: under
#: the time a collect takes from its start to the lock (about 0.3 s of
#: interpreter and imports), so that collects run back to back do not keep
#: the study out
REPORT_WAIT_SECONDS = 0.1


def finished(folder):
    """True when the folder holds a complete dump and its run.info.json."""
    return os.path.exists(os.path.join(folder, "run.info.json")) and complete(os.path.join(folder, "run.h5"))


def _set_aside_if_changed(folder, preset, sample, overrides, set_aside=False):
    """A run folder made with other parameters (its params.json against the
    preset's, :func:`yade_scripts.scene.parameters.changed`) is never reused: with
    ``set_aside`` it is renamed FOLDER.old-K, so that the run is generated
    afresh; without, ConfigError (one line naming the folder, the changed
    parameters and the way out), and nothing is renamed."""
    path = os.path.join(folder, "params.json")
    if not os.path.exists(path):
        return
    with open(path) as fh:
        old = json.load(fh)
    names = changed(old, {"preset": preset, **resolve(preset, sample, overrides)})
    if not names:
        return
    if not set_aside:
        raise ConfigError(f"{folder}: a run folder of other parameters ({', '.join(names)}); nothing renamed "
                          "or run: give another study folder (STUDY=DIR, --out DIR), or ask to keep it as "
                          f"{os.path.basename(folder)}.old-K and start afresh (SET_ASIDE=1, --set-aside)")
    k = 1
    while os.path.exists(f"{folder}.old-{k}"):
        k += 1
    os.rename(folder, f"{folder}.old-{k}")       # SET_ASIDE
    print(f"[{sample}] parameters changed ({', '.join(names)}): previous run kept as {folder}.old-{k}", flush=True)


def _threads(sample, preset, overrides):
    """YADE threads of a single run: all cores for the polyhedra kernel, one
    otherwise."""
    p = resolve(preset, sample, overrides)
    if sample == "polyhedra" and p["contact_engine"] == "kernel":
        return os.cpu_count() or 1
    return 1


def _need_yade():
    if shutil.which("yade") is None:
        raise ConfigError("yade is not installed (make installs Debian's yade)")


def run_samples(out, preset, overrides=None, library=None, samples=SAMPLES, counts=None, figures=True,
                set_aside=False):
    """Run one seed of each sample side by side: the study of ``python -m
    yade_scripts.campaign.study`` with one seed (``--ensemble 1``).

    Each sample's run folder ``OUT/<sample>`` is generated when it is not
    there (:func:`yade_scripts.campaign.generate.generate`); one made with other
    parameters is refused (ConfigError, nothing renamed) or, with
    ``set_aside``, first set aside as ``OUT/<sample>.old-K``; one that
    holds a complete dump and its ``run.info.json`` is not run again. The
    others run at once through :func:`yade_scripts.launch.pool.run_pool`, each on
    its own threads (polyhedra on the compiled kernel: every core of the
    machine; otherwise one), every scene line relayed with the sample in
    front and kept in the folder's ``yade.log``; a crashed run is resumed
    from its checkpoint as the pool's rule says, and each complete dump is
    analysed on a free core (:func:`analyse_after`). The report is
    :func:`analyse_and_report`'s.

    Parameters
    ----------
    out : str
        The study's folder.
    preset : str
        A preset of :data:`yade_scripts.campaign.presets.PRESETS`.
    overrides : dict, optional
        name -> value (or its text), applied to both samples.
    library : str, optional
        The polyhedra's shape library (default
        :data:`yade_scripts.campaign.generate.DEFAULT_LIBRARY`).
    samples : sequence of str
        The samples to run (default both, S1 and S2).
    counts : sequence of str, optional
        The other contact counts each complete S1 dump is analysed with
        (default :data:`postproc.study.counts.EXTRA_COUNTS`).
    figures : bool, optional
        Draw the analyses' figures (default; False: numbers only).

    Returns
    -------
    dict
        sample -> status: 0 done (now or already), else the exit code or
        the reason (:func:`yade_scripts.launch.pool.run_pool`).

    Raises
    ------
    ConfigError
        No ``yade`` on the PATH, or invalid parameters.
    yade_scripts.runs.runlock.RunBusy
        Another process writes one of the runs; nothing was touched.

    Examples
    --------
    A study whose spheres run is complete (here an empty dump, closed by
    :class:`postproc.schema.DumpWriter`, standing in for the finished run)
    does not run it again, and starts nothing; ``yade`` must still be on
    the PATH.

    >>> import os, tempfile
    >>> from postproc.schema import DumpWriter
    >>> from yade_scripts.campaign.generate import generate
    >>> out = tempfile.mkdtemp()
    >>> _ = generate(os.path.join(out, "spheres"), "tiny", "spheres")
    >>> DumpWriter(os.path.join(out, "spheres", "run.h5"), "spheres", {}).close()
    >>> _ = open(os.path.join(out, "spheres", "run.info.json"), "w").write("{}")
    >>> run_samples(out, "tiny", samples=("spheres",))
    [spheres] already complete in .../spheres, not run again
    {'spheres': 0}
    """
    _need_yade()
    jobs = []
    if not set_aside:                  # every sample's folder checked before any is touched
        for s in samples:
            _set_aside_if_changed(os.path.join(out, s), preset, s, overrides)
    for s in samples:
        folder = os.path.join(out, s)
        _set_aside_if_changed(folder, preset, s, overrides, set_aside)
        if finished(folder):
            print(f"[{s}] already complete in {folder}, not run again", flush=True)
            continue
        if not os.path.exists(os.path.join(folder, "triaxial.py")):
            generate(folder, preset, s, overrides, library=library or DEFAULT_LIBRARY)
        jobs.append(Job(folder, None, s, os.path.join(folder, "run.h5"), tag=s, threads=_threads(s, preset, overrides),
                        log=os.path.join(folder, "yade.log"), echo_all=True))
    status = run_pool(jobs, max(1, sum(j.threads for j in jobs)), echo=lambda m: print(m, flush=True),
                      after=functools.partial(analyse_after, counts=counts, figures=figures)) if jobs else {}
    return {s: status.get(s, 0) for s in samples}


def run_ensemble(out, preset, n, overrides=None, library=None, jobs=2, samples=SAMPLES, job_threads=None,
                 counts=None, figures=True, archive=None, set_aside=False):
    """Run seeds 1..n of each sample in one schedule: the study of ``make
    study`` (``--ensemble N``, N >= 2; the Makefile's default is 3).

    Each sample gets the run folder ``OUT/<sample>-ensemble`` with a table
    of the seeds (generated when it is not there; one made with other
    parameters is refused (ConfigError, nothing renamed) or, with
    ``set_aside``, first set aside as ``.old-K``; one with the same
    parameters gets its table written again, for another n). Every seed of
    every sample is a job of :func:`yade_scripts.launch.pool.run_pool` on ``jobs``
    cores: longest first by :func:`yade_scripts.launch.slurm.estimate`, the seeds
    of both samples interleaved, a freed core given to a running polyhedra
    run on the kernel once none waits; complete dumps are not run again,
    and each complete dump is analysed on a free core
    (:func:`analyse_after`). The schedule and its idle core-time go to
    ``OUT/schedule.json``.

    Parameters
    ----------
    out : str
        The study's folder.
    preset : str
        A preset of :data:`yade_scripts.campaign.presets.PRESETS`.
    n : int
        Seeds per sample (1..n).
    overrides : dict, optional
        name -> value (or its text), applied to both samples.
    library : str, optional
        The polyhedra's shape library (default
        :data:`yade_scripts.campaign.generate.DEFAULT_LIBRARY`).
    jobs : int
        Cores of the schedule.
    samples : sequence of str
        The samples to run (default both).
    job_threads : dict, optional
        sample -> YADE threads a job starts on (at most ``jobs``; default
        one each).
    counts : sequence of str, optional
        The other contact counts each complete S1 dump is analysed with
        (default :data:`postproc.study.counts.EXTRA_COUNTS`).
    figures : bool, optional
        Draw the analyses' figures (default; False: numbers only).
    archive : str, optional
        An archive of analysed runs (:mod:`yade_scripts.campaign.archive`): a seed
        whose dump is not complete here and that the archive holds usable
        (:func:`yade_scripts.campaign.archive_store.archived`) is not run; its status is
        :data:`ARCHIVED`. Each run that completes here is then analysed at
        once, on the first free core (``after_first`` of
        :func:`yade_scripts.launch.pool.run_pool`), and added to the archive.
        An archive holding a run of another analysis version, other
        parameters or another shape library (:func:`yade_scripts.campaign.archive_store.conflicts`)
        is refused before anything runs: ConfigError naming those runs.
    set_aside : bool, optional
        Rename a run folder of other parameters ``.old-K`` and start it
        afresh (default False: ConfigError, nothing renamed).

    Returns
    -------
    dict
        sample -> [(label "seed K", dump path, status)], status 0 complete,
        :data:`ARCHIVED` taken from the archive, else the exit code or the
        reason (:func:`yade_scripts.launch.pool.run_pool`).

    Raises
    ------
    ConfigError
        No ``yade`` on the PATH, or invalid parameters.
    yade_scripts.runs.runlock.RunBusy
        Another process writes one of the runs; nothing was touched.
    """
    pool, rows, kept, clash = [], {}, set(), []
    if not set_aside:                  # every sample's folder checked before any is touched
        for s in samples:
            _set_aside_if_changed(os.path.join(out, f"{s}-ensemble"), preset, s, overrides)
    for s in samples:
        folder = os.path.join(out, f"{s}-ensemble")
        _set_aside_if_changed(folder, preset, s, overrides, set_aside)
        seeds = list(range(1, n + 1))
        if not os.path.exists(os.path.join(folder, "triaxial.py")):
            generate(folder, preset, s, overrides, seeds=seeds, library=library or DEFAULT_LIBRARY)
        else:                      # same parameters, maybe another n: rewrite the table only
            write_seed_table(folder, s, seeds)
        p = resolve(preset, s, overrides)
        cost = estimate(p)["core_hours"] * 3600
        rows[s] = read_table(folder)
        clash += _conflicts(archive, folder, counts)
        kept.update(_from_archive(archive, folder, [dump_of(folder, r) for _, r in rows[s]], counts))
        pool += [Job(folder, k, r["description"], dump_of(folder, r), cost, tag=s,
                     widen=(s == "polyhedra" and p["contact_engine"] == "kernel"),
                     threads=min((job_threads or {}).get(s, 1), jobs))
                 for k, r in rows[s] if dump_of(folder, r) not in kept]
    if clash:
        raise ConfigError(_refusal(archive, clash))
    if pool:
        _need_yade()
    status = run_pool(pool, jobs, record=os.path.join(out, "schedule.json"), echo=lambda m: print(m, flush=True),
                      after=functools.partial(analyse_after, counts=counts, figures=figures, archive=archive),
                      after_first=archive is not None) if pool else {}
    def outcome(s, r):
        dump = dump_of(os.path.join(out, f"{s}-ensemble"), r)
        return f"seed {r['seed']}", dump, ARCHIVED if dump in kept else status[r["description"]]

    return {s: [outcome(s, r) for _, r in rows[s]] for s in samples}


def plan_ensemble(out, preset, n, overrides=None, library=None, samples=SAMPLES, counts=None, archive=None):
    """What :func:`run_ensemble` would do, done nothing of: for each sample,
    how many of seeds 1..n are taken from ``archive`` (usable and not
    complete here), complete here, and to run, and the archive's runs it
    would refuse.

    A sample's run folder that is not there yet is generated into a
    temporary folder of the same name (its parameters and shape library
    are what the archive is compared with), then removed; nothing in
    ``out`` is made or changed.

    Parameters
    ----------
    out, preset, n, overrides, library, samples, counts, archive
        As :func:`run_ensemble`'s.

    Returns
    -------
    dict
        sample -> {"archived": int, "here": int, "run": int, "conflicts":
        [line], "refused": [line]} (``conflicts``: runs of another analysis
        version, parameters or shape library, which make the study refuse;
        ``refused``: other archived runs not used, which run again).

    Raises
    ------
    ConfigError
        Invalid parameters, or a run folder of ``out`` made with other
        parameters (what the study would refuse).
    """
    import tempfile

    plan = {}
    with tempfile.TemporaryDirectory(prefix="study-dry-run-") as tmp:
        for s in samples:
            folder = os.path.join(out, f"{s}-ensemble")
            fresh = os.path.join(tmp, f"{s}-ensemble")      # the folder as the study would make it, for n seeds
            generate(fresh, preset, s, overrides, seeds=list(range(1, n + 1)), library=library or DEFAULT_LIBRARY)
            table = fresh
            if os.path.exists(os.path.join(folder, "triaxial.py")):
                _set_aside_if_changed(folder, preset, s, overrides, set_aside=False)
                table = folder
            held = _archived(archive, table, counts) if archive else {}
            got = {"archived": 0, "here": 0, "run": 0, "conflicts": _conflicts(archive, table, counts),
                   "refused": []}
            for _, r in read_table(fresh):
                name = os.path.basename(dump_of(fresh, r))
                how, what = held.get(name, (None, None))
                if complete(os.path.join(folder, name)) or complete(os.path.join(folder, r["description"], name)):
                    got["here"] += 1
                elif how == "ok":
                    got["archived"] += 1
                else:
                    got["run"] += 1
                    if how == "refused" and what not in got["conflicts"]:
                        got["refused"].append(what)
            plan[s] = got
    return plan


def describe_plan(plan):
    """The dry run's line: "A + B archived and usable; C + D to run" (one
    number per sample, in the plan's order), with the complete dumps here
    when there are any."""
    def nums(key):
        return " + ".join(str(p[key]) for p in plan.values())

    here = any(p["here"] for p in plan.values())
    return (f"{nums('archived')} archived and usable; " + (f"{nums('here')} complete here; " if here else "")
            + f"{nums('run')} to run")


def _from_archive(archive, table, dumps, counts):
    """The dumps of the runs of the run folder ``table`` (their
    dumps ``dumps``) that the archive ``archive`` holds usable and whose dump
    is not complete here (:func:`yade_scripts.campaign.archive_store.archived`), a set;
    each archived run not usable is named, and runs again."""
    if not archive:
        return set()
    held = _archived(archive, table, counts)
    out = set()
    for dump in dumps:
        how, what = held.get(os.path.basename(dump), (None, None))
        if how is None or complete(dump):
            continue
        if how == "ok":
            out.add(dump)
            print(f"[study] {os.path.basename(dump)}: taken from the archive {archive} (analysed on "
                  f"{what['record'].get('saved', '?')}), not run here", flush=True)
        else:
            print(f"[study] {what}", flush=True)
    return out


def _refusal(archive, clash):
    """The one line of a study refused for the archive's runs ``clash``
    (:func:`yade_scripts.campaign.archive_store.conflicts`' lines)."""
    names = ", ".join(line.split(" archived but not used")[0] for line in clash[:3])
    return (f"the archive {archive} holds {len(clash)} run(s) of another analysis version, other parameters or "
            f"another shape library ({names}{', ...' if len(clash) > 3 else ''}); nothing run, nothing replaced: "
            "name a new archive (ARCHIVE=NEW_DIR), or read this one with the code that made it "
            "(python -m yade_scripts.campaign.archive collect-at-commit ARCHIVE OUT, docs/study.md)")


def _conflicts(archive, table, counts):
    """:func:`yade_scripts.campaign.archive_store.conflicts` for the study's ``counts``
    (None: :data:`postproc.study.counts.EXTRA_COUNTS`); [] without an archive."""
    from postproc.study.counts import EXTRA_COUNTS

    return conflicts(archive, table, counts=EXTRA_COUNTS if counts is None else counts) if archive else []


def _archived(archive, table, counts):
    """:func:`yade_scripts.campaign.archive_store.archived` for the study's ``counts``
    (None: :data:`postproc.study.counts.EXTRA_COUNTS`)."""
    from postproc.study.counts import EXTRA_COUNTS

    return archived(archive, table, counts=EXTRA_COUNTS if counts is None else counts)


def analyse_after(job, counts=None, figures=True, archive=None):
    """The pool's work after a complete run (:func:`yade_scripts.launch.pool.run_pool`'s
    ``after``): ``python -m yade_scripts.campaign.study --analyse DUMP [--counts
    ...]``, the analyses the study makes of it, done while other runs still
    go; the study's own pass then keeps them (:func:`analyse_dump`).
    ``counts``: the other contact counts (default
    :data:`postproc.study.counts.EXTRA_COUNTS`; an empty sequence: none);
    ``figures=False``: ``--no-figures``; ``archive``: ``--archive DEST``,
    the run then kept in that archive (:mod:`yade_scripts.campaign.archive`)."""
    more = (([] if counts is None else ["--counts", *counts]) + ([] if figures else ["--no-figures"])
            + ([] if archive is None else ["--archive", os.path.abspath(archive)]))
    return [sys.executable, "-m", "yade_scripts.campaign.study", "--analyse", os.path.abspath(job.dump), *more]


def analyse_one(dump, counts=None, figures=True):
    """The study's analyses of one complete dump: the primary one
    (:func:`analyse_dump`) and, for polyhedra, the other contact counts
    ``counts`` (default :data:`postproc.study.counts.EXTRA_COUNTS`,
    :func:`postproc.study.counts.analyse_counts`, numbers only); the
    primary one with its figures unless ``figures=False``. Returns 0 when
    all worked, else 1 (each problem printed in one line)."""
    from postproc.schema import DumpFormatError, DumpReader
    from postproc.study.counts import analyse_counts

    try:
        with DumpReader(dump) as r:
            sample = r.sample_kind
    except (DumpFormatError, OSError) as exc:
        print(f"study: error: {dump}: {exc}", file=sys.stderr)
        return 1
    analysis = analysis_folder(dump)
    if analyse_dump(dump, analysis, figures=figures) is not None:
        return 1
    if sample == "polyhedra":
        _, bad = analyse_counts(dump, analysis, counts=counts)
        for line in bad:
            print(f"[study] {line}", flush=True)
        return 1 if bad else 0
    return 0


def archive_one(dump, archive):
    """Add the analysed runs of ``dump``'s run folder to the archive
    ``archive`` (:func:`yade_scripts.campaign.archive_store.save`), what ``--analyse DUMP
    --archive DEST`` does after the analyses; 0, or 1 when ``dump``'s run
    is not in the archive afterwards (the reason printed in one line)."""
    try:
        saved, skipped = save(os.path.dirname(os.path.abspath(dump)), archive,
                              echo=lambda m: print(m, flush=True))
    except (ConfigError, OSError) as exc:
        print(f"study: error: archive {archive}: {exc}", file=sys.stderr)
        return 1
    mine = f"{os.path.basename(os.path.dirname(os.path.abspath(dump)))}/{os.path.basename(dump)}"
    why = [x for x in skipped if x.startswith(mine + ":") and not x.endswith(": already archived")]
    for line in why:
        print(f"study: error: {line}", file=sys.stderr)
    return 1 if why else 0


def run_exits(dump):
    """The exit codes of the recorded attempts of the run writing ``dump``
    (:func:`yade_scripts.runs.runstate.read_attempts`), stops asked for left
    out; [] when none is recorded."""
    return [a.get("exit") for a in read_attempts(dump) if not a.get("requested")]


def analyse_dump(dump, analysis, errors=True, figures=True):
    """The dump's analysis (:func:`postproc.pipeline.analyze_path`, what
    ``postproc analyze`` runs; ``errors=False``: no standard errors;
    ``figures=False``: no figures) into
    ``analysis``; None when it worked (some bad snapshots allowed: they are
    in analysis/errors.txt and printed), else the one-line reason. An
    analysis made from the same dump files with the same options by the
    same code (:func:`postproc.provenance.is_current`) is kept, not made
    again."""
    from postproc.pipeline import BAD_INPUT, AnalysisOptions, analyze_path
    from postproc.provenance import is_current

    options = AnalysisOptions(errors=errors, figures=figures)
    if is_current(dump, analysis, options):
        print(f"[study] {analysis} is up to date (same dump, options and code), kept", flush=True)
        return None
    try:
        _, problems = analyze_path(dump, analysis, options, progress=False)
    except BAD_INPUT as exc:
        print(f"[study] analysis of {dump} failed: {exc}", flush=True)
        return str(exc)
    for line in problems:
        print(f"[study] {dump}: {line}", flush=True)
    return None if os.path.exists(os.path.join(analysis, "summary.csv")) else "no summary.csv written"


def partial_progress(dump):
    """How far an unfinished run got: {"eps_1_reached", "final_strain",
    "steady_from_eps_1", "steady_snapshots"} from its dump (eps_1 = ln(H_iso /
    H) of each shear snapshot against the isotropic one), or None when the
    dump is unreadable or has no isotropic snapshot. The steady state starts
    at STEADY_START x final_strain in eps_1 (the report's steady window,
    eps_q >= STEADY_START x its final value, in the axial strain)."""
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


def report_lock(out, wait=False):
    """Take the lock on OUT's manifest and report (``OUT/report.lock``,
    :data:`REPORT_LOCK`): one process writes them at a time (a study's
    end, ``--collect``; ``postproc report``, which never imports
    yade_scripts, takes no lock). The holder's record names it a study
    (``wait``) or a collect.

    Parameters
    ----------
    out : str
        The study or run folder.
    wait : bool, optional
        False (default): raise :class:`yade_scripts.runs.runlock.RunBusy`
        (one line, naming the holder) when another process holds it;
        True: wait for it, saying so once (a study that has run for
        hours does not give up its report for a ``--collect``).

    Returns
    -------
    RunLock
        The lock, held; ``release()`` it.
    """
    lock = RunLock(os.path.join(out, REPORT_LOCK), "study" if wait else "collect",
                   subject=f"the report of {out} (manifest.json, report/)")
    if not wait:
        return lock.acquire()
    return lock.acquire_waiting(REPORT_WAIT_SECONDS, lambda holder: print(
        f"[study] waiting for {describe(holder)} to finish writing the manifest and report of {out}", flush=True))


def analyse_and_report(out, runs, attempts=None, unfinished=None, counts=None, figures=True, archive=None):
    """Analyse every dump of ``runs`` = {sample: [(label, dump, status)]},
    write OUT/manifest.json and the report; returns the list of failures.
    Holds OUT's report lock (:func:`report_lock`) meanwhile, or raises
    :class:`yade_scripts.runs.runlock.RunBusy` before analysing or writing
    anything when another process holds it (its callers, the study's end
    and ``--collect``, take it first, over a wider span).
    Each usable S1 dump is also analysed with the other contact counts
    ``counts`` (default :data:`postproc.study.counts.EXTRA_COUNTS`), which
    the manifest lists and the report reads claim 6 by. ``figures=False``:
    the analyses and the report without their figures (numbers only).
    ``unfinished`` {sample: [manifest entry]}: runs that are not to be
    analysed (:func:`collect`'s unfinished and invalid lines), listed after
    the analysed ones with their status.

    A failed run whose dump got past the start of the steady state (two
    shear snapshots or more with eps_1 >= STEADY_START x final_strain, see
    :func:`partial_progress`) is analysed and marked ``partial``: the report
    uses its steady snapshots and says how far it got. ``attempts``
    {(sample, label): [exit code of each attempt]}
    (default: each run's record, :func:`run_exits`) goes into the manifest
    when a run was resumed. A run of status :data:`ARCHIVED` is read from
    the archive ``archive`` (:func:`yade_scripts.campaign.archive_store.archived`): its
    analyses are not made again, its manifest entry is "ok" with an
    ``archived`` record and a note."""
    lock = report_lock(out)
    try:
        return _analyse_and_report(out, runs, attempts, unfinished, counts, figures, archive)
    finally:
        lock.release()


def _analyse_and_report(out, runs, attempts, unfinished, counts, figures, archive):
    """:func:`analyse_and_report`'s work, its lock held."""
    from postproc.study.counts import analyse_counts
    from postproc.study.report import build_report

    manifest, failed = {}, []
    for s, items in runs.items():
        manifest[s] = []
        for label, dump, status in items:
            if status == ARCHIVED:
                entry = _archived_entry(out, archive, dump, counts, label)
                if entry["status"] != "ok":
                    failed.append(f"{s} {label}")
                manifest[s].append(entry)
                continue
            stem = os.path.splitext(dump)[0]
            folder = os.path.dirname(dump)
            analysis = analysis_folder(dump)
            info = stem + ".info.json"
            extra = {}
            tries = attempts.get((s, label), []) if attempts is not None else run_exits(dump)
            if len(tries) > 1:
                extra["attempts"] = tries
                extra["note"] = f"resumed {len(tries) - 1} time(s) from its checkpoint (exits {tries})"
            progress = partial_progress(dump) if status != 0 and os.path.exists(dump) else None
            if status != 0 and progress and progress["steady_snapshots"] >= 2:
                print(f"[{s}] analysing {label} (partial, reached eps_1 = {progress['eps_1_reached']:.3f}): {dump}",
                      flush=True)
                bad = analyse_dump(dump, analysis, figures=figures)
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
                bad = analyse_dump(dump, analysis, figures=figures)
                why = "ok" if bad is None else f"analysis failed ({bad})"
                if why != "ok":
                    failed.append(f"{s} {label}")
            if s == "polyhedra" and why in ("ok", "partial"):     # claim 6 by the other contact counts
                done, bad = analyse_counts(dump, analysis, counts=counts)
                for line in bad:
                    print(f"[study] {line}", flush=True)
                extra["counts"] = {c: os.path.relpath(f, out) for c, f in done.items()}
            manifest[s].append({"label": label, "dump": os.path.relpath(dump, out),
                                "analysis": os.path.relpath(analysis, out),
                                "info": os.path.relpath(info, out), "status": why,
                                "state": why if why in ("ok", "partial") else "failed", **extra})
    for s, entries in (unfinished or {}).items():
        manifest.setdefault(s, []).extend(entries)
    with open(os.path.join(out, "manifest.json"), "w") as fh:
        json.dump(manifest, fh, indent=1)
    path = build_report(out, figures=figures)
    print(f"[study] report written to {path} (and report.html)", flush=True)
    return failed


def _archived_entry(out, archive, dump, counts, label):
    """The manifest entry of a run taken from the archive ``archive``
    (paths relative to the study ``out``)."""
    how, what = _archived(archive, os.path.dirname(dump), counts).get(os.path.basename(dump), (None, None))
    entry = {"label": label, "dump": os.path.relpath(dump, out)}
    if how != "ok":
        return {**entry, "status": f"not in the archive any more ({what or 'no record'})", "state": "failed"}
    rec = what["record"]
    print(f"[study] {label} of {os.path.basename(os.path.dirname(dump))}: from the archive {archive}", flush=True)
    return {**entry, "analysis": os.path.relpath(what["analysis"], out),
            "info": what["info"] and os.path.relpath(what["info"], out), "status": "ok", "state": "ok",
            "counts": {c: os.path.relpath(f, out) for c, f in what["counts"].items()},
            "archived": {"archive": os.path.relpath(archive, out), "dump_sha256": rec["dump"]["sha256"],
                         "saved": rec.get("saved")},
            "note": f"from the archive {archive}: analysed on {rec.get('saved', '?')}, its dump "
                    f"({rec['dump']['snapshots']} snapshots, SHA-256 {rec['dump']['sha256'][:12]}) not on this host"}


def unusable_samples(out):
    """Samples of OUT/manifest.json with no run that is ok or partial."""
    with open(os.path.join(out, "manifest.json")) as fh:
        manifest = json.load(fh)
    return [s for s, rs in manifest.items() if not any(r["status"] in ("ok", "partial") for r in rs)]


def collect(folder, counts=None, figures=True, archive=None):
    """Analyse and report whatever has finished in the generated run folders
    at or below ``folder``, and say what every other line is: ``python -m
    yade_scripts.campaign.study --collect DIR``, e.g. after a SLURM array.

    The run folders are ``folder`` itself or those one level below it,
    each with a ``table.txt`` (but for the folders set aside as
    ``FOLDER.old-K``, :data:`SET_ASIDE`); a line's dump is in the line's
    own folder ``<description>/``, as a SLURM array task writes it, or next
    to the table, as the study and sweeps do. A line that is not finished
    is named with its state: pending or running in SLURM (``squeue`` of
    the jobs recorded for the folder,
    :func:`yade_scripts.launch.slurm.queue_states`), running (a process holds its
    lock, :mod:`yade_scripts.runs.runlock`: a task, a study or a scene, on any
    node that shares the folder), resumable at step N, failed (why),
    unfinished, not started, an invalid line
    (:func:`yade_scripts.launch.batch.table_lines`: named, never blocking the
    other lines or arrays), or a complete dump that does not add up
    (refused, never analysed). Pending and running lines are never in the
    resubmit command. Writes ``FOLDER/manifest.json`` (every line of every
    table) and ``FOLDER/report/`` (:func:`analyse_and_report`), also when
    nothing has finished yet. Nothing is run.

    Parameters
    ----------
    folder : str
        A generated run folder, or a folder of them.
    counts : sequence of str, optional
        The other contact counts each finished S1 dump is analysed with
        (default :data:`postproc.study.counts.EXTRA_COUNTS`).
    figures : bool, optional
        Draw the analyses' and the report's figures (default; False:
        numbers only).
    archive : str, optional
        An archive of analysed runs (:mod:`yade_scripts.campaign.archive`): a line
        whose dump is not complete here and that the archive holds usable
        is taken from it, not listed as unfinished.

    Returns
    -------
    runs : dict
        The runs analysed: sample -> [(label, dump, 0 or
        :data:`ARCHIVED`)].
    pending : list of str
        The lines not finished: "<folder>/<description> (<state>)".
    failed : list of str
        The runs whose analysis failed: "<sample> <label>".
    resubmit : dict
        table folder -> the command that runs its unfinished lines again
        (``sbatch --array=...`` where the folder has a ``slurm.sh``, else
        ``python -m yade_scripts.launch.batch ... --only ...``).

    Raises
    ------
    ConfigError
        ``folder`` is missing or holds no run folder.
    RunBusy
        Another process (a study at its end, another collect) writes the
        folder's manifest and report (:func:`report_lock`): nothing is
        analysed or written.

    Examples
    --------
    >>> import os, tempfile
    >>> from yade_scripts.campaign.generate import generate
    >>> out = os.path.join(tempfile.mkdtemp(), "t1")
    >>> _ = generate(out, "tiny", "spheres", seeds=[1])
    >>> runs, pending, failed, resubmit = collect(out)
    [study] report written to .../t1/report/report.md (and report.html)
    >>> runs, pending, failed
    ({}, ['spheres-seed1 (not started)'], [])
    >>> resubmit[out]
    'python -m yade_scripts.launch.batch .../t1 --only spheres-seed1'
    >>> sorted(os.listdir(out))
    ['manifest.json', 'params.json', 'pkg', 'report', 'report.lock', 'table.txt', 'triaxial.py']
    """
    if not os.path.isdir(folder):
        raise ConfigError(f"{folder}: no such folder")
    tables = run_folders(folder)
    if not tables:
        raise ConfigError(f"{folder}: no generated run folder (table.txt) in it or one level below")
    lock = report_lock(folder)      # before looking at the runs: a refusal is one line, and no older scan
    try:                            # overwrites what a study's end wrote meanwhile
        return _collect(folder, tables, counts, figures, archive)
    finally:
        lock.release()


def _collect(folder, tables, counts, figures, archive):
    """:func:`collect`'s work on its run folders ``tables``, the report lock held."""
    runs, others, pending, resubmit = {}, {}, [], {}
    for t in tables:
        prefix = f"{os.path.basename(t)} " if len(tables) > 1 else ""
        try:
            with open(os.path.join(t, "params.json")) as fh:
                sample = json.load(fh)["sample"]
            lines = table_lines(t)
        except (OSError, ValueError, KeyError, ConfigError) as exc:
            why = str(exc) if isinstance(exc, ConfigError) else f"{t}: params.json missing or without 'sample'"
            pending.append(f"{os.path.relpath(t, folder)} (invalid run folder: {why})")
            others.setdefault("unknown", []).append({"label": prefix.strip() or os.path.basename(t), "dump": None,
                                                     "status": f"invalid run folder: {why}"})
            continue
        todo = []
        queue = queue_states(t) if os.path.exists(os.path.join(t, "slurm.sh")) else {}
        held = _from_archive(archive, t, [line_dump(t, x) for x in lines if not x.error], counts)
        for line in lines:
            label = prefix + (f"seed {line.row['seed']}" if "seed" in line.row and not line.error
                              else line.description)
            where = {"table": os.path.relpath(os.path.join(t, "table.txt"), folder), "line": line.number,
                     "task": line.task}
            if line.error:
                st_detail, dump, state = f"invalid line: {line.error}", None, "invalid"
            else:
                dump = line_dump(t, line)
                if dump in held:
                    runs.setdefault(sample, []).append((label, dump, ARCHIVED))
                    continue
                st = state_of(dump)          # complete only when it verifies whole
                if st.finished:
                    runs.setdefault(sample, []).append((label, dump, 0))
                    continue
                if st.state == "damaged":        # truncated or not verifying: never "starts afresh"
                    st_detail, state = f"refused, not analysed: {dump}: {st.detail}", "refused"
                elif st.state == "unreadable":   # held open by another process: it may be fine
                    st_detail, state = st.detail, "unreadable"
                elif line.task in queue:
                    st_detail = queue_detail(*queue[line.task])
                    state = "running" if queue[line.task][1] in ON_A_NODE else "pending"
                else:
                    st_detail, state = st.detail, st.state
                    if st.state != "running":
                        todo.append(line)
            pending.append(f"{os.path.relpath(os.path.join(t, line.description), folder)} ({st_detail})")
            others.setdefault(sample, []).append({"label": label, "dump": dump and os.path.relpath(dump, folder),
                                                  "status": st_detail, "state": state, **where})
        name = os.path.basename(os.path.abspath(t))
        slurm_sh = os.path.join(os.path.abspath(t), "slurm.sh")

        def command(ls):
            if os.path.exists(slurm_sh):
                return f"sbatch --array={','.join(str(x.task) for x in ls)} {slurm_sh}"
            return f"python -m yade_scripts.launch.batch {os.path.abspath(t)} --only {' '.join(x.description for x in ls)}"

        if todo:
            resubmit[t] = command(todo)
        mine = [e for e in others.get(sample, []) if e.get("table") == os.path.relpath(os.path.join(t, "table.txt"),
                                                                                      folder)]
        by_number = {x.number: x for x in lines}
        for e in mine:
            line = by_number[e["line"]]
            if e["status"].startswith("refused"):
                e["note"] = (f"the dump does not add up and may be a finished run: look at it (or move it aside), "
                             f"then {command([line])}, whose task moves it aside itself (never removes it)")
            elif e.get("state") == "unreadable":
                e["note"] = f"close what holds the dump open, then collect again (or {command([line])})"
            elif line.error:
                e["note"] = f"fix line {line.number} of {name}/table.txt, then: {command([line])}"
            elif line in todo:
                e["resubmit"] = resubmit[t]
                e["note"] = f"resubmit the unfinished lines of {name}: {resubmit[t]}"
    for p in pending:
        print(f"study: not finished: {p}", file=sys.stderr)
    for t, cmd in resubmit.items():
        print(f"study: resubmit the unfinished lines of {os.path.basename(os.path.abspath(t))}: {cmd}",
              file=sys.stderr)
    if not runs:
        print(f"study: no run has finished yet ({len(pending)} not finished): the manifest and the report list them",
              file=sys.stderr)
    failed = analyse_and_report(folder, runs, unfinished=others, counts=counts, figures=figures, archive=archive)
    return runs, pending, failed, resubmit


def main(argv=None):
    """``python -m yade_scripts.campaign.study``: the study (:func:`run_samples` or
    :func:`run_ensemble`, then :func:`analyse_and_report`), ``--collect
    DIR`` (:func:`collect`) or ``--analyse DUMP`` (:func:`analyse_one`).
    The options and the memory the runs need at once
    (:func:`yade_scripts.launch.resources.check_memory`) are checked before the
    folder is made; the study then holds its folder's lock
    (``OUT/study.lock``).

    Parameters
    ----------
    argv : list of str, optional
        The command line's arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit code (the module docstring): 0 every sample has a usable
        run; 1 a sample has none (with ``--collect``: an analysis failed;
        with ``--analyse``: it failed); 2 invalid options; 4 another
        process writes the folder or one of its runs, or (``--collect``)
        its manifest and report; 75 stopped (SIGTERM,
        Ctrl-C: run the same command again to resume).
    """
    ap = argparse.ArgumentParser(prog="python -m yade_scripts.campaign.study", description=__doc__.splitlines()[0])
    ap.add_argument("--preset", default="default")
    ap.add_argument("--out", help="study folder (required unless --collect)")
    ap.add_argument("--collect", metavar="DIR",
                    help="analyse and report whatever has finished in the run folders of DIR "
                         "(e.g. a SLURM array from generate --slurm), run nothing")
    ap.add_argument("--analyse", metavar="DUMP",
                    help="make the study's analyses of one complete dump (its analysis folder beside it, and "
                         "the other contact counts for polyhedra), run nothing; the study does this itself")
    ap.add_argument("--set", action="append", metavar="NAME=VALUE")
    ap.add_argument("--library")
    ap.add_argument("--ensemble", type=int, default=1, help="seeds per sample (>= 2: one schedule over both samples)")
    ap.add_argument("--jobs", type=int, default=2, help="cores of the schedule (ensembles)")
    ap.add_argument("--job-threads", type=int, default=1,
                    help="YADE threads a polyhedra job of an ensemble starts on (the kernel's OpenMP "
                         "threads; sphere jobs use one): e.g. --jobs 16 --job-threads 2 on a 16-core node")
    ap.add_argument("--counts", nargs="*", metavar="COUNT",
                    help="the contact counts claim 6 is read by besides ours (postproc analyze --types), "
                         "each S1 dump analysed once more per count: default lmgc90; e.g. --counts lmgc90 "
                         "lmgc90-2009; none: --counts with nothing after it")
    ap.add_argument("--archive", metavar="DEST",
                    help="an archive of analysed runs (python -m yade_scripts.campaign.archive STUDY DEST): seeds it "
                         "holds are not run, their archived analyses are used (ensembles and --collect)")
    ap.add_argument("--set-aside", action="store_true",
                    help="rename a run folder of other parameters FOLDER.old-K and start it afresh "
                         "(without: the study refuses it and renames nothing)")
    ap.add_argument("--dry-run", action="store_true",
                    help="ensembles: say how many seeds the archive gives and how many would run; run and "
                         "write nothing")
    ap.add_argument("--no-figures", action="store_true",
                    help="numbers only: the analyses and the report without their figures (faster)")
    args = ap.parse_args(argv)
    if args.counts is not None:
        from postproc.errors import InputError
        from postproc.study.counts import check_counts

        try:
            args.counts = check_counts(args.counts)
        except InputError as exc:
            print(f"study: error: {exc}", file=sys.stderr)
            return 2
    if args.archive and not os.path.isdir(args.archive):
        print(f"study: error: --archive {args.archive}: no such folder (make it, empty, to start an archive; "
              f"python -m yade_scripts.campaign.archive STUDY DEST adds a study's analysed runs to one)", file=sys.stderr)
        return 2
    if args.archive and not (args.collect or args.analyse) and args.ensemble < 2:
        print("study: error: --archive reads the seeds of an ensemble (--ensemble N >= 2) or a --collect",
              file=sys.stderr)
        return 2
    if args.analyse:
        import signal

        signal.signal(signal.SIGTERM, lambda *_: sys.exit(75))    # stopped: its temporary folder goes
        if not complete(args.analyse):
            print(f"study: error: {args.analyse}: not a complete dump", file=sys.stderr)
            return 2
        code = analyse_one(args.analyse, args.counts, figures=not args.no_figures)
        return archive_one(args.analyse, args.archive) if code == 0 and args.archive else code
    if args.collect:
        try:
            runs, pending, failed, _ = collect(args.collect, args.counts, figures=not args.no_figures,
                                               archive=args.archive)
        except ConfigError as exc:
            print(f"study: error: {exc}", file=sys.stderr)
            return 2
        except RunBusy as exc:      # a study's end or another --collect writes the manifest and report
            print(f"study: error: {exc}", file=sys.stderr)
            return EXIT_BUSY
        n = sum(len(v) for v in runs.values())
        print(f"study: collected {n} finished run(s), {len(pending)} not finished; report in "
              f"{args.collect}/report/report.md", file=sys.stderr)
        return 1 if failed else 0
    if not args.out:
        ap.error("--out is required (unless --collect)")
    if args.dry_run:
        return _dry_run(args)
    try:                            # checked before the folder is made: a refused study makes nothing
        if args.ensemble < 1:
            raise ConfigError(f"--ensemble must be >= 1, got {args.ensemble}")
        if args.ensemble > 1 and (args.jobs < 1 or args.job_threads < 1):
            raise ConfigError(f"--jobs and --job-threads must be >= 1, got {args.jobs} and {args.job_threads}")
        overrides = parse_overrides(args.set)
        params = [resolve(args.preset, s, overrides) for s in SAMPLES]
        # at once: both samples (one seed), or --jobs runs of the largest (ensembles)
        check_memory(params if args.ensemble == 1 else
                     [max(params, key=memory_mb)] * min(args.jobs, args.ensemble * len(SAMPLES)))
        if args.archive:            # an archive it would not use as it is: refused before anything is made
            plan = plan_ensemble(args.out, args.preset, args.ensemble, overrides, args.library,
                                 counts=args.counts, archive=args.archive)
            clash = [line for p in plan.values() for line in p["conflicts"]]
            if clash:
                raise ConfigError(_refusal(args.archive, clash))
    except ConfigError as exc:
        print(f"study: error: {exc}", file=sys.stderr)
        return 2
    try:
        os.makedirs(args.out, exist_ok=True)
        lock = RunLock(os.path.join(args.out, "study.lock"), "study").acquire()
    except RunBusy as exc:          # another study writes this folder: touch nothing
        print(f"study: error: {exc}", file=sys.stderr)
        return EXIT_BUSY
    except OSError as exc:
        print(f"study: error: {args.out}: {exc.strerror or exc}", file=sys.stderr)
        return 2
    try:
        return _study(args, overrides)
    finally:
        lock.release()


def _dry_run(args):
    """``--dry-run``: :func:`plan_ensemble`'s line, the archive's refused
    runs each in a line; exit 0, or 2 when the study would refuse."""
    if args.ensemble < 2:
        print("study: error: --dry-run plans an ensemble (--ensemble N >= 2)", file=sys.stderr)
        return 2
    try:
        plan = plan_ensemble(args.out, args.preset, args.ensemble, parse_overrides(args.set), args.library,
                             counts=args.counts, archive=args.archive)
    except ConfigError as exc:
        print(f"study: error: {exc}", file=sys.stderr)
        return 2
    for p in plan.values():
        for line in p["refused"]:
            print(f"[study] {line}")
    clash = [line for p in plan.values() for line in p["conflicts"]]
    print(f"study: dry run of {args.out} (nothing run or written): {describe_plan(plan)}"
          + (f" (seeds of {' + '.join(plan)})" if plan else ""))
    if clash:
        print(f"study: error: the study would refuse: {_refusal(args.archive, clash)}", file=sys.stderr)
        return 2
    return 0


def _study(args, overrides):
    """The study of ``main``'s parsed ``args`` (checked), its folder's lock held."""
    try:
        if args.ensemble == 1:
            codes = run_samples(args.out, args.preset, overrides, args.library, counts=args.counts,
                                figures=not args.no_figures, set_aside=args.set_aside)
            runs = {s: [("seed 1", os.path.join(args.out, s, "run.h5"), c)] for s, c in codes.items()}
        else:
            runs = run_ensemble(args.out, args.preset, args.ensemble, overrides, args.library, args.jobs,
                                job_threads={"polyhedra": args.job_threads}, counts=args.counts,
                                figures=not args.no_figures, archive=args.archive, set_aside=args.set_aside)
    except ConfigError as exc:
        print(f"study: error: {exc}", file=sys.stderr)
        return 2
    except RunBusy as exc:          # a run of the study written by another process (a task, a scene by hand)
        print(f"study: error: {exc}", file=sys.stderr)
        return EXIT_BUSY
    stopped = [f"{s} {label}" for s in runs for label, _, status in runs[s] if status == "stopped"]
    if stopped:
        print(f"study: stopped (SIGTERM or Ctrl-C): {', '.join(stopped)} not finished, each run kept its "
              f"checkpoint; run the same command again to resume", file=sys.stderr)
        return EXIT_TERM
    lock = report_lock(args.out, wait=True)        # the manifest read back as written: no collect in between
    try:
        failed = analyse_and_report(args.out, runs, counts=args.counts, figures=not args.no_figures,
                                    archive=args.archive)
        missing = unusable_samples(args.out)
    finally:
        lock.release()
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
