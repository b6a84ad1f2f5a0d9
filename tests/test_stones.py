"""The real-stone library in reference_data: provenance, the import's numbers,
and that the documented command rebuilds a stone of it exactly."""
import json
import os
import shutil

import numpy as np
import pytest

from shapes import stones
from shapes.library import ShapeLibrary
from shapes.hullreduce import Budget
from shapes.meshimport import import_mesh, read_mesh

ROOT = os.path.join(os.path.dirname(__file__), os.pardir)
LIB = os.path.join(ROOT, stones.DEFAULT_OUT)
STONE = os.path.join(os.path.dirname(__file__), "data", "stonepacking")
COMMIT = "076e2e33ceec5617daf6230dc9bdd6ebd6edfe21"


@pytest.fixture(scope="module")
def lib():
    return ShapeLibrary(LIB)


def test_every_stone_names_its_source_licence_and_error(lib):
    n = len(lib)
    assert n == lib.attrs["n_shapes"] == 147
    src = [s.decode() for s in lib.source]
    assert all(s.startswith(f"{stones.REPOSITORY}@{COMMIT}:data/example1") for s in src)
    assert len(set(src)) == n
    assert {s.decode() for s in lib.licence} == {f"MIT, {stones.COPYRIGHT}"}
    assert lib.attrs["licence"] == f"MIT, {stones.COPYRIGHT}" and lib.attrs["commit"] == COMMIT
    refused = json.loads(lib.attrs["refused"])
    assert [os.path.basename(r[0]) for r in refused] == ["stone_106.obj"] and "inward-facing shell" in refused[0][1]
    err, dvol = lib.reduction_hausdorff, lib.reduction_volume_change
    assert err.shape == dvol.shape == (n,) and np.all(err >= 0) and np.all(dvol <= 0)
    assert np.all((lib.n_vertices >= 4) & (lib.n_vertices <= 37))        # the import's default cap
    with open(os.path.join(STONE, "LICENSE")) as a, open(LIB.rsplit(".", 1)[0] + ".LICENSE") as b:
        assert a.read() == b.read()


def test_the_table_beside_it_holds_each_stones_numbers(lib):
    with open(LIB.rsplit(".", 1)[0] + ".md") as fh:
        rows = [r.split(" | ") for r in fh.read().splitlines() if r.startswith("| ") and r[2].isdigit()]
    assert len(rows) == len(lib)
    for i, r in enumerate(rows):
        assert int(r[0][2:]) == i and lib.source[i].decode().endswith(r[1].strip("`"))
        assert int(r[2]) == lib.n_vertices[i] and int(r[3]) == lib.n_faces[i]
        assert abs(float(r[4]) - lib.reduction_hausdorff[i]) <= 5e-5       # printed to 4 decimals


def test_the_documented_import_rebuilds_a_stone_to_round_off(lib):
    """stone_041 (the tests' copy of the same file) imported again at the
    default budget gives the library's grain: same vertices to round-off."""
    i = [k for k, s in enumerate(lib.source) if s.decode().endswith("/stone_041.obj")]
    assert len(i) == 1
    v, t = read_mesh(os.path.join(STONE, "stone_041.obj"))
    g = import_mesh(v, t, Budget())
    mine, _, _ = lib[i[0]]
    assert g.polyhedron.n_vertices == len(mine)
    scale = np.abs(mine).max()
    assert np.abs(np.sort(g.polyhedron.vertices, axis=0) - np.sort(mine, axis=0)).max() <= 1e-12 * scale
    assert g.reduction_hausdorff == pytest.approx(lib.reduction_hausdorff[i[0]], rel=1e-12)


def fake_checkout(tmp_path, licence=True):
    repo = tmp_path / "StonePacking-3D"
    for f in stones.FOLDERS:
        (repo / f).mkdir(parents=True)
    if licence:
        shutil.copy(os.path.join(STONE, "LICENSE"), repo)
    shutil.copy(os.path.join(STONE, "stone_041.obj"), repo / stones.FOLDERS[1])
    (repo / stones.FOLDERS[0] / "broken.obj").write_text("v 0 0 0\n")
    return repo


def test_command_writes_library_table_and_licence_and_lists_the_refused(tmp_path, capsys):
    repo = fake_checkout(tmp_path)
    out = tmp_path / "lib" / "stones.h5"
    assert stones.main([str(repo), "--out", str(out), "--commit", "a" * 40]) == 1
    err = capsys.readouterr().err.splitlines()
    assert err[0].startswith(f"shapes.stones: refused {stones.FOLDERS[0]}/broken.obj: ")
    assert err[-1].startswith(f"shapes.stones: 1 stones -> {out} in ") and "1 refused" in err[-1]
    lib = ShapeLibrary(str(out))
    assert lib.source[0].decode() == f"{stones.REPOSITORY}@{'a' * 40}:{stones.FOLDERS[1]}/stone_041.obj"
    assert (tmp_path / "lib" / "stones.LICENSE").read_text().startswith("MIT License")
    assert "broken.obj" in (tmp_path / "lib" / "stones.md").read_text()


@pytest.mark.parametrize("case, message", [
    ("missing", "no such folder"), ("no licence", "no LICENSE file"),
    ("other licence", "not the MIT licence"), ("no folder", "no folder data/example18/available_stones")])
def test_an_unusable_checkout_is_refused_in_one_line(tmp_path, capsys, case, message):
    repo = fake_checkout(tmp_path, licence=case != "no licence")
    if case == "missing":
        repo = tmp_path / "nowhere"
    elif case == "other licence":
        (repo / "LICENSE").write_text("Apache License 2.0\n")
    elif case == "no folder":
        shutil.rmtree(repo / stones.FOLDERS[1])
    assert stones.main([str(repo), "--out", str(tmp_path / "x.h5")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("shapes.stones: error: ") and message in err[0]
    assert not (tmp_path / "x.h5").exists()
