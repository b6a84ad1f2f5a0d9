"""The registry of contact-type criteria (postproc.classify.CRITERIA) is the
one place a criterion is named: the command line's --types choices and
help, the analysis options, the claims' and the results' names of a count
read it, and a criterion added to it alone is offered and run everywhere."""
import ast
import dataclasses
import os

import numpy as np
import pandas as pd
import pytest

from postproc import classify
from postproc.classify import CRITERIA, DEFAULT_METHOD, Classes, Classifier, Criterion, check_options
from postproc.cli import main
from postproc.errors import InputError

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
#: the modules that read the registry and must not name a criterion themselves
READERS = ("postproc/cli.py", "postproc/pipeline.py", "postproc/study/results.py", "postproc/study/claims.py")


def _all_ff(classifier, snap, variants):
    """A test's criterion: every polyhedra pair face to face."""
    base = classifier._angular_classes(snap, variants)
    lab = np.where(base.poly, "FF", base.labels)
    return Classes(lab, {"lo": lab, "hi": lab} if variants else {}, base.poly, None,
                   {"ct_method": classifier.method, "ct_threshold": classifier.tolerance,
                    "ct_theta_deg": classifier.theta_deg})


DUMMY = Criterion("all-ff", "every polyhedra pair face to face (a test's)", "--tolerance",
                  "beta, a test's parameter", 0.3, "(beta)", "the all-FF count, beta {:g}", "the all-FF count",
                  _all_ff, lambda tol: classify.cpm.check_alpha(tol))


def string_names(path, names, skip=()):
    """[(line, name)] of the string constants of a module's code equal to a
    criterion's name (dictionary keys read with ``x["points"]`` left out),
    outside the top-level statements whose line range is in ``skip``."""
    tree = ast.parse(open(os.path.join(ROOT, path)).read())
    keys = {id(n.slice) for n in ast.walk(tree) if isinstance(n, ast.Subscript)}
    out = []
    for n in ast.walk(tree):
        if isinstance(n, ast.Constant) and isinstance(n.value, str) and n.value in names and id(n) not in keys:
            if not any(a <= n.lineno <= b for a, b in skip):
                out.append((n.lineno, n.value))
    return out


def _help(capsys, *argv):
    """A command's help, without its white space (argparse wraps lines, at
    hyphens too); compare with :func:`_bare` strings."""
    with pytest.raises(SystemExit):
        main(list(argv) + ["--help"])
    return _bare(capsys.readouterr().out)


def _bare(text):
    return "".join(text.split())


def test_the_registry_drives_the_command_line(capsys):
    for cmd in ("analyze", "export-vtk"):
        text = _help(capsys, cmd)
        assert "{" + ",".join(CRITERIA) + "}" in text, cmd
        assert _bare(f"(default {DEFAULT_METHOD})") in text or cmd == "analyze"
    text = _help(capsys, "analyze")
    for c in CRITERIA.values():
        assert _bare(f"{c.name}, {c.description}") in text, c.name
        if c.option == "--tolerance":
            assert _bare(f"{c.parameter} (default {c.default:g})") in text, c.name
    assert list(CRITERIA)[0] == DEFAULT_METHOD


@pytest.mark.parametrize("path", READERS)
def test_no_reader_names_a_criterion(path):
    assert not string_names(path, set(CRITERIA)), f"{path} names criteria; read postproc.classify.CRITERIA"


def test_classify_names_them_only_in_the_registry():
    tree = ast.parse(open(os.path.join(ROOT, "postproc/classify.py")).read())
    allowed = [(n.lineno, n.end_lineno) for n in tree.body
               if (isinstance(n, ast.Assign) and any(getattr(t, "id", None) in ("CRITERIA", "DEFAULT_METHOD")
                                                     for t in n.targets))
               or (isinstance(n, ast.ClassDef) and n.name == "AngularTables")]      # the angular criterion itself
    assert len(allowed) == 3
    assert not string_names("postproc/classify.py", set(CRITERIA), allowed)


def test_the_name_check_can_fail(tmp_path, monkeypatch):
    """A reader that spells a criterion out is caught."""
    bad = tmp_path / "postproc"
    bad.mkdir()
    (bad / "reader.py").write_text('TYPES = ("points", "lmgc90")\nx = {}\ny = x["points"]\n')
    monkeypatch.setattr(__import__(__name__), "ROOT", str(tmp_path))
    assert string_names("postproc/reader.py", set(CRITERIA)) == [(1, "points"), (1, "lmgc90")]


def test_a_criterion_added_to_the_registry_is_offered_and_run(capsys, monkeypatch):
    monkeypatch.setitem(CRITERIA, DUMMY.name, DUMMY)
    # the command line offers it, with its description and parameter
    text = _help(capsys, "analyze")
    assert "{" + ",".join(CRITERIA) + "}" in text and ",all-ff}" in text
    assert _bare("all-ff, every polyhedra pair face to face (a test's)") in text
    assert _bare("beta, a test's parameter (default 0.3)") in text
    assert "all-ff" in _help(capsys, "export-vtk")
    # the options take it, and its tolerance check is its own
    check_options(DUMMY.name, tolerance=0.2)
    with pytest.raises(InputError, match="alpha"):
        check_options(DUMMY.name, tolerance=-1)
    # the classifier runs its implementation, with its default parameter
    from shapes.polyhedron import geometric_faces
    from test_footprint_types import CASES, SHAPES, _pairs, _snapshot

    shapes = [(v, t, geometric_faces(v, t)) for v, t in SHAPES]
    clf = Classifier(tuple(map(list, zip(*shapes))), method=DUMMY.name)
    assert clf.parameter == 0.3
    res = clf.classify(_snapshot(_pairs(list(CASES.values())[:3], 1e-3)))
    assert res.poly.sum() == 3 and set(res.labels[res.poly]) == {"FF"}
    # the claims name it as the registry does
    from postproc.study import claims

    df = pd.DataFrame({"ct_method": [DUMMY.name], "ct_threshold": [0.3], "ct_theta_deg": [5.0]})
    assert claims._criterion_text(df) == "the all-FF count, beta 0.3"
    assert claims._criterion_text(df, "lo") == "the all-FF count, beta 0.15"


def test_an_unknown_criterion_is_one_line():
    with pytest.raises(InputError) as e:
        check_options("nope")
    assert str(e.value) == f"--types must be one of {', '.join(CRITERIA)}, got 'nope'"
    with pytest.raises(InputError):
        classify.criterion(["points"])


def test_every_entry_is_complete():
    for name, c in CRITERIA.items():
        assert c.name == name and c.option in ("--tolerance", "--threshold", "--theta")
        assert all(getattr(c, f.name) not in (None, "") for f in dataclasses.fields(c)), name
        assert "{:g}" in c.reading and callable(c.classify) and callable(c.check)
