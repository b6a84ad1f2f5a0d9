"""Build LMGC90's Python API (``pylmgc90``) from the vendored source, and find it.

The source snapshot is ``lmgc90/vendor`` (see ``lmgc90/vendor/ORIGIN.md``).
It is configured with cmake and built once into ``lmgc90/_build/<hash>/``,
where ``<hash>`` is the SHA-1 of every vendored file's path and content, of
the cmake flags and of the Python it is built for: a changed source is built
afresh and a stale build is never loaded. The build goes to a temporary
directory renamed into place when it is complete, so a half-built directory
is never taken for a build. ``make lmgc90`` calls :func:`build`.

Needs gfortran, swig, cmake, liblapack-dev and libblas-dev (Debian packages,
``make lmgc90`` installs them). Usage::

    python -m lmgc90.build            # build if needed, print the package's folder
    from lmgc90.build import import_pylmgc90
    chipy, pre = import_pylmgc90()
"""
from __future__ import annotations

import hashlib
import importlib
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
VENDOR = os.path.join(HERE, "vendor")
BUILD_ROOT = os.path.join(HERE, "_build")
CMAKE_FLAGS = ["-DSPARSE_LIBRARY=none", "-DMATLIB_VERSION=none", "-DWITH_HDF5=OFF",
               "-DNO_DOXYGEN=ON", "-DWITH_DOCSTRING=OFF", "-DNO_TEST=ON",
               "-DCMAKE_BUILD_TYPE=Release"]


class LMGC90BuildError(RuntimeError):
    """LMGC90 is not built, or its build cannot be loaded."""


def source_hash(python=sys.executable):
    """12 hex digits naming the build: the vendored tree, the flags, the Python."""
    h = hashlib.sha1()
    for root, dirs, files in os.walk(VENDOR):
        dirs.sort()
        for name in sorted(files):
            path = os.path.join(root, name)
            h.update(os.path.relpath(path, VENDOR).encode() + b"\0")
            if os.path.islink(path):
                h.update(os.readlink(path).encode())
            else:
                with open(path, "rb") as fh:
                    h.update(fh.read())
    # the interpreter's own path, not the file it links to: a venv and the
    # system Python share one binary but not their numpy (whose headers the
    # build compiles against)
    h.update(" ".join(CMAKE_FLAGS).encode() + b"\0" + os.path.abspath(python).encode())
    return h.hexdigest()[:12]


def build_dir(python=sys.executable):
    """The cache folder of the build for the current source and Python."""
    return os.path.join(BUILD_ROOT, source_hash(python))


def build(jobs=2, python=sys.executable, quiet=True):
    """Configure and compile LMGC90 if its cached build is missing.

    Returns the folder that holds the ``pylmgc90`` package. Raises
    :class:`LMGC90BuildError` with the first error line when cmake or the
    compilation fails (the full log is kept in ``lmgc90/_build/failed-<hash>.log``).
    """
    final = build_dir(python)
    if os.path.isdir(os.path.join(final, "pylmgc90")):
        return final
    missing = [tool for tool in ("cmake", "gfortran", "swig") if shutil.which(tool) is None]
    if missing:
        raise LMGC90BuildError(f"cannot build LMGC90: {', '.join(missing)} not found (make lmgc90 installs them)")
    os.makedirs(BUILD_ROOT, exist_ok=True)
    tmp = tempfile.mkdtemp(prefix=".partial-", dir=BUILD_ROOT)
    log_path = os.path.join(tmp, "build.log")
    steps = [["cmake", "-S", VENDOR, "-B", tmp, f"-DPython_EXECUTABLE={python}", *CMAKE_FLAGS],
             ["cmake", "--build", tmp, "-j", str(jobs)]]
    with open(log_path, "w") as log:
        for cmd in steps:
            res = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, text=True)
            if res.returncode != 0:
                break
    if res.returncode != 0:
        kept = os.path.join(BUILD_ROOT, f"failed-{os.path.basename(final)}.log")
        shutil.copy(log_path, kept)
        shutil.rmtree(tmp, ignore_errors=True)
        with open(kept) as fh:
            errors = [line.strip() for line in fh if "Error" in line or "error:" in line]
        raise LMGC90BuildError(f"building LMGC90 failed: {(errors or ['see log'])[0]} (log: {kept})")
    if not os.path.isdir(os.path.join(tmp, "pylmgc90")):
        shutil.rmtree(tmp, ignore_errors=True)
        raise LMGC90BuildError("building LMGC90 made no pylmgc90 package")
    os.replace(tmp, final)
    if not quiet:
        print(f"lmgc90: built {final}", file=sys.stderr)
    return final


def pylmgc90_path(directory=None):
    """The folder holding a complete ``pylmgc90`` package (its ``chipy`` extension).

    ``directory`` defaults to the cached build for the current source and
    Python. Raises :class:`LMGC90BuildError` naming what is missing.
    """
    directory = directory or build_dir()
    pkg = os.path.join(directory, "pylmgc90")
    if not os.path.isdir(pkg):
        raise LMGC90BuildError(f"LMGC90 is not built in {directory} (run make lmgc90)")
    chipy = os.path.join(pkg, "chipy")
    if not os.path.isdir(chipy) or not any(n.endswith(".so") for n in os.listdir(chipy)):
        raise LMGC90BuildError(f"LMGC90 build in {directory} has no compiled chipy module (run make lmgc90)")
    return directory


def import_pylmgc90(directory=None):
    """Import ``pylmgc90.chipy`` and ``pylmgc90.pre`` from a build; returns ``(chipy, pre)``.

    Raises :class:`LMGC90BuildError` in one line when the build is missing or
    its compiled modules cannot be loaded (e.g. a corrupt shared library).
    """
    directory = pylmgc90_path(directory)
    if directory not in sys.path:
        sys.path.insert(0, directory)
    try:
        chipy = importlib.import_module("pylmgc90.chipy")
        pre = importlib.import_module("pylmgc90.pre")
    except (ImportError, OSError) as exc:
        msg = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        raise LMGC90BuildError(f"LMGC90 build in {directory} cannot be loaded: {msg}") from None
    return chipy, pre


def main(argv=None):
    """``python -m lmgc90.build``: build if needed, print the folder; one-line errors."""
    try:
        path = build(quiet=False)
        import_pylmgc90(path)
    except LMGC90BuildError as exc:
        print(f"lmgc90: {exc}", file=sys.stderr)
        return 1
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
