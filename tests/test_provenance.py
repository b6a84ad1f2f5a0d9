"""What an analysis was made from (postproc.provenance): an analysis is
current only for the same input files, options and code, and the study
keeps a current analysis instead of making it again."""
import json
import os

import pytest

from builders import lattice_snapshot, write_snapshot
from postproc import provenance
from postproc.pipeline import AnalysisOptions, analyze_path
from postproc.schema import DumpWriter


def _dump(path, n=4):
    """A spheres dump: one isotropic snapshot, then n - 1 of shear."""
    with DumpWriter(str(path), "spheres", {}) as w:
        for k in range(n):
            snap, _, _ = lattice_snapshot()
            write_snapshot(w, snap, step=k, stage="isotropic" if k == 0 else "shear")
    return str(path)


#: the analysis options of these tests: numbers only (figures: their own test below)
BARE = AnalysisOptions(figures=False)


@pytest.fixture
def analysed(tmp_path):
    dump = _dump(tmp_path / "run.h5")
    out = str(tmp_path / "analysis")
    analyze_path(dump, out, BARE, progress=False)
    return dump, out


def test_an_analysis_records_its_source_and_is_current(analysed):
    dump, out = analysed
    rec = json.load(open(os.path.join(out, provenance.SOURCE_FILE)))
    st = os.stat(dump)
    assert rec["input"] == [["run.h5", st.st_size, st.st_mtime_ns]]
    assert rec["options"]["types"] == "points" and rec["options"]["errors"] is True
    assert rec["code"] == provenance.code_hash() and len(rec["code"]) == 64
    assert provenance.is_current(dump, out, BARE)


def test_the_analysis_version_not_the_code_hash_decides(analysed):
    """Another code hash of today's version is current; a record with no
    version reads its code hash through HISTORICAL_CODE_VERSIONS (the
    committed archive's c237acd4... is version 1); an unknown hash or
    another version is not current."""
    dump, out = analysed
    path = os.path.join(out, provenance.SOURCE_FILE)
    rec = json.load(open(path))
    assert rec["version"] == provenance.ANALYSIS_VERSION == 1

    def with_(**kw):
        new = {k: v for k, v in rec.items() if k not in kw or kw[k] is not None}
        new.update({k: v for k, v in kw.items() if v is not None})
        if kw.get("version", 0) is None:
            new.pop("version", None)
        json.dump(new, open(path, "w"))
        return provenance.is_current(dump, out, BARE)

    assert with_(code="f" * 64)                                         # an edit that moved no number
    old = "c237acd4bb6279825166a98265fa3598662f8f292f25a36eade50abedecce914"
    assert provenance.HISTORICAL_CODE_VERSIONS[old] == 1
    assert with_(code=old, version=None)                                # written before versions: version 1
    assert not with_(code="0" * 64, version=None)                       # no version, unknown hash
    assert not with_(version=2)
    assert not with_(version="1")                                       # not an integer: unknown
    assert provenance.version_of({"code": old}) == 1 and provenance.version_of([]) is None


def test_another_dump_other_options_or_no_record_is_not_current(analysed):
    dump, out = analysed
    assert not provenance.is_current(dump, out, AnalysisOptions(errors=False, figures=False))
    assert not provenance.is_current(dump, out, AnalysisOptions(snapshots=(0, 1), figures=False))
    st = os.stat(dump)
    os.utime(dump, ns=(st.st_atime_ns, st.st_mtime_ns + 1))          # the dump was rewritten
    assert not provenance.is_current(dump, out, BARE)
    analyze_path(dump, out, BARE, progress=False)
    assert provenance.is_current(dump, out, BARE)
    os.remove(os.path.join(out, provenance.SOURCE_FILE))               # made before records existed
    assert not provenance.is_current(dump, out, BARE)
    open(os.path.join(out, provenance.SOURCE_FILE), "w").write("{not json")
    assert not provenance.is_current(dump, out, BARE)
    assert not provenance.is_current(dump + ".missing", out, BARE)


def test_a_dump_in_parts_counts_its_parts(tmp_path):
    dump = _dump(tmp_path / "run.h5")
    parts = tmp_path / "run.h5.parts"
    parts.mkdir()
    (parts / "snapshot_000004.h5").write_bytes(b"x" * 10)
    files = provenance.input_files(dump)
    assert [f[0] for f in files] == ["run.h5", "snapshot_000004.h5"] and files[1][1] == 10


def test_the_code_hash_follows_every_source_file(tmp_path, monkeypatch):
    """An edit to the code of any source file of the packages changes the
    hash; a compiled build or cache folder, a comment or a docstring does
    not."""
    pkg = tmp_path / "fakepkg"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "__init__.py").write_text('"""A package."""\n\n\ndef f(x):\n    """Twice x."""\n    return 2 * x\n')
    (pkg / "sub" / "kernel.c").write_text("int f(void) { return 1; }\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.setattr(provenance, "PACKAGES", ("fakepkg",))
    h = provenance.code_hash.__wrapped__
    first = h()
    (pkg / "_build").mkdir()
    (pkg / "_build" / "kernel.c").write_text("generated")
    assert h() == first
    (pkg / "__init__.py").write_text('"""A package, said otherwise."""\n\n\ndef f(x):  # doubles\n'
                                     '    """x doubled."""\n\n    return 2 * x\n')
    assert h() == first
    (pkg / "__init__.py").write_text('def f(x):\n    return 3 * x\n')
    assert h() != first
    second = h()
    (pkg / "sub" / "kernel.c").write_text("int f(void) { return 2; }\n")
    assert h() not in (first, second)


def test_the_study_keeps_a_current_analysis(analysed, capsys):
    from yade_scripts.campaign.study import analyse_dump

    dump, out = analysed
    mtime = os.path.getmtime(os.path.join(out, "summary.csv"))
    assert analyse_dump(dump, out, figures=False) is None
    assert "is up to date (same dump, options and code), kept" in capsys.readouterr().out
    assert os.path.getmtime(os.path.join(out, "summary.csv")) == mtime
    assert analyse_dump(dump, out, errors=False, figures=False) is None    # other options: made again
    assert "up to date" not in capsys.readouterr().out
    assert os.path.getmtime(os.path.join(out, "summary.csv")) > mtime


def test_analyse_refuses_a_dump_that_is_not_complete(tmp_path, capsys):
    from yade_scripts.campaign.study import main

    assert main(["--analyse", str(tmp_path / "nothing.h5")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "not a complete dump" in err[0]
    dump = _dump(tmp_path / "run.h5")                 # written and closed: complete
    assert main(["--analyse", dump, "--no-figures"]) == 0
    assert os.path.exists(tmp_path / "analysis" / "summary.csv") and not list(tmp_path.rglob("*.png"))
    assert main(["--analyse", dump, "--no-figures"]) == 0
    assert "is up to date" in capsys.readouterr().out


def test_without_figures_the_same_files_but_the_figures(tmp_path):
    """``figures=False`` writes every file of the analysis but the figures,
    byte for byte the same (source.json but its options' flag); an
    analysis with figures is current for one asked without them, not the
    reverse; and an analysis without figures removes the figures an
    earlier one left in its folder."""
    from postproc.pipeline import FIGURE_FILES

    dump = _dump(tmp_path / "run.h5")
    out, bare = str(tmp_path / "drawn"), str(tmp_path / "bare")
    analyze_path(dump, out, AnalysisOptions(), progress=False)
    analyze_path(dump, bare, BARE, progress=False)
    drawn = sorted(os.listdir(out))
    assert {"qp_sff.png", "networks.png"} <= set(drawn) and set(drawn) - set(FIGURE_FILES) == set(os.listdir(bare))
    for name in os.listdir(bare):
        a, b = (open(os.path.join(d, name), "rb").read() for d in (out, bare))
        if name == provenance.SOURCE_FILE:            # recorded only when off: a default record is as before
            a, b = json.loads(a), json.loads(b)
            assert "figures" not in a["options"] and b["options"].pop("figures") is False
        assert a == b, name
    assert provenance.is_current(dump, out, AnalysisOptions()) is True
    assert provenance.is_current(dump, out, AnalysisOptions(figures=False)) is True
    assert provenance.is_current(dump, bare, AnalysisOptions()) is False
    analyze_path(dump, out, AnalysisOptions(figures=False), progress=False)
    assert sorted(os.listdir(out)) == sorted(os.listdir(bare))
