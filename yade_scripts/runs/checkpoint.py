"""Checkpoint files of a triaxial run: what an exact restart needs, written
atomically, with a version and a checksum.

One checkpoint is one file, ``STEM.ckpt`` next to the dump ``STEM.h5``::

    line 1   b"triaxial-checkpoint 1\\n"         (name and format version)
    line 2   JSON header, one line: {"payload_bytes": N, "sha256": HEX, "step": ...}
    then     N bytes: an uncompressed numpy .npz archive holding the arrays
             of the run (kernel state, tangential histories, shapes ...), the
             JSON metadata (``__meta__``, the Python side of the run) and the
             binary blobs (``__blob__NAME``, e.g. YADE's O.save of the scene)

:func:`save` writes ``STEM.ckpt.tmp``, fsyncs it, renames the current
checkpoint to ``STEM.ckpt.prev`` and the new one into place (``os.replace``
is atomic; the folder is fsynced), so a process killed at any instant leaves
at least one complete checkpoint: the new one, or the previous one as
``.prev``. :func:`read` checks the name, version, length and SHA-256 and
raises :class:`CheckpointError` with a one-line reason for a truncated,
corrupt or foreign file; :func:`candidates` lists the newest first.

numpy + standard library only: YADE's system Python imports it (from the run
folder's copy of the packages) and so do the tests.
"""
from __future__ import annotations

import hashlib
import io
import json
import os

import numpy as np

MAGIC = b"triaxial-checkpoint"
FORMAT_VERSION = 1
_META = "__meta__"
_BLOB = "__blob__"

#: parameters that may change between an interrupted run and its resume
#: without changing the physics (how often to report or checkpoint, the
#: thread count: the kernel is bit-identical on any number of threads, and
#: on the plugin's path as on the PyRunner's)
RUNTIME_PARAMETERS = frozenset({"resume", "checkpoint_seconds", "report_seconds", "max_steps", "kernel_threads",
                                "kernel_plugin", "timing", "noTableOk"})


class CheckpointError(ValueError):
    """A checkpoint that cannot be used (truncated, corrupt, foreign or of
    another run); the message is one line.

    A :class:`ValueError`, so that a caller catching ValueError (e.g.
    :func:`choose`) catches it too.

    Attributes
    ----------
    args : tuple of str
        One element: the one-line message, the file's name first.
    """


def fingerprint(parameters):
    """SHA-256 (hex) of the parameters that define a run's physics (every
    parameter but :data:`RUNTIME_PARAMETERS`), to refuse a checkpoint of
    another run.

    Parameters
    ----------
    parameters : dict
        The run's parameters, name (str) -> value. Names in
        :data:`RUNTIME_PARAMETERS` and names starting with ``_`` are left
        out; the others are serialised as sorted-key JSON, a value JSON
        cannot hold as its ``repr``.

    Returns
    -------
    str
        64 lowercase hexadecimal characters.
    """
    keep = {k: v for k, v in parameters.items() if k not in RUNTIME_PARAMETERS and not k.startswith("_")}
    text = json.dumps(keep, sort_keys=True, default=repr)
    return hashlib.sha256(text.encode()).hexdigest()


def _fsync_dir(path):
    try:
        fd = os.open(path or ".", os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def encode(meta, arrays=None, blobs=None):
    """The bytes of a checkpoint file (the layout of the module docstring).

    Parameters
    ----------
    meta : dict
        JSON-serialisable metadata (floats are written with repr, so they
        come back bit for bit); its ``"step"`` and ``"stage"`` (None when
        missing) are copied into the header line.
    arrays : dict, optional
        name (str) -> array-like, each stored as ``np.asarray`` of it (any
        shape and dtype but object). Names may not start with ``__``.
    blobs : dict, optional
        name (str) -> bytes-like (e.g. YADE's saved scene), stored as uint8
        arrays ``__blob__NAME``.

    Returns
    -------
    bytes
        The whole file: the name-and-version line, the JSON header line
        (payload_bytes, sha256, step, stage) and the uncompressed ``.npz``
        payload.

    Raises
    ------
    ValueError
        An array name starting with ``__`` (reserved), or an array of dtype
        object.
    TypeError
        ``meta`` holds a value JSON cannot serialise (raised by
        :func:`json.dumps`).
    """
    arrays = dict(arrays or {})
    for k in arrays:
        if k.startswith("__"):
            raise ValueError(f"array name {k!r} is reserved")
    payload = {k: np.asarray(v) for k, v in arrays.items()}
    for k, v in payload.items():
        if v.dtype == object:
            raise ValueError(f"array {k!r} has dtype object")
    payload[_META] = np.frombuffer(json.dumps(meta, sort_keys=True).encode(), np.uint8)
    for k, b in (blobs or {}).items():
        payload[_BLOB + k] = np.frombuffer(bytes(b), np.uint8)
    buf = io.BytesIO()
    np.savez(buf, **payload)
    body = buf.getvalue()
    header = {"payload_bytes": len(body), "sha256": hashlib.sha256(body).hexdigest(),
              "step": meta.get("step"), "stage": meta.get("stage")}
    return MAGIC + b" %d\n" % FORMAT_VERSION + json.dumps(header).encode() + b"\n" + body


def decode(data, name="checkpoint"):
    """(meta, arrays, blobs) from the bytes of a checkpoint file; raises
    CheckpointError (one line) when they are not a complete checkpoint of
    this format.

    Parameters
    ----------
    data : bytes
        The whole file, as :func:`encode` wrote it.
    name : str
        What the error messages call it (the file's path).

    Returns
    -------
    meta : dict
        The JSON metadata, as given to :func:`encode`.
    arrays : dict
        name (str) -> numpy.ndarray, as stored.
    blobs : dict
        name (str) -> bytes.

    Raises
    ------
    CheckpointError
        One line starting with ``name``: no name-and-version line, another
        format version, an unreadable header line, a payload shorter or
        longer than the header says, a SHA-256 mismatch, or a payload that
        is not a readable ``.npz`` archive with the metadata.
    """
    first, sep, rest = data.partition(b"\n")
    if not sep or not first.startswith(MAGIC + b" "):
        raise CheckpointError(f"{name}: not a triaxial checkpoint (no '{MAGIC.decode()}' header)")
    try:
        version = int(first[len(MAGIC) + 1:])
    except ValueError:
        raise CheckpointError(f"{name}: unreadable format version {first[len(MAGIC) + 1:]!r}") from None
    if version != FORMAT_VERSION:
        raise CheckpointError(f"{name}: format version {version}, this code reads version {FORMAT_VERSION}")
    line, sep, body = rest.partition(b"\n")
    try:
        header = json.loads(line)
        n, digest = int(header["payload_bytes"]), str(header["sha256"])
    except (ValueError, KeyError, TypeError):
        raise CheckpointError(f"{name}: header line unreadable (truncated or corrupt)") from None
    if not sep or len(body) < n:
        raise CheckpointError(f"{name}: truncated ({len(body)} of {n} payload bytes)")
    if len(body) > n:
        raise CheckpointError(f"{name}: {len(body) - n} bytes too many after the payload (corrupt)")
    if hashlib.sha256(body).hexdigest() != digest:
        raise CheckpointError(f"{name}: checksum mismatch (corrupt)")
    try:
        with np.load(io.BytesIO(body), allow_pickle=False) as z:
            items = {k: z[k] for k in z.files}
        meta = json.loads(items.pop(_META).tobytes())
    except Exception as exc:      # a payload with the right checksum but no valid archive: not ours
        raise CheckpointError(f"{name}: payload unreadable ({exc.__class__.__name__})") from None
    blobs = {k[len(_BLOB):]: items.pop(k).tobytes() for k in list(items) if k.startswith(_BLOB)}
    return meta, items, blobs


def header(path):
    """The JSON header of the checkpoint file ``path`` (payload_bytes,
    sha256, step, stage), from its first two lines only: cheap for a large
    checkpoint, but the payload is not checked (:func:`read` does).
    CheckpointError (one line) when the file is missing or its first two
    lines are not a header of this format.

    Parameters
    ----------
    path : str
        The checkpoint file.

    Returns
    -------
    dict
        The header line as written by :func:`encode`: "payload_bytes"
        (int, bytes), "sha256" (hex str), "step" (int or None, YADE's
        iteration) and "stage" (str or None), as far as the file has them
        (only that it is a JSON object is checked).

    Raises
    ------
    CheckpointError
        One line starting with ``path``: the file cannot be read, its first
        line is not this format's name and version, or its second line (at
        most 1 MiB read) is not a JSON object.
    """
    try:
        with open(path, "rb") as fh:
            first, second = fh.readline(), fh.readline(1 << 20)
    except OSError as exc:
        raise CheckpointError(f"{path}: cannot be read ({exc.strerror or exc})") from None
    if first.rstrip(b"\n") != MAGIC + b" %d" % FORMAT_VERSION:
        raise CheckpointError(f"{path}: not a triaxial checkpoint of format version {FORMAT_VERSION}")
    try:
        h = json.loads(second)
    except ValueError:
        raise CheckpointError(f"{path}: header line unreadable (truncated or corrupt)") from None
    if not isinstance(h, dict):
        raise CheckpointError(f"{path}: header line unreadable (truncated or corrupt)")
    return h


def read(path):
    """(meta, arrays, blobs) of the checkpoint file ``path``; CheckpointError
    (one line) when it is missing, truncated, corrupt or foreign.

    Parameters
    ----------
    path : str
        The checkpoint file.

    Returns
    -------
    meta : dict
        The JSON metadata.
    arrays : dict
        name (str) -> numpy.ndarray.
    blobs : dict
        name (str) -> bytes.

    Raises
    ------
    CheckpointError
        One line: the file cannot be read, or :func:`decode` refuses it.
    """
    try:
        with open(path, "rb") as fh:
            data = fh.read()
    except OSError as exc:
        raise CheckpointError(f"{path}: cannot be read ({exc.strerror or exc})") from None
    return decode(data, path)


def save(path, meta, arrays=None, blobs=None):
    """Write a checkpoint atomically (see the module docstring); the previous
    one is kept as ``path + '.prev'`` until this one is complete. Returns the
    file size in bytes.

    Parameters
    ----------
    path : str
        The checkpoint file (``STEM.ckpt``); ``path + '.tmp'`` is written
        first, an existing ``path`` becomes ``path + '.prev'`` (replacing
        an older ``.prev``).
    meta, arrays, blobs
        As :func:`encode` takes them.

    Returns
    -------
    int
        The file's size, bytes.

    Raises
    ------
    ValueError
        As :func:`encode` (a reserved array name, an object array); nothing
        is written then.
    """
    data = encode(meta, arrays, blobs)
    tmp = path + ".tmp"
    with open(tmp, "wb") as fh:
        fh.write(data)
        fh.flush()
        os.fsync(fh.fileno())
    if os.path.exists(path):
        os.replace(path, path + ".prev")
    os.replace(tmp, path)
    _fsync_dir(os.path.dirname(os.path.abspath(path)))
    return len(data)


def candidates(path):
    """The checkpoint files of ``path`` that exist, newest first: ``path``
    then ``path + '.prev'``.

    Parameters
    ----------
    path : str
        The checkpoint file (``STEM.ckpt``).

    Returns
    -------
    list of str
        Zero, one or two paths; whether they are readable is not checked
        (:func:`read`, :func:`choose`).
    """
    return [p for p in (path, path + ".prev") if os.path.exists(p)]


def remove(path):
    """Delete the checkpoint ``path``, its ``.prev`` and a left-over ``.tmp``.

    Parameters
    ----------
    path : str
        The checkpoint file (``STEM.ckpt``); those of the three that do not
        exist are skipped.

    Returns
    -------
    None
    """
    for p in (path, path + ".prev", path + ".tmp"):
        if os.path.exists(p):
            os.remove(p)


def pack_arrays(prefix, arrays):
    """{prefix + '/' + name: array} (a group of arrays inside a checkpoint).

    Parameters
    ----------
    prefix : str
        The group's name.
    arrays : dict
        name (str) -> array (any value; it is not copied).

    Returns
    -------
    dict
        ``prefix/name`` (str) -> the same array, for the ``arrays`` of
        :func:`encode` or :func:`save`.
    """
    return {f"{prefix}/{k}": v for k, v in arrays.items()}


def unpack_arrays(prefix, arrays):
    """The group ``prefix`` of :func:`pack_arrays`, names without the prefix.

    Parameters
    ----------
    prefix : str
        The group's name.
    arrays : dict
        name (str) -> array, e.g. the arrays of :func:`read`.

    Returns
    -------
    dict
        name (str, ``prefix/`` removed) -> array, for every name that
        starts with ``prefix/``; {} when there is none.
    """
    n = len(prefix) + 1
    return {k[n:]: v for k, v in arrays.items() if k.startswith(prefix + "/")}


def ragged(rows, dtype):
    """(concatenated rows, offsets (len + 1,)) of a list of arrays (e.g. the
    vertices of every shape).

    Parameters
    ----------
    rows : sequence of array-like
        K arrays of shapes (n_k, ...), the same trailing shape each.
    dtype : numpy dtype or type
        The dtype each row is converted to.

    Returns
    -------
    flat : numpy.ndarray
        The rows concatenated along axis 0, shape (sum n_k, ...); shape
        (0,) of ``dtype`` when ``rows`` is empty.
    off : numpy.ndarray
        int64, shape (K + 1,): row k is ``flat[off[k]:off[k + 1]]``;
        ``off[0] == 0``.
    """
    rows = [np.asarray(r, dtype) for r in rows]
    off = np.concatenate([[0], np.cumsum([len(r) for r in rows])]).astype(np.int64)
    flat = np.concatenate(rows) if rows else np.zeros((0,), dtype)
    return flat, off


def unragged(flat, off):
    """The list of arrays of :func:`ragged`.

    Parameters
    ----------
    flat : numpy.ndarray
        The concatenated rows, shape (N, ...).
    off : numpy.ndarray
        Integer offsets, shape (K + 1,).

    Returns
    -------
    list of numpy.ndarray
        K arrays, ``flat[off[k]:off[k + 1]]`` (views of ``flat``).
    """
    return [flat[off[k]:off[k + 1]] for k in range(len(off) - 1)]


def choose(path, expected_fingerprint, accept, say=print):
    """The newest usable checkpoint of ``path`` (``path``, then its
    ``.prev``): (file, meta, arrays, blobs, accept(meta)) or None.

    A candidate is skipped, with one line through ``say``, when it is
    truncated, corrupt or foreign (:func:`read`), was written by a run with
    other parameters (``expected_fingerprint``, see :func:`fingerprint`), or
    when ``accept(meta)`` raises ValueError (e.g. the dump lacks a snapshot
    the checkpoint counts). ``accept`` is the caller's own check and
    preparation (reopening the dump); its result is returned.

    Parameters
    ----------
    path : str
        The checkpoint file (``STEM.ckpt``).
    expected_fingerprint : str
        :func:`fingerprint` of this run's parameters; a checkpoint whose
        ``meta["fingerprint"]`` differs is skipped.
    accept : callable
        ``accept(meta)``: the caller's check of a candidate's metadata (a
        dict); raising ValueError (CheckpointError and DumpFormatError
        among them), KeyError or TypeError skips the candidate.
    say : callable
        Takes each one-line message of a skipped candidate (``checkpoint
        not used: ...; trying the previous one`` or ``...; starting
        afresh``).

    Returns
    -------
    tuple or None
        ``(file, meta, arrays, blobs, value)`` of the first usable
        candidate: its path (str), metadata (dict), arrays (dict of name
        -> numpy.ndarray), blobs (dict of name -> bytes) and
        ``accept(meta)``'s result; None when no candidate exists or none is
        usable.
    """
    found = candidates(path)
    for k, p in enumerate(found):
        try:
            meta, arrays, blobs = read(p)
            if meta.get("fingerprint") != expected_fingerprint:
                raise CheckpointError(f"{p}: written by a run with other parameters")
            value = accept(meta)
        except (ValueError, KeyError, TypeError) as exc:    # CheckpointError, DumpFormatError, a field missing
            rest = "trying the previous one" if k + 1 < len(found) else "starting afresh"
            why = str(exc).splitlines()[0] if str(exc) else exc.__class__.__name__
            if isinstance(exc, KeyError):
                why = f"{p}: field {why} missing"
            elif isinstance(exc, TypeError):
                why = f"{p}: a field of the wrong type ({why})"
            say(f"checkpoint not used: {why}; {rest}")
            continue
        return p, meta, arrays, blobs, value
    return None
