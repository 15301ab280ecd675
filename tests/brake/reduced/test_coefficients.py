"""Coefficients [13] of the reduced model against a sympy Galerkin projection."""

import json
import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import quad

from .derivations import galerkin, gamma, nu, xi
from stickslip.brake import coefficients, coupling, neutral_radius_ratio, shape_integrals
from stickslip.errors import ParameterError

POINTS = [(1.05, 0.0, 0.3), (1.5, 0.3, 1e-6), (2.0, 0.45, 2.0), (4.0, 0.25, 0.01), (10.0, 0.1, 1.0)]


def _num(expr, x, n, g):
    return float(sp.lambdify((xi, nu, gamma), expr, "math")(x, n, g))


def _printed_eq13(x, n, g):
    """Eq. [13] exactly as printed (ln = natural log)."""
    at, bt = (1 - n) / ((1 + n) * (1 - 2 * n)), 1 / (2 * (1 + n))
    L = math.log(x)
    A = -2 * x**2 * L / (x**2 - 1) + (1 + x**2) / 2
    B = x**4 * L / (x**2 - 1) + (1 - 3 * x**2) / 4
    C1 = 2 * x**2 * L / (x**2 - 1) - 1
    C2 = -2 * x**2 * L / (x**2 - 1) - 1 + 2 * x**2
    a, b = at * A / (g * B), bt * A / (g * B)
    return dict(a=a, b=b, g=(2 * at + 2 * (x**2 - 1) * bt) / (g * B), h=2 * x**2 * bt / (g * B),
                D=(a * C1 - b * C2) / A, A=A, B=B, C1=C1, C2=C2)


@pytest.mark.slow  # 9 s (the fast set's budget)
def test_galerkin_equations_have_the_structure_of_eq15():
    """U-equation: U'', V', U only; V-equation: V'', U', V only (not the printed [12])."""
    eqs, _ = galerkin()
    for name, absent in (("U", ("U'", "V", "V''")), ("V", ("V'", "U", "U''"))):
        for term in absent:
            assert sp.simplify(eqs[name][term]) == 0, (name, term)
    # the coupling is antisymmetric: the same D with opposite signs, as in [15]
    assert sp.simplify(eqs["U"]["V'"] + eqs["V"]["U'"]) == 0


@pytest.mark.parametrize("x, n, g", POINTS)
def test_code_and_printed_eq13_match_the_galerkin_projection(x, n, g):
    eqs, _ = galerkin()
    derived = {"b": -eqs["U"]["U''"], "D": -eqs["U"]["V'"], "g": eqs["U"]["U"],
               "a": -eqs["V"]["V''"], "h": eqs["V"]["V"]}
    code, printed = coefficients(x, n, g).to_dict(), _printed_eq13(x, n, g)
    for k, expr in derived.items():
        value = _num(expr, x, n, g)
        assert code[k] == pytest.approx(value, rel=1e-10, abs=1e-12 / g), k
        assert printed[k] == pytest.approx(value, rel=1e-10, abs=1e-12 / g), k
    for k in ("A", "B", "C1", "C2"):
        assert code[k] == pytest.approx(printed[k], rel=1e-12)


def test_printed_eq12_has_its_second_derivatives_swapped():
    """Printed [12]: U_tt - b V'' ... and V_tt - a U'' ...; the projection has b U'' and a V''."""
    eqs, _ = galerkin()
    x, n, g = 1.5, 0.3, 1.0
    c = coefficients(x, n, g)
    assert _num(eqs["U"]["V''"], x, n, g) == 0.0 and _num(eqs["V"]["U''"], x, n, g) == 0.0
    assert -_num(eqs["U"]["U''"], x, n, g) == pytest.approx(c.b, rel=1e-12)
    assert -_num(eqs["V"]["V''"], x, n, g) == pytest.approx(c.a, rel=1e-12)
    assert abs(c.a - c.b) > 0.5 * c.a  # a != b: the swap matters


def test_modal_mass_is_gamma_B_over_xi2_minus_1():
    _, M = galerkin()
    for x, n, g in POINTS:
        c = coefficients(x, n, g)
        assert _num(M, x, n, g) == pytest.approx(c.modal_mass, rel=1e-12)


@pytest.mark.parametrize("x", [1.01, 1.5, 3.0, 20.0])
def test_shape_integrals_are_the_galerkin_integrals(x):
    X = lambda r: (x**2 / r - r) / (x**2 - 1)  # noqa: E731
    I2 = quad(lambda r: X(r) ** 2 / r, 1, x, epsabs=0, epsrel=1e-13)[0]
    Ir = quad(lambda r: X(r) ** 2 * r, 1, x, epsabs=0, epsrel=1e-13)[0]
    k = x**2 - 1
    A, B, C1, C2 = shape_integrals(x)
    assert (A, B, C1, C2) == pytest.approx((k * I2, k * Ir, k * (0.5 - I2), k * (1.5 + I2)), rel=1e-9)


def test_A_B_C1_C2_are_positive_for_all_xi():
    x = 1.0 + np.logspace(-4, 3, 4000)
    for v in shape_integrals(x):
        assert np.all(v > 0)
    # near xi = 1 (e = xi^2 - 1 -> 0) the leading terms are positive: A ~ e^2/12, ...
    e = sp.symbols("e", positive=True)
    ell = (1 + e) * sp.log(1 + e) / e
    series = [sp.series(expr, e, 0, 3).removeO() for expr in
              (-ell + (2 + e) / 2, (1 + e) * ell / 2 + (1 - 3 * (1 + e)) / 4, ell - 1, -ell - 1 + 2 * (1 + e))]
    leading = [sp.Poly(s, e).terms()[-1] for s in series]  # lowest power first after reversal
    assert all(coef > 0 for _, coef in leading), leading


def test_neutral_radius_ratio_is_where_D_changes_sign():
    for n in (0.26, 0.3, 0.4, 0.49):
        x = neutral_radius_ratio(n)
        assert coupling(x, n) == pytest.approx(0.0, abs=1e-12)
        assert coupling(x * 0.99, n) > 0 > coupling(x * 1.01, n)
        assert coefficients(x * 1.01, n, 1.0).D < 0 < coefficients(x * 0.99, n, 1.0).D
    grid = 1.0 + np.logspace(-4, 3, 2000)
    for n in (0.0, 0.1, 0.25):
        assert neutral_radius_ratio(n) is None
        assert np.all(coupling(grid, n) < 0)
    # C2/C1 -> 3 as xi -> 1 and increases: D = 0 needs a~/b~ = 2(1-nu)/(1-2nu) > 3, nu > 1/4
    _, _, C1, C2 = shape_integrals(grid)
    assert np.all(np.diff(C2 / C1) > 0) and C2[0] / C1[0] == pytest.approx(3.0, rel=1e-3)
    assert neutral_radius_ratio(0.3) == pytest.approx(1.1821, abs=1e-4)


def test_coefficients_outputs_are_json_ready_with_units():
    c = coefficients(1.5, 0.3, 1e-3)
    d = c.to_dict()
    assert list(d) == ["a", "b", "g", "h", "D", "A", "B", "C1", "C2"]
    json.dumps(d)
    ds = c.to_xarray()
    assert all(ds[k].attrs["units"] == "1" for k in d) and float(ds["D"]) == d["D"]


@pytest.mark.parametrize("args, name", [((1.0, 0.3, 1.0), "xi"), ((0.5, 0.3, 1.0), "xi"),
                                        ((1.5, 0.5, 1.0), "nu"), ((1.5, -0.1, 1.0), "nu"),
                                        ((1.5, 0.3, 0.0), "gamma"), ((float("nan"), 0.3, 1.0), "xi"),
                                        ((1.5, 0.3, float("inf")), "gamma")])
def test_coefficients_reject_bad_parameters(args, name):
    with pytest.raises(ParameterError, match=name) as err:
        coefficients(*args)
    assert err.value.name == name
