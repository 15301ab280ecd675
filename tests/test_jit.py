"""Kernels run compiled or interpreted from one source (`stickslip.jit`): the same numbers bit
for bit, a short job without numba, a long one compiled."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from stickslip.jit import KernelSet
from stickslip.oscillator import kernel

#: Seeded oscillators (m, k, c, N, V, mu0, mu1, fs), stick-slip, pure slip, overdamped and
#: negatively damped (a falling law), and starts.
RNG = np.random.default_rng(47)
CASES = [(np.array([m, k, c, 1.0, V, mu0, mu1, mu0 + extra]), x0, v0)
         for m, k, c, V, mu0, mu1, extra, x0, v0 in zip(
             10 ** RNG.uniform(-2, 2, 60), 10 ** RNG.uniform(-2, 3, 60), np.concatenate([np.zeros(20), 10 ** RNG.uniform(
                 -3, 2, 40)]), 10 ** RNG.uniform(-2, 0.5, 60), RNG.uniform(0.1, 0.8, 60),
             np.concatenate([np.zeros(30), RNG.uniform(0.0, 0.3, 30)]), RNG.uniform(0.0, 0.4, 60),
             RNG.uniform(-1.0, 1.0, 60), RNG.uniform(-0.5, 0.5, 60))]


@pytest.mark.parametrize("index", range(len(CASES)))
def test_the_event_loop_gives_the_same_bits_compiled_and_interpreted(index):
    p, x0, v0 = CASES[index]
    mode = 1 if v0 < p[4] else -1
    for section, use in ((0.0, False), (0.5 * p[4], True)):
        a = kernel.KERNELS.interpreted.run_affine(p, x0, v0, mode, 40.0 / np.sqrt(p[1] / p[0]), 400, section, use)
        b = kernel.KERNELS.compiled.run_affine(p, x0, v0, mode, 40.0 / np.sqrt(p[1] / p[0]), 400, section, use)
        assert a[4] == b[4] and a[5] == b[5] and (a[4] > 0 or a[5] == -1)  # -1: the law out of its range
        for x, y in zip(a[:4], b[:4]):
            assert np.array_equal(x, y), (index, np.max(np.abs(x - y)))


def test_the_closed_form_flow_gives_the_same_bits_compiled_and_interpreted():
    interp, comp = kernel.KERNELS.interpreted, kernel.KERNELS.compiled
    t = np.linspace(0.0, 50.0, 257)
    for sigma, w02 in ((0.0, 1.0), (-0.3, 2.0), (0.05, 1.0), (-40.0, 1.0), (-1.0, 1.0)):
        om2 = w02 - sigma**2
        for a, b in zip(interp.state(sigma, w02, om2, 0.3, -0.1, t), comp.state(sigma, w02, om2, 0.3, -0.1, t)):
            assert np.array_equal(a, b)
        ends = [interp.next_piece(sigma, w02, om2, 0.3, -0.1, 0.0, 50.0), comp.next_piece(sigma, w02, om2, 0.3, -0.1,
                                                                                          0.0, 50.0)]
        assert ends[0] == ends[1]
        v_end = interp.velocity_acceleration(sigma, w02, om2, 0.3, -0.1, ends[0])[0]
        level = 0.5 * (-0.1 + v_end)
        if ends[0] > 0 and (v_end - level) * (-0.1 - level) < 0:
            assert interp.velocity_root(sigma, w02, om2, 0.3, -0.1, level, 0.0, ends[0]) == \
                comp.velocity_root(sigma, w02, om2, 0.3, -0.1, level, 0.0, ends[0])


def test_the_readme_first_command_runs_without_numba():
    """Issue 47: the README's first command spares numba's start-up (0.6 s): it runs interpreted.
    Planted: a budget of 0 (compiled from the first segment) loads numba and fails this."""
    code = ("import sys, io, contextlib\n"
            "from stickslip.cli import run\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            "    assert run(['oscillator', 'cycle', '--mass', '1', '--stiffness', '1', '--normal-force', '1',"
            " '--belt-speed', '0.2', '--fs', '0.6', '--fd', '0.4']) == 0\n"
            "print(sorted(m for m in ('numba', 'scipy.optimize', 'scipy.linalg', 'scipy.integrate') if m in sys.modules))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]", out


def test_a_long_job_runs_compiled_and_a_short_one_interpreted():
    calls = []

    def probe(x):
        calls.append(x)
        return x

    kernels = KernelSet({"probe": probe}, ("probe",), budget=100)
    assert kernels.choose(60) is kernels.interpreted and not kernels.loaded
    kernels.charge(kernels.interpreted, 60)
    assert kernels.choose(30) is kernels.interpreted
    assert kernels.choose(50) is kernels.compiled and kernels.loaded  # 60 spent + 50 > 100
    assert kernels.choose(0) is kernels.compiled  # once loaded, always
