"""What an analysis was made from, so that a study reruns only what changed.

:func:`postproc.pipeline.analyze_path` writes ``OUT/source.json`` beside
``summary.csv``: the input's files (name, size in bytes, modification time
in ns), the analysis options, the analysis version
(:data:`ANALYSIS_VERSION`) and, as provenance only, a hash of the analysis
code (every source file of the ``postproc`` and ``shapes`` packages,
comments and docstrings left out; the options' ``figures`` only when
False). An analysis is current (:func:`is_current`) when its input, options
and analysis version are what they would be now (but that one with figures
is current for a request without them), so
a rerun of the study (``make study``, ``yade_scripts.campaign.study --collect``)
keeps it instead of analysing a 5000-grain dump again (minutes per dump),
and redoes it when the dump, the options or the analysis version changed.
A folder without ``source.json`` (made before it existed) is never current.

The version, not the code hash, says whether old numbers are today's
numbers: the code hash changes with any edit (an input check, a message),
the version only when an output number changes. A record written before
the version existed carries only its code hash; :func:`version_of` reads it
through :data:`HISTORICAL_CODE_VERSIONS`, and a code hash not in that table
has no version (never current, never used from an archive).
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

#: The analysis version: an integer that must be incremented by every change
#: to ``postproc/`` or ``shapes/`` that moves any number an analysis writes
#: (summary.csv, the other tables, the JSON records), and only then.
#: tests/test_analysis_golden.py holds a digest of every output number of
#: committed fixture dumps under this version and fails when the numbers
#: change and the version did not. After a bump, analyses and archived runs
#: of the earlier version are no longer used: re-collect (or rerun) the
#: committed results, or read an old archive with the code that made it
#: (``python -m yade_scripts.campaign.archive collect-at-commit``).
ANALYSIS_VERSION = 1

#: code hashes (:func:`code_hash`) of analyses written before records named
#: their version -> the version their numbers are (the commit whose tree has
#: that hash). Each was checked by running tests/golden/analysis_digest.py
#: against that commit's postproc/ and shapes/: the same digest as version
#: 1's. c237acd4... made the committed archive reference_data/claim6-5000.
#: Add no hash whose digest was not checked so.
HISTORICAL_CODE_VERSIONS = {
    "c237acd4bb6279825166a98265fa3598662f8f292f25a36eade50abedecce914": 1,     # c4d1cf9
    "a10f2ba8bbe13ac43f31683ec10ecb358a0922f83307318af94aa03da21a7e5e": 1,     # cc57b28
    "febbb1ced82ca2df6e789a9e94d929e9338104719c146700e129c60306693706": 1,     # 1132f6d
    "926a4c8195ad08ee3ac64706126c9784460ae6070494f55492d96f85b2df2fe6": 1,     # 2169b80
    "b96755e1f368e95bd01432ca756ca967385242c3586ca351940d9c01f0237e65": 1,     # 0a1156b
    "0d55a8760ad58aa5ce3847912d508cbb7b7bab72e9160851f1bf6b7483148b9f": 1,     # 28e969a
    "52bb03e9f6a91d5431d379619195490815d1b2d3592954409aedfb2eec3c730e": 1,     # 23dd53c
    "3610b0e60342b7d05b02916bedf9a49b27d6f602c89461312b567964223d1970": 1,     # d1f831b
    "278922f1e1bf437065b19de0d9f66d10dbc9d41c43d3db244d95590428d63e32": 1,     # 0c821d5
    "d0e1fc60c4ffee38677bbc3696ea5566098683712d29c0279b73690e4e6c3d81": 1,     # 2219f6f
    "cde2326896d91f1174971ce787e58f237371b63690e18fb1b3aab116f69daeb7": 1,     # 642d54a
    "88d27a767b0759723b177fd2e35fd94e51fe93b612830f529d67f090510ea0ae": 1,     # bca27a8
    "22bcb40d32816b368ed4d78b3a197e9f54c8fbaa0990ead582124037e4072773": 1,     # 2435ccb
    "da46e0dbad97fb9d87207665d3474aeb4d85a682efc8844c0f2a6215d2ec42a1": 1,     # 675ade0
    "67713b7a7c8377df95d6fd6ba2be49e15d275e9fe3519f1d2ac52437c0e5b91f": 1,     # 4d32836
    "610a327dd34eaaf1ee730357dea20177820285db947b9c51028697a7ab39a643": 1,     # 179f5cf
}


def version_of(record):
    """The analysis version of a provenance record (a source.json or an
    archive's run record, a dict): its ``"version"`` when it names one,
    else the version :data:`HISTORICAL_CODE_VERSIONS` gives its ``"code"``,
    else None (unknown: never taken for today's numbers).

    >>> version_of({"version": 3, "code": "x"})
    3
    >>> version_of({"code": "c237acd4bb6279825166a98265fa3598662f8f292f25a36eade50abedecce914"})
    1
    >>> version_of({"code": "0" * 64}) is None
    True
    """
    if not isinstance(record, dict):
        return None
    v = record.get("version")
    if isinstance(v, int) and not isinstance(v, bool):
        return v
    if v is not None:
        return None
    code = record.get("code")
    return HISTORICAL_CODE_VERSIONS.get(code) if isinstance(code, str) else None


def is_today(record):
    """True when the provenance record ``record`` (a dict) has today's
    analysis version (:func:`version_of` == :data:`ANALYSIS_VERSION`)."""
    return version_of(record) == ANALYSIS_VERSION


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
    """{"input", "options", "version", "code"}: what an analysis of ``path``
    with :class:`postproc.pipeline.AnalysisOptions` ``options`` is made from
    (JSON-ready; "code" is provenance, not compared). Raises OSError when
    ``path`` cannot be read."""
    files = input_files(path) + (input_files(options.atoms) if getattr(options, "atoms", None) else [])
    return {"input": files, "options": _options(options), "version": ANALYSIS_VERSION, "code": code_hash()}


def is_current(path, out, options):
    """True when ``out`` holds an analysis (summary.csv) of ``path`` made with
    ``options`` under today's analysis version (:func:`is_today`) from
    today's input files (its source.json's input and options equal
    :func:`stamp`'s, but that an analysis with figures is current for one
    asked without them); False otherwise, also when anything is missing or
    unreadable. The code hash is not compared."""
    try:
        if not os.path.exists(os.path.join(out, "summary.csv")):
            return False
        with open(os.path.join(out, SOURCE_FILE)) as fh:
            old = json.load(fh)
        now = stamp(path, options)
        was = dict(old.get("options") or {})
        drew = was.pop("figures", True) is True     # recorded only when False
        want = now["options"].pop("figures", True) is True
        return ({"input": old.get("input"), "options": was} == {"input": now["input"], "options": now["options"]}
                and is_today(old) and (drew or not want))
    except (OSError, ValueError, AttributeError, TypeError):
        return False
