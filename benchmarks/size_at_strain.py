"""The study's quantities at several numbers of grains, compared at the same
axial strain: for runs that have not reached their steady state yet (a
5000-grain study under way), or to see where along the shear two sizes part.

    python benchmarks/size_at_strain.py FOLDER [FOLDER ...] [--sample polyhedra] \
        [--bins 0.04 0.075 0.105 0.145] [--out runs/size-at-strain]

Each FOLDER is searched (recursively) for the per-seed analyses of one
sample: folders named ``...<sample>-seed<K>`` (a study's
``analysis-polyhedra-seed1``, or ``postproc analyze RUN.h5 --out DIR``'s
``DIR/polyhedra-seed1``) holding a ``summary.csv`` (one row per snapshot;
the point count's contact types; LMGC90's count, ``...-lmgc90``, is left
out). A partial dump (a run still going) is analysed like any other: copy
``RUN.h5`` and ``RUN.h5.parts`` aside first, then ``postproc analyze``.

Per seed, the shear snapshots with eps_1 in each bin [lo, hi) are averaged;
per number of grains (the summary's ``n_particles``) the table gives the
mean over seeds with the seeds' standard deviation and their number, and
between consecutive numbers of grains the difference with its 95 % Welch
interval (each seed's bin mean one sample; two seeds or more a side). The
bins are of eps_1 (axial strain, compression positive), not eps_q. Writes
OUT/size-at-strain.csv (one row per seed and bin) and OUT/size-at-strain.md
(one table per quantity: rows N, columns the bins).
"""
import argparse
import glob
import os
import re
import sys

import numpy as np
import pandas as pd

from postproc.statistics import difference, plateau_estimate

QUANTITIES = ("q_over_p", "a", "a_l", "a_n", "a_t", "sff_residual", "z", "ct_frac_VF", "ct_frac_EE",
              "ct_frac_FF", "ct_frac_simple", "ct_frac_double")


def per_seed_bins(paths, bins, quantities=QUANTITIES):
    """One row per (summary.csv, bin): N, seed folder, bin, snapshots, and
    the mean of each quantity over that seed's shear snapshots in the bin.
    ``bins`` (B+1,) increasing eps_1 edges."""
    rows = []
    for path in paths:
        d = pd.read_csv(path)
        missing = [c for c in ("stage", "eps_1", "n_particles", *quantities) if c not in d.columns]
        if missing:
            raise ValueError(f"{path}: no column {', '.join(missing)} (not a postproc analyze summary)")
        d = d[d["stage"] == "shear"]
        for lo, hi in zip(bins[:-1], bins[1:]):
            m = d[(d["eps_1"] >= lo) & (d["eps_1"] < hi)]
            if len(m):
                rows.append({"N": int(m["n_particles"].iloc[0]), "seed": os.path.basename(os.path.dirname(path)),
                             "bin": f"{lo:g}-{hi:g}", "snapshots": len(m),
                             **{q: float(m[q].mean()) for q in quantities}})
    return pd.DataFrame(rows)


def differences(per_seed, q):
    """{(N1, N2, bin): Estimate of N2's mean minus N1's} for consecutive N
    (Welch's interval over the seeds' bin means, postproc.statistics)."""
    ns = sorted(per_seed["N"].unique())
    out = {}
    for n1, n2 in zip(ns[:-1], ns[1:]):
        for b in per_seed["bin"].unique():
            v1, v2 = ([[x] for x in per_seed[(per_seed["N"] == n) & (per_seed["bin"] == b)][q]] for n in (n1, n2))
            if len(v1) >= 2 and len(v2) >= 2:
                out[n1, n2, b] = difference(plateau_estimate(v2), plateau_estimate(v1))
    return out


def tables(per_seed, quantities=QUANTITIES):
    """Markdown: per quantity, rows N, columns the bins, 'mean ± sd (n)' over
    seeds; then a row per pair of consecutive N (two seeds or more each):
    the difference with its 95 % Welch interval."""
    out = []
    for q in quantities:
        cell = per_seed.groupby(["N", "bin"])[q].agg(
            lambda x: f"{x.mean():.3f} ± {x.std(ddof=1):.3f} ({len(x)})" if len(x) > 1 else f"{x.mean():.3f} (1)")
        t = cell.unstack("bin")
        diff = differences(per_seed, q)
        pairs = sorted({(n1, n2) for n1, n2, _ in diff})
        out.append(f"### {q}\n\n| N | " + " | ".join(f"eps_1 {b}" for b in t.columns) + " |\n|---|"
                   + "---|" * len(t.columns) + "\n"
                   + "".join(f"| {n} | " + " | ".join(str(v) if isinstance(v, str) else "" for v in t.loc[n])
                             + " |\n" for n in t.index)
                   + "".join(f"| {n2} − {n1} | " + " | ".join(diff[n1, n2, b].text(3) if (n1, n2, b) in diff else ""
                                                            for b in t.columns) + " |\n" for n1, n2 in pairs))
    return "\n".join(out)


def find_summaries(folder, sample):
    pat = re.compile(rf"{sample}-seed\d+$")
    return sorted(p for p in glob.glob(os.path.join(folder, "**", "summary.csv"), recursive=True)
                  if pat.search(os.path.basename(os.path.dirname(p))))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("folders", nargs="+")
    ap.add_argument("--sample", default="polyhedra", choices=("polyhedra", "spheres"))
    ap.add_argument("--bins", type=float, nargs="+", default=[0.04, 0.075, 0.105, 0.145])
    ap.add_argument("--out", default="runs/size-at-strain")
    args = ap.parse_args(argv)
    bins = np.asarray(args.bins)
    if len(bins) < 2 or np.any(np.diff(bins) <= 0):
        print("size_at_strain: --bins must be two or more increasing strains", file=sys.stderr)
        return 2
    paths = []
    for f in args.folders:
        found = find_summaries(f, args.sample)
        if not found:
            print(f"size_at_strain: {f}: no {args.sample}-seed<K>/summary.csv under it", file=sys.stderr)
            return 2
        paths += found
    try:
        per_seed = per_seed_bins(paths, bins)
    except (ValueError, OSError, pd.errors.ParserError) as exc:
        print(f"size_at_strain: {exc}", file=sys.stderr)
        return 2
    if per_seed.empty:
        print("size_at_strain: no shear snapshot falls in the bins", file=sys.stderr)
        return 2
    os.makedirs(args.out, exist_ok=True)
    per_seed.to_csv(os.path.join(args.out, "size-at-strain.csv"), index=False)
    text = tables(per_seed)
    with open(os.path.join(args.out, "size-at-strain.md"), "w") as fh:
        fh.write(f"# {args.sample}: the quantities at the same eps_1, by number of grains\n\n{text}")
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
