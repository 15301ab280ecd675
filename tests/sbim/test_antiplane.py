"""The spectral boundary integral method, antiplane (`stickslip.sbim`, issue 46's first increment), against
the equations of elastodynamics solved here, not by the code. Thresholds set before the runs.

* The kernel ``H(T) = int_T^inf J1(u)/u du`` against its definition integrated by quadrature (1e-10).
* One Fourier mode of the surface under a traction ``T0 cos(k x)`` applied at ``t = 0`` moves as
  ``W(t) = (c T0 / mu) int_0^t J0(omega u) du`` (the Laplace transform of the antiplane wave equation
  in the half-space: ``W(s) = c T0 / (mu s sqrt(s^2 + omega^2))``), integrated here by quadrature;
  the static limit ``T0 / (mu |k|)``. Over three periods, the error within 2 % of the static slip at
  beta = 0.05 and its observed order from beta = 0.2 to 0.05 in [1.7, 2.3]: the first threshold, [0.8,
  1.3], was set for the weights of a rate held over the step (first order, measured 1.0) and failed
  at 2.00 with the scheme's weights since issue 46's second increment (each step's slip at its end,
  stable to beta = 2/pi where the others were not): this smooth problem converges at second order with
  them, a measurement, not a property claimed for every run; the new range was set after seeing it.
* The radiation-damping limit: a uniform traction step slides the surface at ``V = c T0 / mu`` at
  once and for ever (1e-12); on a patch of half-width ``a`` the centre slides at that rate until the
  waves from the patch's edges arrive at ``t = a / c`` (1 % before ``0.8 a / c``).
* Coulomb: a stuck interface under a traction below its static strength does not move; above it, the
  whole interface slides at ``c (T0 - tau_d) / mu`` (1e-12).
"""

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.special import j0, j1

from stickslip.errors import ParameterError
from stickslip.sbim import (AntiplaneProblem, Coulomb, FreeSurface, SlipWeakening, antiplane_kernel, mode_traction,
                            run_antiplane, uniform_traction)

MU, C, L = 3e10, 3000.0, 1000.0  # a crustal rock, a 1 km period


def test_the_kernel_is_its_definition():
    for T in (0.0, 0.3, 2.0, 7.5, 30.0):
        expected = 1.0 - quad(lambda u: j1(u) / u, 0.0, T, limit=500)[0] if T else 1.0
        assert antiplane_kernel(T) == pytest.approx(expected, abs=1e-10)


def exact_mode(t, T0, k):
    """``(c T0 / mu) int_0^t J0(k c u) du`` by quadrature."""
    return np.array([C * T0 / MU * quad(lambda u: j0(k * C * u), 0.0, s, limit=500)[0] for s in t])


def test_one_mode_of_the_free_surface_follows_the_exact_step_response():
    T0, m, N = 1e6, 2, 32
    k = 2 * math.pi * m / L
    period = 2 * math.pi / (k * C)
    errors = []
    for beta in (0.2, 0.05):
        problem = AntiplaneProblem(MU, C, L, N, mode_traction(T0, m, L), FreeSurface(), beta=beta,
                                   history_periods=10.0)
        steps = int(round(3 * period / problem.dt))
        run = run_antiplane(problem, steps)
        W = 2.0 / N * (run.slip @ np.cos(k * problem.x))  # the mode's amplitude
        exact = exact_mode(run.t, T0, k)
        errors.append(np.abs(W - exact).max())
        assert np.abs(run.slip - np.outer(W, np.cos(k * problem.x))).max() <= 1e-9 * np.abs(W).max()  # one mode
    static = T0 / (MU * k)
    order = math.log(errors[0] / errors[1]) / math.log(4.0)
    assert errors[1] <= 0.02 * static, (errors, static)
    assert 1.7 <= order <= 2.3, (order, errors)


def test_a_uniform_traction_step_slides_the_surface_at_the_radiation_damping_rate():
    run = run_antiplane(AntiplaneProblem(MU, C, L, 16, uniform_traction(2e6)), 50)
    assert np.abs(run.slip_rate - C * 2e6 / MU).max() <= 1e-12 * C * 2e6 / MU
    assert np.abs(run.shear_stress).max() <= 1e-9 * 2e6  # free: the traction balanced by the radiation


def test_the_centre_of_a_loaded_patch_slides_at_the_radiation_rate_until_the_edges_are_heard():
    """The first run loaded a patch with sharp edges and failed the 1 % set before it (2.5 % at 0.8 a / c):
    the spectral representation of a sharp edge rings (Gibbs) ahead of its front. The patch's edges are
    now tapered over 20 m (10 elements; a raised cosine), the front at ``a - 10 m``: 1 % until 0.8 of its
    arrival, set before this second run."""
    N, a, T0, w = 512, 100.0, 2e6, 20.0
    r = lambda x: np.abs(x - L / 2)  # noqa: E731
    taper = lambda x, t: T0 * np.clip(0.5 + 0.5 * np.cos(np.pi * (r(x) - (a - w / 2)) / w), 0.0, 1.0) \
        * (r(x) < a + w / 2) + T0 * (r(x) <= a - w / 2) * 0.0  # noqa: E731
    problem = AntiplaneProblem(MU, C, L, N, lambda x, t: np.where(r(x) <= a - w / 2, T0, taper(x, t)), beta=0.25)
    run = run_antiplane(problem, int(1.5 * a / C / problem.dt))
    centre = run.slip_rate[:, N // 2]
    early = run.t < 0.8 * (a - w / 2) / C
    assert np.abs(centre[early] / (C * T0 / MU) - 1.0).max() <= 0.01
    assert np.abs(centre[run.t > 1.2 * a / C] / (C * T0 / MU) - 1.0).min() > 0.05  # and then it changes


def test_coulomb_sticks_below_its_static_strength_and_slides_above_at_the_kinetic_rate():
    stuck = run_antiplane(AntiplaneProblem(MU, C, L, 16, uniform_traction(5e6), Coulomb(6e6, 4e6)), 20)
    assert not stuck.slip.any() and np.allclose(stuck.shear_stress, 5e6)
    sliding = run_antiplane(AntiplaneProblem(MU, C, L, 16, uniform_traction(7e6), Coulomb(6e6, 4e6)), 20)
    assert np.abs(sliding.slip_rate - C * 3e6 / MU).max() <= 1e-12 * C * 3e6 / MU
    weakening = run_antiplane(AntiplaneProblem(MU, C, L, 16, uniform_traction(7e6), SlipWeakening(6e6, 4e6, 0.1)),
                              200)
    assert weakening.slip_rate[-1].min() == pytest.approx(C * 3e6 / MU, rel=1e-9)  # fully weakened
    assert weakening.slip_rate[1].max() < C * 1.1e6 / MU  # at first nearly at the static strength


def test_a_run_is_a_cf_dataset():
    ds = run_antiplane(AntiplaneProblem(MU, C, L, 16, uniform_traction(1e6)), 5).to_xarray()
    assert ds["slip_rate"].attrs["units"] == "m/s" and ds["shear_stress"].attrs["units"] == "Pa"
    assert ds["x"].attrs["units"] == "m" and ds.sizes["t"] == 6


@pytest.mark.parametrize("change, name", [
    (dict(beta=0.7), "beta"), (dict(beta=0.0), "beta"), (dict(elements=2), "elements"),
    (dict(shear_modulus=float("nan")), "shear_modulus"), (dict(length=-1.0), "length"),
    (dict(traction=3.0), "traction"), (dict(law="coulomb"), "law"), (dict(history_periods=0.0), "history_periods"),
])
def test_bad_input_is_refused_naming_it(change, name):
    args = dict(shear_modulus=MU, shear_wave_speed=C, length=L, elements=16, traction=uniform_traction(1e6))
    with pytest.raises(ParameterError, match=name) as info:
        AntiplaneProblem(**{**args, **change})
    if name == "beta" and change["beta"] > 0.6:
        assert "0.6366" in str(info.value) and "stable limit" in str(info.value)


def test_a_kinetic_strength_above_the_static_one_is_refused():
    with pytest.raises(ParameterError, match="kinetic_strength"):
        Coulomb(4e6, 6e6)


def test_the_ragged_history_convolves_as_a_dense_sum_written_here_compiled_or_not():
    """Each mode's memory ``sum_j W_j V_{s-1-j}`` over its own count of past steps, against the sum written
    out here over a dense array of the weights ``dt H(omega (j + 1) dt)`` (H by quadrature here); the
    compiled kernels give the interpreted ones' numbers bit for bit."""
    from stickslip.sbim.history import KERNELS, History
    from stickslip.sbim.kernels import ragged_step_weights

    rng = np.random.default_rng(0)
    omega, dt, counts, steps = np.array([0.0, 1.0, 2.0, 5.0]), 0.3, np.array([0, 7, 4, 2]), 12
    H = lambda T: 1.0 - quad(lambda u: j1(u) / u, 0.0, T, limit=500)[0]  # noqa: E731
    dense = np.array([[dt * H(w * dt * (j + 1)) if j < n and w > 0 else 0.0 for j in range(7)]
                      for w, n in zip(omega, counts)])
    flat = ragged_step_weights(omega, dt, counts)
    assert np.allclose(flat, np.concatenate([dense[m, :n] for m, n in enumerate(counts)]), rtol=1e-10, atol=1e-13)
    rates = rng.normal(size=(steps, 4)) + 1j * rng.normal(size=(steps, 4))
    runs = {}
    for name in ("interpreted", "compiled"):
        h = History(flat, counts, steps)
        h.kernels = getattr(KERNELS, name)
        got = []
        for s in range(steps):
            got.append(h.memory(s).copy())
            h.push(s, rates[s])
        runs[name] = np.array(got)
    for s in range(steps):
        expected = [sum(dense[m, j] * rates[s - 1 - j, m] for j in range(min(counts[m], s))) for m in range(4)]
        assert np.allclose(runs["interpreted"][s], expected, rtol=1e-14, atol=1e-14)
    assert np.array_equal(runs["interpreted"], runs["compiled"])


@pytest.mark.parametrize("traction", [lambda x, t: "a", lambda x, t: np.ones(3), lambda x, t: (x, x)])
def test_a_traction_giving_other_than_one_number_per_node_is_refused(traction):
    with pytest.raises(ParameterError, match="traction"):
        run_antiplane(AntiplaneProblem(MU, C, L, 16, traction), 5)


@pytest.mark.parametrize("law", ["slip-weakening", "rate-state"])
def test_a_killed_run_resumes_to_the_bit_and_another_runs_file_is_refused(tmp_path, law):
    """Killed right after a checkpoint, a run resumed from its file is the uninterrupted one to the last bit
    (samples, books, the stuck and sliding nodes, each mode's history, rate-and-state's state); a file kept
    under another run's key is refused naming ``checkpoint``."""
    from stickslip.rsf import RateState
    from stickslip.sbim import RateStateFriction
    from stickslip.sbim.antiplane import RUN_FORMAT, partial_antiplane
    from stickslip.sbim.runfile import Checkpoint

    from .resume import killed_and_resumed

    def problem():
        if law == "rate-state":
            friction = RateStateFriction(RateState(0.01, 0.015, 1e-3), 5e7, 1e-6, np.linspace(0, 0.3, 32))
            return AntiplaneProblem(MU, C, L, 32, uniform_traction(friction.steady_drive(MU / C)), friction)
        return AntiplaneProblem(MU, C, L, 32, mode_traction(7e6, 1, L), SlipWeakening(6e6, 4e6, 1e-4))

    whole, resumed = killed_and_resumed(problem, 90, 7, 41, tmp_path / "run.nc", antiplane=True)
    assert np.abs(whole.slip_rate).max() > 0 and resumed.t.size == whole.t.size
    for name in ("t", "slip", "slip_rate", "shear_stress", "load_work", "dissipation", "travel"):
        assert np.array_equal(getattr(resumed, name), getattr(whole, name)), name
    other = Checkpoint(tmp_path / "run.nc", "another", lambda s: partial_antiplane(problem(), s).to_xarray(),
                       run_format=RUN_FORMAT)
    with pytest.raises(ParameterError, match="checkpoint"):
        run_antiplane(problem(), 90, every=7, checkpoint=other)


def test_the_checkpoint_and_progress_hooks_are_checked():
    problem = AntiplaneProblem(MU, C, L, 16, uniform_traction(1e6))
    with pytest.raises(ParameterError, match="checkpoint"):
        run_antiplane(problem, 5, checkpoint="run.nc")
    with pytest.raises(ParameterError, match="progress"):
        run_antiplane(problem, 5, progress=3)
    seen = []
    run_antiplane(problem, 130, progress=lambda done, total: seen.append((done, total)))
    assert seen == [(0, 130), (64, 130), (128, 130)]


def test_a_checkpoint_of_another_kind_or_of_other_steps_is_refused_naming_it(tmp_path):
    """A Checkpoint left at the in-plane default run_format, or one resumed for other steps under the same key,
    is refused in one ParameterError naming ``checkpoint`` (not a numpy or netCDF error)."""
    from stickslip.sbim.antiplane import RUN_FORMAT, partial_antiplane
    from stickslip.sbim.runfile import Checkpoint

    problem = AntiplaneProblem(MU, C, L, 16, mode_traction(7e6, 1, L), Coulomb(6e6, 4e6))
    fields = lambda state: partial_antiplane(problem, state).to_xarray()  # noqa: E731
    with pytest.raises(ParameterError, match="checkpoint") as info:
        run_antiplane(problem, 20, checkpoint=Checkpoint(tmp_path / "a.nc", "k", fields))
    assert "stickslip.sbim.antiplane.RUN_FORMAT" in str(info.value)
    run_antiplane(problem, 20, every=5, checkpoint=Checkpoint(tmp_path / "b.nc", "k", fields, run_format=RUN_FORMAT))
    for steps, every in ((10, 5), (20, 4)):
        with pytest.raises(ParameterError, match="checkpoint"):
            run_antiplane(problem, steps, every=every,
                          checkpoint=Checkpoint(tmp_path / "b.nc", "k", fields, run_format=RUN_FORMAT))
    again = run_antiplane(problem, 20, every=5, checkpoint=Checkpoint(tmp_path / "b.nc", "k", fields,
                                                                       run_format=RUN_FORMAT))
    assert again.t.size == 5
