"""Command line: ``postproc analyze PATH --out DIR``.

Exit codes: 0 all snapshots analysed; 1 some snapshots were bad (the good
ones are written, the bad ones listed in ``DIR/errors.txt`` and on stderr);
2 nothing could be analysed (bad file or options; nothing written).
"""
from __future__ import annotations

import argparse
import os
import shutil
import sys
import tempfile

import numpy as np

from .errors import InputError
from .schema import DumpFormatError, DumpReader

BAD_INPUT = (InputError, DumpFormatError)


def _open_source(path, volume, box):
    """(count, iterator of Snapshot or exception, close) for a dump or table."""
    ext = os.path.splitext(path)[1].lower()
    if ext in (".csv", ".parquet", ".pq"):
        from .tables import read_contact_table

        snaps = read_contact_table(path, volume=volume, box=box)
        return len(snaps), iter(snaps), lambda: None
    if volume is not None or box is not None:
        raise InputError("--volume and --box are for flat contact tables; a dump has its box")
    reader = DumpReader(path)
    if len(reader) == 0:
        reader.close()
        raise InputError(f"{path}: the dump holds no snapshots")

    def gen():
        for i in range(len(reader)):
            try:
                yield reader.read(i)
            except DumpFormatError as exc:
                yield exc

    return len(reader), gen(), reader.close


def reference_index(stages):
    """The snapshot whose box is zero strain: the last "isotropic" one (the
    state from which shear starts), else the first "shear" one, else 0."""
    iso = [k for k, s in enumerate(stages) if s == "isotropic"]
    if iso:
        return iso[-1]
    return next((k for k, s in enumerate(stages) if s == "shear"), 0)


def analyze_path(path, out, axis="z", volume=None, box=None, nbins=18,
                 errors=True, progress=None):
    """Analyse every snapshot of ``path`` and write ``out/summary.csv`` and
    the figures. Returns (n_good, list of error lines)."""
    import pandas as pd

    from . import plots
    from .analysis import add_strains, analyze_snapshot

    if volume is not None and not (np.isfinite(volume) and volume > 0):
        raise InputError(f"--volume must be finite and > 0, got {volume}")
    try:
        from .axes import axis_vector

        e = axis_vector(axis)
    except ValueError as exc:
        raise InputError(f"--axis: {exc}") from None
    count, snaps, close = _open_source(path, volume, box)
    rows, lengths, stages, last, problems = [], [], [], None, []
    try:
        from tqdm import tqdm

        bar = tqdm(snaps, total=count, unit="snapshot", file=sys.stderr,
                   disable=(count < 5) if progress is None else not progress)
        for snap in bar:
            if isinstance(snap, Exception):
                problems.append(str(snap))
                continue
            try:
                res = analyze_snapshot(snap, axis=e, nbins=nbins, errors=errors)
            except BAD_INPUT as exc:
                problems.append(str(exc) if str(exc).startswith(("snapshot", path))
                                else f"snapshot {snap.name}: {exc}")
                continue
            rows.append(res.row)
            lengths.append(snap.box_lengths)
            stages.append(snap.stage)
            last = (snap, res)
    finally:
        close()
    if not rows:
        raise InputError("no snapshot could be analysed: " + "; ".join(problems[:3]))
    ref = reference_index(stages)
    add_strains(rows, np.array(lengths), lengths[ref], e)
    df = pd.DataFrame(rows)
    lead = ["step", "eps_1", "eps_q", "eps_v", "p", "q", "q_over_p", "a", "a_l",
            "a_n", "a_t", "sff", "sff_residual", "z", "n_contacts"]
    df = df[lead + [c for c in df.columns if c not in lead]]

    label = os.path.basename(path)
    parent = os.path.dirname(os.path.abspath(out)) or "."
    os.makedirs(parent, exist_ok=True)
    tmp = tempfile.mkdtemp(prefix=".postproc-", dir=parent)
    try:
        df.to_csv(os.path.join(tmp, "summary.csv"), index=False)
        plots.plot_qp_sff(df, os.path.join(tmp, "qp_sff.png"), label)
        plots.plot_anisotropies(df, os.path.join(tmp, "anisotropies.png"), label)
        snap, res = last
        plots.plot_polar(res.angular, res.fits, os.path.join(tmp, "polar_last.png"),
                         f"{label}: snapshot {snap.name} (step {snap.step})")
        if problems:
            with open(os.path.join(tmp, "errors.txt"), "w") as fh:
                fh.write("\n".join(problems) + "\n")
        os.makedirs(out, exist_ok=True)
        stale = os.path.join(out, "errors.txt")
        if not problems and os.path.exists(stale):
            os.remove(stale)
        for name in os.listdir(tmp):
            os.replace(os.path.join(tmp, name), os.path.join(out, name))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return len(rows), problems


def main(argv=None):
    ap = argparse.ArgumentParser(prog="postproc", description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    an = sub.add_parser("analyze", help="stress, fabric and force anisotropies of a dump or contact table")
    an.add_argument("path", help="RUN.h5 dump, or a flat contact table (.csv / .parquet)")
    an.add_argument("--out", required=True, help="output folder")
    an.add_argument("--axis", default="z", help="compression axis: x, y or z (default z)")
    an.add_argument("--volume", type=float, help="packing volume in m^3 (flat tables)")
    an.add_argument("--box", type=float, nargs=3, metavar=("LX", "LY", "LZ"),
                    help="box lengths in m (flat tables; gives volume and wall areas)")
    an.add_argument("--bins", type=int, default=18, help="theta bins on [0, 90 deg] (default 18)")
    an.add_argument("--no-errors", action="store_true", help="skip standard errors (faster)")
    an.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                    help="progress bar (default: on for 5 snapshots or more)")
    sy = sub.add_parser("synthetic", help="write a synthetic dump with known anisotropies (no simulation)")
    sy.add_argument("path", help="RUN.h5 to create")
    sy.add_argument("--contacts", type=int, default=20000)
    sy.add_argument("--snapshots", type=int, default=6)
    sy.add_argument("--final", type=float, nargs=4, default=(0.3, 0.1, 0.5, 0.2),
                    metavar=("A", "A_L", "A_N", "A_T"), help="anisotropies of the last snapshot")
    sy.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    if args.cmd == "synthetic":
        from .synthetic import write_synthetic_dump

        try:
            write_synthetic_dump(args.path, args.contacts, args.snapshots, tuple(args.final),
                                 seed=args.seed)
        except (ValueError, OSError) as exc:
            print(f"postproc: error: {exc}", file=sys.stderr)
            return 2
        print(f"postproc: wrote synthetic dump {args.path}", file=sys.stderr)
        return 0
    try:
        if args.bins < 2:
            raise InputError("--bins must be at least 2")
        n, problems = analyze_path(args.path, args.out, axis=args.axis, volume=args.volume,
                                   box=args.box, nbins=args.bins, errors=not args.no_errors,
                                   progress=args.progress)
    except BAD_INPUT as exc:
        print(f"postproc: error: {exc}", file=sys.stderr)
        return 2
    for line in problems:
        print(f"postproc: error: {line}", file=sys.stderr)
    print(f"postproc: analysed {n} snapshot(s) of {args.path} -> {args.out}"
          + (f"; {len(problems)} bad snapshot(s), see {args.out}/errors.txt" if problems else ""),
          file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
