"""The compression axis and rotations about it."""
from __future__ import annotations

import numpy as np


def axis_vector(axis):
    """The unit compression axis from 0/1/2, 'x'/'y'/'z' or a 3-vector.

    Returns (3,) float, unit norm.
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
    """(3, 3) proper rotation R with R @ e_z = axis (Rodrigues' formula)."""
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
    in (w, x, y, z) order; the quaternions are normalised first."""
    q = np.asarray(q, float)
    q = q / np.linalg.norm(q, axis=1)[:, None]
    w, x, y, z = q.T
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1),
    ], -2)
