"""The spread of CD snapshots of one steady state: one step's forces or the mean over K steps.

    python benchmarks/cd_snapshot_scatter.py RUN.h5 [RUN.h5 ...]

Each RUN.h5 is a dump of ``lmgc90/triaxial.py`` (for the measurement: held
at sigma0 in its isotropic stage, ``iso_min_steps`` beyond ``max_steps`` and
a snapshot every ``iso_snapshot_steps``). Per dump, over its snapshots whose
window is full (``average_steps`` steps averaged): the mean and standard
deviation of p/sigma0 (the Love-Weber stress of the dumped contact forces,
``postproc.stress.contact_stress``), of the lateral wall stress / sigma0
(the four lateral walls' dumped forces over their areas) and of the CD
contact-type proportions among force-bearing pairs, by every point within
the alert distance and by the force-carrying points
(``postproc.cdpoints.cd_type_columns``). One table row per dump.
"""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

from postproc.cdpoints import cd_type_columns  # noqa: E402
from postproc.contactset import resolve  # noqa: E402
from postproc.schema import DumpReader  # noqa: E402
from postproc.stress import contact_stress, wall_stress  # noqa: E402


def rows_of(path):
    """Per full-window snapshot: (p/s0, lateral/s0, alert fractions (3,), force fractions (3,))."""
    folder = os.path.dirname(os.path.abspath(path))
    params = json.load(open(os.path.join(folder, "run.params.json")))
    s0 = params["sigma0"]
    out = []
    with DumpReader(path) as r:
        for k in range(len(r)):
            lm = np.load(os.path.join(folder, "run.reactions", f"{k:06d}.npz"))
            K = int(lm["average_steps"]) if "average_steps" in lm else 1
            if int(lm["steps_averaged"] if "steps_averaged" in lm else 1) < K:
                continue
            snap = r.read(k)
            cs = resolve(snap)
            p = np.trace(contact_stress(cs.force, cs.arm, cs.volume)) / 3 / s0
            sw = np.diag(wall_stress(snap.wall_forces, snap.box_lengths))
            lat = 0.5 * (sw[0] + sw[1]) / s0
            c = cd_type_columns(snap)
            out.append([p, lat] + [c[f"cd_alert_frac_{g}"] for g in ("simple", "double", "triple")]
                       + [c[f"cd_force_frac_{g}"] for g in ("simple", "double", "triple")])
    return K, np.array(out)


def main(paths):
    """Print one markdown row per dump (mean and sd over its snapshots)."""
    print("| K | snapshots | p/σ0 mean, sd | lateral σ/σ0 mean, sd | alert count s/d/t (sd) | force count s/d/t (sd) |")
    print("|---|---|---|---|---|---|")
    for path in paths:
        K, a = rows_of(path)
        m, s = a.mean(0), a.std(0, ddof=1)
        tri = lambda j: "/".join(f"{m[j + i]:.2f}" for i in range(3)) + \
            " (" + "/".join(f"{s[j + i]:.2f}" for i in range(3)) + ")"
        print(f"| {K} | {len(a)} | {m[0]:.3f}, {s[0]:.3f} | {m[1]:.3f}, {s[1]:.3f} | {tri(2)} | {tri(5)} |")


if __name__ == "__main__":
    main(sys.argv[1:])
