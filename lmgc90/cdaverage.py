"""Contact forces and wall reactions averaged over the last K CD steps.

Pure numpy. One CD step's contact forces are impulses over that step
divided by dt; with rigid grains and walls pressed by a constant force they
swing between 0 and several sigma0 from step to step (docs/lmgc90.md). A
snapshot that stands for the packing's quasi-static state takes, as CD
practitioners do, the impulses summed over the K steps before it divided
by K dt: the mean force over the window.

Points are matched across steps by LMGC90's identity of an interaction,
(interaction type, candidate body, antagonist body, candidate contactor,
antagonist contactor, candidate sub-contactor, antagonist sub-contactor)
(``getInteractions`` fields ``inter``, ``icdbdy``, ``ianbdy``, ``icdtac``,
``iantac``, ``icdsci``, ``iansci``), and, since LMGC90 gives every point of a
PRPRx (common-plane) pair the same identity (sub-contactors 0), by the
point's rank among its pair's points in LMGC90's order (``icdan``): the
k-th point of a pair in one step is matched with the k-th in another. When a
pair's number of points changes inside the window, the ranks past the
smaller number are points that appear or vanish; which geometric point
carries which rank is then LMGC90's order, not a geometric match. A pair's
total force, every body's net force and the stress identities do not
depend on the matching; only the split of a pair's mean force among its
points does. A point absent from some
steps of the window counts zero impulse there, so every point's mean force
is (sum of its impulses) / (K dt) and the forces on any body sum to its
mean reaction over the window exactly. The averaged state keeps every point
seen in the window with a nonzero mean force plus every point of the last
step; its position, gap and frame are those of the last step it was seen
(the last step for the points alive then), its force the window's mean,
expressed in that frame.
"""
from __future__ import annotations

from collections import deque

import numpy as np


class ForceWindow:
    """The last K steps' contact points and wall reactions, and their mean.

    Parameters
    ----------
    steps : int
        K >= 1, the window's length in steps (1: the last step alone).

    Examples
    --------
    One point carries 3 N in step 1 and vanishes, another carries 1 N then
    3 N: the means over K = 2 are 1.5 N and 2 N.

    >>> import numpy as np
    >>> from lmgc90.cdaverage import ForceWindow
    >>> w = ForceWindow(2)
    >>> F = np.eye(3)[None]
    >>> w.add([[0, 1, 2, 1, 1, 1, 1], [0, 1, 3, 1, 1, 1, 1]], [1, 1], [2, 3], np.zeros((2, 3)),
    ...       np.tile(F, (2, 1, 1)), [[0, 3.0, 0], [0, 1.0, 0]], [0.0, 0.0], np.zeros((6, 3)))
    >>> w.add([[0, 1, 3, 1, 1, 1, 1]], [1], [3], np.zeros((1, 3)), F, [[0, 3.0, 0]], [0.0],
    ...       np.ones((6, 3)))
    >>> cd, an, x, uc, r, gap, walls = w.mean()
    >>> print(an, r[:, 1], walls[0])
    [2 3] [1.5 2. ] [0.5 0.5 0.5]
    """

    def __init__(self, steps):
        if int(steps) < 1:
            raise ValueError(f"the averaging window needs at least one step, got {steps}")
        self.steps = int(steps)
        self._window = deque(maxlen=self.steps)

    def __len__(self):
        return len(self._window)

    @property
    def full(self):
        """Whether the window holds K steps (bool)."""
        return len(self._window) == self.steps

    def clear(self):
        """Forget every step (a stage change: the window restarts).

        Returns
        -------
        None
        """
        self._window.clear()

    def add(self, keys, candidate, antagonist, point, frames, reactions, gap, wall_forces):
        """Append one step (the oldest drops out once K are held).

        Parameters
        ----------
        keys : array_like, shape (P, 7)
            int, each point's LMGC90 identity in LMGC90's order (module
            docstring); points sharing one are told apart by their rank.
        candidate, antagonist : array_like, shape (P,)
            int, body rows (any numbering, kept as given).
        point : array_like, shape (P, 3)
            m, the contact points.
        frames : array_like, shape (P, 3, 3)
            local frames, columns t, n, s.
        reactions : array_like, shape (P, 3)
            N, (r_t, r_n, r_s) (the step's impulse / dt) in the local frame.
        gap : array_like, shape (P,)
            m.
        wall_forces : array_like, shape (W, 3)
            N, some bodies' contact reactions this step (the walls', or
            every body's: LMGC90's ``Reac_``), averaged alike.

        Returns
        -------
        None
        """
        k = np.asarray(keys, np.int64).reshape(-1, 7)
        k = np.concatenate([k, rank_among_equals(k)[:, None]], axis=1)
        uc = np.asarray(frames, float).reshape(-1, 3, 3)
        r = np.asarray(reactions, float).reshape(-1, 3)
        P = len(k)
        for name, a in (("candidate", candidate), ("antagonist", antagonist), ("gap", gap)):
            if np.asarray(a).reshape(-1).shape[0] != P:
                raise ValueError(f"{name} has {np.asarray(a).size} entries for {P} points")
        if len(uc) != P or len(r) != P or np.asarray(point).reshape(-1, 3).shape[0] != P:
            raise ValueError(f"points, frames and reactions must have {P} rows, one per key")
        self._window.append({
            "keys": k, "cd": np.asarray(candidate, np.int64).reshape(-1),
            "an": np.asarray(antagonist, np.int64).reshape(-1), "x": np.asarray(point, float).reshape(-1, 3),
            "uc": uc, "f": np.einsum("pij,pj->pi", uc, r), "gap": np.asarray(gap, float).reshape(-1),
            "walls": np.asarray(wall_forces, float).copy()})

    def mean(self):
        """The window's mean state, in :meth:`add`'s layout.

        Returns
        -------
        candidate, antagonist : ndarray, shape (Q,)
        point : ndarray, shape (Q, 3)
            m, the point's last position in the window.
        frames : ndarray, shape (Q, 3, 3)
            its last local frame.
        reactions : ndarray, shape (Q, 3)
            N, the mean force sum(impulses) / (K dt) in that frame, where K
            is the number of steps held (fewer than ``steps`` before the
            window fills).
        gap : ndarray, shape (Q,)
            m, the last gap.
        wall_forces : ndarray, shape (W, 3)
            N, those bodies' mean reactions.

        Raises
        ------
        ValueError
            On an empty window.
        """
        if not self._window:
            raise ValueError("the averaging window holds no step")
        K = len(self._window)
        allkeys = np.concatenate([s["keys"] for s in self._window])
        uniq, inv = np.unique(allkeys, axis=0, return_inverse=True)
        inv = inv.reshape(-1)
        Q = len(uniq)
        fsum = np.zeros((Q, 3))
        np.add.at(fsum, inv, np.concatenate([s["f"] for s in self._window]))
        # the last occurrence of each point: later steps overwrite earlier ones
        last = np.zeros(Q, np.int64)
        last[inv] = np.arange(len(inv))
        cat = {n: np.concatenate([s[n] for s in self._window]) for n in ("cd", "an", "x", "uc", "gap")}
        n_last = len(self._window[-1]["keys"])
        alive_last = np.zeros(Q, bool)
        alive_last[inv[len(inv) - n_last:]] = True
        fmean = fsum / K
        keep = alive_last | np.any(fmean != 0.0, axis=1)
        sel = last[keep]
        uc = cat["uc"][sel]
        r = np.einsum("pji,pj->pi", uc, fmean[keep])        # global -> local (the frame is orthonormal)
        walls = sum(s["walls"] for s in self._window) / K
        return cat["cd"][sel], cat["an"][sel], cat["x"][sel], uc, r, cat["gap"][sel], walls


def rank_among_equals(keys):
    """Each row's rank among the rows equal to it, in their order.

    Parameters
    ----------
    keys : array_like, shape (P, M)
        int rows.

    Returns
    -------
    ndarray of int64, shape (P,)
        0 for a row's first occurrence, 1 for its second, ...

    Examples
    --------
    >>> from lmgc90.cdaverage import rank_among_equals
    >>> print(rank_among_equals([[1, 2], [3, 4], [1, 2], [1, 2]]).tolist())
    [0, 0, 1, 2]
    """
    k = np.asarray(keys, np.int64)
    k = k.reshape(len(k), -1)
    if len(k) == 0:
        return np.zeros(0, np.int64)
    _, inv = np.unique(k, axis=0, return_inverse=True)
    inv = inv.reshape(-1)
    order = np.argsort(inv, kind="stable")
    g = inv[order]
    start = np.r_[0, np.flatnonzero(np.diff(g)) + 1]
    first = np.repeat(start, np.diff(np.r_[start, len(g)]))
    rank = np.empty(len(k), np.int64)
    rank[order] = np.arange(len(k)) - first
    return rank
