"""The Python examples of the README and the tutorial run as written."""

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _blocks(name):
    return re.findall(r"```python\n(.*?)```", (ROOT / name).read_text(), flags=re.S)


def test_readme_example_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in _blocks("README.md"):
        exec(block, namespace)
    assert abs(namespace["cycle"].period - 6.712388980384690) < 1e-12
    assert (tmp_path / "run.nc").exists()


@pytest.mark.slow
def test_tutorial_examples_run(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in _blocks("docs/tutorial-oscillator.md"):
        exec(block, namespace)
    assert namespace["hopf"].criticality == "subcritical"
    assert any(e["kind"] == "grazing" for e in namespace["stick_slip"].events)


def test_brake_tutorial_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in _blocks("docs/tutorial-brake.md"):
        exec(block, namespace)
    assert namespace["wave"].regime == "stick-slip-separation" and namespace["s"].p_e > 0
    assert namespace["regime"].regime.startswith("stick")


def test_halfspace_tutorial_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in _blocks("docs/tutorial-halfspace.md"):
        exec(block, namespace)
    assert abs(namespace["wave"].c + 0.7) < 1e-6 and abs(namespace["wave"].b - 2.0) < 1e-6
    assert namespace["f"].slip_residual < 1e-10
