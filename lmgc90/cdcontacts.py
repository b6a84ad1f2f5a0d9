"""LMGC90's interactions as the dump schema's contacts and contact points.

Pure numpy. Every LMGC90 interaction (PRPRx, PRPLx, SPSPx, SPPLx) is one
contact point between a candidate body and an antagonist body, with a local
frame (t, n, s), a reaction r = (r_t, r_n, r_s) and a gap. LMGC90's
conventions: n points from the antagonist to the candidate, the reaction
acts on the candidate (its opposite on the antagonist) and r_n >= 0 pushes
the two apart. So in the schema's terms (forces on id2 by id1, normal from
id1 to id2) id1 is the antagonist and id2 the candidate, the point's force
is ``r_t t + r_n n + r_s s`` and its normal ``n``. ``tests/test_lmgc90_triaxial.py``
checks these conventions against LMGC90's own per-body reactions.

The dump gets one ``contacts`` row per pair of bodies (any number of
points: one for a vertex, two along an edge, three or more on a face) and
every point in ``points`` (:func:`pairs_and_points`).
"""
from __future__ import annotations

import numpy as np


def point_forces(frames, reactions):
    """Global force vectors of contact points from their local frames.

    Parameters
    ----------
    frames : array_like, shape (P, 3, 3)
        LMGC90's local frames, columns t, n, s (``getInteractions()['uc']``).
    reactions : array_like, shape (P, 3)
        N, (r_t, r_n, r_s) (forces: LMGC90's impulses divided by the time step).

    Returns
    -------
    normal : ndarray, shape (P, 3)
        The unit normals n.
    force_normal, force_tangential : ndarray, shape (P, 3)
        N, ``r_n n`` and ``r_t t + r_s s``: the force on the candidate.

    Examples
    --------
    >>> import numpy as np
    >>> from lmgc90.cdcontacts import point_forces
    >>> frame = np.eye(3)[None]                  # t = x, n = y, s = z
    >>> n, fn, ft = point_forces(frame, [[1.0, 5.0, 2.0]])
    >>> print(n[0], fn[0], ft[0])
    [0. 1. 0.] [0. 5. 0.] [1. 0. 2.]
    """
    uc = np.asarray(frames, float).reshape(-1, 3, 3)
    r = np.asarray(reactions, float).reshape(-1, 3)
    n = uc[:, :, 1]
    fn = n * r[:, 1:2]
    ft = uc[:, :, 0] * r[:, 0:1] + uc[:, :, 2] * r[:, 2:3]
    return n, fn, ft


def pairs_and_points(id_candidate, id_antagonist, point, frames, reactions, gap):
    """The schema's ``contacts`` (one row per pair) and ``points`` of one state.

    Parameters
    ----------
    id_candidate, id_antagonist : array_like, shape (P,)
        int, the dump ids of each point's candidate and antagonist bodies.
    point : array_like, shape (P, 3)
        m, the contact points.
    frames : array_like, shape (P, 3, 3)
        local frames, columns t, n, s (n from antagonist to candidate).
    reactions : array_like, shape (P, 3)
        N, (r_t, r_n, r_s), the force on the candidate in the local frame.
    gap : array_like, shape (P,)
        m, negative for an interpenetration.

    Returns
    -------
    contacts : dict
        The ``contacts/*`` fields, one row per unordered pair, sorted by
        (id1, id2): ``id1`` the pair's antagonist (the lower id when points
        disagree), ``id2`` the other; ``force_normal`` + ``force_tangential``
        = the sum of the points' forces on id2 by id1 (N), split along the
        pair's normal, the unit vector along the sum of the points' normals
        weighted by their normal forces (unweighted when the pair carries
        none); ``point`` the points' centroid weighted by their normal
        forces (unweighted when none): for the grain-wall pairs of
        frictionless walls, whose forces all lie along the wall's normal,
        the pair's row then gives exactly the points' moment about any
        grain centre, so the Love-Weber stress of the rows is that of the
        points; ``overlap`` the largest interpenetration, m (-min gap,
        ``overlap_kind = "depth"``; negative when no point interpenetrates).
    points : dict
        The ``points/*`` fields: ``contact`` (P,) row of each point's pair;
        ``point``; ``normal`` (from id1 to id2 of its row);
        ``force_normal``, ``force_tangential`` (N, on id2 by id1); ``gap``.

    Examples
    --------
    Two points of one face contact, candidate 8 on antagonist 7 (n = +z),
    and one point of 9 on 7:

    >>> import numpy as np
    >>> from lmgc90.cdcontacts import pairs_and_points
    >>> F = np.tile(np.array([[1.0, 0, 0], [0, 0, 1], [0, 1, 0]]), (3, 1, 1))   # t = x, n = z, s = y
    >>> c, p = pairs_and_points([8, 8, 9], [7, 7, 7], [[0, 0, 0], [1, 0, 0], [0, 5, 0]], F,
    ...                         [[0.0, 3.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]], [0.0, -1e-4, 2e-4])
    >>> print(c["id1"], c["id2"], c["force_normal"][0], c["point"][0], p["contact"])
    [7 7] [8 9] [0. 0. 4.] [0.25 0.   0.  ] [0 0 1]
    """
    cd = np.asarray(id_candidate, np.int64).reshape(-1)
    an = np.asarray(id_antagonist, np.int64).reshape(-1)
    x = np.asarray(point, float).reshape(-1, 3)
    g = np.asarray(gap, float).reshape(-1)
    n, fn, ft = point_forces(frames, reactions)
    P = len(cd)
    if P == 0:
        z3 = np.zeros((0, 3))
        return ({"id1": np.zeros(0, np.int64), "id2": np.zeros(0, np.int64), "point": z3, "normal": z3,
                 "force_normal": z3, "force_tangential": z3, "overlap": np.zeros(0)},
                {"contact": np.zeros(0, np.int64), "point": z3, "normal": z3, "force_normal": z3,
                 "force_tangential": z3, "gap": np.zeros(0)})
    lo, hi = np.minimum(cd, an), np.maximum(cd, an)
    keys = np.stack([lo, hi], axis=1)
    uniq, row = np.unique(keys, axis=0, return_inverse=True)
    row = row.reshape(-1)
    C = len(uniq)
    # the pair's id1: the antagonist of its first point
    first = np.full(C, P, np.int64)
    np.minimum.at(first, row, np.arange(P))
    id1 = an[first]
    id2 = np.where(uniq[:, 0] == id1, uniq[:, 1], uniq[:, 0])
    sign = np.where(an == id1[row], 1.0, -1.0)[:, None]      # -1: the point sees the pair the other way round
    n, fn, ft = sign * n, sign * fn, sign * ft
    rn = np.einsum("ij,ij->i", fn, n)                          # >= 0 in LMGC90
    w_sum = np.zeros(C)
    np.add.at(w_sum, row, rn)
    carried = w_sum[row] > 0
    w = np.where(carried, rn, 1.0)
    wsum = np.zeros(C)
    np.add.at(wsum, row, w)
    nsum = np.zeros((C, 3))
    np.add.at(nsum, row, w[:, None] * n)
    xsum = np.zeros((C, 3))
    np.add.at(xsum, row, w[:, None] * x)
    F = np.zeros((C, 3))
    np.add.at(F, row, fn + ft)
    nbar = nsum / np.linalg.norm(nsum, axis=1, keepdims=True)
    Fn = np.einsum("ij,ij->i", F, nbar)[:, None] * nbar
    overlap = np.full(C, -np.inf)
    np.maximum.at(overlap, row, -g)
    contacts = {"id1": id1.astype(np.int64), "id2": id2.astype(np.int64), "point": xsum / wsum[:, None],
                "normal": nbar, "force_normal": Fn, "force_tangential": F - Fn, "overlap": overlap}
    points = {"contact": row.astype(np.int64), "point": x, "normal": n, "force_normal": fn,
              "force_tangential": ft, "gap": g}
    return contacts, points


def body_forces(contacts, ids):
    """The net contact force on each body from the dump's ``contacts`` rows.

    Parameters
    ----------
    contacts : dict
        ``id1``, ``id2`` (C,), ``force_normal``, ``force_tangential`` (C, 3) N.
    ids : array_like, shape (B,)
        The bodies wanted (grains and walls alike).

    Returns
    -------
    ndarray, shape (B, 3)
        N, the sum of the rows' forces on each body: +force where it is id2,
        -force where it is id1.

    Examples
    --------
    >>> from lmgc90.cdcontacts import body_forces
    >>> c = {"id1": [0], "id2": [1], "force_normal": [[0, 0, 2.0]], "force_tangential": [[1.0, 0, 0]]}
    >>> print(body_forces(c, [0, 1]))
    [[-1.  0. -2.]
     [ 1.  0.  2.]]
    """
    ids = np.asarray(ids, np.int64)
    slot = {int(b): k for k, b in enumerate(ids)}
    F = np.asarray(contacts["force_normal"], float) + np.asarray(contacts["force_tangential"], float)
    out = np.zeros((len(ids), 3))
    for k, (a, b) in enumerate(zip(np.asarray(contacts["id1"]).tolist(), np.asarray(contacts["id2"]).tolist())):
        if a in slot:
            out[slot[a]] -= F[k]
        if b in slot:
            out[slot[b]] += F[k]
    return out
