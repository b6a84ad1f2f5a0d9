"""The CD front: Contact Dynamics runs of one state under several solver
settings (time step, NLGS tolerance, relaxation, start), side by side.

Input: CD run folders of ``python -m lmgc90.triaxial`` (or their archived
copies, ``reference_data/cd-front/``), each with ``run.params.json``,
``run.info.json``, ``run.log.csv`` (one row a step: NLGS iterations,
convergence, seconds) and ``analysis/summary.csv`` (``postproc analyze`` of its
dump). Output: one row a run with the steady-window means of the study's
quantities (q/p, eq. 2; a, a_l, a_n, a_t, eqs. a1-a3; z; the CD type counts
off the contact points, :mod:`postproc.cdpoints`) and the solver's cost.
Pure functions over the tables; :func:`read_run` and :func:`write_front` do
the I/O.
"""
from __future__ import annotations

import json
import os

import numpy as np
import pandas as pd

from ..errors import InputError, read_json_object

QUANTITIES = ("q_over_p", "a", "a_l", "a_n", "a_t", "z",
              "cd_alert_frac_simple", "cd_alert_frac_double", "cd_alert_frac_triple",
              "cd_force_frac_simple", "cd_force_frac_double", "cd_force_frac_triple")
SETTINGS = ("dt", "nlgs_tol", "nlgs_relax", "start")


def read_run(folder):
    """A CD run folder's tables: (params dict, info dict, log DataFrame, summary DataFrame).

    Raises
    ------
    InputError
        (one line) naming the missing or unreadable file.
    """
    params = read_json_object(os.path.join(folder, "run.params.json"), "CD run parameters")
    info = read_json_object(os.path.join(folder, "run.info.json"), "CD run info")
    out = []
    for name in ("run.log.csv", os.path.join("analysis", "summary.csv")):
        path = os.path.join(folder, name)
        try:
            out.append(pd.read_csv(path))
        except (OSError, pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as exc:
            raise InputError(f"{path}: not readable as CSV ({exc.__class__.__name__})") from None
    log, summary = out
    for need, table, path in ((("stage", "nlgs_iterations", "converged"), log, "run.log.csv"),
                              (("stage", "eps_1"), summary, "analysis/summary.csv")):
        missing = [c for c in need if c not in table]
        if missing:
            raise InputError(f"{os.path.join(folder, path)}: no column {missing[0]}")
    return params, info, log, summary


def front_row(name, params, info, log, summary, eps_lo=0.1, eps_hi=0.3):
    """One run's row of the front.

    Parameters
    ----------
    name : str
        The run's label.
    params, info : dict
        ``run.params.json`` and ``run.info.json``.
    log : DataFrame
        ``run.log.csv`` (one row a step).
    summary : DataFrame
        ``analysis/summary.csv`` (one row a snapshot).
    eps_lo, eps_hi : float
        The steady window in eps_1 = ln(H0 / H) (the paper's eq. 3), inclusive.

    Returns
    -------
    dict
        The run's settings (:data:`SETTINGS`), ``snapshots`` in the window, the
        window's mean of each of :data:`QUANTITIES` present (NaN otherwise),
        ``iterations`` (mean NLGS iterations a shear step), ``at_cap`` (share
        of shear steps that ended unconverged), ``steps``, ``wall_seconds``
        and ``phi_iso`` (the isotropic solid fraction).

    Examples
    --------
    >>> import pandas as pd
    >>> log = pd.DataFrame({"stage": ["isotropic", "shear", "shear"], "nlgs_iterations": [5, 10, 30],
    ...                     "converged": [1, 1, 0]})
    >>> summ = pd.DataFrame({"stage": ["isotropic", "shear", "shear"], "eps_1": [0.0, 0.1, 0.2],
    ...                      "q_over_p": [0.0, 0.4, 0.6]})
    >>> r = front_row("x", {"dt": 1e-3, "nlgs_tol": 1e-3}, {"steps": 3}, log, summ)
    >>> r["q_over_p"], r["iterations"], r["at_cap"], r["snapshots"]
    (0.5, 20.0, 0.5, 2)
    """
    shear = log[log["stage"] == "shear"]
    win = summary[(summary["stage"] == "shear") & (summary["eps_1"] >= eps_lo - 1e-12)
                  & (summary["eps_1"] <= eps_hi + 1e-12)]
    row = {"run": name, **{k: params.get(k) for k in SETTINGS}, "snapshots": int(len(win))}
    for q in QUANTITIES:
        row[q] = float(win[q].mean()) if q in win and len(win) else float("nan")
    row["iterations"] = float(shear["nlgs_iterations"].mean()) if len(shear) else float("nan")
    row["at_cap"] = float((shear["converged"] == 0).mean()) if len(shear) else float("nan")
    row["steps"] = info.get("steps")
    row["wall_seconds"] = info.get("wall_seconds")
    row["phi_iso"] = info.get("solid_fraction_isotropic")
    return row


def front_table(rows):
    """The front's rows as a DataFrame, in the given order, with each
    quantity's difference from the first row (the reference: the tightest
    setting) as ``d_<quantity>``."""
    df = pd.DataFrame(rows)
    if df.empty:
        raise InputError("no CD runs given")
    for q in QUANTITIES:
        df["d_" + q] = df[q] - df[q].iloc[0]
    return df


def markdown(df):
    """The front as a markdown table (the settings, cost, q/p, anisotropies, z, the two counts)."""
    def f(x, d=3):
        return "–" if x is None or (isinstance(x, float) and not np.isfinite(x)) else f"{x:.{d}f}"
    lines = ["| run | dt (s) | tol | start | NLGS iterations a shear step | shear steps at the cap | q/p | a | a_l | "
             "a_n | a_t | z | every point s / d / t | force-carrying s / d / t |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for _, r in df.iterrows():
        ev = " / ".join(f(r[f"cd_alert_frac_{g}"], 2) for g in ("simple", "double", "triple"))
        fc = " / ".join(f(r[f"cd_force_frac_{g}"], 2) for g in ("simple", "double", "triple"))
        lines.append(f"| {r['run']} | {r['dt']:g} | {r['nlgs_tol']:g} | {r['start']} | {f(r['iterations'], 0)} | "
                     f"{100 * r['at_cap']:.1f} % | {f(r['q_over_p'])} | {f(r['a'])} | {f(r['a_l'])} | {f(r['a_n'])} | "
                     f"{f(r['a_t'])} | {f(r['z'], 2)} | {ev} | {fc} |")
    return "\n".join(lines) + "\n"


def write_front(folders, out, eps_lo=0.1, eps_hi=0.3):
    """Read the run folders (the first is the reference), write
    ``out/cd-front.md`` and ``out/cd-front.csv``; returns the DataFrame."""
    rows = []
    for folder in folders:
        rows.append(front_row(os.path.basename(os.path.normpath(folder)), *read_run(folder), eps_lo=eps_lo,
                              eps_hi=eps_hi))
    df = front_table(rows)
    os.makedirs(out, exist_ok=True)
    df.to_csv(os.path.join(out, "cd-front.csv"), index=False)
    with open(os.path.join(out, "cd-front.md"), "w") as fh:
        fh.write(f"# The CD front (means over eps_1 {eps_lo}-{eps_hi}; the first run is the reference)\n\n")
        fh.write(markdown(df))
    with open(os.path.join(out, "cd-front.json"), "w") as fh:
        json.dump(json.loads(df.to_json(orient="records")), fh, indent=1)
    return df
