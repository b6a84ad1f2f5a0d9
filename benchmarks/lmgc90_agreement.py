"""Our counts against LMGC90's compiled code, on the committed fixtures.

    python benchmarks/lmgc90_agreement.py [--out runs/lmgc90] [--speed DUMP.h5 SNAPSHOT]

For every packing fixture of tests/data/lmgc90 (a snapshot of a 1000-grain
S1 dump with LMGC90's interactions at two alert distances, both point-stage
routes; made by tests/data/lmgc90/make_fixtures.py) and every route, the
number of contact points of each grain pair by ``lmgc90_points`` against
LMGC90's: pairs compared (every pair LMGC90 finds and every dumped
contact), the share with equal counts (all, dumped contacts), and the group
proportions simple / double / triple of the dumped contacts (0 or 1 point
simple, 2 double, 3-4 triple) by LMGC90 and by us. The earlier band count
(``--types commonplane``, tau = 0.1, started from the dumped normal) is
compared with LMGC90's default route on the same dumped contacts. Writes
OUT/lmgc90_agreement.csv and .md.

``--speed DUMP SNAPSHOT``: the classifier's cost per contact of
``lmgc90``, ``lmgc90-planplan`` and ``commonplane`` on that snapshot of the
dump, in one run, as the median of 3 repetitions each, and their ratios.
"""
import argparse
import collections
import json
import os
import sys
import time

import numpy as np
import pandas as pd

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from postproc import commonplane as cp  # noqa: E402

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "data", "lmgc90")
ROUTES = {"new": "lmgc90", "old": "lmgc90-planplan"}


def groups(counts):
    c = np.asarray(counts)
    return [float(np.mean(c <= 1)), float(np.mean(c == 2)), float(np.mean(c >= 3))]


def one(name):
    with np.load(os.path.join(HERE, name)) as f:
        F = {k: f[k] for k in f.files}
    vo, to = F["shape_vertex_offsets"], F["shape_triangle_offsets"]
    verts = [F["shape_vertices"][vo[i]:vo[i + 1]] for i in range(len(vo) - 1)]
    tris = [F["shape_triangles"][to[i]:to[i + 1]] for i in range(len(to) - 1)]
    tables = cp.lmgc90_tables(verts, tris)
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
            n = cp.lmgc90_points(tables, srow[i], x[i], q[i], srow[k], x[k], q[k], float(alert),
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


def speed(dump, which):
    from postproc.classify import Classifier
    from postproc.schema import DumpReader
    with DumpReader(dump) as r:
        shapes = r.shapes()
        snap = r.read(int(which) % len(r))
    cost = {}
    for m in ("commonplane", "lmgc90", "lmgc90-planplan"):
        c = Classifier(shapes, m)
        c.classify(snap, variants=False)                   # tables built once, as in an analysis
        ts = []
        for _ in range(3):
            t0 = time.perf_counter()
            cl = c.classify(snap, variants=False)
            ts.append(time.perf_counter() - t0)
        n = int(cl.poly.sum())
        cost[m] = float(np.median(ts)) / n
        print(f"{m:16s} {n} contacts: {cost[m] * 1e3:.2f} ms a contact (median of 3)")
    for m in ("lmgc90", "lmgc90-planplan"):
        print(f"ratio {m} / commonplane: {cost[m] / cost['commonplane']:.2f}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", default="runs/lmgc90")
    ap.add_argument("--speed", nargs=2, metavar=("DUMP", "SNAPSHOT"))
    a = ap.parse_args()
    if a.speed:
        speed(*a.speed)
        return
    os.makedirs(a.out, exist_ok=True)
    rows, prov = [], None
    for name in sorted(f for f in os.listdir(HERE) if f.startswith("packing-")):
        r, prov = one(name)
        rows += r
    df = pd.DataFrame(rows)
    df.to_csv(os.path.join(a.out, "lmgc90_agreement.csv"), index=False)
    fmt = lambda g: " / ".join(f"{x:.2f}" for x in g)
    with open(os.path.join(a.out, "lmgc90_agreement.md"), "w") as fh:
        fh.write(f"LMGC90: {prov['wheel']} (library sha256 {prov['library_sha256'][:12]}), {prov['detection']}, "
                 f"cundall_iter {prov['cundall_iterations']}\n\n")
        fh.write("| snapshot | route | alert (r_min) | pairs | equal counts | contacts | equal | "
                 "LMGC90 s / d / t | ours s / d / t |\n|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            fh.write(f"| {r['snapshot']} ({r['stage']}) | {r['route']} | {r['alert_rel_rmin']:g} | {r['pairs']} | "
                     f"{r['equal_all']:.4f} | {r['contacts']} | {r['equal_contacts']:.4f} | "
                     f"{fmt(r['lmgc_groups'])} | {fmt(r['our_groups'])} |\n")
    print(open(os.path.join(a.out, "lmgc90_agreement.md")).read())


if __name__ == "__main__":
    main()
