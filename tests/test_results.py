"""The committed results of the default study and the README's claims table
(postproc.study.results): a hand-built report folder with known numbers
goes through ``postproc results`` into the JSON file and the table, and the
committed README's table is the one the committed results file gives."""
import json
import os
import re

import pandas as pd
import pytest

from postproc.cli import main
from postproc.errors import InputError
from postproc.study import results as R

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
README = os.path.join(ROOT, "README.md")

CLAIMS = [
    (1, "q/p higher", "reproduced", "plateau q/p: ...", "seeds"),
    (2, "a lower", "reproduced", "plateau a: ...", "seeds"),
    (3, "a_l", "inconclusive", "plateau a_l: ...", "seeds"),
    (4, "a_n, a_t", "reproduced", "...", "seeds"),
    (5, "2/5", "reproduced", "...", "seeds"),
    (6, "types", "not reproduced", "FF mean force / mean 2.46 [2.30, 2.62] (> 1) | x", "seeds"),
]
# (quantity, sample, ours, low, high, published)
COMPARISON = [
    ("q/p plateau", "polyhedra", 0.4412, 0.4011, 0.4813, 0.46),
    ("q/p plateau", "spheres", 0.2504, 0.2398, 0.2611, 0.23),
    ("a", "polyhedra", 0.1034, 0.0712, 0.1356, 0.08),
    ("a", "spheres", 0.2901, 0.2803, 0.2999, 0.24),
    ("a_l", "polyhedra", -0.0312, -0.0489, -0.0135, 0.12),
    ("a_l", "spheres", 0.0021, -0.0018, 0.0060, 0.0),
    ("a_n + a_t", "polyhedra", 1.0301, 0.9801, 1.0801, 0.88),
    ("a_n + a_t", "spheres", 0.3302, 0.3101, 0.3503, 0.26),
    ("a_t", "polyhedra", 0.4701, 0.4402, 0.5003, None),
    ("a_t", "spheres", 0.0705, 0.0650, 0.0760, 0.05),
    ("(2/5)(a+a_l+a_n+a_t)", "polyhedra", 0.4409, 0.4208, 0.4610, 0.43),
    ("(2/5)(a+a_l+a_n+a_t)", "spheres", 0.2488, 0.2381, 0.2595, 0.2),
    ("proportion of simple contacts", "polyhedra", 0.71, 0.70, 0.72, 0.7),
    ("proportion of double contacts", "polyhedra", 0.27, 0.26, 0.28, 0.15),
    ("proportion of triple contacts", "polyhedra", 0.02, 0.01, 0.03, 0.15),
]
# (count, seeds, factor, verdict, VF, EE, VF_shift, EE_shift)
CLAIM6 = [
    ("points", 3, 0.5, "not reproduced", "+0.029 [0.014, 0.044]", "+0.083 [0.070, 0.096]",
     "+0.001 [-0.003, 0.005] stable", "+0.003 [-0.002, 0.008] stable"),
    ("points", 3, 1.0, "not reproduced", "+0.028 [0.014, 0.043]", "+0.080 [0.069, 0.091]", None, None),
    ("points", 3, 2.0, "not reproduced", "+0.026 [0.012, 0.040]", "+0.075 [0.063, 0.087]",
     "-0.002 [-0.006, 0.002] stable", "-0.005 [-0.009, -0.001] stable"),
    ("commonplane", 3, 0.5, "inconclusive", "-0.007 [-0.022, 0.008]", "+0.002 [-0.021, 0.025]",
     "+0.019 [0.009, 0.030] undecided", "+0.038 [0.018, 0.058] moves"),
    ("commonplane", 3, 1.0, "reproduced", "-0.026 [-0.043, -0.010]", "-0.036 [-0.069, -0.003]", None, None),
    ("commonplane", 3, 2.0, "inconclusive", "-0.017 [-0.044, 0.011]", "-0.064 [-0.124, -0.004]",
     "+0.009 [-0.010, 0.028] undecided", "-0.028 [-0.080, 0.024] undecided"),
]


def make_study(folder, claim6=True, seeds=3):
    """A study folder as make study leaves it, with known numbers."""
    rep = folder / "report"
    rep.mkdir(parents=True)
    pd.DataFrame(CLAIMS, columns=["id", "claim", "verdict", "numbers", "basis"]).to_csv(rep / "claims.csv",
                                                                                       index=False)
    comp = pd.DataFrame(COMPARISON, columns=["quantity", "sample", "ours", "ci_low", "ci_high", "published"])
    comp.insert(5, "interval", "seeds")
    comp.to_csv(rep / "comparison.csv", index=False)
    if claim6:
        c6 = pd.DataFrame(CLAIM6, columns=["count", "seeds", "factor", "verdict", "VF", "EE", "VF_shift", "EE_shift"])
        c6["numbers"] = "FF mean force / mean 1.21 [1.20, 1.22] (> 1)"
        c6.to_csv(rep / "claim6.csv", index=False)
    (rep / "fig_qp.png").write_bytes(b"\x89PNG not really")
    manifest = {}
    for s in ("polyhedra", "spheres"):
        (folder / f"{s}-ensemble").mkdir()
        (folder / f"{s}-ensemble" / "params.json").write_text(json.dumps({"preset": "default", "sample": s}))
        manifest[s] = [{"label": f"seed {k}", "dump": f"{s}-ensemble/{s}-seed{k}.h5", "status": "ok"}
                       for k in range(1, seeds + 1)]
    manifest["spheres"].append({"label": "seed 9", "dump": "spheres-ensemble/spheres-seed9.h5",
                                "status": "run failed (3)"})
    (folder / "manifest.json").write_text(json.dumps(manifest))
    return folder


def test_collect_reads_the_three_tables_and_the_manifest(tmp_path):
    res = R.collect(str(make_study(tmp_path / "study")))
    assert res["study"] == {"preset": "default", "seeds": {"polyhedra": 3, "spheres": 3},
                            "runs": {"polyhedra": {"ok": 3}, "spheres": {"ok": 3, "failed": 1}}}
    assert [c["verdict"] for c in res["claims"]] == [c[2] for c in CLAIMS]
    row = next(r for r in res["comparison"] if r["quantity"] == "a_l" and r["sample"] == "polyhedra")
    assert (row["ours"], row["ci_low"], row["ci_high"], row["published"]) == (-0.0312, -0.0489, -0.0135, 0.12)
    # a missing published value is null in the JSON, not NaN (which JSON does not have)
    assert next(r for r in res["comparison"] if r["quantity"] == "a_t" and r["sample"] == "polyhedra")[
        "published"] is None
    assert len(res["claim6"]) == 6 and res["claim6"][1]["VF_shift"] is None
    json.dumps(res, allow_nan=False)
    assert res["about"].startswith("Results of the default study (make study)")
    # another preset's study says which, with its seeds
    other = make_study(tmp_path / "other", seeds=6)
    for s in ("polyhedra", "spheres"):
        (other / f"{s}-ensemble" / "params.json").write_text(json.dumps({"preset": "intermediate", "sample": s}))
    assert R.collect(str(other))["about"].startswith("Results of a study on the intermediate preset (6 + 6 seeds)")


def test_the_claims_table_quotes_the_results(tmp_path):
    lines = R.claims_table(R.collect(str(make_study(tmp_path / "study"))))
    assert lines[0].startswith("| # | the paper's claim |") and "over 3 + 3 seeds" in lines[0]
    assert len(lines) == 2 + 5 + 2
    one = lines[2].split(" | ")
    assert one[2] == "q/p plateau 0.46 / 0.23"
    assert one[3] == "q/p plateau 0.44 [0.40, 0.48] / 0.25 [0.24, 0.26]"
    assert one[4] == "reproduced |"
    three = lines[4].split(" | ")
    assert three[3] == "a_l −0.03 [−0.05, −0.01] / 0.00 [−0.00, 0.01]" and three[4] == "inconclusive |"
    four = lines[5].split(" | ")
    assert four[2] == "a_n + a_t 0.88 / 0.26; a_t – / 0.05"
    five = lines[6].split(" | ")
    assert five[2] == "(2/5)(a+a_l+a_n+a_t) 0.43 / 0.20; q/p plateau 0.46 / 0.23"
    points, common = lines[7], lines[8]
    assert "our contact-point count" in points and "VF +0.028 [0.014, 0.043] axial, EE +0.080 [0.069, 0.091] axial" in points
    assert "VF stable/stable, EE stable/stable" in points and points.endswith("| not reproduced |")
    assert "the earlier band count on a common plane" in common and "VF −0.026 [−0.043, −0.010] lateral" in common
    assert "VF undecided/undecided, EE moves/undecided" in common and common.endswith("| reproduced |")
    assert "simple / double / triple contacts 0.70 / 0.15 / 0.15" in points


def test_without_claim6_csv_claim6_comes_from_claims_csv(tmp_path):
    lines = R.claims_table(R.collect(str(make_study(tmp_path / "study", claim6=False))))
    assert len(lines) == 2 + 6
    assert lines[-1].endswith("| not reproduced |") and "2.46 [2.30, 2.62] (> 1) / x" in lines[-1]


def test_postproc_results_writes_the_file_the_table_and_the_figure(tmp_path, capsys):
    study = make_study(tmp_path / "study")
    readme = tmp_path / "README.md"
    readme.write_text("# Title\n\nbefore\n\n" + R.readme_block(None) + "\n\nafter\n")
    out = tmp_path / "data" / "default-study.json"
    fig = tmp_path / "qp.png"
    assert main(["results", str(study), "--out", str(out), "--readme", str(readme), "--figure", str(fig)]) == 0
    assert "claims table rewritten" in capsys.readouterr().err
    written = json.loads(out.read_text())
    assert written == R.collect(str(study))
    text = readme.read_text()
    assert text.startswith("# Title\n\nbefore\n\n" + R.BEGIN) and text.endswith(R.END + "\n\nafter\n")
    assert R.readme_table(text) == R.readme_block(written)
    assert R.PENDING not in text and "q/p plateau 0.44 [0.40, 0.48]" in text
    assert fig.read_bytes() == b"\x89PNG not really"
    # again: same file, same README
    assert main(["results", str(study), "--out", str(out), "--readme", str(readme)]) == 0
    assert "unchanged" in capsys.readouterr().err
    # the numbers change: the table follows
    comp = pd.read_csv(study / "report" / "comparison.csv")
    comp.loc[0, "ours"] = 0.5123
    comp.to_csv(study / "report" / "comparison.csv", index=False)
    assert main(["results", str(study), "--out", str(out), "--readme", str(readme)]) == 0
    assert "q/p plateau 0.51 [0.40, 0.48]" in readme.read_text()


@pytest.mark.parametrize("damage, message", [
    (lambda st: os.remove(st / "report" / "claims.csv"), "claims.csv: missing"),
    (lambda st: pd.read_csv(st / "report" / "comparison.csv").drop(columns="published").to_csv(
        st / "report" / "comparison.csv", index=False), "comparison.csv: no column 'published'"),
    (lambda st: pd.read_csv(st / "report" / "claims.csv").iloc[:5].to_csv(
        st / "report" / "claims.csv", index=False), "the claims are not 1 to 6"),
    (lambda st: (st / "manifest.json").write_text("{"), "manifest.json: not valid JSON"),
])
def test_a_bad_report_is_one_line_and_writes_nothing(tmp_path, capsys, damage, message):
    study = make_study(tmp_path / "study")
    damage(study)
    out = tmp_path / "r.json"
    with pytest.raises(InputError, match=re.escape(message)):
        R.collect(str(study))
    assert main(["results", str(study), "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert message in err and len(err.splitlines()) == 1
    assert not out.exists()


def test_a_report_without_its_q_p_figure_writes_nothing(tmp_path, capsys):
    """A report written without figures (``--no-figures``) has no
    fig_qp.png: asked for the README's figure, results refuses in one
    line before writing its file."""
    study = make_study(tmp_path / "study")
    os.remove(study / "report" / "fig_qp.png")
    out = tmp_path / "r.json"
    assert main(["results", str(study), "--out", str(out), "--figure", str(tmp_path / "qp.png")]) == 2
    err = capsys.readouterr().err.strip()
    assert "fig_qp.png: missing (the report drew no q/p figure)" in err and len(err.splitlines()) == 1
    assert not out.exists() and not (tmp_path / "qp.png").exists()


def test_a_readme_without_the_markers_is_refused(tmp_path):
    readme = tmp_path / "README.md"
    readme.write_text("# no table\n")
    with pytest.raises(InputError, match="no generated claims table"):
        R.update_readme(str(readme), None)


def test_the_readme_table_is_the_committed_results():
    """The README's claims table is what reference_data/default-study.json
    gives (or says that no results are committed, when there is none)."""
    text = open(README).read()
    assert R.readme_table(text) == R.readme_block(R.load_results())


def test_the_readme_is_short_and_names_no_file_outside_the_repository():
    text = open(README).read()
    assert len(text.splitlines()) <= 160
    assert "shared/" not in text
    for target in re.findall(r"\]\(([^)#]+)(?:#[^)]*)?\)", text):
        if not target.startswith(("http://", "https://")):
            assert os.path.exists(os.path.join(ROOT, target)), target


def test_compare_results_says_same_or_lists_what_differs(tmp_path, capsys):
    """``postproc compare-results``: a study against the committed file
    written from it is "same as the README" (exit 0); a number moved below
    the table's precision is still the same; a changed verdict, a number
    moved at the table's precision and a changed claim-6 leaning are listed,
    one line each (exit 1); no committed file or no report: one line, exit 2."""
    study = make_study(tmp_path / "study")
    ref = tmp_path / "ref.json"
    assert main(["results", str(study), "--out", str(ref)]) == 0
    capsys.readouterr()
    assert main(["compare-results", str(study), "--reference", str(ref)]) == 0
    assert capsys.readouterr().out.startswith("same as the README: every verdict")
    rep = study / "report"
    comp = pd.read_csv(rep / "comparison.csv")
    row = (comp["quantity"] == "a_l") & (comp["sample"] == "polyhedra")
    comp.loc[row, "ours"] = -0.0314                      # -0.03 at two decimals, as before: the same
    comp.to_csv(rep / "comparison.csv", index=False)
    assert main(["compare-results", str(study), "--reference", str(ref)]) == 0
    capsys.readouterr()
    comp.loc[row, ["ours", "ci_low", "ci_high"]] = [-0.0412, -0.0521, -0.0303]
    comp.to_csv(rep / "comparison.csv", index=False)
    claims = pd.read_csv(rep / "claims.csv")
    claims.loc[claims["id"] == 3, "verdict"] = "not reproduced"
    claims.to_csv(rep / "claims.csv", index=False)
    c6 = pd.read_csv(rep / "claim6.csv")
    c6.loc[(c6["count"] == "commonplane") & (c6["factor"] == 1.0), "EE"] = "-0.010 [-0.040, 0.020]"
    c6.to_csv(rep / "claim6.csv", index=False)
    assert main(["compare-results", str(study), "--reference", str(ref)]) == 1
    out = capsys.readouterr().out.splitlines()
    assert out[0].endswith("in 3 place(s):")
    assert out[1:4] == ["  claim 3: not reproduced (committed: inconclusive)",
                        "  a_l, polyhedra: −0.04 [−0.05, −0.03] (committed: −0.03 [−0.05, −0.01])",
                        "  claim 6 (commonplane, factor 1) EE: -0.010 [-0.040, 0.020] (committed: "
                        "-0.036 [-0.069, -0.003])"]
    assert "another machine" in out[4]
    assert main(["compare-results", str(study), "--reference", str(tmp_path / "none.json")]) == 2
    assert main(["compare-results", str(tmp_path / "nothing"), "--reference", str(ref)]) == 2
    err = capsys.readouterr().err
    assert err.count("postproc: error:") == 2 and "Traceback" not in err


def test_runs_are_counted_by_their_state_not_all_as_failed(tmp_path):
    """A study collected while it runs lists running, resumable and not
    started runs: they are counted as such. A manifest with a "state" per
    run is read by it; one written before that field, by its status text."""
    folder = make_study(tmp_path / "study")
    manifest = json.loads((folder / "manifest.json").read_text())
    texts = {"running: pid 12 on host a (step 9)": "running", "resumable at step 120 (b.ckpt)": "resumable",
             "not started": "not started", "pending: SLURM job 7_3, PENDING, Priority": "pending",
             "unfinished, no checkpoint (killed)": "unfinished", "failed: killed (SIGTERM)": "failed",
             "refused, not analysed: snapshot 3 does not add up": "refused",
             "invalid line: no seed": "invalid", "analysis failed (NaN)": "failed"}
    extra = [{"label": f"seed {10 + k}", "dump": None, "status": t} for k, t in enumerate(texts)]
    manifest["polyhedra"] += extra
    (folder / "manifest.json").write_text(json.dumps(manifest))
    want = {"ok": 3, "running": 1, "resumable": 1, "not started": 1, "pending": 1, "unfinished": 1,
            "failed": 2, "refused": 1, "invalid": 1}
    assert R.collect(str(folder))["study"]["runs"]["polyhedra"] == want
    # the state field wins over the text
    manifest["polyhedra"] = [{**e, "state": "running"} for e in manifest["polyhedra"][:3]]
    (folder / "manifest.json").write_text(json.dumps(manifest))
    assert R.collect(str(folder))["study"]["runs"]["polyhedra"] == {"running": 3}
    assert R.collect(str(folder))["study"]["seeds"]["polyhedra"] == 0
