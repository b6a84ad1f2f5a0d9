"""The README's Python example runs as written (on a synthetic dump)."""
import os
import re

from postproc.synthetic import write_synthetic_dump

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def test_the_readme_python_example_runs(tmp_path, monkeypatch):
    text = open(os.path.join(ROOT, "README.md")).read()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, "the README has no Python example"
    write_synthetic_dump(str(tmp_path / "RUN.h5"), 4000, 3, (0.3, 0.1, 0.5, 0.2), seed=1)
    monkeypatch.chdir(tmp_path)
    scope = {}
    exec(blocks[0], scope)
    assert scope["n_snapshots"] == 3 and scope["bad"] == []
    summary = scope["summary"]
    assert len(summary) == 3 and {"p", "q", "a", "a_l", "a_n", "a_t", "z"} <= set(summary.columns)
    assert summary["a"].iloc[-1] > 0.2          # the synthetic final anisotropy is 0.3
