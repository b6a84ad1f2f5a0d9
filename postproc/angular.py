"""Angular functions of branch vectors and forces, and their harmonic fits.

theta is the angle between the branch direction n' and the compression axis.
The functions are pi-periodic and, under axisymmetric loading, independent of
the azimuth, so n' is folded into the hemisphere cos theta >= 0 (with f
flipped alongside, which is the same contact seen with id1 and id2 swapped)
and binned in theta on [0, pi/2]. Bin k covers both caps
theta_k <= theta < theta_{k+1} and pi - theta_{k+1} < theta <= pi - theta_k,
a solid angle 4 pi (cos theta_k - cos theta_{k+1}).

* P_Omega(theta) = N_k / (N dOmega_k), normalised so that its integral over
  the sphere is 1 (seed eq. 5);
* <l>(theta), <f_n'>(theta), <f_t'>(theta): means over the contacts of the
  bin (eqs. 5 and 8), f_t' = f . t' with t' the unit vector orthogonal to n'
  in the meridian plane pointing towards the axis, so that <f_t'> > 0 where
  friction resists the axial compression.

The fits (:func:`fit_harmonics`) are weighted least squares of the harmonic
forms of eqs. 6, 7 and 9 with weights dOmega_k, so that with many bins they approach
the L2 projection on the sphere. The regressors are the *bin averages* of
3cos^2 theta - 1 and sin 2theta over each bin's solid angle, not their values
at the bin centre, which removes the discretisation bias at first order.
Standard errors are propagated from the per-bin standard errors.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .axes import axis_vector


@dataclass
class AngularFunctions:
    """Binned angular functions of one contact set (:func:`angular_functions`).

    theta is measured from the compression axis and folded onto
    [0, pi/2]; every array is (nbins,) unless said.

    Attributes
    ----------
    edges : ndarray, shape (nbins + 1,)
        rad, the theta edges on [0, pi/2].
    solid_angle : ndarray
        sr, the solid angle of each bin, both caps: 4 pi (cos theta_k -
        cos theta_{k+1}).
    count : ndarray
        Contacts per bin.
    P, P_se : ndarray
        1/sr, the density of branch directions P_Omega(theta) (seed eq. 5;
        its integral over the sphere is 1) and its standard error.
    l_mean, l_se : ndarray
        m, the mean branch length <l>(theta) and its standard error.
    fn_mean, fn_se : ndarray
        N, the mean radial force <f_n'>(theta) = <f . n'>, positive in
        compression, and its standard error.
    ft_mean, ft_se : ndarray
        N, the mean orthoradial force <f_t'>(theta) = <f . t'>, t' pointing
        towards the axis in the meridian plane (positive where friction
        resists the axial compression), and its standard error.
    p2_avg, s2_avg : ndarray
        The bin averages of 3 cos^2 theta - 1 and sin 2 theta over the bin's
        solid angle (the fits' regressors).
    """

    edges: np.ndarray        # (nbins + 1,) rad, theta edges on [0, pi/2]
    solid_angle: np.ndarray  # sr, both caps
    count: np.ndarray        # contacts per bin
    P: np.ndarray            # 1/sr
    P_se: np.ndarray
    l_mean: np.ndarray       # m
    l_se: np.ndarray
    fn_mean: np.ndarray      # N, radial force f . n'
    fn_se: np.ndarray
    ft_mean: np.ndarray      # N, orthoradial force f . t'
    ft_se: np.ndarray
    p2_avg: np.ndarray       # bin average of 3 cos^2 theta - 1
    s2_avg: np.ndarray       # bin average of sin 2 theta

    @property
    def centers(self):
        """ndarray, shape (nbins,): rad, the bin centres."""
        return 0.5 * (self.edges[1:] + self.edges[:-1])


def _bin_stats(idx, values, nbins, count):
    s = np.bincount(idx, values, nbins)
    ss = np.bincount(idx, values * values, nbins)
    with np.errstate(invalid="ignore", divide="ignore"):
        mean = s / count
        var = ss / count - mean * mean
        var = np.maximum(var, 0.0) * count / np.maximum(count - 1, 1)
        se = np.sqrt(var / count)
    se[count < 2] = np.nan
    return mean, se


def angular_functions(branch, force, axis=2, nbins=18):
    """Bin the branch-vector and force functions of the seed (eqs. 5, 8).

    Parameters
    ----------
    branch : array_like, shape (N, 3)
        m, branch vectors l = x2 - x1 (none of zero length).
    force : array_like, shape (N, 3)
        N, the contact forces on id2 by id1.
    axis : int, str or array_like of shape (3,), optional
        The compression axis: 0, 1, 2, 'x', 'y', 'z' or a vector (default z).
    nbins : int, optional
        Number of equal theta bins on [0, pi/2] (default 18, i.e. 5 deg).

    Returns
    -------
    AngularFunctions
        P_Omega, <l>, <f_n'>, <f_t'> per bin with their standard errors.

    Examples
    --------
    >>> from postproc.angular import angular_functions
    >>> from postproc.synthetic import harmonic_contacts
    >>> c = harmonic_contacts(100_000, 0.3, 0.1, 0.5, 0.2, seed=3)
    >>> af = angular_functions(c.branch, c.force, "z", nbins=9)
    >>> print(len(af.P), int(af.count.sum()), round(float((af.P * af.solid_angle).sum()), 12))
    9 100000 1.0
    """
    L = np.asarray(branch, float)
    f = np.asarray(force, float)
    e = axis_vector(axis)
    N = len(L)
    length = np.sqrt(np.einsum("ij,ij->i", L, L))
    n = L / length[:, None]
    c = n @ e
    sign = np.where(c < 0, -1.0, 1.0)
    ca = np.abs(c)
    sin = np.sqrt(np.maximum(1.0 - ca * ca, 0.0))
    fn = np.einsum("ij,ij->i", f, n)
    with np.errstate(invalid="ignore", divide="ignore"):
        ft = np.where(sin > 0, sign * (f @ e - c * fn) / sin, 0.0)
    theta = np.arccos(np.clip(ca, 0.0, 1.0))
    edges = np.linspace(0.0, np.pi / 2, nbins + 1)
    idx = np.minimum((theta / (np.pi / 2) * nbins).astype(np.int64), nbins - 1)
    count = np.bincount(idx, minlength=nbins).astype(float)
    u_hi, u_lo = np.cos(edges[:-1]), np.cos(edges[1:])   # u = cos theta
    du = u_hi - u_lo
    dOmega = 4 * np.pi * du
    P = count / (N * dOmega)
    P_se = np.sqrt(count * (1 - count / N)) / (N * dOmega)
    l_mean, l_se = _bin_stats(idx, length, nbins, count)
    fn_mean, fn_se = _bin_stats(idx, fn, nbins, count)
    ft_mean, ft_se = _bin_stats(idx, ft, nbins, count)

    def prim_p2(u):
        return u ** 3 - u

    def prim_s2(u):  # integral of 2 u sqrt(1 - u^2) du
        return -(2.0 / 3.0) * (1 - u * u) ** 1.5

    p2_avg = (prim_p2(u_hi) - prim_p2(u_lo)) / du
    s2_avg = (prim_s2(u_hi) - prim_s2(u_lo)) / du
    return AngularFunctions(edges, dOmega, count, P, P_se, l_mean, l_se,
                            fn_mean, fn_se, ft_mean, ft_se, p2_avg, s2_avg)


def _wls(X, y, se, w):
    """Weighted least squares y ~ X beta; returns beta and its covariance
    propagated from the independent per-point errors ``se``."""
    W = w[:, None]
    A = np.linalg.solve(X.T @ (W * X), (W * X).T)   # beta = A y
    beta = A @ y
    cov = (A * se[None, :] ** 2) @ A.T
    return beta, cov


def fit_harmonics(af: AngularFunctions):
    """Least-squares fits of the seed's harmonic forms (eqs. 6, 7 and 9).

    P_Omega = (1 + a P2)/(4 pi), <l> = l0 (1 + a_l P2), <f_n'> = f0 (1 + a_n
    P2), <f_t'> = f0 a_t sin 2theta, P2 = 3 cos^2 theta - 1, weighted by the
    bins' solid angles, with the bin averages of P2 and sin 2theta as
    regressors (module docstring).

    Parameters
    ----------
    af : AngularFunctions
        The binned functions of :func:`angular_functions`.

    Returns
    -------
    dict
        ``a_fit``, ``a_l_fit``, ``a_n_fit``, ``a_t_fit`` (dimensionless, the
        signs of :func:`postproc.fabric.anisotropies`), ``l0_fit`` (m),
        ``f0_fit`` (N) and the standard errors ``*_fit_se``. Bins with fewer
        than 2 contacts are left out of the mean-value fits; with fewer than
        2 such bins those values are NaN.

    Examples
    --------
    >>> from postproc.angular import angular_functions, fit_harmonics
    >>> from postproc.synthetic import harmonic_contacts
    >>> c = harmonic_contacts(100_000, 0.3, 0.1, 0.5, 0.2, seed=3)
    >>> fits = fit_harmonics(angular_functions(c.branch, c.force, "z", nbins=9))
    >>> print([round(fits[k], 2) for k in ("a_fit", "a_l_fit", "a_n_fit", "a_t_fit")])
    [0.3, 0.1, 0.5, 0.2]
    """
    ok = af.count >= 2
    w = af.solid_angle
    G, S = af.p2_avg, af.s2_avg
    # P: 4 pi P - 1 = a G
    y = 4 * np.pi * af.P - 1
    se = 4 * np.pi * af.P_se
    beta, cov = _wls(G[:, None], y, np.where(np.isfinite(se), se, 0.0), w)
    out = {"a_fit": float(beta[0]), "a_fit_se": float(np.sqrt(cov[0, 0]))}
    if ok.sum() < 2:
        nan = float("nan")
        out.update({k: nan for k in ("a_l_fit", "a_n_fit", "a_t_fit", "l0_fit", "f0_fit",
                                     "a_l_fit_se", "a_n_fit_se", "a_t_fit_se")})
        return out
    X = np.column_stack([np.ones(ok.sum()), G[ok]])
    for key, mean, mse in (("l", af.l_mean, af.l_se), ("n", af.fn_mean, af.fn_se)):
        b, C = _wls(X, mean[ok], mse[ok], w[ok])
        ratio = b[1] / b[0]
        grad = np.array([-b[1] / b[0] ** 2, 1 / b[0]])
        out[f"a_{key}_fit"] = float(ratio)
        out[f"a_{key}_fit_se"] = float(np.sqrt(grad @ C @ grad))
        out["l0_fit" if key == "l" else "f0_fit"] = float(b[0])
        if key == "n":
            f0, f0_var = b[0], C[0, 0]
    bt, Ct = _wls(S[ok][:, None], af.ft_mean[ok], af.ft_se[ok], w[ok])
    out["a_t_fit"] = float(bt[0] / f0)
    # delta method for bt / f0, the two fits' errors taken as independent
    out["a_t_fit_se"] = float(np.hypot(np.sqrt(Ct[0, 0]) / f0,
                                       bt[0] * np.sqrt(f0_var) / f0 ** 2))
    return out


def harmonic_curves(fits, theta):
    """The fitted functions of eqs. 6, 7 and 9 at given angles.

    Parameters
    ----------
    fits : dict
        ``a_fit``, ``a_l_fit``, ``a_n_fit``, ``a_t_fit``, ``l0_fit`` (m),
        ``f0_fit`` (N), as :func:`fit_harmonics` returns them.
    theta : array_like
        rad, angles from the compression axis, any shape.

    Returns
    -------
    dict
        ``P`` (1/sr), ``l`` (m), ``fn`` and ``ft`` (N), each of the shape of
        ``theta``.

    Examples
    --------
    >>> import numpy as np
    >>> from postproc.angular import harmonic_curves
    >>> fits = {"a_fit": 0.3, "a_l_fit": 0.0, "a_n_fit": 0.5, "a_t_fit": 0.2, "l0_fit": 0.03, "f0_fit": 10.0}
    >>> curves = harmonic_curves(fits, np.array([0.0, np.pi / 4, np.pi / 2]))
    >>> print(np.round(curves["fn"], 6), np.round(curves["ft"], 6))
    [20.  12.5  5. ] [0. 2. 0.]
    """
    theta = np.asarray(theta, float)
    p2 = 3 * np.cos(theta) ** 2 - 1
    return {
        "P": (1 + fits["a_fit"] * p2) / (4 * np.pi),
        "l": fits["l0_fit"] * (1 + fits["a_l_fit"] * p2),
        "fn": fits["f0_fit"] * (1 + fits["a_n_fit"] * p2),
        "ft": fits["f0_fit"] * fits["a_t_fit"] * np.sin(2 * theta),
    }
