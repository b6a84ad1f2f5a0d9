"""Throughput of the postproc analysis on synthetic contacts.

Run by hand (``make bench`` or ``python benchmarks/bench_analysis.py``);
the figures go into docs/measurements.md. Timings are the best of ``--repeat`` runs.

Measured paths, for N contacts already in memory:
  core      stress (sum f (x) l / V) + the four tensor anisotropies + sff,
            with standard errors (the default of ``postproc analyze``)
  core-nose the same without standard errors
  snapshot  the whole per-snapshot analysis from a Snapshot: id -> row
            lookup and input checks, three stress forms, anisotropies with
            errors, binned functions and fits, coordination, rattlers
"""
import argparse
import time

import numpy as np

from postproc.analysis import analyze_snapshot
from postproc.fabric import anisotropies, stress_force_fabric
from postproc.schema import Snapshot
from postproc.stress import contact_stress, invariants
from postproc.synthetic import harmonic_contacts


def core(branch, force, volume, errors):
    sigma = contact_stress(force, branch, volume)
    inv = invariants(sigma)
    an = anisotropies(branch, force, 2, errors=errors)
    return inv["q_over_p"], stress_force_fabric(an["a"], an["a_l"], an["a_n"], an["a_t"])


def best_of(fn, repeat):
    best = np.inf
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--contacts", type=int, default=1_000_000)
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    N = args.contacts
    s = harmonic_contacts(N, 0.3, 0.1, 0.5, 0.2, seed=0)
    snap = Snapshot(name="000000", step=0, time=0.0, stage="shear", volume=s.volume,
                    box_lo=np.zeros(3), box_hi=np.ones(3), wall_ids=np.arange(6) + 2 * N,
                    wall_forces=None, body_ids=np.concatenate([s.id1, s.id2]),
                    positions=np.concatenate([s.x1, s.x2]), id1=s.id1, id2=s.id2,
                    point=s.point, force=s.force)
    rows = [
        ("core (stress + a, a_l, a_n, a_t + sff, with s.e.)",
         best_of(lambda: core(s.branch, s.force, s.volume, True), args.repeat)),
        ("core without standard errors",
         best_of(lambda: core(s.branch, s.force, s.volume, False), args.repeat)),
        ("whole snapshot analysis (checks, 3 stresses, fits, z)",
         best_of(lambda: analyze_snapshot(snap), args.repeat)),
    ]
    print(f"{N} contacts, best of {args.repeat}")
    for name, t in rows:
        print(f"{name:55s} {t * 1e3:8.1f} ms  {N / t:10.3g} contacts/s")


if __name__ == "__main__":
    main()
