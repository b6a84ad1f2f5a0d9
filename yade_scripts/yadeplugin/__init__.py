"""The YADE plugin that runs the polyhedra kernel inside YADE's own step.

``PolyhedraKernelEngine`` (``PolyhedraKernelEngine.cpp`` here) is a YADE
``GlobalEngine``: each step it reads the polyhedra's poses and the walls'
positions from YADE's bodies, calls the compiled kernel (``shapes/polycontact.c``,
the library Python loaded with ctypes) and adds the forces and torques to
YADE's force container, without the Python round trip of the ``PyRunner``
path (:mod:`yade_scripts.scene.kernel_contacts` drives both).

This module builds it against the installed YADE and decides whether it may
be used:

1. *What YADE is this?* :func:`find_yade` reads the installed YADE's
   ``config.py`` (its library folder, version, precision and compile-time
   features); :func:`defines` turns the features into the preprocessor
   definitions YADE's own build used (CMakeLists.txt of YADE), on which the
   layouts of its classes depend.
2. *Build* (:func:`build`): ``g++`` against the YADE headers vendored in
   ``include/`` (YADE's, GPL-2.0-or-later, ``include/ORIGIN.md``), Eigen,
   Boost.Python, CGAL and MPI headers from Debian. The sizes of the classes
   the plugin reads (``Scene``, ``Body``, ``State``, ``BodyContainer``,
   ``Engine``, ``GlobalEngine``) are read off the installed ``libyade.so``
   (the ``operator new`` of its ``Create<Class>`` factories) and checked by
   ``static_assert`` at compile time; after the build every vtable the plugin
   shares with YADE's libraries must have the same size as theirs
   (:func:`vtable_mismatches`).
3. *Probe* (:func:`probe`): a tiny polyhedra scene in a YADE subprocess
   started with ``YADE_PREFIX`` on the plugin's prefix folder steps once with
   the plugin and once with the ``PyRunner`` path from the same state; the
   poses and masses read and the forces and torques added must be equal bit
   for bit. A crash (a layout that differs would crash rather than mislead)
   or a difference marks the build unusable.

The result is kept in ``_build/<key>/status.json``, where ``key`` hashes the
sources, the flags and the installed ``libyade.so``: another YADE, a changed
source or other flags build and probe again; a second call is a lookup.
:func:`environment` gives the ``YADE_PREFIX`` the launchers (``pool``,
``batch``, the SLURM script) set for a YADE job; YADE then loads every
``lib*.so`` of ``$YADE_PREFIX/lib/<arch>/yade-double``, a folder of links to
Debian's own plugins and this one.

Standard library only (YADE's Python imports it too). Command line:
``python -m yade_scripts.yadeplugin build`` (``make kernel`` runs it) and
``python -m yade_scripts.yadeplugin status``.
"""
from __future__ import annotations

import glob
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

from ..runs import noremote

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.join(HERE, "PolyhedraKernelEngine.cpp")
#: the engine for a user's own scene (yade_scripts.yadeplugin.contacts), built into the same library
USER_SOURCE = os.path.join(HERE, "PolyhedraContactEngine.cpp")
#: the kernel's step and the addition of its forces, shared by the two engines
SHARED_HEADER = os.path.join(HERE, "kernel_step.hpp")
INCLUDE = os.path.join(HERE, "include")
PROBE_SCENE = os.path.join(HERE, "probe_scene.py")
CLASS_NAME = "PolyhedraKernelEngine"
LIBRARY_NAME = "libPolyhedraKernelEngine.so"
#: classes whose layout the plugin relies on, with the size YADE allocates
CHECKED_CLASSES = ("Scene", "Body", "State", "BodyContainer", "Engine", "GlobalEngine", "Interaction",
                   "InteractionContainer")
#: classes the user's engine writes at measured offsets (no header): their sizes bound the measurement
MEASURED_CLASSES = ("PolyhedraGeom", "PolyhedraPhys")
#: yade.config.features -> the definitions of YADE's CMakeLists.txt
FEATURE_DEFINES = {
    "LOGGER": ["YADE_BOOST_LOG", "BOOST_LOG_DYN_LINK"],
    "OPENMP": ["YADE_OPENMP"],
    "QT5": ["YADE_OPENGL", "YADE_QT5"],
    "MPI": ["YADE_MPI"],
    "VTK": ["YADE_VTK"],
    "GTS": ["YADE_GTS"],
    "CGAL": ["YADE_CGAL"],
    "PFVFLOW": ["FLOW_ENGINE"],
    "LINSOLV": ["LINSOLV"],
    "TWOPHASEFLOW": ["TWOPHASEFLOW"],
    "LS_DEM": ["YADE_LS_DEM"],
    "FEMLIKE": ["YADE_FEM"],
    "GL2PS": ["YADE_GL2PS"],
    "LBMFLOW": ["LBM_ENGINE"],
    "THERMAL": ["THERMAL"],
    "PARTIALSAT": ["PARTIALSAT"],
    "POTENTIAL_PARTICLES": ["YADE_POTENTIAL_PARTICLES"],
    "POTENTIAL_BLOCKS": ["YADE_POTENTIAL_BLOCKS"],
    "COMPLEX_MP": ["YADE_COMPLEX_MP"],
    "SPH": ["YADE_SPH"],
    "LIQMIGRATION": ["YADE_LIQMIGRATION"],
    "DEFORM": ["YADE_DEFORM"],
    "MASK_ARBITRARY": ["YADE_MASK_ARBITRARY"],
    "PROFILING": ["USE_TIMING_DELTAS", "ISC_TIMING"],
}
#: features that need no definition in the headers the plugin includes
FEATURES_WITHOUT_DEFINES = {"USEFUL_ERRORS", "VECTORIZE"}
CXXFLAGS = ["-std=c++17", "-O2", "-fPIC", "-shared", "-fopenmp", "-w"]


class PluginError(RuntimeError):
    """The plugin cannot be built or used here (one line says why)."""


# ------------------------------------------------------------------ the installed YADE
def _launcher_libdir():
    """The library folder the ``yade`` launcher puts on sys.path, or None."""
    exe = shutil.which("yade")
    if not exe:
        return None
    try:
        with open(exe, errors="replace") as fh:
            text = fh.read(20000)
    except OSError:
        return None
    m = re.search(r"""['"](/[^'"]*/yade[^/'"]*)/py['"]""", text)
    return m.group(1) if m else None


def find_yade(lib_dir=None):
    """The installed YADE: a dict with ``lib_dir`` (its plugin folder, e.g.
    /usr/lib/x86_64-linux-gnu/yade-double), ``lib_path`` (that folder
    relative to the prefix, less ``yade-double``), ``suffix``, ``version``,
    ``features`` (list), ``real_bits``, ``real_digits``, ``libyade``.
    Raises PluginError when there is none."""
    lib_dir = lib_dir or _launcher_libdir() or next(iter(sorted(glob.glob("/usr/lib/*/yade-double"))), None)
    if not lib_dir:
        raise PluginError("YADE is not installed (no yade launcher, no /usr/lib/*/yade-double)")
    config = os.path.join(lib_dir, "py", "yade", "config.py")
    libyade = os.path.join(lib_dir, "libyade.so")
    if not (os.path.exists(config) and os.path.exists(libyade)):
        raise PluginError(f"{lib_dir} holds no py/yade/config.py or libyade.so: not a YADE library folder")
    with open(config) as fh:
        text = fh.read()

    def value(name, pattern=r"""['"]([^'"]*)['"]"""):
        m = re.search(rf"^{name}\s*=\s*{pattern}", text, re.M)
        if not m:
            raise PluginError(f"{config}: no {name} =")
        return m.group(1)

    suffix = value("suffix")
    return {"lib_dir": lib_dir, "lib_path": value("libPATH"), "suffix": suffix, "version": value("version"),
            "features": value("features").split(), "real_bits": int(value("highPrecisionBits", r"(\d+)")),
            "real_digits": int(value("highPrecisionDecimalPlaces", r"(\d+)")), "libyade": libyade}


def defines(yade):
    """The preprocessor definitions of the installed YADE's build, from its
    features (raises PluginError on a feature this module does not know:
    its layout effects would be guessed)."""
    unknown = sorted(set(yade["features"]) - set(FEATURE_DEFINES) - FEATURES_WITHOUT_DEFINES)
    if unknown:
        raise PluginError(f"YADE {yade['version']} has features this build does not know: {' '.join(unknown)}")
    if yade["real_bits"] != 64:
        raise PluginError(f"YADE {yade['version']} computes in {yade['real_bits']}-bit reals; the kernel needs double")
    out = [d for f in sorted(set(yade["features"])) for d in FEATURE_DEFINES.get(f, [])]
    if "VECTORIZE" not in yade["features"]:
        out += ["EIGEN_DONT_VECTORIZE", "EIGEN_DONT_ALIGN", "EIGEN_DISABLE_UNALIGNED_ARRAY_ASSERT"]
    out += [f"YADE_REAL_BIT={yade['real_bits']}", f"YADE_REAL_DEC={yade['real_digits']}", "MAX_LOG_LEVEL=5",
            "YADE_ODEINT"]
    return out


def allocated_sizes(libyade, classes=CHECKED_CLASSES):
    """{class: bytes} that ``libyade`` allocates for each class: the size
    its ``yade::Create<Class>()`` factory passes to ``operator new``
    (objdump). Raises PluginError when one cannot be read."""
    try:
        syms = subprocess.run(["nm", "-D", "--defined-only", libyade], capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError) as exc:
        raise PluginError(f"cannot list the symbols of {libyade} (nm from binutils): {exc}") from None
    out = {}
    for c in classes:
        mangled = f"_ZN4yade{len('Create' + c)}Create{c}Ev"
        m = re.search(rf"^([0-9a-f]+) \w {mangled}$", syms, re.M)
        if not m:
            raise PluginError(f"{libyade} has no yade::Create{c}(): cannot check the size of {c}")
        start = int(m.group(1), 16)
        dis = subprocess.run(["objdump", "-d", "--no-show-raw-insn", f"--start-address={start}",
                              f"--stop-address={start + 48}", libyade], capture_output=True, text=True).stdout
        size = re.search(r"mov\s+\$0x([0-9a-f]+),%edi", dis)
        if not size or "_Znwm" not in dis and "operator new" not in dis:
            raise PluginError(f"cannot read sizeof({c}) off yade::Create{c}() in {libyade}")
        out[c] = int(size.group(1), 16)
    return out


def _vtables(path, dynamic):
    args = ["nm", "-C", "-S", "--defined-only"] + (["-D"] if dynamic else []) + [path]
    res = subprocess.run(args, capture_output=True, text=True)
    out = {}
    for line in res.stdout.splitlines():
        m = re.match(r"^[0-9a-f]+ ([0-9a-f]+) \w vtable for (yade::\S+)$", line)
        if m:
            out[m.group(2)] = int(m.group(1), 16)
    return out


def vtable_mismatches(plugin, lib_dir):
    """[(class, ours, YADE's)] for every ``vtable for yade::X`` that the
    plugin and one of YADE's libraries both define with different sizes
    (a virtual function more or less: YADE would call the wrong one)."""
    theirs = {}
    for lib in sorted(glob.glob(os.path.join(lib_dir, "lib*.so"))):
        theirs.update(_vtables(lib, dynamic=True))
    ours = _vtables(plugin, dynamic=False)
    return [(c, n, theirs[c]) for c, n in sorted(ours.items()) if c in theirs and theirs[c] != n]


def _include_dirs():
    """Eigen, Python and MPI headers (Debian's paths), in that order."""
    dirs = []
    for cand in ["/usr/include/eigen3"]:
        if os.path.isdir(cand):
            dirs.append(cand)
    py = sorted(glob.glob("/usr/include/python3*/Python.h"))
    if py:
        dirs.append(os.path.dirname(py[-1]))
    mpi = sorted(glob.glob("/usr/lib/*/openmpi/include/mpi.h") + glob.glob("/usr/include/*/mpich/mpi.h")
                 + glob.glob("/usr/include/mpi.h"))
    if mpi:
        dirs.append(os.path.dirname(mpi[0]))
    return dirs


def _missing_headers(yade):
    """Debian packages whose headers are missing, as a list of names."""
    need = {"/usr/include/eigen3/Eigen/Core": "libeigen3-dev",
            "/usr/include/boost/python.hpp": "libboost-python-dev",
            "/usr/include/boost/serialization/export.hpp": "libboost-serialization-dev",
            "/usr/include/boost/log/trivial.hpp": "libboost-log-dev"}
    if "CGAL" in yade["features"]:
        need["/usr/include/CGAL/Interval_nt.h"] = "libcgal-dev"
    missing = [pkg for path, pkg in need.items() if not os.path.exists(path)]
    if not glob.glob("/usr/include/python3*/Python.h"):
        missing.append("python3-dev")
    if "MPI" in yade["features"] and len(_include_dirs()) < 3:
        missing.append("libopenmpi-dev")
    return missing


# ------------------------------------------------------------------ identity of a build
def source_files(here=HERE):
    """The plugin's source and the vendored headers, sorted (of the copy of
    this package in ``here``)."""
    heads = sorted(glob.glob(os.path.join(here, "include", "**", "*.hpp"), recursive=True))
    # a run folder's copy made before the user-scene engine existed holds only the first
    # source: its hash is over what it holds, as it was computed when it was made
    sources = [os.path.join(here, os.path.basename(f)) for f in (SOURCE, USER_SOURCE, SHARED_HEADER)]
    return [f for f in sources if f == sources[0] or os.path.exists(f)] + heads


def source_hash(here=HERE):
    """Hash of the plugin's sources (12 hex digits): a run folder's copy of
    this package compares it with the loaded plugin's ``sourceHash``."""
    h = hashlib.sha1()
    for path in source_files(here):
        h.update(os.path.relpath(path, here).encode())
        with open(path, "rb") as fh:
            h.update(fh.read())
    return h.hexdigest()[:12]


def _file_hash(path):
    h = hashlib.sha1()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def build_key(yade, here=HERE):
    """Hash of the sources, the flags and the installed libyade.so."""
    h = hashlib.sha1()
    h.update(source_hash(here).encode())
    h.update(" ".join(CXXFLAGS + defines(yade)).encode())
    h.update(_file_hash(yade["libyade"]).encode())
    return h.hexdigest()[:12]


def build_dir(yade, here=HERE):
    """Where the copy of this package in ``here`` keeps its build for ``yade``."""
    return os.path.join(here, "_build", build_key(yade, here))


def prefix_libdir(prefix, yade):
    """The folder of a prefix where YADE looks for plugins."""
    return os.path.join(prefix, yade["lib_path"], "yade" + yade["suffix"])


# ------------------------------------------------------------------ build and probe
def compile_command(yade, out, sizes):
    """The g++ command line that builds the plugin into ``out``."""
    defs = defines(yade) + [f"PKE_SOURCE_HASH=\"{source_hash()}\""]
    defs += [f"PKE_SIZEOF_{c}={n}" for c, n in sorted(sizes.items())]
    return (["g++", *CXXFLAGS, *(f"-D{d}" for d in defs), f"-I{INCLUDE}", *(f"-I{d}" for d in _include_dirs()),
             "-o", out, SOURCE, USER_SOURCE, f"-L{yade['lib_dir']}", "-lyade", f"-Wl,-rpath,{yade['lib_dir']}"])


def _make_prefix(folder, yade, library):
    """``folder/prefix``: links to every entry of YADE's library folder, and
    the plugin."""
    target = prefix_libdir(os.path.join(folder, "prefix"), yade)
    os.makedirs(target)
    for name in sorted(os.listdir(yade["lib_dir"])):
        os.symlink(os.path.join(yade["lib_dir"], name), os.path.join(target, name))
    shutil.copyfile(library, os.path.join(target, LIBRARY_NAME))
    return os.path.join(folder, "prefix")


class _Transient(PluginError):
    """A failure that says nothing of the build (a probe that timed out on a
    loaded host, yade that could not start): not kept, tried again."""


def probe(prefix, timeout=300):
    """Run the probe scene in YADE with ``YADE_PREFIX=prefix``: (ok, one
    line). The probe steps a tiny polyhedra scene with the plugin and with
    the PyRunner path and compares what each read and added, bit for bit.
    Raises _Transient when YADE did not give a verdict for a reason that is
    not the build's (a timeout, yade missing)."""
    out = os.path.join(prefix, "probe.json")
    env = dict(os.environ, YADE_PREFIX=prefix, OMP_WAIT_POLICY="PASSIVE",
               PYTHONPATH=os.pathsep.join([os.path.dirname(os.path.dirname(HERE))]
                                          + [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]))
    env.pop(SKIP_VARIABLE, None)
    try:
        res = subprocess.run(noremote.command(shutil.which("yade") or "yade", ["-j1", "-n", "-x", PROBE_SCENE, out]),
                             env=env, capture_output=True, text=True, timeout=timeout, cwd=prefix)
    except subprocess.TimeoutExpired:
        raise _Transient(f"the probe scene did not finish in {timeout} s") from None
    except OSError as exc:
        raise _Transient(f"cannot start yade: {exc}") from None
    try:
        with open(out) as fh:
            result = json.load(fh)
    except (OSError, ValueError):
        tail = [ln for ln in (res.stdout + res.stderr).splitlines() if ln.strip()][-3:]
        how = f"signal {-res.returncode}" if res.returncode < 0 else f"exit {res.returncode}"
        return False, f"the probe scene stopped ({how}) before its verdict: {' | '.join(tail)[:300]}"
    return bool(result.get("ok")), str(result.get("why", ""))


def build(here=HERE, quiet=True, lib_dir=None):
    """Build and probe the plugin for the installed YADE, unless that was
    done already (``python -m yade_scripts.yadeplugin build``, which ``make
    kernel`` runs).

    The installed YADE is found (:func:`find_yade`); its build key hashes
    the sources, the flags and ``libyade.so``. A kept status for that key
    is returned as it is (a lookup). Otherwise ``g++`` builds the plugin
    (about a minute), its vtables are compared with YADE's
    (:func:`vtable_mismatches`) and the probe scene runs in YADE
    (:func:`probe`); the result is kept in ``_build/<key>/status.json``.
    Missing compilers or headers, a timeout or YADE that cannot start are
    not kept: the next call tries again.

    Parameters
    ----------
    here : str
        The copy of this package whose sources are built (default: this
        one; a run folder's ``pkg/yade_scripts/yadeplugin`` builds its own).
    quiet : bool
        False: say what it does on stderr (``yadeplugin: ...``).
    lib_dir : str, optional
        YADE's library folder (default: the one the ``yade`` launcher
        uses, else ``/usr/lib/*/yade-double``).

    Returns
    -------
    dict
        ``ok`` (bool: the plugin may be used), ``why`` (one line),
        ``prefix`` (the ``YADE_PREFIX`` of the build, or None), and, when
        the build key could be made, ``key``, ``version``, ``source_hash``. Never raises
        for a plugin that cannot be built here: ``ok`` is then False, the
        status says why and the scenes step the kernel from a PyRunner.

    Examples
    --------
    (Building takes a minute and runs YADE; a folder that is not YADE's is
    refused at once.)

    >>> import tempfile
    >>> st = build(lib_dir=tempfile.mkdtemp())
    >>> st["ok"], st["prefix"]
    (False, None)
    >>> st["why"]
    '... holds no py/yade/config.py or libyade.so: not a YADE library folder'
    """
    def say(msg):
        if not quiet:
            print(f"yadeplugin: {msg}", file=sys.stderr)

    try:
        yade = find_yade(lib_dir)
        folder = build_dir(yade, here)
    except PluginError as exc:
        return {"ok": False, "why": str(exc), "prefix": None}
    st = _read_status(folder)
    if st is not None:
        return st
    missing = _missing_headers(yade)
    if shutil.which("g++") is None:
        missing.insert(0, "g++")
    status = {"ok": False, "prefix": None, "key": os.path.basename(folder), "version": yade["version"],
              "source_hash": source_hash()}
    if missing:
        status["why"] = f"cannot build the YADE plugin: missing {', '.join(missing)} (make system installs them)"
        return status               # not kept: installing them makes the next call build
    os.makedirs(os.path.dirname(folder), exist_ok=True)
    tmp = tempfile.mkdtemp(prefix=".tmp-", dir=os.path.dirname(folder))
    try:
        sizes = allocated_sizes(yade["libyade"])
        try:
            measured = allocated_sizes(os.path.join(yade["lib_dir"], "libpkg_polyhedra.so"), MEASURED_CLASSES)
        except PluginError:             # a YADE without polyhedra: the user's engine cannot fill O.interactions
            measured = {}
        lib = os.path.join(tmp, LIBRARY_NAME)
        say(f"building {CLASS_NAME} against YADE {yade['version']} ({len(yade['features'])} features; about a minute)")
        res = subprocess.run(compile_command(yade, lib, sizes), capture_output=True, text=True)
        if res.returncode != 0:
            err = [ln for ln in res.stderr.splitlines() if "error" in ln] or res.stderr.strip().splitlines() or ["?"]
            raise PluginError(f"g++ failed: {err[0][:300]}")
        bad = vtable_mismatches(lib, yade["lib_dir"])
        if bad:
            raise PluginError("virtual tables differ from YADE's: " +
                              ", ".join(f"{c} {a} against {b} bytes" for c, a, b in bad[:4]))
        prefix = _make_prefix(tmp, yade, lib)
        ok, why = probe(prefix)
        if not ok:
            raise PluginError(f"the probe in YADE refused it: {why}")
        status.update(ok=True, why=why)
    except _Transient as exc:            # not kept: the next call tries again
        shutil.rmtree(tmp, ignore_errors=True)
        return dict(status, why=f"not checked: {exc}")
    except PluginError as exc:
        status["why"] = str(exc)
    except Exception as exc:             # noqa: BLE001 - build() never raises: the scenes fall back, with why
        shutil.rmtree(tmp, ignore_errors=True)
        return dict(status, why=f"the build stopped: {type(exc).__name__}: {exc}")
    status["sizes_checked"] = {c: n for c, n in (locals().get("sizes") or {}).items()}
    status["sizes_measured"] = dict(locals().get("measured") or {})
    with open(os.path.join(tmp, "status.json"), "w") as fh:
        json.dump(status, fh, indent=1)
    try:
        os.rename(tmp, folder)
    except OSError:                 # another process finished first: keep its build
        shutil.rmtree(tmp, ignore_errors=True)
    return _read_status(folder) or status


def _read_status(folder):
    try:
        with open(os.path.join(folder, "status.json")) as fh:
            st = json.load(fh)
    except (OSError, ValueError):
        return None
    st["prefix"] = os.path.abspath(os.path.join(folder, "prefix")) if st.get("ok") else None
    return st


def status(here=HERE, lib_dir=None):
    """The status of the plugin's build for the installed YADE and these
    sources, without building (``python -m yade_scripts.yadeplugin
    status``).

    Parameters
    ----------
    here : str
        The copy of this package whose build is looked up (default: this
        one).
    lib_dir : str, optional
        YADE's library folder (default: as :func:`build` finds it).

    Returns
    -------
    dict
        The kept status of :func:`build` (``ok``, ``why``, ``prefix`` ...;
        ``prefix`` the build's ``YADE_PREFIX`` when ``ok``), or ``ok``
        False with ``why`` when there is no YADE or no build.

    Examples
    --------
    >>> import tempfile
    >>> {"ok", "why", "prefix"} <= set(status())
    True
    >>> st = status(lib_dir=tempfile.mkdtemp())
    >>> st["ok"], st["prefix"]
    (False, None)
    """
    try:
        yade = find_yade(lib_dir)
        st = _read_status(build_dir(yade, here))
    except PluginError as exc:
        return {"ok": False, "why": str(exc), "prefix": None}
    if st is None:
        return {"ok": False, "why": "the YADE plugin is not built (make kernel builds it)", "prefix": None}
    return st


#: set to 1 to run the scenes on the PyRunner path even where the plugin is built
SKIP_VARIABLE = "POLYHEDRA_NO_PLUGIN"


def run_folder_copy(folder):
    """This package's copy in a generated run folder (``pkg/``), or None."""
    here = os.path.join(folder, "pkg", "yade_scripts", "yadeplugin")
    return here if os.path.exists(os.path.join(here, os.path.basename(SOURCE))) else None


def environment(env=None, run_folder=None):
    """The environment of a YADE process, with ``YADE_PREFIX`` on a ready
    build of the plugin (YADE loads its plugins when it starts): what the
    launchers (the pool, the SLURM script) give YADE.

    Parameters
    ----------
    env : dict, optional
        The environment to start from (default ``os.environ``); it is not
        changed.
    run_folder : str, optional
        A generated run folder: the build must then be of that folder's
        own copy of the sources (the scene checks the loaded plugin against
        it): its own build, or this package's when the sources are the
        same.

    Returns
    -------
    dict
        A copy of ``env``, with ``YADE_PREFIX`` set when there is such a
        build and :data:`SKIP_VARIABLE` (``POLYHEDRA_NO_PLUGIN``) is not
        set; else the copy as it was (the scene then steps the kernel from
        a PyRunner and says why).

    Examples
    --------
    >>> env = {"PATH": "/usr/bin", "POLYHEDRA_NO_PLUGIN": "1"}
    >>> environment(env)
    {'PATH': '/usr/bin', 'POLYHEDRA_NO_PLUGIN': '1'}
    >>> environment(env) is env
    False
    """
    env = dict(os.environ if env is None else env)
    if env.get(SKIP_VARIABLE):
        return env
    theirs = run_folder_copy(run_folder) if run_folder else None
    want = source_hash(theirs) if theirs else source_hash()
    for here in ([theirs] if theirs else []) + [HERE]:
        if source_hash(here) != want:
            continue
        st = status(here)
        if st.get("ok") and st.get("prefix"):
            env["YADE_PREFIX"] = st["prefix"]
            break
    return env


def copy_build(dest_here, here=HERE):
    """Copy the ready build of ``here`` (if any) into the package copy
    ``dest_here`` (a run folder's ``pkg/yade_scripts/yadeplugin``), so the
    folder carries its plugin; returns the status copied, or None."""
    st = status(here)
    if not st.get("ok"):
        return None
    src = os.path.dirname(st["prefix"])
    dst = os.path.join(dest_here, "_build", os.path.basename(src))
    if not os.path.exists(dst):
        shutil.copytree(src, dst, symlinks=True)
    return st


