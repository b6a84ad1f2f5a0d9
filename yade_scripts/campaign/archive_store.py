"""The archive's records: a study's analysed runs kept without their dumps
(what they are and how ``make study ARCHIVE=DEST`` reads them:
:mod:`yade_scripts.campaign.archive`, the command).

:func:`save` adds a study's complete, analysed runs to an archive;
:func:`archived` and :func:`conflicts` judge an archive's records against a
run folder for the study (which seeds it holds, which refuse);
:func:`study_folders` generates a study's run folders from the records;
:func:`library_fingerprint` names a shape library by its content.
"""
from __future__ import annotations

import datetime
import hashlib
import json
import os
import shutil

from postproc.staging import staging_dir

from ..launch.batch import table_lines
from ..runs.runlock import RunLock, describe
from ..runs.runstate import complete
from ..scene.parameters import ConfigError
from .generate import DEFAULT_LIBRARY, generate
from .presets import resolve
from .runfolders import analysis_folder, line_dump, run_folders, whole

#: the analysis files kept: the numbers the report reads, not the figures
KEPT_SUFFIXES = (".csv", ".json", ".txt")
#: a run folder's record in the archive: its params.json and shape library (:func:`_folder_record`)
FOLDER_RECORD = "archive.json"
#: the record of one archived run, beside where its dump would be
RUN_RECORD = ".archived.json"
#: the archive's lock: one process adds to it at a time (:func:`save`)
LOCK = "archive.lock"
#: seconds between two tries of the lock
LOCK_WAIT_SECONDS = 0.2


def sha256_of(path, chunk=1 << 22):
    """SHA-256 (hex) of a file's bytes.

    Parameters
    ----------
    path : str
        The file.
    chunk : int
        Bytes read at a time (default 4 MiB).

    Returns
    -------
    str
        64 lowercase hexadecimal characters.

    Raises
    ------
    OSError
        The file cannot be read.
    """
    h = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(chunk), b""):
            h.update(block)
    return h.hexdigest()


def _analysis_folders(dump):
    """{name: folder} of a dump's analyses: "" its primary one, COUNT its
    analysis with that contact count (:func:`postproc.study.counts.count_folder`)."""
    primary = analysis_folder(dump)
    out = {"": primary}
    parent, base = os.path.split(primary)
    for name in sorted(os.listdir(parent)) if os.path.isdir(parent) else []:
        if name.startswith(base + "-") and os.path.isdir(os.path.join(parent, name)):
            out[name[len(base) + 1:]] = os.path.join(parent, name)
    return out


def _made_from(folder, dump):
    """None when ``folder`` holds an analysis (summary.csv, source.json) of
    the dump file ``dump`` as it is now, made under today's analysis
    version; else why not."""
    from postproc.provenance import SOURCE_FILE, input_files, is_today

    try:
        with open(os.path.join(folder, SOURCE_FILE)) as fh:
            src = json.load(fh)
        if not os.path.exists(os.path.join(folder, "summary.csv")):
            return "no summary.csv"
    except (OSError, ValueError):
        return "no readable source.json"
    if not is_today(src):
        return "made under another analysis version"
    if src.get("input") != input_files(dump):
        return "made from another dump file"
    return None


def library_fingerprint(path):
    """SHA-256 (hex) of a shape library's content: every dataset (its path,
    dtype, shape and bytes) and every attribute of the HDF5 file in sorted
    order, but the file's ``name`` attribute (the name it was written
    under). Two builds of the same library are two files whose bytes differ
    (the name, HDF5's own layout), with the same fingerprint.

    Parameters
    ----------
    path : str
        The shape library (HDF5).

    Returns
    -------
    str
        64 lowercase hexadecimal characters.

    Raises
    ------
    OSError
        The file cannot be opened as HDF5 (h5py's error).
    """
    import h5py
    import numpy as np

    h = hashlib.sha256()

    def attrs(obj, where):
        for k in sorted(obj.attrs):
            if where == "/" and k == "name":
                continue
            h.update(f"{where}@{k}".encode())
            h.update(repr(np.asarray(obj.attrs[k]).tolist()).encode())

    with h5py.File(path, "r") as f:
        attrs(f, "/")
        names = []
        f.visit(names.append)
        for name in sorted(names):
            obj = f[name]
            attrs(obj, name)
            if isinstance(obj, h5py.Dataset):
                data = np.ascontiguousarray(obj[()])
                h.update(f"{name}:{data.dtype.str}:{data.shape}".encode())
                h.update(data.tobytes() if data.dtype.kind != "O" else repr(data.tolist()).encode())
    return h.hexdigest()


def _library_of(table):
    """:func:`library_fingerprint` of the shape library a run folder's
    params.json names, or None (no library: spheres)."""
    with open(os.path.join(table, "params.json")) as fh:
        lib = json.load(fh).get("library")
    path = os.path.join(table, lib) if lib else None
    return library_fingerprint(path) if path and os.path.exists(path) else None


def _folder_record(table):
    """What a run folder's archived runs must share with a folder that uses
    them: its params.json and its shape library's content
    (:func:`library_fingerprint`)."""
    with open(os.path.join(table, "params.json")) as fh:
        params = json.load(fh)
    return {"params": params, "library_fingerprint": _library_of(table)}


def save(study, dest, echo=print):
    """Add to the archive ``dest`` every run of ``study`` that is complete,
    adds up (:meth:`postproc.schema.DumpReader.verify`) and whose primary
    analysis was made from its dump by today's code, with every analysis of
    it by another contact count that is current too.

    A run already archived from the same dump under today's analysis
    version is left as it is (or, analysed now by more contact counts,
    archived again with them); a run whose seed is archived from another
    dump (another host's run) is refused, so that no seed is archived
    twice; a run archived under another analysis version is never replaced
    (skipped, with why: that record is another version's result). Each run's files are written to a
    temporary folder and moved into place, its record last: a run is in
    the archive when, and only when, its record is. One process adds to an
    archive at a time (``DEST/archive.lock``; another waits for it).

    Parameters
    ----------
    study : str
        A study folder (or one generated run folder).
    dest : str
        The archive's folder (made when missing).
    echo : callable
        Where each run's line goes.

    Returns
    -------
    saved : list of str
        "<run folder>/<dump name>" of each run added.
    skipped : list of str
        One line per run not added, with why.

    Raises
    ------
    ConfigError
        ``study`` holds no run folder, or one of its run folders is
        archived in ``dest`` with other parameters or another shape library.
    """
    if not os.path.isdir(study) or not run_folders(study):
        raise ConfigError(f"{study}: no generated run folder (table.txt) in it or one level below")
    os.makedirs(dest, exist_ok=True)
    lock = _lock(dest, echo)
    try:
        return _save(study, dest, echo)
    finally:
        lock.release()


def _lock(dest, echo):
    """The archive's lock (:data:`LOCK`), held; waits for another holder."""
    lock = RunLock(os.path.join(dest, LOCK), "archive", subject=f"the archive {dest}")
    return lock.acquire_waiting(LOCK_WAIT_SECONDS, lambda holder: echo(
        f"[archive] waiting for {describe(holder)} to finish adding to {dest}"))


def _save(study, dest, echo):
    """:func:`save`'s work, the archive's lock held."""
    from postproc.provenance import ANALYSIS_VERSION, code_hash, is_today
    from postproc.schema import DumpReader

    saved, skipped = [], []
    for table in run_folders(study):
        name = os.path.basename(os.path.abspath(table))
        into = os.path.join(dest, name)
        mine = _folder_record(table)
        there = _read_json(os.path.join(into, FOLDER_RECORD))
        if there == {}:
            raise ConfigError(f"{into}/{FOLDER_RECORD}: the archive's folder record cannot be read "
                              "(not a JSON object): mend it from git or remove the folder")
        if there is not None and there != mine:
            raise ConfigError(f"{into}: archived runs of other parameters or another shape library than {table}")
        os.makedirs(into, exist_ok=True)
        if there is None:
            _write_json(os.path.join(into, FOLDER_RECORD), mine)
        for line in table_lines(table):
            if line.error:
                continue
            dump = line_dump(table, line)
            stem = os.path.splitext(os.path.basename(dump))[0]
            where = f"{name}/{os.path.basename(dump)}"
            if not complete(dump):
                skipped.append(f"{where}: not complete")
                continue
            folders = _analysis_folders(dump)
            counts = {c: f for c, f in folders.items() if c and _made_from(f, dump) is None}
            record_path = os.path.join(into, stem + RUN_RECORD)
            old = _read_json(record_path)
            if old is not None and (not old or _run_record_fault(old)):
                skipped.append(f"{where}: its archived record {record_path} cannot be read; not replaced "
                               "(mend it from git, or move it aside)")
                continue
            current = bool(old) and is_today(old)
            if old and not current:
                skipped.append(f"{where}: archived under another analysis version; never replaced "
                               "(archive to a new folder)")
                continue
            if current and _same_file(old, into, dump) and set(counts) <= set(old.get("counts", [])):
                skipped.append(f"{where}: already archived")
                continue
            bad = whole(dump)
            why = f"does not add up ({bad})" if bad else _made_from(folders[""], dump)
            if why:
                skipped.append(f"{where}: {why}")
                continue
            sha = sha256_of(dump)
            if current and old.get("dump", {}).get("sha256") != sha:
                skipped.append(f"{where}: its seed is archived from another run (dump SHA-256 "
                               f"{old.get('dump', {}).get('sha256', '?')[:12]}), not added")
                continue
            if old is not None:
                echo(f"[archive] {where}: archived again (with more counts)")
                os.remove(record_path)
            with DumpReader(dump) as r:
                n = len(r)
            kept = {"": folders[""], **counts}
            files = _copy_run(dump, table, into, kept)
            info = os.path.relpath(os.path.splitext(dump)[0] + ".info.json", table)
            record = {"seed": line.row.get("seed"), "description": line.description,
                      "analyses": {c: os.path.relpath(f, table) for c, f in kept.items()},
                      "info": info if info in files else None,
                      "dump": {"name": os.path.basename(dump), "bytes": os.path.getsize(dump),
                               "snapshots": n, "sha256": sha},
                      "version": ANALYSIS_VERSION, "code": code_hash(), "counts": sorted(counts), "files": files,
                      "saved": datetime.datetime.now().isoformat(timespec="seconds")}
            _write_json(record_path, record)
            saved.append(where)
            echo(f"[archive] {where}: kept ({len(files)} files, counts: {', '.join(sorted(counts)) or 'none'})")
    return saved, skipped


def _same_file(record, into, dump):
    """Whether the archived run ``record`` (in the archive's run folder
    ``into``) was analysed from the dump file ``dump`` as it is now (its
    primary analysis's source.json names the same file, size and
    modification time), without reading the dump."""
    from postproc.provenance import SOURCE_FILE, input_files

    try:
        with open(os.path.join(into, record["analyses"][""], SOURCE_FILE)) as fh:
            return json.load(fh).get("input") == input_files(dump)
    except (OSError, ValueError, KeyError, TypeError):
        return False


def _copy_run(dump, table, into, folders):
    """Copy a run's kept files (its info and attempts records, and of each
    analysis folder the files of :data:`KEPT_SUFFIXES`) from ``table`` to
    ``into``, each folder through a temporary one; {path relative to
    ``into``: SHA-256}."""
    stem = os.path.splitext(dump)[0]
    files = {}
    for path in (stem + ".info.json", stem + ".attempts.json"):
        if os.path.exists(path):
            rel = os.path.relpath(path, table)
            os.makedirs(os.path.dirname(os.path.join(into, rel)), exist_ok=True)
            shutil.copyfile(path, os.path.join(into, rel))
            files[rel] = sha256_of(path)
    for folder in folders.values():
        rel = os.path.relpath(folder, table)
        tmp = staging_dir(into, ".tmp-")
        for f in sorted(os.listdir(folder)):
            if f.endswith(KEPT_SUFFIXES) and os.path.isfile(os.path.join(folder, f)):
                shutil.copyfile(os.path.join(folder, f), os.path.join(tmp, f))
                files[f"{rel}/{f}"] = sha256_of(os.path.join(folder, f))
        target = os.path.join(into, rel)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        if os.path.isdir(target):
            shutil.rmtree(target)
        os.replace(tmp, target)
    return files


def archived(dest, table, counts=()):
    """The archived runs of the run folder ``table`` in the archive
    ``dest``, each usable or not, with why.

    A run is usable when its record is there, the archive's copy of the run
    folder has the same parameters and shape library as ``table``, every
    file it records has the recorded SHA-256, its analysis version is
    today's (:func:`postproc.provenance.is_today`), and it has an analysis
    by every contact count of ``counts``.

    Parameters
    ----------
    dest : str or None
        The archive (None: none, returns {}).
    table : str
        A generated run folder of the study or the collect.
    counts : sequence of str
        The other contact counts the study reads (S1 runs only).

    Returns
    -------
    dict
        dump name -> ("ok", entry) or ("refused", one line why). An entry has
        "analysis" (its primary analysis folder in the archive), "counts"
        {count: folder}, "info" (its run.info.json, or None) and "record".
    """
    return {k: v[:2] for k, v in _judge(dest, table, counts).items()}


def conflicts(dest, table, counts=()):
    """The archived runs of ``table`` in ``dest`` that a study must not run
    again over: archived under another analysis version, or from a run
    folder of other parameters or another shape library (running it here
    would put another result beside, or over, that record).

    Parameters
    ----------
    dest : str or None
        The archive (None or "": no archive).
    table : str
        A sample's run folder of the study (its ``params.json`` is read).
    counts : sequence of str
        The contact counts the study reads besides its own.

    Returns
    -------
    list of str
        One line per such run, naming it and why; empty when there is none
        or no archive (see :func:`archived`).
    """
    return [line for how, line, conflict in _judge(dest, table, counts).values() if conflict]


def _judge(dest, table, counts):
    """:func:`archived`'s verdicts, each with a third item: True when the
    run is refused for another version, other parameters or another shape
    library (:func:`conflicts`)."""
    from postproc.provenance import is_today, version_of

    if not dest:
        return {}
    into = os.path.join(dest, os.path.basename(os.path.abspath(table)))
    there = _read_json(os.path.join(into, FOLDER_RECORD))
    if there is None:
        return {}
    unread = None if there else f"its folder's record {FOLDER_RECORD} cannot be read"
    records = sorted(f for f in os.listdir(into) if f.endswith(RUN_RECORD))
    with open(os.path.join(table, "params.json")) as fh:
        sample = json.load(fh).get("sample")
    same = there == _folder_record(table)
    out = {}
    for f in records:
        rec = _read_json(os.path.join(into, f)) or {}
        fault = _run_record_fault(rec)
        named = None if fault else rec.get("dump", {}).get("name")
        name = named if isinstance(named, str) and named else f[: -len(RUN_RECORD)] + ".h5"
        why, conflict = None, False
        if unread or fault:
            why = unread or fault
        elif not same:
            why, conflict = "archived from a run folder of other parameters or another shape library", True
        elif not is_today(rec):
            v = version_of(rec)
            why = (f"analysed under analysis version {v}" if v is not None else
                   f"analysed by code {str(rec.get('code'))[:12]} of no known analysis version")
            why, conflict = why + ", not today's", True
        else:
            for rel, sha in rec.get("files", {}).items():
                p = os.path.join(into, rel)
                if not os.path.exists(p) or sha256_of(p) != sha:
                    why = f"{rel} is missing or not as recorded"
                    break
            missing = [c for c in (counts if sample == "polyhedra" else ()) if c not in rec.get("counts", [])]
            if why is None and missing:
                why = f"no analysis by the {', '.join(missing)} count"
        if why:
            out[name] = ("refused", f"{into}/{name} archived but not used: {why}"
                         + ("" if conflict else "; it runs again"), conflict)
            continue
        where = {c: os.path.join(into, rel) for c, rel in rec["analyses"].items()}
        out[name] = ("ok", {"analysis": where.pop(""), "counts": where, "record": rec,
                            "info": rec.get("info") and os.path.join(into, rec["info"])}, False)
    return out


def study_folders(dest, out, library=None):
    """Generate in ``out`` the run folders of the archive ``dest``'s study,
    as the study made them (each archived folder's preset, sample, other
    parameters and seeds, from its ``archive.json`` and run records), so
    that ``python -m yade_scripts.campaign.study --collect OUT --archive DEST``
    reads the archive on a host that has none of the study's folders.

    Parameters
    ----------
    dest : str
        The archive.
    out : str
        The study folder to make (it must not hold these run folders yet).
    library : str, optional
        The polyhedra's shape library (default
        :data:`yade_scripts.campaign.generate.DEFAULT_LIBRARY`, ``make shapes``); its
        content must be the archived one's (:func:`library_fingerprint`).

    Returns
    -------
    list of str
        The run folders made.

    Raises
    ------
    ConfigError
        ``dest`` holds no archived run folder, one folder's record cannot
        be read, or a generated folder's parameters or shape library differ
        from the archived ones (named; nothing else is checked then).
    """
    names = sorted(n for n in os.listdir(dest) if os.path.isfile(os.path.join(dest, n, FOLDER_RECORD))) \
        if os.path.isdir(dest) else []
    if not names:
        raise ConfigError(f"{dest}: no archived run folder ({FOLDER_RECORD}) in it")
    made = []
    for name in names:
        rec = _read_json(os.path.join(dest, name, FOLDER_RECORD))
        params = (rec or {}).get("params")
        if not isinstance(params, dict) or "preset" not in params or "sample" not in params:
            raise ConfigError(f"{dest}/{name}/{FOLDER_RECORD}: no parameters (preset, sample) in it")
        seeds = sorted({int(r["seed"]) for r in (_read_json(os.path.join(dest, name, f)) or {}
                                                  for f in os.listdir(os.path.join(dest, name))
                                                  if f.endswith(RUN_RECORD))
                        if str(r.get("seed", "")).isdigit()})
        if not seeds:
            raise ConfigError(f"{dest}/{name}: no archived run with a seed")
        base = resolve(params["preset"], params["sample"])
        overrides = {k: v for k, v in params.items() if k in base and base[k] != v and k not in ("seed", "library")}
        table = os.path.join(out, name)
        generate(table, params["preset"], params["sample"], overrides, seeds=seeds,
                 library=library or DEFAULT_LIBRARY)
        mine = _folder_record(table)
        if mine != rec:
            keys = sorted(k for k in set(mine["params"]) | set(params)
                          if mine["params"].get(k) != params.get(k))
            what = (f"parameters {', '.join(keys)}" if keys else
                    f"shape library (fingerprint {str(mine['library_fingerprint'])[:12]}, archived "
                    f"{str(rec.get('library_fingerprint'))[:12]}: give the library it was run on)")
            raise ConfigError(f"{table}: generated with other {what} than {dest}/{name}")
        made.append(table)
    return made


def _read_json(path):
    """The JSON object (a dict) in the record ``path``: None when there is
    no such file, {} when it cannot be read or holds no object."""
    try:
        with open(path, encoding="utf-8") as fh:
            value = json.load(fh)
    except FileNotFoundError:
        return None
    except (OSError, ValueError, RecursionError):
        return {}
    return value if isinstance(value, dict) else {}


def _run_record_fault(rec):
    """None when the run record ``rec`` has the shape :func:`_save` writes
    (the fields :func:`archived` reads), else what is wrong."""
    if not rec:
        return "its record cannot be read"
    analyses = rec.get("analyses")
    if not isinstance(analyses, dict) or not isinstance(analyses.get(""), str) \
            or not all(isinstance(v, str) for v in analyses.values()):
        return "its record names no analysis"
    files, counts, dump = rec.get("files", {}), rec.get("counts", []), rec.get("dump")
    if not isinstance(files, dict) or not all(isinstance(x, str) for kv in files.items() for x in kv) \
            or not isinstance(counts, list) or not all(isinstance(c, str) for c in counts) \
            or not isinstance(rec.get("info"), (str, type(None))):
        return "its record is not of the archive's shape"
    if not isinstance(dump, dict) or not isinstance(dump.get("name"), str) \
            or not isinstance(dump.get("sha256"), str) or type(dump.get("snapshots")) is not int:
        return "its record does not describe its dump (name, sha256, snapshots)"
    return None


def _write_json(path, data):
    tmp = path + ".tmp"
    with open(tmp, "w") as fh:
        json.dump(data, fh, indent=1, sort_keys=True)
        fh.write("\n")
    os.replace(tmp, path)
