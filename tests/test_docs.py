"""The documentation builds without a single warning: the Markdown pages of
docs/ and the API reference generated from every module's docstrings
(``make docs``)."""
import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


@pytest.mark.slow
def test_docs_build_without_warnings(tmp_path):
    pytest.importorskip("sphinx")
    pytest.importorskip("myst_parser")
    res = subprocess.run([sys.executable, "-m", "sphinx", "-E", "-W", "-q", "-b", "html",
                          os.path.join(ROOT, "docs"), str(tmp_path / "html")],
                         capture_output=True, text=True, timeout=600)
    assert res.returncode == 0, res.stderr[-3000:]
    assert (tmp_path / "html" / "api.html").exists()
    # every module of the three packages has its section in the API page
    api = (tmp_path / "html" / "api.html").read_text()
    for mod in ("postproc.pipeline", "postproc.study.report", "shapes.sections", "yade_scripts.parameters"):
        assert f'id="module-{mod}"' in api, mod
