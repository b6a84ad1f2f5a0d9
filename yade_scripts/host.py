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
    """(model, sorted SIMD_FLAGS present) from the text of /proc/cpuinfo,
    its first processor block: model is "NAME (family F, model M, stepping
    S)" (a virtual machine's name alone can hide the generation), with the
    parts it does not give left out; ("", []) when it gives none."""
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
    CPU (sorted names; [] when numpy does not say), or (None, []) without
    numpy."""
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
    """Dict of the host facts a run's numbers can depend on: ``hostname``,
    ``machine``, ``cpu`` (model name), ``cpu_flags`` (SIMD_FLAGS present),
    ``numpy`` (version), ``numpy_simd`` (extensions numpy dispatches to),
    ``libc`` ("glibc 2.36"), ``python``. A fact that cannot be read is
    an empty string or list, never an error."""
    try:
        with open(cpuinfo_path) as fh:
            model, flags = cpu_from_cpuinfo(fh.read())
    except OSError:
        model, flags = "", []
    np_version, np_simd = numpy_simd()
    libc = " ".join(p for p in platform.libc_ver() if p)
    return {"hostname": platform.node(), "machine": platform.machine(), "cpu": model, "cpu_flags": flags,
            "numpy": np_version or "", "numpy_simd": np_simd, "libc": libc, "python": platform.python_version()}
