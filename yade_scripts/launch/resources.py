"""Will the runs fit this machine's memory? Checked before any YADE starts,
with a one-line refusal (the grains' fit in their box is a parameter check,
:func:`yade_scripts.scene.parameters.check`).

Peak memory of one YADE process (VmHWM) of the default S1, measured here: 331
MB at 1000 grains and 560 MB at 5000 (kernel on one thread, in shear), so
274 MB + 57 kB per grain; ``benchmarks/bench_scale.py`` measures the peak at
the paper's 36 933 grains against this model (docs/scenes.md). YADE's
spheres cost less per particle; the polyhedra figure is used for both, an
upper bound.
"""
from __future__ import annotations

import os

from ..scene.parameters import ConfigError

#: peak resident memory of one run, MB: base + per grain x N
MEMORY_BASE_MB = 274.0
MEMORY_PER_GRAIN_MB = 0.057


def memory_mb(params):
    """The peak resident memory of one run: MEMORY_BASE_MB +
    MEMORY_PER_GRAIN_MB x N (274 MB + 57 kB per grain, the model of the
    module docstring, measured on the default S1 and used for both samples).

    Parameters
    ----------
    params : dict
        A run's parameters (:func:`yade_scripts.campaign.presets.resolve`); only
        ``n_particles`` is read.

    Returns
    -------
    float
        MB.

    Examples
    --------
    >>> from yade_scripts.campaign.presets import resolve
    >>> round(memory_mb(resolve("default", "polyhedra")), 1), round(memory_mb({"n_particles": 36933}))
    (331.0, 2379)
    """
    return MEMORY_BASE_MB + MEMORY_PER_GRAIN_MB * int(params["n_particles"])


def machine_memory_mb():
    """The machine's total memory.

    Returns
    -------
    float or None
        MB (2^20 bytes), from ``MemTotal`` of /proc/meminfo, else from
        sysconf; None when neither tells.

    Examples
    --------
    >>> machine_memory_mb() > 0
    True
    """
    try:
        with open("/proc/meminfo") as fh:
            for line in fh:
                if line.startswith("MemTotal:"):
                    return int(line.split()[1]) / 1024
    except OSError:
        pass
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2 ** 20
    except (ValueError, OSError, AttributeError):
        return None


def check_memory(runs, memory_total_mb=None):
    """Refuse runs that together need more memory than the machine has,
    before any of them starts (the sum of :func:`memory_mb`).

    Parameters
    ----------
    runs : list of dict
        The checked parameters of the runs that go at once.
    memory_total_mb : float, optional
        MB available (default: this machine's, :func:`machine_memory_mb`;
        nothing is refused when that is unknown).

    Returns
    -------
    None

    Raises
    ------
    ConfigError
        One line: how much the runs need, the largest of them, and the
        memory there is.

    Examples
    --------
    >>> from yade_scripts.campaign.presets import resolve
    >>> s1 = resolve("default", "polyhedra")
    >>> check_memory([s1, s1], memory_total_mb=1024)          # 662 MB of 1 GB
    >>> check_memory([s1] * 4, memory_total_mb=1024)
    Traceback (most recent call last):
        ...
    yade_scripts.scene.parameters.ConfigError: 4 run(s) at once need about 1.3 GB of memory (the largest, ...
    """
    total = machine_memory_mb() if memory_total_mb is None else memory_total_mb
    need = sum(memory_mb(p) for p in runs)
    if total is not None and runs and need > total:
        big = max(runs, key=memory_mb)
        raise ConfigError(f"{len(runs)} run(s) at once need about {need / 1024:.1f} GB of memory (the largest, "
                          f"{big['n_particles']} {big['sample']}, {memory_mb(big):.0f} MB), more than this "
                          f"machine's {total / 1024:.1f} GB: run fewer at once (--jobs) or on a larger node")
