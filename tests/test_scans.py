"""shapes.scans (``python -m shapes.scans``): synthetic scans of generated
grains, written as STL and read back by the import."""
import numpy as np
import pytest

from shapes import scans
from shapes.generate import generate_library
from shapes.hullreduce import Budget
from shapes.meshimport import import_mesh, read_mesh


def test_ray_cast_reaches_the_surface_of_a_cube():
    v = np.array([[x, y, z] for x in (-.5, .5) for y in (-.5, .5) for z in (-.5, .5)], float)
    from shapes.polyhedron import hull

    vertices, triangles = hull(v)[:2]
    u = np.array([[1.0, 0, 0], [0, 0, -1.0], np.ones(3) / np.sqrt(3)])
    np.testing.assert_allclose(scans.ray_cast_convex(u, vertices, triangles),
                               [0.5, 0.5, np.sqrt(3) / 2], rtol=1e-12)


def test_write_scans_command(tmp_path, capsys):
    """One scan of 20 480 triangles at d = 40 mm: written, read back, and
    imported to a grain of the generated grain's size; --help answers."""
    assert scans.main(["--write-scans", str(tmp_path), "--n", "1"]) == 0
    assert "1 scans in" in capsys.readouterr().out
    v, t = read_mesh(str(tmp_path / "stone000.stl"))
    assert len(t) == 20480
    grain = generate_library(1, seed=11)[0][0]
    extent = np.ptp(grain.vertices, axis=0).max() * 40.0
    assert np.ptp(v, axis=0).max() == pytest.approx(extent, rel=0.1)
    g = import_mesh(v, t, Budget())
    assert 4 <= g.polyhedron.n_vertices <= 64
    with pytest.raises(SystemExit) as exc:
        scans.main(["--help"])
    assert exc.value.code == 0 and "usage: python -m shapes.scans" in capsys.readouterr().out
