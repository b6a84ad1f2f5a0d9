"""Throughput of the contact-type classification (postproc.contacttypes).

    python benchmarks/bench_contact_types.py [--contacts N] [--library LIB.h5]

Random pairs of grains of the shape library (``make shapes``) with random
orientations and random normals; prints contacts/s (best of 3) and the
proportions of each pair type at theta/2, theta and 2 theta.
"""
import argparse
import time

import numpy as np

from postproc import contacttypes
from postproc.contacttypes import DEFAULT_THETA_DEG, PAIR_TYPES, classify_contacts, shape_tables
from shapes.library import ShapeLibrary


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--contacts", type=int, default=1_000_000)
    ap.add_argument("--library", default="runs/shapes/library.h5")
    args = ap.parse_args()
    lib = ShapeLibrary(args.library)
    tables = shape_tables(*zip(*[lib[s] for s in range(len(lib))]))
    rng = np.random.default_rng(0)
    N = args.contacts
    s1, s2 = rng.integers(len(lib), size=N), rng.integers(len(lib), size=N)
    q1, q2 = rng.normal(size=(N, 4)), rng.normal(size=(N, 4))
    n = rng.normal(size=(N, 3))
    n /= np.linalg.norm(n, axis=1)[:, None]
    for threads in (1, contacttypes._THREADS):
        contacttypes._THREADS = threads
        best = np.inf
        for _ in range(3):
            t = time.perf_counter()
            classify_contacts(tables, s1, s2, q1, q2, n)
            best = min(best, time.perf_counter() - t)
        print(f"{N} contacts, {len(lib)} shapes, {threads} thread(s): {best:.2f} s, "
              f"{N / best:.3g} contacts/s")
    for theta in (DEFAULT_THETA_DEG / 2, DEFAULT_THETA_DEG, 2 * DEFAULT_THETA_DEG):
        _, _, pair = classify_contacts(tables, s1[:100_000], s2[:100_000], q1[:100_000], q2[:100_000],
                                       n[:100_000], theta)
        frac = np.bincount(pair, minlength=6) / len(pair)
        print(f"theta {theta:4.1f} deg (random orientations): " +
              ", ".join(f"{t} {f:.4f}" for t, f in zip(PAIR_TYPES, frac)))


if __name__ == "__main__":
    main()
