"""The study's grains as LMGC90 sees them: posed vertices, frames, quaternions.

Pure numpy. A grain of the dump schema is a shape in its local frame
(vertices in m, origin at the centre of mass, axes along the principal axes
of inertia), a position and a unit quaternion (w, x, y, z) turning the local
frame into the global one. LMGC90's ``pre`` builds a POLYR from the posed
(global) vertices and computes its own centre of mass and inertia frame; the
grain's orientation at any later time is then the rotation LMGC90's frame
has turned through since the start, applied to the initial orientation
(:func:`orientation_now`).
"""
from __future__ import annotations

import numpy as np


def quaternion_matrix(q):
    """Rotation matrices of unit quaternions.

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Unit quaternions (w, x, y, z).

    Returns
    -------
    ndarray, shape (..., 3, 3)
        R with ``x_global = R @ x_local``.

    Examples
    --------
    >>> import numpy as np
    >>> from lmgc90.grains import quaternion_matrix
    >>> R = quaternion_matrix([np.cos(np.pi / 4), 0.0, 0.0, np.sin(np.pi / 4)])   # 90 deg about z
    >>> print(np.round(R @ [1.0, 0.0, 0.0], 12) + 0.0)
    [0. 1. 0.]
    """
    q = np.asarray(q, float)
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = np.moveaxis(q, -1, 0)
    R = np.empty(q.shape[:-1] + (3, 3))
    R[..., 0, 0] = 1 - 2 * (y * y + z * z)
    R[..., 0, 1] = 2 * (x * y - w * z)
    R[..., 0, 2] = 2 * (x * z + w * y)
    R[..., 1, 0] = 2 * (x * y + w * z)
    R[..., 1, 1] = 1 - 2 * (x * x + z * z)
    R[..., 1, 2] = 2 * (y * z - w * x)
    R[..., 2, 0] = 2 * (x * z - w * y)
    R[..., 2, 1] = 2 * (y * z + w * x)
    R[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return R


def matrix_quaternion(R):
    """Unit quaternions (w >= 0) of rotation matrices (Shepperd's method).

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Proper rotation matrices.

    Returns
    -------
    ndarray, shape (..., 4)
        (w, x, y, z) with ``quaternion_matrix(q) == R`` to round-off.

    Examples
    --------
    >>> import numpy as np
    >>> from lmgc90.grains import matrix_quaternion, quaternion_matrix
    >>> q = np.array([0.5, 0.5, -0.5, 0.5])
    >>> print(np.allclose(matrix_quaternion(quaternion_matrix(q)), q))
    True
    """
    R = np.asarray(R, float)
    flat = R.reshape(-1, 3, 3)
    out = np.empty((len(flat), 4))
    for k, m in enumerate(flat):
        tr = np.trace(m)
        cand = np.array([tr, m[0, 0], m[1, 1], m[2, 2]])
        i = int(np.argmax(cand))
        if i == 0:
            s = 2.0 * np.sqrt(1.0 + tr)
            q = [0.25 * s, (m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s]
        elif i == 1:
            s = 2.0 * np.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2])
            q = [(m[2, 1] - m[1, 2]) / s, 0.25 * s, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s]
        elif i == 2:
            s = 2.0 * np.sqrt(1.0 - m[0, 0] + m[1, 1] - m[2, 2])
            q = [(m[0, 2] - m[2, 0]) / s, (m[0, 1] + m[1, 0]) / s, 0.25 * s, (m[1, 2] + m[2, 1]) / s]
        else:
            s = 2.0 * np.sqrt(1.0 - m[0, 0] - m[1, 1] + m[2, 2])
            q = [(m[1, 0] - m[0, 1]) / s, (m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, 0.25 * s]
        q = np.asarray(q)
        out[k] = (q if q[0] >= 0 else -q) / np.linalg.norm(q)
    return out.reshape(R.shape[:-2] + (4,))


def posed_vertices(vertices, quaternion, position):
    """A grain's vertices in the global frame.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        m, in the grain's local frame (origin at its centre of mass).
    quaternion : array_like, shape (4,)
        (w, x, y, z), local to global.
    position : array_like, shape (3,)
        m, the centre of mass.

    Returns
    -------
    ndarray, shape (V, 3)
        m, ``R v + x``.

    Examples
    --------
    >>> from lmgc90.grains import posed_vertices
    >>> print(posed_vertices([[1.0, 0.0, 0.0]], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 2.0]))
    [[1. 0. 2.]]
    """
    v = np.asarray(vertices, float).reshape(-1, 3)
    return v @ quaternion_matrix(quaternion).T + np.asarray(position, float)


def orientation_now(q0, frame0, frame):
    """The grains' orientations after LMGC90's frames turned from ``frame0``
    to ``frame``.

    LMGC90 keeps each body's inertia frame as a (3, 3) matrix whose columns
    are the body axes in the global frame (``RBDY3_GetBodyMatrix('IF___')``).
    The rotation since the start is ``frame @ frame0.T``, and the grain's
    local frame (the dump's) turned with it: ``R = frame @ frame0.T @ R0``.

    Parameters
    ----------
    q0 : array_like, shape (N, 4)
        (w, x, y, z), the grains' orientations when their POLYR were built.
    frame0, frame : array_like, shape (N, 3, 3)
        LMGC90's inertia frames then and now.

    Returns
    -------
    ndarray, shape (N, 4)
        (w, x, y, z), w >= 0.

    Examples
    --------
    >>> import numpy as np
    >>> from lmgc90.grains import orientation_now, quaternion_matrix
    >>> F0 = quaternion_matrix([[0.5, 0.5, 0.5, 0.5]])          # any LMGC90 frame
    >>> turn = quaternion_matrix([[np.cos(0.3), np.sin(0.3), 0.0, 0.0]])
    >>> q = orientation_now([[1.0, 0.0, 0.0, 0.0]], F0, turn @ F0)
    >>> print(np.allclose(quaternion_matrix(q), turn))
    True
    """
    R0 = quaternion_matrix(np.asarray(q0, float).reshape(-1, 4))
    F0 = np.asarray(frame0, float).reshape(-1, 3, 3)
    F = np.asarray(frame, float).reshape(-1, 3, 3)
    return matrix_quaternion(F @ np.swapaxes(F0, 1, 2) @ R0)


def bounding_size(vertices):
    """The schema's size of a polyhedron: d = 2 x the largest centre-to-vertex
    distance.

    Parameters
    ----------
    vertices : array_like, shape (V, 3)
        m, local frame (origin at the centre of mass).

    Returns
    -------
    float
        m.

    Examples
    --------
    >>> from lmgc90.grains import bounding_size
    >>> print(bounding_size([[0.01, 0.0, 0.0], [0.0, -0.02, 0.0], [0.0, 0.0, 0.005]]))
    0.04
    """
    v = np.asarray(vertices, float).reshape(-1, 3)
    return float(2.0 * np.linalg.norm(v, axis=1).max())
