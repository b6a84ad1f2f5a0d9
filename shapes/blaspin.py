"""The same library on every CPU of a kind: OpenBLAS's kernels pinned.

numpy's and scipy's wheels carry OpenBLAS built with ``DYNAMIC_ARCH``: it
picks its kernels by the CPU it finds, and two kernel sets round a matrix
product differently in the last bits. A grain's vertices go through such
products (its principal frame), so the same recipe and seed give libraries
that differ in their bytes, hence in their fingerprint, from one CPU to the
next, or from one environment to the next (``OPENBLAS_CORETYPE`` chooses
them by hand). ``python -m shapes build --n 1000 --seed 0`` gives the
committed archive's library (fingerprint ``2a9094b6…``) with OpenBLAS's
``SkylakeX`` or ``Cooperlake`` (AVX-512) kernels, and another
(``aeafe8a3…``) with its ``Haswell`` or ``Zen`` ones, on the same CPU
(docs/measurements.md, "The shape library across CPUs").

``python -m shapes`` therefore runs with ``OPENBLAS_CORETYPE`` set to
:func:`reproducible_coretype`: ``SkylakeX`` on a CPU with the AVX-512
subsets those kernels use, ``Haswell`` on one with AVX2 and FMA only,
replacing another value the environment gives (with a note on stderr), unless
``SHAPES_KEEP_OPENBLAS_CORETYPE=1``. OpenBLAS reads the variable when it is
loaded, so :func:`pin` re-executes the command once with it set.
"""
from __future__ import annotations

import os
import sys

#: the CPU flags each pinned kernel set needs, in order of preference
CORETYPES = (("SkylakeX", ("avx512f", "avx512dq", "avx512bw", "avx512vl")),
             ("Haswell", ("avx2", "fma")))
ENV = "OPENBLAS_CORETYPE"
KEEP = "SHAPES_KEEP_OPENBLAS_CORETYPE"


def cpu_flags(cpuinfo="/proc/cpuinfo"):
    """The CPU's feature flags (Linux ``/proc/cpuinfo``); an empty set where unreadable.

    Parameters
    ----------
    cpuinfo : str
        The file to read.

    Returns
    -------
    set of str
        The flags of the first processor listed.
    """
    try:
        with open(cpuinfo) as fh:
            for line in fh:
                if line.startswith("flags"):
                    return set(line.split(":", 1)[1].split())
    except OSError:
        pass
    return set()


def reproducible_coretype(flags):
    """The OpenBLAS kernel set a library is built with on a CPU with ``flags``.

    Parameters
    ----------
    flags : set of str
        CPU feature flags (:func:`cpu_flags`).

    Returns
    -------
    str or None
        ``"SkylakeX"``, ``"Haswell"``, or None (neither: OpenBLAS chooses).

    Examples
    --------
    >>> reproducible_coretype({"avx2", "fma", "avx512f", "avx512dq", "avx512bw", "avx512vl"})
    'SkylakeX'
    >>> reproducible_coretype({"avx2", "fma", "avx512f"})
    'Haswell'
    >>> reproducible_coretype({"sse4_2"}) is None
    True
    """
    for name, needed in CORETYPES:
        if set(needed) <= set(flags):
            return name
    return None


def openblas_core():
    """The kernel set numpy's own OpenBLAS runs with in this process (e.g. ``"Haswell"``).

    Returns
    -------
    str or None
        OpenBLAS's core name, or None when numpy carries no OpenBLAS that
        says it (another BLAS, or a build without the query).
    """
    import ctypes
    import glob

    import numpy

    libs = glob.glob(os.path.join(os.path.dirname(os.path.dirname(numpy.__file__)), "numpy.libs", "*openblas*"))
    for path in libs:
        try:
            lib = ctypes.CDLL(path)
        except OSError:
            continue
        for name in ("scipy_openblas_get_corename64_", "openblas_get_corename64_", "openblas_get_corename"):
            f = getattr(lib, name, None)
            if f is not None:
                f.restype = ctypes.c_char_p
                return f().decode()
    return None


def pin(argv, environ=None, execv=os.execv, flags=None, stderr=None):
    """Re-execute ``python -m shapes argv`` with ``OPENBLAS_CORETYPE`` pinned, unless it already is.

    Parameters
    ----------
    argv : list of str
        The command line after ``python -m shapes``.
    environ : mapping, optional
        The environment (default ``os.environ``), updated in place.
    execv : callable
        ``os.execv`` (a test passes its own).
    flags : set of str, optional
        The CPU's flags (default :func:`cpu_flags`).
    stderr : file, optional
        Where the note on a replaced value goes (default ``sys.stderr``).

    Returns
    -------
    str or None
        The core type in force when it returns without re-executing: the
        pinned one, the environment's own under ``SHAPES_KEEP_OPENBLAS_CORETYPE=1``,
        or None where no pinned set runs on this CPU (OpenBLAS chooses).
    """
    environ = os.environ if environ is None else environ
    if environ.get(KEEP) == "1":
        return environ.get(ENV)
    chosen = reproducible_coretype(cpu_flags() if flags is None else flags)
    if chosen is None or environ.get(ENV) == chosen:
        return environ.get(ENV)
    if environ.get(ENV):
        print(f"shapes: OPENBLAS_CORETYPE={environ[ENV]} replaced by {chosen}, so that the library is the "
              f"same on every CPU of this kind ({KEEP}=1 keeps it)", file=stderr or sys.stderr)
    environ[ENV] = chosen
    execv(sys.executable, [sys.executable, "-m", "shapes", *argv])
    return chosen
