"""The contact-dump schema: the single source of truth for what a run writes.

This module is shared by the YADE scene scripts (Debian's system Python,
numpy 1.24, h5py 3.7) and by the ``postproc`` analysis package. It therefore
imports **only** the standard library, numpy and h5py, and nothing else from
``postproc``. It can be copied next to a generated ``triaxial.py`` as is.

Layout of one run (schema version 2 or 3, all quantities in SI units)
======================================================================
One HDF5 file per simulation run, ``RUN.h5``. File attributes:

``schema``            ``"granular-contact-dump"``
``schema_version``    ``2`` (an integer), or ``3`` for a dump that holds
                      contact points (``points/*`` below, written by
                      Contact Dynamics runs). Version 1 (no contact
                      footprint) is still read; readers refuse any other
                      version
``sample_kind``       ``"polyhedra"`` or ``"spheres"``
``parameters``        JSON text: every parameter that generated the run
``units``             JSON text: unit of every dataset below
``overlap_kind``      ``"volume"`` (m^3, polyhedra volumetric law) or
                      ``"depth"`` (m, sphere law)
``created``           ISO 8601 UTC time the writer was opened
``n_snapshots``       the number of snapshot groups (written after the data)
``complete``          ``1`` once the writer was closed normally, else ``0``
                      (written last of all)

``/shapes`` (polyhedra only, written once). Shape ``s`` owns vertices
``vertices[vertex_offsets[s]:vertex_offsets[s+1]]`` (m, in the body's local
frame: origin at the centre of mass, axes along the principal axes of
inertia) and triangles ``triangles[triangle_offsets[s]:triangle_offsets[s+1]]``
(indices local to the shape, counter-clockwise seen from outside).
``triangle_face`` (same length as ``triangles``) numbers the geometric face
each triangle belongs to inside its shape (coplanar triangles share a face).

``/snapshots/NNNNNN`` (one group per snapshot, ``NNNNNN`` = 0, 1, 2 ... in
time order). Group attributes ``step`` (int), ``time`` (s), ``stage``
(``"isotropic"``, ``"shear"`` ...). Datasets:

``box/lo``, ``box/hi``        (3,) m. Inner wall planes: the box is
                              ``lo <= x <= hi``; volume = prod(hi - lo).
``walls/id``                  (6,) int64 body ids of the walls, in the order
                              x-, x+, y-, y+, z-, z+.
``walls/force``               (6, 3) N. Total force exerted **on** each wall
                              by the particles. Under compression the x+ wall
                              is pushed towards +x.
``cell``                      (3, 3) m, optional: a periodic cell whose
                              columns are the cell vectors (YADE's
                              ``O.cell.hSize``). Then the volume is
                              det(cell), branch vectors follow the
                              minimum-image convention, and ``walls/id``,
                              ``walls/force`` may be empty (0 walls);
                              ``box/lo``, ``box/hi`` bound the cell (their
                              difference gives the strains).
``bodies/id``                 (B,) int64 particle ids (walls are not bodies
                              here; they are listed in ``walls/id``).
``bodies/kind``               (B,) int8: 0 sphere, 1 polyhedron.
``bodies/position``           (B, 3) m, centre of mass.
``bodies/orientation``        (B, 4) unit quaternion (w, x, y, z) turning the
                              local frame into the global one.
``bodies/volume``             (B,) m^3.
``bodies/mass``               (B,) kg.
``bodies/shape_index``        (B,) int32 row of ``/shapes`` (-1 for spheres).
``bodies/size``               (B,) m. d = 2 x the largest centre-to-vertex
                              distance (polyhedra), 2 x radius (spheres).
``bodies/velocity``           (B, 3) m/s (optional).
``contacts/id1``, ``id2``     (C,) int64 body ids (a wall id is allowed on
                              either side).
``contacts/point``            (C, 3) m, contact point.
``contacts/normal``           (C, 3) unit normal pointing from id1 to id2.
``contacts/force_normal``     (C, 3) N. Normal force exerted **on id2 by
                              id1**; a repulsive contact has
                              ``force_normal . normal > 0``.
``contacts/force_tangential`` (C, 3) N. Tangential force on id2 by id1.
``contacts/overlap``          (C,) m^3 or m (see ``overlap_kind``).
``contacts/footprint``        (C, 2) m, optional (version 2, polyhedra runs
                              with the compiled kernel): the principal
                              extents of the overlap's shadow on the contact
                              plane, largest first (``shapes/overlap.py``).
``contacts/footprint_area``   (C,) m^2, optional: the area of that shadow.

``points/*`` (optional, schema version 3): the individual contact points
of a contact (Contact Dynamics: every interaction LMGC90 detects is one
point, and a pair of polyhedra touching along an edge or a face has two or
more). ``contacts/*`` then holds one row per pair of bodies, its forces the
sums over the pair's points. P points:

``points/contact``            (P,) int64 row of ``contacts/*`` the point
                              belongs to (0 <= contact < C).
``points/point``              (P, 3) m, the point.
``points/normal``             (P, 3) unit normal pointing from id1 to id2 of
                              its contact.
``points/force_normal``       (P, 3) N, normal force on id2 by id1 at this
                              point.
``points/force_tangential``   (P, 3) N, tangential force on id2 by id1.
``points/gap``                (P,) m, the signed distance between the two
                              surfaces at the point (negative =
                              interpenetration).

Sign convention: forces are the forces on id2 by id1; stresses computed from
them are compression positive.

``/index`` (one row per snapshot, written with each snapshot; dumps written
before it existed have none and still read). Datasets, each of length
``n_snapshots``, row ``k`` for ``/snapshots/k``:

``step``                      (N,) int64, the snapshot's ``step`` attribute.
``n_bodies``                  (N,) int64, the length of its ``bodies/id``.
``n_contacts``                (N,) int64, the length of its ``contacts/id1``.
``checksum``                  (N,) uint32, :func:`snapshot_checksum` of it.

Group attribute ``checksum_kind`` = ``"crc32-v1"``: ``zlib.crc32`` run over,
in this order, the line ``"step {step} time {time.hex()} stage {stage}\\n"``
(``float.hex``: exact) and then, for every dataset of the snapshot in the
order of its path inside the group (``"bodies/id"``, ``"box/hi"``, ...,
sorted as Python strings), the line ``"{path} {dtype} {shape}\\n"`` (the
little-endian numpy dtype string such as ``<f8``; the shape as ``6x3``, empty
for a scalar) followed by the raw little-endian bytes in C order.

Whole-dump checks
=================
:class:`DumpReader` refuses (one-line :class:`DumpFormatError`) a dump whose
``n_snapshots`` is not the number of snapshot groups, whose groups are not
exactly ``000000`` ... ``n-1``, or whose index has not one row per snapshot;
:meth:`DumpReader.read` refuses a snapshot whose step, body or contact count
or checksum differs from its index row (another writer's part, or damage).
:meth:`DumpReader.verify` (or :func:`verify_dump`) reads every snapshot once
to check a whole dump before an analysis.

Atomic writes
=============
HDF5 is not journaled: a process killed while it modifies a file can leave
the whole file unreadable. The writer therefore never modifies a file that a
reader may need. Each snapshot is written to its own small HDF5 file in the
folder ``RUN.h5.parts/``, closed, fsync'ed and renamed into place; then the
small master ``RUN.h5`` (attributes plus HDF5 external links to the parts) is
rewritten to a temporary name and renamed over the old one. ``os.replace`` is
atomic, so at every instant ``RUN.h5`` is a complete file naming only complete
snapshots. h5py follows the external links transparently, so readers see the
layout above. The master also holds ``/index``, rewritten with it, so the
index always names exactly the snapshots the master links to.
:meth:`DumpWriter.close` finally packs everything into one self-contained
``RUN.h5`` through a temporary file: the shapes and snapshots are copied
first, then ``/index``, then the attributes, ``n_snapshots`` and, last of
all, ``complete``; every packed snapshot is checked against the writer's
index (a part replaced by another writer stops the packing, the parts are
kept) before the temporary file is renamed over ``RUN.h5`` and the parts
folder removed. :meth:`DumpWriter.resume` takes the index back from the
master and checks every kept part against it.
"""
from __future__ import annotations

import datetime as _dt
import json
import os
import shutil
import zlib
from dataclasses import dataclass, field
from typing import Iterator, Optional

import h5py
import numpy as np

SCHEMA_NAME = "granular-contact-dump"
SCHEMA_VERSION = 2
POINTS_SCHEMA_VERSION = 3    # the version of a dump that holds points/*
READABLE_VERSIONS = (1, 2, 3)   # version 1: no contacts/footprint; 3: points/*
SAMPLE_KINDS = ("polyhedra", "spheres")
WALL_ORDER = ("x-", "x+", "y-", "y+", "z-", "z+")
KIND_SPHERE, KIND_POLYHEDRON, KIND_WALL = 0, 1, 2

UNITS = {
    "time": "s", "box": "m", "walls/force": "N", "bodies/position": "m",
    "bodies/orientation": "1 (quaternion w,x,y,z)", "bodies/volume": "m^3",
    "bodies/mass": "kg", "bodies/size": "m", "bodies/velocity": "m/s",
    "contacts/point": "m", "contacts/normal": "1",
    "contacts/force_normal": "N", "contacts/force_tangential": "N",
    "contacts/overlap": "m^3 (overlap_kind=volume) or m (overlap_kind=depth)",
    "contacts/footprint": "m", "contacts/footprint_area": "m^2",
    "shapes/vertices": "m",
}
POINTS_UNITS = {   # added to ``units`` in a dump that holds points (version 3)
    "points/point": "m", "points/normal": "1", "points/force_normal": "N",
    "points/force_tangential": "N", "points/gap": "m",
}

_BODY_FIELDS = {  # name: (dtype, trailing shape, required)
    "id": (np.int64, (), True), "kind": (np.int8, (), True),
    "position": (np.float64, (3,), True), "orientation": (np.float64, (4,), True),
    "volume": (np.float64, (), True), "mass": (np.float64, (), True),
    "shape_index": (np.int32, (), True), "size": (np.float64, (), True),
    "velocity": (np.float64, (3,), False),
}
_CONTACT_FIELDS = {
    "id1": (np.int64, (), True), "id2": (np.int64, (), True),
    "point": (np.float64, (3,), True), "normal": (np.float64, (3,), True),
    "force_normal": (np.float64, (3,), True),
    "force_tangential": (np.float64, (3,), True),
    "overlap": (np.float64, (), True),
    "footprint": (np.float64, (2,), False),
    "footprint_area": (np.float64, (), False),
}
_POINT_FIELDS = {
    "contact": (np.int64, ()), "point": (np.float64, (3,)),
    "normal": (np.float64, (3,)), "force_normal": (np.float64, (3,)),
    "force_tangential": (np.float64, (3,)), "gap": (np.float64, ()),
}
POINT_FIELDS = tuple(_POINT_FIELDS)
UNIT_NORMAL_TOL = 1e-6   # |1 - |n|| allowed for points/normal (text outputs hold 7-8 digits)
CHECKSUM_KIND = "crc32-v1"    # how /index/checksum is computed (snapshot_checksum)
INDEX_FIELDS = ("step", "n_bodies", "n_contacts", "checksum")
_INDEX_DTYPES = (np.int64, np.int64, np.int64, np.uint32)


class DumpFormatError(ValueError):
    """A dump that does not follow this schema (or cannot be read at all)."""


@dataclass
class Snapshot:
    """One state of a run, as plain numpy arrays (SI units).

    Contact forces are the forces on ``id2`` by ``id1``. ``force`` is the
    total contact force (C, 3); ``force_normal`` (C, 3) its normal part when
    the source gives it (None for flat contact tables). Quantities a source
    does not provide are None (or NaN for the box of a flat table).
    ``points`` (version-3 dumps) maps each of :data:`POINT_FIELDS` to its
    array: ``contact`` (P,) int64 row of the contact arrays, ``point``,
    ``normal``, ``force_normal``, ``force_tangential`` (P, 3) and ``gap``
    (P,) m (negative = interpenetration); None when the snapshot has none.
    """

    name: str
    step: int
    time: float
    stage: str
    volume: float                  # m^3, box volume (or given by the user)
    box_lo: np.ndarray             # (3,) m, NaN when unknown
    box_hi: np.ndarray             # (3,) m, NaN when unknown
    wall_ids: np.ndarray           # (W,) int64
    wall_forces: Optional[np.ndarray]  # (W, 3) N on each wall, or None
    body_ids: np.ndarray           # (B,) int64
    positions: np.ndarray          # (B, 3) m
    id1: np.ndarray                # (C,) int64
    id2: np.ndarray                # (C,) int64
    point: np.ndarray              # (C, 3) m
    force: np.ndarray              # (C, 3) N, on id2 by id1
    force_normal: Optional[np.ndarray] = None   # (C, 3) N
    normal: Optional[np.ndarray] = None         # (C, 3)
    overlap: Optional[np.ndarray] = None        # (C,)
    body_kind: Optional[np.ndarray] = None      # (B,) int8
    orientations: Optional[np.ndarray] = None   # (B, 4)
    volumes: Optional[np.ndarray] = None        # (B,)
    masses: Optional[np.ndarray] = None         # (B,)
    shape_index: Optional[np.ndarray] = None    # (B,)
    sizes: Optional[np.ndarray] = None          # (B,)
    footprint: Optional[np.ndarray] = None      # (C, 2) m, overlap shadow extents (kernel runs)
    footprint_area: Optional[np.ndarray] = None  # (C,) m^2
    cell: Optional[np.ndarray] = None           # (3, 3) m, periodic cell, columns = cell vectors
    branch: Optional[np.ndarray] = None         # (C, 3) m, explicit x2 - x1 (NaN for walls)
    points: Optional[dict] = None               # points/* arrays by field name (version 3), or None
    extra: dict = field(default_factory=dict)

    @property
    def box_lengths(self) -> np.ndarray:
        """(3,) m, hi - lo (NaN when the box is unknown)."""
        return np.asarray(self.box_hi, float) - np.asarray(self.box_lo, float)


def snapshot_checksum(step, time, stage, datasets) -> int:
    """The ``crc32-v1`` checksum of one snapshot (see the module docstring).

    Parameters
    ----------
    step : int
    time : float
    stage : str
        The snapshot group's attributes.
    datasets : dict
        Every dataset of the snapshot: path inside the snapshot group
        (``"bodies/id"``, ``"box/lo"`` ...) to array.

    Returns
    -------
    int
        ``zlib.crc32`` of the attributes line, then of each dataset's
        ``"{path} {dtype} {shape}"`` line and raw little-endian bytes, in the
        sorted order of the paths (0 <= value < 2**32).
    """
    if isinstance(stage, bytes):
        stage = stage.decode()
    crc = zlib.crc32(f"step {int(step)} time {float(time).hex()} stage {stage}\n".encode())
    for path in sorted(datasets):
        arr = np.asarray(datasets[path])
        arr = np.ascontiguousarray(arr, dtype=arr.dtype.newbyteorder("<"))
        shape = "x".join(str(n) for n in arr.shape)
        crc = zlib.crc32(f"{path} {arr.dtype.str} {shape}\n".encode(), crc)
        crc = zlib.crc32(arr.reshape(-1).view(np.uint8), crc)
    return crc & 0xFFFFFFFF


def _index_row(step, time, stage, datasets):
    """(step, n_bodies, n_contacts, checksum) of one snapshot."""
    return (int(step), len(datasets["bodies/id"]), len(datasets["contacts/id1"]),
            snapshot_checksum(step, time, stage, datasets))


def _load_group(g):
    """(step, time, stage, {path: array}) of a snapshot group: every dataset
    below it, read once. Raises KeyError/OSError/ValueError when it is
    incomplete or unreadable."""
    datasets = {}

    def take(path, obj):
        if isinstance(obj, h5py.Dataset):
            datasets[path] = obj[()]

    g.visititems(take)
    stage = g.attrs["stage"]
    stage = stage.decode() if isinstance(stage, bytes) else str(stage)
    return int(g.attrs["step"]), float(g.attrs["time"]), stage, datasets


def _row_differences(row, recorded, check_checksum=True):
    """What differs between an index row computed from a snapshot and the
    recorded one: a list of short phrases (empty when they agree)."""
    out = []
    for (what, got, want) in (("step", row[0], recorded[0]), ("bodies", row[1], recorded[1]),
                              ("contacts", row[2], recorded[2])):
        if int(got) != int(want):
            out.append(f"{what} {got}, the index says {want}" if what == "step"
                       else f"{got} {what}, the index says {want}")
    if check_checksum and int(row[3]) != int(recorded[3]):
        out.append(f"checksum {int(row[3]):08x}, the index says {int(recorded[3]):08x}")
    return out


def _read_index(f, where):
    """The index of an open dump as (rows, checksum kind): rows a list of
    (step, n_bodies, n_contacts, checksum) tuples; None when the dump has
    no index (written before it existed). Raises DumpFormatError (one line)
    when it is there but unreadable or ragged."""
    if "index" not in f:
        return None
    try:
        g = f["index"]
        cols = [np.asarray(g[k][()]).reshape(-1) for k in INDEX_FIELDS]
        kind = g.attrs.get("checksum_kind", "")
    except (KeyError, OSError, ValueError) as exc:
        raise DumpFormatError(f"{where}: /index is incomplete or unreadable ({exc})") from None
    if len({len(c) for c in cols}) != 1:
        raise DumpFormatError(f"{where}: /index datasets have different lengths "
                              f"({', '.join(f'{k} {len(c)}' for k, c in zip(INDEX_FIELDS, cols))})")
    kind = kind.decode() if isinstance(kind, bytes) else str(kind)
    return [tuple(int(c[i]) for c in cols) for i in range(len(cols[0]))], kind


def _write_index(f, rows):
    g = f.create_group("index")
    for k, (name, dtype) in enumerate(zip(INDEX_FIELDS, _INDEX_DTYPES)):
        g[name] = np.array([r[k] for r in rows], dtype=dtype)
    g.attrs["checksum_kind"] = CHECKSUM_KIND


def _ranges(names):
    """'000000–000004, 000006' for a list of snapshot names."""
    nums = sorted(int(n) for n in names if n.isdigit())
    parts, k = [], 0
    while k < len(nums):
        j = k
        while j + 1 < len(nums) and nums[j + 1] == nums[j] + 1:
            j += 1
        parts.append(f"{nums[k]:06d}" if j == k else f"{nums[k]:06d}–{nums[j]:06d}")
        k = j + 1
    parts += [repr(n) for n in names if not n.isdigit()]
    return ", ".join(parts)


def _fsync_file(path: str) -> None:
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _fsync_dir(path: str) -> None:
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


def _as_field(name, value, spec, n):
    dtype, trailing, _ = spec
    arr = np.asarray(value, dtype=dtype)
    if arr.shape != (n,) + trailing:
        raise DumpFormatError(
            f"{name}: expected shape {(n,) + trailing}, got {arr.shape}")
    return arr


def check_points(points, n_contacts, where="points"):
    """Validate the contact points of one snapshot.

    Parameters
    ----------
    points : dict
        ``contact`` (P,) int, ``point``, ``normal``, ``force_normal``,
        ``force_tangential`` (P, 3) float (m, unit, N, N) and ``gap`` (P,)
        m, as in the module docstring. Other keys are refused.
    n_contacts : int
        C, the number of rows of the snapshot's ``contacts/*``.
    where : str
        What to name in an error (a file and snapshot when reading).

    Returns
    -------
    dict
        The same fields as contiguous arrays of the schema's dtypes.

    Raises
    ------
    DumpFormatError
        (one line) on a missing or unknown field, a wrong shape or dtype
        kind, a non-finite value, a ``contact`` row outside ``0 .. C-1`` or
        a normal whose length differs from 1 by more than
        :data:`UNIT_NORMAL_TOL`.
    """
    if not isinstance(points, dict):
        raise DumpFormatError(f"{where}: expected a dict of arrays, got {type(points).__name__}")
    missing = [k for k in _POINT_FIELDS if k not in points]
    unknown = sorted(set(points) - set(_POINT_FIELDS))
    if missing or unknown:
        raise DumpFormatError(f"{where}: " + "; ".join(
            ([f"missing {', '.join(missing)}"] if missing else []) +
            ([f"unknown {', '.join(unknown)}"] if unknown else [])))
    n = len(np.atleast_1d(points["contact"]))
    out = {}
    for k, (dtype, trailing) in _POINT_FIELDS.items():
        raw = np.asarray(points[k])
        if raw.shape != (n,) + trailing:
            raise DumpFormatError(f"{where}/{k}: expected shape {(n,) + trailing}, got {raw.shape}")
        if k == "contact":
            if raw.dtype.kind not in "iu" and not (raw.size == 0 and raw.dtype.kind == "f"):
                raise DumpFormatError(f"{where}/contact: expected integers, got dtype {raw.dtype}")
        elif raw.dtype.kind not in "fiu":
            raise DumpFormatError(f"{where}/{k}: expected numbers, got dtype {raw.dtype}")
        arr = np.ascontiguousarray(raw, dtype=dtype)
        if k != "contact" and not np.all(np.isfinite(arr)):
            bad = int(np.flatnonzero(~np.all(np.isfinite(arr.reshape(n, -1)), axis=1))[0])
            raise DumpFormatError(f"{where}/{k}: not finite at point {bad}")
        out[k] = arr
    c = out["contact"]
    if n and (c.min() < 0 or c.max() >= n_contacts):
        bad = int(np.flatnonzero((c < 0) | (c >= n_contacts))[0])
        raise DumpFormatError(f"{where}/contact: row {int(c[bad])} at point {bad} is outside "
                              f"0..{n_contacts - 1} ({n_contacts} contacts)")
    if n:
        length = np.linalg.norm(out["normal"], axis=1)
        if np.abs(length - 1.0).max() > UNIT_NORMAL_TOL:
            bad = int(np.argmax(np.abs(length - 1.0)))
            raise DumpFormatError(f"{where}/normal: not a unit vector at point {bad} "
                                  f"(length {length[bad]:.9g})")
    return out


class DumpWriter:
    """Write one run, snapshot by snapshot, so that a killed writer never
    leaves an unreadable file (see the module docstring).

    Parameters
    ----------
    path : str
        The run file, ``RUN.h5``. Its parts go to ``RUN.h5.parts/``.
    sample_kind : {"polyhedra", "spheres"}
    parameters : dict
        JSON-serialisable generating parameters (stored verbatim).
    overlap_kind : {"volume", "depth"}
    """

    def __init__(self, path, sample_kind, parameters, overlap_kind="depth"):
        if sample_kind not in SAMPLE_KINDS:
            raise DumpFormatError(f"sample_kind must be one of {SAMPLE_KINDS}, "
                                  f"got {sample_kind!r}")
        if overlap_kind not in ("volume", "depth"):
            raise DumpFormatError("overlap_kind must be 'volume' or 'depth'")
        self.path = os.path.abspath(path)
        self.parts = self.path + ".parts"
        if os.path.exists(self.path) or os.path.exists(self.parts):
            raise DumpFormatError(f"{path}: refusing to overwrite an existing run")
        os.makedirs(self.parts)
        self.attrs = {
            "schema": SCHEMA_NAME, "schema_version": SCHEMA_VERSION,
            "sample_kind": sample_kind,
            "parameters": json.dumps(parameters, sort_keys=True, default=float),
            "units": json.dumps(UNITS, sort_keys=True),
            "overlap_kind": overlap_kind,
            "created": _dt.datetime.now(_dt.timezone.utc).isoformat(),
            "complete": 0,
        }
        self._links = {}      # name in master -> (part file basename, path in part)
        self._index = []      # (step, n_bodies, n_contacts, checksum) per snapshot
        self._n_snapshots = 0
        self._closed = False
        self._write_master()

    @property
    def n_snapshots(self):
        """Snapshots in the dump so far (those kept from an earlier attempt
        included)."""
        return self._n_snapshots

    @classmethod
    def resume(cls, path, n_snapshots):
        """Reopen the unfinished run ``path`` (not closed: its parts folder is
        still there) to append after its first ``n_snapshots`` snapshots,
        the count a checkpoint recorded. Snapshots written after that (by a
        run that went on past its checkpoint and then died) are removed, so
        the resumed run has no duplicate and no gap.

        The index is taken back from the master's ``/index`` and every kept
        part is read once and checked against its row (a master written
        before the index existed: the index is computed from the parts).

        Raises
        ------
        DumpFormatError
            (one line) when the run is complete, has fewer snapshots, an
            unreadable one, or a part that does not match the checksum the
            master recorded for it (another writer's).
        """
        path = os.path.abspath(path)
        parts = path + ".parts"
        n_snapshots = int(n_snapshots)
        if not os.path.isdir(parts):
            raise DumpFormatError(f"{path}: no parts folder to resume (a complete run, or no run)")
        try:
            with h5py.File(path, "r") as f:
                attrs = {k: f.attrs[k] for k in f.attrs if k != "n_snapshots"}
                recorded = _read_index(f, path)
        except OSError as exc:
            raise DumpFormatError(f"{path}: master file unreadable ({exc.__class__.__name__})") from None
        if attrs.get("schema") != SCHEMA_NAME or \
                int(attrs.get("schema_version", -1)) not in (SCHEMA_VERSION, POINTS_SCHEMA_VERSION):
            raise DumpFormatError(f"{path}: not a version-{SCHEMA_VERSION} or "
                                  f"-{POINTS_SCHEMA_VERSION} {SCHEMA_NAME} run")
        self = cls.__new__(cls)
        self.path, self.parts = path, parts
        self.attrs = {k: (v.decode() if isinstance(v, bytes) else v) for k, v in attrs.items()}
        self.attrs["complete"] = 0
        self._links, self._index, self._closed = {}, [], False
        if os.path.exists(os.path.join(parts, "shapes.h5")):
            self._links["shapes"] = ("shapes.h5", "/shapes")
        for k in range(n_snapshots):
            base = f"snapshot_{k:06d}.h5"
            try:
                with h5py.File(os.path.join(parts, base), "r") as f:
                    row = _index_row(*_load_group(f["snapshot"]))
            except (OSError, KeyError, ValueError):
                raise DumpFormatError(f"{path}: snapshot {k:06d} is missing or unreadable; "
                                      f"cannot resume after {n_snapshots} snapshots") from None
            if recorded is not None:
                rows, kind = recorded
                if k >= len(rows):
                    raise DumpFormatError(f"{path}: snapshot {k:06d} is not in the master's index "
                                          f"({len(rows)} rows); cannot resume after {n_snapshots} snapshots")
                bad = _row_differences(row, rows[k], check_checksum=kind == CHECKSUM_KIND)
                if bad:
                    raise DumpFormatError(f"{path}: snapshot {k:06d} ({os.path.basename(parts)}/{base}) is not "
                                          f"what the master recorded ({'; '.join(bad)}): replaced by another "
                                          f"writer?; cannot resume")
            self._index.append(row)
            self._links[f"snapshots/{k:06d}"] = (base, "/snapshot")
        self._n_snapshots = n_snapshots
        for name in os.listdir(parts):        # later snapshots and half-written files
            later = name.startswith("snapshot_") and name.endswith(".h5") and \
                name[len("snapshot_"):-3].isdigit() and int(name[len("snapshot_"):-3]) >= self._n_snapshots
            if later or name.endswith(".tmp"):
                os.remove(os.path.join(parts, name))
        self._write_master()
        return self

    # -- helpers ---------------------------------------------------------
    def _write_part(self, basename, fill):
        """Write one part file atomically: fill(h5file) into a temporary
        file, fsync, rename."""
        final = os.path.join(self.parts, basename)
        tmp = final + ".tmp"
        with h5py.File(tmp, "w") as f:
            fill(f)
        _fsync_file(tmp)
        os.replace(tmp, final)
        _fsync_dir(self.parts)

    def _write_attrs(self, f, complete):
        """The file attributes, ``n_snapshots`` and ``complete`` last."""
        for k, v in self.attrs.items():
            if k not in ("complete", "n_snapshots"):
                f.attrs[k] = v
        f.attrs["n_snapshots"] = self._n_snapshots
        f.attrs["complete"] = int(complete)

    def _write_master(self):
        tmp = self.path + ".tmp"
        rel = os.path.basename(self.parts)
        with h5py.File(tmp, "w") as f:
            f.require_group("snapshots")
            for name, (base, inner) in self._links.items():
                f[name] = h5py.ExternalLink(rel + "/" + base, inner)
            _write_index(f, self._index)
            self._write_attrs(f, self.attrs["complete"])
        _fsync_file(tmp)
        os.replace(tmp, self.path)
        _fsync_dir(os.path.dirname(self.path))

    # -- public API ------------------------------------------------------
    def write_shapes(self, vertices, triangles, triangle_faces=None):
        """Store the polyhedra shapes once.

        Parameters
        ----------
        vertices : list of (V_s, 3) arrays
            m, the vertices of shape s in its local frame.
        triangles : list of (T_s, 3) int arrays
            indices into the vertices of shape s.
        triangle_faces : list of (T_s,) int arrays, optional
            the geometric face of each triangle (default: every triangle
            is its own face).
        """
        if "shapes" in self._links:
            raise DumpFormatError("shapes were already written")
        if len(vertices) != len(triangles):
            raise DumpFormatError("vertices and triangles have different lengths")
        if triangle_faces is None:
            triangle_faces = [np.arange(len(t)) for t in triangles]
        v = [np.asarray(x, np.float64).reshape(-1, 3) for x in vertices]
        t = [np.asarray(x, np.int64).reshape(-1, 3) for x in triangles]
        tf = [np.asarray(x, np.int64).reshape(-1) for x in triangle_faces]
        for s, (vs, ts, fs) in enumerate(zip(v, t, tf)):
            if len(ts) and (ts.min() < 0 or ts.max() >= len(vs)):
                raise DumpFormatError(f"shape {s}: triangle index out of range")
            if len(fs) != len(ts):
                raise DumpFormatError(f"shape {s}: triangle_faces length mismatch")

        def fill(f):
            g = f.create_group("shapes")
            g["vertex_offsets"] = np.concatenate([[0], np.cumsum([len(x) for x in v])]).astype(np.int64)
            g["triangle_offsets"] = np.concatenate([[0], np.cumsum([len(x) for x in t])]).astype(np.int64)
            g["vertices"] = np.concatenate(v) if v else np.zeros((0, 3))
            g["triangles"] = np.concatenate(t) if t else np.zeros((0, 3), np.int64)
            g["triangle_face"] = np.concatenate(tf) if tf else np.zeros(0, np.int64)

        self._write_part("shapes.h5", fill)
        self._links["shapes"] = ("shapes.h5", "/shapes")
        self._write_master()

    def update_parameters(self, **values):
        """Add values learnt during the run (e.g. the solid fraction after
        compression, the top-wall speed) to the ``parameters`` attribute;
        stored with the next snapshot (or at close)."""
        params = json.loads(self.attrs["parameters"])
        params.update(values)
        self.attrs["parameters"] = json.dumps(params, sort_keys=True, default=float)

    def write_snapshot(self, *, step, time, stage, box_lo, box_hi, wall_ids,
                       wall_forces, bodies, contacts, cell=None, points=None):
        """Append one snapshot atomically.

        bodies : dict of arrays with the ``bodies/*`` fields of the schema.
        contacts : dict of arrays with the ``contacts/*`` fields.
        cell : (3, 3) m, optional periodic cell (columns are the cell
        vectors, YADE's ``O.cell.hSize``); a periodic snapshot may have no
        walls (``wall_ids`` and ``wall_forces`` empty).
        points : dict of arrays, optional: the contact points (``contact``
        (P,) row of ``contacts``, ``point``, ``normal``, ``force_normal``,
        ``force_tangential`` (P, 3), ``gap`` (P,) m, negative =
        interpenetration), validated by :func:`check_points`. The first
        snapshot with points makes the dump schema version 3; a dump
        without points stays version 2, unchanged.
        Shapes and units as in the module docstring; forces on id2 by id1.
        """
        if self._closed:
            raise DumpFormatError("writer is closed")
        if cell is not None:
            cell = np.asarray(cell, np.float64)
            if cell.shape != (3, 3) or not np.all(np.isfinite(cell)) or np.linalg.det(cell) <= 0:
                raise DumpFormatError("cell must be a finite (3, 3) matrix with det > 0")
        nb = len(np.atleast_1d(bodies["id"]))
        nc = len(np.atleast_1d(contacts["id1"]))
        b = {k: _as_field("bodies/" + k, bodies[k], s, nb)
             for k, s in _BODY_FIELDS.items() if s[2] or k in bodies}
        c = {k: _as_field("contacts/" + k, contacts[k], s, nc)
             for k, s in _CONTACT_FIELDS.items() if s[2] or k in contacts}
        lo = _as_field("box/lo", box_lo, (np.float64, (), True), 3)
        hi = _as_field("box/hi", box_hi, (np.float64, (), True), 3)
        nw = len(WALL_ORDER)
        if cell is not None:
            nw = 0 if len(np.atleast_1d(wall_ids)) == 0 else nw
        wid = _as_field("walls/id", wall_ids, (np.int64, (), True), nw)
        wf = _as_field("walls/force", np.reshape(wall_forces, (nw, 3)) if nw == 0 else wall_forces,
                       (np.float64, (3,), True), nw)
        name = f"{self._n_snapshots:06d}"
        data = {"box/lo": lo, "box/hi": hi, "walls/id": wid, "walls/force": wf}
        if cell is not None:
            data["cell"] = cell
        data.update({"bodies/" + k: arr for k, arr in b.items()})
        data.update({"contacts/" + k: arr for k, arr in c.items()})
        if points is not None:
            p = check_points(points, nc)
            data.update({"points/" + k: arr for k, arr in p.items()})
            if self.attrs["schema_version"] != POINTS_SCHEMA_VERSION:
                self.attrs["schema_version"] = POINTS_SCHEMA_VERSION
                units = json.loads(self.attrs["units"])
                units.update(POINTS_UNITS)
                self.attrs["units"] = json.dumps(units, sort_keys=True)
        step, time, stage = int(step), float(time), str(stage)
        row = _index_row(step, time, stage, data)

        def fill(f):
            g = f.create_group("snapshot")
            g.attrs["step"] = step
            g.attrs["time"] = time
            g.attrs["stage"] = stage
            for k, arr in data.items():
                g[k] = arr

        self._write_part(f"snapshot_{name}.h5", fill)
        self._links[f"snapshots/{name}"] = (f"snapshot_{name}.h5", "/snapshot")
        self._index.append(row)
        self._n_snapshots += 1
        self._write_master()
        return name

    def close(self, pack=True, complete=True):
        """Close the run.

        Parameters
        ----------
        pack : bool
            Copy every part into one self-contained file that atomically
            replaces ``RUN.h5``, then delete ``RUN.h5.parts/`` (default).
            The data are copied first, then ``/index``, the attributes,
            ``n_snapshots`` and ``complete`` last; each packed snapshot is
            checked against the index before the rename.
        complete : bool
            The run reached its end (a run stopped on a failure is closed
            with complete=False).

        Raises
        ------
        DumpFormatError
            (one line) when a part no longer holds what this writer wrote
            (another writer replaced it): nothing is packed, ``RUN.h5`` and
            its parts stay as they were (not complete).
        """
        if self._closed:
            return
        if not pack:
            self.attrs["complete"] = int(bool(complete))
            self._write_master()
            self._closed = True
            return
        tmp = self.path + ".pack.tmp"
        try:
            with h5py.File(self.path, "r") as src, h5py.File(tmp, "w") as dst:
                dst.require_group("snapshots")
                for name in self._links:
                    src.copy(src[name], dst, name=name)
                _write_index(dst, self._index)
                self._write_attrs(dst, bool(complete))
            self._check_packed(tmp)
        except (OSError, KeyError, ValueError) as exc:
            if os.path.exists(tmp):
                os.remove(tmp)
            if isinstance(exc, DumpFormatError):
                raise
            raise DumpFormatError(f"{self.path}: packing failed ({exc.__class__.__name__}: {exc}); "
                                  f"the parts are kept") from None
        self.attrs["complete"] = int(bool(complete))
        _fsync_file(tmp)
        os.replace(tmp, self.path)
        _fsync_dir(os.path.dirname(self.path))
        shutil.rmtree(self.parts, ignore_errors=True)
        self._closed = True

    def _check_packed(self, tmp):
        """Every snapshot of the packed temporary file against the index."""
        with h5py.File(tmp, "r") as f:
            for k, want in enumerate(self._index):
                bad = _row_differences(_index_row(*_load_group(f[f"snapshots/{k:06d}"])), want)
                if bad:
                    raise DumpFormatError(
                        f"{self.path}: snapshot {k:06d} in {os.path.basename(self.parts)}/ is not what this "
                        f"writer wrote ({'; '.join(bad)}): replaced by another writer?; not packed, "
                        f"the parts are kept")

    def __enter__(self):
        return self

    def __exit__(self, exc_type, *exc):
        # On an exception keep the parts (every snapshot already written
        # stays readable through the master file); pack on normal exit.
        self.close(pack=exc_type is None, complete=exc_type is None)


# ---------------------------------------------------------------- reading
@dataclass(frozen=True)
class DumpCheck:
    """What :meth:`DumpReader.verify` checked."""

    path: str
    n_snapshots: int
    checksums: bool      # every snapshot compared with its /index checksum
    complete: bool       # the dump's ``complete`` attribute


def _unreadable(path, exc):
    """Why h5py could not open ``path`` (its OSError ``exc``), in words: an
    empty file, a file that is not HDF5 at all (no HDF5 signature at its
    start), one that cannot be read, or an HDF5 file cut short or damaged."""
    try:
        size = os.path.getsize(path)
        with open(path, "rb") as fh:
            head = fh.read(8)
    except OSError as err:
        return f"cannot be read ({err.strerror or err.__class__.__name__})"
    if size == 0:
        return "an empty file (0 bytes), not a dump"
    if head != b"\x89HDF\r\n\x1a\n":
        return f"not an HDF5 file ({size} bytes, no HDF5 signature at its start), so not a dump"
    return f"not a readable HDF5 file (truncated or corrupt?): {exc.__class__.__name__}"


class DumpReader:
    """Read a run written by :class:`DumpWriter` (packed or not).

    Opening checks the schema name and version, that ``n_snapshots`` (when
    present) is the number of snapshot groups, that these are exactly
    ``000000`` ... ``n-1``, and that ``/index`` (when present) has one row per
    snapshot; it raises :class:`DumpFormatError` with a one-line message
    otherwise. Snapshots are read one at a time (``read(i)`` or iteration)
    so large runs fit in memory; each is checked against its index row.
    :meth:`verify` checks them all.

    Attributes
    ----------
    indexed : bool
        The dump has an ``/index`` (dumps written before it existed have
        none: only the count and name checks apply to them).
    """

    def __init__(self, path):
        self.path = str(path)
        if not os.path.exists(self.path):
            raise DumpFormatError(f"{self.path}: no such file")
        try:
            self._f = h5py.File(self.path, "r")
        except OSError as exc:
            raise DumpFormatError(f"{self.path}: {_unreadable(self.path, exc)}") from None
        a = self._f.attrs
        if a.get("schema") != SCHEMA_NAME:
            self._f.close()
            raise DumpFormatError(f"{self.path}: not a {SCHEMA_NAME} file "
                                  f"(attribute 'schema' is {a.get('schema')!r})")
        version = int(a.get("schema_version", -1))
        if version not in READABLE_VERSIONS:
            self._f.close()
            raise DumpFormatError(f"{self.path}: schema version {version} is not "
                                  f"supported (this reader reads versions "
                                  f"{', '.join(map(str, READABLE_VERSIONS))}; current {SCHEMA_VERSION})")
        self.version = version
        self.sample_kind = str(a["sample_kind"])
        self.parameters = json.loads(a["parameters"])
        self.units = json.loads(a["units"])
        self.overlap_kind = str(a["overlap_kind"])
        self.complete = bool(a.get("complete", 0))
        self.names = sorted(self._f["snapshots"].keys()) if "snapshots" in self._f else []
        try:
            try:
                said = int(a["n_snapshots"]) if "n_snapshots" in a else None
            except (TypeError, ValueError):
                raise DumpFormatError(f"{self.path}: attribute n_snapshots is not an integer "
                                      f"({a['n_snapshots']!r})") from None
            self._check_whole(said)
            recorded = _read_index(self._f, self.path)
        except DumpFormatError:
            self._f.close()
            raise
        self._index, self._checksum_kind = recorded if recorded is not None else (None, None)
        self.indexed = recorded is not None
        if self.indexed and len(self._index) != len(self.names):
            self._f.close()
            raise DumpFormatError(f"{self.path}: the index has {len(self._index)} rows for "
                                  f"{len(self.names)} snapshots: not a whole dump (two writers?)")

    def _check_whole(self, said):
        """n_snapshots against the groups, and the groups' names: 000000 ...
        n-1 without a gap."""
        names = self.names
        expected = [f"{k:06d}" for k in range(len(names))]
        if (said is None or said == len(names)) and names == expected:
            return
        held = f"holds {len(names)} ({_ranges(names)})" if names else "holds none"
        if said is None:
            raise DumpFormatError(f"{self.path}: {held}, not 000000–{len(names) - 1:06d} without a gap: "
                                  f"not a whole dump (two writers?)")
        missing = sorted(set(f"{k:06d}" for k in range(min(said, 10 ** 6))) - set(names))
        lacks = f", lacks {_ranges(missing)}" if missing and said <= 10 ** 6 else ""
        raise DumpFormatError(f"{self.path}: says {said} snapshots, {held}{lacks}: "
                              f"not a whole dump (two writers?)")

    def close(self):
        self._f.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __len__(self):
        return len(self.names)

    def shapes(self):
        """Return (vertices, triangles, triangle_faces): lists with one array
        per shape, or None when the run has no shapes."""
        if "shapes" not in self._f:
            return None
        try:
            g = self._f["shapes"]
            vo, to = g["vertex_offsets"][()], g["triangle_offsets"][()]
            v, t, tf = g["vertices"][()], g["triangles"][()], g["triangle_face"][()]
        except (KeyError, OSError) as exc:
            raise DumpFormatError(f"{self.path}: /shapes unreadable: {exc}") from None
        n = len(vo) - 1
        return ([v[vo[i]:vo[i + 1]] for i in range(n)],
                [t[to[i]:to[i + 1]] for i in range(n)],
                [tf[to[i]:to[i + 1]] for i in range(n)])

    def read(self, i) -> Snapshot:
        """Snapshot number ``i`` (0-based, time order).

        Raises
        ------
        DumpFormatError
            (one line) when the snapshot is incomplete or unreadable, or its
            step, body or contact count or checksum differs from its row of
            ``/index`` (a part replaced by another writer's, or damage).
        """
        name, version = self.names[i], self.version
        try:
            step, time, stage, d = _load_group(self._f["snapshots/" + name])
        except (KeyError, OSError, ValueError) as exc:
            raise DumpFormatError(f"{self.path}: snapshot {name} is incomplete or "
                                  f"unreadable ({exc})") from None
        if self._index is not None:
            try:
                row = _index_row(step, time, stage, d)
            except KeyError as exc:
                raise DumpFormatError(f"{self.path}: snapshot {name} is incomplete or "
                                      f"unreadable ({exc} missing)") from None
            bad = _row_differences(row, self._index[int(name)], self._checksum_kind == CHECKSUM_KIND)
            if bad:
                raise DumpFormatError(f"{self.path}: snapshot {name} does not match its index row "
                                      f"({'; '.join(bad)}): replaced or damaged (two writers?)")
        try:
            lo, hi = d["box/lo"], d["box/hi"]
            b = {k: d["bodies/" + k] for k in _BODY_FIELDS if "bodies/" + k in d}
            c = {k: d["contacts/" + k] for k, s in _CONTACT_FIELDS.items()
                 if s[2] or "contacts/" + k in d}
            cell = d.get("cell")
            pts = None
            if any(k.startswith("points/") for k in d):
                if version < POINTS_SCHEMA_VERSION:
                    raise DumpFormatError(f"{self.path}: snapshot {name} holds points/ but the dump "
                                          f"says schema version {version} (points need {POINTS_SCHEMA_VERSION})")
                pts = check_points({k[len("points/"):]: v for k, v in d.items() if k.startswith("points/")},
                                   len(c["id1"]), where=f"{self.path}: snapshot {name} points")
            snap = Snapshot(
                name=name, step=step, time=time, stage=stage,
                volume=float(np.prod(hi - lo)) if cell is None else float(abs(np.linalg.det(cell))),
                box_lo=lo, box_hi=hi, cell=cell,
                wall_ids=d["walls/id"], wall_forces=d["walls/force"],
                body_ids=b["id"], positions=b["position"],
                id1=c["id1"], id2=c["id2"], point=c["point"],
                force=c["force_normal"] + c["force_tangential"],
                force_normal=c["force_normal"], normal=c["normal"],
                overlap=c["overlap"], body_kind=b["kind"],
                orientations=b["orientation"], volumes=b["volume"],
                masses=b["mass"], shape_index=b["shape_index"], sizes=b["size"],
                footprint=c.get("footprint"), footprint_area=c.get("footprint_area"),
                points=pts,
            )
        except DumpFormatError:
            raise
        except (KeyError, ValueError) as exc:
            raise DumpFormatError(f"{self.path}: snapshot {name} is incomplete or "
                                  f"unreadable ({exc})") from None
        return snap

    def verify(self):
        """Check the whole dump: read every snapshot once, each against its
        index row (the count and name checks were made on opening).

        Returns
        -------
        DumpCheck
            what was checked: the number of snapshots, whether checksums
            were compared (False for a dump without an index) and
            ``complete``.

        Raises
        ------
        DumpFormatError
            (one line) at the first snapshot that does not add up.
        """
        for i in range(len(self.names)):
            self.read(i)
        return DumpCheck(self.path, len(self.names),
                         self.indexed and self._checksum_kind == CHECKSUM_KIND, self.complete)

    def __iter__(self) -> Iterator[Snapshot]:
        for i in range(len(self.names)):
            yield self.read(i)


def verify_dump(path) -> DumpCheck:
    """Open the dump ``path``, check it whole (:meth:`DumpReader.verify`)
    and close it.

    Returns
    -------
    DumpCheck

    Raises
    ------
    DumpFormatError
        (one line) when it is not a whole, consistent dump.
    """
    with DumpReader(path) as r:
        return r.verify()
