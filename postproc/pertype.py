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
    """{label: (3, 3) Pa} partial stresses sigma_k = (1/V) sum_{c in k} f (x) arm
    (seed eq. 2 restricted to class k). They sum to the total stress over all
    contacts exactly (up to round-off), because every contact has one label.

    labels (C,); force (C, 3) N; arm (C, 3) m (branch vector for particle
    pairs, particle-to-contact-point for walls); volume m^3.
    """
    labels = np.asarray(labels)
    return {str(k): contact_stress(force[labels == k], arm[labels == k], volume)
            for k in np.unique(labels)}


def class_statistics(labels, normal_force, branch, axis=2):
    """Per-class statistics of the contacts given (typically the force-bearing
    particle-particle contacts of one snapshot).

    labels (C,); normal_force (C,) N, magnitudes; branch (C, 3) m.
    Returns {label: dict} with ``fraction`` (of the contacts given),
    ``mean_force_ratio`` (class mean of f_n over the overall mean),
    ``force_share`` (class sum of f_n over the total), ``fabric_a`` (signed
    branch-vector anisotropy of the class, (5/2)(F_3 - F_1) with F the
    class fabric tensor: negative when the class leans towards the lateral,
    minor principal directions) and its standard error ``fabric_a_se``
    (sqrt(5/4 / n) would hold for an isotropic class; here the sample
    variance of (15/4)(u^2 - 1/3) is used).
    """
    labels = np.asarray(labels)
    fn = np.asarray(normal_force, float)
    L = np.asarray(branch, float)
    e = axis_vector(axis)
    u = (L @ e) / np.linalg.norm(L, axis=1)
    g = 1.25 * (3 * u * u - 1)          # contribution of one contact to a
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


def stress_contributions(partials, p, axis=2):
    """{label: (p_k / p, q_k / p)}: the share of the mean stress and of the
    signed axial deviator q = (sigma_aa - mean lateral)/3 carried by each
    class. Both are linear in the stress, so over all classes they sum to 1
    and to the total q_axial / p (seed eq. 2 split by class).

    partials {label: (3, 3) Pa} from :func:`partial_stresses`; p the total
    mean stress, Pa, compression positive; axis the compression axis.
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
