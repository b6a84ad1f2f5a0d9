"""The cost of LMGC90's count against the earlier band count, per contact.

    python benchmarks/bench_lmgc90.py DUMP.h5 SNAPSHOT

The classifier's cost per contact of ``lmgc90``, ``lmgc90-planplan``,
``lmgc90-2009`` and ``commonplane`` on that snapshot of the dump (an index; negative from the
end), in one run, as the median of 3 repetitions each, and their ratios.
(Their agreement with LMGC90's compiled code is ``postproc
investigate lmgc90-agreement``.)
"""
import argparse
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from postproc.classify import Classifier  # noqa: E402
from postproc.schema import DumpReader  # noqa: E402


def speed(dump, which):
    with DumpReader(dump) as r:
        shapes = r.shapes()
        snap = r.read(int(which) % len(r))
    cost = {}
    for m in ("commonplane", "lmgc90", "lmgc90-planplan", "lmgc90-2009"):
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
    for m in ("lmgc90", "lmgc90-planplan", "lmgc90-2009"):
        print(f"ratio {m} / commonplane: {cost[m] / cost['commonplane']:.2f}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dump")
    ap.add_argument("snapshot")
    a = ap.parse_args()
    speed(a.dump, a.snapshot)


if __name__ == "__main__":
    main()
