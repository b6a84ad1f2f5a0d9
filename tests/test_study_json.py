"""A study's JSON files (manifest, run info and parameters, schedule) when
they are malformed: one line naming the file, never a traceback; the
report is still written when only a run's file is bad."""
import json
import os

import pytest

from postproc.cli import main
from postproc.errors import InputError, read_json, read_json_object
from postproc.study.manifest import read_manifest
from postproc.study.report import build_report

RUN = {"label": "seed 1", "dump": "polyhedra-ensemble/polyhedra-seed1.h5",
       "analysis": "polyhedra-ensemble/analysis-polyhedra-seed1",
       "info": "polyhedra-ensemble/polyhedra-seed1.info.json", "status": "failed: exit 1"}


@pytest.mark.parametrize("text, message", [
    ('{"runs": [', r"not valid JSON \(Expecting value at line 1, column 11\), so not a thing"),
    ('{\n  "a": 1,\n  "b": }', r"at line 3, column 8\)"),
    (b'{"a": "\xff"}', r"not UTF-8 text \(byte 7\), so not a thing"),
    ("[" * 200000, r"nested too deeply|not valid JSON"),
])
def test_read_json_names_the_file_and_the_fault(tmp_path, text, message):
    path = tmp_path / "x.json"
    path.write_bytes(text if isinstance(text, bytes) else text.encode())
    with pytest.raises(InputError, match=message) as err:
        read_json(str(path), "thing")
    assert str(err.value).startswith(str(path)) and "\n" not in str(err.value)


def test_read_json_other_faults(tmp_path):
    with pytest.raises(InputError, match="no such file"):
        read_json(str(tmp_path / "none.json"))
    with pytest.raises(InputError, match="cannot read the thing"):
        read_json(str(tmp_path), "thing")                  # a folder
    (tmp_path / "l.json").write_text("[1, 2]")
    with pytest.raises(InputError, match=r"not a thing \(a JSON list, not an object\)"):
        read_json_object(str(tmp_path / "l.json"), "thing")
    (tmp_path / "u.json").write_bytes('{"ε": "σ0"}'.encode())
    assert read_json_object(str(tmp_path / "u.json")) == {"ε": "σ0"}   # UTF-8 whatever the locale


@pytest.mark.parametrize("manifest, message", [
    ([1, 2], r"its top level is a list"),
    ({"polyhedra": {"label": "seed 1"}}, r"sample 'polyhedra' is not a list of runs"),
    ({"polyhedra": [RUN, {**RUN, "status": 3}]}, r"run 2 of 'polyhedra' has no text status"),
    ({"spheres": [{k: v for k, v in RUN.items() if k != "label"}]}, r"run 1 of 'spheres' has no text label"),
    ({"polyhedra": [{**RUN, "dump": 7}]}, r"run 1 of 'polyhedra': dump is not a path"),
    ({"polyhedra": [{**RUN, "counts": ["lmgc90"]}]}, r"counts is not an object of paths"),
])
def test_a_manifest_of_the_wrong_shape_is_named(tmp_path, capsys, manifest, message):
    path = tmp_path / "manifest.json"
    path.write_text(json.dumps(manifest))
    with pytest.raises(InputError, match=message):
        read_manifest(str(path))
    for argv in (["report", str(tmp_path), "--no-figures"],
                 ["results", str(tmp_path), "--out", str(tmp_path / "r.json")],
                 ["investigate", "size-front", str(tmp_path), "--out", str(tmp_path / "front")]):
        assert main(argv) == 2, argv
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and "not a study manifest" in err[0] and "Traceback" not in err[0], (argv, err)


def test_a_valid_manifest_is_read_as_written(tmp_path):
    good = {"polyhedra": [RUN, {**RUN, "label": "seed 2", "status": "ok", "info": None,
                                "counts": {"lmgc90": "polyhedra-ensemble/analysis-lmgc90"}}],
            "spheres": []}
    path = tmp_path / "manifest.json"
    path.write_text(json.dumps(good))
    assert read_manifest(str(path)) == good


def test_the_report_is_written_beside_bad_run_files(tmp_path):
    """A run's unreadable info or parameters, and a schedule of the wrong
    shape, are listed under the report's Problems; the report is written."""
    (tmp_path / "polyhedra-ensemble").mkdir()
    (tmp_path / "manifest.json").write_text(json.dumps({"polyhedra": [RUN]}))
    (tmp_path / "polyhedra-ensemble" / "polyhedra-seed1.info.json").write_text('{"steps": ')
    (tmp_path / "polyhedra-ensemble" / "params.json").write_text("[1]")
    (tmp_path / "schedule.json").write_text(json.dumps({"summary": {"makespan_s": 5}}))
    md = open(build_report(str(tmp_path), figures=False)).read()
    problems = md.split("**Problems**")[1].split("\n## ")[0]
    info = os.path.join(str(tmp_path), RUN["info"])
    assert f"{info}: not valid JSON (Expecting value at line 1, column 11), so not a run info file" in problems
    assert "params.json: not a run parameters file (a JSON list, not an object)" in problems
    assert "schedule.json: not a schedule of the pool's shape (KeyError: 'cores')" in problems
    assert "S1's grains are not described" in md
    # valid JSON of the wrong shape: named too, the report still written
    (tmp_path / "polyhedra-ensemble" / "polyhedra-seed1.info.json").write_text('{"host": "node17", "steps": "x"}')
    md = open(build_report(str(tmp_path), figures=False)).read()
    assert "the runs' info files are not of the study's shape" in md.split("**Problems**")[1]


def test_a_run_count_of_grains_that_is_no_count_is_named(tmp_path):
    """The size front reads N from each run's params.json: a fraction, NaN,
    Infinity, text, a bool or an integer too large for a float is named in
    one line, never an OverflowError; a whole float is taken."""
    from postproc.study.sizefront import _n_particles

    run = {"dump": str(tmp_path / "run.h5")}
    pj = tmp_path / "params.json"
    for good, n in (("5000", 5000), ("5000.0", 5000)):
        pj.write_text('{"n_particles": %s}' % good)
        assert _n_particles(run) == n
    for bad in ("2.5", "NaN", "Infinity", '"5000"', "true", "1" + "0" * 400, "0"):
        pj.write_text('{"n_particles": %s}' % bad)
        with pytest.raises(InputError, match=r"params.json: n_particles .* is not a number of grains"):
            _n_particles(run)
