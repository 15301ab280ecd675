"""Sphinx configuration: the Markdown docs (MyST), the notebooks executed (myst-nb), a gallery
of pictures built from scripts (sphinx-gallery), the command-line reference and an API reference
from the docstrings.

Build with ``make docs`` (warnings are errors); the HTML lands in ``build/docs/html``.
"""

from __future__ import annotations

import importlib.util
import os
import shutil
import sys
from pathlib import Path

import stickslip

DOCS = Path(__file__).resolve().parent
sys.path.insert(0, str(DOCS))  # the gallery's image scraper and the inventories' writer

import field_docs  # noqa: E402
from gallery_support import FigureScraper  # noqa: E402
from inventories import write_inventories  # noqa: E402

project = "stickslip"
author = "stickslip developers"
copyright = "stickslip developers (BSD 3-Clause)"
release = version = stickslip.__version__

# math rendered offline: MathJax from the sphinx-mathjax-offline package, copied into _static (the
# default loads it from a CDN, and a page read without a network showed raw TeX)
extensions = ["myst_nb", "sphinx.ext.autodoc", "sphinx.ext.napoleon", "sphinx.ext.mathjax",
              "sphinx-mathjax-offline", "sphinx.ext.intersphinx", "sphinx_gallery.gen_gallery"]
# no typographic dashes and quotes: "--law" outside a code span became "–law" (79 times in the CLI
# reference, the parameters and the theory), which fails when pasted into a shell
smartquotes = False
root_doc = "index"
# the gallery writes a notebook beside each script, for download: not pages of their own
exclude_patterns = ["_build", "Thumbs.db", ".DS_Store", "auto_gallery/**/*.ipynb", "gallery/**"]

# The notebooks of notebooks/ are rendered with their outputs: copied here, executed at each
# build (cached in the build folder), in a temporary folder, an error failing the build.
NOTEBOOKS = DOCS / "nb"
NOTEBOOKS.mkdir(exist_ok=True)
for _nb in sorted((DOCS.parent / "notebooks").glob("*.ipynb")):
    shutil.copyfile(_nb, NOTEBOOKS / _nb.name)
nb_execution_mode = "cache"
nb_execution_cache_path = str(DOCS.parent / "build" / "docs" / "jupyter_cache")
nb_execution_timeout = 300  # seconds per cell: the slowest takes about 30 s on a loaded 2-core machine
nb_execution_raise_on_error = True
nb_execution_in_temp = True
nb_execution_show_tb = True

# Docstrings are numpy style; `name` in a docstring links to the object when it resolves
# and is set as code otherwise (no warning: the build is not nitpicky).
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_rtype = False
napoleon_use_ivar = True
default_role = "py:obj"
autodoc_default_options = {"show-inheritance": True, "member-order": "bysource"}
autodoc_typehints = "description"
autodoc_typehints_format = "short"
autodoc_preserve_defaults = True
add_module_names = False
python_use_unqualified_type_names = True

# Links to the libraries' own docs. This machine reaches only the package registries, so the
# inventories are written locally (docs/inventories.py: the names our docs use, with their
# pages in each library's documentation) instead of being downloaded.
intersphinx_mapping = write_inventories(DOCS.parent / "build" / "docs" / "inventories")

# MyST: headings get anchors, so the Markdown docs can link to sections; $...$ and $$...$$ math
myst_heading_anchors = 3
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence"]

# The gallery: every script of gallery/ runs at each build; the pictures it draws (matplotlib
# figures made without pyplot, as the package makes them) are kept with its code.
sphinx_gallery_conf = {
    "examples_dirs": ["gallery"],
    "gallery_dirs": ["auto_gallery"],
    "filename_pattern": r"/plot_",
    "image_scrapers": (FigureScraper(),),
    "download_all_examples": False,
    "remove_config_comments": True,
    # no page of execution times: its table loads jQuery and DataTables from CDNs (the docs render offline)
    "write_computation_times": False,
    "within_subsection_order": "FileNameSortKey",
    "reset_modules": (),
    "capture_repr": (),
    "show_memory": False,
}

# STICKSLIP_DOCS_FAST=1: neither the notebooks nor the gallery's scripts run (a quick look at the text)
if os.environ.get("STICKSLIP_DOCS_FAST"):
    nb_execution_mode = "off"
    sphinx_gallery_conf["plot_gallery"] = "False"

html_theme = "furo" if importlib.util.find_spec("furo") else "alabaster"
html_title = f"stickslip {release}"
html_static_path: list[str] = []


def setup(app):
    field_docs.connect(app)  # each dataclass's fields: one table (units, ranges), not listed again
