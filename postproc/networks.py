"""Strong and weak force networks and the distribution of normal forces.

Pure functions over the arrays of :class:`~postproc.contactset.ContactSet`
(force-bearing particle-particle contacts, unless said). The split follows
Radjai et al. (1998) and the seed paper: a contact belongs to the *strong*
network when its normal force exceeds the mean normal force <f_n> of the
snapshot, to the *weak* one otherwise. Compression positive; forces on id2
by id1, N; branch vectors from id1 to id2, m.
"""
from __future__ import annotations

import numpy as np

from .errors import InputError
from .fabric import anisotropies


def strong_mask(normal_force):
    """The strong network: the contacts whose normal force exceeds the mean.

    Parameters
    ----------
    normal_force : array_like, shape (C,)
        N, normal forces, compression positive.

    Returns
    -------
    ndarray of bool, shape (C,)
        f_n > <f_n>: True in the strong network, False in the weak one.

    Raises
    ------
    InputError
        For no contacts or a force that is not finite.

    Examples
    --------
    >>> from postproc.networks import strong_mask
    >>> print(strong_mask([1.0, 2.0, 3.0, 6.0]))
    [False False False  True]
    """
    fn = np.asarray(normal_force, float)
    if fn.size == 0:
        raise InputError("no contacts to split into strong and weak networks")
    if not np.all(np.isfinite(fn)):
        raise InputError(f"normal force is not finite at contact {int(np.flatnonzero(~np.isfinite(fn))[0])}")
    return fn > fn.mean()


def network_statistics(normal_force, branch, force, axis=2, labels=None, classes=(),
                       errors=False):
    """Anisotropies and composition of the strong and weak networks.

    Parameters
    ----------
    normal_force : array_like, shape (C,)
        N, normal forces, compression positive.
    branch : ndarray, shape (C, 3)
        m, branch vectors x2 - x1.
    force : ndarray, shape (C, 3)
        N, contact forces on id2 by id1.
    axis : int, str or array_like of shape (3,), optional
        The compression axis (default z).
    labels : array_like, shape (C,), optional
        Contact classes (e.g. "VF", "FF").
    classes : sequence of str, optional
        The class names whose share of each network is reported.
    errors : bool, optional
        Also the anisotropies' standard errors (default False).

    Returns
    -------
    dict
        {"strong": dict, "weak": dict}, each with ``fraction`` (of the
        contacts), ``force_share`` (of the summed normal force), the
        anisotropies ``a``, ``a_l``, ``a_n``, ``a_t`` of the network alone
        (seed eqs. 6, 7 and 9 restricted to it, :func:`postproc.fabric.anisotropies`;
        NaN for a network of fewer than 2 contacts) and, for each class k,
        ``frac_<k>``: the share of the network's contacts of class k.

    Examples
    --------
    Four contacts of normal forces 1, 2, 3 and 6 N (mean 3): the last is
    the strong network and carries half the force.

    >>> import numpy as np
    >>> from postproc.networks import network_statistics
    >>> fn = np.array([1.0, 2.0, 3.0, 6.0])
    >>> branch = np.array([[0, 0, 0.02], [0.02, 0, 0], [0, 0.02, 0], [0, 0, 0.02]])
    >>> force = branch / 0.02 * fn[:, None]
    >>> r = network_statistics(fn, branch, force, "z", labels=["FF", "VF", "VF", "FF"], classes=("FF",))
    >>> print(r["strong"]["fraction"], r["strong"]["force_share"], r["strong"]["frac_FF"])
    0.25 0.5 1.0
    >>> print(round(r["weak"]["a_n"], 3), round(r["weak"]["frac_FF"], 3))
    -0.625 0.333
    """
    fn = np.asarray(normal_force, float)
    strong = strong_mask(fn)
    labels = None if labels is None else np.asarray(labels)
    out = {}
    for name, sel in (("strong", strong), ("weak", ~strong)):
        n = int(sel.sum())
        row = {"fraction": n / len(fn), "force_share": float(fn[sel].sum() / fn.sum())}
        if n >= 2:
            an = anisotropies(branch[sel], force[sel], axis, errors=errors)
            row.update({k: an[k] for k in an if k.startswith("a")})
        else:
            row.update({k: np.nan for k in ("a", "a_l", "a_n", "a_t")})
        if labels is not None:
            for k in classes:
                row[f"frac_{k}"] = float(np.mean(labels[sel] == k)) if n else np.nan
        out[name] = row
    return out


def force_pdf(normal_force, mean=None, bins=None):
    """Probability density of the normalised normal force f_n / <f_n>.

    Parameters
    ----------
    normal_force : array_like, shape (C,)
        N, normal forces (only the positive ones are counted).
    mean : float, optional
        N, the <f_n> to normalise by (default their own mean: give the mean
        over all contacts to compare the classes of one packing).
    bins : array_like, optional
        Bin edges in units of <f_n>; by default 30 logarithmic bins from the
        smallest to the largest value, as for a log-log plot.

    Returns
    -------
    centres : ndarray, shape (K,)
        The bins' geometric centres, in units of <f_n>.
    density : ndarray, shape (K,)
        counts / (n width) with n all the values given, so the density
        integrates to the fraction of values inside the bins (1 with the
        default bins); empty bins give 0.

    Raises
    ------
    InputError
        When no normal force is positive.

    Examples
    --------
    >>> import numpy as np
    >>> from postproc.networks import force_pdf
    >>> x, density = force_pdf([1.0, 1.0, 2.0, 4.0], bins=[0.25, 0.75, 1.25, 2.25])
    >>> print(np.round(x, 3), density)
    [0.433 0.968 1.677] [1.   0.5  0.25]
    """
    fn = np.asarray(normal_force, float)
    fn = fn[fn > 0]
    if fn.size == 0:
        raise InputError("no positive normal forces for a force distribution")
    x = fn / (fn.mean() if mean is None else float(mean))
    if bins is None:
        lo, hi = x.min(), x.max()
        bins = np.geomspace(lo, hi * (1 + 1e-12), 31) if hi > lo else np.array([lo * 0.5, lo * 1.5])
    counts, edges = np.histogram(x, bins=bins)
    return np.sqrt(edges[:-1] * edges[1:]), counts / (x.size * np.diff(edges))
