"""The paper's contact types read directly off Contact Dynamics contact points.

In LMGC90 every detected interaction is one contact point, and the paper
names a pair of polyhedra by how many points it touches at: **simple**
(one point: vertex–face or edge–edge), **double** (two: edge–face),
**triple** (three or more: face–face). A dump of a CD run (schema version 3)
holds those points (``Snapshot.points``, :mod:`postproc.schema`); this
module counts them per pair of grains, twice:

* ``alert``: every point the detection kept, i.e. within the alert distance
  (optionally only those with ``gap <= alert``);
* ``force``: only the points that carry a force, f_n = force_normal . normal
  above :func:`force_floor` (round-off of the largest force).

and computes claim 6's quantities for each count with the functions the
analysis uses for our own counts (:func:`postproc.pertype.class_statistics`,
:func:`~postproc.pertype.partial_stresses`,
:func:`~postproc.pertype.stress_contributions`,
:func:`postproc.networks.strong_mask`), the three groups standing for the
pair types (simple for VF and EE, double for EF, triple for FF). Pure
functions over arrays; compression positive; forces on id2 by id1.
"""
from __future__ import annotations

import numpy as np

from .axes import axis_vector
from .contactset import resolve
from .errors import InputError
from .networks import strong_mask
from .pertype import class_columns, class_statistics, partial_stresses, stress_contributions
from .schema import POINT_FIELDS
from .stress import contact_stress

GROUPS = ("simple", "double", "triple")
COUNTS = ("alert", "force")


def points_per_pair(contact, n_contacts, keep=None):
    """The number of contact points of each contact row (pair of bodies).

    Parameters
    ----------
    contact : array_like of int, shape (P,)
        The contact row of each point (``points/contact``), 0 <= row < C.
    n_contacts : int
        C, the number of contact rows.
    keep : array_like of bool, shape (P,), optional
        Count only these points (default: all).

    Returns
    -------
    ndarray of int64, shape (C,)
        Points per contact row (0 for a row without a kept point).

    Raises
    ------
    InputError
        A row outside 0 .. C-1 or a ``keep`` of another length.

    Examples
    --------
    >>> from postproc.cdpoints import points_per_pair
    >>> print(points_per_pair([0, 0, 2, 2, 2], 4).tolist())
    [2, 0, 3, 0]
    >>> print(points_per_pair([0, 0, 2, 2, 2], 4, keep=[True, False, True, True, False]).tolist())
    [1, 0, 2, 0]
    """
    c = np.asarray(contact, np.int64).reshape(-1)
    if len(c) and (c.min() < 0 or c.max() >= n_contacts):
        raise InputError(f"point contact row {int(c[(c < 0) | (c >= n_contacts)][0])} is outside "
                         f"0..{n_contacts - 1}")
    w = None
    if keep is not None:
        keep = np.asarray(keep, bool).reshape(-1)
        if len(keep) != len(c):
            raise InputError(f"keep has {len(keep)} entries for {len(c)} points")
        w = keep.astype(np.int64)
    return np.bincount(c, weights=w, minlength=int(n_contacts)).astype(np.int64)


def group_of_count(counts):
    """The paper's group of a pair from its number of points.

    Parameters
    ----------
    counts : array_like of int, shape (C,)
        Points per pair.

    Returns
    -------
    ndarray of str, shape (C,)
        "simple" (1 point: vertex–face, edge–edge), "double" (2:
        edge–face), "triple" (3 or more: face–face), "none" (0).

    Examples
    --------
    >>> from postproc.cdpoints import group_of_count
    >>> print(group_of_count([0, 1, 2, 3, 7]).tolist())
    ['none', 'simple', 'double', 'triple', 'triple']
    """
    n = np.asarray(counts, np.int64)
    return np.select([n == 1, n == 2, n >= 3], ["simple", "double", "triple"], "none").astype(str)


def force_floor(normal_force):
    """The smallest normal force counted as carried: P eps max(f_n).

    NLGS projects the normal impulse of an open or unloaded contact to 0
    exactly; a loaded point's force has round-off of eps times its own
    size. A force below P eps max(f_n) (P points, eps the float64 machine
    epsilon) is below the round-off of the Love–Weber sum over the P points,
    so it cannot be told from zero by any quantity of the analysis.

    Parameters
    ----------
    normal_force : array_like, shape (P,)
        N, the signed normal force of each point (compression positive).

    Returns
    -------
    float
        N, the floor (0 when no point carries a positive force).

    Examples
    --------
    >>> from postproc.cdpoints import force_floor
    >>> print(force_floor([0.0, 2.0, 4.0]) == 3 * 4.0 * 2.0 ** -52)
    True
    """
    fn = np.asarray(normal_force, float).reshape(-1)
    top = float(fn.max()) if len(fn) else 0.0
    return len(fn) * np.finfo(float).eps * top if top > 0 else 0.0


def point_normal_force(points):
    """The signed normal force of each point, f_n = force_normal . normal.

    Parameters
    ----------
    points : dict
        ``Snapshot.points`` (``force_normal`` and ``normal`` (P, 3)).

    Returns
    -------
    ndarray, shape (P,)
        N, positive for a repulsive (compressive) point.
    """
    return np.einsum("ij,ij->i", np.asarray(points["force_normal"], float), np.asarray(points["normal"], float))


def cd_labels(snap, alert=None):
    """The group of every contact row under both counts.

    Parameters
    ----------
    snap : postproc.schema.Snapshot
        A snapshot with ``points`` (schema version 3).
    alert : float, optional
        m: count in ``alert`` only the points with ``gap <= alert`` (default:
        every point the dump holds, i.e. the detection's alert distance).

    Returns
    -------
    dict
        ``alert``, ``force``: (C,) str arrays, the group ("simple",
        "double", "triple") of each particle pair, "none" for a pair with no
        counted point and "wall" for a contact with a wall; ``n_alert``,
        ``n_force``: (C,) int64 points per row; ``carrying``: (P,) bool, the
        points of the ``force`` count; ``floor``: the force floor in N.

    Raises
    ------
    InputError
        A snapshot without points.
    """
    if snap.points is None:
        raise InputError(f"snapshot {snap.name} (step {snap.step}) has no contact points "
                         f"(points/*: a Contact Dynamics dump, schema version 3)")
    pts = snap.points
    missing = [k for k in POINT_FIELDS if k not in pts]
    if missing:
        raise InputError(f"snapshot {snap.name}: points lack {', '.join(missing)}")
    nc = len(snap.id1)
    fn = point_normal_force(pts)
    floor = force_floor(fn)
    carrying = fn > floor
    near = np.ones(len(fn), bool) if alert is None else np.asarray(pts["gap"], float) <= float(alert)
    walls = np.isin(snap.id1, snap.wall_ids) | np.isin(snap.id2, snap.wall_ids)
    out = {"carrying": carrying, "floor": floor}
    for name, keep in (("alert", near), ("force", carrying)):
        n = points_per_pair(pts["contact"], nc, keep)
        lab = group_of_count(n).astype(object)
        lab[walls] = "wall"
        out[name], out["n_" + name] = lab.astype(str), n
    return out


def cd_type_columns(snap, axis=2, alert=None):
    """Claim 6's quantities for both CD counts of one snapshot.

    The population of both counts is the same, as for our counts
    (:func:`postproc.analysis.contact_type_columns`): the force-bearing
    particle pairs, those with at least one point carrying a force. Each
    pair is labelled by its number of points under the count; per group
    (simple, double, triple) the proportion, the mean normal force over the
    overall mean, the force share and the signed branch-vector leaning
    (5/2)(F_3 - F_1) of the group (:func:`postproc.pertype.class_statistics`,
    seed eq. 6 restricted to the group), the group's share of q_axial/p
    (seed eq. 2 split by group) and the share of triples in the strong and
    weak networks.

    Parameters
    ----------
    snap : postproc.schema.Snapshot
        A snapshot with ``points`` (schema version 3), contacts one row per
        pair (forces summed over its points).
    axis : int, str or array_like of shape (3,), optional
        The compression axis (default z).
    alert : float, optional
        m, see :func:`cd_labels`.

    Returns
    -------
    dict
        For C in ("alert", "force") and g in GROUPS: ``cd_<C>_frac_<g>``,
        ``cd_<C>_fratio_<g>``, ``cd_<C>_fshare_<g>``, ``cd_<C>_fabric_<g>``
        and ``_se``, ``cd_<C>_qp_<g>``, and ``cd_<C>_strong_frac_triple``,
        ``cd_<C>_weak_frac_triple``; ``cd_alert_frac_<g>_all``: the
        proportions over every particle pair with a point (carrying or not);
        ``cd_pairs`` (force-bearing pairs), ``cd_pairs_all``,
        ``cd_points``, ``cd_points_carrying``, ``cd_force_floor`` (N),
        ``cd_points_per_pair`` (the mean number of force-carrying points
        of a force-bearing pair).

    Raises
    ------
    InputError
        A snapshot without points, or without a force-bearing pair.

    Examples
    --------
    See ``tests/test_cdpoints.py`` for snapshots built by hand.
    """
    lab = cd_labels(snap, alert)
    cs = resolve(snap)
    e = axis_vector(axis)
    pop = cs.pp & (lab["n_force"] > 0)
    if not pop.any():
        raise InputError(f"snapshot {snap.name} (step {snap.step}): no particle pair carries a force")
    fn, L = cs.normal_force[pop], cs.arm[pop]
    total = contact_stress(cs.force, cs.arm, cs.volume)
    p = float(np.trace(total)) / 3.0
    strong = strong_mask(fn)
    row = {"cd_pairs": int(pop.sum()), "cd_points": int(len(lab["carrying"])),
           "cd_points_carrying": int(lab["carrying"].sum()), "cd_force_floor": float(lab["floor"])}
    seen = cs.pp & (lab["n_alert"] > 0)
    row["cd_pairs_all"] = int(seen.sum())
    for g in GROUPS:
        row[f"cd_alert_frac_{g}_all"] = float(np.mean(lab["alert"][seen] == g)) if seen.any() else np.nan
    for count in COUNTS:
        labels = lab[count]
        row.update(class_columns(class_statistics(labels[pop], fn, L, e), GROUPS, f"cd_{count}_"))
        qp = stress_contributions(partial_stresses(labels, cs.force, cs.arm, cs.volume), p, e)
        for g in GROUPS:
            row[f"cd_{count}_qp_{g}"] = float(qp[g][1]) if g in qp else 0.0
        for name, net in (("strong", strong), ("weak", ~strong)):
            row[f"cd_{count}_{name}_frac_triple"] = float(np.mean(labels[pop][net] == "triple")) \
                if net.any() else np.nan
    row["cd_points_per_pair"] = float(lab["n_force"][pop].mean())
    return row
