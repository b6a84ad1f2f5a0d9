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
#: the columns a table is read by
READ = REQUIRED + BRANCH + ("step",)


def _records_by_line(path):
    """The records of the CSV file ``path`` and the line each starts on;
    a record the csv module refuses (a quote left open, a field over its
    limit) is named by that line."""
    records, starts, start = [], [], 1
    try:
        with open(path, newline="", encoding="utf-8-sig") as fh:
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
    rows = [records[k] for k in keep[1:]]
    lines = np.asarray(starts, np.int64)[keep[1:]]
    n = len(header)
    named = n
    while named > 1 and header[named - 1] == "":
        named -= 1                               # empty names at the end (a spreadsheet's blank columns)
    dup = sorted({c for c in header if c in READ and header.count(c) > 1})
    if dup:
        raise InputError(f"{path}: columns named twice in the header: {', '.join(dup)}")
    if named < n:                                # rows may stop before the header's empty names
        rows = [r + [""] * (n - len(r)) if named <= len(r) < n else r for r in rows]
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
        text = data.decode("utf-8-sig")
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
    want = [c for c in READ if c in names]
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            # every column read, the others by inference: pandas' usecols
            # costs about 3x the whole parse
            df = pd.read_csv(path, dtype={c: "int64" if c in WHOLE else "float64" for c in want},
                             skipinitialspace=True, encoding="utf-8-sig")
    except (ValueError, OSError, Warning):
        return None
    if len(df) != len(rows):
        return None
    if any(len(df) and np.abs(df[c].to_numpy()).max() >= 2 ** 53 for c in want if c in WHOLE):
        return None          # pandas may have read such ids through float64: read them exactly
    return {c: df[c] for c in want}, rows + 1


def _is_missing(v):
    """True for a cell that holds no value: None, NA, a float NaN, or a
    missing-value text (:data:`NA_TEXT`, or NaN in any case: ``NAN``)."""
    if v is None or v is pd.NA or (isinstance(v, float) and np.isnan(v)):
        return True
    t = str(v).strip()
    return t in NA_TEXT or t.lower().lstrip("+-") == "nan"


def _numbers(path, columns, lines):
    """The columns the table reads (:data:`READ`) as numbers: a DataFrame
    with the column ``_line``, each row's line in a CSV file or its row
    from 1 in a Parquet file.

    ``columns`` maps a name to a pandas Series or a tuple of cell texts;
    ``lines``, (R,) int, each row's line in a CSV file (None: rows of a
    Parquet file). Every cell must be a number or a missing value
    (:func:`_is_missing`); ids and steps whole numbers
    (:func:`_whole_column`). A bad cell is refused in one line naming its
    line (or row) and column."""
    out = {}
    for col in [c for c in READ if c in columns]:
        raw = columns[col]
        if isinstance(raw, pd.Series) and pd.api.types.is_bool_dtype(raw.dtype):
            raise InputError(f"{path}: column {col} holds true/false values, not numbers")
        if col in WHOLE:
            out[col] = _whole_column(path, col, raw, lines)
            continue
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
                if not _is_missing(text[i]):
                    raise InputError(f"{path}: {_where(lines, i)}, column {col}: {str(text[i])[:40]!r} "
                                     "is not a number")
        out[col] = vals
    n = len(next(iter(out.values()))) if out else 0
    out["_line"] = np.asarray(lines, np.int64) if lines is not None else np.arange(1, n + 1)
    return pd.DataFrame(out)


def _whole_column(path, col, raw, lines):
    """(R,) int64: an id or step column read exactly (an integer column as
    it is, text by ``int`` before ``float``: 64-bit ids are not rounded
    through float64); a cell that is missing, not a number, not whole, not
    finite or out of range is refused in one line naming its line (or row)
    and column."""
    if isinstance(raw, pd.Series) and pd.api.types.is_integer_dtype(raw.dtype):
        if raw.isna().any():
            raise InputError(f"{path}: {_where(lines, int(np.flatnonzero(raw.isna().to_numpy())[0]))}, "
                             f"column {col}: missing")
        if raw.dtype.kind == "u" and len(raw) and int(raw.max()) >= 2 ** 63:
            i = int(np.flatnonzero(raw.to_numpy() >= 2 ** 63)[0])
            raise InputError(f"{path}: {_where(lines, i)}, column {col}: {raw.iloc[i]} is out of range "
                             "for a 64-bit id")
        return raw.to_numpy(np.int64)
    text = raw.to_numpy(object) if isinstance(raw, pd.Series) else raw
    out = np.empty(len(text), np.int64)
    for i, v in enumerate(text):
        got = _whole_cell(v)
        if isinstance(got, str):
            raise InputError(f"{path}: {_where(lines, i)}, column {col}: {got}")
        out[i] = got
    return out


def _whole_cell(v):
    """The int a cell holds, or why it holds none (a str)."""
    if _is_missing(v):
        return "missing"
    if isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_)):
        i = int(v)
    else:
        t = str(v).strip()
        try:
            i = int(t)
        except ValueError:
            try:
                f = float(t)
            except ValueError:
                return f"{t[:40]!r} is not a number"
            if not np.isfinite(f):
                return f"{t[:40]!r} is not finite"
            if f != np.round(f):
                return f"{t[:40]!r}, not a whole number"
            if abs(f) >= 2.0 ** 53:
                return f"{t[:40]!r} is out of range for a whole number written as a float (2^53)"
            i = int(f)
    if not -2 ** 63 <= i < 2 ** 63:
        return f"{v!r} is out of range for a 64-bit id"
    return i


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
