"""benchmarks/timestep_draws.py: the exact order statistics of the most
limiting grain against brute-force enumeration of every draw."""
import importlib.util
import itertools
import os

import numpy as np
import pytest

from shapes import sizes

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
spec = importlib.util.spec_from_file_location("timestep_draws", os.path.join(ROOT, "benchmarks", "timestep_draws.py"))
td = importlib.util.module_from_spec(spec)
spec.loader.exec_module(td)


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
