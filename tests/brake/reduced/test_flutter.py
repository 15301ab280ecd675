"""Flutter of steady sliding: closed-form s(n) against two independent numerical routes.

Both routes discretise the corrected reduced equations [12] on a theta-grid and replace
the unilateral contact by a stiff penalty ``P = kappa (delta - U)_+`` (so ``U = delta`` is
not imposed and no Fourier analysis is used): (1) eigenvalues and eigenvectors of the
linearised grid operator, (2) nonlinear time integration with Coulomb friction
``Q = f P sign(1 - V_t)`` from a perturbed steady state, measuring the growth rate and
the phase speed of the perturbation.
"""

import json

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from stickslip.brake import (BrakeParams, PhysicalParams, coefficients, growth_rate_limit, growth_rates,
                             most_unstable_mode, neutral_radius_ratio)
from stickslip.brake.reduced import grid_growth_rates
from stickslip.errors import ParameterError

BASE = BrakeParams(xi=1.5, nu=0.3, gamma=1.0, delta=0.001, friction=0.7)  # coefficients of order 1
THIN = BrakeParams(xi=1.1, nu=0.4, gamma=1.0, delta=0.001, friction=0.7)  # D > 0


def _spectral_derivatives(N):
    k = np.fft.fftfreq(N, 1.0 / N)
    eye = np.eye(N)
    d1 = np.real(np.fft.ifft(1j * k[:, None] * np.fft.fft(eye, axis=0), axis=0))
    d2 = np.real(np.fft.ifft(-(k**2)[:, None] * np.fft.fft(eye, axis=0), axis=0))
    return d1, d2


def _penalised_operator(params, N, kappa):
    c = coefficients(params.xi, params.nu, params.gamma)
    d1, d2 = _spectral_derivatives(N)
    eye, zero = np.eye(N), np.zeros((2 * N, 2 * N))
    K = np.block([[c.b * d2 - (c.g + kappa) * eye, c.D * d1],
                  [-c.D * d1 - params.friction * kappa * eye, c.a * d2 - c.h * eye]])
    return np.block([[zero, np.eye(2 * N)], [K, zero]])


@pytest.mark.parametrize("params", [BASE, THIN], ids=["D<0", "D>0"])
def test_growth_rates_match_the_penalised_grid_operator(params):
    N, modes = 15, np.arange(1, 7)
    s = growth_rates(params, modes).s
    theta = 2 * np.pi * np.arange(N) / N
    errors, g = [], params.coefficients().g
    for kappa in (1e3 * g, 1e5 * g):  # contact stiffness >> radial stiffness g
        lam, vec = np.linalg.eig(_penalised_operator(params, N, kappa))
        err = []
        for n, s_n in zip(modes, s):
            i = np.argmin(np.abs(lam - s_n))
            err.append(abs(lam[i] - s_n) / abs(s_n))
            v = vec[N:2 * N, i]  # V-part of the eigenvector: e^{+i n theta}, not e^{-i n theta}
            plus, minus = abs(np.exp(-1j * n * theta) @ v), abs(np.exp(1j * n * theta) @ v)
            assert plus > 100 * minus, (n, plus, minus)
        errors.append(max(err))
    assert errors[1] < 1e-5
    assert 30 < errors[0] / errors[1] < 300  # the penalty error is O(1/kappa)


def _integrate(params, n, t_end, N=16):
    c = coefficients(params.xi, params.nu, params.gamma)
    kappa = 1e3 * c.g
    d1, d2 = _spectral_derivatives(N)
    U_s = kappa * params.delta / (kappa + c.g)
    P_s = c.g * U_s
    V_s = params.friction * P_s / c.h
    theta = 2 * np.pi * np.arange(N) / N

    def rhs(t, y):
        U, V, Ut, Vt = y.reshape(4, N)
        P = kappa * np.maximum(params.delta - U, 0.0)
        Q = params.friction * P * np.sign(1.0 - Vt)
        return np.concatenate([Ut, Vt, c.b * d2 @ U + c.D * d1 @ V - c.g * U + P,
                               c.a * d2 @ V - c.D * d1 @ U - c.h * V + Q])

    y0 = np.concatenate([np.full(N, U_s), V_s + 1e-6 * V_s * np.cos(n * theta), np.zeros(2 * N)])
    t = np.linspace(0.0, t_end, 801)
    sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", t_eval=t, rtol=1e-10, atol=1e-16)
    assert sol.success
    V = sol.y[N:2 * N] - V_s
    P = kappa * np.maximum(params.delta - sol.y[:N], 0.0)
    assert np.all(P > 0) and np.all(np.abs(sol.y[3 * N:]) < 1)  # contact and forward slip throughout
    return t, np.exp(-1j * n * theta) @ V / N


@pytest.mark.parametrize("params, n", [(BASE, 3), (THIN, 2)], ids=["D<0", "D>0"])
def test_time_integration_grows_and_travels_as_predicted(params, n):
    s = growth_rates(params, n).s[0]
    t, amp = _integrate(params, n, 9.0 / s.real)
    late = t > t[-1] / 2
    rate = np.polyfit(t[late], np.log(np.abs(amp[late])), 1)[0]
    omega = np.polyfit(t[late], np.unwrap(np.angle(amp[late])), 1)[0]
    assert rate == pytest.approx(s.real, rel=5e-3)
    assert omega == pytest.approx(s.imag, rel=5e-3)  # phase speed -omega/n: direction of the wave


def test_growth_rate_increases_with_n_toward_its_limit():
    g = growth_rates(BASE, range(1, 201))
    lim = growth_rate_limit(BASE)
    assert np.all(np.diff(g.growth_rate) > 0) and np.all(g.growth_rate < lim)
    c = BASE.coefficients()
    assert lim == pytest.approx(BASE.friction * abs(c.D) / (2 * np.sqrt(c.a)))
    far = growth_rates(BASE, 10**6).growth_rate[0]
    assert far == pytest.approx(lim, rel=1e-9)
    assert most_unstable_mode(BASE, [3, 17, 5]).n == 17
    # small f D: Re s ~ n f |D| / (2 sqrt(a n^2 + h)) (first order in the circulatory term)
    small = BASE.replace(friction=1e-6)
    n = np.arange(1, 6)
    assert growth_rates(small, n).growth_rate == pytest.approx(
        n * 1e-6 * abs(c.D) / (2 * np.sqrt(c.a * n**2 + c.h)), rel=1e-9)


def test_no_flutter_without_friction_or_coupling():
    g = growth_rates(BASE.replace(friction=0.0), range(0, 8))
    c = BASE.coefficients()
    assert np.all(g.growth_rate == 0) and not g.unstable
    assert g.frequency == pytest.approx(np.sqrt(c.a * g.n**2 + c.h))
    x_star = neutral_radius_ratio(0.3)
    g = growth_rates(BASE.replace(xi=x_star), range(1, 8))
    assert np.all(np.abs(g.growth_rate) < 1e-9 * np.abs(g.frequency))


def test_scaling_with_gamma_and_shaft_speed():
    n = range(1, 9)
    s1, s2 = growth_rates(BASE, n).s, growth_rates(BASE.replace(gamma=1e-4), n).s
    assert s2 * np.sqrt(1e-4) == pytest.approx(s1, rel=1e-12)  # s sqrt(gamma) is gamma-free
    assert growth_rates(BASE.replace(delta=0.02), n).s == pytest.approx(s1, rel=1e-14)  # linear: delta-free
    rates = [growth_rates(PhysicalParams(om, 1e-4, 0.7).dimensionless(), n).to_xarray()["growth_rate_si"].values
             for om in (1.0, 50.0, 80.0)]
    assert rates[0] == pytest.approx(rates[1], rel=1e-10) and rates[2] == pytest.approx(rates[1], rel=1e-10)


def test_wave_direction_follows_the_sign_of_D():
    for params in (BASE, THIN):
        D = params.coefficients().D
        assert all(np.sign(m.wave_speed) == np.sign(D) for m in growth_rates(params, range(1, 6)).modes)


def test_outputs_follow_the_cli_contract():
    g = growth_rates(BrakeParams.from_physical(50.0, 1e-4, 0.7), [5, 1, 3, 3])
    d = json.loads(json.dumps(g.to_dict()))
    assert [m["n"] for m in d["modes"]] == [1, 3, 5]
    assert set(d["modes"][0]) == {"n", "growth_rate", "frequency"} and d["most_unstable"] == 5
    ds = g.to_xarray()
    assert ds["growth_rate"].attrs["units"] == "1" and ds["growth_rate_si"].attrs["units"] == "1/s"
    assert ds["growth_rate_si"].values == pytest.approx(50.0 * g.growth_rate)


@pytest.mark.parametrize("params, modes, name", [
    (BASE.replace(delta=0.0), [1], "delta"), (BASE, [], "modes"), (BASE, [-1], "modes"),
    (BASE, [1.5], "modes"), (BASE, "1-20", "modes"), (BASE, [True], "modes"), ("params", [1], "params")])
def test_stability_rejects_bad_input(params, modes, name):
    with pytest.raises(ParameterError) as err:
        growth_rates(params, modes)
    assert err.value.name == name


def test_grid_route_is_independent_of_the_closed_form():
    p = BrakeParams(2.0, 0.45, 3e-6, 0.002, 1.3)
    modes = [1, 2, 5]
    assert grid_growth_rates(p, modes, nodes=13) == pytest.approx(growth_rates(p, modes).growth_rate, rel=1e-4)


@pytest.mark.parametrize("kwargs, name", [(dict(nodes=12), "nodes"), (dict(nodes=9), "nodes"),
                                          (dict(penalty=0.0), "penalty"), (dict(modes=[]), "modes")])
def test_grid_route_rejects_bad_input(kwargs, name):
    args = dict(params=BrakeParams(1.5, 0.3, 1.0, 0.001, 0.5), modes=[1, 5], nodes=13) | kwargs
    with pytest.raises(ParameterError) as err:
        grid_growth_rates(**args)
    assert err.value.name == name
