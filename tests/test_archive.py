"""The archive of analysed runs (yade_scripts.archive) without YADE: what
tells two shape libraries apart, and a bad archive named in one line. The
whole path (a study archived, a new study folder reading it) is in
tests/test_study_smoke.py."""
import shutil

import pytest

from yade_scripts.archive import library_fingerprint
from yade_scripts.archive import main as archive_main


def _library(path, seed, n=12):
    from shapes.generate import Recipe, generate_library
    from shapes.library import write_library

    shapes, _ = generate_library(n, seed=seed)
    write_library(str(path), shapes, seed, Recipe().as_dict(), {})
    return str(path)


def test_two_builds_of_one_library_share_the_fingerprint_and_another_library_does_not(tmp_path):
    """The same grains written twice under other names are two files whose
    bytes differ (the name), with one fingerprint; one grain's vertices
    moved by one ulp, or other grains, change it."""
    import h5py
    import numpy as np

    a = _library(tmp_path / "a.h5", 5)
    b = _library(tmp_path / "b.h5", 5)
    assert open(a, "rb").read() != open(b, "rb").read()
    assert library_fingerprint(a) == library_fingerprint(b)
    assert library_fingerprint(_library(tmp_path / "c.h5", 6)) != library_fingerprint(a)
    d = tmp_path / "d.h5"
    shutil.copyfile(a, d)
    with h5py.File(d, "r+") as f:
        names = []
        f.visit(names.append)
        name = next(n for n in sorted(names) if isinstance(f[n], h5py.Dataset) and f[n].dtype.kind == "f")
        data = f[name][()]
        flat = data.reshape(-1)
        flat[0] = np.nextafter(flat[0], np.inf)
        f[name][...] = flat.reshape(data.shape)
    assert library_fingerprint(str(d)) != library_fingerprint(a)


@pytest.mark.parametrize("make, message", [
    (lambda p: None, "no generated run folder"),
    (lambda p: (p / "table.txt").write_text("description seed\n"), "params.json"),
])
def test_a_folder_that_is_no_study_is_one_line(tmp_path, capsys, make, message):
    study = tmp_path / "study"
    study.mkdir()
    make(study)
    assert archive_main([str(study), str(tmp_path / "arch")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("archive: error: ") and message in err and "\n" not in err
