"""Every result object has ``to_dict`` (JSON-ready), ``to_xarray`` (following the CF rules of
`cf_rules`), a short one-line repr naming its class and numbers, and an HTML table for
Jupyter (issue 10, library manners)."""

import json

import numpy as np
import pytest

from stickslip.brake import BrakeParams, continue_waves, growth_rates, travelling_wave, wave_persistence
from stickslip.brake.fem import assemble, annulus_mesh, classify_fem, fem_growth_rates, integrate_fem, steady_state
from stickslip.brake.ring import classify, integrate
from stickslip.friction import Coulomb, Stribeck
from stickslip.halfspace import Material, direct_problem, inverse_problem, loading_from_wave, wave_from_inverse
from stickslip.oscillator import (Oscillator, continue_cycle, equilibrium_stability, hopf_points, limit_cycle,
                                  simulate)
from stickslip.results import Result
from stickslip.rsf import RateState, SpringSlider, hopf_criticality
from stickslip.system import Contact, Harmonic, System, forced_response, rate_state_simulate, rate_state_steady

from .cf_rules import problems

CASE = BrakeParams.from_physical(50.0, 1e-4, 0.7)
_RSF_BLOCK = System(mass=[[1.0]], stiffness=[[4000.0]],
                    contacts=[Contact([1.0], 10.0, RateState(a=0.01, b=0.015, dc=1e-5), surface_speed=1e-6)])


@pytest.fixture(scope="module")
def results():
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.6, 0.4), damping=0.05)
    stribeck = Oscillator(1.0, 1.0, 1.0, 0.5, Stribeck(0.6, 0.4, 0.1), damping=0.05)
    wave = travelling_wave(CASE, 8)
    ring = integrate(CASE, 32, transits=2.0)
    fem = integrate_fem(CASE, 16, 1, transits=2.0)
    rates = growth_rates(CASE)
    field_wave = wave_from_inverse(11.358, -0.7, 0.001, nu=0.25, mu=0.5)
    return {
        "Trajectory": simulate(osc, 20.0), "LimitCycle": limit_cycle(osc), "Branch": continue_cycle(osc, 0.25),
        "EquilibriumStability": equilibrium_stability(stribeck),
        "HopfPoint": hopf_points(stribeck, "belt_speed", 0.01, 1.0)[0],
        "ReducedCoefficients": CASE.coefficients(), "SteadySliding": CASE.steady(), "GrowthRates": rates,
        "ModeGrowth": rates.modes[0], "TravellingWave": wave, "Zone": wave.zones[0],
        "WaveBranch": continue_waves(BrakeParams.from_physical(50.0, 1e-5, 0.7), 4, stop=9e-6 / 0.1, num=3),
        "WavePersistence": wave_persistence(wave, nodes=64, periods=2),
        "RingRun": ring, "RegimeResult": classify(ring, transits=1.0), "FemRun": fem,
        "FemRegime": classify_fem(fem, transits=1.0), "FemSteady": steady_state(CASE, n_theta=16, n_r=1),
        "FemGrowth": fem_growth_rates(CASE, assemble(annulus_mesh(16, 2, CASE.xi), CASE.nu), modes=[1, 2]),
        "InverseSolution": inverse_problem(np.array([2.0, 3.0]), np.array([-0.7, -0.7]), 0.001, nu=0.25, mu=0.5),
        "DirectSolution": direct_problem(9.52e-4, 3.514e-3, 0.001, nu=0.25, mu=0.5),
        "InterfaceFields": field_wave.fields(n=101), "StickSlipWave": field_wave,
        "Loading": loading_from_wave(-0.7, 0.001, nu=0.25, mu=0.5, mu_star=0.4),
        "Material": Material(2.1e11, 0.3, 7850.0),
        "RateStateRun": rate_state_simulate(_RSF_BLOCK, t_end=10.0, samples=11),
        "RateStateSteady": rate_state_steady(_RSF_BLOCK),
        "HopfCriticality": hopf_criticality(SpringSlider(RateState(a=0.01, b=0.015, dc=1e-5), normal_stress=1e7,
                                                         stiffness=1e9), 1e-6),
        "ForcedResponse": forced_response(System([[1.0]], [[1.0]], [Contact([1.0], 1.0, Coulomb(0.2, 0.2))],
                                                 damping=[[0.05]], harmonics=[Harmonic(0.6, [1.0])]), transient=30.0),
    }


NAMES = ["Trajectory", "LimitCycle", "Branch", "EquilibriumStability", "HopfPoint", "ReducedCoefficients",
         "SteadySliding", "GrowthRates", "ModeGrowth", "TravellingWave", "Zone", "WaveBranch", "WavePersistence",
         "RingRun", "RegimeResult", "FemRun", "FemRegime", "FemSteady", "FemGrowth", "InverseSolution",
         "DirectSolution", "InterfaceFields", "StickSlipWave", "Loading", "Material", "RateStateRun", "RateStateSteady",
         "HopfCriticality", "ForcedResponse"]


@pytest.mark.parametrize("name", NAMES)
def test_a_result_has_manners(name, results):
    result = results[name]
    assert isinstance(result, Result) and type(result).__name__ == name
    data = result.to_dict()
    json.dumps(data, default=lambda x: x.item() if hasattr(x, "item") else str(x))
    text = repr(result)
    assert text.startswith(f"{name}(") and "\n" not in text and len(text) < 400 and "array(" not in text, text
    page = result._repr_html_()
    assert page.startswith("<table>") and name in page and "<td>" in page
    ds = result.to_xarray(201) if name in ("Trajectory", "LimitCycle", "TravellingWave", "StickSlipWave") \
        else result.to_xarray()
    assert problems(ds, name) == []


def test_the_repr_shows_the_numbers_of_to_dict(results):
    cycle = results["LimitCycle"]
    assert f"period={cycle.period:.4g}" in repr(cycle)
    assert "<td>period</td>" in cycle._repr_html_() and "<td>s</td>" in cycle._repr_html_()
