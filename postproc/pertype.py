"""Force transmission by contact class: proportions, forces, fabric and
partial stresses (the quantities behind the paper's claim 6).

Pure functions over the arrays of :class:`~postproc.contactset.ContactSet`
and a (C,) array of class labels (e.g. from
:func:`postproc.contacttypes.classify_snapshot`: "VV" ... "FF", "sphere",
"wall"). Compression positive; forces on id2 by id1.
"""
from __future__ import annotations

import numpy as np

from .axes import axis_vector
from .stress import contact_stress


def partial_stresses(labels, force, arm, volume):
    """Partial stresses of the contact classes (seed eq. 2 restricted to a
    class).

    sigma_k = (1/V) sum_{c in k} f (x) arm. They sum to the total stress over
    all contacts exactly (up to round-off), because every contact has one
    label.

    Parameters
    ----------
    labels : array_like, shape (C,)
        The class of each contact (e.g. "VF", "FF", "wall").
    force : ndarray, shape (C, 3)
        N, forces on id2 by id1.
    arm : ndarray, shape (C, 3)
        m, the branch vector for particle pairs, particle to contact point
        for walls (:class:`~postproc.contactset.ContactSet`).
    volume : float
        m^3.

    Returns
    -------
    dict
        {label: ndarray (3, 3)}, Pa, compression positive.

    Examples
    --------
    >>> import numpy as np
    >>> from postproc.pertype import partial_stresses, stress_contributions
    >>> labels = np.array(["FF", "VF", "wall"])
    >>> force = np.array([[0, 0, 10.0], [3.0, 0, 0], [0, 0, -2.0]])
    >>> arm = np.array([[0, 0, 0.05], [0.05, 0, 0], [0, 0, -0.02]])
    >>> parts = partial_stresses(labels, force, arm, 1e-3)
    >>> print({k: np.round(np.diag(v), 9).tolist() for k, v in parts.items()})
    {'FF': [0.0, 0.0, 500.0], 'VF': [150.0, 0.0, 0.0], 'wall': [0.0, 0.0, 40.0]}
    """
    labels = np.asarray(labels)
    return {str(k): contact_stress(force[labels == k], arm[labels == k], volume)
            for k in np.unique(labels)}


def axial_leaning(branch, axis=2):
    """Each contact's contribution to a signed branch-vector anisotropy
    (claim 6's leaning): (5/4)(3 u^2 - 1), u the cosine of the branch vector
    with the compression axis. Its mean over a set of contacts is
    (5/2)(F_3 - F_1) of their fabric tensor F, the anisotropy a of seed
    eq. 6 restricted to the set: positive towards the axis, negative towards
    the lateral (minor principal) directions.

    Parameters
    ----------
    branch : array_like, shape (C, 3)
        m, branch vectors (their sign does not matter).
    axis : int, str or array_like of shape (3,), optional
        The compression axis (default z).

    Returns
    -------
    ndarray, shape (C,)
        Dimensionless, in [-5/4, 5/2].

    Examples
    --------
    >>> import numpy as np
    >>> from postproc.pertype import axial_leaning
    >>> print(axial_leaning(np.array([[0, 0, 2.0], [1.0, 0, 0]])).tolist())
    [2.5, -1.25]
    """
    L = np.asarray(branch, float)
    u = (L @ axis_vector(axis)) / np.linalg.norm(L, axis=1)
    return 1.25 * (3 * u * u - 1)


def class_statistics(labels, normal_force, branch, axis=2):
    """Per-class statistics of the contacts given (typically the
    force-bearing particle-particle contacts of one snapshot).

    Parameters
    ----------
    labels : array_like, shape (C,)
        The class of each contact.
    normal_force : array_like, shape (C,)
        N, normal force magnitudes.
    branch : array_like, shape (C, 3)
        m, branch vectors (their sign does not matter).
    axis : int, str or array_like of shape (3,), optional
        The compression axis (default z).

    Returns
    -------
    dict
        {label: dict} with ``count``; ``fraction`` (of the contacts given);
        ``mean_force_ratio`` (class mean of f_n over the overall mean);
        ``force_share`` (class sum of f_n over the total); ``fabric_a``, the
        class's signed branch-vector anisotropy (5/2)(F_3 - F_1) with F the
        class fabric tensor, i.e. the mean of (5/4)(3 u^2 - 1), u the cosine
        to the axis: positive when the class leans towards the compression
        axis, negative towards the lateral (minor principal) directions;
        ``fabric_a_se`` its standard error (sample variance over the class;
        NaN for one contact).

    Examples
    --------
    >>> import numpy as np
    >>> from postproc.pertype import class_statistics
    >>> labels = np.array(["FF", "VF", "VF", "EE"])
    >>> fn = np.array([10.0, 3.0, 4.0, 1.0])
    >>> branch = np.array([[0, 0, 0.05], [0.05, 0, 0], [0, 0.05, 0], [0.03, 0, 0.04]])
    >>> st = class_statistics(labels, fn, branch)
    >>> print(st["FF"]["fabric_a"], st["VF"]["fabric_a"], round(st["EE"]["fabric_a"], 4))
    2.5 -1.25 1.15
    >>> print(round(st["FF"]["mean_force_ratio"], 4), st["VF"]["fraction"])
    2.2222 0.5
    """
    labels = np.asarray(labels)
    fn = np.asarray(normal_force, float)
    g = axial_leaning(branch, axis)     # contribution of one contact to a
    total, mean = fn.sum(), fn.mean()
    out = {}
    for k in np.unique(labels):
        sel = labels == k
        n = int(sel.sum())
        out[str(k)] = {
            "count": n,
            "fraction": n / len(labels),
            "mean_force_ratio": float(fn[sel].mean() / mean) if mean > 0 else np.nan,
            "force_share": float(fn[sel].sum() / total) if total > 0 else np.nan,
            "fabric_a": float(g[sel].mean()),
            "fabric_a_se": float(g[sel].std(ddof=1) / np.sqrt(n)) if n > 1 else np.nan,
        }
    return out


def class_columns(stats, classes, prefix):
    """The summary's per-class columns of :func:`class_statistics`, a class
    without a contact given its empty values.

    Parameters
    ----------
    stats : dict
        :func:`class_statistics`' result.
    classes : sequence of str
        The classes to write, present or not.
    prefix : str
        The columns' prefix, e.g. ``"ct_"``.

    Returns
    -------
    dict
        For each k of ``classes``, in this order: ``{prefix}frac_{k}``,
        ``{prefix}fratio_{k}``, ``{prefix}fshare_{k}``, ``{prefix}fabric_{k}``
        and ``{prefix}fabric_{k}_se``; an absent class has 0 for its fraction
        and force share, NaN for the others.

    Examples
    --------
    >>> import numpy as np
    >>> st = class_statistics(np.array(["FF", "VF"]), np.array([3.0, 1.0]), np.array([[0, 0, 1.0], [1.0, 0, 0]]))
    >>> row = class_columns(st, ("FF", "EE"), "ct_")
    >>> print(row["ct_frac_FF"], row["ct_fshare_FF"], row["ct_frac_EE"], row["ct_fabric_EE"])
    0.5 0.75 0.0 nan
    """
    row = {}
    for k in classes:
        d = stats.get(k)
        row[f"{prefix}frac_{k}"] = d["fraction"] if d else 0.0
        row[f"{prefix}fratio_{k}"] = d["mean_force_ratio"] if d else np.nan
        row[f"{prefix}fshare_{k}"] = d["force_share"] if d else 0.0
        row[f"{prefix}fabric_{k}"] = d["fabric_a"] if d else np.nan
        row[f"{prefix}fabric_{k}_se"] = d["fabric_a_se"] if d else np.nan
    return row


def stress_contributions(partials, p, axis=2):
    """The shares of the mean stress and of the axial deviator carried by each
    class (seed eq. 2 split by class).

    Parameters
    ----------
    partials : dict
        {label: ndarray (3, 3)}, Pa, from :func:`partial_stresses`.
    p : float
        Pa, the total mean stress, compression positive.
    axis : int, str or array_like of shape (3,), optional
        The compression axis (default z).

    Returns
    -------
    dict
        {label: (p_k / p, q_k / p)} with q_k = (sigma_aa - mean lateral)/3 of
        the class's partial stress, signed (negative where the class resists
        the lateral stress more than the axial one). Both are linear in the
        stress, so over all classes they sum to 1 and to the total
        q_axial / p; (NaN, NaN) when p is 0.

    Examples
    --------
    >>> import numpy as np
    >>> from postproc.pertype import partial_stresses, stress_contributions
    >>> labels = np.array(["FF", "VF", "wall"])
    >>> force = np.array([[0, 0, 10.0], [3.0, 0, 0], [0, 0, -2.0]])
    >>> arm = np.array([[0, 0, 0.05], [0.05, 0, 0], [0, 0, -0.02]])
    >>> parts = partial_stresses(labels, force, arm, 1e-3)
    >>> p = np.trace(sum(parts.values())) / 3
    >>> print({k: tuple(round(float(x), 4) for x in v) for k, v in stress_contributions(parts, p).items()})
    {'FF': (0.7246, 0.7246), 'VF': (0.2174, -0.1087), 'wall': (0.058, 0.058)}
    """
    e = axis_vector(axis)
    out = {}
    for k, s in partials.items():
        sym = 0.5 * (s + s.T)
        s_aa = e @ sym @ e
        pk = np.trace(sym) / 3.0
        qk = (s_aa - (np.trace(sym) - s_aa) / 2.0) / 3.0
        out[k] = (pk / p, qk / p) if p else (np.nan, np.nan)
    return out
