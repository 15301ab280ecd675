"""The notebooks of `notebooks/` run from top to bottom, print no warning and draw a figure.

They are stored without outputs (checked here, fast); `make test-slow` executes each one in a
fresh Jupyter kernel of this Python (nbclient + ipykernel, the ``test`` extra).
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted((ROOT / "notebooks").glob("*.ipynb"))


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


@pytest.fixture
def python3_kernel(tmp_path, monkeypatch):
    """The kernel ``python3`` is this interpreter (not a ``python3`` kernel installed elsewhere)."""
    spec = tmp_path / "jupyter" / "kernels" / "python3"
    spec.mkdir(parents=True)
    (spec / "kernel.json").write_text(json.dumps({
        "argv": [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"],
        "display_name": "Python 3 (stickslip tests)", "language": "python"}))
    monkeypatch.setenv("JUPYTER_PATH", str(tmp_path / "jupyter"))
    monkeypatch.setenv("JUPYTER_PLATFORM_DIRS", "1")
    return "python3"


@pytest.mark.slow
@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: p.stem)
def test_notebook_runs(path, tmp_path, python3_kernel):
    import nbformat
    from nbclient import NotebookClient

    nb = nbformat.read(path, as_version=4)
    work = tmp_path / "work"
    work.mkdir()
    NotebookClient(nb, kernel_name=python3_kernel, timeout=600,
                   resources={"metadata": {"path": str(work)}}).execute()  # raises on the first error
    outputs = [out for cell in nb.cells if cell.cell_type == "code" for out in cell.outputs]
    stderr = [out.text for out in outputs if out.output_type == "stream" and out.name == "stderr"]
    assert not stderr, f"{path.name} printed on stderr (a warning?): {stderr}"
    assert any("image/png" in out.get("data", {}) for out in outputs), f"{path.name} shows no figure"
    assert any("text/html" in out.get("data", {}) and "xarray" in out["data"]["text/html"] for out in outputs), \
        f"{path.name} shows no xarray dataset"
