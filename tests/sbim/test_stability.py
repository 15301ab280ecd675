"""The explicit scheme's stability (`stickslip.sbim.stability`), against the recurrence's eigenvalues
computed here and against runs.

* The count of roots outside a circle by the argument principle equals the count of eigenvalues of the
  recurrence's companion matrix written here (antiplane and in-plane, free and held, radius 1 and 1.001).
* Runs under a random, rough load (every mode excited) stay bounded at the largest steps accepted:
  antiplane at beta = 0.6 and in-plane in contact at 0.3, over 3000 steps (the largest rate of the last
  500 steps at most that of the first 500). With the exact weights of a rate held over the step (the
  first increment's) the antiplane run grows at beta = 0.6: the test below shows it, as the reason for
  the scheme's weights.
* The in-plane memory faded over its window keeps a long free run stable where the same memory cut short
  grows (its recurrence's eigenvalues computed here).
* A free in-plane surface at nu = 0.4 is refused at beta = 0.3 (the instantaneous coupling 2 - c_p / c_s
  is negative there; its shortest modes grow), naming beta; at nu = 1/4 it is accepted.
"""

import math

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.sbim import (AntiplaneProblem, CoulombFriction, InplaneProblem, growing_roots, run_antiplane,
                            run_inplane)
from stickslip.sbim.inplane_kernels import hann_taper, inplane_kernels, static_stiffness, wave_speed_ratio
from stickslip.sbim.kernels import antiplane_kernel

MU, C, L = 3e10, 3000.0, 1000.0


def companion(a, M, kind, nu, held):
    """The map (u_n, q_{n-1}, ..., q_{n-M}) -> (u_{n+1}, q_n, ..., q_{n-M+1}) of one mode."""
    T = a * np.arange(1, M + 1)
    if kind == "antiplane":
        D, S0, H = np.eye(1), np.eye(1), antiplane_kernel(T)[:, None, None]
    else:
        h11, h22, h12 = inplane_kernels(T, nu) * hann_taper(np.arange(M), M)
        s11, s22, s12 = static_stiffness(nu)
        if held:
            D, S0, H = np.eye(1), np.array([[s11]]), h11[:, None, None]
        else:
            D = np.diag([1.0, wave_speed_ratio(nu)])
            S0 = np.array([[s11, -1j * s12], [1j * s12, s22]])
            H = np.array([[[x, -1j * z], [1j * z, y]] for x, y, z in zip(h11, h22, h12)])
    d = D.shape[0]
    Di = np.linalg.inv(D)
    A = np.zeros((d * (M + 1), d * (M + 1)), dtype=complex)
    q = np.hstack([-a * Di @ S0] + [a * Di @ H[i] for i in range(M)])  # q_n from u_n and the past q
    A[:d] = q + np.hstack([np.eye(d), np.zeros((d, d * M))])  # u_{n+1} = u_n + q_n
    A[d:2 * d] = q
    A[2 * d:, d:d * M] = np.eye(d * (M - 1))
    return A


@pytest.mark.parametrize("kind, nu, held", [("antiplane", None, False), ("inplane", 0.25, False),
                                            ("inplane", 0.25, True), ("inplane", 0.4, False)])
def test_the_roots_counted_on_the_circle_are_the_companion_matrixs_eigenvalues(kind, nu, held):
    for beta in (0.05, 0.3, 0.45, 0.7):
        for M in (6, 40):
            a = math.pi * beta
            moduli = np.abs(np.linalg.eigvals(companion(a, M, kind, nu, held)))
            for radius in (1.0, 1.001):
                expected = int((moduli > radius).sum())
                assert growing_roots(a, M, kind, nu, held, radius) == expected, (beta, M, radius)


def rough(N, seed):
    rng = np.random.default_rng(seed)
    values = rng.normal(size=(2, N)) * 1e6
    return lambda x, t: values[:, np.rint(x / (L / N)).astype(int) % N]


def test_rough_loads_stay_bounded_at_the_largest_steps_accepted():
    load = rough(64, 1)
    anti = run_antiplane(AntiplaneProblem(MU, C, L, 64, lambda x, t: load(x, t)[0], beta=0.6), 3000)
    rates = np.abs(anti.slip_rate).max(axis=1)
    assert rates[-500:].max() <= rates[:500].max()
    contact = run_inplane(InplaneProblem(MU, C, 0.25, L, 64, lambda x, t: (load(x, t)[0], load(x, t)[1] - 5e6),
                                         CoulombFriction(0.3, 0.3), beta=0.3), 3000)
    rates = np.abs(contact.slip_rate).max(axis=1) + np.abs(contact.opening_rate).max(axis=1)
    assert rates[-500:].max() <= rates[:500].max()


def test_the_exact_weights_of_a_rate_held_over_the_step_grow_where_the_schemes_do_not():
    """Why the scheme takes each step's slip at its end: the recurrence of the shortest mode with the
    exact weights ``int H`` over each step, written here, has a root outside the unit circle at beta = 0.6
    (and already at 0.2); the scheme's (`growing_roots`) has none."""
    from stickslip.sbim.kernels import antiplane_kernel_integral

    for beta in (0.2, 0.6):
        a = math.pi * beta
        M = int(math.ceil(4 * 2 * math.pi / a))
        A = companion(a, M, "antiplane", None, False)
        j = np.arange(M)
        exact = antiplane_kernel_integral(a * (j + 1)) - antiplane_kernel_integral(a * j)  # int H over each step
        A[:2, 1:] = exact[None, :]  # a (int H over the step) / a
        assert np.abs(np.linalg.eigvals(A)).max() > 1.001
        assert growing_roots(a, M) == 0


def test_a_free_surface_above_a_third_in_poisson_is_refused_naming_beta():
    load = rough(32, 2)
    with pytest.raises(ParameterError, match="beta") as info:
        run_inplane(InplaneProblem(MU, C, 0.4, L, 32, load, beta=0.3), 2000)
    assert "grow" in str(info.value) and "history_periods" in str(info.value)
    run_inplane(InplaneProblem(MU, C, 0.25, L, 32, load, beta=0.3), 2000)


def test_the_faded_memory_keeps_a_long_free_run_stable_where_a_cut_one_grows():
    """A free surface at nu = 1/4 with 8 periods of history over 4000 steps: accepted with the scheme's
    faded memory; the same memory cut short at its window (faded over a window 300 times longer)
    has a root outside the unit circle for the longest mode (the Rayleigh mode growing slowly; the count
    is the one checked against the companion matrix above)."""
    N = 128
    run = run_inplane(InplaneProblem(MU, C, 0.25, L, N, rough(N, 3), beta=0.3, history_periods=8), 4000, every=4000)
    assert np.all(np.isfinite(run.opening))
    a = 2 * math.pi * 0.3 / N
    M = int(math.ceil(8 * 2 * math.pi / a))
    assert growing_roots(a, M, "inplane", 0.25) == 0
    assert growing_roots(a, M, "inplane", 0.25, window_steps=1 << 20) > 0  # a window 300 times longer
