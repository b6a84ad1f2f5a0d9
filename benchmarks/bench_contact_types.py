"""Throughput of the contact-type classification.

    python benchmarks/bench_contact_types.py [--contacts N] [--library LIB.h5] [--dump RUN.h5]

Angular criterion (postproc.contacttypes): random pairs of grains of the
shape library (``make shapes``) with random orientations and random
normals; prints contacts/s (best of 3). (The proportions of each pair type
of such pairs, the geometric chance, are ``postproc investigate random-types``.)

Footprint criterion (postproc.classify, the default), with ``--dump`` (a
kernel S1 dump): the last snapshot's contacts repeated up to N contacts,
classified from the dumped footprint (the groups alone, and the whole
classification with the feature labels and the half/double-threshold
variants), then from footprints recomputed from the shapes and poses
(``shapes.overlap.batch_overlap``, on the snapshot's own contacts, one and
all threads). Medians of 5.
"""
import argparse
import time

import numpy as np

from postproc import contacttypes
from postproc.contacttypes import classify_contacts, shape_tables
from shapes.library import ShapeLibrary


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--contacts", type=int, default=1_000_000)
    ap.add_argument("--library", default="runs/shapes/library.h5")
    ap.add_argument("--dump", help="kernel S1 dump for the footprint criterion")
    args = ap.parse_args()
    if args.dump:
        footprint_bench(args.dump, args.contacts)
        return
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


def _median_time(fn, k=5):
    ts = []
    for _ in range(k):
        t = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t)
    return float(np.median(ts))


def footprint_bench(path, N):
    import os

    from postproc.classify import Classifier
    from postproc.contactset import lookup
    from postproc.footprint import footprint_groups, pair_size, relative_extents, recompute
    from postproc.schema import DumpReader

    with DumpReader(path) as r:
        shapes = r.shapes()
        snap = r.read(len(r) - 1)
    if snap.footprint is None:
        raise SystemExit(f"{path}: no dumped footprint (not a kernel run)")
    i1, i2 = lookup(snap.id1, snap.body_ids), lookup(snap.id2, snap.body_ids)
    pp = (i1 >= 0) & (i2 >= 0)
    C = int(pp.sum())
    reps = max(1, N // C)
    keep = np.tile(np.flatnonzero(pp), reps)
    for name in ("id1", "id2", "point", "force", "force_normal", "normal", "overlap", "footprint",
                 "footprint_area"):
        setattr(snap, name, getattr(snap, name)[keep])
    M = len(keep)
    cl = Classifier(shapes)
    d = pair_size(snap.sizes[i1[keep]], snap.sizes[i2[keep]])
    t = _median_time(lambda: footprint_groups(relative_extents(snap.footprint, d)))
    print(f"footprint groups alone (dumped footprint, {M} contacts): {t * 1e3:.1f} ms, {M / t:.3g} contacts/s")
    t = _median_time(lambda: cl.classify(snap, variants=False))
    print(f"whole classification, dumped footprint (types VV..FF, checks, lookup): {t:.2f} s, "
          f"{M / t:.3g} contacts/s")
    t = _median_time(lambda: cl.classify(snap, variants=True))
    print(f"  the same with the t/2 and 2t variants: {t:.2f} s, {M / t:.3g} contacts/s")
    a, b = i1[pp], i2[pp]
    args = (cl.geometry, snap.shape_index[a], snap.positions[a], snap.orientations[a],
            snap.shape_index[b], snap.positions[b], snap.orientations[b])
    for threads in (1, os.cpu_count() or 1):
        t = _median_time(lambda: recompute(*args, threads=threads))
        print(f"recomputing the footprint ({C} touching pairs of the snapshot, {threads} thread(s)): "
              f"{t * 1e3:.1f} ms, {C / t:.3g} contacts/s")
    small = DumpReader(path)
    s = small.read(len(small) - 1)
    small.close()
    s.footprint = None
    t = _median_time(lambda: cl.classify(s, variants=True))
    print(f"whole classification with recomputation ({len(s.id1)} contacts incl. walls): {t * 1e3:.1f} ms, "
          f"{C / t:.3g} particle contacts/s")


if __name__ == "__main__":
    main()
