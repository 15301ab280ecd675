"""Physical loading: [25], [26], T* and the way back to the remote stresses."""

import math

import pytest

from stickslip.errors import ParameterError
from stickslip.halfspace import (Material, driving_traction, loading_from_wave, remote_strain,
                                 stress_from_v_star, stresses_from_T, v_star_from_stress)

E, NU, RHO = 2.1e11, 0.3, 7850.0


def test_remote_strain_is_positive_under_compression():
    tau = -1e7
    eps = remote_strain(tau, E, NU)
    assert eps > 0
    assert eps == pytest.approx(-NU * (1 + NU) * tau / E, rel=1e-15)
    # plane strain = plane stress with E' = E/(1 - nu^2), nu' = nu/(1 - nu)
    Ep, nup = E / (1 - NU**2), NU / (1 - NU)
    assert eps == pytest.approx(remote_strain(tau, Ep, nup, plane="stress"), rel=1e-14)
    assert remote_strain(tau, E, NU, plane="stress") == pytest.approx(-NU * tau / E, rel=1e-15)


def test_v_star_26_in_physical_and_scaled_units():
    mat = Material(E, NU, RHO)
    tau, c = -2e7, -0.7 * mat.c2
    V_star = -c * remote_strain(tau, E, NU)              # [26]: V* = -c eps*_xx
    assert V_star > 0
    assert V_star == pytest.approx(c * NU * (1 + NU) * tau / E, rel=1e-14)
    vs = v_star_from_stress(-0.7, tau / mat.shear_modulus, NU)
    assert vs == pytest.approx(V_star / mat.c2, rel=1e-13)
    assert stress_from_v_star(-0.7, vs, NU) == pytest.approx(tau / mat.shear_modulus, rel=1e-13)


def test_driving_traction_and_back():
    mu, mu_star, tau = 0.5, 0.4, -3.0
    tau_xy = -mu_star * tau
    T = driving_traction(tau, tau_xy, mu)
    assert T == pytest.approx((mu - mu_star) * (-tau), rel=1e-15) and T > 0
    back = stresses_from_T(T, mu, mu_star)
    assert back == pytest.approx((tau, tau_xy), rel=1e-14)


def test_figure14_loading():
    L = loading_from_wave(-0.7, 1e-3, nu=NU, mu=0.5, mu_star=0.4)
    assert L.tau_yy == pytest.approx(2e-3 / (-0.7 * NU), rel=1e-14)
    assert L.T == pytest.approx(0.1 * 2e-3 / (0.7 * NU), rel=1e-14)
    assert L.tau_xy == pytest.approx(-0.4 * L.tau_yy) and L.tau_xy > 0
    assert v_star_from_stress(-0.7, L.tau_yy, NU) == pytest.approx(1e-3, rel=1e-14)
    assert math.isclose(L.to_dict()["T"], L.T)


@pytest.mark.parametrize("call, name", [
    (lambda: remote_strain(1.0, E, NU), "tau_yy"),
    (lambda: remote_strain(-1.0, -E, NU), "young"),
    (lambda: remote_strain(-1.0, E, NU, plane="shell"), "plane"),
    (lambda: stresses_from_T(1.0, 0.5, 0.5), "mu_star"),
    (lambda: stresses_from_T(1.0, 0.5, -0.1), "mu_star"),
    (lambda: stresses_from_T(0.0, 0.5, 0.1), "T"),
    (lambda: stress_from_v_star(-0.5, 1e-3, 0.0), "nu"),
    (lambda: stress_from_v_star(0.5, 1e-3, 0.3), "c"),
    (lambda: v_star_from_stress(-0.5, 1.0, 0.3), "tau_yy"),
    (lambda: loading_from_wave(-0.7, 1e-3, nu=0.3, mu=0.0, mu_star=0.0), "mu"),
])
def test_loading_rejects_bad_input(call, name):
    with pytest.raises(ParameterError) as err:
        call()
    assert err.value.name == name
