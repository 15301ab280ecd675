"""The closed-form slip flow against an independent integrator, in every damping regime."""


import numpy as np
import pytest
from scipy.integrate import solve_ivp

from stickslip.friction import Coulomb, LinearWeakening
from stickslip.oscillator import Mode, Oscillator
from stickslip.oscillator import kernel
from stickslip.oscillator.kernel import run_affine
from stickslip.oscillator.flows import AffineSlip, NumericSlip

# (damping, tau): undamped, damped, negatively damped, overdamped, critically damped, growing node
REGIMES = {"undamped": (0.0, 0.0), "damped": (0.3, 0.0), "negative": (0.0, 0.5), "overdamped": (3.0, 0.0),
           "critical": (2.0, 0.0), "growing-node": (0.0, 6.0)}


def _osc(damping, tau):
    return Oscillator(1.0, 1.0, 1.0, 0.2, LinearWeakening(0.5, 0.4, tau), damping)


@pytest.mark.parametrize("regime", REGIMES)
@pytest.mark.parametrize("mode", [Mode.SLIP_POS, Mode.SLIP_NEG])
def test_closed_form_matches_solve_ivp(regime, mode):
    osc = _osc(*REGIMES[regime])
    flow = AffineSlip(osc, mode)
    x0, v0 = 0.3, (-0.1 if mode == Mode.SLIP_POS else 0.9)  # stays on its side of v = V
    rhs = lambda t, y: [y[1], float(osc.acceleration(y[0], y[1], mode))]
    t = np.linspace(0.0, 0.4, 7)
    ref = solve_ivp(rhs, (0, t[-1]), [x0, v0], t_eval=t, method="DOP853", rtol=1e-13, atol=1e-15)
    x, v = flow._state(t, x0, v0)
    assert np.max(np.abs(x - ref.y[0])) < 1e-11
    assert np.max(np.abs(v - ref.y[1])) < 1e-11


@pytest.mark.parametrize("regime", REGIMES)
def test_jacobian_is_the_derivative_of_the_flow(regime):
    flow = AffineSlip(_osc(*REGIMES[regime]), Mode.SLIP_POS)
    t, h = 0.7, 1e-6
    jac = flow.jacobian(t)
    for j, (dx, dv) in enumerate(((h, 0), (0, h))):
        plus = np.array(flow._state(t, 0.3 + dx, -0.1 + dv))
        minus = np.array(flow._state(t, 0.3 - dx, -0.1 - dv))
        assert np.allclose((plus - minus) / (2 * h), jac[:, j], rtol=1e-7, atol=1e-9)


def test_near_critical_series_is_continuous():
    """sin(wt)/w and sinh(kt)/k are replaced by series near critical damping: no jump."""
    values = []
    for c in (2.0 - 1e-9, 2.0, 2.0 + 1e-9):
        flow = AffineSlip(_osc(c, 0.0), Mode.SLIP_POS)
        values.append(flow._state(np.array([1.5]), 0.3, -0.1))
    assert np.allclose(values[0], values[1], atol=1e-9) and np.allclose(values[1], values[2], atol=1e-9)


@pytest.mark.parametrize("regime", ["undamped", "damped", "negative", "overdamped"])
def test_crossing_time_agrees_with_dense_search(regime):
    osc = _osc(*REGIMES[regime])
    flow = AffineSlip(osc, Mode.SLIP_POS)
    t_max = 30.0
    t_hit, index = flow.first_crossing(0.5, osc.belt_speed, t_max, [(osc.belt_speed, 1)])
    t = np.linspace(1e-9, t_max, 600001)
    v = flow._state(t, 0.5, osc.belt_speed)[1]
    above = np.nonzero((v[1:] >= osc.belt_speed) & (v[:-1] < osc.belt_speed))[0]
    if above.size == 0:  # damped: the arc never comes back up to the belt speed
        assert index is None and t_hit == t_max
        return
    assert index == 0
    assert abs(t[above[0] + 1] - t_hit) <= 2 * (t[1] - t[0])
    assert flow._state(t_hit, 0.5, osc.belt_speed)[1] == pytest.approx(osc.belt_speed, abs=1e-15)


def test_departure_from_the_line_is_not_a_crossing():
    """A start exactly on v = V with zero acceleration (f_s = mu(0)) leaves tangentially."""
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.4, 0.4))
    x_hi = osc.stick_limits[1]
    for flow in (AffineSlip(osc, Mode.SLIP_POS), NumericSlip(osc, Mode.SLIP_POS)):
        t_hit, index = flow.first_crossing(x_hi, 0.2, 50.0, [(0.2, 1)])
        assert index == 0 and t_hit > 1.0  # a whole slip arc, not an immediate re-stick


def test_numeric_flow_finds_a_crossing_inside_one_step():
    """v overshoots the level by very little between two steps: the extremum split finds it."""
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.6, 0.4), damping=0.05)
    exact = AffineSlip(osc, Mode.SLIP_POS)
    numeric = NumericSlip(osc, Mode.SLIP_POS, rtol=1e-10)
    # choose a level just below the velocity maximum of the return arc
    t = np.linspace(0.0, 3.0, 200001)
    peak = exact._state(t, 0.3, 0.0)[1].max()
    level = peak - 1e-7
    t1, i1 = exact.first_crossing(0.3, 0.0, 20.0, [(level, 1)])
    t2, i2 = numeric.first_crossing(0.3, 0.0, 20.0, [(level, 1)])
    assert i1 == i2 == 0 and abs(t1 - t2) < 1e-6


def test_compiled_kernel_and_python_flow_agree():
    osc = _osc(0.1, 0.3)
    mu0, mu1 = osc.friction.affine
    p = np.array([osc.mass, osc.stiffness, osc.damping, osc.normal_force, osc.belt_speed, mu0, mu1, osc.friction.fs])
    modes, t, x, v, n, status = run_affine(p, -0.3, 0.0, 1, 1e6, 4, 0.0, False)
    flow = AffineSlip(osc, Mode.SLIP_POS)
    t_hit, _ = flow.first_crossing(-0.3, 0.0, 1e6, [(osc.belt_speed, 1)])
    assert modes[0] == 1 and t[1] == pytest.approx(t_hit, rel=1e-14)
    assert x[1] == pytest.approx(float(flow._state(t_hit, -0.3, 0.0)[0]), abs=1e-14)


@pytest.mark.parametrize("zeta", [50.0, 1e4, 1e8])
def test_strongly_overdamped_flow_stays_finite_and_exact(zeta):
    """Overdamped far past critical (damping ratio zeta), over many natural periods: cosh and
    sinh alone overflow there (issue 9: NaN from zeta = 50 on), the flow must not. Checked
    against the matrix exponential of the same linear system in 40-digit arithmetic
    (mpmath; scipy's double-precision expm itself loses digits on a matrix this stiff),
    the Jacobian against the same exponential."""
    import mpmath

    osc = Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.6, 0.4), 2.0 * zeta)
    flow = AffineSlip(osc, Mode.SLIP_POS)
    x0, v0 = 0.3, -0.1
    with mpmath.workdps(40):
        system = mpmath.matrix([[0, 1], [-flow.w02, 2 * flow.sigma]])  # (xi, v)' for xi = x - x_c
        for t in (1e-3 / zeta, 1.0, 100.0, 1e4):
            exact = mpmath.expm(system * t)
            ref = exact * mpmath.matrix([x0 - flow.x_c, v0])
            xi, v = kernel.state(flow.sigma, flow.w02, flow.om2, x0 - flow.x_c, v0, np.array([t]))
            assert np.isfinite([xi[0], v[0]]).all()
            assert abs(xi[0] - float(ref[0])) <= 1e-12 * abs(float(ref[0]))
            assert abs(v[0] - float(ref[1])) <= 1e-9 * abs(float(ref[1])) + 1e-15
            jac = np.array(exact.tolist(), dtype=float)
            assert np.allclose(flow.jacobian(t), jac, rtol=1e-9, atol=1e-15)
