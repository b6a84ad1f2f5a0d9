"""export-vtk on a hand-built dump: geometry, forces and types read back."""
import numpy as np
import pytest

from builders import write_snapshot
from postproc.cli import main
from postproc.schema import DumpWriter
from shapes.polyhedron import geometric_faces, hull
from test_networks import cube_lattice, expected_types


def _cube_dump(tmp_path):
    snap, _, _ = cube_lattice()
    d = snap.sizes[0]
    v, t = hull(np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) * d / 2)
    path = str(tmp_path / "cubes.h5")
    with DumpWriter(path, "polyhedra", {}) as w:
        w.write_shapes([v], [t], [geometric_faces(v, t)])
        write_snapshot(w, snap, step=0, stage="shear")
        write_snapshot(w, snap, step=1, stage="shear", time=1.0)
    return path, snap, v


def test_export_vtk_reads_back(tmp_path, capsys):
    import meshio

    path, snap, v = _cube_dump(tmp_path)
    out = tmp_path / "vtk"
    # the lattice's cubes touch exactly or very deep: the angular criterion's answers are exact
    assert main(["export-vtk", path, str(out), "--types", "angular"]) == 0
    m = meshio.read(out / "particles_000001.vtu")
    nb = len(snap.body_ids)
    assert m.cells_dict["triangle"].shape == (12 * nb, 3)
    # the top layer is turned 45 deg about x: its vertices reach d/sqrt(2) above the centre
    top = snap.positions[:, 2].max()
    assert m.points[:, 2].max() == pytest.approx(top + snap.sizes[0] / np.sqrt(2))
    assert m.points[:, 2].min() == pytest.approx(snap.positions[:, 2].min() - snap.sizes[0] / 2)
    c = meshio.read(out / "contacts_000001.vtu")
    fn = c.cell_data["fn"][0]
    assert np.allclose(np.sort(fn), np.sort(np.linalg.norm(snap.force_normal, axis=1)))
    types = c.cell_data["type"][0]
    counts = expected_types()
    assert (types == 4).sum() == counts["EF"] and (types == 3).sum() == counts["EE"]
    assert (types == 7).sum() == np.sum((snap.id1 < 6) | (snap.id2 < 6))
    # each particle's load is the sum of |f_n| over its contacts
    pid = m.cell_data["id"][0]
    load = m.cell_data["force"][0]
    body = snap.body_ids[0]
    mine = (snap.id1 == body) | (snap.id2 == body)
    assert load[pid == body][0] == pytest.approx(np.linalg.norm(snap.force_normal[mine], axis=1).sum())
    pvd = (out / "particles.pvd").read_text()
    assert 'timestep="1"' in pvd and "particles_000001.vtu" in pvd


def test_export_vtk_bad_input(tmp_path, capsys):
    path, _, _ = _cube_dump(tmp_path)
    assert main(["export-vtk", path, str(tmp_path / "v"), "--snapshots", "5"]) == 2
    assert "index 5 out of range (the dump has 2)" in capsys.readouterr().err
    assert main(["export-vtk", str(tmp_path / "missing.h5"), str(tmp_path / "v")]) == 2
    assert "no such file" in capsys.readouterr().err
