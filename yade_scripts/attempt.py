"""One attempt at a run, for the scene (``triaxial.py``): resume from the
newest usable checkpoint or start afresh, run YADE with periodic and
SIGTERM checkpoints, and the exit codes.

Exit codes of ``triaxial.py``: :data:`EXIT_DONE` done (or complete
already), :data:`EXIT_FAILED` stopped on a blow-up or max_steps (message
printed, snapshots kept), :data:`EXIT_TERM` checkpoint written after
SIGTERM (run again to resume); anything else is a crash (run again to
resume from the last periodic checkpoint).

numpy + the standard library; the YADE objects (``O``) are passed in.
"""
from __future__ import annotations

import os
import shutil
import signal
import time

try:
    from yade_scripts import checkpoint
except ImportError:           # run folder: lib/checkpoint.py
    import checkpoint  # type: ignore

EXIT_DONE, EXIT_FAILED, EXIT_TERM = 0, 3, 75


def run_files(dump, ckpt, stem):
    """Every file an attempt writes: the dump and its parts folder, the
    checkpoint and its previous copy, STEM.log.csv and STEM.info.json."""
    return [dump, dump + ".parts", ckpt, ckpt + ".prev", stem + ".log.csv", stem + ".info.json"]


def resume_or_start(dump, ckpt, stem, fingerprint, resume, dumpschema, say):
    """Decide how this attempt begins. Returns ``("resume", chosen)`` with
    the checkpoint :func:`checkpoint.choose` picked and its reopened dump
    writer (path, meta, arrays, blobs, writer); ``("complete", None)`` when
    the dump is finished already; or ``("afresh", None)`` after removing
    what an unfinished attempt left (said through ``say``)."""
    if resume:
        chosen = checkpoint.choose(ckpt, fingerprint,
                                   lambda meta: dumpschema.DumpWriter.resume(dump, meta["n_snapshots"]), say=say)
        if chosen is not None:
            return "resume", chosen
    if os.path.exists(dump):
        try:
            with dumpschema.DumpReader(dump) as r:
                if r.complete:
                    return "complete", None
        except dumpschema.DumpFormatError:
            pass
    left = [p for p in run_files(dump, ckpt, stem) if os.path.exists(p)]
    if left:
        say(f"starting afresh: removing the unfinished attempt ({', '.join(map(os.path.basename, left))})")
        shutil.rmtree(dump + ".parts", ignore_errors=True)
        for p in left:
            if os.path.isfile(p):
                os.remove(p)
    return "afresh", None


def scene_bytes(O, path):
    """The YADE scene (O.save) as bytes, through the temporary file
    ``path``."""
    O.save(path)
    with open(path, "rb") as fh:
        blob = fh.read()
    os.remove(path)
    return blob


def load_scene_bytes(O, blob, path):
    """O.load of a scene saved by :func:`scene_bytes`, through ``path``."""
    with open(path, "wb") as fh:
        fh.write(blob)
    O.load(path)
    os.remove(path)


class Runner:
    """Runs YADE until the scene stops it or a checkpoint is due.

    SIGTERM only raises a flag (:attr:`terminated`); the run then stops at
    the end of a step. The stop goes through ``O.stopAtIter``, set by
    :meth:`end_of_step` inside the step (the scene's controller calls it
    first thing every step): YADE then ends its loop after that step is
    complete. (``O.pause()`` from this thread would clear ``O.running``
    while a step is still under way, so ``O.wait()`` returns early and a
    checkpoint could catch half a step.)"""

    def __init__(self, O, checkpoint_seconds):
        self.O, self.checkpoint_seconds = O, checkpoint_seconds
        self.terminated = False
        self.failed = None                   # why the scene stopped the run, when it did
        self._pause_request = False
        self.last_checkpoint = self.t0 = time.time()
        # what the earlier attempts of this run took (from the checkpoint)
        self.earlier_wall_seconds, self.earlier_engine_seconds, self.resumes = 0.0, {}, []
        signal.signal(signal.SIGTERM, self._on_term)

    def start(self):
        """This attempt's clock starts now."""
        self.t0 = self.last_checkpoint = time.time()

    def wall_seconds(self):
        """Wall time of the run so far (s), earlier attempts included."""
        return self.earlier_wall_seconds + time.time() - self.t0

    def history(self, engine_seconds):
        """{wall_seconds, engine_seconds, resumes} of the run so far, with
        ``engine_seconds`` ({engine: s}) of this attempt added to the
        earlier attempts'."""
        total = {k: self.earlier_engine_seconds.get(k, 0.0) + v for k, v in engine_seconds.items()}
        return {"wall_seconds": self.wall_seconds(), "resumes": self.resumes, "engine_seconds": total}

    def resumed_from(self, meta, record):
        """This attempt continues the checkpoint ``meta`` (as written with
        :meth:`history`); ``record`` describes the resume."""
        self.earlier_wall_seconds = meta["wall_seconds"]
        self.earlier_engine_seconds = meta["engine_seconds"]
        self.resumes = meta["resumes"] + [record]

    def _on_term(self, signum, frame):
        self.terminated = True

    def end_of_step(self):
        """If a checkpoint is due, make this step the last of the run."""
        if self._pause_request:
            self._pause_request = False
            self.O.stopAtIter = self.O.iter + 1

    def run_until_stop(self):
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

    def checkpointed(self):
        """A checkpoint was written now."""
        self.last_checkpoint = time.time()


class Progress:
    """When to print a progress line: at most every ``seconds`` of wall time,
    with the steps per second since the last one."""

    def __init__(self, seconds):
        self.seconds = seconds
        self.last_time, self.last_step, self.steps_per_second = time.time(), 0, 0.0

    def tick(self, step):
        """The steps per second since the last line when a line is due now,
        else None."""
        now = time.time()
        if now - self.last_time <= self.seconds:
            return None
        self.steps_per_second = (step - self.last_step) / (now - self.last_time)
        self.last_time, self.last_step = now, step
        return self.steps_per_second

    def restart(self, step):
        """Count steps from ``step`` (a resumed run)."""
        self.last_step = step
