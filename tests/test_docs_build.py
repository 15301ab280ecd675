"""The docs name only code and files that exist.

`docs/theory/brake-fem.md` once named a module that does not exist; this guard resolves every
dotted name of the package (``stickslip.brake.fem.run``, or ``brake.reduced.steady`` relative
to the package) and every repository path (``tests/brake/fem/``, ``benchmarks/x.py``) that the
README, the Markdown docs and the notebooks mention.

The HTML build itself (Sphinx, warnings as errors) is `make docs`, which `.ci/run` runs after
the tests: it is not repeated here.
"""

from __future__ import annotations

import importlib
import pkgutil
import re
from pathlib import Path

import stickslip

ROOT = Path(__file__).resolve().parents[1]

#: The files whose names are checked.
SOURCES = sorted([ROOT / "README.md", *(ROOT / "docs").rglob("*.md"), *(ROOT / "notebooks").glob("*.ipynb")])
#: Suffixes of file names, not of dotted code names (`brake.md`, `run.nc`).
FILE_SUFFIXES = {"md", "py", "nc", "png", "html", "zarr", "json", "ipynb", "toml", "txt", "pdf", "svg", "csv"}
#: Folders of the repository whose paths the docs may name.
TOP_FOLDERS = ("src", "tests", "docs", "benchmarks", "notebooks")

_DOTTED = re.compile(r"(?<![\w./-])((?:stickslip|[a-z_][a-z0-9_]*)(?:\.[A-Za-z_][A-Za-z0-9_]*)+)")
_PATH = re.compile(r"(?<![\w./-])((?:%s)/[\w./-]*)" % "|".join(TOP_FOLDERS))
_CODE_SPAN = re.compile(r"`([^`\n]+)`")


def _subpackages() -> set[str]:
    """First components of a name relative to the package (``brake``, ``contact``, ...)."""
    return {m.name for m in pkgutil.iter_modules(stickslip.__path__)}


def resolves(name: str) -> bool:
    """Whether ``name`` (``stickslip.a.b.c``) is a module, or an attribute of one, of the package."""
    parts = name.split(".")
    for cut in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        try:
            for attr in parts[cut:]:
                obj = getattr(obj, attr)
        except AttributeError:
            return False
        return True
    return False


def dotted_names(text: str) -> set[str]:
    """``stickslip.x.y`` anywhere, and ``x.y`` in a code span when ``x`` is a sub-package of stickslip
    (a file name such as ``brake.md`` is not a code name), as absolute names."""
    found = {m for m in _DOTTED.findall(text) if m.startswith("stickslip.")}
    subpackages = _subpackages()
    for span in _CODE_SPAN.findall(text):
        for name in _DOTTED.findall(span):
            first, last = name.split(".")[0], name.rsplit(".", 1)[1]
            if first in subpackages and last not in FILE_SUFFIXES:
                found.add("stickslip." + name)
    return {name.rstrip(".") for name in found}


def repository_paths(text: str) -> set[str]:
    """Paths under the repository's own folders (``tests/x.py::test_y`` -> ``tests/x.py``)."""
    return {m.split("::")[0].rstrip(".,:;") for m in _PATH.findall(text)}


def unresolved(text: str) -> list[str]:
    """The names and paths of ``text`` that do not exist."""
    bad = [n for n in sorted(dotted_names(text)) if not resolves(n)]
    return bad + [p for p in sorted(repository_paths(text)) if not (ROOT / p).exists()]


def test_every_name_and_path_in_the_docs_exists():
    assert len(SOURCES) > 10
    problems = {str(f.relative_to(ROOT)): bad for f in SOURCES if (bad := unresolved(f.read_text()))}
    assert not problems, f"names or paths that do not exist: {problems}"


def test_the_guard_finds_a_wrong_name():
    text = ("Code: `stickslip.brake.fem.mesh` (`annulus_mesh`), `stickslip.brake.fem.meshes`, `brake.reduced.steady`, "
            "`brake.reduced.stedy`, `contact.kernel.csr_apply`, see `brake.md` and `tests/brake/fem/`, "
            "`tests/brake/fem/test_nothing.py::test_x`, `stickslip.__version__`, `stickslip.nothing`.")
    assert dotted_names(text) == {"stickslip.brake.fem.mesh", "stickslip.brake.fem.meshes",
                                  "stickslip.brake.reduced.steady", "stickslip.brake.reduced.stedy",
                                  "stickslip.contact.kernel.csr_apply", "stickslip.__version__", "stickslip.nothing"}
    assert unresolved(text) == ["stickslip.brake.fem.meshes", "stickslip.brake.reduced.stedy", "stickslip.nothing",
                                "tests/brake/fem/test_nothing.py"]
    # the name this guard was written for
    assert not resolves("stickslip.brake.fem.scheme.stencil_apply")
    assert resolves("stickslip.contact.kernel.stencil_apply")
