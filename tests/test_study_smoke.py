"""The whole study pipeline on the tiny preset, two seeds per sample in one
schedule (yade_scripts.launch.pool): runs, analyses, report, figures, the claims
table and the schedule's record."""
import json
import math
import os
import shutil
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from matplotlib.image import imread
from saved_figures import check_descriptor_figure, is_png, line, record

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
    """The study folder, main's exit code and every figure saved in this
    process meanwhile (saved_figures.record: the report's own figures)."""
    from yade_scripts.campaign.study import main

    out = tmp_path_factory.mktemp("study")
    with pytest.MonkeyPatch.context() as mp:
        saved = record(mp)
        rc = main(["--preset", "tiny", "--out", str(out), "--ensemble", "2", "--library", shape_library])
    return out, rc, saved


def shear(df):
    return df[df["stage"] == "shear"]


def run_library(out):
    """The shape library of the study's first polyhedra run (its run
    folder's copy, named in its params.json), the report's library section's."""
    from postproc.study.report import discover
    from shapes.library import ShapeLibrary

    for r in discover(str(out)).get("polyhedra", []):
        pj = os.path.join(os.path.dirname(r.get("dump") or ""), "params.json")
        if os.path.exists(pj):
            with open(pj) as fh:
                return ShapeLibrary(os.path.join(os.path.dirname(pj), json.load(fh).get("library", "shapes.h5")))
    raise AssertionError("no polyhedra run with a params.json")


def check_qp_figure(fig, summaries):
    """fig_qp.png: every usable seed's q/p against eps_q over its shear
    snapshots (solid, in the order of the summaries), the published
    plateaus dashed."""
    from postproc.study.report import LABEL, REFERENCE

    with open(REFERENCE) as fh:
        pub = json.load(fh)["results"]["q_over_p_plateau"]
    ax = fig.axes[0]
    solid = [ln for ln in ax.get_lines() if ln.get_linestyle() == "-"]
    frames = [shear(df) for s in summaries for df in summaries[s]]
    assert len(solid) == len(frames)
    for ln, sh in zip(solid, frames):
        np.testing.assert_allclose(ln.get_xydata(), sh[["eps_q", "q_over_p"]].to_numpy(float), rtol=1e-12)
    dashed = {ln.get_label(): ln.get_ydata()[0] for ln in ax.get_lines() if ln.get_linestyle() == "--"}
    assert dashed == {f"{LABEL[s]}, published plateau": pub[s] for s in summaries if pub.get(s) is not None}
    assert ax.get_xlabel() == r"$\varepsilon_q$" and ax.get_ylabel() == "q/p"


def check_report_figures(out, rep, saved):
    """The report's figures, as saved, show the study's numbers: q/p of every
    seed, the anisotropies' mean over seeds, every shear snapshot's q/p
    against (2/5) sum a, the polar data of the first seed's snapshot nearest
    eps_q = 0.3, the branch directions by contact group, every contact of
    the slabs; the S1 figures of its analysis are the analysis's own (drawn
    again from its summary.csv: the same pixels); the grains' descriptors
    are the run's library's."""
    import warnings

    from postproc import plots
    from postproc.analysis import analyze_snapshot
    from postproc.angular import harmonic_curves
    from postproc.schema import DumpReader
    from postproc.study import report as R
    from shapes.descriptors import library_descriptors

    runs = R.discover(str(out))
    summaries = R.run_summaries(runs)
    check_qp_figure(saved.at(rep / "fig_qp.png"), summaries)
    # anisotropies: per sample, each seed interpolated on the first seed's strains, then averaged
    samples = [s for s in R.SAMPLES if summaries.get(s)]
    fig = saved.at(rep / "fig_anisotropies.png")
    assert len(fig.axes) == len(samples)
    for ax, s in zip(fig.axes, samples):
        assert ax.get_title() == f"{R.LABEL[s]} ({len(summaries[s])} seed(s))"
        grid = shear(summaries[s][0])["eps_q"].to_numpy(float)
        for k in ("a", "a_l", "a_n", "a_t"):
            curves = []
            for df in summaries[s]:
                sh = shear(df)
                sh = sh[np.isfinite(sh["eps_q"]) & np.isfinite(sh[k])].sort_values("eps_q")
                if len(sh) >= 2:                                        # a seed with one value is left out
                    curves.append(np.interp(grid, sh["eps_q"], sh[k], left=np.nan, right=np.nan))
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)          # a strain no seed reached
                mean = np.nanmean(curves, axis=0)
            np.testing.assert_allclose(line(ax, k).get_xydata(), np.column_stack([grid, mean]), rtol=1e-9)
    assert fig.axes[0].get_ylabel() == "anisotropy"
    # sff: every shear snapshot of every seed, one series of points per seed
    ax = saved.at(rep / "fig_sff.png").axes[0]
    points = [ln for ln in ax.get_lines() if ln.get_marker() == "o"]
    frames = [shear(df) for s in summaries for df in summaries[s]]
    assert len(points) == len(frames)
    for ln, sh in zip(points, frames):
        np.testing.assert_allclose(ln.get_xydata(), sh[["sff", "q_axial_over_p"]].to_numpy(float), rtol=1e-12)
    eq = line(ax, "equality")
    np.testing.assert_array_equal(eq.get_xdata(), eq.get_ydata())
    # polar: per sample, the bins of the first seed's snapshot named in the title, mirrored, and their fits
    fig = saved.at(rep / "fig_polar.png")
    polar = [s for s in R.SAMPLES if R.usable_runs(runs, s)]
    assert len(fig.axes) == 2 * len(polar)
    tt = np.linspace(0, 2 * np.pi, 361)
    for row, s in enumerate(polar):
        run = R.usable_runs(runs, s)[0]
        df = summaries[s][0]
        name = fig.axes[2 * row].get_title().split("\nsnapshot ")[1].split(",")[0]
        eq = df["eps_q"].to_numpy(float)
        k = len(df) - 1 if np.nanmax(eq) < 0.3 else int(np.nanargmin(np.abs(eq - 0.3)))
        assert name == str(df["snapshot"].iloc[k]).zfill(6)               # nearest eps_q = 0.3, else the last
        with DumpReader(run["dump"]) as reader:
            res = analyze_snapshot(reader.read(reader.names.index(name)), errors=False)
        curves = harmonic_curves(res.fits, tt)
        for ax, key, data in ((fig.axes[2 * row], "P", res.angular.P),
                              (fig.axes[2 * row + 1], "l", res.angular.l_mean)):
            pts, fit = ax.get_lines()
            assert len(pts.get_ydata()) == 4 * len(res.angular.centers)
            np.testing.assert_allclose(pts.get_ydata(), np.concatenate([data, data[::-1], data, data[::-1]]),
                                       rtol=1e-9)
            np.testing.assert_allclose(fit.get_ydata(), curves[key], rtol=1e-9)
            assert ax.get_title().startswith(f"{R.LABEL[s]}: ")
    # branch directions of simple and triple contacts of S1's first seed
    data, caption = R.group_branch_polar(R.usable_runs(runs, "polyhedra")[0])
    ax = saved.at(rep / "fig_types_polar.png").axes[0]
    for g, af in data.items():
        m = np.concatenate([af.P, af.P[::-1], af.P, af.P[::-1]])
        np.testing.assert_allclose(line(ax, g).get_ydata(), np.append(m, m[0]), rtol=1e-12)
    np.testing.assert_allclose(line(ax, "isotropic").get_ydata(), 1 / (4 * np.pi))
    assert caption in ax.get_title() and len(data) >= 1
    # the slabs: every contact of the slab of each picked snapshot, by its force; by type for S1
    from matplotlib.collections import LineCollection
    from matplotlib.colors import to_rgba

    picked = R._slab_snapshots(runs)
    for fname, which in (("packing_slab.png", list(picked)), ("s1_slab_types.png", ["polyhedra"])):
        fig = saved.at(rep / fname)
        assert len(fig.axes) == len(which) + (fname == "packing_slab.png")     # and the colour bar
        for ax, s in zip(fig.axes, which):
            run, name, strain = picked[s]
            sl, snap_name = R._slab_of(run, name)
            fn = np.asarray(sl["fn"], float)
            title = (f"{R.LABEL[s]}, snapshot {snap_name}, "
                     + (f"εq = {strain:.3f}" if np.isfinite(strain) else "last snapshot"))
            assert ax.get_title() == f"{title}\n{len(fn)} contacts in a slab {sl['thickness'] * 1e3:.0f} mm thick"
            (lc,) = [c for c in ax.collections if isinstance(c, LineCollection)]
            segs, expect = np.array(lc.get_segments()), np.asarray(sl["segments"], float)
            assert segs.shape == expect.shape                            # every contact, drawn once
            np.testing.assert_allclose(segs[np.lexsort(segs.reshape(len(segs), -1).T)],
                                       expect[np.lexsort(expect.reshape(len(expect), -1).T)], rtol=1e-12)
            np.testing.assert_allclose(np.sort(lc.get_linewidths()),
                                       np.sort(0.3 + 1.1 * np.clip(fn / fn.mean(), 0, 4)), rtol=1e-12)
            if fname == "s1_slab_types.png":
                colours = [tuple(c) for c in lc.get_colors()]
                for g, c in plots.TYPE_COLOURS.items():
                    assert colours.count(to_rgba(c)) == int(np.sum(np.asarray(sl["labels"]) == g)), g
            assert ax.get_xlabel() == "x (m)" and ax.get_ylabel() == "z (m)"
    # S1's analysis figures: copied unchanged, and drawn from the analysis's own summary.csv
    s1 = R.usable_runs(runs, "polyhedra")[0]
    for name in ("contact_types.png", "footprint.png", "force_pdf.png", "networks.png"):
        assert (rep / f"s1_{name}").read_bytes() == (Path(s1["analysis"]) / name).read_bytes(), name
    df = pd.read_csv(Path(s1["analysis"]) / "summary.csv")
    label = os.path.basename(s1["dump"])
    for name, fn in (("contact_types.png", plots.plot_contact_types), ("networks.png", plots.plot_networks)):
        again = Path(rep).parent / f"again-{name}"
        fn(df, str(again), label)
        np.testing.assert_array_equal(imread(again), imread(rep / f"s1_{name}"), err_msg=name)
    lib = run_library(out)
    check_descriptor_figure(saved.at(rep / "library_descriptors.png"), {lib.name: (lib, library_descriptors(lib))})


def test_report_figures_and_claims_are_produced(study, capsys):
    out, rc, saved = study
    assert rc == 0
    rep = out / "report"
    md = (rep / "report.md").read_text()
    assert (rep / "report.html").stat().st_size > 0
    for name in FIGURES:
        image = imread(rep / name)                 # a PNG with something drawn on it
        assert image.ndim == 3 and image.shape[0] > 200 and image[..., :3].std() > 0.05, name
        assert f"]({name})" in md, name
    check_report_figures(out, rep, saved)          # and what is drawn is the study's numbers
    claims = pd.read_csv(rep / "claims.csv")
    assert claims["id"].tolist() == [1, 2, 3, 4, 5, 6]
    assert (claims["basis"] == "seeds").all()
    comp = pd.read_csv(rep / "comparison.csv")
    assert comp["ours"].map(math.isfinite).all() and (comp["interval"] == "seeds").all()
    # make compare on this tiny study: against results written from itself, the same; against
    # the committed default study's, it says what differs (the tiny preset is not the default)
    from postproc.cli import main as postproc_main

    capsys.readouterr()
    assert postproc_main(["results", str(out), "--out", str(out / "own.json")]) == 0
    assert postproc_main(["compare-results", str(out), "--reference", str(out / "own.json")]) == 0
    assert capsys.readouterr().out.startswith("same as the README")
    assert postproc_main(["compare-results", str(out)]) == 1
    said = capsys.readouterr().out.splitlines()
    assert "  preset: tiny (committed: default)" in said and "another machine" in said[-1]
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
    from yade_scripts.launch.pool import idle_core_seconds
    assert sched["summary"]["idle_core_s"] == pytest.approx(idle_core_seconds(sched["attempts"], 2))
    assert sched["summary"]["busy_core_s"] > 0
    assert "Schedule (`schedule.json`)" in md and "idle" in md
    # all four runs ran on this host, named once
    hosts = [line for line in md.splitlines() if line.startswith("Host: ")]
    assert len(hosts) == 1 and hosts[0].count("seed") == 4


def test_rerun_skips_finished_runs_and_a_failed_run_is_reported(study, capsys, monkeypatch):
    from postproc.study.report import build_report
    from yade_scripts.campaign.study import main

    out, _, _ = study
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
    saved = record(monkeypatch)
    md = open(build_report(str(out), str(out / "report-failed"))).read()
    # fig_qp.png as written: q/p of the one polyhedra seed left and the two sphere seeds, as analysed
    fig = saved.at(out / "report-failed" / "fig_qp.png")
    lines = [ln for ln in fig.axes[0].get_lines() if ln.get_linestyle() == "-"]
    assert len(lines) == 3
    s1 = pd.read_csv(out / manifest["polyhedra"][0]["analysis"] / "summary.csv")
    s1 = s1[s1["stage"] == "shear"]
    assert list(lines[0].get_ydata()) == pytest.approx(s1["q_over_p"].tolist())
    summaries = {s: [pd.read_csv(out / r["analysis"] / "summary.csv", dtype={"snapshot": str})
                     for r in manifest[s] if r["status"] == "ok"] for s in manifest}
    assert {s: len(v) for s, v in summaries.items()} == {"polyhedra": 1, "spheres": 2}
    check_qp_figure(fig, summaries)
    assert "S1 polyhedra seed 2: run failed (3)" in md
    comp = pd.read_csv(out / "report-failed" / "comparison.csv")
    # one seed left: no interval over seeds (tiny runs have 2 steady snapshots: "one value")
    assert comp.loc[comp["sample"] == "polyhedra", "interval"].isin(["one value", "batch means (one seed)"]).all()
    assert (comp.loc[comp["sample"] == "spheres", "interval"] == "seeds").all()
    assert is_png(out / "report-failed" / "fig_qp.png")


def test_an_archive_carries_the_analysed_seeds_to_a_new_host(study, shape_library, tmp_path, capsys):
    """``python -m yade_scripts.campaign.archive`` keeps every analysed run's numbers
    without its dump or figures; a new study folder (a new host) with
    ``--archive`` refuses an archive holding a record of another analysis
    version (replacing nothing), runs none of the usable archived seeds and
    only the one the archive lacks, and reports the same numbers as the
    study made from the dumps; ``--collect --archive`` reads it the same way."""
    import hashlib

    from yade_scripts.campaign.archive_store import RUN_RECORD, archived
    from yade_scripts.campaign.archive import main as archive_main
    from yade_scripts.campaign.study import ARCHIVED, collect, main

    out, _, _ = study
    arch = tmp_path / "arch"
    assert archive_main([str(out), str(arch)]) == 0
    for s, counts in (("polyhedra", ["lmgc90"]), ("spheres", [])):
        for k in (1, 2):
            rec = json.loads((arch / f"{s}-ensemble" / f"{s}-seed{k}{RUN_RECORD}").read_text())
            dump = out / f"{s}-ensemble" / f"{s}-seed{k}.h5"
            assert rec["dump"]["sha256"] == hashlib.sha256(dump.read_bytes()).hexdigest()
            assert rec["counts"] == counts and rec["dump"]["bytes"] == dump.stat().st_size
    assert not list(arch.rglob("*.h5")) and not list(arch.rglob("*.png"))
    capsys.readouterr()
    assert archive_main([str(out), str(arch)]) == 0                # a second time: nothing added
    assert capsys.readouterr().out.count("already archived") == 4
    # extending it: a dry run of 3 seeds on a new host takes 2 + 2 from it and would run seed 3 of each
    plan = tmp_path / "plan"
    assert main(["--preset", "tiny", "--out", str(plan), "--ensemble", "3", "--library", shape_library,
                 "--archive", str(arch), "--dry-run"]) == 0
    assert "2 + 2 archived and usable; 1 + 1 to run" in capsys.readouterr().out and not plan.exists()
    # on the study's own folder, whose dumps are here
    assert main(["--preset", "tiny", "--out", str(out), "--ensemble", "3", "--library", shape_library,
                 "--archive", str(arch), "--dry-run"]) == 0
    assert "0 + 0 archived and usable; 2 + 2 complete here; 1 + 1 to run" in capsys.readouterr().out
    # one record of an unknown analysis version: the study refuses before it runs anything, and
    # replaces nothing
    stale = arch / "spheres-ensemble" / f"spheres-seed2{RUN_RECORD}"
    rec = json.loads(stale.read_text())
    stale.write_text(json.dumps({**{k: v for k, v in rec.items() if k != "version"}, "code": "0" * 64}))
    before = {p: p.read_bytes() for p in arch.rglob("*") if p.is_file() and p.name != "archive.lock"}
    new = tmp_path / "new"
    args = ["--preset", "tiny", "--out", str(new), "--ensemble", "2", "--library", shape_library,
            "--archive", str(arch)]
    assert main(args) == 2
    err = capsys.readouterr().err
    assert f"the archive {arch} holds 1 run(s) of another analysis version" in err
    assert "spheres-seed2.h5" in err and "ARCHIVE=NEW_DIR" in err and len(err.strip().splitlines()) == 1
    assert {p: p.read_bytes() for p in arch.rglob("*") if p.is_file() and p.name != "archive.lock"} == before
    assert not new.exists()                                     # refused before anything was made
    # the archive without that seed's record (as if never archived): it runs here and is archived
    stale.unlink()
    assert main(args) == 0
    said = capsys.readouterr().out
    assert said.count("taken from the archive") == 3
    assert "spheres-seed2 started" in said and "polyhedra-seed1 started" not in said
    from postproc.provenance import ANALYSIS_VERSION
    assert "spheres-seed2: the work after it started" in said
    assert "spheres-seed2.h5: kept" in (new / "spheres-ensemble" / "spheres-seed2.after.log").read_text()
    rec2 = json.loads(stale.read_text())
    dump2 = new / "spheres-ensemble" / "spheres-seed2.h5"
    assert rec2["version"] == ANALYSIS_VERSION and rec2["dump"]["sha256"] == hashlib.sha256(dump2.read_bytes()).hexdigest()
    manifest = json.loads((new / "manifest.json").read_text())
    assert [r["status"] for s in ("polyhedra", "spheres") for r in manifest[s]] == ["ok"] * 4
    assert [("archived" in r) for s in ("polyhedra", "spheres") for r in manifest[s]] == [True, True, True, False]
    assert not (new / "polyhedra-ensemble" / "polyhedra-seed1.h5").exists()
    # the figures that read a dump start from a seed whose dump is here: S2's seed 2, none of S1
    md = (new / "report" / "report.md").read_text()
    assert "polar data of S1" in md and "polar data of S2" not in md
    assert (new / "report" / "fig_polar.png").exists() and not (new / "report" / "fig_types_polar.png").exists()
    assert "from the archive" in md
    # the same numbers as from the dumps (seed 2 of S2 ran again on this host: the same run, step for step)
    for name in ("comparison.csv", "claims.csv", "claim6.csv"):
        pd.testing.assert_frame_equal(pd.read_csv(new / "report" / name), pd.read_csv(out / "report" / name))
    # a file that is not as recorded: that seed is refused, with the file named
    summary = arch / "polyhedra-ensemble" / "analysis-polyhedra-seed1" / "summary.csv"
    text = summary.read_text()
    summary.write_text(text.replace("shear", "Shear", 1))
    held = archived(str(arch), str(new / "polyhedra-ensemble"), counts=["lmgc90"])
    assert held["polyhedra-seed1.h5"][0] == "refused" and "summary.csv is missing or not as recorded" in \
        held["polyhedra-seed1.h5"][1]
    assert held["polyhedra-seed2.h5"][0] == "ok"
    # a count the archive lacks refuses the S1 seeds, not the S2 ones
    held = archived(str(arch), str(new / "polyhedra-ensemble"), counts=["lmgc90", "lmgc90-2009"])
    assert "no analysis by the lmgc90-2009 count" in held["polyhedra-seed2.h5"][1]
    assert archived(str(arch), str(new / "spheres-ensemble"), counts=["lmgc90-2009"])["spheres-seed1.h5"][0] == "ok"
    # collect: the archived seeds are runs, not unfinished lines; a refused one is unfinished
    runs, pending, failed, _ = collect(str(new), archive=str(arch))
    assert pending == ["polyhedra-ensemble/polyhedra-seed1 (not started)"] and failed == []
    summary.write_text(text)
    runs, pending, failed, _ = collect(str(new), archive=str(arch))
    assert pending == [] and failed == []
    assert {s: [st for _, _, st in runs[s]] for s in runs} == {"polyhedra": [ARCHIVED, ARCHIVED],
                                                             "spheres": [ARCHIVED, 0]}
    for name in ("comparison.csv", "claim6.csv"):
        pd.testing.assert_frame_equal(pd.read_csv(new / "report" / name), pd.read_csv(out / "report" / name))


def test_study_runs_s1_on_an_imported_library(tmp_path, monkeypatch):
    """``make study SHAPES=LIB.h5`` with a library imported from meshes (as a
    user's scans would be): the tiny S1 runs on the imported grains (the
    dump's shapes are the library's), and the report names the library and
    shows its descriptors. It is also the path of plain `make study`: one
    seed per sample, side by side, S1 on the compiled kernel started as
    yade -jN (so the kernel gets N threads)."""
    import h5py
    import numpy as np
    import trimesh

    from postproc.schema import DumpReader
    from shapes.__main__ import main as shapes_main
    from shapes.library import ShapeLibrary
    from yade_scripts.campaign.study import main

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
    saved = record(monkeypatch)
    assert main(["--preset", "tiny", "--out", str(out), "--library", str(lib)]) == 0
    info = json.loads((out / "polyhedra" / "run.info.json").read_text())
    assert info["kernel"]["threads"] == (os.cpu_count() or 1) and info["kernel"]["touch_steps"] > 0
    with DumpReader(str(out / "polyhedra" / "run.h5")) as r:
        assert r.complete and r.parameters["contact_engine"] == "kernel"
    with h5py.File(out / "polyhedra" / "run.h5", "r") as h:
        counts = np.diff(np.asarray(h["shapes"]["vertex_offsets"]))
    imported = {len(library[i][0]) for i in range(len(library))}
    assert len(counts) == 20 and set(counts.tolist()) <= imported   # every grain of the run is an imported one
    md = (out / "report" / "report.md").read_text()
    assert "## The grains of S1" in md and "**test stones**" in md and "imported from 24 meshes" in md
    assert "convexity deficit" in md
    # and its figure shows the imported grains' descriptors
    from shapes.descriptors import library_descriptors

    used = run_library(out)
    assert used.name == "test stones" and len(used) == 24
    check_descriptor_figure(saved.at(out / "report" / "library_descriptors.png"),
                            {used.name: (used, library_descriptors(used))})
