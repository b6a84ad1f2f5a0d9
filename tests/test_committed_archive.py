"""The committed archive is alive: reference_data/claim6-5000 (15 + 15
5000-grain seeds, analysed by code before the analysis version existed) is
collected by today's code into reference_data/claim6-5000.json, number for
number; a dry run on it plans an extension to 20 seeds; and the command that
reads an archive with the code of its commit finds that commit and refuses
what it cannot do."""
import json
import os
import subprocess
import sys

import pytest

from yade_scripts.campaign.archive_store import library_fingerprint

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ARCHIVE = os.path.join(ROOT, "reference_data", "claim6-5000")
COMMITTED = os.path.join(ROOT, "reference_data", "claim6-5000.json")


@pytest.fixture(scope="module")
def library(tmp_path_factory):
    """The shape library the committed study ran on (make shapes: 1000
    shapes, seed 0, OpenBLAS's kernels pinned by python -m shapes): this
    checkout's when it is that one, else built (about 20 s of CPU)."""
    from shapes.blaspin import cpu_flags, reproducible_coretype

    if reproducible_coretype(cpu_flags()) != "SkylakeX":
        pytest.skip("the archive's library was built with OpenBLAS's AVX-512 kernels, which this CPU "
                    "cannot run (shapes/blaspin.py)")
    with open(os.path.join(ARCHIVE, "polyhedra-ensemble", "archive.json")) as fh:
        wanted = json.load(fh)["library_fingerprint"]
    mine = os.path.join(ROOT, "runs", "shapes", "library.h5")
    if os.path.exists(mine) and library_fingerprint(mine) == wanted:
        return mine
    path = str(tmp_path_factory.mktemp("shapes") / "library.h5")
    subprocess.run([sys.executable, "-m", "shapes", "build", "--n", "1000", "--seed", "0", "--out", path],
                   check=True, capture_output=True, cwd=ROOT)
    assert library_fingerprint(path) == wanted
    return path


def test_the_committed_archive_collects_to_its_committed_results(library, tmp_path, capsys):
    from postproc.cli import main as postproc_main
    from yade_scripts.campaign.archive import main as archive_main

    out = tmp_path / "claim6"
    assert archive_main(["collect", ARCHIVE, str(out), "--library", library]) == 0
    err = capsys.readouterr().err
    assert "collected 30 finished run(s), 0 not finished" in err
    assert postproc_main(["results", str(out), "--out", str(tmp_path / "r.json")]) == 0
    with open(COMMITTED) as fh:
        committed = json.load(fh)
    got = json.loads((tmp_path / "r.json").read_text())
    assert got == committed                       # every field, every number: nothing differs legitimately
    assert (tmp_path / "r.json").read_bytes() == open(COMMITTED, "rb").read()


def test_a_dry_run_on_the_committed_archive_plans_seeds_16_to_20(library, tmp_path, capsys):
    from yade_scripts.campaign.study import main

    out = tmp_path / "study"
    assert main(["--preset", "intermediate", "--ensemble", "20", "--out", str(out), "--archive", ARCHIVE,
                 "--library", library, "--counts", "lmgc90", "lmgc90-2009", "--dry-run"]) == 0
    said = capsys.readouterr().out
    assert "15 + 15 archived and usable; 5 + 5 to run" in said
    assert not out.exists()                                              # nothing made
    assert main(["--preset", "intermediate", "--ensemble", "15", "--out", str(out), "--archive", ARCHIVE,
                 "--library", library, "--dry-run"]) == 0
    assert "15 + 15 archived and usable; 0 + 0 to run" in capsys.readouterr().out


def _git(cwd, *args):
    subprocess.run(["git", "-c", "user.name=t", "-c", "user.email=t@t", *args], cwd=cwd, check=True,
                   capture_output=True)


def test_collect_at_commit_finds_the_archives_commit_and_refuses_what_it_cannot(tmp_path):
    from yade_scripts.campaign.archive import main
    from yade_scripts.campaign.archive_commit import archive_commit
    from yade_scripts.scene.parameters import ConfigError

    root, rel, commit = archive_commit(ARCHIVE)
    assert rel == os.path.join("reference_data", "claim6-5000")
    assert commit == subprocess.run(["git", "log", "-1", "--format=%H", "--", rel], cwd=root,
                                    capture_output=True, text=True).stdout.strip()
    repo = tmp_path / "repo"
    (repo / "arch").mkdir(parents=True)
    with pytest.raises(ConfigError, match="not in a git repository"):
        archive_commit(str(repo / "arch"))
    _git(repo, "init", "-q")
    (repo / "arch" / "a.json").write_text("{}")
    with pytest.raises(ConfigError, match="has changes not committed"):
        archive_commit(str(repo / "arch"))                               # untracked
    _git(repo, "add", "arch")
    _git(repo, "commit", "-qm", "one")
    _git(repo, "commit", "-q", "--allow-empty", "-m", "two")          # later, not touching the archive
    first = subprocess.run(["git", "rev-list", "--max-parents=0", "HEAD"], cwd=repo, capture_output=True,
                           text=True).stdout.strip()
    assert archive_commit(str(repo / "arch"))[2] == first
    (repo / "arch" / "a.json").write_text('{"x": 1}')
    with pytest.raises(ConfigError, match=r"arch: has changes not committed \(git status -- arch\)"):
        archive_commit(str(repo / "arch"))
    with pytest.raises(ConfigError, match="no such archive folder"):
        archive_commit(str(tmp_path / "none"))
    busy = tmp_path / "busy"
    busy.mkdir()
    (busy / "x").write_text("")
    assert main(["collect-at-commit", ARCHIVE, str(busy)]) == 2      # refused: a non-empty OUT
    assert main(["collect", ARCHIVE, str(busy)]) == 2
