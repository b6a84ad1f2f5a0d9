"""Text dumps of the LAMMPS family: LIGGGHTS ``compute pair/gran/local`` and
LAMMPS ``compute pair/local`` + ``compute property/local`` (``dump local``),
with LAMMPS ``dump custom`` (id x y z) for the positions.

Every block of a dump (``ITEM: TIMESTEP`` ... its rows) becomes one
:class:`~postproc.schema.Snapshot`; a bad block becomes an InputError naming
the file, the line and the problem, and the other blocks are kept.

Sign conventions, pinned from the sources (this package's convention is the
force on id2 by id1, branch vector x2 - x1; both codes give the opposite):

* LIGGGHTS-PUBLIC (github.com/CFDEMproject/LIGGGHTS-PUBLIC, commit 3d5c00f2):
  ``src/compute_pair_gran_local.cpp:476-478`` writes the ``force`` columns
  from the fx, fy, fz it is handed; ``src/pair_gran.cpp:800-802`` hands it
  ``i_forces.delta_F``, which ``src/pair_gran_base.h:425`` (force_update,
  line 87) adds to ``f[i]``: the force on the FIRST particle (id1) by the
  second. ``force_normal``/``force_tangential`` (lines 483-512) are that
  force split along x_j - x_i, so they act on id1 too. Positions are
  remapped into the box (lines 448-453), hence minimum image across
  periodic boundaries; the third ``id`` column is 1 for a pair across a
  periodic boundary (lines 462-472).
* LAMMPS (github.com/lammps/lammps; the repository is too large to fetch
  whole, so these files were read one by one and are cited by function and
  expression): ``src/compute_pair_local.cpp`` (commit 65d2a8ca,
  ComputePairLocal::compute_pairs) sets ``delx = xtmp - x[j][0]`` (x_I -
  x_J) and writes ``case FX: ptr[n] = delx*fpair``; for ``pair_style
  granular``, ``src/GRANULAR/pair_granular.cpp`` PairGranular::single()
  sets ``fforce = Fntot*rinv`` (current master) and ``svector[0..2] =
  fs1..fs3`` (the tangential force on I, ``p1 p2 p3``), ``svector[9..11] =
  delx, dely, delz`` (x_I - x_J through the periodic image, ``p10 p11
  p12``; the same in commit 28607f15 and in master). So fx..fz + p1..p3 is
  the total force on I = patom1 by J = patom2. ``compute property/local
  patom1 patom2 cutoff radius`` (src/compute_property_local.cpp,
  count_pairs) runs the same pair loop with the same newton/ghost skips and
  the same ``rsq >= radsum*radsum`` test as ``compute pair/local ... cutoff
  radius``, so their rows match one to one.

Both are therefore negated here. Box bounds (``pp`` = periodic) come from
each block's header; the volume is the box volume. A tilted (triclinic)
header holds the bounding box and xy, xz, yz; the cell's own bounds and
its matrix follow LAMMPS's dump documentation (:class:`Block`). Ids are
checked for the rounding of a ``%g`` format (:func:`_ids`,
:func:`_pairs_once`): such files are refused with the ``dump_modify`` line
that writes them exactly (:data:`EXACT_FORMAT` for LAMMPS,
:func:`liggghts_exact_format` for LIGGGHTS, whose 3.8 refuses the former).

Off-diagonal convention: our stress is sigma_ij = sum f_i l_j / V; LAMMPS's
pressure tensor is P_ij = sum l_i f_j / V (ev_tally_xyz: v[3] = delx*fy),
so LAMMPS's pxy is our sigma[1, 0] (tests/test_lammps_fixtures.py).
"""
from __future__ import annotations

import io
import os
import re

import numpy as np
import pandas as pd

from .contactset import lookup
from .errors import InputError
from .periodic import minimum_image
from .schema import Snapshot

#: LIGGGHTS pair/gran/local layouts by column count, keywords in LIGGGHTS'
#: fixed output order (pos, vel, id, force, force_normal, force_tangential)
LIGGGHTS_LAYOUTS = {
    12: "pos id force",
    15: "pos id force_normal force_tangential",
    18: "pos id force force_normal force_tangential",
}
#: LAMMPS contact dump layouts (names used when the header labels are the
#: compute references c_ID[k]); an optional leading "index" column is dropped
LAMMPS_LAYOUTS = {
    11: ("id1", "id2", "fx", "fy", "fz", "ftx", "fty", "ftz", "lx", "ly", "lz"),
    8: ("id1", "id2", "fx", "fy", "fz", "ftx", "fty", "ftz"),
}
FORMATS = ("liggghts-local", "lammps-local")


class Block:
    """One ``ITEM: TIMESTEP`` block: step, box (lo, hi, periodic (3,) bool,
    tilt (xy, xz, yz) m, zeros for an orthogonal box), column labels, data
    (N, K) float, the file line of its first row and the rows' text."""

    def __init__(self, step, lo, hi, periodic, columns, data, first_line, tilt=None, rows=None):
        self.step, self.lo, self.hi, self.periodic = step, lo, hi, periodic
        self.columns, self.data, self.first_line = columns, data, first_line
        self.tilt = np.zeros(3) if tilt is None else tilt
        self.rows = rows

    @property
    def matrix(self):
        """(3, 3) m, the box's edge vectors as columns: a = (lx, 0, 0),
        b = (xy, ly, 0), c = (xz, yz, lz) (LAMMPS's restricted triclinic
        box; diag(hi - lo) when orthogonal)."""
        lx, ly, lz = self.hi - self.lo
        xy, xz, yz = self.tilt
        return np.array([[lx, xy, xz], [0.0, ly, yz], [0.0, 0.0, lz]])

    @property
    def tilted(self):
        return bool(np.any(self.tilt != 0))


def _blocks(path):
    """Yield Block or InputError for each block of a LAMMPS-style text dump."""
    if not os.path.exists(path):
        raise InputError(f"{path}: no such file")
    with open(path, "r", errors="replace") as fh:
        lines = fh.read().splitlines()
    if not lines or not lines[0].startswith("ITEM: TIMESTEP"):
        raise InputError(f"{path}: line 1: not a LAMMPS/LIGGGHTS dump (no 'ITEM: TIMESTEP')")
    starts = [k for k, s in enumerate(lines) if s.startswith("ITEM: TIMESTEP")]
    for b, k0 in enumerate(starts):
        k1 = starts[b + 1] if b + 1 < len(starts) else len(lines)
        try:
            yield _parse_block(path, lines, k0, k1)
        except InputError as exc:
            yield exc


def _parse_block(path, lines, k0, k1):
    def need(k, prefix):
        if k >= k1 or not lines[k].startswith(prefix):
            got = lines[k][:40] if k < k1 else "end of block"
            raise InputError(f"{path}: line {k + 1}: expected '{prefix}', got '{got}' "
                             "(truncated block?)")

    def number(k, kind):
        if k >= k1:
            raise InputError(f"{path}: line {k + 1}: block ends before its {kind} (truncated)")
        try:
            return int(lines[k].split()[0])
        except (ValueError, IndexError):
            raise InputError(f"{path}: line {k + 1}: {kind} '{lines[k][:30]}' is not an integer") from None

    step = number(k0 + 1, "timestep")
    need(k0 + 2, "ITEM: NUMBER OF")
    n = number(k0 + 3, "number of rows")
    need(k0 + 4, "ITEM: BOX BOUNDS")
    flags = lines[k0 + 4].split()[3:]
    tilt = flags[:3] == ["xy", "xz", "yz"]
    flags = flags[3:] if tilt else flags
    if len(flags) != 3:
        raise InputError(f"{path}: line {k0 + 5}: box bounds need three boundary flags, "
                         f"got {flags}")
    periodic = np.array([f == "pp" for f in flags])
    lo, hi, tilts = np.zeros(3), np.zeros(3), np.zeros(3)
    for d in range(3):
        k = k0 + 5 + d
        try:
            vals = [float(v) for v in lines[k].split()] if k < k1 else []
        except ValueError:
            vals = []
        if len(vals) != (3 if tilt else 2) or not np.all(np.isfinite(vals)):
            raise InputError(f"{path}: line {k + 1}: bad box bounds '{lines[k][:40] if k < k1 else ''}'")
        lo[d], hi[d] = vals[0], vals[1]
        if tilt:
            tilts[d] = vals[2]
    if tilt:
        # the header holds the bounding box of the tilted cell and xy, xz, yz
        # (in that order, one per line); the cell's own bounds are, as in
        # LAMMPS's documentation of dump (triclinic boxes):
        xy, xz, yz = tilts
        lo[0] -= min(0.0, xy, xz, xy + xz)
        hi[0] -= max(0.0, xy, xz, xy + xz)
        lo[1] -= min(0.0, yz)
        hi[1] -= max(0.0, yz)
    if np.any(hi <= lo):
        raise InputError(f"{path}: line {k0 + 6}: box has hi <= lo")
    hk = k0 + 8
    if hk >= k1 or not lines[hk].startswith("ITEM: "):
        raise InputError(f"{path}: line {hk + 1}: expected the column header 'ITEM: ENTRIES ...'")
    head = lines[hk].split()
    columns = head[2:]
    rows = lines[hk + 1:k1]
    if len(rows) < n:
        raise InputError(f"{path}: line {k1}: block of step {step} announces {n} rows and "
                         f"has {len(rows)} (truncated)")
    if len(rows) > n:
        raise InputError(f"{path}: line {hk + 2 + n}: block of step {step} has more than the "
                         f"{n} rows it announces")
    K = len(columns)
    data = _fast_rows(rows, n, K)
    if data is not None:
        return Block(step, lo, hi, periodic, columns, data, hk + 2, tilts, rows)
    # something is wrong (or unusual): the slow path finds the line and column
    counts = np.fromiter((len(r.split()) for r in rows), int, len(rows))
    bad = np.flatnonzero(counts != K)
    if bad.size:
        j = int(bad[0])
        raise InputError(f"{path}: line {hk + 2 + j}: {counts[j]} values, the header names {K} "
                         "columns")
    try:
        data = np.array(" ".join(rows).split(), float).reshape(n, K)
    except ValueError:
        for j, r in enumerate(rows):
            for c, v in enumerate(r.split()):
                try:
                    float(v)
                except ValueError:
                    raise InputError(f"{path}: line {hk + 2 + j}, column {c + 1} "
                                     f"({columns[c]}): '{v}' is not a number") from None
        raise
    nonfinite = ~np.isfinite(data)
    if nonfinite.any():
        j, c = map(int, np.argwhere(nonfinite)[0])
        raise InputError(f"{path}: line {hk + 2 + j}, column {c + 1} ({columns[c]}): "
                         f"{data[j, c]} (NaN or infinite)")
    return Block(step, lo, hi, periodic, columns, data, hk + 2, tilts, rows)


def _fast_rows(rows, n, K):
    """(n, K) float array of the rows through pandas' C parser, or None when
    anything is off (ragged rows, text, NaN, blank lines): the caller then
    walks the rows to name the first bad line and column."""

    if n == 0:
        return None
    try:
        df = pd.read_csv(io.StringIO("\n".join(rows)), sep=r"\s+", header=None,
                         engine="c", dtype=np.float64, skip_blank_lines=False)
    except (ValueError, pd.errors.ParserError):
        return None
    data = df.to_numpy()
    if data.shape != (n, K) or not np.isfinite(data).all():
        return None
    return data


#: the dump_modify line that makes LAMMPS write ids (and every value) exactly
EXACT_FORMAT = "dump_modify ID format float %.15g"


def liggghts_exact_format(ncols):
    """The dump_modify line that makes LIGGGHTS write every column of a dump
    local exactly: LIGGGHTS 3.8 takes one format per column in a single
    string (it refuses LAMMPS's ``format float``: "Illegal dump_modify
    command"), and %.17g gives back each double."""
    return 'dump_modify ID format "' + " ".join(["%.17g"] * ncols) + '"'

#: ids above this are not exact in a float64
MAX_EXACT_ID = 2 ** 53


def _ids(path, blk, col, label, fix=EXACT_FORMAT):
    """(N,) int64 ids of column ``col``. Refuses ids that a text format
    cannot have held exactly: non-integers, values above 2^53, and ids of
    1 000 000 or more written with an exponent (the default ``%g`` of
    LAMMPS and LIGGGHTS keeps 6 significant digits, so such ids are
    rounded); ``fix`` is the dump_modify line the message gives."""
    v = blk.data[:, col]
    bad = v != np.round(v)
    if bad.any():
        j = int(np.flatnonzero(bad)[0])
        raise InputError(f"{path}: line {blk.first_line + j}, column {col + 1} ({label}): "
                         f"{v[j]} is not an integer id")
    big = np.abs(v) > MAX_EXACT_ID
    if big.any():
        j = int(np.flatnonzero(big)[0])
        raise InputError(f"{path}: line {blk.first_line + j}, column {col + 1} ({label}): id {v[j]:.17g} "
                         "is above 2^53 and cannot be read exactly")
    large = np.flatnonzero(np.abs(v) >= 1e6)
    if large.size and blk.rows is not None:
        for j in large[:64]:
            text = blk.rows[j].split()[col]
            if "e" in text or "E" in text:
                raise InputError(f"{path}: line {blk.first_line + j}, column {col + 1} ({label}): id written as "
                                 f"'{text}': the default %g format keeps 6 significant digits, so ids of "
                                 f"1 000 000 or more are rounded; write them exactly with '{fix}' "
                                 "(docs/other-codes.md)")
    return v.astype(np.int64)


def _pairs_once(path, blk, id1, id2):
    """Refuse a body joined to itself and a pair listed twice in one block:
    both mean ids that the file's format did not hold exactly."""
    same = np.flatnonzero(id1 == id2)
    if same.size:
        j = int(same[0])
        raise InputError(f"{path}: line {blk.first_line + j}: a contact joins body {int(id1[j])} to itself "
                         f"(ids rounded by the file's format? write them exactly with '{EXACT_FORMAT}')")
    key = np.sort(np.stack([id1, id2], axis=1), axis=1)
    _, first, count = np.unique(key, axis=0, return_index=True, return_counts=True)
    if np.any(count > 1):
        again = np.setdiff1d(np.arange(len(key)), first)
        j = int(again[0])
        raise InputError(f"{path}: line {blk.first_line + j}: the pair {int(id1[j])}-{int(id2[j])} is listed "
                         f"twice in one block (ids rounded by the file's format? write them exactly with "
                         f"'{EXACT_FORMAT}')")


def _wrap(d, blk):
    """Minimum image of d (C, 3) along the periodic axes of the block's box;
    in a tilted box that is periodic on every axis, in the cell's fractional
    coordinates (:func:`postproc.periodic.minimum_image`)."""
    if blk.tilted:
        if not blk.periodic.all():
            raise InputError("a tilted box that is not periodic on every axis: give the branch vectors "
                             "(LAMMPS p10 p11 p12)")

        return minimum_image(d, blk.matrix)
    L = blk.hi - blk.lo
    out = d.copy()
    for k in np.flatnonzero(blk.periodic):
        out[:, k] -= L[k] * np.round(d[:, k] / L[k])
    return out


def sniff(path):
    """"liggghts-local", "lammps-local" or None (not a LAMMPS-style local dump),
    from the first block's header alone."""
    try:
        with open(path, "r", errors="replace") as fh:
            head = [fh.readline() for _ in range(9)]
    except OSError:
        return None
    if not head[0].startswith("ITEM: TIMESTEP") or not head[2].startswith("ITEM: NUMBER OF ENTRIES"):
        return None
    cols = head[8].split()[2:]
    computes = {re.sub(r"\[\d+\]$", "", c) for c in cols if c.startswith("c_")}
    if len(computes) == 1 and len(cols) in LIGGGHTS_LAYOUTS:
        return "liggghts-local"
    return "lammps-local"


def _snapshot(k, blk, id1, id2, force, force_normal, branch, body_ids, positions):
    L = blk.hi - blk.lo
    cell = blk.matrix if blk.periodic.all() else None
    return Snapshot(
        name=f"{k:06d}", step=int(blk.step), time=float("nan"), stage="dump",
        volume=float(np.prod(L)), box_lo=blk.lo, box_hi=blk.hi,
        wall_ids=np.zeros(0, np.int64), wall_forces=None, body_ids=body_ids,
        positions=positions, id1=id1, id2=id2, point=np.zeros((len(id1), 3)), force=force,
        force_normal=force_normal, cell=cell, branch=branch)


def _bodies(path, blk, ids, pos):
    """Unique ids and their positions (a body's positions must agree modulo
    the periodic box)."""
    uid, first, inv = np.unique(ids, return_index=True, return_inverse=True)
    centres = pos[first]
    dev = np.abs(_wrap(pos - centres[inv], blk)).max(axis=1)
    clash = dev > 1e-6 * np.max(blk.hi - blk.lo)
    if clash.any():
        j = int(np.flatnonzero(clash)[0]) % len(blk.data)
        raise InputError(f"{path}: line {blk.first_line + j}: particle {int(ids[np.flatnonzero(clash)[0]])}"
                         " appears at two positions that are not periodic images")
    return uid, centres


def read_liggghts_local(path):
    """Snapshots (or InputError per bad block) of a LIGGGHTS ``dump local``
    of ``compute pair/gran/local`` with the keywords ``pos id force``
    (12 columns: x1 y1 z1 x2 y2 z2 id1 id2 periodic-flag fx fy fz), ``pos id
    force_normal force_tangential`` (15) or all three force keywords (18).
    Forces are turned into the forces on id2 by id1 (see the module
    docstring); branch vectors are minimum images across the periodic
    (``pp``) axes of each block's box. Returns a list."""
    return _each_block(path, lambda k, blk: _liggghts_block(path, k, blk))


def _each_block(path, parse):
    """parse(k, block) for every TIMESTEP block of ``path``: a list with one
    snapshot or one InputError per block (a bad block loses no other)."""
    out = []
    for k, blk in enumerate(_blocks(path)):
        if isinstance(blk, InputError):
            out.append(blk)
            continue
        try:
            out.append(parse(k, blk))
        except InputError as exc:
            out.append(exc)
    return out


def _liggghts_block(path, k, blk):
    K = len(blk.columns)
    if K not in LIGGGHTS_LAYOUTS:
        raise InputError(f"{path}: line {blk.first_line - 1}: {K} columns; pair/gran/local "
                         "dumps read here have 12 (pos id force), 15 (pos id force_normal "
                         "force_tangential) or 18 columns")
    D = blk.data
    x1, x2 = D[:, 0:3], D[:, 3:6]
    fix = liggghts_exact_format(K)
    id1 = _ids(path, blk, 6, blk.columns[6], fix)
    id2 = _ids(path, blk, 7, blk.columns[7], fix)
    flag = D[:, 8]
    if np.any((flag != 0) & (flag != 1)):
        j = int(np.flatnonzero((flag != 0) & (flag != 1))[0])
        raise InputError(f"{path}: line {blk.first_line + j}, column 9 ({blk.columns[8]}): "
                         f"periodic flag {flag[j]} is not 0 or 1 (are the keywords pos id force?)")
    if np.any(flag == 1) and not blk.periodic.any():
        j = int(np.flatnonzero(flag == 1)[0])
        raise InputError(f"{path}: line {blk.first_line + j}: contact across a periodic "
                         "boundary in a box with no periodic axis (bounds not 'pp')")
    if K == 12:
        f_on_1, fn_on_1 = D[:, 9:12], None
    else:
        s = 9 if K == 15 else 12
        fn_on_1 = D[:, s:s + 3]
        f_on_1 = fn_on_1 + D[:, s + 3:s + 6]
    branch = _wrap(x2 - x1, blk)
    uid, centres = _bodies(path, blk, np.concatenate([id1, id2]), np.concatenate([x1, x2]))
    snap = _snapshot(k, blk, id1, id2, -f_on_1, None if fn_on_1 is None else -fn_on_1,
                     branch, uid, centres)
    snap.point = x1 + branch / 2
    return snap


def read_atoms(path):
    """{step: (ids (B,), positions (B, 3))} from a LAMMPS ``dump custom`` with
    columns id x y z (also xu yu zu or xs ys zs, scaled by the box)."""
    out = {}
    for blk in _blocks(path):
        if isinstance(blk, InputError):
            raise blk
        cols = blk.columns
        try:
            c_id = cols.index("id")
        except ValueError:
            raise InputError(f"{path}: line {blk.first_line - 1}: the atom dump has no 'id' "
                             "column") from None
        for names, scaled in ((("x", "y", "z"), False), (("xu", "yu", "zu"), False),
                              (("xs", "ys", "zs"), True)):
            if all(c in cols for c in names):
                pos = blk.data[:, [cols.index(c) for c in names]]
                if scaled:
                    pos = blk.lo + pos @ blk.matrix.T
                break
        else:
            raise InputError(f"{path}: line {blk.first_line - 1}: the atom dump needs columns "
                             "x y z (or xu yu zu, xs ys zs)")
        out[blk.step] = (_ids(path, blk, c_id, "id"), pos)
    return out


def read_lammps_local(path, atoms):
    """Snapshots (or InputError per bad block) of a LAMMPS ``dump local`` of
    ``compute property/local patom1 patom2`` and ``compute pair/local fx fy fz
    p1 p2 p3 [p10 p11 p12]`` (pair_style granular; see docs/other-codes.md for the
    exact input lines), with the positions from the ``dump custom`` file
    ``atoms`` (same timesteps). Columns in that order, or named id1 id2 fx fy
    fz ftx fty ftz [lx ly lz] with ``dump_modify colname``; a leading
    ``index`` column is allowed. With p10..p12 the branch vectors are used as
    given (exact through periodic and sheared boxes); without them they are
    minimum images of the atom positions. Forces become the forces on id2 by
    id1 (module docstring). Returns a list."""
    if atoms is None:
        raise InputError(f"{path}: a LAMMPS pair/local dump needs the atom positions "
                         "(--atoms ATOMS.dump, a dump custom with id x y z)")
    pos_by_step = read_atoms(atoms)
    return _each_block(path, lambda k, blk: _lammps_block(path, atoms, k, blk, pos_by_step))


def _lammps_block(path, atoms, k, blk, pos_by_step):
    cols = list(blk.columns)
    D = blk.data
    if cols and cols[0] == "index":
        cols, D = cols[1:], D[:, 1:]
    named = set(LAMMPS_LAYOUTS[11]) & set(cols)
    if {"id1", "id2", "fx", "fy", "fz", "ftx", "fty", "ftz"} <= named:
        idx = {c: cols.index(c) for c in named}
        has_branch = {"lx", "ly", "lz"} <= named
    elif len(cols) in LAMMPS_LAYOUTS:
        idx = {c: j for j, c in enumerate(LAMMPS_LAYOUTS[len(cols)])}
        has_branch = len(cols) == 11
    else:
        raise InputError(f"{path}: line {blk.first_line - 1}: {len(cols)} columns; a LAMMPS "
                         "contact dump has 8 (patom1 patom2 fx fy fz p1 p2 p3) or 11 "
                         "(... p10 p11 p12) columns, or named ones (docs/other-codes.md)")
    off = 1 if blk.columns[0] == "index" else 0
    id1 = _ids(path, blk, idx["id1"] + off, "patom1")
    id2 = _ids(path, blk, idx["id2"] + off, "patom2")
    _pairs_once(path, blk, id1, id2)
    f_on_1 = D[:, [idx["fx"], idx["fy"], idx["fz"]]] + D[:, [idx["ftx"], idx["fty"], idx["ftz"]]]
    if blk.step not in pos_by_step:
        raise InputError(f"{path}: line {blk.first_line - 9}: step {blk.step} has no block in "
                         f"the atom dump {atoms}")
    ids, pos = pos_by_step[blk.step]
    if len(np.unique(ids)) != len(ids):
        raise InputError(f"{atoms}: step {blk.step}: duplicate atom ids")

    for side, v in (("patom1", id1), ("patom2", id2)):
        miss = lookup(v, ids) < 0
        if miss.any():
            j = int(np.flatnonzero(miss)[0])
            raise InputError(f"{path}: line {blk.first_line + j}: {side} {int(v[j])} is not in "
                             f"the atom dump {atoms} at step {blk.step}")
    if has_branch:
        branch = -D[:, [idx["lx"], idx["ly"], idx["lz"]]]        # x_J - x_I
    elif blk.tilted and not blk.periodic.all():
        raise InputError(f"{path}: line {blk.first_line - 5}: a tilted box that is not periodic on every "
                         "axis: give the branch vectors (LAMMPS p10 p11 p12)")
    else:
        branch = _wrap(pos[lookup(id2, ids)] - pos[lookup(id1, ids)], blk)
    snap = _snapshot(k, blk, id1, id2, -f_on_1, None, branch, ids, pos)
    snap.point = pos[lookup(id1, ids)] + branch / 2
    return snap


def read_text_dump(path, fmt=None, atoms=None):
    """List of Snapshot or InputError (one per block) of a LIGGGHTS or LAMMPS
    local dump; ``fmt`` one of :data:`FORMATS`, or None to detect it."""
    fmt = fmt or sniff(path)
    if fmt == "liggghts-local":
        if atoms is not None:
            raise InputError("--atoms is for LAMMPS pair/local dumps")
        return read_liggghts_local(path)
    if fmt == "lammps-local":
        return read_lammps_local(path, atoms)
    if fmt is None:
        raise InputError(f"{path}: not a LAMMPS/LIGGGHTS local dump (no 'ITEM: NUMBER OF "
                         "ENTRIES' header); formats: " + ", ".join(FORMATS))
    raise InputError(f"unknown format '{fmt}'; known: " + ", ".join(FORMATS))
