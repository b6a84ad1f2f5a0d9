"""Periodic cells: the minimum-image convention for branch vectors.

A periodic cell is a (3, 3) matrix H whose columns are the cell vectors
(YADE's ``O.cell.hSize``; an orthorhombic cell LX, LY, LZ is diag(L)). A
point x has the images x + H n for every integer vector n. The branch
vector of a contact between bodies at x1 and x2 is the image of x2 - x1
closest to zero in the cell's fractional coordinates:

    s = H^-1 (x2 - x1),   l = H (s - round(s)),

which is the true minimum image whenever the contact is shorter than half
the cell's smallest width (for an orthorhombic cell, exactly
l_k = d_k - L_k round(d_k / L_k)). With branch vectors so defined the
internal-moment stress sum f (x) l / V over the contacts of the cell (seed
eq. 2, V = det H) is the stress of the infinite periodic packing, with no
boundary term. For a strongly sheared cell, where this choice can pick the
wrong image, give the branch vectors explicitly (table columns lx, ly, lz).
"""
from __future__ import annotations

import numpy as np

from .errors import InputError


def cell_matrix(cell):
    """(3, 3) m cell matrix from three lengths (orthorhombic) or a (3, 3)
    matrix (columns = cell vectors). InputError if not finite or det <= 0.

    Parameters
    ----------
    cell : array_like, shape (3,) or (3, 3)
        m, the lengths LX, LY, LZ of an orthorhombic cell, or the cell
        matrix H whose columns are the cell vectors (YADE's
        ``O.cell.hSize``).

    Returns
    -------
    ndarray, shape (3, 3)
        float, m, H: diag(LX, LY, LZ) for three lengths, else the matrix as
        given. Its determinant is the cell volume V (m^3, > 0).

    Raises
    ------
    InputError
        Another shape, a non-finite entry, or det H <= 0 (a flat or
        left-handed cell).
    """
    H = np.asarray(cell, float)
    if H.shape == (3,):
        H = np.diag(H)
    if H.shape != (3, 3) or not np.all(np.isfinite(H)):
        raise InputError(f"periodic cell must be 3 lengths or a 3x3 matrix, got {H.tolist()}")
    if not np.linalg.det(H) > 0:
        raise InputError(f"periodic cell {H.tolist()} has volume <= 0")
    return H


def minimum_image(d, cell):
    """(C, 3) m, the image of each vector d (C, 3) closest to zero in the
    fractional coordinates of ``cell`` (3, 3); see the module docstring.

    Parameters
    ----------
    d : array_like, shape (C, 3)
        m, the vectors to wrap, e.g. x2 - x1 of each contact.
    cell : array_like, shape (3,) or (3, 3)
        m, the periodic cell (:func:`cell_matrix`).

    Returns
    -------
    ndarray, shape (C, 3)
        float, m, l = H (s - round(s)) with s = H^-1 d: each vector minus the
        integer combination of cell vectors that brings its fractional
        coordinates into [-1/2, 1/2] (for a diagonal H, l_k = d_k - L_k
        round(d_k / L_k)). It is the true minimum image when the result is
        shorter than half the cell's smallest width.

    Raises
    ------
    InputError
        A bad cell (:func:`cell_matrix`).
    """
    H = cell_matrix(cell)
    d = np.asarray(d, float)
    if np.count_nonzero(H - np.diag(np.diag(H))) == 0:
        L = np.diag(H)
        return d - L * np.round(d / L)
    s = np.linalg.solve(H, d.T).T
    return (s - np.round(s)) @ H.T


def same_point_modulo(a, b, cell, rtol=1e-9):
    """(N,) bool: a and b (N, 3) are images of one point of the cell, to
    ``rtol`` times the cell size.

    Parameters
    ----------
    a, b : array_like, shape (N, 3)
        m, the points to compare, row by row.
    cell : array_like, shape (3,) or (3, 3)
        m, the periodic cell (:func:`cell_matrix`).
    rtol : float, optional
        The tolerance relative to the cell size, taken as the largest
        absolute entry of H (default 1e-9).

    Returns
    -------
    ndarray of bool, shape (N,)
        True where every component of the minimum image of a - b
        (:func:`minimum_image`) is at most rtol * max|H| in absolute value.

    Raises
    ------
    InputError
        A bad cell (:func:`cell_matrix`).
    """
    H = cell_matrix(cell)
    r = minimum_image(np.asarray(a, float) - np.asarray(b, float), H)
    return np.abs(r).max(axis=1) <= rtol * np.abs(H).max()
