"""Where a run ran: the host facts that can change its numbers bit for bit.

A run repeats step for step only on hosts whose CPUs make glibc's maths
library pick the same code (docs/scenes.md, "Preparation"; measured, on
docs/measurements.md, "Preparation": switching off
glibc's AVX2/FMA code moved the isotropic state by 50 steps; numpy's vector
dispatch, the kernel's thread count and the venv's numpy/scipy did not), and a
packing's dynamics amplify a last-bit difference. The scene records these
facts in ``run.info.json`` (``"host"``, read by the attempt that finished the
run) so that two runs that differ can be told apart by their hosts.

Standard library, and numpy when it is there (runs on YADE's Python and in
the venv).
"""
from __future__ import annotations

import platform

#: the CPU flags (as /proc/cpuinfo names them) that select vector code paths
SIMD_FLAGS = ("sse4_2", "avx", "avx2", "fma", "avx512f", "avx512dq", "avx512vl", "avx512bw")


def cpu_from_cpuinfo(text):
    """The CPU's model and vector extensions, from the text of
    /proc/cpuinfo (its first processor block).

    Parameters
    ----------
    text : str
        The text of /proc/cpuinfo.

    Returns
    -------
    model : str
        "NAME (family F, model M, stepping S)" (a virtual machine's name
        alone can hide the generation), the parts the text does not give
        left out; "" when it gives none.
    flags : list of str
        The :data:`SIMD_FLAGS` among the block's ``flags``, sorted.

    Examples
    --------
    >>> text = ("processor : 0\\nmodel name : Intel Xeon\\ncpu family : 6\\nmodel : 85\\n"
    ...         "stepping : 7\\nflags : fpu sse4_2 avx avx2 fma\\n\\nprocessor : 1\\n")
    >>> cpu_from_cpuinfo(text)
    ('Intel Xeon (family 6, model 85, stepping 7)', ['avx', 'avx2', 'fma', 'sse4_2'])
    >>> cpu_from_cpuinfo("")
    ('', [])
    """
    first = text.split("\n\n", 1)[0]
    fields = {}
    for line in first.splitlines():
        key, sep, value = line.partition(":")
        if sep:
            fields.setdefault(key.strip(), value.strip())
    ids = ", ".join(f"{k.replace('cpu ', '')} {fields[k]}" for k in ("cpu family", "model", "stepping")
                    if fields.get(k))
    model = fields.get("model name", "") + (f" ({ids})" if ids else "")
    present = set(fields.get("flags", "").split())
    return model.strip(), sorted(f for f in SIMD_FLAGS if f in present)


def numpy_simd():
    """numpy's version and the SIMD extensions its dispatch found on this
    CPU.

    Returns
    -------
    version : str or None
        numpy's version; None without numpy.
    extensions : list of str
        The extensions numpy's dispatch found (sorted names, e.g. "AVX2",
        "FMA3"); [] when numpy does not say or is missing.

    Examples
    --------
    >>> import numpy
    >>> version, extensions = numpy_simd()
    >>> version == numpy.__version__, isinstance(extensions, list)
    (True, True)
    """
    try:
        import numpy as np
    except ImportError:
        return None, []
    features = {}
    for name in ("numpy._core._multiarray_umath", "numpy.core._multiarray_umath"):
        try:
            mod = __import__(name, fromlist=["__cpu_features__"])
            features = getattr(mod, "__cpu_features__", {})
            break
        except ImportError:
            continue
    return np.__version__, sorted(k for k, v in features.items() if v)


def host_info(cpuinfo_path="/proc/cpuinfo"):
    """The facts of this host that a run's numbers can depend on, as the
    scene stores them in ``run.info.json`` (``"host"``).

    Parameters
    ----------
    cpuinfo_path : str
        Where to read the CPU's model and flags (:func:`cpu_from_cpuinfo`).

    Returns
    -------
    dict
        ``hostname``, ``machine`` (e.g. "x86_64"), ``cpu`` (model name),
        ``cpu_flags`` (the :data:`SIMD_FLAGS` present), ``numpy``
        (version), ``numpy_simd`` (the extensions numpy dispatches to),
        ``libc`` (e.g. "glibc 2.36"), ``python`` (version). A fact that
        cannot be read is an empty string or list, never an error.

    Examples
    --------
    >>> info = host_info()
    >>> sorted(info)
    ['cpu', 'cpu_flags', 'hostname', 'libc', 'machine', 'numpy', 'numpy_simd', 'python']
    >>> info["python"] == platform.python_version()
    True
    >>> host_info("/nonexistent/cpuinfo")["cpu"], host_info("/nonexistent/cpuinfo")["cpu_flags"]
    ('', [])
    """
    try:
        with open(cpuinfo_path) as fh:
            model, flags = cpu_from_cpuinfo(fh.read())
    except OSError:
        model, flags = "", []
    np_version, np_simd = numpy_simd()
    libc = " ".join(p for p in platform.libc_ver() if p)
    return {"hostname": platform.node(), "machine": platform.machine(), "cpu": model, "cpu_flags": flags,
            "numpy": np_version or "", "numpy_simd": np_simd, "libc": libc, "python": platform.python_version()}
