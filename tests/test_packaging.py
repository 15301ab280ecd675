"""A package people can install and cite (issue 27).

The version is the git tag's (hatch-vcs: ``v0.1.0`` gives 0.1.0, a commit after it
0.1.1.devN+g<hash>), written at install into ``src/stickslip/version.py``, so the installed
metadata, ``stickslip --version`` and the files' CF ``source`` say the same; ``CITATION.cff`` names
the newest release of the CHANGELOG, which is the newest tag. The extras name what the examples, notebooks and
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

#: A release's heading in CHANGELOG.md: ``## 0.1.0 — 2026-11-28``.
RELEASE = re.compile(r"^## (\d+\.\d+\.\d+) — (\d{4}-\d{2}-\d{2})\s*$", re.M)


def version_literals(pyproject: dict, init_source: str) -> list[str]:
    """Every version number written by hand: ``[project] version`` and each ``__version__ = "1.2"``
    of the package's ``__init__.py`` (the fallback of a tree never installed, ``0+unknown``, is none)."""
    found = [f"pyproject.toml: {pyproject['project']['version']}"] if "version" in pyproject["project"] else []
    for node in ast.walk(ast.parse(init_source)):
        if isinstance(node, ast.Assign) and any(getattr(t, "id", None) == "__version__" for t in node.targets):
            value = node.value.value if isinstance(node.value, ast.Constant) else None
            if isinstance(value, str) and value != "0+unknown":
                found.append(f"__init__.py: {value}")
    return found


def latest_release(changelog: str) -> tuple[str, str]:
    """The newest release of CHANGELOG.md: ``(version, date)``."""
    found = RELEASE.search(changelog)
    assert found, "CHANGELOG.md has no release heading (## X.Y.Z — YYYY-MM-DD)"
    return found.group(1), found.group(2)


def _git(*args: str) -> str | None:
    try:
        done = subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return None
    return done.stdout.strip() if done.returncode == 0 else None


def test_the_version_is_the_git_tags_only():
    init = ROOT / "src" / "stickslip" / "__init__.py"
    assert version_literals(PYPROJECT, init.read_text()) == []
    assert "version" in PYPROJECT["project"]["dynamic"]
    assert PYPROJECT["tool"]["hatch"]["version"]["source"] == "vcs"
    assert "hatch-vcs" in _requirement_names(tomllib.loads((ROOT / "pyproject.toml").read_text())["build-system"]
                                             ["requires"])


def test_the_guard_finds_a_version_written_by_hand():
    pyproject = {"project": {"version": "0.1.0", "dynamic": []}}
    assert version_literals(pyproject, '__version__ = "0.1.0"\n') == ["pyproject.toml: 0.1.0", "__init__.py: 0.1.0"]
    assert version_literals({"project": {}}, 'try:\n    pass\nexcept ImportError:\n    __version__ = "0.2"\n') == [
        "__init__.py: 0.2"]
    assert version_literals({"project": {}}, '__version__ = "0+unknown"\n') == []


def test_the_installed_metadata_has_the_package_version():
    installed = importlib.metadata.version("stickslip")
    assert installed == stickslip.__version__, (
        f"installed metadata says {installed}, stickslip.__version__ {stickslip.__version__}: the version changed "
        "since the install; reinstall (`pip install -e .`)")


def test_the_release_is_the_tags_and_the_version_follows_it():
    """The newest release of the CHANGELOG is the newest ``v*`` tag (where the clone has its tags),
    and the installed version is that release or a development version after it."""
    from packaging.version import Version

    release, _ = latest_release((ROOT / "CHANGELOG.md").read_text())
    installed = Version(stickslip.__version__)
    tag = _git("describe", "--tags", "--abbrev=0", "--match", "v[0-9]*")
    if tag is None:
        pytest.skip("no release tag in this clone (a clone without tags): the version is a development one")
    assert tag == f"v{release}", f"the newest tag is {tag}, the CHANGELOG's newest release {release}"
    assert installed >= Version(release), f"installed {installed} is older than the release {release}"
    if installed.is_devrelease:
        assert installed.local is not None and installed.local.startswith("g"), installed  # after the tag: +g<hash>
    else:
        assert str(installed) == release


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

def citation_problems(cff: dict, version: str, date: str) -> list[str]:
    """What is wrong with a parsed CITATION.cff: CFF 1.2.0's required keys and shapes, and our facts
    (the release ``version`` of ``date``)."""
    problems = [f"unknown key {k!r}" for k in sorted(set(cff) - CFF_ROOT_KEYS)]
    problems += [f"missing {k!r}" for k in ("cff-version", "message", "title", "authors") if k not in cff]
    if str(cff.get("cff-version")) != "1.2.0":
        problems.append(f"cff-version {cff.get('cff-version')!r}, not 1.2.0")
    if str(cff.get("version")) != version:
        problems.append(f"version {cff.get('version')!r}, the release is {version}")
    if str(cff.get("date-released")) != date:
        problems.append(f"date-released {str(cff.get('date-released'))!r}, the release's is {date}")
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


def test_the_citation_file_is_valid_and_names_the_release():
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    assert citation_problems(cff, *latest_release((ROOT / "CHANGELOG.md").read_text())) == []


def test_the_citation_guard_finds_a_stale_release():
    release, date = latest_release((ROOT / "CHANGELOG.md").read_text())
    cff = {**yaml.safe_load((ROOT / "CITATION.cff").read_text()), "version": release, "date-released": date}
    assert citation_problems(cff, "9.9.9", date) == [f"version {release!r}, the release is 9.9.9"]
    assert citation_problems(cff, release, "2000-01-01") == [f"date-released {date!r}, the release's is 2000-01-01"]
    wrong = {**cff, "refrences": cff["references"], "references": []}
    assert citation_problems(wrong, release, date) == ["unknown key 'refrences'", "the paper is not cited"]


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
