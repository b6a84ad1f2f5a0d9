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
    """(C,) bool: f_n > <f_n>, the strong network. normal_force (C,) N,
    compression positive. Raises InputError for no contacts or a NaN."""
    fn = np.asarray(normal_force, float)
    if fn.size == 0:
        raise InputError("no contacts to split into strong and weak networks")
    if not np.all(np.isfinite(fn)):
        raise InputError(f"normal force is not finite at contact {int(np.flatnonzero(~np.isfinite(fn))[0])}")
    return fn > fn.mean()


def network_statistics(normal_force, branch, force, axis=2, labels=None, classes=(),
                       errors=False):
    """Anisotropies and composition of the strong and weak networks.

    normal_force (C,) N; branch (C, 3) m; force (C, 3) N; axis the
    compression axis (index or unit vector); labels (C,) contact classes
    (optional) and ``classes`` the class names to report.

    Returns {"strong": dict, "weak": dict}, each with ``fraction`` (of the
    contacts), ``force_share`` (of the summed normal force), the
    anisotropies ``a``, ``a_n``, ``a_t`` (and ``a_l``) of the network alone
    (seed eqs. 5-7 restricted to it; :func:`postproc.fabric.anisotropies`)
    and, for each class k, ``frac_<k>``: the share of the network's contacts
    that are of class k. A network with fewer than 2 contacts gets NaN
    anisotropies.
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

    normal_force (C,) N (> 0 for force-bearing contacts); ``mean`` the <f_n>
    to normalise by (default their own mean: give the mean over all
    contacts to compare the classes of one packing). ``bins`` are
    edges in units of <f_n>; by default 30 logarithmic bins from the
    smallest to the largest value, as for a log-log plot.
    Returns (centres (K,), density (K,)): counts / (n width) with n all the
    values given, so the density integrates to the fraction of values
    inside the bins (1 with the default bins); empty bins give 0.
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
