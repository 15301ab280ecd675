"""Steady sliding [11], [16] against a sympy Lamé solution."""

import json

import numpy as np
import pytest
import sympy as sp

from .derivations import delta, f, lame_steady, nu, r, xi
from stickslip.brake import BrakeParams, coefficients, steady_sliding
from stickslip.errors import ParameterError

CASES = [(1.5, 0.3, 0.001, 0.7), (1.1, 0.0, 0.004, 0.2), (3.0, 0.45, 0.01, 2.0), (2.0, 0.25, 0.002, 0.0)]


def _num(expr, **values):
    names = (xi, nu, delta, f, r)
    return float(sp.lambdify(names, expr, "math")(*(values[s.name] for s in names)))


@pytest.mark.parametrize("x, n, d, fr", CASES)
def test_steady_state_is_the_lame_solution(x, n, d, fr):
    u, v, stress = lame_steady()
    st = steady_sliding(x, n, d, fr)
    vals = dict(xi=x, nu=n, delta=d, f=fr)
    assert st.p_e == pytest.approx(-_num(stress["s_rr"], **vals, r=1.0), rel=1e-12)
    assert st.q_e == pytest.approx(-_num(stress["s_rt"], **vals, r=1.0), rel=1e-12, abs=1e-300)
    assert st.V_e == pytest.approx(_num(v, **vals, r=1.0), rel=1e-12, abs=1e-300)
    assert st.U_e == d
    for rr in np.linspace(1.0, x, 7):
        assert float(st.u(rr)) == pytest.approx(_num(u, **vals, r=rr), rel=1e-12, abs=1e-15)
        assert float(st.v(rr)) == pytest.approx(_num(v, **vals, r=rr), rel=1e-12, abs=1e-15)
        s_rr, s_tt, s_rt, _ = st.stress(rr)
        for got, key in ((s_rr, "s_rr"), (s_tt, "s_tt"), (s_rt, "s_rt")):
            assert float(got) == pytest.approx(_num(stress[key], **vals, r=rr), rel=1e-11, abs=1e-15), key


def test_lame_solution_has_the_shape_X_of_the_reduced_model():
    u, v, _ = lame_steady()
    X = (xi**2 / r - r) / (xi**2 - 1)
    assert sp.simplify(u / X) == delta
    assert sp.simplify(sp.diff(v / X, r)) == 0  # v_e is X(r) times a constant too


def test_contact_pressure_is_positive_and_printed_eq11_has_the_wrong_sign():
    """Printed: p_e = delta/(1 - xi^2) (xi^2 + 1/(1-2nu))/(1+nu) (mu read as nu): exactly -p_e."""
    for x in (1.01, 1.5, 4.0):
        for n in (0.0, 0.3, 0.49):
            st = steady_sliding(x, n, 0.003, 0.5)
            printed = 0.003 / (1 - x**2) / (1 + n) * (x**2 + 1 / (1 - 2 * n))
            assert st.p_e > 0 and st.q_e > 0 and st.V_e > 0
            assert printed == pytest.approx(-st.p_e, rel=1e-13)
            printed_v = 0.003 * 0.5 * (1 + 1 / (x**2 * (1 - 2 * n)))  # v_e(1) of [11], mu read as nu
            assert printed_v == pytest.approx(st.V_e, rel=1e-13)


@pytest.mark.parametrize("x, n, d, fr", CASES)
def test_reduced_steady_state_eq16_agrees_with_lame(x, n, d, fr):
    """[16]: U_e = delta, V_e = delta f g/h, P_e = g delta, Q_e = f P_e; p_e = M P_e."""
    g = 0.37
    st = steady_sliding(x, n, d, fr, gamma=g)
    c = coefficients(x, n, g)
    assert st.V_e == pytest.approx(d * fr * c.g / c.h, rel=1e-12, abs=1e-300)
    assert st.P_e == pytest.approx(c.g * d, rel=1e-14)
    assert st.Q_e == pytest.approx(fr * st.P_e, rel=1e-14)
    assert st.p_e == pytest.approx(c.modal_mass * st.P_e, rel=1e-12)  # same pressure, two scalings
    # the reduced equations [12] hold at the steady state: g U_e = P_e and h V_e = Q_e
    assert c.g * st.U_e == pytest.approx(st.P_e) and c.h * st.V_e == pytest.approx(st.Q_e, rel=1e-12, abs=1e-300)


def test_steady_outputs():
    st = BrakeParams(1.5, 0.3, 1e-6, 0.001, 0.7).steady()
    d = st.to_dict()
    assert {"p_e", "q_e", "U_e", "V_e", "P_e", "Q_e"} == set(d)
    json.dumps(d)
    assert set(steady_sliding(1.5, 0.3, 0.001, 0.7).to_dict()) == {"p_e", "q_e", "U_e", "V_e"}
    ds = st.to_xarray(11)
    assert ds["u"].values[0] == pytest.approx(0.001) and ds["u"].values[-1] == pytest.approx(0.0, abs=1e-18)
    assert ds["sigma_rr"].values[0] == pytest.approx(-st.p_e) and ds["sigma_rr"].attrs["scale"] == "E"
    assert ds["sigma_rth"].values[0] == pytest.approx(-st.q_e)


@pytest.mark.parametrize("kwargs, name", [(dict(xi=0.9), "xi"), (dict(nu=0.5), "nu"), (dict(delta=-1e-3), "delta"),
                                          (dict(friction=-0.1), "friction"), (dict(gamma=-1.0), "gamma")])
def test_steady_rejects_bad_parameters(kwargs, name):
    args = dict(xi=1.5, nu=0.3, delta=0.001, friction=0.5) | kwargs
    with pytest.raises(ParameterError, match=name):
        steady_sliding(**args)
