"""Free vibrations: exact plane-strain annulus frequencies (Bessel), FE convergence, the reduced
model's one-term Galerkin frequencies, the Fourier-block reduction and the CFL limit."""

import numpy as np
import pytest
from scipy.linalg import eigh
from scipy.optimize import brentq
from scipy.special import jv, jvp, yv, yvp

from stickslip.brake import BrakeParams
from stickslip.brake.reduced.coefficients import elastic_moduli
from stickslip.brake.fem import (FemScheme, annulus_frequencies, annulus_mesh, assemble, fem_frequencies,
                                 fourier_block, max_frequency)
from stickslip.brake.ring import RingScheme
from stickslip.errors import ParameterError

from ...contact.helpers import free_run
from .helpers import orders

XI, NU = 1.5, 0.3
AT, BT = (float(x) for x in elastic_moduli(NU))


def _roots(fun, count, w_max=20.0):
    grid = np.linspace(0.05, w_max, 4000)
    d = np.array([fun(w) for w in grid])
    return np.array([brentq(fun, grid[k], grid[k + 1], xtol=1e-14) for k in
                     np.flatnonzero(np.sign(d[:-1]) * np.sign(d[1:]) < 0)][:count])


def test_axisymmetric_roots_match_the_two_by_two_closed_forms():
    """n = 0 splits: torsion ``u_theta = Z_1(k_s r)``, ``sigma_rtheta(1) ~ -k Z_2(k)``; breathing
    ``u_r = Z_1(k_p r)``, ``sigma_rr(1) = ã k Z_1'(k) + (ã - 2 b̃) Z_1(k)``; clamped at ``xi``."""
    def torsion(w):
        k = w / np.sqrt(BT)
        return jv(1, k * XI) * yv(2, k) - yv(1, k * XI) * jv(2, k)

    def breathing(w):
        k = w / np.sqrt(AT)
        s = [AT * k * d(1, k) + (AT - 2 * BT) * z(1, k) for z, d in ((jv, jvp), (yv, yvp))]
        return jv(1, k * XI) * s[1] - yv(1, k * XI) * s[0]

    expected = np.sort(np.concatenate([_roots(torsion, 3), _roots(breathing, 3)]))[:4]
    assert annulus_frequencies(XI, NU, 0, 4) == pytest.approx(expected, rel=1e-11)


def test_fem_frequencies_converge_to_bessel_roots_with_order_two():
    modes = range(0, 5)
    exact = np.array([annulus_frequencies(XI, NU, n, 2) for n in modes])
    grids = [32, 64, 128]
    err = [np.max(np.abs(fem_frequencies(assemble(annulus_mesh(N, N // 8), NU), modes, 2) - exact) / exact)
           for N in grids]
    o = orders([1.0 / N for N in grids], err)
    assert err[-1] < 3.5e-3 and np.all(np.abs(o - 2.0) < 0.1), (err, o)  # 4.6e-2, 1.2e-2, 3.0e-3


def test_reduced_model_frequencies_are_rayleigh_ritz_upper_bounds():
    """[12] is a Galerkin projection on ``X(r) (U, V) e^{i n theta}``: both of its frequencies of
    mode ``n`` bound the two lowest exact ones from above (by 11-33 % for n <= 8)."""
    ring = RingScheme(BrakeParams(XI, NU, 1.0, 1e-3, 0.0), 64)
    ratio = np.array([ring.frequencies(n, discrete=False) / annulus_frequencies(XI, NU, n, 2) for n in range(9)])
    assert np.all(ratio > 1.0) and np.all(ratio < 1.35), ratio
    assert ratio[:4, 0] == pytest.approx(1.17, abs=0.02)


def test_fourier_blocks_give_the_spectrum_of_the_full_matrix():
    s = assemble(annulus_mesh(32, 3), NU)
    full = np.sort(eigh(s.K.toarray(), np.diag(s.mass), eigvals_only=True))
    blocks = np.sort(fem_frequencies(s, range(0, 17)) ** 2, axis=None)
    blocks = np.sort(np.concatenate([blocks, np.sort(fem_frequencies(s, range(1, 16)) ** 2, axis=None)]))
    assert blocks == pytest.approx(full, rel=1e-12, abs=1e-12 * full.max())
    K3 = fourier_block(s, 3)
    assert np.abs(K3 - K3.conj().T).max() < 1e-15 * np.abs(K3).max()
    with pytest.raises(ParameterError):
        fem_frequencies(s, [17])


@pytest.mark.parametrize("beta2", [0.5, 0.75, 1.0])
def test_cfl_limit_of_the_free_problem(beta2):
    """Just below ``dt_max = sqrt(2/beta2)/omega_max`` the free problem stays bounded; above, it blows up."""
    s = FemScheme(BrakeParams(XI, NU, 1.0, 1e-3, 0.0), 32, 2, beta2, 1.0)
    assert s.omega_max == pytest.approx(max_frequency(s.system))
    rng = np.random.default_rng(2)
    grow = []
    for factor in (0.99, 1.02):
        u = free_run(s, rng.standard_normal(s.system.n_free), 3000, factor * s.dt_max)
        grow.append(np.abs(u).max() if np.all(np.isfinite(u)) else np.inf)
    assert grow[0] < 10 and grow[1] > 1e6


def test_transit_and_cfl_step_scale_with_the_mesh():
    p = BrakeParams.from_physical(50.0, 1e-4, 0.7)
    s1, s2 = FemScheme(p, 64, 4), FemScheme(p, 128, 8)
    assert s1.transit_time == pytest.approx(2 * np.pi * np.sqrt(p.gamma / AT))
    assert s2.steps_per_transit / s1.steps_per_transit == pytest.approx(2.0, rel=0.05)  # 2.07
    assert s1.p_wave_speed * 0.1 * 50.0 == pytest.approx(np.sqrt(2.1e11 * AT / 7850.0))  # c_p in m/s


def test_exact_frequencies_reject_bad_input():
    for kwargs, name in ((dict(n=-1), "n"), (dict(n=1.5), "n"), (dict(count=0), "count"),
                         (dict(w_max=2.0, count=3), "w_max"), (dict(xi=0.9), "xi")):
        with pytest.raises(ParameterError) as err:
            annulus_frequencies(**(dict(xi=XI, nu=NU, n=1) | kwargs))
        assert err.value.name == name


def test_mode_functions_reject_bad_input():
    s = assemble(annulus_mesh(16, 1), NU)
    for call in (lambda: fourier_block(s, 9), lambda: fourier_block("s", 1), lambda: max_frequency("s"),
                 lambda: fem_frequencies("s", [1]), lambda: fem_frequencies(s, [-1])):
        with pytest.raises(ParameterError):
            call()
    from stickslip.brake.fem.exact import characteristic_matrix
    for kwargs in (dict(w=0.0), dict(w=[1.0, np.nan]), dict(n=-2), dict(nu=0.5)):
        with pytest.raises(ParameterError):
            characteristic_matrix(**(dict(w=1.0, n=1, xi=XI, nu=NU) | kwargs))
    assert characteristic_matrix(np.array([1.0, 2.0]), 2, XI, NU).shape == (2, 4, 4)
