"""Contact forces and wall reactions averaged over the last K CD steps.

Pure numpy. One CD step's contact forces are impulses over that step
divided by dt; with rigid grains and walls pressed by a constant force they
swing between 0 and several sigma0 from step to step (docs/lmgc90.md). A
snapshot that stands for the packing's quasi-static state takes, as CD
practitioners do, the impulses summed over the K steps before it divided
by K dt: the mean force over the window.

Points are matched across steps by LMGC90's identity of an interaction:
(interaction type, candidate body, antagonist body, candidate contactor,
antagonist contactor, candidate sub-contactor, antagonist sub-contactor)
(``getInteractions`` fields ``inter``, ``icdbdy``, ``ianbdy``, ``icdtac``,
``iantac``, ``icdsci``, ``iansci``: for PRPRx the sub-contactors are the
vertex / face numbers of the common-plane point). A point absent from some
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
            int, each point's identity (module docstring).
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
