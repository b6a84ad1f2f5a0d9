"""The archive of analysed runs (yade_scripts.campaign.archive) without YADE: what
tells two shape libraries apart, and a bad archive named in one line. The
whole path (a study archived, a new study folder reading it) is in
tests/test_study_smoke.py."""
import os
import shutil

import pytest

from yade_scripts.campaign.archive_store import library_fingerprint
from yade_scripts.campaign.archive import main as archive_main


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


def _archive_of_one_folder(tmp_path):
    """A run folder (spheres, no library) and an archive of it by hand: one
    good run record and records of the wrong shape."""
    import json

    from postproc.provenance import ANALYSIS_VERSION, code_hash
    from yade_scripts.campaign.archive_store import FOLDER_RECORD, RUN_RECORD, _folder_record

    table = tmp_path / "study" / "spheres-ensemble"
    table.mkdir(parents=True)
    (table / "params.json").write_text(json.dumps({"sample": "spheres", "preset": "tiny"}))
    (table / "table.txt").write_text("description seed\n")
    into = tmp_path / "arch" / "spheres-ensemble"
    into.mkdir(parents=True)
    (into / FOLDER_RECORD).write_text(json.dumps(_folder_record(str(table))))
    good = {"analyses": {"": "analysis-spheres-seed1"}, "info": None, "files": {}, "counts": [],
            "dump": {"name": "spheres-seed1.h5", "sha256": "0" * 64, "snapshots": 3},
            "version": ANALYSIS_VERSION, "code": code_hash(), "saved": "2026-11-30T07:00:00"}
    records = {"seed1": good, "seed2": [1, 2], "seed3": {**good, "dump": "spheres-seed3.h5"},
               "seed4": {k: v for k, v in good.items() if k != "analyses"},
               "seed5": {**good, "files": {"a.csv": 7}}, "seed6": "{broken",
               "seed7": {k: v for k, v in good.items() if k != "dump"},
               "seed8": {**good, "dump": {"name": "spheres-seed8.h5", "snapshots": 3}},
               "seed9": {**good, "dump": {**good["dump"], "sha256": 7}},
               "seed10": {**good, "counts": [1]}}
    for k, rec in records.items():
        text = rec if isinstance(rec, str) else json.dumps(rec)
        (into / f"spheres-{k}{RUN_RECORD}").write_text(text)
    return str(table), into


def test_archive_records_of_the_wrong_shape_are_named_not_fatal(tmp_path):
    """A run record that is not the archive's shape (a list, a dump that is
    text, no analyses, a file's digest that is a number, not JSON) is that
    seed's reason to run again; the other seeds are used."""
    from yade_scripts.campaign.archive_store import archived

    table, _ = _archive_of_one_folder(tmp_path)
    got = archived(str(tmp_path / "arch"), table)
    assert got["spheres-seed1.h5"][0] == "ok"
    why = {k: v[1].split("archived but not used: ")[1] for k, v in got.items() if v[0] == "refused"}
    assert why == {"spheres-seed2.h5": "its record cannot be read; it runs again",
                   "spheres-seed3.h5": "its record does not describe its dump (name, sha256, snapshots); it runs again",
                   "spheres-seed4.h5": "its record names no analysis; it runs again",
                   "spheres-seed5.h5": "its record is not of the archive's shape; it runs again",
                   "spheres-seed6.h5": "its record cannot be read; it runs again",
                   "spheres-seed7.h5": "its record does not describe its dump (name, sha256, snapshots); it runs again",
                   "spheres-seed8.h5": "its record does not describe its dump (name, sha256, snapshots); it runs again",
                   "spheres-seed9.h5": "its record does not describe its dump (name, sha256, snapshots); it runs again",
                   "spheres-seed10.h5": "its record is not of the archive's shape; it runs again"}


def test_an_unreadable_folder_record_is_named_as_such(tmp_path, capsys):
    """A folder record that cannot be read refuses its seeds with that
    reason (not "other parameters"), and adding to it stops in one line."""
    from yade_scripts.campaign.archive_store import FOLDER_RECORD, archived

    table, into = _archive_of_one_folder(tmp_path)
    (into / FOLDER_RECORD).write_text('{"params": ')
    got = archived(str(tmp_path / "arch"), table)
    assert {v[0] for v in got.values()} == {"refused"}
    assert "its folder's record archive.json cannot be read" in got["spheres-seed1.h5"][1]
    assert archive_main([str(tmp_path / "study"), str(tmp_path / "arch")]) == 2
    err = capsys.readouterr().err.strip()
    assert "archive.json: the archive's folder record cannot be read" in err and "\n" not in err


def test_records_of_another_version_or_other_parameters_are_conflicts(tmp_path):
    """A run archived under another analysis version (or by code of no known
    version) is not used and is a conflict (the study refuses, replacing
    nothing), not a seed to run again; one of the committed archive's old
    code hash without a version is version 1's, used; the folder's
    parameters changed make every record a conflict."""
    import json

    from yade_scripts.campaign.archive_store import FOLDER_RECORD, RUN_RECORD, archived, conflicts

    table, into = _archive_of_one_folder(tmp_path)
    for f in into.glob(f"*{RUN_RECORD}"):
        if f.name != f"spheres-seed1{RUN_RECORD}":
            f.unlink()
    good = json.loads((into / f"spheres-seed1{RUN_RECORD}").read_text())
    old = "c237acd4bb6279825166a98265fa3598662f8f292f25a36eade50abedecce914"
    records = {"seed2": {**good, "version": 2}, "seed3": {**{k: v for k, v in good.items() if k != "version"},
                                                         "code": "0" * 64},
               "seed4": {**{k: v for k, v in good.items() if k != "version"}, "code": old}}
    for k, rec in records.items():
        rec = {**rec, "dump": {**rec["dump"], "name": f"spheres-{k}.h5"}}
        (into / f"spheres-{k}{RUN_RECORD}").write_text(json.dumps(rec))
    arch = str(tmp_path / "arch")
    got = archived(arch, table)
    assert got["spheres-seed1.h5"][0] == got["spheres-seed4.h5"][0] == "ok"
    assert got["spheres-seed2.h5"][1].endswith("archived but not used: analysed under analysis version 2, not today's")
    assert got["spheres-seed3.h5"][1].endswith(
        "archived but not used: analysed by code 000000000000 of no known analysis version, not today's")
    assert sorted(c.split(" archived")[0].rsplit("/", 1)[1] for c in conflicts(arch, table)) == \
        ["spheres-seed2.h5", "spheres-seed3.h5"]
    params = json.loads((into / FOLDER_RECORD).read_text())
    params["params"]["preset"] = "default"
    (into / FOLDER_RECORD).write_text(json.dumps(params))
    assert len(conflicts(arch, table)) == 4
    assert conflicts(None, table) == []


@pytest.mark.parametrize("mask, mode", [(0o022, 0o755), (0o027, 0o750)])
def test_an_archived_analysis_folder_takes_the_user_s_umask(tmp_path, mask, mode):
    """An analysis folder is copied into the archive through a staging folder
    renamed into place: it gets the mode any new folder gets under the
    umask, not tempfile's 0700."""
    import stat

    from yade_scripts.campaign.archive_store import _copy_run

    table = tmp_path / "study" / "spheres-ensemble"
    (table / "analysis-spheres-seed1").mkdir(parents=True)
    (table / "analysis-spheres-seed1" / "summary.csv").write_text("step\n1\n")
    into = tmp_path / "arch" / "spheres-ensemble"
    into.mkdir(parents=True)
    old = os.umask(mask)
    try:
        files = _copy_run(str(table / "spheres-seed1.h5"), str(table), str(into),
                          {"": str(table / "analysis-spheres-seed1")})
    finally:
        os.umask(old)
    assert list(files) == ["analysis-spheres-seed1/summary.csv"]
    assert stat.S_IMODE(os.stat(into / "analysis-spheres-seed1").st_mode) == mode
