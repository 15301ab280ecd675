"""The architecture of docs/architecture.md, checked on the source: imports run one way
(cli -> figures/report -> models -> contact/friction -> errors/validation), models and
brake sub-models import only what they may, no module uses another's private names, there
is no import cycle, and no module switches the matplotlib backend or imports pyplot."""

import ast
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "src"
PACKAGE = SRC / "stickslip"

#: Top-level parts of the package and what each may import (besides itself).
BASE = {"errors", "validation", "quantities", "cf", "results"}
MODELS = {"oscillator", "brake", "halfspace", "fem", "system", "rsf"}
ALLOWED = {
    "errors": set(),
    "validation": {"errors"},
    "quantities": {"errors"},
    "vocabulary": {"quantities"},  # deprecated alias of quantities (0.2 only)
    "cf": {"quantities", "__init__"},
    "results": {"cf", "quantities", "errors"},
    "friction": BASE,
    "lawkernel": {"friction"},
    "dop853": set(),
    "kernelcopy": set(),
    "jit": set(),
    "version": set(),  # written at install from the git tag (hatch-vcs)
    "orbits": {"errors"},
    "files": BASE,
    "contact": BASE | {"files", "kernelcopy"},
    "cluster": {"errors"},
    "sweep": BASE | {"files", "cluster"},
    "oscillator": BASE | {"friction", "lawkernel", "dop853", "kernelcopy", "jit", "sweep"},
    "brake": BASE | {"contact", "sweep", "files", "system", "friction"},  # the waves' spectrum: a ring of contacts
    "halfspace": BASE,
    "fem": BASE | {"contact", "friction", "sweep", "files"},
    "system": BASE | {"friction", "lawkernel", "dop853", "kernelcopy", "rsf", "orbits"},
    "rsf": BASE | {"jit"},  # the slider's equations as compiled kernels
    "sbim": BASE | {"rsf", "jit", "files", "halfspace"},  # the half-space in time: rsf's laws, compiled kernels,
    # its run file, the paper's waves (sbim.waves) as initial states
    # (halfspace's waves to come)
    "plotting": {"errors", "validation", "legibility"},  # its argument checks: leaves, imports stay one-way
    "legibility": {"validation"},  # reads laid-out figures, draws nothing
    "errata": set(),
    "figures": BASE | MODELS | {"contact", "friction", "sweep", "files", "plotting", "sbim"},
    "report": BASE | {"figures", "errata", "plotting", "files", "sweep", "__init__"},  # sweep: its process pool
    "cli": BASE | MODELS | {"friction", "contact", "sweep", "cluster", "files", "plotting", "figures", "report", "__init__",
                            "sbim"},
    "__main__": {"cli"},
    "precompile": MODELS | {"friction", "sbim"},  # a small case of each compiled path
    "__init__": {"version"},
}
#: Sub-models of stickslip.brake and what each may import from the others.
BRAKE = {"reduced": set(), "waves": {"reduced"}, "ring": {"reduced"}, "fem": {"reduced"},
         "maps": {"reduced", "waves", "ring"}, "__init__": {"reduced", "waves", "ring"}}


def _modules():
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = path.relative_to(SRC).with_suffix("").parts
        name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
        yield name, path, parts[-1] == "__init__"


MODULES = {name: (path, is_pkg) for name, path, is_pkg in _modules()}


def _imports(name, path, is_pkg):
    """``(target module, imported names, line)`` for every import of the package (any depth)."""
    tree = ast.parse(path.read_text())
    base = name.split(".") if is_pkg else name.split(".")[:-1]
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                mod = ".".join(base[:len(base) - node.level + 1] + ([node.module] if node.module else []))
            else:
                mod = node.module or ""
            if mod.split(".")[0] == "stickslip":
                out.append((mod, [a.name for a in node.names], node.lineno))
        elif isinstance(node, ast.Import):
            out += [(a.name, [], node.lineno) for a in node.names if a.name.split(".")[0] == "stickslip"]
    return out


def _targets(mod, names):
    """The modules an import statement loads: submodules named in it, else the module itself."""
    subs = [f"{mod}.{n}" for n in names if f"{mod}.{n}" in MODULES]
    return subs if subs else [mod]


def _part(module):
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "__init__"


EDGES = {name: [(t, names, line) for mod, names, line in _imports(name, *MODULES[name]) for t in _targets(mod, names)]
         for name in MODULES}


def test_the_package_is_laid_out_as_documented():
    parts = {_part(m) for m in MODULES}
    assert parts == set(ALLOWED), parts ^ set(ALLOWED)
    brake = {m.split(".")[2] if m.count(".") >= 2 else "__init__" for m in MODULES if _part(m) == "brake"}
    assert brake == set(BRAKE), brake ^ set(BRAKE)


def test_imports_run_one_way():
    bad = []
    for name, edges in EDGES.items():
        src = _part(name)
        for target, _, line in edges:
            dst = _part(target)
            # the paper's annulus is a specialisation of the general FE body: brake.fem (only) builds on fem
            annulus = dst == "fem" and (name + ".").startswith("stickslip.brake.fem.")
            if dst != src and dst not in ALLOWED[src] and not annulus:
                bad.append(f"{name}:{line} imports {target}")
            if src == dst == "brake" and name.count(".") >= 2 and target.count(".") >= 2:
                a, b = name.split(".")[2], target.split(".")[2]
                if a != b and b not in BRAKE[a]:
                    bad.append(f"{name}:{line} imports {target}")
    assert not bad, "\n".join(bad)


def _private(names_or_module):
    return [p for p in names_or_module if p.startswith("_") and not (p.startswith("__") and p.endswith("__"))]


@pytest.mark.parametrize("root", ["src", "tests", "benchmarks"])
def test_no_private_names_cross_modules(root):
    """No ``from x import _y``, no private module ``x._m``, no ``module._attr`` on an imported module."""
    bad = []
    for path in sorted((ROOT / root).rglob("*.py")):
        tree = ast.parse(path.read_text())
        modules_bound = set()
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom) and (node.level or (node.module or "").startswith("stickslip")):
                private = _private((node.module or "").split(".")) + _private([a.name for a in node.names])
                if private:
                    bad.append(f"{path.relative_to(ROOT)}:{node.lineno} imports {private}")
                modules_bound |= {a.asname or a.name for a in node.names}
            elif isinstance(node, ast.Import):
                for a in node.names:
                    if a.name.startswith("stickslip"):
                        if _private(a.name.split(".")):
                            bad.append(f"{path.relative_to(ROOT)}:{node.lineno} imports {a.name}")
                        modules_bound.add(a.asname or a.name.split(".")[0])
        for node in ast.walk(tree):
            if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and \
                    node.value.id in modules_bound and _private([node.attr]):
                bad.append(f"{path.relative_to(ROOT)}:{node.lineno} uses {node.value.id}.{node.attr}")
    assert not bad, "\n".join(bad)


def test_no_import_cycles():
    graph = {name: {t for t, _, _ in edges if t in MODULES and t != name} for name, edges in EDGES.items()}
    state, cycles = {}, []

    def visit(node, stack):
        state[node] = "open"
        for nxt in sorted(graph[node]):
            if state.get(nxt) == "open":
                cycles.append(" -> ".join(stack[stack.index(nxt):] + [nxt]))
            elif nxt not in state:
                visit(nxt, stack + [nxt])
        state[node] = "done"

    for name in sorted(graph):
        if name not in state:
            visit(name, [name])
    assert not cycles, "\n".join(cycles)


def test_model_packages_hold_no_plotting():
    bad = [f"{name}:{line}" for name, (path, _) in MODULES.items() if _part(name) in MODELS | {"contact"}
           for line, text in enumerate(path.read_text().splitlines(), 1) if "matplotlib" in text]
    assert not bad, bad


def test_importing_and_plotting_keeps_the_users_backend(tmp_path):
    """A user's backend survives importing every module and drawing a figure; pyplot is never loaded."""
    code = f"""
import matplotlib, sys
matplotlib.use("svg")
import importlib
for name in {sorted(MODULES)!r}:
    if name != "stickslip.__main__":
        importlib.import_module(name)
from stickslip.figures import registry
registry()
from stickslip import plotting
from stickslip.figures.brake import stability
plotting.save(stability.plot(stability.compute(quick=True)), {str(tmp_path / "s.png")!r})
assert matplotlib.get_backend() == "svg", matplotlib.get_backend()
assert "matplotlib.pyplot" not in sys.modules
"""
    subprocess.run([sys.executable, "-c", code], check=True, cwd=tmp_path)
