"""The discrete energy of the FE scheme without contact: conserved by central differences,
decaying at the rate of the amplification matrix with beta2 > 1/2.

With contact (the work of the reactions) see tests/contact/test_conditions.py."""

import numpy as np
import pytest

from stickslip.brake import BrakeParams
from stickslip.brake.fem import FemInitial, FemScheme, fourier_block, integrate_fem
from stickslip.contact import amplification_matrix

# order-one coefficients; kappa = delta / sqrt(gamma) = 0.03 is small enough for separation
PARAMS = BrakeParams(xi=1.5, nu=0.3, gamma=1.0, delta=0.03, friction=0.7)
MESH = (32, 2)


def test_free_problem_conserves_the_scheme_energy():
    """No contact, central differences: ``w^T M w/2 + u_m^T K u_{m+1}/2`` constant to round-off."""
    s = FemScheme(PARAMS, *MESH, 0.5)
    rng = np.random.default_rng(3)
    ini = FemInitial(rng.standard_normal(s.system.n_free), np.zeros(s.system.n_free), "noise")
    run = integrate_fem(PARAMS, *MESH, transits=20, initial=ini, beta2=0.5, contact=False, samples_per_transit=8)
    E = run.energy
    assert E.min() > 0 and np.abs(E / E[0] - 1).max() < 1e-12


@pytest.mark.parametrize("beta2", [0.6, 0.9])
def test_free_mode_decays_at_the_rate_of_the_amplification_matrix(beta2):
    """A free eigenmode (n = 3, lowest branch): energy ratio after M steps = ``|z|^{2M}`` (in log,
    to 1 %: the scheme energy of a damped scheme also oscillates within a period)."""
    s = FemScheme(PARAMS, *MESH, beta2)
    N, n_r = MESH
    m = s.system.mass[:: 2 * N].repeat(2)
    w2, vec = np.linalg.eigh(fourier_block(s.system, 3) / np.sqrt(np.outer(m, m)))
    shape = (vec[:, 0] / np.sqrt(m)).reshape(n_r, 2)
    field = np.real(shape[:, :, None] * np.exp(3j * s.theta))  # (n_r, comp, theta)
    ini = FemInitial(s.system.from_fields(field[:, 0], field[:, 1]), np.zeros(s.system.n_free), "mode 3")
    run = integrate_fem(PARAMS, *MESH, transits=5, initial=ini, beta2=beta2, contact=False, samples_per_transit=8)
    z = np.abs(np.linalg.eigvals(amplification_matrix(w2[0] / PARAMS.gamma * s.dt**2, beta2))).max()
    steps = (run.t[-1] - run.t[0]) / s.dt
    assert np.log(run.energy[-1] / run.energy[0]) == pytest.approx(2 * steps * np.log(z), rel=0.01)
    assert run.energy[-1] < 0.9 * run.energy[0]
