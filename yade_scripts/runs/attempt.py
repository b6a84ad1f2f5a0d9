"""One attempt at a run, as the scene (``triaxial.py``) sees it: how it
begins, how YADE runs with checkpoints on time and on SIGTERM, and what a
checkpoint holds.

    run = Attempt(O, dump, parameters, checkpoint_seconds, resume, timing, say)
    if run.complete: ...                      # the dump is finished already
    writer = run.open_dump(new_dump)          # reopened after the checkpoint's snapshots, or new_dump()
    log = run.open_log(header)                # cut at the checkpoint's row, or new with its header
    run.start()
    if run.resumed: run.restore(set_state, where)
    outcome = run.loop(done, get_state, where)    # "done", "failed", "terminated" or "stalled"

A checkpoint (:mod:`yade_scripts.runs.checkpoint`) holds YADE's scene (O.save),
the dump's and the log's positions, the run's history (wall and engine
seconds, earlier resumes) and the scene's own state: ``get_state()``
returns (JSON-able dict, {name: array}), whose keys join the checkpoint's
metadata, and ``set_state(meta, arrays)`` gets that metadata back (the
loading program, the kernel's pair histories ...).
Whether an attempt resumes, and from which checkpoint, is decided here;
the exit codes and what comes after an attempt are
:mod:`yade_scripts.runs.runstate`'s.

numpy, h5py and the standard library; the YADE objects (``O``) are passed in.
"""
from __future__ import annotations

import atexit
import contextlib
import json
import os
import shutil
import signal
import sys
import time
from dataclasses import dataclass

from postproc.schema import DumpWriter

from . import checkpoint
from .runlock import RunLock, describe, inherited, lock_path
from .runstate import RunFiles, clear_attempt, dump_condition


@dataclass
class Resumed:
    """The checkpoint an attempt resumes from.

    Attributes
    ----------
    checkpoint : str
        Its file (``STEM.ckpt`` or ``STEM.ckpt.prev``).
    meta : dict
        The checkpoint's metadata (:func:`yade_scripts.runs.checkpoint.read`):
        fingerprint, step, time, stage, eps_1, n_snapshots, dump_parameters
        (JSON text), log_bytes, why, the run's history (wall_seconds, engine_seconds, resumes) and
        the keys of the scene's ``get_state()``.
    arrays : dict
        name (str) -> numpy.ndarray: the arrays it holds.
    scene : bytes
        YADE's saved scene (O.save).
    writer : postproc.schema.DumpWriter
        The dump, reopened after the checkpoint's snapshots.
    step : int
        The step (YADE's iteration) the checkpoint was written at.
    dump_parameters : dict
        The dump's parameters as the first attempt wrote them.
    """
    checkpoint: str
    meta: dict
    arrays: dict
    scene: bytes
    writer: DumpWriter

    @property
    def step(self):
        """The step (YADE's iteration) the checkpoint was written at (int)."""
        return int(self.meta["step"])

    @property
    def dump_parameters(self):
        """The dump's parameters as the first attempt wrote them (dict)."""
        return json.loads(self.meta["dump_parameters"])


def scene_bytes(O, path):
    """The YADE scene (O.save) as bytes, through the temporary file ``path``.

    Parameters
    ----------
    O : yade.Omega
        The running YADE's ``O``.
    path : str
        The temporary file (``.yade`` or another suffix O.save takes); it
        is overwritten, then removed.

    Returns
    -------
    bytes
        The saved file's content.
    """
    O.save(path)
    with open(path, "rb") as fh:
        blob = fh.read()
    os.remove(path)
    return blob


def load_scene_bytes(O, blob, path):
    """O.load of a scene saved by :func:`scene_bytes`, through ``path``.

    Parameters
    ----------
    O : yade.Omega
        The running YADE's ``O``; its scene is replaced.
    blob : bytes
        A scene of :func:`scene_bytes`.
    path : str
        The temporary file (the same suffix as when it was saved); it is
        overwritten, then removed.

    Returns
    -------
    None
    """
    with open(path, "wb") as fh:
        fh.write(blob)
    O.load(path)
    os.remove(path)


class Attempt:
    """One attempt at the run that writes ``dump``.

    On creation it decides how the attempt begins: :attr:`complete` (the
    dump is finished: nothing to do), :attr:`resumed` (a
    :class:`Resumed`: the newest usable checkpoint written with the same
    ``parameters``, see :func:`yade_scripts.runs.checkpoint.choose`), or afresh
    (what an unfinished attempt left is removed, with a line through
    ``say``). ``resume=False`` always starts afresh. Before it looks at
    any file it makes sure it is the run's only writer
    (:mod:`yade_scripts.runs.runlock`): the process that started it holds the
    run's lock for it, or it takes the lock itself, held until the process
    ends; another holder raises :class:`~yade_scripts.runs.runlock.RunBusy`
    (one line naming it) and nothing is touched. From then on SIGTERM
    only raises :attr:`terminated`; the run stops at the end of a step and
    writes a checkpoint.

    The stop goes through ``O.stopAtIter``, set by :meth:`end_of_step`
    inside the step (the scene's controller calls it first thing every
    step): YADE then ends its loop after that step is complete. (``O.pause()``
    from this thread would clear ``O.running`` while a step is still under
    way, so ``O.wait()`` returns early and a checkpoint could catch half a
    step.)

    Parameters
    ----------
    O : yade.Omega
        The running YADE's ``O``.
    dump : str
        The run's dump, ``STEM.h5`` (its companions:
        :class:`~yade_scripts.runs.runstate.RunFiles`).
    parameters : dict
        The run's parameters; their :func:`yade_scripts.runs.checkpoint.fingerprint`
        must match a checkpoint's for it to be used.
    checkpoint_seconds : float
        Seconds of wall time between two periodic checkpoints (0 or less:
        none, only on SIGTERM).
    resume : bool
        False: always start afresh.
    timing : bool
        Whether the engines' times are recorded (the scene sets
        ``O.timingEnabled`` to it): :meth:`engine_seconds` reads them only
        then.
    say : callable
        Takes each one-line message.

    Attributes
    ----------
    O : yade.Omega
        As given.
    say : callable
        As given.
    timing : bool
        As given.
    checkpoint_seconds : float
        As given.
    files : yade_scripts.runs.runstate.RunFiles
        The run's files.
    fingerprint : str
        :func:`yade_scripts.runs.checkpoint.fingerprint` of ``parameters``.
    complete : bool
        True when the dump was finished already: nothing to do.
    resumed : Resumed or None
        The checkpoint this attempt resumes from, or None (afresh, or
        complete).
    writer : postproc.schema.DumpWriter or None
        The dump's writer once :meth:`open_dump` has run.
    log : file object or None
        ``STEM.log.csv``, open for writing, once :meth:`open_log` has run.
    terminated : bool
        True once SIGTERM has arrived.
    failed : str or None
        Why the scene stopped the run (:meth:`fail`), when it did.
    scene_saving : callable
        Returns a context manager put around O.save of a checkpoint
        (default :func:`contextlib.nullcontext`; the scene swaps in
        engines that any YADE can load).
    t0 : float
        When this attempt's clock started (seconds since the epoch).
    last_checkpoint : float
        When the last checkpoint was written, or the clock started (seconds
        since the epoch).
    earlier_wall_seconds : float
        Wall seconds of the earlier attempts (from the checkpoint).
    earlier_engine_seconds : dict
        engine name (str) -> seconds of the earlier attempts.
    resumes : list of dict
        One per resume so far: step, stage, eps_1, checkpoint (file name),
        written_because ("periodic" or "SIGTERM") and at (UTC, ISO 8601).
    lock : yade_scripts.runs.runlock.RunLock or None
        The run's lock when this process took it itself (released at
        exit); None when the process that started it holds it.

    Raises
    ------
    yade_scripts.runs.runlock.RunBusy
        Another live process holds the run's lock (one line naming it);
        nothing was touched.
    """

    def __init__(self, O, dump, parameters, checkpoint_seconds, resume=True, timing=True, say=print):
        self.O, self.say, self.timing = O, say, timing
        self.files = RunFiles(dump)
        self.fingerprint = checkpoint.fingerprint(parameters)
        self.checkpoint_seconds = checkpoint_seconds
        self.complete, self.resumed = False, None
        self.writer = self.log = None
        self.terminated = False
        self.failed = None                   # why the scene stopped the run, when it did
        self._pause_request = False
        #: a context manager around O.save of a checkpoint (the scene swaps in
        #: engines that any YADE can load: the kernel plugin's PyRunner form)
        self.scene_saving = contextlib.nullcontext
        self.t0 = self.last_checkpoint = time.time()
        # what the earlier attempts of this run took (from the checkpoint)
        self.earlier_wall_seconds, self.earlier_engine_seconds, self.resumes = 0.0, {}, []
        self.lock = None
        if not inherited(lock_path(dump)):
            self.lock = RunLock(lock_path(dump), "scene").acquire()      # RunBusy: another writer
            atexit.register(self.lock.release)                         # an ended run leaves no record
            if self.lock.took_over:
                say(f"taking over the run from {describe(self.lock.took_over)}, which is no longer running")
        self._begin(resume)
        if not self.complete:
            signal.signal(signal.SIGTERM, self._on_term)

    def _begin(self, resume):
        f = self.files
        if resume:
            chosen = checkpoint.choose(f.checkpoint, self.fingerprint,
                                       lambda meta: DumpWriter.resume(f.dump, meta["n_snapshots"]), say=self.say)
            if chosen is not None:
                path, meta, arrays, blobs, writer = chosen
                writer.attrs["parameters"] = meta["dump_parameters"]
                self.resumed = Resumed(path, meta, arrays, blobs["scene"], writer)
                return
        if dump_condition(f.dump)[0] == "complete":
            self.complete = True
            return
        # never removes a dump that may be finished: one that cannot be opened now raises
        # DumpUnreadable (a RunBusy: refused, untouched); a damaged one is moved aside
        for line in clear_attempt(f.dump):
            self.say(f"starting afresh: {line}")

    # ------------------------------------------------------------ the dump and the log
    def open_dump(self, new_dump):
        """The dump writer: the resumed one, else ``new_dump()``.

        Parameters
        ----------
        new_dump : callable
            Takes no argument and returns a new
            :class:`postproc.schema.DumpWriter`; called only when the
            attempt does not resume.

        Returns
        -------
        postproc.schema.DumpWriter
            The writer, also kept as :attr:`writer`.
        """
        self.writer = self.resumed.writer if self.resumed else new_dump()
        return self.writer

    def open_log(self, header):
        """STEM.log.csv: appended after the checkpoint's last row when
        resuming, else new with its ``header``.

        Parameters
        ----------
        header : str
            Written as is at the start of a new log (its column line, with
            its newline); not used when resuming.

        Returns
        -------
        file object
            The log, open for text writing at its end (resuming: cut to the
            checkpoint's ``log_bytes``), also kept as :attr:`log`.
        """
        if self.resumed:
            self.log = open(self.files.log_csv, "a+")
            self.log.truncate(min(self.resumed.meta["log_bytes"], self.log.seek(0, os.SEEK_END)))
            self.log.seek(0, os.SEEK_END)
        else:
            self.log = open(self.files.log_csv, "w")
            self.log.write(header)
        return self.log

    def progress(self, **fields):
        """Rewrite the run's progress record (STEM.progress.json) with
        ``fields`` (step, stage, eps_1, steps_per_second, seconds_left ...)
        and the time; what a scheduler reads to see how long a run has left.

        Parameters
        ----------
        **fields
            JSON-serialisable values, e.g. step (int), stage (str),
            seconds_left (float, s, or None); written with ``"time"``
            (seconds since the epoch, now), which replaces a field of that
            name. The file is replaced atomically.

        Returns
        -------
        None
        """
        path = self.files.progress
        with open(path + ".tmp", "w") as fh:
            json.dump({**fields, "time": time.time()}, fh)
        os.replace(path + ".tmp", path)

    # ------------------------------------------------------------ the clock and the history
    def start(self):
        """This attempt's clock starts now; the progress record says so (a
        scheduler may send SIGTERM from now on: it is handled).

        Returns
        -------
        None
        """
        self.t0 = self.last_checkpoint = time.time()
        self.progress(step=self.O.iter, stage="starting", seconds_left=None)

    def wall_seconds(self):
        """Wall time of the run so far (s), earlier attempts included.

        Returns
        -------
        float
            Seconds: the earlier attempts' plus this one's since :meth:`start`.
        """
        return self.earlier_wall_seconds + time.time() - self.t0

    def engine_seconds(self):
        """{engine: s} of the run so far (YADE's execTime of each engine,
        earlier attempts included); {} without timing.

        Returns
        -------
        dict
            engine (str: its label, else its class name) -> seconds
            (float): this attempt's engines (two under one name summed)
            plus the earlier attempts' seconds under the same name; a name
            of the earlier attempts only keeps its seconds, and an attempt
            without timing adds none.
        """
        out = dict(self.earlier_engine_seconds)
        for e in (self.O.engines if self.timing else ()):
            name = e.label or e.__class__.__name__
            out[name] = out.get(name, 0.0) + e.execTime * 1e-9
        return out

    def history(self):
        """{wall_seconds, engine_seconds, resumes} of the run so far.

        Returns
        -------
        dict
            "wall_seconds" (float, :meth:`wall_seconds`), "engine_seconds"
            (dict, :meth:`engine_seconds`) and "resumes" (list of dict,
            :attr:`resumes`).
        """
        return {"wall_seconds": self.wall_seconds(), "resumes": self.resumes, "engine_seconds": self.engine_seconds()}

    # ------------------------------------------------------------ checkpoints
    def save_checkpoint(self, why, get_state, where):
        """Write STEM.ckpt now (between two steps): YADE's scene, the dump's
        and log's positions, the history and ``get_state()``.

        Needs :meth:`open_dump` and :meth:`open_log` first. Says one line
        (step, stage, size, time taken).

        Parameters
        ----------
        why : str
            Why it is written ("periodic" or "SIGTERM"), kept as the
            metadata's ``why``.
        get_state : callable
            Takes no argument and returns ``(state, arrays)``: the scene's
            JSON-serialisable dict, whose keys join the metadata, and its
            dict of name (str) -> numpy array.
        where : callable
            Takes no argument and returns ``(stage, eps_1)``: the loading
            stage (str) and the axial strain (float).

        Returns
        -------
        None

        Raises
        ------
        ValueError
            A key of ``state`` is one of the checkpoint's own metadata
            names, or an array name is reserved or of dtype object
            (:func:`yade_scripts.runs.checkpoint.encode`).
        """
        O, f = self.O, self.files
        t_save = time.time()
        with self.scene_saving():
            scene = scene_bytes(O, f.checkpoint + ".scene.yade")
        self.log.flush()
        stage, eps_1 = where()
        state, arrays = get_state()
        meta = {"fingerprint": self.fingerprint, "step": O.iter, "time": O.time, "stage": stage,
                "eps_1": float(eps_1), "n_snapshots": self.writer.n_snapshots,
                "dump_parameters": self.writer.attrs["parameters"], "log_bytes": self.log.tell(), "why": why,
                **self.history()}
        clash = sorted(set(meta) & set(state))
        if clash:
            raise ValueError(f"the scene's checkpoint state may not use the names {clash}")
        meta.update(state)
        size = checkpoint.save(f.checkpoint, meta, arrays, {"scene": scene})
        self.say(f"checkpoint ({why}) at step {O.iter} ({stage}, eps_1 = {eps_1:.4f}): "
                 f"{os.path.basename(f.checkpoint)}, {size / 1e6:.1f} MB in {time.time() - t_save:.2f} s")
        self.last_checkpoint = time.time()

    def restore(self, set_state, where):
        """Put the run back in the state of :attr:`resumed`: YADE's scene,
        then ``set_state(meta, arrays)`` for the scene's own parts (``meta``:
        the checkpoint's metadata, the keys of ``get_state()`` among them).

        Needs :attr:`resumed` (not None) and :meth:`open_dump`. Takes the
        earlier attempts' history from the checkpoint, adds this resume to
        :attr:`resumes` and says one line.

        Parameters
        ----------
        set_state : callable
            ``set_state(meta, arrays)`` with the checkpoint's metadata
            (dict) and arrays (dict of name -> numpy.ndarray); its result
            is ignored.
        where : callable
            Takes no argument and returns ``(stage, eps_1)`` of the
            restored state (str, float).

        Returns
        -------
        None
        """
        r, O = self.resumed, self.O
        load_scene_bytes(O, r.scene, self.files.checkpoint + ".scene.yade")
        set_state(r.meta, r.arrays)
        stage, eps_1 = where()
        self.earlier_wall_seconds = r.meta["wall_seconds"]
        self.earlier_engine_seconds = r.meta["engine_seconds"]
        self.resumes = r.meta["resumes"] + [{
            "step": O.iter, "stage": stage, "eps_1": eps_1, "checkpoint": os.path.basename(r.checkpoint),
            "written_because": r.meta["why"], "at": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime())}]
        self.say(f"resumed from {os.path.basename(r.checkpoint)} at step {O.iter} ({stage}, eps_1 = {eps_1:.4f}, "
                 f"{self.writer.n_snapshots} snapshots kept)")

    def finish(self):
        """The run is over (done, or failed: a blow-up replays identically
        from a checkpoint): its checkpoints and progress record go.

        Returns
        -------
        None
        """
        checkpoint.remove(self.files.checkpoint)
        if os.path.exists(self.files.progress):
            os.remove(self.files.progress)

    # ------------------------------------------------------------ running
    def _on_term(self, signum, frame):
        self.terminated = True

    def end_of_step(self):
        """If a checkpoint is due, make this step the last of the run (the
        scene's controller calls this first thing every step).

        Returns
        -------
        None
        """
        if self._pause_request:
            self._pause_request = False
            self.O.stopAtIter = self.O.iter + 1

    def fail(self, reason):
        """The scene stops the run: ``reason`` (one line) is why.

        Parameters
        ----------
        reason : str
            One line, kept as :attr:`failed`; YADE is paused
            (:meth:`loop` then returns "failed").

        Returns
        -------
        None
        """
        self.failed = reason
        self.O.pause()

    def _run_until_stop(self):
        """Run; True when it stopped because a checkpoint is due (SIGTERM,
        or checkpoint_seconds of wall time since the last one), False when
        the scene stopped it (done, failed, or an exception)."""
        if self.terminated:
            return True
        O = self.O
        O.run()
        due = False
        while O.running:             # poll (not O.wait()) so that the SIGTERM handler gets to run
            time.sleep(0.05)
            if not due and (self.terminated or (self.checkpoint_seconds > 0 and
                                                time.time() - self.last_checkpoint >= self.checkpoint_seconds)):
                self._pause_request = True
                due = True
        O.wait()
        self._pause_request = False
        O.stopAtIter = 0
        return due

    def loop(self, done, get_state, where):
        """Run YADE until ``done()``, a failure (:meth:`fail`) or SIGTERM,
        with a checkpoint every checkpoint_seconds of wall time and one on
        SIGTERM. Returns "done", "failed", "terminated" (a checkpoint was
        written: run again to resume), "paused" (YADE was paused by
        something other than the scene, e.g. ``O.pause()`` from another
        thread; a checkpoint was written) or "stalled" (an exception in
        one of the scene's engines stopped YADE).

        Parameters
        ----------
        done : callable
            Takes no argument; True once the run has reached its end.
        get_state, where : callable
            As :meth:`save_checkpoint` takes them.

        Returns
        -------
        str
            "done", "failed", "terminated", "paused" or "stalled".

        Raises
        ------
        ValueError
            As :meth:`save_checkpoint`.
        """
        while True:
            before = getattr(sys, "last_value", None)      # YADE prints an engine's exception, which sets it
            due = self._run_until_stop()
            if self.failed:
                return "failed"
            if done():
                return "done"
            if not due:
                if getattr(sys, "last_value", None) is not before:
                    return "stalled"
                self.save_checkpoint("paused from outside", get_state, where)
                return "paused"
            self.save_checkpoint("SIGTERM" if self.terminated else "periodic", get_state, where)
            if self.terminated:
                return "terminated"


def remove_scratch_at_exit(tmp_filename):
    """Have YADE's scratch folder of this process removed when it exits.

    YADE 2023.02a makes a folder ``/tmp/yade-XXXXXX`` for every process
    (``O.tmpFilename()`` names files in it) and leaves it behind, empty, at
    every exit: one per run attempt, hundreds on a machine that ran a few
    studies. The folder is this process's own, so it is removed with
    everything in it by an exit function (which :func:`leave` runs too).

    Parameters
    ----------
    tmp_filename : str
        ``O.tmpFilename()`` of the running YADE, e.g.
        ``/tmp/yade-3Z5Pqz/tmp-0``.

    Returns
    -------
    str or None
        The folder that will be removed, or None when the name is not in a
        ``yade-*`` folder (nothing is registered then).

    Examples
    --------
    >>> import tempfile
    >>> d = tempfile.mkdtemp(prefix="yade-")
    >>> remove_scratch_at_exit(os.path.join(d, "tmp-0")) == d
    True
    >>> remove_scratch_at_exit("/tmp/elsewhere/tmp-0") is None
    True
    """
    folder = os.path.dirname(os.path.abspath(tmp_filename))
    if not os.path.basename(folder).startswith("yade-") or not os.path.isdir(folder):
        return None
    atexit.register(shutil.rmtree, folder, True)
    return folder


def leave(code):
    """End a scene's process with exit status ``code`` once its work is
    written: Python's exit functions run (the run's lock is released), the
    standard streams are flushed, then ``os._exit`` skips the C++ static
    destructors of YADE's libraries.

    With the kernel's YADE plugin loaded, a process that had saved or loaded
    a scene (a checkpoint on SIGTERM, a resume) sometimes aborted among those
    destructors, after its last line ("double free or corruption", exit -6,
    in a Boost.Log destructor of YADE's ``boot.so``): the dumps, checkpoints
    and logs were whole, the exit status wrong. The cause was not found (the
    plugin no longer registers with Boost.Serialization, which made it
    certain; the runs' dumps are equal bit for bit to the PyRunner path's).

    Parameters
    ----------
    code : int
        The exit status (the scene's EXIT_* codes).

    Returns
    -------
    None
        It does not return.
    """
    atexit._run_exitfuncs()
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):
            pass
    os._exit(int(code))


class Progress:
    """When to print a progress line: at most every ``seconds`` of wall time,
    with the steps per second since the last one.

    Parameters
    ----------
    seconds : float
        Wall seconds a line is due after the last one (more than).

    Attributes
    ----------
    seconds : float
        As given.
    last_time : float
        When the last line was due, or the object made (seconds since the
        epoch).
    last_step : int
        The step of the last line (0 at first, or :meth:`restart`'s).
    steps_per_second : float
        Steps per wall second at the last line (0.0 before the first).
    """

    def __init__(self, seconds):
        self.seconds = seconds
        self.last_time, self.last_step, self.steps_per_second = time.time(), 0, 0.0

    def tick(self, step):
        """The steps per second since the last line when a line is due now,
        else None.

        Parameters
        ----------
        step : int
            The step (YADE's iteration) now.

        Returns
        -------
        float or None
            Steps per wall second since the last line, when more than
            ``seconds`` have passed since it (the line is then counted as
            printed); else None.
        """
        now = time.time()
        if now - self.last_time <= self.seconds:
            return None
        self.steps_per_second = (step - self.last_step) / (now - self.last_time)
        self.last_time, self.last_step = now, step
        return self.steps_per_second

    def restart(self, step):
        """Count steps from ``step`` (a resumed run).

        Parameters
        ----------
        step : int
            The step (YADE's iteration) the run resumes at.

        Returns
        -------
        None
        """
        self.last_step = step
