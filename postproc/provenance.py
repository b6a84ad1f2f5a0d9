"""What an analysis was made from, so that a study reruns only what changed.

:func:`postproc.pipeline.analyze_path` writes ``OUT/source.json`` beside
``summary.csv``: the input's files (name, size in bytes, modification time
in ns), the analysis options, and a hash of the analysis code (every
source file of the ``postproc`` and ``shapes`` packages, comments and
docstrings left out; the options' ``figures`` only when False). An analysis is
current (:func:`is_current`) when all three are what they would be now (but
that one with figures is current for a request without them), so
a rerun of the study (``make study``, ``yade_scripts.study --collect``)
keeps it instead of analysing a 5000-grain dump again (minutes per dump),
and redoes it when the dump, the options or the code changed. A folder
without ``source.json`` (made before it existed) is never current.
"""
from __future__ import annotations

import ast
import dataclasses
import hashlib
import importlib.util
import json
import os
from functools import lru_cache

#: the file beside summary.csv
SOURCE_FILE = "source.json"
#: the packages whose code makes an analysis (the classifiers import shapes)
PACKAGES = ("postproc", "shapes")
#: the code's files that count
CODE_SUFFIXES = (".py", ".c", ".h")


@lru_cache(maxsize=1)
def code_hash():
    """SHA-256 (hex) of the source files of :data:`PACKAGES` (in sorted
    path order, with their paths relative to the package's parent; of each
    Python file its syntax tree without docstrings, of each C file its
    bytes): any edit to the code changes it, an edit to a comment or a
    docstring does not."""
    h = hashlib.sha256()
    for pkg in PACKAGES:
        root = os.path.abspath(list(importlib.util.find_spec(pkg).submodule_search_locations)[0])
        base = os.path.dirname(root)
        files = []
        for folder, dirs, names in os.walk(root):
            dirs[:] = sorted(d for d in dirs if not d.startswith((".", "_build", "__pycache__")))
            files += [os.path.join(folder, n) for n in names if n.endswith(CODE_SUFFIXES)]
        for path in sorted(files):
            h.update(os.path.relpath(path, base).encode())
            with open(path, "rb") as fh:
                h.update(hashlib.sha256(_code_of(path, fh.read())).digest())
    return h.hexdigest()


def _code_of(path, data):
    """What of a source file makes results: for Python its syntax tree
    without docstrings (comments, docstrings and layout do not count), for
    C the bytes."""
    if not path.endswith(".py"):
        return data
    try:
        tree = ast.parse(data)
    except (SyntaxError, ValueError):
        return data
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if (isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) and body
                and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant)
                and isinstance(body[0].value.value, str)):
            node.body = body[1:] or [ast.Pass()]
    return ast.dump(tree).encode()


def input_files(path):
    """[[name, size (bytes), mtime (ns)]] of the input ``path`` and, for a
    dump still in parts, of every file of its ``PATH.parts`` folder."""
    out = []
    for p in [path] + ([os.path.join(path + ".parts", n) for n in sorted(os.listdir(path + ".parts"))]
                       if os.path.isdir(path + ".parts") else []):
        st = os.stat(p)
        out.append([os.path.basename(p), st.st_size, st.st_mtime_ns])
    return out


def _options(options):
    d = dataclasses.asdict(options)
    if d.get("figures", True):       # recorded only when off: a default record is what it was before the option
        d.pop("figures", None)
    return json.loads(json.dumps(d, default=list))       # tuples -> lists, as they read back


def stamp(path, options):
    """{"input", "options", "code"}: what an analysis of ``path`` with
    :class:`postproc.pipeline.AnalysisOptions` ``options`` is made from
    (JSON-ready). Raises OSError when ``path`` cannot be read."""
    files = input_files(path) + (input_files(options.atoms) if getattr(options, "atoms", None) else [])
    return {"input": files, "options": _options(options), "code": code_hash()}


def is_current(path, out, options):
    """True when ``out`` holds an analysis (summary.csv) of ``path`` made with
    ``options`` by today's code from today's input files (its source.json
    equals :func:`stamp`, but that an analysis with figures is current for
    one asked without them); False otherwise, also when anything is missing
    or unreadable."""
    try:
        if not os.path.exists(os.path.join(out, "summary.csv")):
            return False
        with open(os.path.join(out, SOURCE_FILE)) as fh:
            old = json.load(fh)
        now = stamp(path, options)
        was = dict(old.get("options") or {})
        drew = was.pop("figures", True) is True     # recorded only when False
        want = now["options"].pop("figures", True) is True
        return ({"input": old.get("input"), "options": was, "code": old.get("code")} == now
                and (drew or not want))
    except (OSError, ValueError, AttributeError, TypeError):
        return False
