"""Fuzzing the Python API's entry points (issue 9): each public parameter, one bad value at a
time (NaN, infinities, 0, -1, 1e300, 1e-300, text, None, a bool, a list, a complex), must
give a result or a `ParameterError` / `NoSolutionError`, never another exception type
(TypeError, OverflowError, MemoryError, a numba typing error)."""

import warnings

import pytest

from stickslip.brake import (BrakeParams, PhysicalParams, continue_waves, growth_rates, integrate, perturbed_steady,
                             steady_sliding, travelling_wave)
from stickslip.brake.fem import FemScheme, integrate_fem
from stickslip.brake.ring import RingScheme
from stickslip.errors import NoSolutionError, ParameterError
from stickslip.fem.orthotropic import Orthotropic
from stickslip.friction import Coulomb, Stribeck
from stickslip.halfspace import StickSlipWave, direct_problem, inverse_problem
from stickslip.oscillator import Oscillator, continue_cycle, hopf_points, limit_cycle, simulate
from stickslip.sweep import run_sweep
from stickslip.system import Contact, System
from stickslip.system import limit_cycle as system_cycle
from stickslip.system import load_system
from stickslip.system import simulate as system_simulate
from stickslip.system import steady_sliding as system_steady
from stickslip.system import burridge_knopoff
from stickslip.rsf import RateState, SpringSlider, hopf_criticality, linear_stability, slide, slider_cycle
from stickslip.brake.waves import ring_system, wave_spectra, wave_spectrum
from stickslip.system import continue_system, file_parameter, rate_state_simulate, rate_state_steady, relative_cycle

FIG5 = BrakeParams.from_physical(100.0, 1e-4, 0.2)


def _oscillator_build(v):
    return System([[1.0]], [[1.0]], [Contact([1.0], 1.0, Coulomb(0.6, 0.4), v)])


def _ring():
    return ring_system(FIG5, 8)


def _fig5_wave():
    if not _WAVE:
        _WAVE.append(travelling_wave(FIG5, 4))
    return _WAVE[0]


_WAVE: list = []


def _one(x):
    return {"y": x}


def _fresh_store():
    import tempfile

    return tempfile.mkdtemp(prefix="fuzz-") + "/s.zarr"


BAD = [float("nan"), float("inf"), -float("inf"), -1.0, 0.0, 1e300, 1e-300, 1e-320, "x", None, True, [1.0], 1j, [],
       ["a"], 10**20]
OSC = dict(mass=1.0, stiffness=1.0, normal_force=1.0, belt_speed=0.2, friction=Coulomb(0.6, 0.4))
BRAKE = dict(xi=1.5, nu=0.3, gamma=1e-6, delta=0.004, friction=0.2)
P = BrakeParams(**BRAKE)
ORTHO = dict(e1=2e10, e2=5e9, nu12=0.3, g12=3e9, density=1500.0, e3=8e9, nu13=0.2, nu23=0.35)
CONTACT = dict(direction=[1.0, 0.0], normal_force=1.0, friction=Coulomb(0.6, 0.4), surface_speed=0.2)
SYSTEM = dict(mass=[[1.0, 0.0], [0.0, 2.0]], stiffness=[[2.0, -1.0], [-1.0, 1.0]], contacts=[Contact(**CONTACT)])
RSF_LAW = dict(a=0.01, b=0.015, dc=1e-5)
SLIDER = dict(law=RateState(**RSF_LAW), normal_stress=1e7, stiffness=1e10)
RSF_SYSTEM = dict(mass=[[1.0]], stiffness=[[4000.0]],
                  contacts=[Contact([1.0], 10.0, RateState(**RSF_LAW), surface_speed=1e-6)])
CALLS = {
    "rate_state_simulate": (lambda **k: rate_state_simulate(**{"system": System(**RSF_SYSTEM), "t_end": 5.0,
                                                               "samples": 11, **k}),
                            ["system", "x0", "v0", "t_end", "psi0", "samples", "rtol"]),
    "rate_state_steady": (lambda **k: rate_state_steady(**{"system": System(**RSF_SYSTEM), **k}), ["system"]),
    "system steady_sliding": (lambda **k: system_steady(**{"system": System(**SYSTEM), **k}), ["system"]),
    "burridge_knopoff": (lambda **k: burridge_knopoff(**{"blocks": 3, "friction": Coulomb(0.6, 0.4), **k}),
                         ["blocks", "friction", "mass", "coupling", "pull", "normal_force", "plate_speed", "damping"]),
    "RateState": (lambda **k: RateState(**{**RSF_LAW, **k}),
                  [*RSF_LAW, "f0", "v_ref", "evolution", "b2", "dc2", "regularized"]),
    "SpringSlider": (lambda **k: SpringSlider(**{**SLIDER, **k}), [*SLIDER, "mass"]),
    "slide": (lambda **k: slide(**{"slider": SpringSlider(**SLIDER), "load_velocity": 1e-6, "t_end": 10.0, **k}),
              ["slider", "load_velocity", "t_end", "times", "v_init", "samples", "rtol", "start"]),
    "linear_stability": (lambda **k: linear_stability(**{"slider": SpringSlider(**SLIDER), "load_velocity": 1e-6, **k}),
                         ["slider", "load_velocity"]),
    "hopf_criticality": (lambda **k: hopf_criticality(**{"slider": SpringSlider(**SLIDER), "load_velocity": 1e-6, **k}),
                         ["slider", "load_velocity"]),
    "slider_cycle": (lambda **k: slider_cycle(**{"slider": SpringSlider(**SLIDER), "load_velocity": 1e-6, **k}),
                     ["slider", "load_velocity", "transient", "cycles", "rtol", "tol"]),
    "System": (lambda **k: System(**{**SYSTEM, **k}), [*SYSTEM, "damping", "force"]),
    "Contact": (lambda **k: Contact(**{**CONTACT, **k}), [*CONTACT, "name", "normal_on_structure"]),
    "system simulate": (lambda **k: system_simulate(**{"system": System(**SYSTEM), "t_end": 5.0, **k}),
                        ["system", "x0", "v0", "t_end", "samples", "max_events", "segments", "states", "stop_at"]),
    "relative_cycle": (lambda **k: relative_cycle(**{"system": _ring(), "x0": [0.0] * 8, "v0": [0.0] * 8,
                                                     "shift": [1, 2, 3, 4, 5, 6, 7, 0], "contact": 0, "state": 0,
                                                     "horizon": 1.0, **k}),
                       ["system", "x0", "v0", "shift", "contact", "state", "states", "horizon", "tol", "max_iter"]),
    "continue_system": (lambda **k: continue_system(**{"build": _oscillator_build, "start": 0.2, "stop": 0.3,
                                                       "points": 3, "transient": 30.0, **k}),
                        ["build", "start", "stop", "points", "x0", "v0", "transient", "tol", "parameter"]),
    "file_parameter": (lambda **k: file_parameter(**{"data": {"mass": [[1.0]], "stiffness": [[1.0]], "contact": [
        {"direction": [1.0], "normal_force": 1.0, "surface_speed": 0.2, "fs": 0.6, "fd": 0.4}]},
        "key": "contact[0].surface_speed", **k}), ["data", "key"]),
    "ring_system": (lambda **k: ring_system(**{"params": FIG5, "nodes": 16, **k}), ["params", "nodes"]),
    "wave_spectrum": (lambda **k: wave_spectrum(**{"wave": _fig5_wave(), "nodes": 16, **k}), ["wave", "nodes", "tol"]),
    "wave_spectra": (lambda **k: wave_spectra(**{"wave": _fig5_wave(), "nodes": [16], **k}), ["nodes", "tol"]),
    "load_system": (lambda **k: load_system(**{"path": "no such file.toml", **k}), ["path"]),
    "system limit_cycle": (lambda **k: system_cycle(**{"system": System(**SYSTEM), "transient": 20.0, **k}),
                           ["system", "x0", "v0", "transient", "tol", "max_iter"]),
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
    "direct_problem": (lambda **k: direct_problem(**{"T": 9.52e-4, "v": 3.514e-3, "v_star": 1e-3, "nu": 0.3,
                                                     "mu": 0.5, **k}),
                       ["T", "v", "v_star", "nu", "mu"]),
    "StickSlipWave": (lambda **k: StickSlipWave(**{"b": 11.358, "cbar": -0.7, "T": 9.52e-4, "v": 3.514e-3,
                                                   "v_star": 1e-3, "nu": 0.3, "mu": 0.5, **k}),
                      ["b", "cbar", "T", "v", "v_star", "nu", "mu"]),
    "PhysicalParams": (lambda **k: PhysicalParams(**{"omega": 50.0, "mismatch": 1e-4, "friction": 0.7, **k}),
                       ["omega", "mismatch", "friction", "inner_radius", "outer_radius", "young", "density",
                        "poisson"]),
    "limit_cycle": (lambda **k: limit_cycle(Oscillator(**OSC), **k), ["x0", "v0", "rtol"]),
    "hopf_points": (lambda **k: hopf_points(Oscillator(**OSC), **{"parameter": "belt_speed", "lo": 0.1, "hi": 1.0,
                                                                  **k}), ["parameter", "lo", "hi", "num"]),
    "continue_cycle": (lambda **k: continue_cycle(Oscillator(**OSC), **{"stop": 0.25, "max_points": 3, **k}),
                       ["stop", "step", "max_step", "min_step", "max_points"]),
    "steady_sliding": (lambda **k: steady_sliding(**{**{x: BRAKE[x] for x in ("xi", "nu", "delta", "friction")},
                                                     **k}), ["xi", "nu", "delta", "friction"]),
    "growth_rates": (lambda **k: growth_rates(**{"params": P, "modes": [1, 2], **k}), ["params", "modes"]),
    "travelling_wave": (lambda **k: travelling_wave(**{"params": P, "modes": 8, **k}), ["modes", "num"]),
    "continue_waves": (lambda **k: continue_waves(**{"params": P, "modes": 8, "stop": 0.0039, "num": 2, **k}),
                       ["modes", "stop", "num", "tol"]),
    "perturbed_steady": (lambda **k: perturbed_steady(**{"params": P, "nodes": 32, **k}),
                         ["nodes", "amplitude", "mode", "seed", "phase", "noise"]),
    "integrate": (lambda **k: integrate(**{"params": P, "nodes": 32, "transits": 0.5, **k}),
                  ["nodes", "transits", "beta2", "courant", "samples_per_transit", "snapshot_every", "tail", "modes"]),
    "integrate_fem": (lambda **k: integrate_fem(**{"params": P, "n_theta": 16, "n_r": 1, "transits": 0.5, **k}),
                      ["n_theta", "n_r", "transits", "beta2", "courant", "samples_per_transit", "modes"]),
    "Orthotropic": (lambda **k: Orthotropic(**{**ORTHO, **k}), [*ORTHO, "angle", "plane", "alpha", "beta"]),
    "run_sweep": (lambda **k: run_sweep(**{"func": _one, "axes": {"x": [1.0]}, "store": _fresh_store(),
                                           "outputs": {"y": "1"}, "scheduler": "synchronous", **k}),
                  ["axes", "store", "outputs", "batch", "workers"]),
}
def _example_problem():
    """The pad on a disc (coarse mesh) as a body, its frames and a problem, made once."""
    if not _PAD:
        from stickslip.fem.config import load_config

        from .fuzz_harness import example_config

        cfg = load_config(example_config())
        _PAD.update(cfg=cfg, body=cfg.body, surface=cfg.surface, problem=cfg.problem())
    return _PAD


_PAD: dict = {}


def _frames(**k):
    from stickslip.fem import contact_frames

    p = _example_problem()
    return contact_frames(**{"body": p["body"], "group": p["cfg"].group, "surface": p["surface"], **k})


def _contact_problem(**k):
    from stickslip.fem import ContactProblem

    p = _example_problem()["problem"]
    return ContactProblem(**{"system": p.system, "frames": p.frames, "friction": 0.5, "clamped": p.clamped, **k})


def _user_law(**k):
    from stickslip.friction import UserLaw

    value = k.get("returns")
    law = UserLaw(lambda v: value, fs=0.6)
    return limit_cycle(Oscillator(**{**OSC, "friction": law}))


def _fields(**k):
    from stickslip.halfspace import wave_from_inverse

    return wave_from_inverse(11.358, -0.7, 1e-3, nu=0.3, mu=0.5).fields(**{"n": 101, **k})


def _from_hopf(**k):
    from stickslip.friction import LinearWeakening
    from stickslip.oscillator import continue_from_hopf

    osc = Oscillator(**{**OSC, "friction": LinearWeakening(0.6, 0.4, 0.5), "damping": 0.1})
    hopf = hopf_points(osc, "damping", 0.01, 1.0)[0]
    return continue_from_hopf(**{"osc": osc, "hopf": hopf, "stop": 0.15, "max_points": 2, **k})


def _ring_classify(**k):
    from stickslip.brake import classify

    return classify(**{"run": None, **k})


CALLS.update({
    "annulus_frequencies": (lambda **k: __import__("stickslip.brake.fem", fromlist=["x"]).annulus_frequencies(
        **{"xi": 1.5, "nu": 0.3, "n": 2, **k}), ["xi", "nu", "n", "count", "w_max", "step"]),
    "fem perturbed_steady": (lambda **k: __import__("stickslip.brake.fem", fromlist=["x"]).perturbed_steady(
        **{"scheme": FemScheme(P, 16, 1), "mode": 2, **k}), ["scheme", "amplitude", "mode", "seed", "phase", "noise"]),
    "inverse_map": (lambda **k: __import__("stickslip.halfspace", fromlist=["x"]).inverse_map(
        **{"b_values": [2.0, 3.0], "c_values": [-0.5], "v_star": 1e-3, "nu": 0.3, "mu": 0.5, **k}),
        ["b_values", "c_values", "v_star", "nu", "mu", "systems"]),
    "direct_map": (lambda **k: __import__("stickslip.halfspace", fromlist=["x"]).direct_map(
        **{"v_ratio": [3.5], "T_ratio": [0.95], "nu": 0.3, "mu": 0.5, "n_grid": 201, **k}),
        ["v_ratio", "T_ratio", "nu", "mu", "system", "n_grid", "max_solutions"]),
    "fields": (_fields, ["x", "n"]),
    "UserLaw": (_user_law, ["returns"]),
    "continue_from_hopf": (_from_hopf, ["osc", "hopf", "stop", "offset"]),
    "classify": (_ring_classify, ["run"]),
    "contact_frames": (_frames, ["body", "group", "surface", "tolerance"]),
    "ContactProblem": (_contact_problem, ["system", "frames", "friction", "static_friction", "clamped"]),
})
CASES = [(name, param) for name, (_, params) in CALLS.items() for param in params]
#: The model whose declarations the parameters of a call read (default: the shared ones).
DOMAIN = {**{n: "oscillator" for n in ("Oscillator", "Coulomb", "Stribeck", "simulate", "limit_cycle", "hopf_points",
                                       "continue_cycle", "UserLaw", "continue_from_hopf")},
          **{n: "brake" for n in ("BrakeParams", "FemScheme", "RingScheme", "PhysicalParams", "steady_sliding",
                                  "growth_rates", "travelling_wave", "continue_waves", "perturbed_steady", "integrate",
                                  "integrate_fem", "annulus_frequencies", "fem perturbed_steady", "classify")},
          **{n: "halfspace" for n in ("inverse_problem", "direct_problem", "StickSlipWave", "inverse_map",
                                      "direct_map", "fields")},
          **{n: "fem" for n in ("contact_frames", "ContactProblem")},
          **{n: "system" for n in ("System", "Contact", "system simulate", "system limit_cycle", "load_system",
                                   "system steady_sliding", "burridge_knopoff", "rate_state_simulate",
                                   "rate_state_steady")},
          **{n: "rsf" for n in ("RateState", "SpringSlider", "slide", "linear_stability", "slider_cycle",
                                "hopf_criticality")}}


@pytest.mark.parametrize("name, param", CASES, ids=[f"{n} {p}" for n, p in CASES])
def test_bad_values_give_a_parameter_error_or_a_result(name, param, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # a bad value such as "x" is a valid relative store path: keep it out of the tree
    each_bad_value(CALLS[name][0], param, name)


def each_bad_value(func, param: str, name: str) -> None:
    """``func(param=value)`` for each of `BAD`: a result, or a `ParameterError` / `NoSolutionError` that
    says something; any other exception fails, named."""
    for value in BAD:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)
                func(**{param: value})
        except (ParameterError, NoSolutionError) as err:
            assert str(err)
        except Exception as err:  # noqa: BLE001 - what the fuzz is for
            pytest.fail(f"{name}({param}={value!r}) raised {type(err).__name__}: {err}")
