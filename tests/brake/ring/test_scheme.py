"""The explicit ring scheme: dispersion, CFL limit, energy, growth of the flutter, orders.

Closed forms used: the symbols of the centred differences, the amplification matrix of
the explicit Newmark scheme, and the growth rate ``s(n)`` of `stickslip.brake.reduced.flutter`.
"""

import numpy as np
import pytest

from stickslip.brake import BrakeParams, growth_rates
from stickslip.brake.ring import InitialCondition, RingScheme, integrate, perturbed_steady
from stickslip.errors import ParameterError

from ...contact.helpers import free_run

BASE = BrakeParams(xi=1.5, nu=0.3, gamma=1.0, delta=0.001, friction=0.7)  # coefficients of order 1


def start(scheme, ini, contact):
    """The scheme's state for the initial condition ``ini``."""
    return scheme.initial_state(scheme.dofs(ini.U, ini.V), scheme.dofs(ini.Ud, ini.Vd), contact)


def _steps(scheme, k, nsteps, contact=True):
    """Advance the state ``k`` by ``nsteps`` one at a time; returns ``(U_m, V_m)`` per step."""
    out = []
    for _ in range(nsteps):
        last = scheme.advance(k, 1, contact)
        out.append(np.array(scheme.fields(last.u_prev)))
    return np.array(out)


def _free_mode(scheme, k, branch):
    """Standing free eigenmode ``Re((x, y) e^{i k theta})`` of the discrete stiffness."""
    c = scheme.coefficients
    s2, s1 = scheme.symbols(k)
    K = np.array([[c.b * s2 + c.g, -1j * c.D * s1], [1j * c.D * s1, c.a * s2 + c.h]])
    w2, vec = np.linalg.eigh(K)
    e = np.exp(1j * k * scheme.theta)
    x, y = vec[:, branch]
    zero = np.zeros(scheme.nodes)
    return np.sqrt(w2[branch]), InitialCondition(np.real(x * e), np.real(y * e), zero, zero.copy())


@pytest.mark.parametrize("k, branch", [(1, 0), (3, 1), (10, 0), (20, 1)])
def test_kernel_reproduces_the_discrete_dispersion_relation(k, branch):
    """Free problem, one eigenmode: ``u_{m+1} + u_{m-1} = 2 cos(w_d dt) u_m`` with
    ``sin(w_d dt / 2) = w dt / 2`` and ``w^2`` from the centred-difference symbols."""
    scheme = RingScheme(BASE, 64, 0.5, 0.9)
    w, ini = _free_mode(scheme, k, branch)
    u = _steps(scheme, start(scheme, ini, False), 60, contact=False)
    j = np.argmax(np.abs(ini.V))
    ratio = (u[2:, 1, j] + u[:-2, 1, j]) / (2 * u[1:-1, 1, j])
    good = np.abs(u[1:-1, 1, j]) > 0.3 * np.abs(u[:, 1, j]).max()
    predicted = 1 - 2 * (w * scheme.dt / 2) ** 2  # cos(w_d dt)
    assert ratio[good] == pytest.approx(predicted, abs=1e-11)


def test_semi_discrete_dispersion_converges_at_second_order():
    k = np.array([1, 2, 4, 8])
    errors = []
    for N in (64, 128, 256, 512):
        s = RingScheme(BASE, N)
        errors.append(np.max(np.abs(s.frequencies(k) / s.frequencies(k, discrete=False) - 1)))
    order = np.log2(np.array(errors[:-1]) / errors[1:])
    assert order == pytest.approx(2.0, abs=0.05)
    # the discrete stiffness is positive definite (a symmetric K with a stable CFL limit)
    assert np.all(RingScheme(BASE, 64).frequencies(np.arange(33)) > 0)


@pytest.mark.parametrize("beta2", [0.5, 0.75, 1.0])
def test_stability_limit_is_the_cfl_condition(beta2):
    """Just below ``dt_max`` the free problem stays bounded; just above, it blows up."""
    scheme = RingScheme(BASE, 32, beta2, 1.0)
    assert scheme.step_factor(scheme.omega_max * 0.999) <= 1 + 1e-12
    rng = np.random.default_rng(1)
    grow = []
    for factor in (0.99, 1.02):
        u = free_run(scheme, rng.standard_normal(64), 2000, factor * scheme.dt_max)
        grow.append(np.abs(u).max() if np.all(np.isfinite(u)) else np.inf)
    assert grow[0] < 10 and grow[1] > 1e6


def test_free_problem_conserves_the_scheme_energy():
    """Central differences, friction off and no contact: ``|w|^2/2 + u_m K u_{m+1}/2`` is
    constant to round-off (white-noise initial state, all modes excited)."""
    ini = perturbed_steady(BASE, 64, amplitude=1.0, seed=3)
    run = integrate(BASE, 64, transits=20, initial=ini, contact=False, samples_per_transit=8)
    E = run.energy
    assert E.min() > 0 and np.ptp(E) / E.mean() < 1e-12
    assert np.all(run.fractions[:, 3] == 1.0)  # every node reported as separated (no contact)


@pytest.mark.parametrize("beta2", [0.6, 0.9])
def test_free_mode_decays_at_the_predicted_numerical_rate(beta2):
    """``beta2 > 1/2``: the energy of a free mode decays like ``rho^(2m)``, ``rho`` the
    spectral radius of the amplification matrix at ``w dt``."""
    scheme = RingScheme(BASE, 32, beta2, 0.9)
    w, ini = _free_mode(scheme, 6, 1)
    predicted = 2 * np.log(scheme.step_factor(w)) / scheme.dt
    run = integrate(BASE, 32, t_end=20.0 / abs(predicted), initial=ini, contact=False, beta2=beta2,
                    samples_per_transit=64)
    rate = np.polyfit(run.t, np.log(run.energy), 1)[0]
    assert rate == pytest.approx(predicted, rel=2e-2)
    assert predicted < -0.5  # strong numerical damping: not a test that cannot fail


def _measured_growth(params, N, n, beta2, amplitude=1e-6, efolds=12.0):
    scheme = RingScheme(params, N, beta2, 0.9)
    ini = perturbed_steady(params, N, amplitude=amplitude, mode=n)
    s_c = growth_rates(params, n).s[0]
    per_transit = int(np.ceil(8 * abs(s_c.imag) * scheme.transit_time / (2 * np.pi)))  # 8 samples per period
    run = integrate(params, N, t_end=efolds / s_c.real, initial=ini, beta2=beta2,
                    samples_per_transit=max(per_transit, 4))
    assert np.all(run.fractions[:, 1] == 1.0)  # linear regime: contact and forward slip everywhere
    amp, late = run.modes_V[:, n], run.t > run.t[-1] / 2
    rate = np.polyfit(run.t[late], np.log(np.abs(amp[late])), 1)[0]
    omega = np.polyfit(run.t[late], np.unwrap(np.angle(amp[late])), 1)[0]
    return rate + 1j * omega, scheme.growth_rates(n)[0], s_c


@pytest.mark.parametrize("beta2, order", [(0.5, 2), (0.9, 1)])
def test_flutter_grows_at_the_rate_of_linear_theory(beta2, order):
    """Mode 3 of steady sliding: the measured growth rate and frequency agree with the fully
    discrete prediction to 1e-5 and converge to ``s(n)`` of the continuous model as
    ``N`` doubles, at the scheme's order in ``dt ~ dtheta``."""
    errors = []
    for N in (32, 64, 128):
        measured, discrete, continuous = _measured_growth(BASE, N, 3, beta2)
        assert abs(measured - discrete) < 1e-5 * abs(discrete)
        errors.append(abs(measured.real - continuous.real) / continuous.real)
    observed = np.log2(errors[0] / errors[1]), np.log2(errors[1] / errors[2])
    assert observed[1] == pytest.approx(order, abs=0.25) and errors[0] > errors[1] > errors[2]
    if order == 2:
        assert errors[-1] < 2e-3


def test_growth_direction_follows_the_sign_of_D():
    thin = BrakeParams(xi=1.1, nu=0.4, gamma=1.0, delta=0.001, friction=0.7)  # D > 0
    for params in (BASE, thin):
        measured, _, continuous = _measured_growth(params, 64, 4, 0.5, amplitude=1e-8, efolds=8.0)
        assert np.sign(measured.imag) == np.sign(continuous.imag) != 0


@pytest.mark.parametrize("beta2", [0.5, 0.9])
def test_observed_order_in_time(beta2):
    """Fixed grid, linear flutter regime: halving ``dt`` three times, the self-convergence
    ratio of ``V`` at a fixed time gives the scheme's order (2 or 1)."""
    t_end, N = 1.0, 32
    finals = []
    for M in (200, 400, 800, 1600):
        probe = RingScheme(BASE, N, beta2, 1.0)
        scheme = RingScheme(BASE, N, beta2, t_end / (M * probe.dt_max))
        ini = perturbed_steady(BASE, N, amplitude=1e-3, mode=2, noise=1e-3)
        k = start(scheme, ini, True)
        assert np.all(scheme.advance(k, M).state == 1)
        finals.append(scheme.fields(k.u)[1].copy())
    e = [np.abs(finals[i] - finals[i + 1]).max() for i in range(3)]
    order = np.log2(e[1] / e[2])
    assert order == pytest.approx(RingScheme(BASE, N, beta2).order, abs=0.02)


@pytest.mark.parametrize("kwargs, name", [(dict(nodes=4), "nodes"), (dict(nodes=10.5), "nodes"),
                                          (dict(beta2=0.4), "beta2"), (dict(beta2=1.2), "beta2"),
                                          (dict(courant=0.0), "courant"), (dict(courant=1.5), "courant"),
                                          (dict(params="p"), "params")])
def test_scheme_rejects_bad_input(kwargs, name):
    with pytest.raises(ParameterError) as err:
        RingScheme(**(dict(params=BASE) | kwargs))
    assert err.value.name == name
