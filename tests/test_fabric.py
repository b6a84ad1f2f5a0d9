"""Tensor anisotropies against contact sets drawn from the harmonic forms.

Tolerances: every estimate comes with a delta-method standard error
(se ~ 1/sqrt(N)); a recovered value must lie within K_SIGMA standard errors
of the truth. K_SIGMA = 5 leaves a false-failure chance below 1e-6 per
comparison for a normal estimator. The standard errors themselves are checked
against the spread of repeated draws.
"""
import zlib

import numpy as np
import pytest

from postproc.axes import rotation_z_to
from postproc.fabric import anisotropies, stress_force_fabric
from postproc.synthetic import harmonic_contacts

K_SIGMA = 5.0
KEYS = ("a", "a_l", "a_n", "a_t")
CASES = [
    (0.0, 0.0, 0.0, 0.0),
    (0.4, 0.2, 0.6, 0.3),
    (-0.2, 0.1, 0.3, 0.2),
    (0.8, 0.5, 0.9, 0.6),       # large: second-order terms matter
    (0.25, -0.15, 0.2, -0.1),   # extension-like signs
]


def assert_recovered(res, truth):
    for k, t in zip(KEYS, truth):
        assert abs(res[k] - t) < K_SIGMA * res[k + "_se"], (k, res[k], t, res[k + "_se"])


@pytest.mark.parametrize("truth", CASES)
@pytest.mark.parametrize("axis", [2, "x", (1.0, 2.0, -0.5)])
def test_recovers_harmonic_anisotropies(truth, axis):
    s = harmonic_contacts(100_000, *truth, axis=axis, seed=zlib.crc32(repr((truth, axis)).encode()))
    assert_recovered(anisotropies(s.branch, s.force, axis), truth)


def test_isotropic_set_gives_zero_within_noise():
    s = harmonic_contacts(50_000, seed=11)
    res = anisotropies(s.branch, s.force)
    assert_recovered(res, (0, 0, 0, 0))
    # and a's standard error is the analytic one: var(3u^2-1) = 4/5 -> se = sqrt(5/4/N)
    assert res["a_se"] == pytest.approx(np.sqrt(1.25 / 50_000), rel=0.05)


def test_standard_errors_match_the_spread_of_repeated_draws():
    truth = (0.3, 0.15, 0.4, 0.25)
    R, N = 200, 2000
    est, se = [], []
    rng = np.random.default_rng(5)
    for _ in range(R):
        s = harmonic_contacts(N, *truth, seed=rng)
        r = anisotropies(s.branch, s.force)
        est.append([r[k] for k in KEYS])
        se.append([r[k + "_se"] for k in KEYS])
    est, se = np.array(est), np.array(se)
    ratio = est.std(axis=0, ddof=1) / se.mean(axis=0)
    # the sample sd of R = 200 normal draws has relative sd 1/sqrt(2(R-1)) = 5 %:
    # allow 4 of those
    tol = 4 / np.sqrt(2 * (R - 1))
    assert np.all(np.abs(ratio - 1) < tol), ratio
    # no bias: the mean of R estimates within 5 standard errors of the mean
    bias = est.mean(axis=0) - truth
    assert np.all(np.abs(bias) < K_SIGMA * se.mean(axis=0) / np.sqrt(R)), bias


def test_plain_density_weighted_ratio_would_be_biased():
    """The closed-form correction matters: the uncorrected ratio of the G
    tensors mixes a into a_l (a_G = a + a_l + O(a a_l))."""
    truth = (0.5, 0.3, 0.5, 0.3)
    s = harmonic_contacts(200_000, *truth, seed=3)
    res = anisotropies(s.branch, s.force)
    Gl = res["Gl"]
    naive = 2.5 * (Gl[2, 2] - (Gl[0, 0] + Gl[1, 1]) / 2) / np.trace(Gl)
    assert abs(naive - truth[1]) > 50 * res["a_l_se"]
    assert abs(res["a_l"] - truth[1]) < K_SIGMA * res["a_l_se"]


def test_direction_independent_lengths_and_forces_give_zero_exactly():
    """Whatever the fabric, equal lengths and equal radial forces mean
    a_l = a_n = 0, and no tangential force means a_t = 0."""
    rng = np.random.default_rng(2)
    n = rng.normal(size=(5000, 3)) * [1, 1, 2.5]       # strongly anisotropic, not harmonic
    n /= np.linalg.norm(n, axis=1)[:, None]
    res = anisotropies(0.02 * n, 3.0 * n)
    assert res["a"] > 0.3
    for k in ("a_l", "a_n", "a_t"):
        assert res[k] == pytest.approx(0.0, abs=1e-12)


def test_invariances():
    truth = (0.3, 0.1, 0.5, 0.2)
    s = harmonic_contacts(20_000, *truth, seed=8)
    ref = anisotropies(s.branch, s.force)
    rng = np.random.default_rng(1)
    # permutation of contacts
    p = rng.permutation(len(s.branch))
    _same(anisotropies(s.branch[p], s.force[p]), ref)
    # swapping id1/id2 flips l and f together
    flip = np.where(rng.random(len(s.branch)) < 0.5, -1.0, 1.0)[:, None]
    _same(anisotropies(s.branch * flip, s.force * flip), ref)
    # rotating everything together with the axis
    R = rotation_z_to((0.3, -0.8, 0.2)) @ rotation_z_to((1.0, 0.0, 0.0))
    _same(anisotropies(s.branch @ R.T, s.force @ R.T, axis=R[:, 2]), ref)
    # scaling forces and lengths
    for scale in (1e-9, 1e9):
        _same(anisotropies(s.branch * scale, s.force * scale), ref)


def _same(a, b, tol=1e-9):
    for k in KEYS + tuple(k + "_se" for k in KEYS):
        assert a[k] == pytest.approx(b[k], rel=tol, abs=tol), k


def test_bad_arrays_raise_value_error():
    with pytest.raises(ValueError):
        anisotropies(np.zeros((0, 3)), np.zeros((0, 3)))
    with pytest.raises(ValueError):
        anisotropies(np.zeros((4, 3)), np.ones((4, 3)))      # zero-length branches
    with pytest.raises(ValueError):
        anisotropies(np.ones((4, 2)), np.ones((4, 2)))


def test_sff_is_first_order_q_over_p_for_harmonic_sets():
    """For the harmonic forms, sigma = n_v <f (x) l>; the exact q/p along the
    axis differs from (2/5) sum(a) by cross products only. Check the exact
    model q/p (by quadrature) against the stress of a large sample, and that
    the residual of the 2/5 relation shrinks like the square of the
    anisotropies."""
    from scipy.integrate import quad

    def exact_qp(a, a_l, a_n, a_t):
        P = lambda u: 1 + a * (3 * u * u - 1)
        lf = lambda u: (1 + a_l * (3 * u * u - 1))
        fn = lambda u: (1 + a_n * (3 * u * u - 1))
        ft = lambda u: a_t * 2 * u * np.sqrt(1 - u * u)
        # axial: n_3^2 fn + t'_3 n_3 ft, with t'_3 n_3 = sin*cos
        s33 = quad(lambda u: P(u) * lf(u) * (fn(u) * u * u + ft(u) * u * np.sqrt(1 - u * u)), 0, 1)[0]
        # lateral mean: (1-u^2)/2 fn - (sin*cos)/2 ft
        s11 = quad(lambda u: P(u) * lf(u) * (fn(u) * (1 - u * u) / 2 - ft(u) * u * np.sqrt(1 - u * u) / 2), 0, 1)[0]
        return (s33 - s11) / (s33 + 2 * s11)

    truth = (0.3, 0.1, 0.5, 0.2)
    s = harmonic_contacts(400_000, *truth, seed=21)
    sig = s.force.T @ s.branch
    sym = (sig + sig.T) / 2
    qp_sample = (sym[2, 2] - (sym[0, 0] + sym[1, 1]) / 2) / np.trace(sym)
    # sample noise: estimate the se of qp by splitting into 20 batches
    batches = np.array_split(np.arange(len(s.branch)), 20)
    vals = []
    for b in batches:
        sg = s.force[b].T @ s.branch[b]
        sg = (sg + sg.T) / 2
        vals.append((sg[2, 2] - (sg[0, 0] + sg[1, 1]) / 2) / np.trace(sg))
    se = np.std(vals, ddof=1) / np.sqrt(len(vals))
    assert abs(qp_sample - exact_qp(*truth)) < K_SIGMA * se
    # the 2/5 relation holds to first order: residual / eps^2 stays bounded
    res = [abs(exact_qp(*(eps * np.array(truth))) - stress_force_fabric(*(eps * np.array(truth))))
           for eps in (0.1, 0.05, 0.025)]
    assert res[1] / res[0] == pytest.approx(0.25, rel=0.1)
    assert res[2] / res[1] == pytest.approx(0.25, rel=0.1)
