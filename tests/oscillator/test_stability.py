import math

import numpy as np
import pytest

from stickslip.friction import Coulomb, LinearWeakening, Stribeck
from stickslip.oscillator import Oscillator, equilibrium_stability, hopf_points
from stickslip.oscillator.stability import damping_coefficients


def test_linear_law_is_negative_damping():
    """m x'' - f_d tau N x' + k x = f_d(1 - tau V) N: eigenvalues (f_d tau N ± sqrt(...))/(2m)."""
    m, k, N, fd, tau = 2.0, 3.0, 1.5, 0.4, 0.5
    osc = Oscillator(m, k, N, 0.2, LinearWeakening(0.5, fd, tau))
    st = equilibrium_stability(osc)
    assert st.x_e == pytest.approx(fd * (1 - tau * 0.2) * N / k)
    expected = np.roots([m, -fd * tau * N, k])
    assert np.allclose(np.sort_complex(st.eigenvalues), np.sort_complex(expected))
    assert st.kind == "unstable focus" and not st.stable


def test_coulomb_without_damping_is_a_centre():
    st = equilibrium_stability(Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.6, 0.4)))
    assert st.kind == "centre"


def test_hopf_point_of_the_linear_law_is_in_the_damping():
    osc = Oscillator(1.0, 1.0, 2.0, 0.2, LinearWeakening(0.5, 0.4, 0.5))
    points = hopf_points(osc, "damping", 0.0, 2.0)
    assert len(points) == 1 and points[0].value == pytest.approx(0.4 * 0.5 * 2.0, rel=1e-12)
    assert points[0].frequency == pytest.approx(1.0) and points[0].criticality == "degenerate"
    assert hopf_points(osc, "belt_speed", 0.01, 1.0) == []  # independent of V for the linear law


def test_stribeck_hopf_speed_and_criticality():
    N, c, fs, fd, vs = 1.0, 0.05, 0.6, 0.4, 0.1
    osc = Oscillator(1.0, 1.0, N, 0.2, Stribeck(fs, fd, vs), damping=c)
    (p,) = hopf_points(osc, "belt_speed", 0.01, 2.0)
    assert p.value == pytest.approx(vs * math.log(N * (fs - fd) / (c * vs)), rel=1e-12)
    at = osc.replace(belt_speed=p.value)
    d1, d3 = damping_coefficients(at)
    assert abs(d1) < 1e-12
    exact_d3 = -N * (fs - fd) / vs**3 * math.exp(-p.value / vs) / 6
    assert d3 == pytest.approx(exact_d3, rel=1e-5) and p.criticality == "subcritical"
    below, above = (equilibrium_stability(osc.replace(belt_speed=p.value * f)) for f in (0.9, 1.1))
    assert not below.stable and above.stable
