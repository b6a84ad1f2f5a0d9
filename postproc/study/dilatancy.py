"""The peak of shear strength and the dilatancy angle there.

Per run (one seed), from its snapshot series during shear:

* the peak: the largest q/p over the shear snapshots (seed Fig. 3 shows q/p
  rising to a peak, then a plateau; the plateau is
  :func:`postproc.study.claims.plateau`);
* the dilatancy angle psi at the peak, from the volume change against the
  deviatoric strain (seed eq. 3 for eps_v, eps_q):

      sin psi = - d eps_v / d eps_q

  with eps_v compression positive, so a dilating sample (eps_v decreasing)
  has psi > 0. The slope is a least-squares line of eps_v against eps_q over
  the shear snapshots within ``half_window`` snapshots of the peak (snapshots
  are a few 1e-3 of strain apart, and a two-point difference of eps_v is
  noisy at that spacing).
"""
from __future__ import annotations

import numpy as np

from ..errors import InputError


def peak_index(q_over_p, stage):
    """Row of the largest q/p among the shear rows.

    q_over_p (S,) ; stage (S,) str. Raises InputError when no shear row has
    a finite q/p.
    """
    qp = np.asarray(q_over_p, float)
    shear = (np.asarray(stage).astype(str) == "shear") & np.isfinite(qp)
    if not shear.any():
        raise InputError("no shear snapshot with a finite q/p: no peak")
    rows = np.flatnonzero(shear)
    return int(rows[np.argmax(qp[rows])])


def dilatancy_angle(eps_q, eps_v, stage, at, half_window=2):
    """Dilatancy angle psi (degrees) at row ``at``: sin psi = -d eps_v/d eps_q.

    eps_q, eps_v (S,) strains (compression positive; eps_v = eps_1 + eps_2 +
    eps_3); stage (S,) str; at : row index (e.g. :func:`peak_index`). The
    slope is fitted over the shear rows within ``half_window`` rows of ``at``
    (at least 2 rows with distinct eps_q, else NaN). |slope| > 1 (no angle)
    gives NaN.
    """
    eq = np.asarray(eps_q, float)
    ev = np.asarray(eps_v, float)
    if eq.shape != ev.shape:
        raise InputError(f"eps_q has shape {eq.shape} but eps_v {ev.shape}")
    shear = np.flatnonzero((np.asarray(stage).astype(str) == "shear") & np.isfinite(eq) & np.isfinite(ev))
    near = shear[np.abs(shear - int(at)) <= half_window]
    if len(near) < 2 or np.ptp(eq[near]) <= 0:
        return float("nan")
    slope = np.polyfit(eq[near], ev[near], 1)[0]
    if abs(slope) > 1:
        return float("nan")
    return float(np.degrees(np.arcsin(-slope)))


def peak_summary(df, half_window=2):
    """(peak q/p, eps_q at the peak, dilatancy angle at the peak in degrees)
    of one run's summary table (columns q_over_p, eps_q, eps_v, stage);
    NaNs when it has no shear snapshot."""
    try:
        k = peak_index(df["q_over_p"], df["stage"])
    except InputError:
        return float("nan"), float("nan"), float("nan")
    psi = dilatancy_angle(df["eps_q"], df["eps_v"], df["stage"], k, half_window)
    return float(df["q_over_p"].iloc[k]), float(df["eps_q"].iloc[k]), psi
