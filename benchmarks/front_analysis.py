"""Speed against error of the analysis estimators, on synthetic
contact sets with known anisotropies (a, a_l, a_n, a_t) = (0.3, 0.1, 0.5, 0.2):

    python benchmarks/front_analysis.py [--out runs/front-analysis] [--reps 40]

Writes analysis_front.csv (estimator, contacts per set, seconds per set, RMS
error and bias of each anisotropy) and analysis_front.png, and prints the
table.
"""
import argparse
import os

from postproc.study.front import analysis_front
from postproc.plots import plot_analysis_front


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default="runs/front-analysis")
    ap.add_argument("--reps", type=int, default=40)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    table = analysis_front(reps=args.reps)
    table.to_csv(os.path.join(args.out, "analysis_front.csv"), index=False)
    plot_analysis_front(table, os.path.join(args.out, "analysis_front.png"))
    cols = ["estimator", "n", "seconds", "rms_a", "rms_a_l", "rms_a_n", "rms_a_t", "rms_max",
            "bias_a_n", "bias_a_t"]
    print(table[cols].to_string(index=False, float_format=lambda x: f"{x:.3g}"))


if __name__ == "__main__":
    main()
