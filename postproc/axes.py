"""The compression axis and rotations about it."""
from __future__ import annotations

import numpy as np


def axis_vector(axis):
    """The unit compression axis from 0/1/2, 'x'/'y'/'z' or a 3-vector.

    Returns (3,) float, unit norm.

    Parameters
    ----------
    axis : int, str or array_like of shape (3,)
        The compression (axial) axis: an index 0, 1 or 2 (a scalar is
        truncated by ``int``), a letter "x", "y" or "z" (case and
        surrounding spaces ignored), or a direction vector of any finite,
        non-zero length (dimensionless).

    Returns
    -------
    ndarray, shape (3,)
        float, the unit vector along ``axis``: the basis vector for an index
        or a letter, else the given vector normalised (its sign kept).

    Raises
    ------
    ValueError
        An unknown letter, an index other than 0, 1, 2, or a zero or
        non-finite vector.
    """
    if isinstance(axis, str):
        key = axis.strip().lower()
        if key not in ("x", "y", "z"):
            raise ValueError(f"axis must be x, y, z or a 3-vector, got {axis!r}")
        axis = "xyz".index(key)
    if np.ndim(axis) == 0:
        if int(axis) not in (0, 1, 2):
            raise ValueError(f"axis index must be 0, 1 or 2, got {axis!r}")
        e = np.zeros(3)
        e[int(axis)] = 1.0
        return e
    e = np.asarray(axis, float).reshape(3)
    norm = np.linalg.norm(e)
    if not np.isfinite(norm) or norm == 0:
        raise ValueError(f"axis vector {e} has no direction")
    return e / norm


def rotation_z_to(axis):
    """(3, 3) proper rotation R with R @ e_z = axis (Rodrigues' formula).

    Parameters
    ----------
    axis : int, str or array_like of shape (3,)
        The target direction, as :func:`axis_vector` takes it (normalised
        there).

    Returns
    -------
    ndarray, shape (3, 3)
        float, a proper rotation (det +1) turning the unit vector e_z onto
        the unit ``axis``: the rotation about e_z x axis by the angle between
        them; the identity when cos(e_z, axis) > 1 - 1e-15, and the half
        turn about x, diag(1, -1, -1), when it is < -1 + 1e-15.
    """
    e = axis_vector(axis)
    z = np.array([0.0, 0.0, 1.0])
    c = float(z @ e)
    if c > 1 - 1e-15:
        return np.eye(3)
    if c < -1 + 1e-15:
        return np.diag([1.0, -1.0, -1.0])
    k = np.cross(z, e)
    s = np.linalg.norm(k)
    k /= s
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + s * K + (1 - c) * K @ K


def quaternion_matrices(q):
    """(n, 3, 3) rotation matrices (local -> global) of quaternions (n, 4)
    in (w, x, y, z) order; the quaternions are normalised first.

    Parameters
    ----------
    q : array_like, shape (n, 4)
        Orientation quaternions (w, x, y, z), scalar part first, of any
        non-zero norm (a dump's ``bodies/orientation``).

    Returns
    -------
    ndarray, shape (n, 3, 3)
        float, R[i] turns body i's local-frame vectors into global ones,
        x_global = R[i] @ x_local. A zero quaternion gives NaN rows.
    """
    q = np.asarray(q, float)
    q = q / np.linalg.norm(q, axis=1)[:, None]
    w, x, y, z = q.T
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
    ], -2)
