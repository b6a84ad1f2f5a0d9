"""The whole study pipeline on the tiny preset, two seeds per sample in one
schedule (yade_scripts.pool): runs, analyses, report, figures, the claims
table and the schedule's record."""
import json
import math
import os
import shutil

import pandas as pd
import pytest
from matplotlib.image import imread

YADE = shutil.which("yade")
pytestmark = [pytest.mark.yade,
              pytest.mark.skipif(YADE is None,
                                 reason="Debian yade is not installed")]

FIGURES = ("fig_qp.png", "fig_anisotropies.png", "fig_sff.png", "fig_polar.png",
           "s1_contact_types.png", "s1_force_pdf.png", "s1_networks.png", "s1_footprint.png",
           "fig_types_polar.png",
           "packing_slab.png", "s1_slab_types.png")


@pytest.fixture(scope="module")
def study(tmp_path_factory, shape_library):
    from yade_scripts.study import main

    out = tmp_path_factory.mktemp("study")
    rc = main(["--preset", "tiny", "--out", str(out), "--ensemble", "2", "--library", shape_library])
    return out, rc


def test_report_figures_and_claims_are_produced(study, capsys):
    out, rc = study
    assert rc == 0
    rep = out / "report"
    md = (rep / "report.md").read_text()
    assert (rep / "report.html").stat().st_size > 0
    for name in FIGURES:
        image = imread(rep / name)                 # a PNG with something drawn on it
        assert image.ndim == 3 and image.shape[0] > 200 and image[..., :3].std() > 0.05, name
        assert f"]({name})" in md, name
    claims = pd.read_csv(rep / "claims.csv")
    assert claims["id"].tolist() == [1, 2, 3, 4, 5, 6]
    assert (claims["basis"] == "seeds").all()
    comp = pd.read_csv(rep / "comparison.csv")
    assert comp["ours"].map(math.isfinite).all() and (comp["interval"] == "seeds").all()
    # the verdicts are the rules applied to the analyses the manifest lists
    from postproc.study.claims import NEGLIGIBLE, evaluate
    from postproc.study.report import run_summaries, discover

    again = pd.DataFrame(evaluate(run_summaries(discover(str(out)))))
    assert claims["verdict"].tolist() == again["verdict"].tolist()
    assert claims["numbers"].tolist() == again["numbers"].tolist()
    # claim 3 decided again here from the a_l intervals of comparison.csv
    lo = {s: comp.loc[(comp["quantity"] == "a_l") & (comp["sample"] == s), ["ci_low", "ci_high"]].iloc[0]
          for s in ("polyhedra", "spheres")}
    sph = 1 if -NEGLIGIBLE < lo["spheres"]["ci_low"] and lo["spheres"]["ci_high"] < NEGLIGIBLE else \
        (-1 if lo["spheres"]["ci_low"] > NEGLIGIBLE or lo["spheres"]["ci_high"] < -NEGLIGIBLE else 0)
    poly = 1 if lo["polyhedra"]["ci_low"] > NEGLIGIBLE or lo["polyhedra"]["ci_high"] < -NEGLIGIBLE else \
        (-1 if -NEGLIGIBLE < lo["polyhedra"]["ci_low"] and lo["polyhedra"]["ci_high"] < NEGLIGIBLE else 0)
    expected = "not reproduced" if -1 in (sph, poly) else ("reproduced" if sph == poly == 1 else "inconclusive")
    assert claims.loc[2, "verdict"] == expected
    # claim 1 quotes the plateaus of comparison.csv
    for s in ("polyhedra", "spheres"):
        q = comp.loc[(comp["quantity"] == "q/p plateau") & (comp["sample"] == s), "ours"].iloc[0]
        assert f"{s} {q:.2f} [" in claims.loc[0, "numbers"], s
    # claim 6 by count: both counts at half, nominal and double their parameter;
    # the point count's nominal row is claim 6 of claims.csv
    c6 = pd.read_csv(rep / "claim6.csv")
    assert sorted(zip(c6["count"], c6["factor"])) == sorted((c, f) for c in ("points", "lmgc90")
                                                            for f in (0.5, 1.0, 2.0))
    assert c6.loc[(c6["count"] == "points") & (c6["factor"] == 1.0), "verdict"].iloc[0] == claims.loc[5, "verdict"]
    assert (c6["seeds"] == 2).all() and "## Claim 6 by contact count" in md
    assert "Intervals are 95 % over seeds" in md
    manifest = json.loads((out / "manifest.json").read_text())
    assert [r["status"] for s in manifest.values() for r in s] == ["ok"] * 4
    sched = json.loads((out / "schedule.json").read_text())
    runs = {"polyhedra-seed1", "polyhedra-seed2", "spheres-seed1", "spheres-seed2"}
    assert {a["job"] for a in sched["attempts"] if a.get("kind") != "after"} == runs
    # each run analysed once on a free core as soon as it was complete; the pass at the end kept them
    assert sorted(a["job"] for a in sched["attempts"] if a.get("kind") == "after") == sorted(
        f"after {r}" for r in runs)
    assert all(a["exit"] == 0 for a in sched["attempts"] if a.get("kind") == "after")
    assert "4 analyses of finished runs on free cores" in md
    from yade_scripts.pool import idle_core_seconds
    assert sched["summary"]["idle_core_s"] == pytest.approx(idle_core_seconds(sched["attempts"], 2))
    assert sched["summary"]["busy_core_s"] > 0
    assert "Schedule (`schedule.json`)" in md and "idle" in md
    # all four runs ran on this host, named once
    hosts = [line for line in md.splitlines() if line.startswith("Host: ")]
    assert len(hosts) == 1 and hosts[0].count("seed") == 4


def test_rerun_skips_finished_runs_and_a_failed_run_is_reported(study, capsys):
    from postproc.study.report import build_report
    from yade_scripts.study import main

    out, _ = study
    mtime = os.path.getmtime(out / "polyhedra-ensemble" / "polyhedra-seed1.h5")
    summary = out / "polyhedra-ensemble" / "analysis-polyhedra-seed1" / "summary.csv"
    analysed = os.path.getmtime(summary)
    assert main(["--preset", "tiny", "--out", str(out), "--ensemble", "2"]) == 0
    said = capsys.readouterr().out
    assert "polyhedra-seed1 already complete, not run again" in said
    assert os.path.getmtime(out / "polyhedra-ensemble" / "polyhedra-seed1.h5") == mtime
    # nor analysed again: same dump, options and code (postproc.provenance)
    assert said.count("is up to date (same dump, options and code), kept") == 4
    assert os.path.getmtime(summary) == analysed
    # a failed run: listed, the rest still builds (the other seed gives the numbers)
    manifest = json.loads((out / "manifest.json").read_text())
    manifest["polyhedra"][1]["status"] = "run failed (3); see polyhedra-ensemble"
    (out / "manifest.json").write_text(json.dumps(manifest))
    from postproc import plots

    drawn = {}

    def keep(summaries, published, path):
        drawn["qp"] = fig = plot_report_qp(summaries, published, path)
        return fig

    plot_report_qp = plots.plot_report_qp
    plots.plot_report_qp = keep
    try:
        md = open(build_report(str(out), str(out / "report-failed"))).read()
    finally:
        plots.plot_report_qp = plot_report_qp
    # q/p of the two sphere seeds and the one polyhedra seed left, as analysed
    lines = [ln for ln in drawn["qp"].axes[0].get_lines() if ln.get_linestyle() == "-"]
    assert len(lines) == 3
    s1 = pd.read_csv(out / manifest["polyhedra"][0]["analysis"] / "summary.csv")
    s1 = s1[s1["stage"] == "shear"]
    assert list(lines[0].get_ydata()) == pytest.approx(s1["q_over_p"].tolist())
    assert "S1 polyhedra seed 2: run failed (3)" in md
    comp = pd.read_csv(out / "report-failed" / "comparison.csv")
    # one seed left: no interval over seeds (tiny runs have 2 steady snapshots: "one value")
    assert comp.loc[comp["sample"] == "polyhedra", "interval"].isin(["one value", "batch means (one seed)"]).all()
    assert (comp.loc[comp["sample"] == "spheres", "interval"] == "seeds").all()
    assert (out / "report-failed" / "fig_qp.png").exists()


def test_single_seed_study_runs_s1_on_the_kernel_with_every_core(tmp_path, shape_library, capsys):
    """The path of plain `make study`: one seed per sample, side by side, S1
    on the compiled kernel started as yade -jN (so the kernel gets N threads)."""
    import os

    from postproc.schema import DumpReader
    from yade_scripts.study import main

    rc = main(["--preset", "tiny", "--out", str(tmp_path), "--library", shape_library])
    assert rc == 0
    info = json.loads((tmp_path / "polyhedra" / "run.info.json").read_text())
    assert info["kernel"]["threads"] == (os.cpu_count() or 1) and info["kernel"]["touch_steps"] > 0
    with DumpReader(str(tmp_path / "polyhedra" / "run.h5")) as r:
        assert r.complete and r.parameters["contact_engine"] == "kernel"
    assert (tmp_path / "report" / "report.md").exists()


def test_study_runs_s1_on_an_imported_library(tmp_path):
    """``make study SHAPES=LIB.h5`` with a library imported from meshes (as a
    user's scans would be): the tiny S1 runs on the imported grains (the
    dump's shapes are the library's), and the report names the library and
    shows its descriptors."""
    import h5py
    import numpy as np
    import trimesh

    from shapes.__main__ import main as shapes_main
    from shapes.library import ShapeLibrary
    from yade_scripts.study import main

    rng = np.random.default_rng(7)
    scans = tmp_path / "scans"
    scans.mkdir()
    for k in range(24):                             # stones: hulls of points on stretched spheres, 3 formats
        p = rng.normal(size=(60, 3))
        p = p / np.linalg.norm(p, axis=1)[:, None] * [1.0, rng.uniform(0.6, 0.9), rng.uniform(0.4, 0.7)]
        hull = trimesh.convex.convex_hull(p * rng.uniform(0.8, 1.2))
        hull.apply_transform(trimesh.transformations.random_rotation_matrix(rng.random(3)))
        hull.export(str(scans / f"stone{k:02d}.{('stl', 'obj', 'ply')[k % 3]}"))
    lib = tmp_path / "stones.h5"
    assert shapes_main(["import", str(scans), "--out", str(lib), "--name", "test stones"]) == 0
    library = ShapeLibrary(str(lib))
    assert len(library) == 24
    out = tmp_path / "study"
    assert main(["--preset", "tiny", "--out", str(out), "--library", str(lib)]) == 0
    with h5py.File(out / "polyhedra" / "run.h5", "r") as h:
        counts = np.diff(np.asarray(h["shapes"]["vertex_offsets"]))
    imported = {len(library[i][0]) for i in range(len(library))}
    assert len(counts) == 20 and set(counts.tolist()) <= imported   # every grain of the run is an imported one
    md = (out / "report" / "report.md").read_text()
    assert "## The grains of S1" in md and "**test stones**" in md and "imported from 24 meshes" in md
    assert "convexity deficit" in md
