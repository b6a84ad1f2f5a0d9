"""Load the plugin into a YADE that was started without ``YADE_PREFIX``.

YADE loads its plugins when it starts, from ``$YADE_PREFIX/lib/...``. A
script typed as ``yade script.py`` has no such prefix; :func:`engine_class`
then loads this copy's ready build itself (``ctypes``, ``RTLD_GLOBAL``: the
library's constructors register its classes with YADE's class factory) and
asks it to add its classes to ``yade.wrapper`` (``pke_register_python``).
The rules of :func:`loaded_class` hold either way: a
build of other sources, or of another YADE, is refused in one line.

Standard library only.
"""
from __future__ import annotations

import ctypes
import os

from . import (CLASS_NAME, LIBRARY_NAME, MEASURED_CLASSES, SKIP_VARIABLE, PluginError, allocated_sizes, find_yade,
               prefix_libdir, source_hash, status)

USER_CLASS = "PolyhedraContactEngine"
_loaded = {}


def load_library():
    """Load this copy's ready build into the running YADE unless YADE did;
    returns one line saying where the classes came from. Raises
    PluginError (one line) when there is no ready build for this YADE and
    these sources."""
    import yade.wrapper as wrapper

    if hasattr(wrapper, USER_CLASS):
        why = f"loaded by YADE from YADE_PREFIX={os.environ.get('YADE_PREFIX', '?')}"
        return _loaded.setdefault("why", why)
    if hasattr(wrapper, "PolyhedraKernelEngine"):
        raise PluginError(f"YADE loaded an older build of the plugin (YADE_PREFIX={os.environ.get('YADE_PREFIX')}), "
                          "without PolyhedraContactEngine: python3 -m yade_scripts.yadeplugin build")
    st = status()
    if not st.get("ok"):
        raise PluginError(f"the YADE plugin is not ready ({st.get('why')}): python3 -m yade_scripts.yadeplugin build")
    lib = os.path.join(prefix_libdir(st["prefix"], find_yade()), LIBRARY_NAME)
    handle = ctypes.PyDLL(lib, mode=ctypes.RTLD_GLOBAL)
    if handle.pke_register_python() != 0 or not hasattr(wrapper, USER_CLASS):
        raise PluginError(f"{lib} did not register its classes with yade.wrapper")
    _loaded["handle"] = handle
    return _loaded.setdefault("why", f"loaded by this script from {lib}")


def engine_class():
    """``yade.wrapper.PolyhedraContactEngine``, loading the plugin if YADE
    did not; raises PluginError (one line) for a build of other sources."""
    load_library()
    import yade.wrapper as wrapper

    cls = getattr(wrapper, USER_CLASS)
    built, ours = cls().sourceHash, source_hash()
    if built != ours:
        raise PluginError(f"the loaded plugin was built from other sources (hash {built}, this copy's {ours}): "
                          "python3 -m yade_scripts.yadeplugin build")
    return cls


def measured_sizes():
    """{class: bytes} YADE allocates for the classes whose fields the user's
    engine writes at measured offsets (``PolyhedraGeom``, ``PolyhedraPhys``):
    the build's record, else read off the installed YADE now."""
    st = status()
    got = dict(st.get("sizes_measured") or {})
    if set(MEASURED_CLASSES) <= set(got):
        return got
    if "sizes" not in _loaded:
        y = find_yade()
        _loaded["sizes"] = allocated_sizes(os.path.join(y["lib_dir"], "libpkg_polyhedra.so"), MEASURED_CLASSES)
    return _loaded["sizes"]


def loaded_class():
    """(class, why) in YADE's Python: the plugin's engine class when YADE
    loaded it and it was built from this copy's sources, else (None, why)."""
    if os.environ.get(SKIP_VARIABLE):
        return None, f"{SKIP_VARIABLE} is set"
    try:
        import yade.wrapper as wrapper
    except ImportError:
        return None, "not running in YADE"
    cls = getattr(wrapper, CLASS_NAME, None)
    prefix = os.environ.get("YADE_PREFIX")
    where = f"loaded by YADE from YADE_PREFIX={prefix}"
    if cls is None:                 # YADE did not load it: this copy's ready build, loaded here
        try:
            where = load_library()
        except (PluginError, OSError) as exc:
            if not prefix:
                return None, ("YADE was started without YADE_PREFIX and this copy's plugin could not be loaded "
                              f"({exc}; the study, batch and SLURM launchers set it; by hand: "
                              "YADE_PREFIX=$(python3 -m yade_scripts.yadeplugin prefix) yade ...)")
            return None, f"YADE_PREFIX={prefix} holds no {CLASS_NAME} ({exc})"
        cls = getattr(wrapper, CLASS_NAME, None)
        if cls is None:
            return None, f"the plugin loaded ({where}) but yade.wrapper has no {CLASS_NAME}"
    built, ours = cls().sourceHash, source_hash()
    if built != ours:
        return None, f"the loaded plugin was built from other sources (hash {built}, this copy's {ours})"
    return cls, where
