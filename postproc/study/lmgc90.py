"""Our counts against LMGC90's compiled code, on the committed fixtures.

    postproc investigate lmgc90-agreement [--out runs/lmgc90] [--fixtures tests/data/lmgc90]

(:func:`write_agreement`.) For every packing fixture of tests/data/lmgc90
(``packing-*.npz``: a snapshot of a 1000-grain
S1 dump with LMGC90's interactions at two alert distances, both point-stage
routes; made by tests/data/lmgc90/make_fixtures.py) and every route, the
number of contact points of each grain pair by ``lmgc90_points`` against
LMGC90's: pairs compared (every pair LMGC90 finds and every dumped
contact), the share with equal counts (all, dumped contacts), and the group
proportions simple / double / triple of the dumped contacts (0 or 1 point
simple, 2 double, 3-4 triple) by LMGC90 and by us. The earlier band count
(``--types commonplane``, tau = 0.1, started from the dumped normal) is
compared with LMGC90's default route on the same dumped contacts. Writes
OUT/lmgc90_agreement.csv and .md. (The cost of the counts per contact is
timed by ``benchmarks/bench_lmgc90.py``.)
"""
from __future__ import annotations

import collections
import json
import os

import numpy as np
import pandas as pd

from .. import commonplane as cp
from .. import lmgc90count as lmgc
from .. import lmgc90shape as lshape
from ..errors import InputError

#: the committed fixtures, beside the package in a source checkout
FIXTURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "data", "lmgc90")
ROUTES = {"new": "lmgc90", "old": "lmgc90-planplan"}


def groups(counts):
    """The group proportions of a set of contacts by their number of points.

    Parameters
    ----------
    counts : array_like of int, shape (C,)
        Contact points per contact.

    Returns
    -------
    list of float
        [simple, double, triple]: the shares with 0 or 1 point, 2, and 3 or
        more.
    """
    c = np.asarray(counts)
    return [float(np.mean(c <= 1)), float(np.mean(c == 2)), float(np.mean(c >= 3))]


def one(name, fixtures=FIXTURES):
    """Our counts against LMGC90's on one packing fixture.

    Parameters
    ----------
    name : str
        The fixture's file name (``packing-*.npz``).
    fixtures : str
        The folder holding it.

    Returns
    -------
    rows : list of dict
        One per alert distance and route (``lmgc90``, ``lmgc90-planplan``),
        then the earlier band count (``commonplane (tau 0.1)``) against
        LMGC90's default route: snapshot, stage, route, alert_rel_rmin
        (units of the smallest grain radius), alert_m (m), pairs compared,
        equal_all (share of the pairs with equal counts), contacts (the
        dumped ones), equal_contacts, lmgc_groups and our_groups ([simple,
        double, triple] of the dumped contacts, :func:`groups`).
    provenance : dict
        The fixture's provenance (LMGC90's wheel, library hash, detection).
    """
    with np.load(os.path.join(fixtures, name)) as f:
        F = {k: f[k] for k in f.files}
    vo, to = F["shape_vertex_offsets"], F["shape_triangle_offsets"]
    verts = [F["shape_vertices"][vo[i]:vo[i + 1]] for i in range(len(vo) - 1)]
    tris = [F["shape_triangles"][to[i]:to[i + 1]] for i in range(len(to) - 1)]
    tables = lshape.lmgc90_tables(verts, tris)
    row = {s: k for k, s in enumerate(F["shape_rows"])}
    srow = np.array([row[s] for s in F["shape_index"]])
    x, q = F["positions"], F["orientations"]
    idx = {int(i): k for k, i in enumerate(F["body_ids"])}
    dumped, dumped_rows = [], []
    for j, (a, b) in enumerate(zip(F["contact_id1"], F["contact_id2"])):
        if int(a) in idx and int(b) in idx:
            i1, i2 = idx[int(a)], idx[int(b)]
            dumped.append((min(i1, i2), max(i1, i2)))
            dumped_rows.append((j, i1, i2))
    rows = []
    lmgc_new_default = None
    for ia, alert in enumerate(F["alerts"]):
        for route, name_route in ROUTES.items():
            cnt = collections.Counter(zip((F[f"{route}{ia}_cd"] - 1).tolist(), (F[f"{route}{ia}_an"] - 1).tolist()))
            pairs = sorted(set(cnt) | set(dumped))
            i, k = np.array(pairs).T
            n = lmgc.lmgc90_points(tables, srow[i], x[i], q[i], srow[k], x[k], q[k], float(alert),
                                 route=name_route)["points"]
            ours = dict(zip(pairs, n.tolist()))
            lm_d = [cnt.get(p, 0) for p in dumped]
            us_d = [ours[p] for p in dumped]
            rows.append({"snapshot": str(F["snapshot"]), "stage": str(F["stage"]), "route": name_route,
                         "alert_rel_rmin": float(F["alerts_rel"][ia]), "alert_m": float(alert),
                         "pairs": len(pairs), "equal_all": float(np.mean([ours[p] == cnt.get(p, 0) for p in pairs])),
                         "contacts": len(dumped), "equal_contacts": float(np.mean(np.equal(lm_d, us_d))),
                         "lmgc_groups": groups(lm_d), "our_groups": groups(us_d)})
            if route == "new" and ia == 0:
                lmgc_new_default = lm_d
    # the earlier band count, from the dumped normals, against LMGC90's default route
    planes = cp.plane_tables(verts, tris)
    j, i1, i2 = (np.array(x) for x in zip(*dumped_rows))
    q = F["orientations"]
    old = cp.contact_points(planes, srow[i1], F["positions"][i1], q[i1], srow[i2], F["positions"][i2], q[i2],
                            F["contact_normal"][j])["points"]
    rows.append({"snapshot": str(F["snapshot"]), "stage": str(F["stage"]), "route": "commonplane (tau 0.1)",
                 "alert_rel_rmin": float(F["alerts_rel"][0]), "alert_m": float(F["alerts"][0]),
                 "pairs": len(dumped), "equal_all": float(np.mean(old == np.array(lmgc_new_default))),
                 "contacts": len(dumped), "equal_contacts": float(np.mean(old == np.array(lmgc_new_default))),
                 "lmgc_groups": groups(lmgc_new_default), "our_groups": groups(old)})
    prov = json.loads(str(F["provenance"]))
    return rows, prov


def write_agreement(out="runs/lmgc90", fixtures=FIXTURES):
    """Our counts against LMGC90's on every packing fixture (:func:`one`):
    writes OUT/lmgc90_agreement.csv (one row per fixture, alert and route)
    and OUT/lmgc90_agreement.md (LMGC90's provenance and the table).

    Parameters
    ----------
    out : str
        Output folder (made if missing).
    fixtures : str
        The folder of the ``packing-*.npz`` fixtures (default the committed
        tests/data/lmgc90).

    Returns
    -------
    str
        The text of lmgc90_agreement.md.

    Raises
    ------
    InputError
        No packing fixture in ``fixtures``.
    """
    try:
        names = sorted(f for f in os.listdir(fixtures) if f.startswith("packing-"))
    except OSError as exc:
        raise InputError(f"{fixtures}: {exc.strerror or exc}") from None
    if not names:
        raise InputError(f"{fixtures}: no packing-*.npz fixture")
    os.makedirs(out, exist_ok=True)
    rows, prov = [], None
    for name in names:
        r, prov = one(name, fixtures)
        rows += r
    df = pd.DataFrame(rows)
    df.to_csv(os.path.join(out, "lmgc90_agreement.csv"), index=False)
    fmt = lambda g: " / ".join(f"{x:.2f}" for x in g)  # noqa: E731
    with open(os.path.join(out, "lmgc90_agreement.md"), "w") as fh:
        fh.write(f"LMGC90: {prov['wheel']} (library sha256 {prov['library_sha256'][:12]}), {prov['detection']}, "
                 f"cundall_iter {prov['cundall_iterations']}\n\n")
        fh.write("| snapshot | route | alert (r_min) | pairs | equal counts | contacts | equal | "
                 "LMGC90 s / d / t | ours s / d / t |\n|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            fh.write(f"| {r['snapshot']} ({r['stage']}) | {r['route']} | {r['alert_rel_rmin']:g} | {r['pairs']} | "
                     f"{r['equal_all']:.4f} | {r['contacts']} | {r['equal_contacts']:.4f} | "
                     f"{fmt(r['lmgc_groups'])} | {fmt(r['our_groups'])} |\n")
    with open(os.path.join(out, "lmgc90_agreement.md")) as fh:
        return fh.read()
