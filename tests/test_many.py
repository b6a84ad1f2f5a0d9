"""Many inputs at once: one folder per input, a combined
summary.csv with a source column, a bad file reported and skipped."""
import os

import pandas as pd
import pytest

from postproc.cli import main
from postproc.many import expand_inputs, output_names
from postproc.synthetic import write_synthetic_dump


@pytest.fixture
def inputs(tmp_path):
    d = tmp_path / "runs"
    d.mkdir()
    paths = []
    for k in range(3):
        p = str(d / f"run{k}.h5")
        write_synthetic_dump(p, n_contacts=2000, n_snapshots=2, seed=k)
        paths.append(p)
    bad = d / "broken.h5"
    bad.write_bytes(b"not an hdf5 file at all")
    (d / "notes.txt").write_text("ignored")
    return d, paths, str(bad)


@pytest.mark.slow
def test_jobs_folder_combined_summary_and_a_bad_file(tmp_path, inputs, capsys):
    d, paths, bad = inputs
    out = tmp_path / "out"
    assert main(["analyze", str(d), "--out", str(out), "--jobs", "2"]) == 1
    err = capsys.readouterr().err
    assert f"{bad}:" in err and "(skipped)" in err
    df = pd.read_csv(out / "summary.csv")
    assert df.columns[0] == "source"
    assert sorted(df["source"].unique()) == sorted(paths)
    assert len(df) == 6
    for k in range(3):
        assert (out / f"run{k}" / "qp_sff.png").read_bytes()[:4] == b"\x89PNG"    # drawn by the workers
        one = pd.read_csv(out / f"run{k}" / "summary.csv")
        mine = df[df["source"] == paths[k]].drop(columns="source").reset_index(drop=True)
        pd.testing.assert_frame_equal(mine, one)
    assert not (out / "broken").exists() or not (out / "broken" / "summary.csv").exists()
    assert bad in (out / "errors.txt").read_text()


@pytest.mark.slow
def test_parallel_equals_serial(tmp_path, inputs):
    d, paths, bad = inputs
    a, b = tmp_path / "a", tmp_path / "b"
    assert main(["analyze", *paths, "--out", str(a), "--jobs", "1", "--no-errors", "--no-figures"]) == 0
    assert main(["analyze", *paths, "--out", str(b), "--jobs", "3", "--no-errors", "--no-figures"]) == 0
    pd.testing.assert_frame_equal(pd.read_csv(a / "summary.csv"), pd.read_csv(b / "summary.csv"))
    assert not (a / "errors.txt").exists() and not list(b.rglob("*.png"))     # --no-figures reaches the workers


def test_nothing_analysable_and_bad_options(tmp_path, inputs, capsys):
    d, paths, bad = inputs
    assert main(["analyze", bad, str(tmp_path / "missing.h5"), "--out", str(tmp_path / "o")]) == 2
    assert "no input could be analysed" in capsys.readouterr().err
    assert main(["analyze", *paths, "--out", str(tmp_path / "o"), "--jobs", "0"]) == 2
    empty = tmp_path / "empty"
    empty.mkdir()
    assert main(["analyze", str(empty), "--out", str(tmp_path / "o")]) == 2
    assert "no input files" in capsys.readouterr().err


def test_names_are_unique(tmp_path):
    files = ["/x/a/run.h5", "/x/b/run.h5", "/x/c.csv", "/y/b/run.csv"]
    names = output_names(files)
    assert len(set(names)) == len(names) and names[2] == "c"
    assert expand_inputs([str(tmp_path / "nothere.h5")]) == [str(tmp_path / "nothere.h5")]
    assert os.path.basename(names[0]) == "a_run"
