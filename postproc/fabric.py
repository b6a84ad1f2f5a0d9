"""Branch-vector fabric and force anisotropies from tensors.

The seed paper (Azema, Radjai & Saussine 2009) describes the angular
distributions of the branch vectors l = l n' (n' unit) and of the contact
forces f = f_n' n' + f_t' t' by their second-order harmonic forms (eqs. 6, 7 and 9;
the decomposition of f is eq. 8),
with theta measured from the compression axis and P2 = 3 cos^2 theta - 1:

    P(Omega)      = (1/4pi) [1 + a   P2]
    <l>(Omega)    = l0      [1 + a_l P2]
    <f_n'>(Omega) = f0      [1 + a_n P2]
    <f_t'>(Omega) = f0 a_t sin 2theta

and defines the anisotropies through tensors (paper-values.md), index 3 being
the compression axis and 1 the mean of the two lateral directions:

    F   = <n (x) n>                         a   = (5/2)(F_3 - F_1) / tr F
    H^l = int <l>(Omega) n (x) n dOmega     a_l = (5/2)(H^l_3 - H^l_1) / tr H^l
    H^n = int <f_n'>(Omega) n (x) n dOmega  a_n = (5/2)(H^n_3 - H^n_1) / tr H^n
    H^t = int <f_t'>(Omega) t (x) n dOmega  a_t = (5/2)(H^t_3 - H^t_1) / tr H^n

For the harmonic forms these relations are exact.

Estimation
----------
F is a plain contact average. The H tensors integrate *conditional* means
over the sphere without the contact density P; what the contacts give
directly are the density-weighted tensors

    G^l = <l n (x) n>_c = int P <l> n (x) n dOmega,  G^n = <f_n' n (x) n>_c,
    G^t = <f_perp (x) n>_c,                          (f_perp = f - f_n' n')

whose axial anisotropies mix in a (for instance a_G^l = a + a_l + O(a a_l)).
Integrating the harmonic forms exactly over the sphere (with
<P2^2> = 4/5, <P2 u^2> = 4/15, <P2^2 u^2> = 44/105, <u^2 (1-u^2)> = 2/15,
<P2 u^2 (1-u^2)> = 4/105, u = cos theta, <.> the mean over the sphere) gives

    b_X := (5/4)(3 G^X_33 / tr G^X - 1) = (a + a_X + (4/7) a a_X) / (1 + (4/5) a a_X)
    (15/4) G^t_33 / tr G^n             = a_t (1 + 2a/7) / (1 + (4/5) a a_n)

for X = l, n. These are inverted in closed form:

    a_X = (b_X - a) / (1 + (4/7) a - (4/5) a b_X)
    a_t = (15/4) (G^t_33 / tr G^n) (1 + (4/5) a a_n) / (1 + 2a/7).

So a contact set drawn from the harmonic forms is recovered without bias at
second order in the anisotropies (a plain ratio of the G tensors would be off
by terms like a * a_l), and a fabric whose lengths or forces do not depend on
direction gives a_l = a_n = 0 exactly, whatever its fabric.

Orthoradial direction and sign: t' is the unit vector orthogonal to n' in the
meridian plane, oriented towards the compression axis for cos theta > 0; only
f_perp enters G^t, so no explicit t' is needed, and a_t > 0 when tangential
forces resist the axial compression, as in the paper.

Standard errors: every estimate is a smooth function of six contact means;
the delta method with their sample covariance (contacts taken as
independent) gives the ``*_se`` values.
"""
from __future__ import annotations

import numpy as np

from .axes import axis_vector

_CHUNK = 1 << 13


def _from_means(m):
    """(a, a_l, a_n, a_t) from the contact means
    m = [<u^2>, <l u^2>, <l>, <f_n u^2>, <f_n>, <f_perp.e u>] (u = n.e)."""
    m = np.asarray(m, float)
    a = 1.25 * (3 * m[0] - 1)
    b_l = 1.25 * (3 * m[1] / m[2] - 1)
    b_n = 1.25 * (3 * m[3] / m[4] - 1)
    a_l = (b_l - a) / (1 + 4 / 7 * a - 0.8 * a * b_l)
    a_n = (b_n - a) / (1 + 4 / 7 * a - 0.8 * a * b_n)
    a_t = 3.75 * m[5] / m[4] * (1 + 0.8 * a * a_n) / (1 + 2 * a / 7)
    return np.array([a, a_l, a_n, a_t])


def anisotropies(branch, force, axis=2, *, errors=True, chunk=_CHUNK):
    """Fabric and force anisotropies a, a_l, a_n, a_t from tensors (seed
    eqs. 6, 7 and 9; the estimators and their inversion: module docstring).

    Parameters
    ----------
    branch : array_like, shape (N, 3)
        m, branch vectors l = x2 - x1 of particle-particle contacts (the
        estimators are even in l: the order of id1 and id2 does not matter).
    force : array_like, shape (N, 3)
        N, the contact forces on id2 by id1 of the same contacts; a force
        pushing id2 away from id1 (compression) has f . l > 0.
    axis : int, str or array_like of shape (3,), optional
        The compression axis ("3" of the paper): 0, 1, 2, 'x', 'y', 'z' or a
        vector (default 2, z).
    errors : bool, optional
        Also return delta-method standard errors ``*_se``, the contacts
        taken as independent (default True).
    chunk : int, optional
        Contacts per block; sums are accumulated block by block so the
        temporaries stay in cache (results do not depend on it beyond
        round-off).

    Returns
    -------
    dict
        ``a``, ``a_l``, ``a_n``, ``a_t`` : float, dimensionless; positive
        when branches are more frequent (a), longer (a_l), carry larger
        normal forces (a_n) along the compression axis, and when tangential
        forces resist the axial compression (a_t). ``l0`` (m) and ``f0`` (N)
        the sphere means of <l> and <f_n'> of the harmonic model; ``n`` the
        number of contacts; ``F`` (dimensionless), ``Gl`` (m), ``Gn`` (N),
        ``Gt`` (N): the (3, 3) contact averages of the module docstring; with
        ``errors``, ``a_se`` ... ``a_t_se``.

    Raises
    ------
    ValueError
        For arrays that are not both (N, 3), no contacts, or a branch vector
        of zero length or not finite.

    Examples
    --------
    Three contacts along x, y and z, the axial one twice as long and
    carrying twice the normal force: no fabric anisotropy, equal length and
    force anisotropies, no tangential forces.

    >>> import numpy as np
    >>> from postproc.fabric import anisotropies
    >>> branch = np.array([[0.01, 0, 0], [0, 0.01, 0], [0, 0, 0.02]])
    >>> force = np.array([[1.0, 0, 0], [0, 1.0, 0], [0, 0, 2.0]])
    >>> r = anisotropies(branch, force, axis="z", errors=False)
    >>> print(r["a"], r["a_l"], r["a_n"], r["a_t"])
    0.0 0.625 0.625 0.0

    200 000 contacts drawn from the harmonic forms with a = 0.3, a_l = 0.1,
    a_n = 0.5, a_t = 0.2 are recovered within their standard errors:

    >>> from postproc.synthetic import harmonic_contacts
    >>> c = harmonic_contacts(200_000, 0.3, 0.1, 0.5, 0.2, seed=3)
    >>> r = anisotropies(c.branch, c.force)
    >>> print([round(float(r[k]), 2) for k in ("a", "a_l", "a_n", "a_t")])
    [0.3, 0.1, 0.5, 0.2]
    >>> print([round(float(r[k + "_se"]), 4) for k in ("a", "a_l", "a_n", "a_t")])
    [0.0026, 0.0005, 0.0031, 0.001]
    """
    L = np.ascontiguousarray(branch, dtype=float)
    f = np.ascontiguousarray(force, dtype=float)
    if L.ndim != 2 or L.shape[1] != 3 or f.shape != L.shape:
        raise ValueError(f"branch and force must both be (N, 3), got {L.shape} and {f.shape}")
    N = len(L)
    if N == 0:
        raise ValueError("no contacts")
    e = axis_vector(axis)
    F = np.zeros((3, 3))
    Gl = np.zeros((3, 3))
    Gn = np.zeros((3, 3))
    Gt = np.zeros((3, 3))
    XtX = np.zeros((6, 6))
    for s in range(0, N, chunk):
        Ls, fs = L[s:s + chunk], f[s:s + chunk]
        ls = np.sqrt(np.einsum("ij,ij->i", Ls, Ls))
        if not np.all(ls > 0):
            raise ValueError("branch vectors of zero length or not finite")
        ns = Ls / ls[:, None]
        fn = np.einsum("ij,ij->i", fs, ns)
        fperp = fs - fn[:, None] * ns
        F += ns.T @ ns
        Gl += (ns * ls[:, None]).T @ ns
        Gn += (ns * fn[:, None]).T @ ns
        Gt += fperp.T @ ns
        if errors:
            u = ns @ e
            u2 = u * u
            X = np.column_stack([u2, ls * u2, ls, fn * u2, fn, (fperp @ e) * u])
            XtX += X.T @ X
    F, Gl, Gn, Gt = F / N, Gl / N, Gn / N, Gt / N
    if not (np.isfinite(F).all() and np.isfinite(Gl).all()):
        raise ValueError("branch vectors of zero length or not finite")
    m = np.array([e @ F @ e, e @ Gl @ e, np.trace(Gl), e @ Gn @ e, np.trace(Gn), e @ Gt @ e])
    a, a_l, a_n, a_t = _from_means(m)
    res = {"a": a, "a_l": a_l, "a_n": a_n, "a_t": a_t,
           "l0": float(np.trace(Gl) / (1 + 0.8 * a * a_l)),
           "f0": float(np.trace(Gn) / (1 + 0.8 * a * a_n)),
           "n": N, "F": F, "Gl": Gl, "Gn": Gn, "Gt": Gt}
    if errors:
        cov = (XtX / N - np.outer(m, m)) / max(N - 1, 1)
        J = np.empty((4, 6))
        scale = np.array([1.0, m[2], m[2], abs(m[4]), abs(m[4]), abs(m[4])])
        for k in range(6):
            h = 1e-6 * max(scale[k], 1e-300)
            dm = np.zeros(6)
            dm[k] = h
            J[:, k] = (_from_means(m + dm) - _from_means(m - dm)) / (2 * h)
        se = np.sqrt(np.maximum(np.einsum("ij,jk,ik->i", J, cov, J), 0.0))
        res.update({"a_se": se[0], "a_l_se": se[1], "a_n_se": se[2], "a_t_se": se[3]})
    return res


def stress_force_fabric(a, a_l, a_n, a_t):
    """The stress-force-fabric relation: q/p predicted from the anisotropies.

    Parameters
    ----------
    a, a_l, a_n, a_t : float or array_like
        The fabric, branch-length, normal-force and tangential-force
        anisotropies (dimensionless, :func:`anisotropies`), any common shape.

    Returns
    -------
    float or ndarray
        (2/5)(a + a_l + a_n + a_t), the seed's prediction of q/p (eq. 10), the
        cross products of anisotropies neglected; dimensionless.

    Examples
    --------
    >>> from postproc.fabric import stress_force_fabric
    >>> print(round(stress_force_fabric(0.1, -0.03, 0.55, 0.46), 3))
    0.432
    """
    return 0.4 * (a + a_l + a_n + a_t)
