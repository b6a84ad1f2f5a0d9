"""Folders written beside their destination, then renamed into place.

An analysis folder or an archived run is built in a staging folder next to
where it goes and renamed there when whole, so a reader never sees half of
one. :func:`tempfile.mkdtemp` makes its folder 0700 whatever the umask; a
staging folder here takes the modes the user's umask gives any new folder,
so what is renamed into place is as readable as the rest of the run folder.
"""
from __future__ import annotations

import os
import tempfile


def current_umask():
    """The process's umask (int, e.g. 0o022), read without changing it for
    longer than the call (``os.umask`` sets and returns it in one)."""
    mask = os.umask(0o077)
    os.umask(mask)
    return mask


def staging_dir(parent, prefix):
    """A new, empty folder in ``parent`` named ``prefix`` + a random part,
    with mode 0o777 & ~umask (what ``os.makedirs`` would give it).

    Parameters
    ----------
    parent : str
        The folder the staged one is renamed into place within (same file
        system, so the rename is atomic).
    prefix : str
        The start of its name, e.g. ".postproc-" (hidden while it is written).

    Returns
    -------
    str
        The folder's path.

    Examples
    --------
    >>> import stat
    >>> old = os.umask(0o027)
    >>> d = staging_dir(tempfile.mkdtemp(), ".tmp-")
    >>> _ = os.umask(old)
    >>> oct(stat.S_IMODE(os.stat(d).st_mode)), os.path.basename(d).startswith(".tmp-")
    ('0o750', True)
    """
    path = tempfile.mkdtemp(prefix=prefix, dir=parent)
    os.chmod(path, 0o777 & ~current_umask())
    return path
