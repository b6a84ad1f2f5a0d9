"""Where a study keeps its runs: the run folders of a study folder, a
run's dump in its folder, its analysis folder beside it, and whether a
complete dump adds up. Shared by the study (:mod:`yade_scripts.campaign.study`)
and its archive (:mod:`yade_scripts.campaign.archive_store`).
"""
from __future__ import annotations

import os
import re

from postproc.schema import DumpFormatError, DumpReader

from ..launch.batch import dump_of

#: a run folder set aside because its parameters changed (FOLDER.old-K)
SET_ASIDE = re.compile(r"\.old-\d+$")


def run_folders(folder):
    """The generated run folders of a study (each with a ``table.txt``).

    Parameters
    ----------
    folder : str
        A study folder, or one generated run folder.

    Returns
    -------
    list of str
        ``[folder]`` when it is a run folder itself, else the run folders
        one level below it, sorted, but for those set aside
        (:data:`SET_ASIDE`); [] when there are none.

    Examples
    --------
    >>> import os, tempfile
    >>> study = tempfile.mkdtemp()
    >>> for name in ("spheres-ensemble", "polyhedra-ensemble", "polyhedra-ensemble.old-1", "report"):
    ...     os.makedirs(os.path.join(study, name))
    ...     if name != "report":
    ...         open(os.path.join(study, name, "table.txt"), "w").close()
    >>> [os.path.basename(f) for f in run_folders(study)]
    ['polyhedra-ensemble', 'spheres-ensemble']
    """
    if os.path.exists(os.path.join(folder, "table.txt")):
        return [folder]
    return sorted(os.path.join(folder, d) for d in os.listdir(folder)
                  if os.path.exists(os.path.join(folder, d, "table.txt")) and not SET_ASIDE.search(d))


def line_dump(table, line):
    """The dump of run line ``line`` of the run folder ``table``: in the
    line's own folder ``<description>/`` when there is one (a SLURM array
    task's), else next to the table.

    Parameters
    ----------
    table : str
        The generated run folder (its ``table.txt``).
    line : yade_scripts.launch.batch.TableLine
        A run line of its table.

    Returns
    -------
    str
        The dump's path (:func:`yade_scripts.launch.batch.dump_of`, moved into
        ``table/<description>/`` when that folder exists); it may not
        exist.
    """
    own = os.path.join(table, line.description)
    return (os.path.join(own, os.path.basename(dump_of(table, line.row))) if os.path.isdir(own)
            else dump_of(table, line.row))


def analysis_folder(dump):
    """The analysis folder of a run's dump.

    Parameters
    ----------
    dump : str
        The dump's path.

    Returns
    -------
    str
        ``analysis/`` beside ``run.h5``, else ``analysis-<stem>/`` beside
        ``<stem>.h5``; it may not exist.

    Examples
    --------
    >>> analysis_folder("runs/t1/run.h5"), analysis_folder("study/s/spheres-seed2.h5")
    ('runs/t1/analysis', 'study/s/analysis-spheres-seed2')
    """
    stem = os.path.splitext(dump)[0]
    name = "analysis" if os.path.basename(stem) == "run" else "analysis-" + os.path.basename(stem)
    return os.path.join(os.path.dirname(dump), name)


def whole(dump):
    """Whether a complete dump adds up: every snapshot it says it has, each
    matching what was recorded when it was written
    (:meth:`postproc.schema.DumpReader.verify`).

    Parameters
    ----------
    dump : str
        The path of a complete dump.

    Returns
    -------
    str or None
        None when it adds up, else the one line why not.
    """
    try:
        with DumpReader(dump) as r:
            r.verify()
    except DumpFormatError as exc:
        return str(exc)
    return None
