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

import os

import numpy as np
import pandas as pd

from .errors import InputError
from .periodic import cell_matrix, same_point_modulo
from .schema import WALL_ORDER, Snapshot

REQUIRED = ("id1", "id2", "x1", "y1", "z1", "x2", "y2", "z2",
            "cx", "cy", "cz", "fx", "fy", "fz")
BRANCH = ("lx", "ly", "lz")


def _read_frame(path):

    ext = os.path.splitext(path)[1].lower()
    try:
        if ext in (".parquet", ".pq"):
            try:
                return pd.read_parquet(path)
            except ImportError:
                raise InputError(f"{path}: reading Parquet needs pyarrow "
                                 "(pip install 'ballast-triaxial[parquet]')") from None
        return pd.read_csv(path)
    except InputError:
        raise
    except (OSError, ValueError) as exc:
        first = str(exc).splitlines()[0] if str(exc) else exc.__class__.__name__
        raise InputError(f"{path}: cannot read the contact table: {first}") from None


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
    missing = [c for c in REQUIRED if c not in df.columns]
    if missing:
        raise InputError(f"{path}: missing columns {', '.join(missing)}")
    given = [c for c in BRANCH if c in df.columns]
    if given and len(given) < 3:
        raise InputError(f"{path}: branch columns {', '.join(given)} given without "
                         f"{', '.join(c for c in BRANCH if c not in given)}")
    if len(df) == 0:
        raise InputError(f"{path}: the table has no rows (no contacts)")
    for col in ("id1", "id2"):
        vals = df[col].to_numpy()
        if not np.issubdtype(vals.dtype, np.integer):
            raise InputError(f"{path}: column {col} must hold integers "
                             "(a missing or non-integer id?)")
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
    id1 = df["id1"].to_numpy(np.int64)
    id2 = df["id2"].to_numpy(np.int64)
    x1 = df[["x1", "y1", "z1"]].to_numpy(float)
    x2 = df[["x2", "y2", "z2"]].to_numpy(float)
    c = df[["cx", "cy", "cz"]].to_numpy(float)
    f = df[["fx", "fy", "fz"]].to_numpy(float)
    if (id1 < 0).any():
        r = int(np.flatnonzero(id1 < 0)[0])
        raise InputError(f"{where}: row {r} has a negative id1 (walls go in id2)")
    wall = id2 < 0
    bad = ~np.isfinite(x2[~wall]).all(axis=1)
    if bad.any():
        r = int(np.flatnonzero(~wall)[np.flatnonzero(bad)[0]])
        raise InputError(f"{where}: row {r}: x2,y2,z2 of particle {int(id2[r])} missing or NaN")
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
            raise InputError(f"{where}: row {r}: lx,ly,lz of a particle-particle contact "
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
