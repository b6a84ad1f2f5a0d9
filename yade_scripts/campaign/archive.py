"""A study's analysed runs kept without their dumps, to carry a long study from host to host.

    python -m yade_scripts.campaign.archive STUDY DEST
    python -m yade_scripts.campaign.archive collect DEST OUT [--library LIB]
    python -m yade_scripts.campaign.archive collect-at-commit DEST OUT

A 5000-grain study runs for many hours, longer than a host may be kept: a
new host starts with none of the old one's run folders. The archive keeps,
of every run of STUDY that is complete, adds up and is analysed under
today's analysis version (:data:`postproc.provenance.ANALYSIS_VERSION`),
what the report reads (the analysis folders' numbers: ``*.csv``,
``*.json``, ``*.txt``; no figures, no dump) and its record
``<stem>.archived.json``: the dump's name, size, snapshot count and SHA-256,
the analysis version and, as provenance, the analysis code's hash
(:func:`postproc.provenance.code_hash`), the
SHA-256 of every file kept, and when. DEST mirrors STUDY's run folders
(``DEST/<run folder>/``, each with ``archive.json``: its parameters and a
fingerprint of its shape library's content), so it is small (about 0.4 MB
a 5000-grain S1 seed) and can be committed.

``make study ... ARCHIVE=DEST`` (``python -m yade_scripts.campaign.study --archive
DEST``) then runs only the seeds DEST does not hold: an archived seed is
used as it is (:func:`archived`) when its run folder has the same
parameters and shape library, its files are those recorded and its
analysis version is today's (:func:`postproc.provenance.version_of`: a
record older than the version reads its code hash through
:data:`postproc.provenance.HISTORICAL_CODE_VERSIONS`), and it is never
run again, so no seed is counted twice. An archived record is never
deleted or replaced by another version's: a study that meets one of
another version, other parameters or another shape library refuses before
it runs anything (:func:`conflicts`); write to a new archive, or read the
old one with the code that made it. A record of the same version whose
files are damaged is named and its seed runs again. A seed whose complete dump is on this host is analysed from it,
as always. ``--collect DIR --archive DEST`` reads it the same way. ``collect DEST OUT`` generates the study's run folders in
OUT from the archive's records (:func:`study_folders`) and collects them
with the archive, on a host that has none of them; ``collect-at-commit``
does it with the code of the commit that made the archive
(:mod:`yade_scripts.campaign.archive_commit`), for an archive of another analysis
version. Runs
carried over this way come from other hosts: each repeats step for step
only on its own host's CPU (docs/measurements.md, "Preparation"), and the
statistics over seeds are what they share.
"""
from __future__ import annotations

import argparse
import os
import sys

from ..scene.parameters import ConfigError
from .archive_commit import collect_at_commit
from .archive_store import (FOLDER_RECORD, RUN_RECORD, _read_json, archived, conflicts, library_fingerprint,  # noqa: F401
                            save, study_folders)
from .study import main as study_main


def main(argv=None):
    """``python -m yade_scripts.campaign.archive STUDY DEST``: :func:`save`; exit 0
    when it ran (each run kept or skipped is named), 2 for a bad STUDY or
    DEST (one line).

    Parameters
    ----------
    argv : list of str, optional
        The command line's arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit code: 0 when :func:`save` ran (each run skipped on
        stdout, the count on stderr); 2 when it refused (ConfigError) or a
        file could not be read or written (OSError), one line on stderr.
        (A bad command line exits 2 through argparse.)
    """
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv[:1] in (["collect"], ["collect-at-commit"]):
        return _collect_main(argv)
    ap = argparse.ArgumentParser(prog="python -m yade_scripts.campaign.archive", description=__doc__.splitlines()[0])
    ap.add_argument("study", help="the study folder (or one generated run folder)")
    ap.add_argument("dest", help="the archive's folder, e.g. reference_data/<study name>")
    args = ap.parse_args(argv)
    try:
        saved, skipped = save(args.study, args.dest)
    except (ConfigError, OSError) as exc:
        print(f"archive: error: {exc}", file=sys.stderr)
        return 2
    for line in skipped:
        print(f"[archive] {line}", flush=True)
    print(f"archive: {len(saved)} run(s) added to {args.dest}, {len(skipped)} not", file=sys.stderr)
    return 0


def _collect_main(argv):
    """``collect ARCHIVE OUT [--library LIB]``: the archive's study folders
    (:func:`study_folders`) collected with today's code; ``collect-at-commit
    ARCHIVE OUT``: with the code of the commit that made the archive
    (:mod:`yade_scripts.campaign.archive_commit`). Exit 0, 2 with one line when
    refused, else the collect's exit code."""
    ap = argparse.ArgumentParser(prog=f"python -m yade_scripts.campaign.archive {argv[0]}")
    ap.add_argument("archive")
    ap.add_argument("out", help="a new folder")
    if argv[0] == "collect":
        ap.add_argument("--library", help="the shape library the study ran on (default runs/shapes/library.h5)")
    args = ap.parse_args(argv[1:])
    try:
        if argv[0] == "collect-at-commit":
            collect_at_commit(args.archive, args.out)
            return 0
        if os.path.exists(args.out) and os.listdir(args.out):
            raise ConfigError(f"{args.out}: exists and is not empty; give a new folder")
        study_folders(args.archive, args.out, args.library)
    except (ConfigError, OSError) as exc:
        print(f"archive: error: {exc}", file=sys.stderr)
        return 2
    counts = sorted({c for n in os.listdir(args.archive) if os.path.isdir(os.path.join(args.archive, n))
                     for f in os.listdir(os.path.join(args.archive, n)) if f.endswith(RUN_RECORD)
                     for c in (_read_json(os.path.join(args.archive, n, f)) or {}).get("counts", [])})
    return study_main(["--collect", args.out, "--archive", args.archive, "--no-figures", "--counts", *counts])


if __name__ == "__main__":
    sys.exit(main())
