"""The API reference page (docs/api.md), generated from the packages.

Every module of ``postproc``, ``shapes`` and ``yade_scripts`` found on disk
(each package's ``__init__`` included, as the package) gets its
``automodule`` section, in the order of the files, except the YADE scripts
of :data:`SCRIPTS`, which only YADE can import and which are named with a
link to their page instead. ``make docs`` (docs/conf.py) rewrites api.md
before every build, and ``tests/test_docs.py`` checks that the committed
page is the generated one and that the built page has a section for every
module, so a new module cannot be left out.

    python docs/apigen.py      # rewrite docs/api.md
"""
from __future__ import annotations

import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PAGE = os.path.join(ROOT, "docs", "api.md")
#: (package, heading) in the order of the page
PACKAGES = (("postproc", "The analysis library (`postproc`)"),
            ("shapes", "The polyhedra and the contact kernel (`shapes`)"),
            ("yade_scripts", "The scene and the runs (`yade_scripts`)"))
#: modules that are YADE scripts, not importable outside YADE: {name: where they are documented}
SCRIPTS = {"yade_scripts.scene.triaxial": "[the scenes](scenes.md)",
           "yade_scripts.yadeplugin.probe_scene": "[the compiled kernel](kernel.md)"}


def modules(root=ROOT):
    """[(package, [dotted module names])] of every Python file of the three
    packages and their subpackages (a package's ``__init__.py`` as the
    package itself), sorted by name; folders without ``__init__.py``
    (build folders) are not packages and are skipped."""
    out = []
    for package, _ in PACKAGES:
        names = []
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, package)):
            dirnames[:] = sorted(d for d in dirnames if os.path.exists(os.path.join(dirpath, d, "__init__.py")))
            if "__init__.py" not in filenames:
                continue
            dotted = os.path.relpath(dirpath, root).replace(os.sep, ".")
            for f in sorted(filenames):
                if f.endswith(".py"):
                    names.append(dotted if f == "__init__.py" else f"{dotted}.{f[:-3]}")
        out.append((package, sorted(names)))
    return out


def render(mods=None):
    """The text of docs/api.md for ``mods`` (default: :func:`modules`)."""
    mods = modules() if mods is None else mods
    lines = ["# API reference", "",
             "Generated from the packages by `docs/apigen.py` (`make docs` rewrites this page; do not edit "
             "it by hand): every module of `postproc`, `shapes` and `yade_scripts`, its docstring and those "
             "of its public functions and classes.", ""]
    for (package, names), (_, heading) in zip(mods, PACKAGES):
        lines += [f"## {heading}", ""]
        scripts = [n for n in names if n in SCRIPTS]
        for n in scripts:
            lines += [f"`{n}` is a YADE script, not a module: it is documented in {SCRIPTS[n]}.", ""]
        for n in names:
            if n not in SCRIPTS:
                lines += ["```{eval-rst}", f".. automodule:: {n}", "```", ""]
    return "\n".join(lines).rstrip("\n") + "\n"


def write(path=PAGE):
    """Rewrite ``path`` when its text differs from :func:`render`; True when
    it changed."""
    text = render()
    if os.path.exists(path):
        with open(path) as fh:
            if fh.read() == text:
                return False
    with open(path, "w") as fh:
        fh.write(text)
    return True


if __name__ == "__main__":
    print(f"{PAGE}: {'rewritten' if write() else 'unchanged'}", file=sys.stderr)
