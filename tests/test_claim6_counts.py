"""Claim 6 counted more than one way, in the study layer: the band columns
of the analysis (claim 6's quantities with the count's parameter halved and
doubled), the extra count of a study's S1 dump on claim 6's snapshots, the
band test's words on hand-built seeds, and the report's section."""
import json
import os

import numpy as np
import pandas as pd
import pytest

from postproc.pipeline import AnalysisOptions, analyze_path
from postproc.statistics import steady_indices
from postproc.study.claims import BAND_STABLE, band_test, claim6
from postproc.study.counts import analyse_counts, claim6_snapshots, count_folder
from test_footprint_types import kernel_sets_dump


@pytest.fixture(scope="module")
def dump(tmp_path_factory):
    """A polyhedra dump of 7 snapshots (kernel contact sets of random grains,
    each posed anew): one isotropic, six of shear with the box shortened
    along z by 1 % each."""
    return kernel_sets_dump(str(tmp_path_factory.mktemp("c6") / "run.h5"), 7, np.zeros((6, 3)))


def _summary(dump, out, **kw):
    analyze_path(dump, out, AnalysisOptions(errors=False, figures=False, **kw), progress=False)
    return pd.read_csv(os.path.join(out, "summary.csv"), dtype={"snapshot": str})


def test_band_columns_are_the_analysis_at_half_and_double(dump, tmp_path):
    """summary(alpha)'s *_hi columns equal summary(2 alpha)'s own, and its
    *_lo columns summary(alpha / 2)'s, exactly: the band test reads the
    same classification as an analysis at that parameter (numbers only:
    the analyses without their figures)."""
    base = _summary(dump, str(tmp_path / "a"), tolerance=0.2)
    for factor, tag in ((2.0, "hi"), (0.5, "lo")):
        other = _summary(dump, str(tmp_path / tag), tolerance=0.2 * factor)
        for col in ("ct_fratio_FF", "ct_fratio_VF", "ct_fratio_EE", "ct_fabric_FF", "ct_fabric_VF",
                    "ct_fabric_EE", "strong_frac_FF", "weak_frac_FF", "ct_frac_triple"):
            np.testing.assert_array_equal(base[f"{col}_{tag}"].to_numpy(float), other[col].to_numpy(float),
                                          err_msg=f"{col}_{tag}")
    assert base["ct_frac_FF"].gt(0).any() and base["ct_frac_VF"].gt(0).any()
    # at the nominal parameter the FF shares are the networks' own columns
    assert np.isfinite(base["strong_frac_FF"]).all()


def test_extra_count_reads_claim6_snapshots_only(dump, tmp_path):
    """LMGC90's count of a study's S1 dump: only the isotropic
    snapshot and the primary steady window are analysed, the strains are
    the primary ones, and the steady window of the count's summary is the
    primary one; a second call keeps it; a failed count is one line
    (numbers only: the analyses without their figures)."""
    ana = str(tmp_path / "analysis")
    primary = _summary(dump, ana)
    steady = primary["snapshot"].iloc[steady_indices(primary["eps_q"], primary["stage"])].tolist()
    done, problems = analyse_counts(dump, ana, counts=("lmgc90",))
    assert problems == [] and done == {"lmgc90": count_folder(ana, "lmgc90")}
    cp = pd.read_csv(os.path.join(done["lmgc90"], "summary.csv"), dtype={"snapshot": str})
    assert cp["snapshot"].tolist() == [primary["snapshot"].iloc[0]] + steady
    assert (cp["ct_method"] == "lmgc90").all()
    merged = cp.merge(primary, on="snapshot", suffixes=("", "_p"))
    np.testing.assert_array_equal(merged["eps_q"], merged["eps_q_p"])
    assert cp["snapshot"].iloc[steady_indices(cp["eps_q"], cp["stage"])].tolist() == steady
    mtime = os.path.getmtime(os.path.join(done["lmgc90"], "summary.csv"))
    assert analyse_counts(dump, ana, counts=("lmgc90",))[0] == done
    assert os.path.getmtime(os.path.join(done["lmgc90"], "summary.csv")) == mtime
    done, problems = analyse_counts(dump, ana, counts=("nosuchcount",))
    assert done == {} and len(problems) == 1 and "nosuchcount" in problems[0]
    with pytest.raises(Exception, match="not in the dump"):
        claim6_snapshots(primary.assign(snapshot="999999"), ["000000"])


def _seed(vf, vf_lo, ee=-0.1, n=6, e=0.0):
    """A seed's summary: constant values in a steady window of n shear rows
    (``e`` moves every other quantity of claim 6, so that seeds scatter)."""
    eq = np.linspace(0.0, 0.3, n + 1)
    cols = {"eps_q": eq, "stage": ["isotropic"] + ["shear"] * n, "ct_method": "points", "ct_threshold": 0.1}
    for tag, v in (("", vf), ("lo", vf_lo), ("hi", vf)):
        s = f"_{tag}" if tag else ""
        cols.update({f"ct_fabric_VF{s}": v, f"ct_fabric_EE{s}": ee + e, f"ct_fratio_FF{s}": 1.3 + e,
                     f"ct_fratio_VF{s}": 0.7 + e, f"ct_fratio_EE{s}": 0.6 + e, f"ct_fabric_FF{s}": 0.2 + e,
                     f"strong_frac_FF{s}": 0.5 + e, f"weak_frac_FF{s}": 0.3 - e})
    return pd.DataFrame(cols)


@pytest.mark.parametrize("shifts, word", [
    ((0.01, 0.0, -0.01), "stable"),        # mean 0, sd 0.01: +-4.30 x 0.0058 = +-0.025 < 0.03
    ((0.10, 0.11, 0.09), "moves"),         # 0.10 +- 0.025: above 0.03
    ((0.0, 0.06, -0.03), "undecided"),     # 0.01 +- 0.114: straddles 0.03
])
def test_band_test_words(shifts, word):
    seeds = [_seed(-0.05, -0.05 + s) for s in shifts]
    rows = {r["tag"]: r for r in band_test(seeds)}
    assert rows["lo"]["VF_shift"].mean == pytest.approx(np.mean(shifts), abs=1e-15)
    assert rows["lo"]["VF_word"] == word
    assert rows["hi"]["VF_word"] == "stable" and rows["hi"]["VF_shift"].mean == 0
    lo, hi = rows["lo"]["VF_shift"].ci()
    assert (hi - lo) / 2 == pytest.approx(4.302652729911275 * np.std(shifts, ddof=1) / np.sqrt(3), rel=1e-9)
    assert BAND_STABLE == 0.03


def test_claim6_at_a_band_reads_its_columns():
    """Lateral VF at the nominal parameter, axial at half of it: reproduced
    nominally, not reproduced at half; the criterion text names the
    parameter actually used."""
    seeds = [_seed(-0.05 + e, +0.05 + e, e=e) for e in (0.0, 0.01, -0.01)]
    nominal, half = claim6(seeds), claim6(seeds, "lo")
    assert nominal["verdict"] == "reproduced" and half["verdict"] == "not reproduced"
    assert "tolerance 0.1 V/area" in nominal["numbers"] and "tolerance 0.05 V/area" in half["numbers"]


def test_report_states_claim6_by_count(dump, tmp_path):
    """A study with one S1 run analysed by both counts: the report's claim-6
    section and claim6.csv list each count at x 0.5, x 1, x 2 (the analyses
    and the report without their figures)."""
    from postproc.study.report import build_report

    study = tmp_path / "study"
    ana = study / "analysis"
    _summary(dump, str(ana))
    done, _ = analyse_counts(dump, str(ana), counts=("lmgc90",))
    manifest = {"polyhedra": [{"label": "seed 1", "dump": dump, "analysis": str(ana), "info": None, "status": "ok",
                               "counts": {c: os.path.relpath(f, study) for c, f in done.items()}}]}
    (study / "manifest.json").write_text(json.dumps(manifest))
    md = open(build_report(str(study), figures=False)).read()
    table = pd.read_csv(study / "report" / "claim6.csv")
    assert table["count"].tolist() == ["points"] * 3 + ["lmgc90"] * 3
    assert table["factor"].tolist() == [0.5, 1.0, 2.0] * 2
    assert "## Claim 6 by contact count" in md
    assert sum(line.startswith("| lmgc90 | 1 |") for line in md.splitlines()) == 3


@pytest.fixture(scope="module")
def tiny_study(dump, tmp_path_factory):
    """A study folder of one S1 run (the 7-snapshot dump) analysed by the
    point count, as ``make study`` leaves it (without its other counts)."""
    study = tmp_path_factory.mktemp("tiny-study")
    ana = study / "analysis"
    analyze_path(dump, str(ana), AnalysisOptions(errors=False, figures=False), progress=False)
    manifest = {"polyhedra": [{"label": "seed 1", "dump": dump, "analysis": str(ana), "info": None, "status": "ok",
                               "counts": {}}]}
    (study / "manifest.json").write_text(json.dumps(manifest))
    return str(study)


def test_claim6_criteria_command(tiny_study, capsys):
    """``postproc claim6-criteria`` on a tiny study with the point count at
    its own tolerance (read from the study's analysis) and at half and
    twice it (analysed into STUDY/claim6): a verdict row each, the
    stability test and its figure; a folder without a study: exit 2."""
    from postproc.cli import main

    assert main(["investigate", "claim6-criteria", tiny_study, "--types", "points", "--tolerance", "0.05", "0.2"]) == 0
    out = os.path.join(tiny_study, "claim6")
    assert sorted(os.listdir(out)) == ["claim6.md", "points-tolerance.png", "seed1-points-tol0.05",
                                       "seed1-points-tol0.2"]
    md = open(os.path.join(out, "claim6.md")).read()
    rows = [line for line in md.splitlines() if line.startswith("| points")]
    assert [r.split(" | ")[0] for r in rows[:3]] == ["| points", "| points-tol0.05", "| points-tol0.2"]
    assert all(r.split(" | ")[1] == "1" for r in rows[:3])
    assert "Stability of the leanings (points" in md and "| 0.05 |" in md and "| 0.2 |" in md
    own = pd.read_csv(os.path.join(tiny_study, "analysis", "summary.csv"))
    vf = own["ct_fabric_VF"].to_numpy(float)[steady_indices(own["eps_q"], own["stage"])].mean()
    assert f"| seed 1 | nan | {vf:+.3f} |" in md
    assert "Leanings per seed (points-tol0.2" in capsys.readouterr().out
    assert main(["investigate", "claim6-criteria", out]) == 2
    assert "no usable S1 run" in capsys.readouterr().err


def test_study_reads_claim6_by_the_counts_it_is_given(dump, tmp_path, capsys):
    """``python -m yade_scripts.campaign.study --counts``: each S1 dump analysed once
    more per count given (here the 2009 route), the manifest listing them
    and the report reading claim 6 by each; a second pass with one more
    count makes only the missing analysis; the pool's command after a run
    and ``--analyse`` pass the counts on; an unknown count, or the primary
    one, is refused in one line before anything runs."""
    import shutil

    from yade_scripts.campaign import study as st

    out = tmp_path / "study"
    (out / "polyhedra").mkdir(parents=True)
    run = str(out / "polyhedra" / "run.h5")
    shutil.copy(dump, run)
    runs = {"polyhedra": [("seed 1", run, 0)]}
    assert st.analyse_and_report(str(out), runs, counts=("lmgc90-2009",), figures=False) == []
    manifest = json.loads((out / "manifest.json").read_text())["polyhedra"][0]
    assert manifest["counts"] == {"lmgc90-2009": os.path.join("polyhedra", "analysis-lmgc90-2009")}
    first = out / "polyhedra" / "analysis-lmgc90-2009" / "summary.csv"
    assert (pd.read_csv(first)["ct_method"] == "lmgc90-2009").all()
    table = pd.read_csv(out / "report" / "claim6.csv")
    assert table["count"].tolist() == ["points"] * 3 + ["lmgc90-2009"] * 3
    mtime = os.path.getmtime(first)
    assert st.analyse_and_report(str(out), runs, counts=("lmgc90", "lmgc90-2009"), figures=False) == []
    assert os.path.getmtime(first) == mtime                         # kept, not made again
    assert sorted(json.loads((out / "manifest.json").read_text())["polyhedra"][0]["counts"]) == [
        "lmgc90", "lmgc90-2009"]
    assert pd.read_csv(out / "report" / "claim6.csv")["count"].tolist() == (
        ["points"] * 3 + ["lmgc90"] * 3 + ["lmgc90-2009"] * 3)
    # the pool's work after a run, and --analyse, carry the counts
    job = type("Job", (), {"dump": run})()
    assert st.analyse_after(job)[-2:] == ["--analyse", os.path.abspath(run)]
    assert st.analyse_after(job, ("lmgc90-2009",))[-2:] == ["--counts", "lmgc90-2009"]
    shutil.rmtree(out / "polyhedra" / "analysis-lmgc90-planplan", ignore_errors=True)
    assert st.main(["--analyse", run, "--counts", "lmgc90-planplan", "--no-figures"]) == 0
    assert (out / "polyhedra" / "analysis-lmgc90-planplan" / "summary.csv").exists()
    capsys.readouterr()
    # refused in one line, nothing made
    for bad, why in ((["nosuch"], "unknown count 'nosuch'"), (["points"], "points is the primary count")):
        assert st.main(["--out", str(tmp_path / "never"), "--counts", *bad]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and why in err
        assert not (tmp_path / "never").exists()
