"""The slider's compiled equations (`stickslip.rsf.kernel`) against the equations as written
(`SpringSlider.rhs`, numpy, complex-capable) and their Jacobian against complex steps of those:
a consistency check of two writings of the same equations, the derivatives by an independent
route. The integration itself is verified against rsfmodel's published cases and independent stiff
solves (test_slider.py)."""

import itertools
import sys

import numpy as np
import pytest

from stickslip.rsf import RateState, SpringSlider, slide
from stickslip.rsf.kernel import KERNELS, pack
from stickslip.rsf.slider import jacobian

CASES = list(itertools.product(("aging", "slip", "prz"), (False, True), (False, True), (0.0, 1e3)))


def _state(slider, rng, z=None):
    """A state near steady sliding at 1 um/s; with ``z``, its slip rate set where the regularised
    law's ``z = ln(V / 2 V_0) + Psi / a`` is ``z`` (at steady sliding z is about 50: the logarithm's
    regime, where the regularisation changes nothing)."""
    y = slider.steady_state(1e-6)
    y = y + rng.normal(size=y.size) * np.r_[1.0, 0.5 * np.ones(slider.law.states), 1e4, 1e-3]
    if z is not None:
        law = slider.law
        big_psi = law.f0 + law.b_values @ y[1:1 + law.states]
        y[0] = z + np.log(2.0 * law.v_ref) - big_psi / law.a
    return y


@pytest.mark.parametrize("evolution, regularized, two, mass", CASES)
def test_the_compiled_equations_and_jacobian_are_the_written_ones(evolution, regularized, two, mass):
    law = RateState(0.011, 0.015, 1e-5, evolution=evolution, regularized=regularized, b2=0.004 if two else 0.0,
                    dc2=1e-4 if two else None)
    slider = SpringSlider(law, 1e7, 1e10, mass)
    rng = np.random.default_rng(7)
    for kernels in (KERNELS.interpreted, KERNELS.compiled):
        for z in (None, None, -2.0, 0.0, 1.5):
            y = _state(slider, rng, z)
            p = pack(slider, 3e-6)
            rate, jac = np.empty(y.size), np.empty((y.size, y.size))
            kernels.rhs(y, p, rate)
            kernels.jacobian(y, p, jac)
            written = slider.rhs(y, 3e-6)
            assert np.allclose(rate, written, rtol=1e-12, atol=0.0), (rate, written)
            steps = jacobian(slider, y, 3e-6)
            assert np.max(np.abs(jac - steps)) <= 1e-12 * np.max(np.abs(steps)), (jac, steps)


def test_the_regularised_law_far_above_its_switch_to_the_logarithm():
    """z > 30 (V far above V_0 e^(-Psi/a)): the asinh's logarithm, its slope the law's a."""
    law = RateState(0.01, 0.015, 1e-5, regularized=True)
    slider = SpringSlider(law, 1e7, 1e10)
    y = slider.steady_state(1.0) + np.array([0.3, -0.5, 1e4, 0.0])  # z = 52 at steady sliding, 45 here
    p = pack(slider, 1.0)
    rate, jac = np.empty(y.size), np.empty((y.size, y.size))
    KERNELS.compiled.rhs(y, p, rate)
    KERNELS.compiled.jacobian(y, p, jac)
    assert np.allclose(rate, slider.rhs(y, 1.0), rtol=1e-12, atol=1e-300)
    assert np.allclose(jac, jacobian(slider, y, 1.0), rtol=1e-12, atol=1e-12 * np.abs(jac).max())


def test_a_short_slide_runs_interpreted_without_numba():
    """A run of a few hundred steps pays no numba start-up (`stickslip.jit`): a fresh process."""
    import subprocess

    code = ("import sys\nfrom stickslip.rsf import RateState, SpringSlider, slide\n"
            "slide(SpringSlider(RateState(0.01, 0.015, 1e-5), 1e7, 1e10), [1e-6, 1e-5], 30.0, times=[0, 10])\n"
            "print('numba' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0 and done.stdout.strip() == "False", done.stderr[-500:]


def test_a_piece_that_outgrows_the_interpreted_allowance_is_solved_again_compiled():
    """A fresh process starts a run of stick-slip cycles interpreted; past its allowance of calls the
    piece is solved again compiled: its result equals this process's compiled run (to the integration's
    tolerance: the two writings run the same operations, but Python's and numba's exp may differ in
    the last bit)."""
    import subprocess

    slider = "SpringSlider(RateState(0.01, 0.015, 1e-5), 1e7, 0.5 * 5e9, 1e6)"  # stick-slip cycles with inertia
    code = ("import sys\nimport numpy as np\nfrom stickslip.rsf import RateState, SpringSlider, slide\n"
            "from stickslip.rsf.kernel import KERNELS\n"
            f"r = slide({slider}, 1e-6, 5000.0, v_init=1.1e-6)\n"
            "print(KERNELS.loaded, repr(r.slip_rate[::50].tolist()))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    loaded, rates = done.stdout.split(" ", 1)
    assert done.returncode == 0 and loaded == "True", done.stderr[-500:]
    KERNELS.compiled  # noqa: B018 (this process: compiled from the start)
    here = slide(eval(slider), 1e-6, 5000.0, v_init=1.1e-6)
    assert np.allclose(eval(rates), here.slip_rate[::50], rtol=1e-7, atol=0.0)
