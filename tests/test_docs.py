"""The documentation: docs/api.md is generated from the packages and lists
every module; the pages build without a single warning (``make docs``),
and the built API page has a section for every module."""
import importlib.util
import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def apigen():
    spec = importlib.util.spec_from_file_location("apigen", os.path.join(ROOT, "docs", "apigen.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def every_module():
    """Every module of the three packages, found here independently of
    docs/apigen.py: each .py file of a folder holding __init__.py."""
    found = set()
    for package in ("postproc", "shapes", "yade_scripts"):
        for dirpath, dirnames, filenames in os.walk(os.path.join(ROOT, package)):
            if "__init__.py" not in filenames:
                dirnames[:] = []
                continue
            dotted = os.path.relpath(dirpath, ROOT).replace(os.sep, ".")
            found |= {dotted if f == "__init__.py" else f"{dotted}.{f[:-3]}" for f in filenames if f.endswith(".py")}
    return found


def test_the_api_page_is_the_generated_one():
    with open(os.path.join(ROOT, "docs", "api.md")) as fh:
        assert fh.read() == apigen().render(), "docs/api.md is stale: run python docs/apigen.py (or make docs)"


def test_the_api_page_names_every_module():
    with open(os.path.join(ROOT, "docs", "api.md")) as fh:
        text = fh.read()
    scripts = set(apigen().SCRIPTS)
    modules = every_module()
    assert {"postproc.pipeline", "postproc.study.report", "yade_scripts.launch.pool", "yade_scripts.runs.host",
            "shapes.sections", "postproc.study.results"} <= modules
    missing = sorted(m for m in modules - scripts if f".. automodule:: {m}\n" not in text)
    assert not missing, f"modules without a section in docs/api.md: {missing}"
    for m in scripts:
        assert f"`{m}` is a YADE script" in text


def test_a_new_module_gets_its_section(tmp_path):
    """apigen finds what is on disk: a module added to a package is listed."""
    gen = apigen()
    for package, _ in gen.PACKAGES:
        (tmp_path / package / "sub").mkdir(parents=True)
        (tmp_path / package / "__init__.py").write_text("")
        (tmp_path / package / "sub" / "__init__.py").write_text("")
        (tmp_path / package / "sub" / "newmod.py").write_text("")
        (tmp_path / package / "_build").mkdir()
        (tmp_path / package / "_build" / "junk.py").write_text("")
    mods = dict(gen.modules(str(tmp_path)))
    assert mods["postproc"] == ["postproc", "postproc.sub", "postproc.sub.newmod"]
    assert ".. automodule:: shapes.sub.newmod" in gen.render(gen.modules(str(tmp_path)))


@pytest.mark.slow
def test_docs_build_without_warnings(tmp_path):
    pytest.importorskip("sphinx")
    pytest.importorskip("myst_parser")
    res = subprocess.run([sys.executable, "-m", "sphinx", "-E", "-W", "-q", "-b", "html",
                          os.path.join(ROOT, "docs"), str(tmp_path / "html")],
                         capture_output=True, text=True, timeout=600)
    assert res.returncode == 0, res.stderr[-3000:]
    assert (tmp_path / "html" / "api.html").exists()
    # every module of the three packages has its section in the built API page
    api = (tmp_path / "html" / "api.html").read_text()
    missing = sorted(m for m in every_module() - set(apigen().SCRIPTS) if f'id="module-{m}"' not in api)
    assert not missing, f"modules without a section in the built API page: {missing}"
    # and every page of docs/ is in the table of contents (built, linked from the index)
    index = (tmp_path / "html" / "index.html").read_text()
    for page in os.listdir(os.path.join(ROOT, "docs")):
        if page.endswith(".md") and page != "index.md":
            assert f'href="{page[:-3]}.html"' in index, page
