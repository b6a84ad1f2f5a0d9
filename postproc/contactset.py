"""From a :class:`~postproc.schema.Snapshot` to analysis-ready contact arrays.

This is where ids become row indices and where bad input is caught: every
check raises :class:`~postproc.errors.InputError` with a one-line message
naming the snapshot and the offending contact or body, never a numpy error.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .errors import InputError
from .periodic import minimum_image
from .schema import WALL_ORDER, Snapshot


@dataclass
class ContactSet:
    """The contacts of one snapshot, resolved against its bodies (C
    contacts, B particles; SI units, forces on id2 by id1).

    Attributes
    ----------
    force : (C, 3) N, total contact force on id2 by id1.
    arm : (C, 3) m, y2 - y1 where y is the particle centre for a particle
        and the contact point for a wall. ``force (x) arm`` summed over all
        contacts is minus the sum of the particles' internal moments, so
        sigma = sum(force (x) arm) / V is compression positive (seed eq. 2).
    pp : (C,) bool, True for particle-particle contacts. For those, ``arm``
        is the branch vector l = x2 - x1.
    i1, i2 : (C,) int, particle rows of id1 and id2 (-1 for a wall).
    wall_slot : (C,) int, for a particle-wall contact the wall's slot in
        ``WALL_ORDER`` (0..5) when known, -1 otherwise or for pp contacts.
    wall_sign : (C,) float, +1 when the wall is id2, -1 when it is id1, 0 for
        pp contacts: ``wall_sign * force`` is the force on the wall.
    normal_force : (C,) N, magnitude of the normal force: |force_normal| when
        the source gives the contact normal split, else the radial component
        force . l/|l| (pp; positive for a repulsive, compressive contact) or
        |force| (walls).
    n_particles : int, B.
    volume : float, m^3, the snapshot's volume V (``snap.volume``, > 0), the
        V of the stress sums.
    """

    force: np.ndarray
    arm: np.ndarray
    pp: np.ndarray
    i1: np.ndarray
    i2: np.ndarray
    wall_slot: np.ndarray
    wall_sign: np.ndarray
    normal_force: np.ndarray
    n_particles: int
    volume: float


def _first_bad(mask):
    return int(np.flatnonzero(mask)[0])


def _check_finite(label, arr, where, what):
    arr = np.asarray(arr, dtype=float)
    bad = ~np.isfinite(arr)
    if bad.ndim > 1:
        bad = bad.any(axis=tuple(range(1, bad.ndim)))
    if bad.any():
        k = _first_bad(bad)
        raise InputError(f"{where}: {int(bad.sum())} {label} NaN or infinite "
                         f"(first: {what} {k})")


def _has_duplicates(ids):
    """True when the int array ``ids`` holds a value twice (O(n) for the
    dense ids YADE uses, a sort otherwise)."""
    if len(ids) < 2:
        return False
    lo, hi = int(ids.min()), int(ids.max())
    if hi - lo < 4 * len(ids) + 64:
        return bool(np.bincount(ids - lo).max() > 1)
    s = np.sort(ids)
    return bool((s[1:] == s[:-1]).any())


def lookup(ids, table_ids):
    """Row of each id in ``table_ids`` (unique ids), -1 where absent.

    Parameters
    ----------
    ids : array_like of int, shape (N,)
        The ids to look up (body or wall ids; any integers).
    table_ids : array_like of int, shape (M,)
        The table's ids, each at most once (the row returned for a
        duplicated id is not defined).

    Returns
    -------
    ndarray of int64, shape (N,)
        The row (0..M-1) of each id in ``table_ids``, or -1 when it is not
        there (all -1 for an empty table). Dense non-negative ids (largest
        < 4 M + 64, as YADE numbers its bodies) use a direct lookup table,
        others a sorted search.
    """
    ids = np.asarray(ids, np.int64)
    table_ids = np.asarray(table_ids, np.int64)
    if len(table_ids) == 0:
        return np.full(len(ids), -1, np.int64)
    lo, hi = int(table_ids.min()), int(table_ids.max())
    if lo >= 0 and hi < 4 * len(table_ids) + 64:
        # dense ids (YADE numbers bodies 0..N-1): a direct lookup table
        table = np.full(hi + 1, -1, np.int64)
        table[table_ids] = np.arange(len(table_ids))
        inside = (ids >= 0) & (ids <= hi)
        return np.where(inside, table[np.clip(ids, 0, hi)], -1)
    order = np.argsort(table_ids)
    s = table_ids[order]
    pos = np.clip(np.searchsorted(s, ids), 0, len(s) - 1)
    return np.where(s[pos] == ids, order[pos], -1)


def resolve(snap: Snapshot) -> ContactSet:
    """Validate a snapshot and build its :class:`ContactSet`.

    Branch vectors: ``snap.branch`` when given, else x2 - x1, taken by
    minimum image when ``snap.cell`` is a periodic cell
    (:mod:`postproc.periodic`).

    Raises InputError for: non-positive or non-finite volume, no contacts,
    NaN/inf in positions, contact points or forces, duplicate body ids,
    contacts naming unknown ids, self-contacts, wall-wall contacts, and
    particle-particle contacts with coincident centres.

    Parameters
    ----------
    snap : postproc.schema.Snapshot
        One snapshot: body ids (B,) and centres (B, 3) m, wall ids (W,),
        contact ids id1, id2 (C,), contact points (C, 3) m, total forces
        (C, 3) N on id2 by id1 and, when the source has them, the normal
        forces (C, 3) N, a periodic cell (3, 3) m and explicit branch
        vectors (C, 3) m (NaN allowed for wall contacts).

    Returns
    -------
    ContactSet
        The contacts resolved against the bodies (see its Attributes): rows
        of the two sides, arms (branch vectors for particle pairs, m),
        wall slots and signs, normal forces (N), B and the volume (m^3).
        A wall slot is known (0..5, ``WALL_ORDER``) only when the snapshot
        lists exactly six walls.

    Raises
    ------
    InputError
        One line naming the snapshot and the first offending contact or
        body, for each case listed above, or branch vectors of a shape
        other than (C, 3) or non-finite for a particle pair.
    """
    where = f"snapshot {snap.name} (step {snap.step})"
    V = float(snap.volume)
    if not np.isfinite(V) or V <= 0:
        raise InputError(f"{where}: volume is {V!r}; it must be finite and > 0")
    nc = len(snap.id1)
    if nc == 0:
        raise InputError(f"{where}: no contacts")
    body_ids = np.asarray(snap.body_ids, np.int64)
    if _has_duplicates(body_ids):
        raise InputError(f"{where}: duplicate body ids")
    wall_ids = np.asarray(snap.wall_ids, np.int64)
    _check_finite("body positions are", snap.positions, where, "body row")
    _check_finite("contact points are", snap.point, where, "contact")
    _check_finite("contact forces are", snap.force, where, "contact")
    if snap.force_normal is not None:
        _check_finite("normal forces are", snap.force_normal, where, "contact")

    id1 = np.asarray(snap.id1, np.int64)
    id2 = np.asarray(snap.id2, np.int64)
    i1, i2 = lookup(id1, body_ids), lookup(id2, body_ids)
    w1, w2 = lookup(id1, wall_ids), lookup(id2, wall_ids)
    for ids, ib, iw in ((id1, i1, w1), (id2, i2, w2)):
        unknown = (ib < 0) & (iw < 0)
        if unknown.any():
            k = _first_bad(unknown)
            raise InputError(f"{where}: {int(unknown.sum())} contacts name unknown "
                             f"body ids (first: contact {k}, id {int(ids[k])})")
    if (id1 == id2).any():
        k = _first_bad(id1 == id2)
        raise InputError(f"{where}: contact {k} joins body {int(id1[k])} to itself")
    ww = (i1 < 0) & (i2 < 0)
    if ww.any():
        k = _first_bad(ww)
        raise InputError(f"{where}: contact {k} joins two walls "
                         f"({int(id1[k])}, {int(id2[k])})")

    pos = np.asarray(snap.positions, float)
    point = np.asarray(snap.point, float)
    force = np.asarray(snap.force, float)
    y1 = np.where((i1 >= 0)[:, None], pos[np.maximum(i1, 0)], point)
    y2 = np.where((i2 >= 0)[:, None], pos[np.maximum(i2, 0)], point)
    arm = y2 - y1
    pp = (i1 >= 0) & (i2 >= 0)
    if snap.cell is not None:       # periodic: branch vectors by minimum image

        arm = minimum_image(arm, snap.cell)
    if snap.branch is not None:     # branch vectors given by the source
        br = np.asarray(snap.branch, float)
        if br.shape != (nc, 3):
            raise InputError(f"{where}: branch vectors have shape {br.shape}, expected {(nc, 3)}")
        _check_finite("branch vectors are", np.where(pp[:, None], br, 0.0), where, "contact")
        arm = np.where(pp[:, None], br, arm)
    length = np.sqrt(np.einsum("ij,ij->i", arm, arm))
    zero = pp & (length == 0)
    if zero.any():
        k = _first_bad(zero)
        raise InputError(f"{where}: contact {k} joins bodies {int(id1[k])} and "
                         f"{int(id2[k])} whose centres coincide")

    wall_row = np.where(i1 < 0, w1, np.where(i2 < 0, w2, -1))
    n_slots = len(WALL_ORDER)
    wall_slot = np.where((wall_row >= 0) & (wall_row < n_slots) &
                         (len(wall_ids) == n_slots), wall_row, -1)
    wall_sign = np.where(pp, 0.0, np.where(i2 < 0, 1.0, -1.0))

    if snap.force_normal is not None:
        fn = np.asarray(snap.force_normal, float)
        normal_force = np.sqrt(np.einsum("ij,ij->i", fn, fn))
    else:
        safe = np.where(length > 0, length, 1.0)
        radial = np.einsum("ij,ij->i", force, arm) / safe
        normal_force = np.where(pp, radial, np.sqrt(np.einsum("ij,ij->i", force, force)))
    return ContactSet(force=force, arm=arm, pp=pp, i1=i1, i2=i2,
                      wall_slot=wall_slot, wall_sign=wall_sign,
                      normal_force=normal_force, n_particles=len(body_ids),
                      volume=V)
