"""Binned angular functions and harmonic fits (seed eqs. 5-9)."""
import numpy as np
import pytest

from postproc.angular import angular_functions, fit_harmonics, harmonic_curves
from postproc.synthetic import harmonic_contacts

K_SIGMA = 5.0   # see test_fabric.py
KEYS = ("a_fit", "a_l_fit", "a_n_fit", "a_t_fit")


@pytest.mark.parametrize("truth", [(0.0, 0.0, 0.0, 0.0), (0.4, 0.2, 0.6, 0.3), (-0.2, 0.1, 0.3, 0.2)])
@pytest.mark.parametrize("nbins", [9, 18, 36])
def test_fits_recover_harmonic_anisotropies(truth, nbins):
    s = harmonic_contacts(200_000, *truth, axis="y", seed=nbins)
    fits = fit_harmonics(angular_functions(s.branch, s.force, axis="y", nbins=nbins))
    for k, t in zip(KEYS, truth):
        assert abs(fits[k] - t) < K_SIGMA * fits[k + "_se"], (k, fits[k], t, fits[k + "_se"])


def test_density_is_normalised_over_the_sphere():
    s = harmonic_contacts(10_000, 0.5, seed=1)
    af = angular_functions(s.branch, s.force, nbins=12)
    assert np.sum(af.P * af.solid_angle) == pytest.approx(1.0, rel=1e-12)
    assert af.count.sum() == 10_000
    assert np.sum(af.solid_angle) == pytest.approx(4 * np.pi, rel=1e-12)


def test_orthoradial_force_sign_resists_compression():
    """A contact at 45 deg whose tangential force points towards the axis,
    in either id order, has f_t' > 0."""
    n = np.array([[np.sqrt(0.5), 0, np.sqrt(0.5)]])
    t = np.array([[-np.sqrt(0.5), 0, np.sqrt(0.5)]])   # towards +z axis
    f = 2.0 * n + 0.5 * t
    for sgn in (1.0, -1.0):
        af = angular_functions(sgn * n * 0.03, sgn * f, nbins=2)
        k = int(np.flatnonzero(af.count)[0])
        assert af.ft_mean[k] == pytest.approx(0.5)
        assert af.fn_mean[k] == pytest.approx(2.0)


def test_harmonic_curves_integrate_to_one():
    fits = {"a_fit": 0.3, "l0_fit": 1.0, "a_l_fit": 0.1, "f0_fit": 1.0, "a_n_fit": 0.2, "a_t_fit": 0.1}
    th = np.linspace(0, np.pi, 20001)
    P = harmonic_curves(fits, th)["P"]
    from scipy.integrate import trapezoid

    assert trapezoid(P * 2 * np.pi * np.sin(th), th) == pytest.approx(1.0, rel=1e-6)
