"""Rattlers: the queue-driven k-core (postproc.coordination.rattlers) against
the former layer-by-layer peeling, on the two worst and usual cases.

Run by hand: ``python benchmarks/bench_rattlers.py [--old-chain]``; the
figures go into docs/measurements.md. Times are medians of ``--repeat`` runs.

  chain    a 300 000-contact chain (300 001 particles): its 2-core is empty
           and the peeling is 150 000 layers deep, the case that took the
           former code 436 s. The former code is run on it only with
           ``--old-chain`` (about 7 min); by default on a 30 000-contact
           chain, whose time scales as the square of the length.
  packing  1e6 contacts of a random loose packing: points in a box joined
           within a cut-off (mean z about 5), 10 % of the contacts carrying
           no force, so rattlers and dangling arms of all depths exist.
  analyze  ``postproc analyze`` end to end on the 300 000-contact chain as a
           flat CSV table (the slow case before: 7 min 27 s).
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

from postproc.coordination import rattlers


def layered_rattlers(i1, i2, bearing, n, k=2):
    """The former implementation (one layer per pass, cost n x depth)."""
    active = np.asarray(bearing, bool).copy()
    rat = np.zeros(n, bool)
    while True:
        deg = (np.bincount(i1[active & (i1 >= 0)], minlength=n)
               + np.bincount(i2[active & (i2 >= 0)], minlength=n))
        new = (deg < k) & ~rat
        if not new.any():
            return rat
        rat |= new
        gone = ((i1 >= 0) & rat[np.maximum(i1, 0)]) | ((i2 >= 0) & rat[np.maximum(i2, 0)])
        active &= ~gone


def chain(c):
    return np.arange(c), np.arange(1, c + 1), np.ones(c, bool), c + 1


def packing(c, seed=0):
    from scipy.spatial import cKDTree

    rng = np.random.default_rng(seed)
    n = int(c / 2.5)                       # z = 2 C / N = 5
    x = rng.random((n, 3))
    r = (3 * 5 / (4 * np.pi * n)) ** (1 / 3)   # mean neighbours within r: 5
    pairs = cKDTree(x).query_pairs(r, output_type="ndarray")
    pairs = pairs[rng.permutation(len(pairs))[:c]]
    bearing = rng.random(len(pairs)) > 0.1
    return pairs[:, 0], pairs[:, 1], bearing, n


def median_time(fn, repeat):
    ts = []
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        ts.append(time.perf_counter() - t)
    return statistics.median(ts), out


def chain_table(path, c):
    """A valid flat table of a straight chain under tension-free compression:
    unit spheres along x, unit force along the branch."""
    import pandas as pd

    i = np.arange(c)
    x1 = np.stack([i * 1.0, np.zeros(c), np.zeros(c)], 1)
    x2 = x1 + [1.0, 0, 0]
    pd.DataFrame({"id1": i, "id2": i + 1, "x1": x1[:, 0], "y1": 0.0, "z1": 0.0,
                  "x2": x2[:, 0], "y2": 0.0, "z2": 0.0, "cx": x1[:, 0] + 0.5, "cy": 0.0,
                  "cz": 0.0, "fx": 1.0, "fy": 0.0, "fz": 0.0}).to_csv(path, index=False)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--old-chain", action="store_true",
                    help="also run the former code on the 300 000-contact chain (~7 min)")
    ap.add_argument("--no-analyze", action="store_true", help="skip the end-to-end CLI run")
    args = ap.parse_args()
    rows = []

    i1, i2, b, n = chain(300_000)
    t_new, rat = median_time(lambda: rattlers(i1, i2, b, n), args.repeat)
    assert rat.all()
    rows.append(("chain 300 000 contacts", "new", t_new))
    if args.old_chain:
        t_old, ref = median_time(lambda: layered_rattlers(i1, i2, b, n), 1)
        assert np.array_equal(ref, rat)
        rows.append(("chain 300 000 contacts", "old (1 run)", t_old))
    s1, s2, sb, sn = chain(30_000)
    t_old, ref = median_time(lambda: layered_rattlers(s1, s2, sb, sn), 1)
    t_new, rat = median_time(lambda: rattlers(s1, s2, sb, sn), args.repeat)
    assert np.array_equal(ref, rat)
    rows += [("chain 30 000 contacts", "old (1 run)", t_old),
             ("chain 30 000 contacts", "new", t_new)]

    p1, p2, pb, pn = packing(1_000_000)
    t_old, ref = median_time(lambda: layered_rattlers(p1, p2, pb, pn), args.repeat)
    t_new, rat = median_time(lambda: rattlers(p1, p2, pb, pn), args.repeat)
    assert np.array_equal(ref, rat)
    label = f"packing {len(p1)} contacts, {pn} particles ({int(ref.sum())} rattlers)"
    rows += [(label, "old", t_old), (label, "new", t_new), (label, "old/new", t_old / t_new)]

    if not args.no_analyze:
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "chain.csv")
            chain_table(path, 300_000)
            t = time.perf_counter()
            subprocess.run([sys.executable, "-m", "postproc.cli", "analyze", path, "--out",
                            os.path.join(tmp, "out"), "--volume", "300000", "--no-progress"],
                           check=True)
            rows.append(("postproc analyze, chain 300 000 contacts (CSV)", "new, 1 run",
                         time.perf_counter() - t))
    for name, what, t in rows:
        unit = "x" if what == "old/new" else "s"
        print(f"{name:62s} {what:12s} {t:10.3f} {unit}")


if __name__ == "__main__":
    main()
