"""Every name of our code that README.md and docs/*.md quote in backticks
(``postproc.stress.stress_tensor``, ``yade_scripts/launch/pool.py``,
``yade_scripts.launch.pool.yade_env``, ``shapes/overlap.py``) exists: the module's
file, and each attribute after it as a top-level definition of that module
(or a method of its class). Read with ``ast``, without importing: the YADE
scripts are checked too."""
import ast
import functools
import os
import re

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PACKAGES = ("postproc", "shapes", "yade_scripts")
#: a backticked name of ours: dotted (package.module.attr) or a path (package/module.py, package/module.attr)
NAME = re.compile(r"`((?:%s)(?:[./][A-Za-z_][A-Za-z0-9_]*)+(?:\.py)?)(?:\(\))?`" % "|".join(PACKAGES))


def pages():
    yield os.path.join(ROOT, "README.md")
    docs = os.path.join(ROOT, "docs")
    for name in sorted(os.listdir(docs)):
        if name.endswith(".md") and name != "api.md":
            yield os.path.join(docs, name)


def quoted():
    """[(page, name)] of every backticked name of our packages."""
    out = []
    for page in pages():
        with open(page) as fh:
            text = fh.read()
        out += [(os.path.relpath(page, ROOT), m.group(1)) for m in NAME.finditer(text)]
    return out


@functools.lru_cache(maxsize=None)
def definitions(path):
    """{name: ast node} of a module's top-level definitions (and imports)."""
    with open(path) as fh:
        tree = ast.parse(fh.read())
    names = {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names[node.name] = node
        elif isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            for t in targets:
                for n in ast.walk(t):
                    if isinstance(n, ast.Name):
                        names[n.id] = node
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            for a in node.names:
                names[(a.asname or a.name).split(".")[0]] = node
    return names


def resolve(name):
    """None when ``name`` exists, else why not (one line)."""
    if "/" in name and os.path.isfile(os.path.join(ROOT, name)):       # a file: .py, .c, .cpp ...
        return None
    if name.endswith(".py"):
        return f"no file {name}"
    parts = re.split(r"[./]", name)
    for k in range(len(parts), 0, -1):          # the longest prefix that is a module or a package
        base = os.path.join(ROOT, *parts[:k])
        path = base + ".py" if os.path.isfile(base + ".py") else os.path.join(base, "__init__.py")
        if os.path.isfile(path):
            rest = parts[k:]
            break
    else:
        return f"no module {parts[0]}"
    if not rest:
        return None
    node = definitions(path).get(rest[0])
    if node is None:
        if os.path.isdir(os.path.join(base, rest[0])) or os.path.isfile(os.path.join(base, rest[0] + ".py")):
            return None
        return f"{os.path.relpath(path, ROOT)} defines no {rest[0]}"
    if len(rest) > 1 and isinstance(node, ast.ClassDef):
        members = {n.name for n in node.body if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef))}
        members |= {t.id for n in node.body if isinstance(n, (ast.Assign, ast.AnnAssign))
                    for t in ([n.target] if isinstance(n, ast.AnnAssign) else n.targets) if isinstance(t, ast.Name)}
        if rest[1] not in members:
            return f"class {rest[0]} of {os.path.relpath(path, ROOT)} has no {rest[1]}"
    return None


def test_the_pattern_finds_what_the_docs_quote():
    names = {n for _, n in quoted()}
    assert len(names) > 30
    assert resolve("yade_scripts.launch.pool.yade_env") is None and resolve("yade_scripts/launch/pool.py") is None
    assert resolve("yade_scripts/launch/batch.yade_env") == "yade_scripts/launch/batch.py defines no yade_env"
    assert resolve("postproc.nosuchmodule") is not None


@pytest.mark.parametrize("page,name", sorted(set(quoted())))
def test_every_quoted_name_exists(page, name):
    why = resolve(name)
    assert why is None, f"{page}: `{name}`: {why}"
