"""Runs that cannot start as asked are refused before any YADE starts, with
one line: an initial solid fraction random sequential addition does not
reach, a box smaller than the largest grain, more memory than the machine."""
import pytest

from shapes.sizes import CLASS_DIAMETERS
from yade_scripts.scene import parameters
from yade_scripts.launch import resources
from yade_scripts.scene.parameters import ConfigError
from yade_scripts.campaign.presets import resolve
from yade_scripts.campaign.study import main as study_main


def test_placement_limits_and_the_box():
    assert parameters.D_MAX == max(CLASS_DIAMETERS)
    assert resolve("default", "polyhedra", {"initial_fraction": 0.30})["initial_fraction"] == 0.30
    with pytest.raises(ConfigError, match=r"initial_fraction = 0.31: .*exact shapes jams above 0.3"):
        resolve("default", "polyhedra", {"initial_fraction": 0.31})
    # bounding spheres reach 0.36: every fraction the parameter allows (<= 0.33)
    assert resolve("default", "spheres", {"initial_fraction": 0.33})["initial_fraction"] == 0.33
    assert resolve("soft", "polyhedra", {"initial_fraction": 0.33})["placement"] == "spheres"
    # a flat box of two grains: at most 1.7 cm high, the largest grain is 5 cm
    with pytest.raises(ConfigError, match=r"n_particles = 2 with aspect 0.1 .* at most 0.0174 m across"):
        resolve("default", "polyhedra", {"n_particles": 2, "aspect": 0.1})
    assert resolve("default", "polyhedra", {"n_particles": 2})["n_particles"] == 2


def test_memory_model_and_refusal(tmp_path, monkeypatch, capsys):
    paper = resolve("paper", "polyhedra")
    assert resources.memory_mb(paper) == pytest.approx(274 + 0.057 * 36933)
    resources.check_memory([paper, paper], memory_total_mb=24 * 1024)
    with pytest.raises(ConfigError, match=r"2 run\(s\) at once need about 4.6 GB .*36933 polyhedra"):
        resources.check_memory([paper, paper], memory_total_mb=4000)
    assert resources.machine_memory_mb() > 0
    monkeypatch.setattr(resources, "machine_memory_mb", lambda: 1000.0)
    out = tmp_path / "paper"
    assert study_main(["--preset", "paper", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "more than this machine's 1.0 GB" in err[0]
    assert not out.exists()                     # refused before anything was made
    # an ensemble on 2 cores: two runs of the largest sample at once
    assert study_main(["--preset", "tiny", "--out", str(tmp_path / "t"), "--ensemble", "2",
                       "--jobs", "4", "--set", "n_particles=20000"]) == 2
    assert "4 run(s) at once" in capsys.readouterr().err
