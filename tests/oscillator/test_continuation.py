import math

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.friction import Coulomb, Stribeck
from stickslip.oscillator import Oscillator, continue_cycle, continue_from_hopf, hopf_points
from stickslip.oscillator.stability import damping_coefficients


def test_coulomb_branch_matches_closed_form():
    osc = Oscillator(1.0, 1.0, 1.0, 0.05, Coulomb(0.6, 0.4))
    branch = continue_cycle(osc, 1.0, step=0.05, max_step=0.2)
    v = branch.values
    assert v[0] == 0.05 and v[-1] == pytest.approx(1.0) and "reached" in branch.end_reason
    amp = np.hypot(0.2, v)
    assert np.max(np.abs([c.amplitude for c in branch.cycles] - amp)) < 1e-12
    period = 0.4 / v + 2 * math.pi - 2 * np.arctan(0.2 / v)
    assert np.max(np.abs([c.period for c in branch.cycles] - period)) < 1e-11


def test_damped_coulomb_branch_ends_where_the_return_arc_grazes():
    osc = Oscillator(1.0, 1.0, 1.0, 0.05, Coulomb(0.6, 0.4), damping=0.05)
    branch = continue_cycle(osc, 2.0, step=0.02, max_step=0.05)
    (event,) = [e for e in branch.events if e["kind"] == "grazing"]
    v_end = event["belt_speed"]
    # at the end the closed-form return arc from the stick exit peaks exactly at v = V
    from stickslip.oscillator.flows import AffineSlip
    from stickslip.oscillator.model import Mode

    for v_belt, sign in ((v_end * (1 - 1e-6), 1), (v_end * (1 + 1e-6), -1)):
        o = osc.replace(belt_speed=v_belt)
        t = np.linspace(3.0, 9.0, 600001)
        peak = AffineSlip(o, Mode.SLIP_POS)._state(t, o.stick_limits[1], v_belt)[1].max()
        assert np.sign(peak - v_belt) == sign


def test_small_cycles_near_hopf_follow_the_averaged_amplitude():
    """Observed convergence: |A / A_avg - 1| = O(V - V_H) (first order)."""
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, Stribeck(0.6, 0.4, 0.1), damping=0.05)
    (hopf,) = hopf_points(osc, "belt_speed", 0.01, 2.0)
    errors = []
    for offset in (4e-3, 2e-3, 1e-3):
        branch = continue_from_hopf(osc, hopf, 2.0, offset=offset, max_points=1)
        c = branch.cycles[0]
        d1, d3 = damping_coefficients(c.oscillator)
        errors.append(abs(c.amplitude / math.sqrt(-4 * d1 / (3 * d3)) - 1))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert errors[-1] < 5e-3 and np.all(np.abs(orders - 1) < 0.25)


@pytest.mark.slow
def test_stribeck_branches_meet_at_the_grazing_corner():
    osc = Oscillator(1.0, 1.0, 1.0, 0.05, Stribeck(0.6, 0.4, 0.1), damping=0.05)
    ss = continue_cycle(osc, 2.0, step=0.02, max_step=0.08)
    hopf = hopf_points(osc, "belt_speed", 0.01, 2.0)[0]
    slip = continue_from_hopf(osc, hopf, 2.0, step=0.02, max_step=0.08)
    g1 = [e["belt_speed"] for e in ss.events if e["kind"] == "grazing"]
    g2 = [e["belt_speed"] for e in slip.events if e["kind"] == "grazing"]
    assert g1 and g2 and g1[0] == pytest.approx(g2[0], rel=1e-7)
    assert all(c.touches_stick and c.stable for c in ss.cycles)
    assert not any(c.touches_stick or c.stable for c in slip.cycles)


def test_branch_dataset_and_validation():
    osc = Oscillator(1.0, 1.0, 1.0, 0.1, Coulomb(0.6, 0.4))
    ds = continue_cycle(osc, 0.3, step=0.1, max_step=0.3).to_xarray()
    assert ds["amplitude"].attrs["units"] == "m" and ds.attrs["continuation_parameter"] == "belt_speed"
    with pytest.raises(ParameterError, match="stop"):
        continue_cycle(osc, 0.1)
    with pytest.raises(ParameterError, match="parameter"):
        continue_cycle(osc, 0.3, parameter="colour")
