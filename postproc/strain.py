"""Cumulative strains of the box (seed eq. 3), compression positive."""
from __future__ import annotations

import numpy as np


def box_strains(lengths, reference, axis=2):
    """Logarithmic strains of a rectangular box.

    The seed defines eps_1 = int_{H0}^{H} dH'/H' (eq. 3); we take the sign
    that makes compression positive: eps = ln(L0 / L).

    Parameters
    ----------
    lengths : array_like, shape (S, 3) or (3,)
        m, the box lengths of S states.
    reference : array_like, shape (3,)
        m, the box at zero strain (the start of shear).
    axis : int, optional
        0, 1 or 2, the compression axis (default 2).

    Returns
    -------
    dict
        (S,) arrays: ``eps_1`` (axial), ``eps_2`` >= ``eps_3`` (the two
        lateral strains, sorted), ``eps_q`` = eps_1 - eps_3 and ``eps_v`` =
        eps_1 + eps_2 + eps_3 (positive in contraction); dimensionless.

    Examples
    --------
    A box shortened by 10 % along z while it widens by 1 and 2 %:

    >>> import numpy as np
    >>> from postproc.strain import box_strains
    >>> e = box_strains([[1.0, 1.0, 1.0], [1.01, 1.02, 0.9]], [1.0, 1.0, 1.0])
    >>> print(np.round(e["eps_1"], 4), np.round(e["eps_3"], 4), np.round(e["eps_q"], 4))
    [0.     0.1054] [ 0.     -0.0198] [0.     0.1252]
    """
    L = np.atleast_2d(np.asarray(lengths, float))
    L0 = np.asarray(reference, float).reshape(3)
    with np.errstate(divide="ignore", invalid="ignore"):
        eps = np.log(L0[None, :] / L)
    lateral = [k for k in range(3) if k != int(axis)]
    e1 = eps[:, int(axis)]
    e2 = np.maximum(eps[:, lateral[0]], eps[:, lateral[1]])
    e3 = np.minimum(eps[:, lateral[0]], eps[:, lateral[1]])
    return {"eps_1": e1, "eps_2": e2, "eps_3": e3, "eps_q": e1 - e3,
            "eps_v": e1 + e2 + e3}
