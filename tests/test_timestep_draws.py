"""yade_scripts.campaign.timestep_draws: the exact order statistics of the most
limiting grain against brute-force enumeration of every draw, and the
command on a small library."""
import itertools

import numpy as np
import pytest

from shapes import sizes
from yade_scripts.campaign import timestep_draws as td


@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_expected_rate_equals_the_mean_over_every_draw(n):
    """Three shapes; every assignment of shapes to the n grains (classes by
    the exact counts) is equally likely, so E[max] is their plain mean."""
    x1 = np.array([1.0, 2.5, 1.7])
    d = np.repeat(sizes.CLASS_DIAMETERS, sizes.class_counts(n))
    brute = np.mean([max(x1[s] / np.sqrt(d[k]) for k, s in enumerate(draw))
                     for draw in itertools.product(range(len(x1)), repeat=n)])
    assert td.expected_rate(x1, n) == pytest.approx(brute, rel=1e-12)


def test_expected_rate_grows_to_the_library_limit():
    x1 = np.linspace(1.0, 2.0, 50)
    rates = [td.expected_rate(x1, n) for n in (10, 100, 1000, 10000)]
    assert np.all(np.diff(rates) > 0)
    assert rates[-1] == pytest.approx(2.0 / np.sqrt(sizes.CLASS_DIAMETERS[0]), rel=1e-12)


def test_the_command_help_and_a_small_library(tmp_path, capsys):
    """``python -m yade_scripts.campaign.timestep_draws`` on an 8-grain library: the
    table's rows, 1.0000 at 1000 grains, and one line per N and seed."""
    from shapes.generate import Recipe, generate_library
    from shapes.library import write_library

    with pytest.raises(SystemExit) as exc:
        td.main(["--help"])
    assert exc.value.code == 0 and "usage: python -m yade_scripts.campaign.timestep_draws" in capsys.readouterr().out
    path = str(tmp_path / "lib.h5")
    shapes, _ = generate_library(8, seed=5)
    write_library(path, shapes, 5, Recipe().as_dict(), {})
    assert td.main(["--library", path, "--n", "10", "1000", "--seeds", "1", "2"]) == 0
    out = capsys.readouterr().out
    assert "8 shapes, the most limiting is shape" in out and "| 1000 | 1.0000 |" in out
    assert sum(line.startswith("N ") for line in out.splitlines()) == 4
    assert td.main(["--library", str(tmp_path / "none.h5")]) == 2
    assert "timestep_draws: error:" in capsys.readouterr().err
