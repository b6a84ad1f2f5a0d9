"""YADE without its remote servers.

Debian's ``yade`` launcher (``/usr/bin/yade-double``) calls
``yade.remote.runServers()`` before it runs a script: a TCP Python prompt
on port 9000 and up (its cookie printed on stdout) and an XMLRPC server
without authentication on port 21000 and up, both on every interface. A
batch job must listen on nothing, so every run the project starts goes
through :func:`command`, which starts the same launcher, with the same
options, the same ``YADE_PREFIX`` plugins and the same OpenMP threads, but
with ``runServers`` made a no-op before the launcher imports it; the run
opens no socket and prints no cookie. A scene started by hand with the
``yade`` launcher calls :func:`close_servers` at its start.

Run as a script (what :func:`command` returns)::

    /usr/bin/python3 noremote.py /usr/bin/yade -j2 -n -x triaxial.py

This module uses the standard library only (it runs before YADE exists).
"""
import builtins
import gc
import importlib.abc
import importlib.machinery
import os
import socketserver
import sys
import threading
import types

#: what marks a YADE launcher: it calls this
MARK = b"yade.remote.runServers"


def launcher_python(yade):
    """The Python interpreter of the YADE launcher ``yade`` (its ``#!``
    line), or None when ``yade`` is not a Python launcher that starts
    YADE's remote servers (a stand-in, a compiled program, a shell script).

    >>> launcher_python("/nonexistent/yade") is None
    True
    """
    try:
        with open(yade, "rb") as fh:
            head = fh.read(1 << 16)
    except OSError:
        return None
    first = head.split(b"\n", 1)[0]
    if not first.startswith(b"#!") or b"python" not in first or MARK not in head:
        return None
    words = first[2:].decode(errors="replace").split()
    if os.path.basename(words[0]) == "env" and len(words) > 1:
        return words[1]
    return words[0]


def command(yade, args):
    """The command line that runs the YADE launcher ``yade`` with ``args``
    (list of str, e.g. ``["-j", "2", "-n", "-x", "triaxial.py"]``) without
    its remote servers: ``[python, this file, yade, *args]``; or
    ``[yade, *args]`` when ``yade`` is not such a launcher (a stand-in).

    >>> command("/nonexistent/yade", ["-n", "-x", "triaxial.py"])
    ['/nonexistent/yade', '-n', '-x', 'triaxial.py']
    """
    python = launcher_python(yade)
    if python is None:
        return [yade, *args]
    return [python, os.path.abspath(__file__), yade, *args]


def close_servers(timeout=2.0):
    """Close every ``socketserver`` server of this process (YADE's remote
    prompt and XMLRPC server, which ``runServers`` starts and keeps no
    handle to): stop its loop, close its listening socket.

    Parameters
    ----------
    timeout : float
        Seconds to wait for each server's loop to end (s).

    Returns
    -------
    list of int
        The ports that were listening, sorted (empty when none was open).
    """
    ports = []
    for obj in gc.get_objects():
        if not isinstance(obj, socketserver.BaseServer) or getattr(obj, "socket", None) is None:
            continue
        try:
            port = obj.socket.getsockname()[1]
        except OSError:                       # closed already
            continue
        stopper = threading.Thread(target=obj.shutdown, daemon=True)
        stopper.start()
        stopper.join(timeout)                 # shutdown() waits for a loop that may never have started
        obj.server_close()
        ports.append(int(port))
    return sorted(ports)


class _NoServers(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Import ``yade.remote`` as it is, then make its ``runServers`` a no-op."""

    def find_spec(self, name, path, target=None):
        if name != "yade.remote":
            return None
        spec = importlib.machinery.PathFinder.find_spec(name, path)
        if spec is None:
            return None
        self.real = spec.loader
        spec.loader = self
        return spec

    def create_module(self, spec):
        return self.real.create_module(spec)

    def exec_module(self, module):
        self.real.exec_module(module)
        module.runServers = _no_servers


def _no_servers():
    """Stands for ``yade.remote.runServers``: opens nothing."""
    return None


def main(argv):
    """Run the launcher ``argv[0]`` with options ``argv[1:]`` as if it had
    been started itself, its remote servers off."""
    if not argv:
        sys.exit("noremote.py: usage: noremote.py YADE_LAUNCHER [yade options] script.py")
    launcher = argv[0]
    sys.argv = list(argv)
    sys.path[0] = os.path.dirname(os.path.abspath(launcher))    # as if the launcher were run directly
    sys.meta_path.insert(0, _NoServers())
    with open(launcher, "rb") as fh:
        code = compile(fh.read(), launcher, "exec")
    this = sys.modules["__main__"]            # kept alive while the launcher runs
    main_module = types.ModuleType("__main__")   # YADE runs strings in __main__, whose __builtins__ is a module
    main_module.__file__ = launcher
    main_module.__builtins__ = builtins
    sys.modules["__main__"] = main_module
    try:
        exec(code, main_module.__dict__)
    finally:
        sys.modules["__main__"] = this


if __name__ == "__main__":
    main(sys.argv[1:])
