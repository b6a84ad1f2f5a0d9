"""The shape of the code: ``postproc`` in layers that import only downward,
with no import loop (imports inside functions included), and ``postproc``
never importing yade or the scene package."""
import ast
import os

import pytest
from layering import import_loop

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

#: postproc's layers, from the bottom: a module may import its own layer or
#: lower ones, never a higher one
LAYERS = [
    ("base", {"errors", "schema", "axes", "statistics", "periodic", "provenance", "staging"}),
    ("readers", {"contactset", "tables", "lammpsdump", "synthetic", "lmgc90files"}),
    ("physics", {"stress", "strain", "fabric", "angular", "coordination", "networks", "contacttypes",
                 "contactpoints", "polygons", "commonplane", "lmgc90shape", "lmgc90count", "facetilt", "footprint",
                 "classify", "pertype", "slab", "cdpoints"}),
    ("analysis", {"columns", "analysis", "plots", "vtk", "pipeline"}),
    ("study", {"study.claims", "study.counts", "study.report", "study.front", "study.dilatancy",
               "study.branchlength", "study.sizefront", "study.results", "study.methods", "study.methodsreadme", "study.cdfront", "study.leaning", "study.sizestrain",
               "study.claim6", "study.lmgc90", "study.manifest", "study.alinvestigation",
               "study.typeskappa", "study.commonplaneref", "study.facepair",
               "study.timestepfront", "study.randomtypes", "study.shapefront"}),
    ("interface", {"many", "cli"}),
]
LEVEL = {m: k for k, (_, mods) in enumerate(LAYERS) for m in mods}


def postproc_imports():
    """{module: {postproc module it imports, at any depth of its code}};
    modules of a subpackage are named "package.module" (study.report)."""
    out = {}
    folder = os.path.join(ROOT, "postproc")
    for dirpath, _, names in os.walk(folder):
        package = os.path.relpath(dirpath, folder).replace(os.sep, ".")
        package = "" if package == "." else package + "."
        for name in sorted(names):
            if not name.endswith(".py") or name == "__init__.py":
                continue
            mod = package + name[:-3]
            tree = ast.parse(open(os.path.join(dirpath, name)).read())
            deps = set()
            for node in ast.walk(tree):
                if isinstance(node, ast.ImportFrom) and node.level >= 1:
                    # relative: from the module's package, node.level - 1 packages up
                    base = package.rstrip(".").split(".") if package else []
                    base = base[:len(base) - (node.level - 1)] if node.level > 1 else base
                    prefix = ".".join(base + ([node.module] if node.module else []))
                    if node.module:
                        deps.add(prefix)
                    else:
                        deps.update((prefix + "." if prefix else "") + a.name for a in node.names)
                elif isinstance(node, ast.ImportFrom) and node.module and node.module.startswith("postproc."):
                    deps.add(node.module[len("postproc."):])
                elif isinstance(node, ast.Import):
                    for a in node.names:
                        if a.name.split(".")[0] in ("yade", "yade_scripts"):
                            deps.add("<" + a.name.split(".")[0] + ">")
                if isinstance(node, ast.ImportFrom) and node.module and node.level == 0 \
                        and node.module.split(".")[0] in ("yade", "yade_scripts"):
                    deps.add("<" + node.module.split(".")[0] + ">")
            out[mod] = deps - {mod}
    return out


def test_every_module_has_a_layer():
    missing = sorted(set(postproc_imports()) - set(LEVEL))
    assert not missing, f"postproc modules without a layer in tests/test_layers.py: {missing}"


def test_layers_import_only_downward():
    up = [(m, d) for m, deps in postproc_imports().items() for d in deps
          if d in LEVEL and m in LEVEL and LEVEL[d] > LEVEL[m]]
    assert not up, "imports going up a layer: " + ", ".join(f"{m} -> {d}" for m, d in up)


def test_no_import_loop():
    graph = postproc_imports()
    loop = import_loop(graph)
    assert loop is None, "import loop: " + " -> ".join(loop or [])


def test_postproc_never_imports_yade_or_the_scenes():
    bad = {m: deps & {"<yade>", "<yade_scripts>"} for m, deps in postproc_imports().items()}
    assert not any(bad.values()), bad


@pytest.mark.parametrize("bad", [("stress", "study.report"), ("fabric", "fabric_loop")])
def test_the_checks_can_fail(bad, monkeypatch):
    """The checks above do catch an upward import and a loop."""
    graph = postproc_imports()
    m, d = bad
    if d == "fabric_loop":
        graph = {"a": {"b"}, "b": {"a"}}
        monkeypatch.setattr(__import__(__name__), "postproc_imports", lambda: graph)
        with pytest.raises(AssertionError, match="import loop"):
            test_no_import_loop()
    else:
        graph[m] = graph[m] | {d}
        monkeypatch.setattr(__import__(__name__), "postproc_imports", lambda: graph)
        with pytest.raises(AssertionError, match="going up"):
            test_layers_import_only_downward()
