"""A package people can install and cite (issue 27).

The version is written once, in ``src/stickslip/__init__.py``: hatchling reads it from there
(``dynamic = ["version"]``), so the installed metadata, ``stickslip --version``, the files' CF
``source`` and ``CITATION.cff`` all say the same. The extras name what the examples, notebooks and
docs import. ``.ci/wheel`` (run by ``.ci/run``) builds the wheel and the sdist and installs them
in fresh environments; the checks here are the fast ones.
"""

import ast
import importlib.metadata
import json
import os
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest
import yaml

import stickslip

ROOT = Path(__file__).resolve().parents[1]
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())
#: The paper's title, as its text and the README give it.
PAPER_TITLE = "Friction-induced vibration and stick-slip waves: short survey and new results"
#: The keys CFF 1.2.0 allows at the root of a CITATION.cff (its schema's ``properties``).
CFF_ROOT_KEYS = {"abstract", "authors", "cff-version", "commit", "contact", "date-released", "doi", "identifiers",
                 "keywords", "license", "license-url", "message", "preferred-citation", "references", "repository",
                 "repository-artifact", "repository-code", "title", "type", "url", "version"}


def _requirement_names(requirements: list[str]) -> set[str]:
    """``["gmsh>=4.11", "myst-nb>=1.4"]`` -> ``{"gmsh", "myst-nb"}`` (normalised as PEP 503 does)."""
    return {re.sub(r"[-_.]+", "-", re.match(r"[A-Za-z0-9][A-Za-z0-9._-]*", r).group()).lower() for r in requirements}


# -- one version ---------------------------------------------------------------------------------------------------

def version_literals(pyproject: dict, init_source: str) -> list[str]:
    """Every place a version number is written: ``[project] version`` and each ``__version__ = "..."``."""
    found = [f"pyproject.toml: {pyproject['project']['version']}"] if "version" in pyproject["project"] else []
    for node in ast.parse(init_source).body:
        if isinstance(node, ast.Assign) and any(getattr(t, "id", None) == "__version__" for t in node.targets):
            found.append(f"__init__.py: {ast.literal_eval(node.value)}")
    return found


def test_the_version_is_written_once():
    init = ROOT / "src" / "stickslip" / "__init__.py"
    assert version_literals(PYPROJECT, init.read_text()) == [f"__init__.py: {stickslip.__version__}"]
    assert "version" in PYPROJECT["project"]["dynamic"]
    assert PYPROJECT["tool"]["hatch"]["version"]["path"] == "src/stickslip/__init__.py"


def test_the_guard_finds_a_second_version():
    pyproject = {"project": {"version": "0.1.0", "dynamic": []}}
    assert version_literals(pyproject, '__version__ = "0.1.0"\n') == ["pyproject.toml: 0.1.0", "__init__.py: 0.1.0"]
    assert len(version_literals({"project": {}}, '__version__ = "0.1.0"\n__version__ = "0.2.0"\n')) == 2


def test_the_installed_metadata_has_the_package_version():
    installed = importlib.metadata.version("stickslip")
    assert installed == stickslip.__version__, (
        f"installed metadata says {installed}, stickslip.__version__ {stickslip.__version__}: the version changed "
        "since the install; reinstall (`pip install -e .`)")


# -- extras --------------------------------------------------------------------------------------------------------

def _imports_of_python(source: str) -> set[str]:
    modules = set()
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            modules |= {alias.name.split(".")[0] for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            modules.add(node.module.split(".")[0])
    return modules


def example_imports() -> set[str]:
    """The top-level modules that the scripts of ``examples/`` and the code cells of ``notebooks/`` import."""
    modules = set()
    for path in sorted((ROOT / "examples").rglob("*.py")):
        modules |= _imports_of_python(path.read_text())
    for path in sorted((ROOT / "notebooks").glob("*.ipynb")):
        for cell in json.loads(path.read_text())["cells"]:
            if cell["cell_type"] == "code":
                code = "".join(cell["source"])
                modules |= _imports_of_python("\n".join(line for line in code.splitlines()
                                                        if not line.lstrip().startswith(("%", "!"))))
    return modules - set(sys.stdlib_module_names) - {"stickslip", "__future__"}


def test_the_examples_extra_holds_what_examples_and_notebooks_import():
    extras = PYPROJECT["project"]["optional-dependencies"]
    assert {"gmsh", "jupyter"} <= _requirement_names(extras["examples"])
    assert "gmsh" in _requirement_names(extras["test"]), "the tests mesh with gmsh too"
    declared = _requirement_names(PYPROJECT["project"]["dependencies"] + extras["examples"])
    # a notebook's kernel (IPython) comes with Jupyter
    declared |= {"ipython"} if "jupyter" in declared else set()
    distributions = importlib.metadata.packages_distributions()
    missing = {}
    for module in sorted(example_imports()):
        names = _requirement_names(distributions.get(module, [module]))
        if not names & declared:
            missing[module] = sorted(names)
    assert not missing, f"imported by examples/ or notebooks/ but in no dependency or the examples extra: {missing}"


def test_the_docs_extra_holds_the_sphinx_extensions():
    docs = _requirement_names(PYPROJECT["project"]["optional-dependencies"]["docs"])
    assert {"sphinx", "myst-parser", "furo", "sphinx-gallery", "myst-nb"} <= docs


# -- citation ------------------------------------------------------------------------------------------------------

def citation_problems(cff: dict, version: str) -> list[str]:
    """What is wrong with a parsed CITATION.cff: CFF 1.2.0's required keys and shapes, and our facts."""
    problems = [f"unknown key {k!r}" for k in sorted(set(cff) - CFF_ROOT_KEYS)]
    problems += [f"missing {k!r}" for k in ("cff-version", "message", "title", "authors") if k not in cff]
    if str(cff.get("cff-version")) != "1.2.0":
        problems.append(f"cff-version {cff.get('cff-version')!r}, not 1.2.0")
    if str(cff.get("version")) != version:
        problems.append(f"version {cff.get('version')!r}, the package's is {version}")
    if (cff.get("title"), cff.get("license")) != ("stickslip", "BSD-3-Clause"):
        problems.append(f"title/license {cff.get('title')!r}/{cff.get('license')!r}")
    if cff.get("authors") != [{"name": "stickslip developers"}]:
        problems.append(f"authors {cff.get('authors')!r}")
    works = cff.get("references", []) + ([cff["preferred-citation"]] if "preferred-citation" in cff else [])
    for work in works:
        title = work.get("title")
        problems += [f"reference {title!r} lacks {k!r}" for k in ("type", "title", "authors") if k not in work]
        if not work.get("authors") or not all("name" in a or "family-names" in a for a in work["authors"]):
            problems.append(f"reference {title!r}: each author needs a name or family-names")
    if PAPER_TITLE not in [w.get("title") for w in works]:
        problems.append("the paper is not cited")
    return problems


def test_the_citation_file_is_valid_and_current():
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    assert citation_problems(cff, stickslip.__version__) == []


def test_the_citation_guard_finds_a_stale_version():
    cff = {**yaml.safe_load((ROOT / "CITATION.cff").read_text()), "version": stickslip.__version__}
    assert citation_problems(cff, "9.9.9") == [f"version {cff['version']!r}, the package's is 9.9.9"]
    wrong = {**cff, "refrences": cff["references"], "references": []}
    assert citation_problems(wrong, stickslip.__version__) == ["unknown key 'refrences'", "the paper is not cited"]


def test_the_paper_title_is_the_one_the_readme_and_the_paper_give():
    assert PAPER_TITLE in " ".join((ROOT / "README.md").read_text().split())
    texts = sorted((ROOT.parent / "shared" / "paper").glob("*.txt"))  # shared/ lies beside the clone
    if not texts:
        pytest.skip("the paper's text (shared/paper/ beside the repository) is not here")
    title, subtitle = [line.strip() for line in texts[0].read_text().splitlines() if line.strip()][:2]
    assert f"{title}: {subtitle[0].lower()}{subtitle[1:]}" == PAPER_TITLE


# -- CI ------------------------------------------------------------------------------------------------------------

def test_ci_builds_and_installs_the_wheel_after_the_docs():
    wheel = ROOT / ".ci" / "wheel"
    assert os.access(wheel, os.X_OK), ".ci/wheel must be executable"
    assert subprocess.run(["sh", "-n", str(wheel)], capture_output=True).returncode == 0, "not POSIX sh"
    steps = [line.strip() for line in (ROOT / ".ci" / "run").read_text().splitlines()
             if line.strip() and not line.lstrip().startswith("#")]
    assert "make docs" in steps and any(s.endswith(".ci/wheel") for s in steps)
    assert steps.index("make docs") < next(i for i, s in enumerate(steps) if s.endswith(".ci/wheel"))
