"""The notebooks of `notebooks/` run from top to bottom, print no warning and draw a figure,
and every figure they make is legible.

They are stored without outputs (checked here, fast); `make test-slow` executes each one in a
fresh Jupyter kernel of this Python (nbclient + ipykernel, the ``test`` extra), once for both
slow tests: after the notebook's own cells, a probe cell (added to the copy in memory only)
checks every figure left in the kernel with `stickslip.plotting.legibility_problems`, as the
report's figures are.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))

#: The line of the probe's output that carries its findings (JSON after the tag).
PROBE_TAG = "LEGIBILITY-PROBE "
#: The probe cell run after a notebook's cells: every `matplotlib.figure.Figure` the notebook
#: left in its namespace (a variable, an axes or subfigure of it, a list, tuple or dict of them,
#: a value shown by a cell, which IPython keeps in ``Out``) or in pyplot, checked at the
#: default width (the report's column, 11.7 in, about the width a notebook shows it at) as the
#: figure is laid out when it is shown. It prints one line: ``PROBE_TAG`` and a JSON list of
#: ``{"figure": where, "problems": [...]}``, or ``{"error": ...}`` if the probe itself fails.
PROBE = f'''
def _legibility_probe(namespace):
    import json, sys, traceback
    try:
        from matplotlib.axes import Axes
        from matplotlib.figure import Figure, FigureBase
        from stickslip.plotting import legibility_problems

        found = {{}}

        def root(obj):
            if isinstance(obj, Axes):
                obj = obj.figure
            if isinstance(obj, FigureBase) and not isinstance(obj, Figure):  # a subfigure
                obj = obj.get_figure(root=True) if hasattr(obj, "get_figure") else obj.figure
            return obj if isinstance(obj, Figure) else None

        def walk(obj, where, depth=0):
            fig = root(obj)
            if fig is not None:
                # named by its variable rather than by an axes of it or IPython's caches
                rank = (where.startswith("_"), where.startswith("Out"), fig is not obj)
                if id(fig) not in found or rank < found[id(fig)][0]:
                    found[id(fig)] = (rank, where, fig)
            elif depth < 3 and isinstance(obj, dict):
                for key, value in list(obj.items()):
                    walk(value, f"{{where}}[{{key!r}}]", depth + 1)
            elif depth < 3 and isinstance(obj, (list, tuple)):
                for k, value in enumerate(obj):
                    walk(value, f"{{where}}[{{k}}]", depth + 1)

        for name, value in list(namespace.items()):
            if name in ("In", "_ih", "_oh", "_dh", "exit", "quit", "get_ipython"):
                continue
            walk(value, name)
        if "matplotlib.pyplot" in sys.modules:
            from matplotlib._pylab_helpers import Gcf
            for manager in Gcf.get_all_fig_managers():
                walk(manager.canvas.figure, f"pyplot figure {{manager.num}}")
        report = [{{"figure": where, "problems": legibility_problems(fig)}} for _, where, fig in found.values()]
    except Exception:
        report = {{"error": traceback.format_exc()}}
    print({PROBE_TAG!r} + json.dumps(report))


_legibility_probe(globals())
del _legibility_probe
'''


def test_there_is_one_notebook_per_model():
    assert {p.stem for p in NOTEBOOKS} >= {"oscillator", "brake", "brake-fem", "halfspace"}


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_is_stored_without_outputs(path):
    nb = json.loads(path.read_text())
    code = [cell for cell in nb["cells"] if cell["cell_type"] == "code"]
    assert code
    assert all(not cell["outputs"] and cell["execution_count"] is None for cell in code), \
        f"{path.name}: clear the outputs before committing"
    assert nb["metadata"]["kernelspec"]["name"] == "python3"


def _python3_kernel(root: Path, monkeypatch) -> str:
    """The kernel ``python3`` is this interpreter (not a ``python3`` kernel installed elsewhere)."""
    spec = root / "jupyter" / "kernels" / "python3"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "Python 3 (stickslip tests)", "language": "python"}))
    monkeypatch.setenv("JUPYTER_PATH", str(root / "jupyter"))
    monkeypatch.setenv("JUPYTER_PLATFORM_DIRS", "1")
    return "python3"


def execute(path: Path, kernel_name: str, work: Path):
    """``(outputs of the notebook's cells, the probe's report)``: ``path`` run in a fresh
    kernel in ``work`` (raises on the first error), then the probe `PROBE`."""
    import nbformat
    from nbclient import NotebookClient

    nb = nbformat.read(path, as_version=4)
    n = len(nb.cells)
    nb.cells.append(nbformat.v4.new_code_cell(PROBE))
    NotebookClient(nb, kernel_name=kernel_name, timeout=600,
                   resources={"metadata": {"path": str(work)}}).execute()
    outputs = [out for cell in nb.cells[:n] if cell.cell_type == "code" for out in cell.outputs]
    probe = "".join(out.get("text", "") for out in nb.cells[n].outputs if out.output_type == "stream")
    lines = [line for line in probe.splitlines() if line.startswith(PROBE_TAG)]
    assert len(lines) == 1, f"{path.name}: the legibility probe printed no report: {nb.cells[n].outputs}"
    return outputs, json.loads(lines[0][len(PROBE_TAG):])


@pytest.fixture(scope="module")
def executed(tmp_path_factory):
    """``run(path)``: `execute` once per notebook (both slow tests read the same run)."""
    cache: dict = {}
    root = tmp_path_factory.mktemp("notebooks")
    with pytest.MonkeyPatch.context() as monkeypatch:
        kernel = _python3_kernel(root, monkeypatch)

        def run(path):
            if path not in cache:
                work = root / path.stem
                work.mkdir()
                try:
                    cache[path] = execute(path, kernel, work)
                except Exception as error:  # noqa: BLE001 - the second test sees the same failure
                    cache[path] = error
            if isinstance(cache[path], Exception):
                raise cache[path]
            return cache[path]

        yield run


@pytest.mark.slow
@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_runs(path, executed):
    outputs, _ = executed(path)
    stderr = [out.text for out in outputs if out.output_type == "stream" and out.name == "stderr"]
    assert not stderr, f"{path.name} printed on stderr (a warning?): {stderr}"
    assert any("image/png" in out.get("data", {}) for out in outputs), f"{path.name} shows no figure"
    assert any("text/html" in out.get("data", {}) and "xarray" in out["data"]["text/html"] for out in outputs), \
        f"{path.name} shows no xarray dataset"


@pytest.mark.slow
@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_figures_are_legible(path, executed):
    """Every figure a notebook makes passes `legibility_problems` (issue 27), as the report's do."""
    outputs, report = executed(path)
    assert not isinstance(report, dict), f"{path.name}: the legibility probe failed:\n{report['error']}"
    shown = sum("image/png" in out.get("data", {}) for out in outputs)
    assert report and len(report) >= shown, \
        f"{path.name}: the probe found {len(report)} figure(s), the notebook shows {shown}"
    bad = {entry["figure"]: entry["problems"] for entry in report if entry["problems"]}
    assert not bad, f"{path.name}: {sum(map(len, bad.values()))} legibility problem(s):\n" + "\n".join(
        f"  {figure}: {problem}" for figure, problems in bad.items() for problem in problems)
