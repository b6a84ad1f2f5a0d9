"""Build and load the compiled contact kernel (``polycontact.c``) with ctypes.

Why a C file and ctypes: the kernel must run inside YADE's own Python
(Debian's /usr/bin/python3, numpy 1.24) and in the project's venv. A plain C
shared library loaded with ctypes needs nothing but gcc, which a Debian 12
machine has (``build-essential``), no Python headers, no numba version that
matches both numpy builds, and no YADE headers (YADE plugins cannot be built
here). OpenMP (libgomp, gcc's own) uses both cores.

The library is compiled on first use into ``_build/`` next to the source,
named by a hash of the source and the flags, so a changed source is rebuilt
and a stale build is never loaded. The build goes to a temporary name and is
renamed into place, so two processes that build at once (yade-batch -j 2) do
not see a half-written file. ``make kernel`` builds it ahead of time.

Imports only the standard library and numpy (run folders get a copy of the
package, ``polycontact.c`` included, and build it there).
"""
from __future__ import annotations

import ctypes
import hashlib
import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.join(HERE, "polycontact.c")
# -ffp-contract=off: no fused multiply-adds, so that two code paths that
# compute the same expression (the culled clipping and the plain one) give
# the same bits on every x86-64 or ARM machine
CFLAGS = ["-O3", "-fopenmp", "-fPIC", "-shared", "-std=gnu99", "-fno-math-errno", "-ffp-contract=off"]
_LIB = None


class KernelBuildError(RuntimeError):
    """The C kernel could not be compiled or loaded."""


def library_path(build_dir=None):
    """Path of the shared library for the current source and flags."""
    with open(SOURCE, "rb") as fh:
        digest = hashlib.sha1(fh.read() + " ".join(CFLAGS).encode()).hexdigest()[:12]
    return os.path.join(build_dir or os.path.join(HERE, "_build"), f"polycontact-{digest}.so")


def build(build_dir=None, quiet=True):
    """Compile the kernel if its library is missing; returns its path."""
    path = library_path(build_dir)
    if os.path.exists(path):
        return path
    os.makedirs(os.path.dirname(path), exist_ok=True)
    fd, tmp = tempfile.mkstemp(suffix=".so", dir=os.path.dirname(path))
    os.close(fd)
    cmd = ["gcc", *CFLAGS, "-o", tmp, SOURCE, "-lm"]
    try:
        res = subprocess.run(cmd, capture_output=True, text=True)
    except FileNotFoundError:
        os.unlink(tmp)
        raise KernelBuildError("gcc not found: install it (apt-get install gcc) to build the contact kernel") from None
    if res.returncode != 0:
        os.unlink(tmp)
        first = (res.stderr.strip().splitlines() or ["no message"])[0]
        raise KernelBuildError(f"building {SOURCE} failed: {first}")
    os.replace(tmp, path)
    if not quiet:
        print(f"ckernel: built {path}", file=sys.stderr)
    return path


_D = ctypes.POINTER(ctypes.c_double)
_I = ctypes.POINTER(ctypes.c_int)


def load():
    """The loaded kernel (ctypes CDLL), building it if needed."""
    global _LIB
    if _LIB is not None:
        return _LIB
    lib = ctypes.CDLL(build())
    geo = [ctypes.c_int, _I, _D, _I, _I]
    lib.pc_batch_overlap.argtypes = geo + [ctypes.c_int, _I, _D, _D, _I, _D, _D, _D, _D, _D, _D, _D, _I, ctypes.c_int]
    lib.pc_batch_overlap.restype = ctypes.c_int
    lib.pc_batch_wall.argtypes = geo + [ctypes.c_int, _I, _D, _D, _D, _D, _D, _D, _D, _D, _D, _I, ctypes.c_int]
    lib.pc_batch_wall.restype = ctypes.c_int
    lib.pc_engine_new.argtypes = geo + [ctypes.c_int, _I, _D, ctypes.c_int, _I, _D, ctypes.c_double,
                                        ctypes.c_double, ctypes.c_double, ctypes.c_double, ctypes.c_double,
                                        ctypes.c_int]
    lib.pc_engine_new.restype = ctypes.c_void_p
    lib.pc_engine_free.argtypes = [ctypes.c_void_p]
    lib.pc_engine_free.restype = None
    lib.pc_engine_step.argtypes = [ctypes.c_void_p, _D, _D, _D, _D, _D, _D, _D]
    lib.pc_engine_step.restype = ctypes.c_int
    lib.pc_engine_count.argtypes = [ctypes.c_void_p]
    lib.pc_engine_count.restype = ctypes.c_int
    lib.pc_engine_contacts.argtypes = [ctypes.c_void_p, ctypes.c_int, _I, _I, _D, _D, _D, _D, _D, _D, _D]
    lib.pc_engine_contacts.restype = ctypes.c_int
    lib.pc_engine_memory.argtypes = [ctypes.c_void_p]
    lib.pc_engine_memory.restype = ctypes.c_long
    lib.pc_engine_set_history.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.c_int, _D]
    lib.pc_engine_set_history.restype = ctypes.c_int
    lib.pc_engine_set_friction.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_double]
    lib.pc_engine_set_friction.restype = ctypes.c_int
    lib.pc_engine_set_groups.argtypes = [ctypes.c_void_p, _I]
    lib.pc_engine_set_groups.restype = ctypes.c_int
    lib.pc_engine_set_facets.argtypes = [ctypes.c_void_p, ctypes.c_int]
    lib.pc_engine_set_facets.restype = ctypes.c_int
    lib.pc_engine_get_friction.argtypes = [ctypes.c_void_p, _D]
    lib.pc_engine_get_friction.restype = None
    lib.pc_engine_npairs.argtypes = [ctypes.c_void_p]
    lib.pc_engine_npairs.restype = ctypes.c_int
    lib.pc_engine_get_state.argtypes = [ctypes.c_void_p, _D, _D, _D, _D, _I, _D, _D, _D, _I, _D]
    lib.pc_engine_get_state.restype = None
    lib.pc_engine_set_state.argtypes = [ctypes.c_void_p, _D, _D, _D, _D, ctypes.c_int, _I, _D, _D, _D, _I, _D]
    lib.pc_engine_set_state.restype = ctypes.c_int
    lib.pc_engine_set_mode.argtypes = [ctypes.c_void_p, ctypes.c_int]
    lib.pc_engine_set_mode.restype = None
    lib.pc_engine_set_workspace_points.argtypes = [ctypes.c_void_p, ctypes.c_int]
    lib.pc_engine_set_workspace_points.restype = ctypes.c_int
    lib.pc_engine_layout.argtypes = [_I]
    lib.pc_engine_layout.restype = None
    lib.pc_engine_stat_name.argtypes = [ctypes.c_int]
    lib.pc_engine_stat_name.restype = ctypes.c_char_p
    _LIB = lib
    return lib


def dptr(a):
    """ctypes double pointer to a C-contiguous float64 array."""
    return a.ctypes.data_as(_D)


def iptr(a):
    """ctypes int pointer to a C-contiguous int32 array."""
    return a.ctypes.data_as(_I)


def f64(a, shape=None):
    """``a`` as a C-contiguous float64 array (a copy only when needed),
    reshaped to ``shape`` when given: what :func:`dptr` takes.

    Parameters
    ----------
    a : array_like
        The values.
    shape : tuple of int, optional
        The shape to give the result.

    Returns
    -------
    numpy.ndarray
        float64, C-contiguous.

    Examples
    --------
    >>> f64([[1, 2], [3, 4]], shape=(4,))
    array([1., 2., 3., 4.])
    """
    a = np.ascontiguousarray(a, dtype=np.float64)
    return a if shape is None else a.reshape(shape)


def i32(a):
    """``a`` as a C-contiguous int32 array (a copy only when needed): what
    :func:`iptr` takes.

    Parameters
    ----------
    a : array_like
        The values (integers).

    Returns
    -------
    numpy.ndarray
        int32, C-contiguous.

    Examples
    --------
    >>> i32([0, 8, 16]).dtype
    dtype('int32')
    """
    return np.ascontiguousarray(a, dtype=np.int32)
