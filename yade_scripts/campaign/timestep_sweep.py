"""Speed against error along the time step: S1 at the default kappa and I
with dt = safety x the critical step, safety 0.3 (the default), 0.45, 0.6,
0.9; the runs and their table in one command.

    python -m yade_scripts.campaign.timestep_sweep [--out runs/timestep] [--jobs 2]

Runs the ``timestep`` plan of :mod:`yade_scripts.campaign.sweeps` (200 polyhedra, the
default preset, 3 seeds; finished runs are not run again; each dump is
analysed), then tabulates it with
:func:`postproc.study.timestepfront.write_timestep_front` (what the tables
hold is described there; ``postproc timestep-front OUT`` tabulates a folder
the runs left) and prints the table. A run that fails (e.g. blows up) is
listed with its exit status, and the command then exits 1.
"""
from __future__ import annotations

import argparse
import sys

from yade_scripts.campaign.sweeps import PLANS, TIMESTEP_SAFETIES, run_front


def main(argv=None):
    """The command: run the plan, then tabulate and print.

    Parameters
    ----------
    argv : list of str, optional
        Arguments (default ``sys.argv[1:]``).

    Returns
    -------
    int
        0; 1 when a run failed or none could be analysed.
    """
    from postproc.errors import InputError
    from postproc.study.timestepfront import write_timestep_front

    ap = argparse.ArgumentParser(prog="python -m yade_scripts.campaign.timestep_sweep", description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="runs/timestep")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args(argv)
    status = run_front(args.out, "timestep", jobs=args.jobs, samples=("polyhedra",))
    failed = [(d, c) for d, c in status["polyhedra"].items() if c != 0]
    try:
        text = write_timestep_front(args.out, [d for d, _ in PLANS["timestep"]["polyhedra"]], failed,
                                    reference=TIMESTEP_SAFETIES[0])
    except InputError:
        print("timestep_front: no analysed runs", file=sys.stderr)
        return 1
    print(text)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
