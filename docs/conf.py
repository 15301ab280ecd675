"""Sphinx configuration: the Markdown docs (MyST) and an API reference from the docstrings.

Build with ``make docs`` (warnings are errors); the HTML lands in ``build/docs/html``.
"""

from __future__ import annotations

import importlib.util

import stickslip

project = "stickslip"
author = "stickslip developers"
copyright = "stickslip developers (BSD 3-Clause)"
release = version = stickslip.__version__

extensions = ["myst_parser", "sphinx.ext.autodoc", "sphinx.ext.napoleon", "sphinx.ext.mathjax"]
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "Thumbs.db", ".DS_Store"]

# Docstrings are numpy style; `name` in a docstring links to the object when it resolves
# and is set as code otherwise (no warning: the build is not nitpicky).
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_rtype = False
default_role = "py:obj"
autodoc_default_options = {"show-inheritance": True, "member-order": "bysource"}
autodoc_typehints = "description"
autodoc_typehints_format = "short"
autodoc_preserve_defaults = True
add_module_names = False
python_use_unqualified_type_names = True

# MyST: headings get anchors, so the Markdown docs can link to sections
myst_heading_anchors = 3

html_theme = "furo" if importlib.util.find_spec("furo") else "alabaster"
html_title = f"stickslip {release}"
html_static_path: list[str] = []
