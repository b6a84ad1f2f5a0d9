"""Reading a flat contact table (``postproc.tables``): its two paths
against pandas' own parse of the same file.

    python benchmarks/bench_tables.py [--rows 200000] [--repeat 7]

Writes a synthetic CSV table of ``--rows`` contacts (14 columns, floats to
the bit) twice: plain, which ``read_contact_table`` parses with pandas' C
parser after its line checks, and with one quoted header name, which sends
it through the strict csv-module reader. Times, in alternation so that a
drift of the shared machine hits all alike, ``pandas.read_csv`` of the
plain file (the floor: the parse with no check), and ``read_contact_table``
of each file; prints each one's median of ``--repeat`` runs and its ratio
to pandas'. Both files must give the same snapshot, to the bit.
"""
from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time

import numpy as np
import pandas as pd

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from postproc.tables import read_contact_table  # noqa: E402


def write_tables(folder, rows, seed=1):
    """The plain and the quoted-header CSV files of ``rows`` contacts."""
    rng = np.random.default_rng(seed)
    x = rng.random((rows, 3))
    ids = np.arange(rows)
    df = pd.DataFrame({"id1": ids, "id2": ids + rows, "x1": x[:, 0], "y1": x[:, 1], "z1": x[:, 2],
                       "x2": x[:, 0] + 1, "y2": x[:, 1], "z2": x[:, 2], "cx": x[:, 0] + 0.5, "cy": x[:, 1],
                       "cz": x[:, 2], "fx": rng.random(rows), "fy": rng.random(rows), "fz": rng.random(rows)})
    plain, quoted = os.path.join(folder, "plain.csv"), os.path.join(folder, "quoted.csv")
    df.to_csv(plain, index=False, float_format="%.17g")
    with open(plain) as fh, open(quoted, "w") as out:
        out.write(fh.readline().replace("fz", '"fz"'))
        out.write(fh.read())
    return plain, quoted


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rows", type=int, default=200_000)
    ap.add_argument("--repeat", type=int, default=7)
    args = ap.parse_args(argv)
    if args.rows < 1 or args.repeat < 1:
        ap.error("--rows and --repeat must be at least 1")
    with tempfile.TemporaryDirectory() as tmp:
        plain, quoted = write_tables(tmp, args.rows)
        a, = read_contact_table(plain, volume=1.0)
        b, = read_contact_table(quoted, volume=1.0)
        for f in ("id1", "id2", "positions", "point", "force"):
            if not np.array_equal(getattr(a, f), getattr(b, f)):
                sys.exit(f"bench_tables: the two paths read {f} differently")
        jobs = {"pandas.read_csv (no checks)": lambda: pd.read_csv(plain),
                "read_contact_table, plain (fast path)": lambda: read_contact_table(plain, volume=1.0),
                "read_contact_table, quoted (strict path)": lambda: read_contact_table(quoted, volume=1.0)}
        times = {k: [] for k in jobs}
        for _ in range(args.repeat):
            for k, job in jobs.items():
                t0 = time.perf_counter()
                job()
                times[k].append(time.perf_counter() - t0)
    floor = statistics.median(times["pandas.read_csv (no checks)"])
    print(f"{args.rows} rows, medians of {args.repeat} alternating runs; the two paths give the same snapshot")
    for k, ts in times.items():
        m = statistics.median(ts)
        print(f"  {k:42s} {m:7.3f} s  {m / floor:5.2f} x pandas")
    return 0


if __name__ == "__main__":
    sys.exit(main())
