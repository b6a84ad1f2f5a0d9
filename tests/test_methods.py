"""postproc compare-methods (postproc.study.methods, .methodsreadme): the
claims and the contact types of a YADE study beside a CD one, on hand-built
studies whose verdicts and proportions are known."""
import json
import os

import numpy as np
import pandas as pd
import pytest

from postproc.cli import main
from postproc.errors import InputError
from postproc.study import methodsreadme, results
from postproc.study.claims import claim6_groups
from postproc.study.methods import compare_methods, read_study, run_settings, write_methods

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAPER = json.load(open(os.path.join(ROOT, "reference_data", "paper_values.json")))

S1 = dict(q_over_p=0.46, a=0.08, a_l=0.12, a_n=0.50, a_t=0.38, sff=0.43,
          ct_fratio_FF=1.7, ct_fabric_FF=0.3, ct_fratio_VF=0.7, ct_fratio_EE=0.75,
          ct_fabric_VF=-0.2, ct_fabric_EE=-0.25, strong_frac_FF=0.3, weak_frac_FF=0.1)
S2 = dict(q_over_p=0.23, a=0.24, a_l=0.0, a_n=0.21, a_t=0.05, sff=0.21)
#: exact (noise-free) proportions: the plateau means are these
OURS = dict(ct_frac_simple=0.60, ct_frac_double=0.25, ct_frac_triple=0.15)
CD = dict(cd_alert_frac_simple=0.50, cd_alert_frac_double=0.30, cd_alert_frac_triple=0.20,
          cd_force_frac_simple=0.70, cd_force_frac_double=0.20, cd_force_frac_triple=0.10)
#: claim 6 by the CD counts (noisy, as the claims' columns): every point leans nowhere, force-carrying laterally
CD6 = dict(cd_alert_fratio_triple=1.6, cd_alert_fabric_triple=0.3, cd_alert_fratio_simple=0.8,
           cd_alert_fabric_simple=0.0, cd_alert_strong_frac_triple=0.3, cd_alert_weak_frac_triple=0.1,
           cd_force_fratio_triple=1.7, cd_force_fabric_triple=0.3, cd_force_fratio_simple=0.7,
           cd_force_fabric_simple=-0.2, cd_force_strong_frac_triple=0.3, cd_force_weak_frac_triple=0.1)


def _frame(noisy, exact, rng, n=12, top=0.3):
    df = pd.DataFrame({"snapshot": [str(k).zfill(6) for k in range(n)], "eps_q": np.linspace(0, top, n),
                       "stage": ["isotropic"] + ["shear"] * (n - 1)})
    df["eps_1"] = df["eps_q"]
    for k, v in noisy.items():
        df[k] = v + rng.normal(0, 0.005, n)
    for k, v in exact.items():
        df[k] = v
    df["q_axial_over_p"] = df["q_over_p"]
    if "ct_fratio_FF" in noisy:
        df["ct_method"], df["ct_threshold"] = "points", 0.5
    return df


def _study(folder, samples, partial=()):
    """A study folder: samples = {sample: [(noisy, exact), ...]}; the seeds
    listed in ``partial`` (sample, index) stopped at two thirds of the strain."""
    rng = np.random.default_rng(1)
    manifest = {}
    for s, seeds in samples.items():
        manifest[s] = []
        for k, (noisy, exact) in enumerate(seeds):
            short = (s, k) in partial
            label = f"{s}-seed{k + 1}"
            os.makedirs(os.path.join(folder, label, "analysis"))
            _frame(noisy, exact, rng, n=8 if short else 12, top=0.2 if short else 0.3).to_csv(
                os.path.join(folder, label, "analysis", "summary.csv"), index=False)
            run = {"label": f"seed {k + 1}", "status": "partial" if short else "ok",
                   "analysis": os.path.join(label, "analysis")}
            if short:
                run["partial"] = {"steady_from_eps_1": 0.15}
            manifest[s].append(run)
    with open(os.path.join(folder, "manifest.json"), "w") as fh:
        json.dump(manifest, fh)
    return folder


@pytest.fixture
def studies(tmp_path):
    yade = _study(tmp_path / "yade", {"polyhedra": [(S1, OURS)] * 3, "spheres": [(S2, {})] * 3})
    # CD: the polyhedra's q/p below the spheres' (claim 1 fails), one S1 seed partial
    cd = _study(tmp_path / "cd", {"polyhedra": [(dict(S1, q_over_p=0.20, **CD6), {**OURS, **CD})] * 3,
                                  "spheres": [(S2, {})] * 3}, partial={("polyhedra", 2)})
    return str(yade), str(cd)


def _rows(result, method):
    return {r["count"]: r for r in result["types"] if r["method"] == method}


def test_claim_1_holds_for_yade_and_fails_for_cd(studies, tmp_path):
    result = write_methods(*studies, str(tmp_path / "out"))
    c1 = result["claims"][0]
    assert (c1["YADE"]["verdict"], c1["CD"]["verdict"]) == ("reproduced", "not reproduced")
    assert [c["YADE"]["verdict"] for c in result["claims"]] == ["reproduced"] * 6
    assert c1["paper"] == "q/p plateau S1 0.46, S2 0.23"
    assert "polyhedra 0.20 [" in c1["CD"]["numbers"]
    assert result["studies"]["CD"]["samples"]["polyhedra"] == {"runs": 3, "usable": 3, "partial": 1}
    assert "1 of 3 runs partial" in result["studies"]["CD"]["note"]
    assert result["studies"]["YADE"]["note"] == "complete"
    md = open(tmp_path / "out" / "methods.md").read()
    assert "| 1. q/p of polyhedra is higher" in md and "reproduced | not reproduced" in md
    assert json.load(open(tmp_path / "out" / "methods.json")) == json.loads(json.dumps(result))


def test_contact_types_by_every_count(studies, tmp_path):
    result = write_methods(*studies, str(tmp_path / "out"))
    assert result["paper_types"] == [0.7, 0.15, 0.15]
    yade, cd = _rows(result, "YADE"), _rows(result, "CD")
    assert set(yade) == set(cd) == {"ours (points)", "cd-alert", "cd-force"}
    for rows in (yade, cd):
        ours = rows["ours (points)"]
        assert [ours[g]["mean"] for g in ("simple", "double", "triple")] == pytest.approx([0.60, 0.25, 0.15])
        assert ours["claim6"] == "reproduced" and ours["seeds"] == 3
    for count in ("cd-alert", "cd-force"):      # a YADE dump has no CD points
        assert yade[count]["simple"] is None and yade[count]["claim6"] is None
        assert yade[count]["reason"] == "no cd_* columns: not a CD dump (no CD contact points)"
    assert [cd["cd-force"][g]["mean"] for g in ("simple", "double", "triple")] == pytest.approx([0.7, 0.2, 0.1])
    assert [cd["cd-alert"][g]["mean"] for g in ("simple", "double", "triple")] == pytest.approx([0.5, 0.3, 0.2])
    # claim 6 by each CD count: force-carrying leans lateral; every point's simple leaning is 0 ("none")
    assert cd["cd-force"]["claim6"] == "reproduced"
    assert cd["cd-alert"]["claim6"] == "not reproduced" and "leaning none" in cd["cd-alert"]["claim6_numbers"]


def test_claim6_groups_conditions():
    rng = np.random.default_rng(0)
    frames = [_frame(dict(q_over_p=0.4, **CD6), {}, rng) for _ in range(3)]
    c = claim6_groups(frames, "cd_force_")
    assert c["conditions"] == [1, 1, 1, 1, 1] and c["verdict"] == "reproduced"
    flipped = [df.assign(cd_force_fratio_triple=0.8) for df in frames]
    assert claim6_groups(flipped, "cd_force_")["verdict"] == "not reproduced"
    assert claim6_groups(frames, "cd_nothing_")["verdict"] == "inconclusive"
    assert claim6_groups([], "cd_force_")["verdict"] == "inconclusive"


def test_an_s1_only_cd_study_and_a_missing_column(tmp_path):
    yade = _study(tmp_path / "yade", {"polyhedra": [(S1, OURS)] * 2, "spheres": [(S2, {})] * 2})
    cd_cols = {k: v for k, v in CD.items() if k != "cd_force_frac_double"}
    cd = _study(tmp_path / "cd", {"polyhedra": [(dict(S1, **CD6), {**OURS, **cd_cols})] * 2})
    result = compare_methods({"YADE": read_study(str(yade)), "CD": read_study(str(cd))}, PAPER)
    assert [c["CD"]["verdict"] for c in result["claims"]] == ["inconclusive"] * 5 + ["reproduced"]
    assert result["studies"]["CD"]["note"] == "no usable S2 run"
    force = _rows(result, "CD")["cd-force"]
    assert force["reason"] == "no column cd_force_frac_double" and force["triple"] is None
    assert _rows(result, "CD")["cd-alert"]["claim6"] == "not reproduced"


def test_no_s1_run_and_bad_input(tmp_path, capsys):
    yade = _study(tmp_path / "yade", {"polyhedra": [(S1, OURS)] * 2, "spheres": [(S2, {})] * 2})
    cd = _study(tmp_path / "cd", {"spheres": [(S2, {})] * 2})
    result = compare_methods({"YADE": read_study(str(yade)), "CD": read_study(str(cd))}, PAPER)
    rows = _rows(result, "CD")
    assert all(r["reason"] == "no usable S1 run" and r["simple"] is None for r in rows.values())
    with pytest.raises(InputError, match="not a study folder"):
        read_study(str(tmp_path))
    assert main(["compare-methods", str(yade), str(tmp_path / "none"), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "not a study folder (no manifest.json)" in err[0]


def test_readme_block_round_trip(studies, tmp_path):
    readme = tmp_path / "README.md"
    readme.write_text("# x\n\n" + results.readme_block(None) + "\n\nmore text\n")
    out, js = tmp_path / "out", tmp_path / "methods-small.json"
    assert main(["compare-methods", *studies, "--out", str(out), "--json", str(js), "--readme", str(readme)]) == 0
    text = readme.read_text()
    block = methodsreadme.readme_block(text)
    assert methodsreadme.block_source(text) == "methods-small.json"
    assert block == methodsreadme.block(methodsreadme.load(str(js)), "methods-small.json")
    assert text.index(results.END) < text.index(methodsreadme.BEGIN_PREFIX) < text.index("more text")
    assert "| 1 | q/p plateau S1 0.46, S2 0.23 | reproduced | not reproduced |" in block
    assert "| CD | cd-force | 0.70 [0.70, 0.70] | 0.20 [0.20, 0.20] | 0.10 [0.10, 0.10] | reproduced |" in block
    assert "| YADE | cd-alert |" not in block and "| YADE | cd-force |" not in block   # not applicable
    assert "| CD | cd-alert |" in block
    assert not methodsreadme.update_readme(str(readme), methodsreadme.load(str(js)), "methods-small.json")
    assert main(["compare-methods", *studies, "--out", str(out), "--readme", str(readme)]) == 2   # no --json
    broken = text.replace(methodsreadme.END, "")
    with pytest.raises(InputError, match="markers are broken"):
        methodsreadme.readme_block(broken)
    js.write_text('{"format": 99}')
    with pytest.raises(InputError, match="not a method comparison"):
        methodsreadme.load(str(js))


def test_committed_readme_and_methods_json_agree():
    """The README's by-method block is generated from the committed
    comparison its first line names."""
    text = open(os.path.join(ROOT, "README.md")).read()
    source = methodsreadme.block_source(text)
    assert source is not None and source.startswith("reference_data/methods-")
    assert methodsreadme.readme_block(text) == methodsreadme.block(methodsreadme.load(os.path.join(ROOT, source)),
                                                                   source)


def test_the_force_carrying_count_decides_only_at_a_converged_tolerance(studies):
    """At NLGS tolerance 1e-2 (above methods.FORCE_COUNT_TOL) the
    force-carrying count's proportions are shown and decide nothing; at
    1e-3 it decides as before; the README's first line says the size and
    the tolerance."""
    read = {"YADE": read_study(studies[0]), "CD": read_study(studies[1])}
    for tol, decided in ((0.01, None), (1e-3, "reproduced")):
        r = compare_methods(read, PAPER, settings={"YADE": {"grains": 1000, "nlgs_tol": None},
                                                   "CD": {"grains": None, "nlgs_tol": tol}})
        force = _rows(r, "CD")["cd-force"]
        assert force["claim6"] == decided and force["simple"]["mean"] == pytest.approx(0.70, abs=1e-12)
        assert (force["reason"] is None) == (decided is not None)
        assert _rows(r, "CD")["cd-alert"]["claim6"] is not None       # every point: decided at any tolerance
        line = methodsreadme.table(r)[0]
        assert line.startswith(f"At 1000 grains (CD at NLGS tolerance {tol:g}), the same grains")
    assert "above the 0.001 at which this count converges" in \
        _rows(compare_methods(read, PAPER, settings={"CD": {"grains": None, "nlgs_tol": 0.01}}), "CD")["cd-force"][
            "reason"]


def test_run_settings_read_beside_the_dumps(tmp_path):
    """The grains from a YADE ensemble's params.json, the tolerance from CD
    runs' run.params.json (the largest when they differ); None when nothing
    records them or a file is not JSON."""
    yade, cd1, cd2, bad = (tmp_path / n for n in ("polyhedra-ensemble", "cd1", "cd2", "bad"))
    for d in (yade, cd1, cd2, bad):
        d.mkdir()
    (yade / "params.json").write_text(json.dumps({"n_particles": 1000, "preset": "default"}))
    (cd1 / "run.params.json").write_text(json.dumps({"nlgs_tol": 0.01}))
    (cd2 / "run.params.json").write_text(json.dumps({"nlgs_tol": 0.001}))
    (bad / "run.params.json").write_text("{not json")
    runs = lambda *ds: {"polyhedra": [{"dump": str(d / "run.h5")} for d in ds]}     # noqa: E731
    assert run_settings(runs(yade, yade)) == {"grains": 1000, "nlgs_tol": None}
    assert run_settings(runs(cd1, cd2, bad)) == {"grains": None, "nlgs_tol": 0.01}
    assert run_settings({"spheres": [{"dump": str(cd1 / "run.h5")}]}) == {"grains": None, "nlgs_tol": None}
