"""LMGC90's counts of another git revision beside today's, on the same snapshot.

    python benchmarks/lmgc90_vs_revision.py DUMP.h5 [--rev e756948] [--snapshot 0]
        [--routes lmgc90 lmgc90-2009] [--repeat 3]

Takes ``postproc`` and ``shapes`` as they were at ``--rev`` (``git archive``)
into a temporary folder and runs, in a fresh process for each code and each
repetition (alternating, the revision first), the classifier of each route
on one snapshot of a polyhedra dump as an analysis runs it: with its band
test, i.e. at the alert distance, its half and its double. The shape tables
are built before the clock starts. Reports per route the median time of
each code, their ratio, and whether every output of the counts (points,
gaps, normals, stages, features, groups, pair types; arrays compared byte
for byte, dtype and shape included) is the same.
"""
from __future__ import annotations

import argparse
import os
import pickle
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def worker(root, dump, snapshot, route, out):
    """In this process, with the code of ``root``: count the snapshot with
    the route's classifier (band test included), record every output of
    the LMGC90 counts into ``out`` (pickle) and print the seconds taken."""
    sys.path.insert(0, root)
    try:                                        # LMGC90's count: its own module since the split
        from postproc import lmgc90count as cpl
    except ImportError:                         # of postproc/commonplane.py; before, there
        from postproc import commonplane as cpl
    from postproc.classify import Classifier
    from postproc.schema import DumpReader

    with DumpReader(dump) as r:
        shapes = r.shapes()
        snap = r.read(int(snapshot) % len(r))
    clf = Classifier(shapes, route)
    clf.lmgc90_tables                                            # built before the clock starts
    name = "lmgc90_points_alerts" if hasattr(cpl, "lmgc90_points_alerts") else "lmgc90_points"
    orig, got = getattr(cpl, name), []

    def record(*a, **k):
        res = orig(*a, **k)
        got.extend(res if isinstance(res, list) else [res])
        return res
    setattr(cpl, name, record)
    t0 = time.perf_counter()
    cl = clf.classify(snap, variants=True)
    dt = time.perf_counter() - t0
    with open(out, "wb") as fh:
        pickle.dump(got, fh)
    print(f"{dt:.6f} {int(cl.poly.sum())}")


def differences(a, b):
    """How many outputs of two records differ (byte for byte)."""
    import numpy as np

    if len(a) != len(b):
        return max(len(a), len(b))
    bad = 0
    for x, y in zip(a, b):
        if sorted(x) != sorted(y):
            bad += 1
            continue
        for k in x:
            u, v = (x[k], y[k]) if k in ("xyz", "gaps") else ([x[k]], [y[k]])
            if len(u) != len(v):
                bad += 1
                continue
            for p, q in zip(u, v):
                p, q = np.asarray(p), np.asarray(q)
                bad += int(p.dtype != q.dtype or p.shape != q.shape or p.tobytes() != q.tobytes())
    return bad


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dump")
    ap.add_argument("--rev", default="e756948")
    ap.add_argument("--snapshot", default="0")
    ap.add_argument("--routes", nargs="+", default=["lmgc90", "lmgc90-2009"])
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--worker", nargs=2, metavar=("ROOT", "OUT"), help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a.worker:
        worker(a.worker[0], os.path.abspath(a.dump), a.snapshot, a.routes[0], a.worker[1])
        return
    import numpy as np

    with tempfile.TemporaryDirectory() as tmp:
        old = os.path.join(tmp, "rev")
        os.makedirs(old)
        arch = subprocess.run(f"git -C {ROOT} archive {a.rev} postproc shapes | tar -x -C {old}",
                              shell=True, capture_output=True, text=True)
        if arch.returncode != 0:
            raise SystemExit(f"lmgc90_vs_revision: cannot take postproc and shapes at {a.rev}: "
                             f"{arch.stderr.strip()}")
        for route in a.routes:
            times = {"rev": [], "today": []}
            outs = {}
            n = None
            for rep in range(a.repeat):
                for tag, root in (("rev", old), ("today", ROOT)):
                    out = os.path.join(tmp, f"{tag}-{route}-{rep}.pkl")
                    p = subprocess.run([sys.executable, __file__, a.dump, "--snapshot", a.snapshot, "--routes",
                                        route, "--worker", root, out], capture_output=True, text=True)
                    if p.returncode != 0:
                        raise SystemExit(f"lmgc90_vs_revision: the {tag} code failed on {route}: "
                                         f"{p.stderr.strip().splitlines()[-1] if p.stderr.strip() else p.returncode}")
                    dt, n = p.stdout.split()
                    times[tag].append(float(dt))
                    if rep == 0:
                        with open(out, "rb") as fh:
                            outs[tag] = pickle.load(fh)
            t_rev, t_now = float(np.median(times["rev"])), float(np.median(times["today"]))
            bad = differences(outs["rev"], outs["today"])
            print(f"{route}: {n} contacts x {len(outs['today'])} alert distances; {a.rev} {t_rev:.2f} s, "
                  f"today {t_now:.2f} s (medians of {a.repeat}): {t_rev / t_now:.2f}x; "
                  + ("every output the same, byte for byte" if not bad else f"{bad} outputs differ"), flush=True)


if __name__ == "__main__":
    main()
