"""Fuzzing the Python API's entry points (issue 9): each public parameter, one bad value at a
time (NaN, infinities, 0, -1, 1e300, 1e-300, text, None, a bool, a list, a complex), must
give a result or a `ParameterError` / `NoSolutionError`, never another exception type
(TypeError, OverflowError, MemoryError, a numba typing error)."""

import warnings

import pytest

from stickslip.brake import BrakeParams
from stickslip.brake.fem import FemScheme
from stickslip.brake.ring import RingScheme
from stickslip.errors import NoSolutionError, ParameterError
from stickslip.friction import Coulomb, Stribeck
from stickslip.halfspace import inverse_problem
from stickslip.oscillator import Oscillator, simulate

BAD = [float("nan"), float("inf"), -float("inf"), -1.0, 0.0, 1e300, 1e-300, "x", None, True, [1.0], 1j]
OSC = dict(mass=1.0, stiffness=1.0, normal_force=1.0, belt_speed=0.2, friction=Coulomb(0.6, 0.4))
BRAKE = dict(xi=1.5, nu=0.3, gamma=1e-6, delta=0.004, friction=0.2)
P = BrakeParams(**BRAKE)
CALLS = {
    "Oscillator": (lambda **k: Oscillator(**{**OSC, **k}), [*OSC, "damping"]),
    "Coulomb": (lambda **k: Coulomb(**{"fs": 0.6, "fd": 0.4, **k}), ["fs", "fd"]),
    "Stribeck": (lambda **k: Stribeck(**{"fs": 0.6, "fd": 0.4, "vs": 0.1, **k}), ["fs", "fd", "vs"]),
    "BrakeParams": (lambda **k: BrakeParams(**{**BRAKE, **k}), list(BRAKE)),
    "FemScheme": (lambda **k: FemScheme(**{"params": P, "n_theta": 16, "n_r": 1, **k}),
                  ["n_theta", "n_r", "beta2", "courant"]),
    "RingScheme": (lambda **k: RingScheme(**{"params": P, "nodes": 32, **k}), ["nodes", "beta2", "courant"]),
    "simulate": (lambda **k: simulate(Oscillator(**OSC), **{"t_end": 5.0, **k}), ["t_end", "x0", "v0"]),
    "inverse_problem": (lambda **k: inverse_problem(**{"b": 2.0, "cbar": -0.7, "v_star": 1e-3, "nu": 0.3, "mu": 0.5,
                                                       **k}), ["b", "cbar", "v_star", "nu", "mu"]),
}
CASES = [(name, param) for name, (_, params) in CALLS.items() for param in params]


@pytest.mark.parametrize("name, param", CASES, ids=[f"{n} {p}" for n, p in CASES])
def test_bad_values_give_a_parameter_error_or_a_result(name, param):
    func = CALLS[name][0]
    for value in BAD:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)
                func(**{param: value})
        except (ParameterError, NoSolutionError) as err:
            assert str(err)
