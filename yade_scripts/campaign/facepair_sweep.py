"""Do face-face contacts vanish as the grains stiffen? The face-pair tilt
against the overlap thickness, at kappa = 300, 1000, 3000 and 10 000: the
runs and their analysis in one command.

    python -m yade_scripts.campaign.facepair_sweep [--out runs/facepair] [--jobs 2] [--from-eps1 0.1]
        [--figure docs/figures/facepair-tilt.png]

Runs the ``facepair`` plan of :mod:`yade_scripts.campaign.sweeps` (S1 on the default
preset, 200 grains, I = 5e-3, sheared to eps_1 = 0.15, seeds 1-3; a seed
starts from the same grains and positions at every kappa; finished runs are
not run again), then analyses its dumps with
:func:`postproc.study.facepair.write_facepair` (what is measured and
written is described there; ``postproc facepair-tilt`` analyses any dumps
the same way) and prints the table.
"""
from __future__ import annotations

import argparse
import os
import sys

from yade_scripts.campaign.sweeps import PLANS, run_front


def main(argv=None):
    """The command: run the plan, then analyse and print.

    Parameters
    ----------
    argv : list of str, optional
        Arguments (default ``sys.argv[1:]``).

    Returns
    -------
    int
        0; 1 when a run of the plan failed (nothing is analysed then).
    """
    from postproc.study.facepair import write_facepair

    ap = argparse.ArgumentParser(prog="python -m yade_scripts.campaign.facepair_sweep", description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="runs/facepair")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--from-eps1", type=float, default=0.1)
    ap.add_argument("--figure", default=None, help="default OUT/facepair-tilt.png")
    args = ap.parse_args(argv)
    status = run_front(args.out, "facepair", jobs=args.jobs, samples=("polyhedra",))
    failed = [d for d, c in status["polyhedra"].items() if c != 0]
    if failed:
        print(f"facepair_tilt: failed runs: {', '.join(failed)}", file=sys.stderr)
        return 1
    dumps = [os.path.join(args.out, "polyhedra", f"polyhedra-{desc}.h5") for desc, _ in PLANS["facepair"]["polyhedra"]]
    print(write_facepair(args.out, dumps, args.from_eps1, args.figure))
    return 0


if __name__ == "__main__":
    sys.exit(main())
