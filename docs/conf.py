"""Sphinx configuration: the Markdown pages of docs/ (MyST) and the API
reference from the docstrings (autodoc, NumPy style through napoleon).
Built by ``make docs`` into runs/docs/html; tests/test_docs.py builds it with
warnings as errors."""
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, ROOT)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import apigen  # noqa: E402  (docs/apigen.py: the API page from the packages)

# the API page lists every module of the packages: regenerated before each build
apigen.write()

project = "Grain shape and the strength of ballast"
extensions = ["myst_parser", "sphinx.ext.autodoc", "sphinx.ext.napoleon"]
source_suffix = {".md": "markdown"}
master_doc = "index"
exclude_patterns = ["_build"]
myst_heading_anchors = 3
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "undoc-members": False}
napoleon_numpy_docstring = True
napoleon_google_docstring = False
napoleon_use_ivar = True
html_theme = "alabaster"


def plain_text_docstrings(app, what, name, obj, options, lines):
    """The docstrings are written as plain text for ``help()``: |x| is an
    absolute value, not a substitution, and module docstrings lay out their
    tables with aligned columns. So pipes are escaped everywhere, and a
    module's docstring is shown as it is written (a literal block)."""
    lines[:] = [line.replace("|", r"\|") for line in lines]
    if what == "module" and lines:
        body = ["    " + line if line.strip() else "" for line in lines]
        lines[:] = ["::", ""] + body + [""]


def setup(app):
    app.connect("autodoc-process-docstring", plain_text_docstrings)
# numpydoc types name array shapes by their parameters, e.g. "(n, 3) float":
# napoleon turns each word of a type into a cross-reference, and a word such as
# n or vertices is also an attribute of several classes; such an ambiguous
# reference renders as plain text, so its warning ("more than one target
# found") is not an error here
suppress_warnings = ["ref.python"]
