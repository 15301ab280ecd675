"""The first Lyapunov coefficient (`stickslip.rsf.hopf`): against the closed form of a planar vector
field (Guckenheimer & Holmes 1983, eq. 3.4.11), and the spring-slider's Hopf point against Ranjith &
Rice (1999): with the aging law and no inertia, slip at the critical stiffness is periodic for every
amplitude, so the coefficient vanishes."""

import numpy as np
import pytest

from stickslip.errors import NoSolutionError
from stickslip.rsf import RateState, SpringSlider
from stickslip.rsf.hopf import first_lyapunov_coefficient, hopf_criticality


def _planar(w, a0, fxy, fxx, gxy, gyy):
    """x' = -w y + f, y' = w x + g with f = a0 x r^2 + fxy x y + fxx x^2 / 2, g = a0 y r^2 + gxy x y + gyy y^2 / 2."""
    def field(u):
        x, y = u[0], u[1]
        r2 = x * x + y * y
        return np.array([-w * y + a0 * x * r2 + fxy * x * y + 0.5 * fxx * x * x,
                         w * x + a0 * y * r2 + gxy * x * y + 0.5 * gyy * y * y])
    return field


@pytest.mark.parametrize("w, a0, fxy, fxx, gxy, gyy", [(2.0, -0.3, 0.0, 0.0, 0.0, 0.0), (2.0, -0.3, 0.7, 0.6, 0.5, 0.4),
                                                        (0.5, 0.1, -1.2, 0.3, 0.8, -0.9)])
def test_the_coefficient_of_a_planar_field_is_its_closed_form(w, a0, fxy, fxx, gxy, gyy):
    """GH 3.4.11: a = (f_xxx + f_xyy + g_xxy + g_yyy)/16 + (f_xy (f_xx + f_yy) - g_xy (g_xx + g_yy) - f_xx g_xx
    + f_yy g_yy)/(16 w); with Kuznetsov's unit eigenvector (u = z q + conj(z q), |q| = 1) l1 = 2 a / w."""
    f_yy = g_xx = 0.0
    a = (6 * a0 + 2 * a0 + 2 * a0 + 6 * a0) / 16 + (fxy * (fxx + f_yy) - gxy * (g_xx + gyy) - fxx * g_xx
                                                    + f_yy * gyy) / (16 * w)
    l1, error, omega = first_lyapunov_coefficient(_planar(w, a0, fxy, fxx, gxy, gyy), [0.0, 0.0])
    assert omega == pytest.approx(w, rel=1e-14)
    assert l1 == pytest.approx(2 * a / w, rel=1e-8) and error < 1e-8


def test_the_quasi_static_aging_slider_is_degenerate_as_ranjith_and_rice_found():
    slider = SpringSlider(RateState(a=0.01, b=0.015, dc=1e-5), normal_stress=1e7, stiffness=1e9)
    hopf = hopf_criticality(slider, 1e-6)
    assert hopf.critical_stiffness == pytest.approx(1e7 * 0.005 / 1e-5, rel=1e-9)
    assert hopf.frequency == pytest.approx(1e-6 / 1e-5 * np.sqrt(0.5), rel=1e-9)
    assert hopf.criticality == "degenerate" and abs(hopf.l1) < 1e-6 * hopf.frequency


def test_a_slider_that_never_loses_stability_has_no_hopf_point():
    with pytest.raises(NoSolutionError, match="no Hopf point"):
        hopf_criticality(SpringSlider(RateState(a=0.015, b=0.01, dc=1e-5), normal_stress=1e7, stiffness=1e9), 1e-6)


def test_a_point_off_the_imaginary_axis_is_refused():
    with pytest.raises(NoSolutionError, match="imaginary axis"):
        first_lyapunov_coefficient(lambda u: np.array([-u[1] - 0.1 * u[0], u[0]]), [0.0, 0.0])


def test_a_cycle_tolerance_finer_than_the_integration_is_refused_before_any_work():
    # periods computed to rtol cannot agree to 1e-300: it ran its whole transient (3 min) to say so
    from stickslip.errors import ParameterError
    from stickslip.rsf import RateState, SpringSlider, slider_cycle

    slider = SpringSlider(RateState(a=0.01, b=0.015, dc=1e-5), normal_stress=1e7, stiffness=3e9, mass=1e9)
    with pytest.raises(ParameterError, match=r"tol = 1e-300: must be at least rtol = 1e-10"):
        slider_cycle(slider, 1e-6, tol=1e-300)
    with pytest.raises(ParameterError, match=r"tol = 1e-09: must be at least rtol = 1e-08"):
        slider_cycle(slider, 1e-6, tol=1e-9, rtol=1e-8)
