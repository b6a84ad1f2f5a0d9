"""The shape of ``yade_scripts``: its rooms in layers that import only
downward, with no import loop (imports inside functions and under ``if``
included, and the package ``__init__`` every dotted import runs), and no
import of our own modules hidden inside a function.

From the bottom: ``runs/`` (one run's lock, state, checkpoints and attempt,
the host, YADE without its servers), the YADE plugin's builder and loader
(``yadeplugin/__init__``, ``yadeplugin/load.py``), ``scene/`` (the scene
``triaxial.py`` and its parts), the plugin's probe (``yadeplugin/scene.py``,
a small scene of its own, and the script that runs it) and the engine for a
user's own scene (``yadeplugin/contacts.py``, which writes YADE's
interactions as the scene's dump writer reads them), ``launch/`` (the pool, the table's batch,
SLURM) and ``campaign/`` (presets, run folders, the study, its archive, the
sweeps). Every room sits in one layer but ``yadeplugin/``, whose loader is
below the scene (the kernel's engine asks it for the plugin's class) and
whose probe box is above it (it steps the scene's kernel on both paths).
Read with ``ast``, without importing: the scene's modules import YADE."""
import ast
import os

import pytest
from layering import import_loop

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FOLDER = os.path.join(ROOT, "yade_scripts")

#: the layers, from the bottom: a module may import its own layer or lower
#: ones, never a higher one (modules named from yade_scripts: "runs.attempt";
#: a package by its own name: "runs" is runs/__init__.py)
LAYERS = [
    ("runs", {"runs", "runs.runlock", "runs.checkpoint", "runs.host", "runs.noremote", "runs.runstate",
              "runs.attempt"}),
    ("plugin", {"yadeplugin", "yadeplugin.__main__", "yadeplugin.load"}),
    ("scene", {"scene", "scene.parameters", "scene.servo", "scene.loading", "scene.timestep", "scene.sample",
               "scene.grains", "scene.tangential", "scene.yadedump", "scene.kernel_contacts", "scene.controller",
               "scene.triaxial"}),
    ("probe", {"yadeplugin.scene", "yadeplugin.probe_scene", "yadeplugin.contacts"}),
    ("launch", {"launch", "launch.batch", "launch.pool", "launch.resources", "launch.slurm", "launch.task"}),
    ("campaign", {"campaign", "campaign.presets", "campaign.generate", "campaign.runfolders",
                  "campaign.archive_store", "campaign.archive_commit", "campaign.study", "campaign.archive",
                  "campaign.sweeps", "campaign.timestep_sweep", "campaign.facepair_sweep",
                  "campaign.timestep_draws"}),
]
LEVEL = {m: k for k, (_, mods) in enumerate(LAYERS) for m in mods}


def module_files():
    """{module: path} of every Python file of yade_scripts (the root's
    ``__init__`` left out: it must import nothing, see below)."""
    out = {}
    for dirpath, dirnames, names in os.walk(FOLDER):
        dirnames[:] = [d for d in dirnames if d not in ("_build", "include", "__pycache__")]
        package = os.path.relpath(dirpath, FOLDER).replace(os.sep, ".")
        package = "" if package == "." else package
        for name in sorted(names):
            if not name.endswith(".py"):
                continue
            if name == "__init__.py":
                mod = package
            else:
                mod = (package + "." if package else "") + name[:-3]
            out[mod] = os.path.join(dirpath, name)
    return out


def _imports(path, mod, modules):
    """[(imported module, inside a function?)] of the file ``path`` of module
    ``mod`` (our modules only; ``from P import m`` counts as module P.m when
    there is one, else P; a dotted module brings its packages too)."""
    tree = ast.parse(open(path).read())
    is_package = os.path.basename(path) == "__init__.py"
    here = mod.split(".") if mod else []
    package = here if is_package else here[:-1]
    found = []

    def add(name, nested):
        parts = name.split(".") if name else []
        for k in range(1, len(parts) + 1):          # the packages a dotted import runs
            found.append((".".join(parts[:k]), nested))

    def visit(node, nested):
        for child in ast.iter_child_nodes(node):
            inner = nested or isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda))
            if isinstance(child, ast.ImportFrom):
                if child.level:
                    base = package[:len(package) - (child.level - 1)] if child.level > 1 else package
                    target = ".".join(base + (child.module.split(".") if child.module else []))
                elif child.module == "yade_scripts" or (child.module or "").startswith("yade_scripts."):
                    target = child.module[len("yade_scripts."):] if "." in child.module else ""
                else:
                    target = None
                if target is not None:
                    for a in child.names:
                        sub = (target + "." if target else "") + a.name
                        add(sub if sub in modules else target, inner)
            elif isinstance(child, ast.Import):
                for a in child.names:
                    if a.name.startswith("yade_scripts."):
                        add(a.name[len("yade_scripts."):], inner)
            visit(child, inner)

    visit(tree, False)
    return [(d, nested) for d, nested in found if d != mod and d in modules]


def yade_imports():
    """{module: {our module it imports, at any depth of its code}}."""
    files = module_files()
    return {m: {d for d, _ in _imports(p, m, files)} for m, p in files.items() if m}


def hidden_imports():
    """[(module, our module it imports inside a function)]."""
    files = module_files()
    return sorted({(m, d) for m, p in files.items() if m for d, nested in _imports(p, m, files) if nested})


def test_every_module_has_a_layer():
    missing = sorted(set(yade_imports()) - set(LEVEL))
    assert not missing, f"yade_scripts modules without a layer in tests/test_yade_layers.py: {missing}"
    gone = sorted(set(LEVEL) - set(yade_imports()))
    assert not gone, f"layers name modules that do not exist: {gone}"


def test_the_package_root_imports_nothing():
    """``import yade_scripts.X`` runs yade_scripts/__init__.py first: it
    must not pull in any room."""
    files = module_files()
    assert _imports(files[""], "", files) == []


def test_layers_import_only_downward():
    up = [(m, d) for m, deps in yade_imports().items() for d in deps
          if d in LEVEL and m in LEVEL and LEVEL[d] > LEVEL[m]]
    assert not up, "imports going up a layer: " + ", ".join(f"{m} -> {d}" for m, d in sorted(up))


def test_no_import_loop():
    graph = yade_imports()
    loop = import_loop(graph)
    assert loop is None, "import loop: " + " -> ".join(loop or [])


def test_no_import_of_our_own_hidden_in_a_function():
    """An import of our own modules inside a function hides a loop from
    whoever reads the module's head: every one is at the top."""
    hidden = hidden_imports()
    assert not hidden, "imports inside functions: " + ", ".join(f"{m} -> {d}" for m, d in hidden)


def test_the_reader_sees_every_form_of_import(tmp_path):
    """Relative (``.``, ``..``, ``from .. import m``), absolute, inside a
    function and under ``if``: each is found, with its packages."""
    src = tmp_path / "mod.py"
    src.write_text("from ..runs import checkpoint\nfrom .. import yadeplugin\nfrom .servo import x\n"
                   "import yade_scripts.launch.pool\nif True:\n    from yade_scripts.scene import loading\n"
                   "def f():\n    from yade_scripts.campaign.study import main\n")
    files = {m: None for m in ("runs", "runs.checkpoint", "yadeplugin", "scene", "scene.servo", "scene.loading",
                               "launch", "launch.pool", "campaign", "campaign.study", "scene.mod")}
    got = _imports(str(src), "scene.mod", files)
    assert set(got) == {("runs", False), ("runs.checkpoint", False), ("yadeplugin", False), ("scene", False),
                        ("scene.servo", False), ("launch", False), ("launch.pool", False), ("scene.loading", False),
                        ("campaign", True), ("campaign.study", True)}


@pytest.mark.parametrize("bad", ["upward", "loop", "hidden"])
def test_the_checks_can_fail(bad, monkeypatch):
    """The checks above do catch an upward import, a loop and a hidden import."""
    mod = __import__(__name__)
    if bad == "loop":
        monkeypatch.setattr(mod, "yade_imports", lambda: {"a": {"b"}, "b": {"a"}})
        with pytest.raises(AssertionError, match="import loop"):
            test_no_import_loop()
    elif bad == "upward":
        graph = yade_imports()
        graph["runs.runstate"] = graph["runs.runstate"] | {"campaign.study"}
        monkeypatch.setattr(mod, "yade_imports", lambda: graph)
        with pytest.raises(AssertionError, match="going up"):
            test_layers_import_only_downward()
    else:
        monkeypatch.setattr(mod, "hidden_imports", lambda: [("launch.slurm", "launch.task")])
        with pytest.raises(AssertionError, match="inside functions"):
            test_no_import_of_our_own_hidden_in_a_function()


# ------------------------------------------------------------------ the lmgc90 package
#: lmgc90 sits above postproc, shapes and yade_scripts: it uses them, they never
#: import it. Its scene and its parts take from yade_scripts only one run's
#: machinery and the scene's draws (runs, scene); the CD study driver alone
#: (lmgc90.study) runs its runs through the launchers and the study's
#: analyses, manifest and archive (launch, campaign)
LMGC90_LAUNCHERS = {"lmgc90.study"}


def package_imports(package):
    """{module of ``package``: {dotted module it imports, absolute (relative
    imports resolved), at any depth}} (vendor/ and _build/ left out)."""
    folder = os.path.join(ROOT, package)
    out = {}
    for dirpath, dirnames, names in os.walk(folder):
        dirnames[:] = [d for d in dirnames if d not in ("_build", "vendor", "include", "__pycache__")]
        pkg = [package] + [p for p in os.path.relpath(dirpath, folder).split(os.sep) if p != "."]
        for name in sorted(names):
            if not name.endswith(".py"):
                continue
            mod = ".".join(pkg + ([] if name == "__init__.py" else [name[:-3]]))
            deps = set()
            for node in ast.walk(ast.parse(open(os.path.join(dirpath, name)).read())):
                if isinstance(node, ast.ImportFrom):
                    base = pkg[:len(pkg) - (node.level - 1)] if node.level > 1 else pkg
                    deps.add(".".join((base if node.level else []) + ([node.module] if node.module else [])))
                elif isinstance(node, ast.Import):
                    deps.update(a.name for a in node.names)
            out[mod] = deps
    return out


def test_nothing_below_lmgc90_imports_it():
    up = [(m, d) for p in ("postproc", "shapes", "yade_scripts") for m, deps in package_imports(p).items()
          for d in deps if d == "lmgc90" or d.startswith("lmgc90.")]
    assert not up, "imports of the lmgc90 package from below it: " + ", ".join(f"{m} -> {d}" for m, d in up)


def test_only_the_cd_study_uses_the_launchers():
    graph = package_imports("lmgc90")
    assert LMGC90_LAUNCHERS <= set(graph), "lmgc90 modules named in LMGC90_LAUNCHERS that do not exist"
    wide = [(m, d) for m, deps in graph.items() if m not in LMGC90_LAUNCHERS for d in deps
            if d.split(".")[:2] in (["yade_scripts", "launch"], ["yade_scripts", "campaign"])]
    assert not wide, "lmgc90 modules using the launchers or the campaign: " + ", ".join(f"{m} -> {d}"
                                                                                        for m, d in wide)


def test_the_lmgc90_checks_can_fail(monkeypatch, tmp_path):
    """An import of lmgc90 from below and a launcher used by the scene are caught."""
    mod = __import__(__name__)
    real = package_imports
    monkeypatch.setattr(mod, "package_imports", lambda p: {**real(p), **(
        {"postproc.x": {"lmgc90.study"}} if p == "postproc" else
        {"lmgc90.triaxial": {"yade_scripts.launch.pool"}} if p == "lmgc90" else {})})
    with pytest.raises(AssertionError, match="from below"):
        test_nothing_below_lmgc90_imports_it()
    with pytest.raises(AssertionError, match="using the launchers"):
        test_only_the_cd_study_uses_the_launchers()
