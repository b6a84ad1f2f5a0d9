"""Flat contact tables (CSV or Parquet) from other DEM codes.

Columns (one row per contact, SI units):

``id1,id2``           body ids; a wall contact has a negative ``id2``.
``x1,y1,z1``          centre of body id1, m.
``x2,y2,z2``          centre of body id2, m (empty for a wall).
``cx,cy,cz``          contact point, m.
``fx,fy,fz``          force exerted on id2 by id1, N.
``step`` (optional)   snapshot label; rows with the same step form one
                      snapshot, in increasing step order.

Wall ids -1 .. -6 stand for the walls x-, x+, y-, y+, z-, z+ (so the wall
stress can be computed when the box is given); other negative ids are walls
of unknown position. The volume comes from ``volume=`` (m^3) or ``box=``
(three lengths, m, which also gives the wall areas). A body that appears
with two different centres in one snapshot is an error.

Periodic cells: with ``cell=`` (three lengths LX, LY, LZ, m) the positions
lie in an orthorhombic periodic cell: branch vectors follow the
minimum-image convention (:mod:`postproc.periodic`), the volume defaults to
LX*LY*LZ, and a body may appear at any of its images (its centres must
agree modulo the cell).

``lx,ly,lz`` (optional) the branch vector x2 - x1 of each particle-particle
                      contact, m, used as given (sheared cells, or any code
                      that knows its branch vectors); empty for walls. With
                      them, body centres are not cross-checked (a body's
                      first row gives its position).
"""
from __future__ import annotations

import csv
import os
import warnings

import numpy as np
import pandas as pd

from .errors import InputError
from .periodic import cell_matrix, same_point_modulo
from .schema import WALL_ORDER, Snapshot

REQUIRED = ("id1", "id2", "x1", "y1", "z1", "x2", "y2", "z2",
            "cx", "cy", "cz", "fx", "fy", "fz")
BRANCH = ("lx", "ly", "lz")


#: cell texts read as a missing value (pandas' default ``na_values``)
NA_TEXT = frozenset({"", "#N/A", "#N/A N/A", "#NA", "-1.#IND", "-1.#QNAN", "-NaN", "-nan",
                     "1.#IND", "1.#QNAN", "<NA>", "N/A", "NA", "NULL", "NaN", "None",
                     "n/a", "nan", "null"})
#: columns whose cells must be whole numbers
WHOLE = ("id1", "id2", "step")


def _records_by_line(path):
    """The records of the CSV file ``path`` and the line each starts on;
    a record the csv module refuses (a quote left open, a field over its
    limit) is named by that line."""
    records, starts, start = [], [], 1
    try:
        with open(path, newline="", encoding="utf-8") as fh:
            reader = csv.reader(fh, strict=True)
            while True:
                start = reader.line_num + 1
                row = next(reader, None)
                if row is None:
                    return records, starts
                records.append(row)
                starts.append(start)
    except UnicodeDecodeError as exc:
        raise InputError(f"{path}: not a text table (byte {exc.start} is not UTF-8)") from None
    except csv.Error as exc:
        raise InputError(f"{path}: line {start}: not a readable CSV table ({exc})") from None
    except OSError as exc:
        raise InputError(f"{path}: cannot read the contact table: {exc.strerror or exc}") from None


def _read_csv(path):
    """The columns of a CSV table (name -> tuple of cell texts) and each
    row's line number, (R,) int64, read strictly by the csv module: a quote
    left open, a row of another width than the header and a field over the
    csv module's limit are refused by line.

    Two layouts pandas reads are kept: a trailing delimiter (an empty last
    field) is read as nothing, and when every row has one field more than
    the header and their first fields are unique (row names, as R's
    ``write.table`` writes), the first field is the row's name and dropped.
    """
    records, starts = _records_by_line(path)
    keep = [k for k, r in enumerate(records) if r and (len(r) > 1 or r[0].strip())]  # no blank lines
    if not keep:
        raise InputError(f"{path}: an empty table (no header)")
    header = [c.strip() for c in records[keep[0]]]
    if len(header) > 1 and header[-1] == "":
        header.pop()
    rows = [records[k] for k in keep[1:]]
    lines = np.asarray(starts, np.int64)[keep[1:]]
    n = len(header)
    dup = sorted({c for c in header if header.count(c) > 1})
    if dup:
        raise InputError(f"{path}: columns named twice in the header: {', '.join(dup)}")
    width = np.fromiter(map(len, rows), np.int64, len(rows))
    if (width == n + 1).any():
        trailing = [k for k in np.flatnonzero(width == n + 1) if not rows[k][-1].strip()]
        if len(trailing) < len(rows) and (width == n + 1).all() and len({r[0] for r in rows}) == len(rows):
            rows = [r[1:] for r in rows]         # row names
        else:
            for k in trailing:
                rows[k] = rows[k][:-1]
        width = np.fromiter(map(len, rows), np.int64, len(rows))
    if (width != n).any():
        k = int(np.flatnonzero(width != n)[0])
        raise InputError(f"{path}: line {lines[k]} has {width[k]} fields where the header has {n}")
    cols = list(zip(*rows)) if rows else [()] * n
    return dict(zip(header, cols)), lines


def _read_csv_fast(path):
    """The columns of a plain CSV table (name -> float Series, by pandas'
    C parser) and each row's line, or None when the table is not plain:
    quotes, carriage returns alone, a header with an empty or repeated
    name, a row of another width than the header, a cell pandas cannot
    read as a number. The strict reader (:func:`_read_csv`) then reads it
    and names what is wrong."""
    try:
        with open(path, "rb") as fh:
            data = fh.read()
        if b'"' in data or b"\r" in data.replace(b"\r\n", b""):
            return None
        text = data.decode("utf-8")
    except (OSError, UnicodeDecodeError):
        return None
    lines = text.split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    full = np.flatnonzero([bool(x.strip()) for x in lines])
    if len(full) < 1:
        return None
    names = [c.strip() for c in lines[full[0]].split(",")]
    n = len(names)
    if "" in names or len(set(names)) < n:
        return None
    rows = full[1:]
    if any(lines[k].count(",") != n - 1 for k in rows):
        return None
    want = [c for c in REQUIRED + BRANCH + ("step",) if c in names]
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            df = pd.read_csv(path, usecols=want, dtype={c: "float64" for c in want},
                             skipinitialspace=True, encoding="utf-8")
    except (ValueError, OSError, Warning):
        return None
    if len(df) != len(rows):
        return None
    return {c: df[c] for c in want}, rows + 1


def _numbers(path, columns, lines):
    """The columns the table reads (``REQUIRED``, ``BRANCH``, ``step``) as
    numbers, a DataFrame with the column ``_line``: each row's line in a
    CSV file, or its row from 1 in a Parquet file. ``columns`` maps a name to a pandas Series or a tuple of
    cell texts; ``lines``, (R,) int, each row's line in a CSV file (None:
    rows of a Parquet file). Every cell must be a number or a missing value
    (an empty cell, NaN, NA...: pandas' ``NA_TEXT``); ids and steps whole
    numbers. A bad cell is refused in one line naming its line (or row) and
    column."""
    out = {}
    for col in [c for c in REQUIRED + BRANCH + ("step",) if c in columns]:
        raw = columns[col]
        if isinstance(raw, pd.Series) and pd.api.types.is_bool_dtype(raw.dtype):
            raise InputError(f"{path}: column {col} holds true/false values, not numbers")
        if isinstance(raw, pd.Series) and pd.api.types.is_numeric_dtype(raw.dtype):
            vals, text = raw.to_numpy(dtype=float, na_value=np.nan), None
        else:
            text = raw.to_numpy(object) if isinstance(raw, pd.Series) else raw
            try:
                vals = np.array(text, dtype=float)
            except (TypeError, ValueError):
                cells = pd.Series(text, dtype=object).map(lambda v: v.strip() if isinstance(v, str) else v)
                vals = pd.to_numeric(cells,
                                     errors="coerce").to_numpy(dtype=float, na_value=np.nan)
            for i in np.flatnonzero(np.isnan(vals)):
                v = text[i]
                if not (v is None or v is pd.NA or (isinstance(v, float) and np.isnan(v))
                        or str(v).strip() in NA_TEXT):
                    raise InputError(f"{path}: {_where(lines, i)}, column {col}: {str(v)[:40]!r} "
                                     "is not a number")
        if col in WHOLE:
            gap = ~np.isfinite(vals)
            with np.errstate(invalid="ignore"):
                bad = gap | (vals != np.round(vals)) | (np.abs(vals) > 2.0 ** 53)
            if bad.any():
                i = int(np.flatnonzero(bad)[0])
                shown = vals[i] if text is None else text[i]
                what = "missing" if gap[i] else f"{str(shown)[:40]!r}, not a whole number"
                raise InputError(f"{path}: {_where(lines, i)}, column {col}: {what}")
            vals = vals.astype(np.int64)
        out[col] = vals
    n = len(next(iter(out.values()))) if out else 0
    out["_line"] = np.asarray(lines, np.int64) if lines is not None else np.arange(1, n + 1)
    return pd.DataFrame(out)


def _where(lines, i):
    """Row ``i``'s place: its line in a CSV file, its row in a Parquet one."""
    return f"line {int(lines[i])}" if lines is not None else f"row {i + 1}"


def _is_parquet(path):
    return os.path.splitext(path)[1].lower() in (".parquet", ".pq")


def _read_frame(path):
    """The table at ``path`` (``.parquet``/``.pq`` or CSV) with its
    numbers read and checked (:func:`_numbers`)."""
    if _is_parquet(path):
        try:
            df = pd.read_parquet(path)
        except ImportError:
            raise InputError(f"{path}: reading Parquet needs pyarrow "
                             "(pip install 'ballast-triaxial[parquet]')") from None
        except (OSError, ValueError) as exc:
            first = str(exc).splitlines()[0] if str(exc) else exc.__class__.__name__
            raise InputError(f"{path}: cannot read the contact table: {first}") from None
        names = [str(c).strip() for c in df.columns]
        dup = sorted({c for c in names if names.count(c) > 1})
        if dup:
            raise InputError(f"{path}: columns named twice: {', '.join(dup)}")
        columns = {c: df.iloc[:, j].reset_index(drop=True) for j, c in enumerate(names)}
        lines = None
    else:
        columns, lines = _read_csv_fast(path) or _read_csv(path)
    missing = [c for c in REQUIRED if c not in columns]
    if missing:
        raise InputError(f"{path}: missing columns {', '.join(missing)}")
    return _numbers(path, columns, lines)


def read_contact_table(path, volume=None, box=None, cell=None):
    """Read a flat contact table into a list of :class:`Snapshot`.

    Parameters
    ----------
    path : str, ``.csv`` or ``.parquet``.
    volume : float, m^3, the packing volume (or give ``box`` or ``cell``).
    box : (3,) m, box lengths; sets the volume and the wall areas.
    cell : (3,) m, lengths of an orthorhombic periodic cell (see above);
        the volume defaults to their product.

    Returns
    -------
    list of Snapshot (forces on id2 by id1; ``force_normal`` is None).
    """
    if not os.path.exists(path):
        raise InputError(f"{path}: no such file")
    if box is not None:
        box = np.asarray(box, float).reshape(3)
        if not np.all(np.isfinite(box)) or np.any(box <= 0):
            raise InputError(f"box lengths {box.tolist()} must be finite and > 0")
        vol = float(np.prod(box))
        if volume is not None and not np.isclose(vol, volume, rtol=1e-9):
            raise InputError(f"--volume {volume} disagrees with --box (volume {vol})")
        volume = vol
    if cell is not None:
        if box is not None:
            raise InputError("--box (walls) and --cell (periodic) exclude each other")

        cell = np.asarray(cell, float).reshape(3)
        if not np.all(np.isfinite(cell)) or np.any(cell <= 0):
            raise InputError(f"cell lengths {cell.tolist()} must be finite and > 0")
        cell = cell_matrix(cell)
        volume = float(np.linalg.det(cell)) if volume is None else volume
    if volume is None:
        raise InputError(f"{path}: a flat contact table needs the volume (--volume, --box or --cell)")
    df = _read_frame(path)
    given = [c for c in BRANCH if c in df.columns]
    if given and len(given) < 3:
        raise InputError(f"{path}: branch columns {', '.join(given)} given without "
                         f"{', '.join(c for c in BRANCH if c not in given)}")
    if len(df) == 0:
        raise InputError(f"{path}: the table has no rows (no contacts)")
    if "step" in df.columns:
        steps = np.unique(df["step"].to_numpy())
        groups = [(int(s), df[df["step"].to_numpy() == s]) for s in steps]
    else:
        groups = [(0, df)]
    return [_snapshot(path, k, step, g, float(volume), box, cell)
            for k, (step, g) in enumerate(groups)]


def _snapshot(path, k, step, df, volume, box, cell=None):
    name = f"{k:06d}"
    where = f"{path}: snapshot {name} (step {step})"

    def at(r):
        """Row ``r`` of this snapshot: its line in a CSV file, its row in a
        Parquet one."""
        return f"{'row' if _is_parquet(path) else 'line'} {int(df['_line'].iloc[r])}"

    id1 = df["id1"].to_numpy(np.int64)
    id2 = df["id2"].to_numpy(np.int64)
    x1 = df[["x1", "y1", "z1"]].to_numpy(float)
    x2 = df[["x2", "y2", "z2"]].to_numpy(float)
    c = df[["cx", "cy", "cz"]].to_numpy(float)
    f = df[["fx", "fy", "fz"]].to_numpy(float)
    if (id1 < 0).any():
        r = int(np.flatnonzero(id1 < 0)[0])
        raise InputError(f"{where}: {at(r)} has a negative id1 (walls go in id2)")
    wall = id2 < 0
    bad = ~np.isfinite(x2[~wall]).all(axis=1)
    if bad.any():
        r = int(np.flatnonzero(~wall)[np.flatnonzero(bad)[0]])
        raise InputError(f"{where}: {at(r)}: x2,y2,z2 of particle {int(id2[r])} missing or NaN")
    ids = np.concatenate([id1, id2[~wall]])
    pos = np.concatenate([x1, x2[~wall]])
    uid, first, inv = np.unique(ids, return_index=True, return_inverse=True)
    centres = pos[first]
    branch = None
    if "lx" in df.columns:
        branch = df[list(BRANCH)].to_numpy(float)
        bad = ~np.isfinite(branch[~wall]).all(axis=1)
        if bad.any():
            r = int(np.flatnonzero(~wall)[np.flatnonzero(bad)[0]])
            raise InputError(f"{where}: {at(r)}: lx,ly,lz of a particle-particle contact "
                             "missing or NaN")
    elif cell is not None:

        clash = ~same_point_modulo(pos, centres[inv], cell)
        if clash.any():
            j = int(np.flatnonzero(clash)[0])
            raise InputError(f"{where}: body {int(ids[j])} appears at two centres that are "
                             "not images of each other in the periodic cell")
    else:
        with np.errstate(invalid="ignore"):
            dev = np.abs(pos - centres[inv]).max(axis=1)
        scale = np.nanmax(np.abs(pos)) if len(pos) else 1.0
        clash = dev > 1e-9 * max(scale, 1e-300)
        if clash.any():
            j = int(np.flatnonzero(clash)[0])
            raise InputError(f"{where}: body {int(ids[j])} appears with two different centres"
                             " (a periodic cell? give --cell LX LY LZ)")
    wall_ids = np.unique(id2[wall])
    standard = np.arange(-1, -len(WALL_ORDER) - 1, -1)
    if box is not None and np.isin(wall_ids, standard).all():
        wall_ids = standard.astype(np.int64)
        lo, hi = np.zeros(3), np.asarray(box, float)
    elif cell is not None:
        lo, hi = np.zeros(3), np.diag(cell).copy()
    else:
        lo, hi = np.full(3, np.nan), np.full(3, np.nan)
    return Snapshot(
        name=name, step=int(step), time=float("nan"), stage="table",
        volume=volume, box_lo=lo, box_hi=hi, wall_ids=wall_ids, wall_forces=None,
        body_ids=uid, positions=centres, id1=id1, id2=id2, point=c, force=f,
        cell=cell, branch=branch)
