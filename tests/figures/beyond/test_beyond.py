"""The figures beyond the paper: their checks pass on the computed data and fail on data that
contradict the closed forms (each planted into the dataset)."""

import numpy as np
import pytest

from stickslip.figures.beyond import adams, flutter, regimes, rsf_slider, squeal


@pytest.fixture(scope="module")
def rsf_data():
    return rsf_slider.compute(quick=True)


@pytest.fixture(scope="module")
def squeal_data():
    return squeal.compute(quick=True)


def _failed(checks):
    return [c.name for c in checks if not c.passed]


def test_the_slider_checks_pass_and_catch_a_wrong_critical_stiffness(rsf_data):
    assert _failed(rsf_slider.check(rsf_data)) == []
    wrong = rsf_data.copy(deep=True)
    wrong["critical_stiffness"][-1] *= 1 + 1e-6  # one point off the closed form
    assert any("k_c" in name for name in _failed(rsf_slider.check(wrong)))
    stuck = rsf_data.copy(deep=True)
    stuck["friction"].loc[{"law": "aging"}] = np.minimum(stuck["friction"].sel(law="aging"), 0.6)  # no healing
    assert any("heals" in name for name in _failed(rsf_slider.check(stuck)))


def test_the_squeal_checks_pass_and_catch_a_wrong_threshold_or_an_open_orbit(squeal_data):
    assert _failed(squeal.check(squeal_data)) == []
    wrong = squeal_data.copy(deep=True)
    wrong["mu_critical"] = wrong["mu_critical"] * (1 + 1e-5)
    assert any("flutter" in name for name in _failed(squeal.check(wrong)))
    drift = squeal_data.copy(deep=True)
    drift["closing_error"] = drift["closing_error"] + 1e-6
    assert any("closes" in name for name in _failed(squeal.check(drift)))


@pytest.mark.slow
def test_the_flutter_checks_pass_and_catch_a_growth_off_the_relation_or_a_stalled_convergence():
    data = flutter.compute(quick=True)
    assert _failed(flutter.check(data)) == []
    wrong = data.copy(deep=True)
    wrong["growth"].loc[{"law": "Coulomb", "mode": 4}] *= 1.03  # one mode 3 % off the relation
    assert any("Coulomb sliding grows" in name for name in _failed(flutter.check(wrong)))
    stalled = data.copy(deep=True)
    stalled["difference"].loc[{"law": "Prakash-Clifton"}] = 1e-3  # the differences stop falling
    assert any("converges" in name for name in _failed(flutter.check(stalled)))


@pytest.mark.slow
def test_the_adams_checks_pass_and_catch_a_growth_off_the_relation_or_a_growing_identical_pair():
    data = adams.compute(quick=True)
    assert _failed(adams.check(data)) == []
    wrong = data.copy(deep=True)
    wrong["growth"] = wrong["growth"] * 1.02  # 2 % off the relation
    assert any("relation's rate" in name for name in _failed(adams.check(wrong)))
    grown = data.copy(deep=True)
    grown["identical_growth"] = grown["identical_growth"] * 0 + 0.01
    assert any("identical" in name for name in _failed(adams.check(grown)))


def test_a_growing_waves_slip_rate_and_normal_traction_are_in_the_ratio_the_regime_boundary_assumes():
    """The boundary s* of beyond.regimes rests on |dV| / |d sigma_yy| = |p| c_s / (mu |S12(p)|) for the
    growing wave in contact: the figure's s* at f = 2 (its fastest mode's k c_s t_r) measured on runs of that
    one mode from 4 periods to 6, at
    beta = 0.1 and 0.05 and extrapolated to dt -> 0 (first order). A first try, beta = 0.1 from 2 periods to
    3 against 3 %, was 4.1 % low (the load's own response not yet outgrown, and the step's error: 2.4 % and
    1.2 % at the two steps later on); the threshold below was set after that look."""
    import logging
    import math

    from stickslip.sbim import CoulombFriction, InplaneProblem, PrakashClifton, run_inplane

    f, s, n = 2.0, 0.3, 2
    expected, mode, _ = regimes.boundary(f)
    kappa = mode * regimes.KAPPA1
    v0 = regimes.CS * s * regimes.N0 / regimes.MU
    k = 2 * math.pi * n / regimes.L
    t_r = kappa / (k * regimes.CS)
    law = PrakashClifton(CoulombFriction(f, f), t_r * 2 * v0, v0)

    def load(x, t):
        return (f + s) * regimes.N0 + 1.0 * np.cos(k * x), np.full(x.shape, -regimes.N0)

    period = 2 * math.pi / (k * regimes.CS)
    quiet = logging.getLogger("stickslip.sbim")
    level = quiet.level
    ratios = []
    for beta in (0.1, 0.05):
        problem = InplaneProblem(regimes.MU, regimes.CS, regimes.NU, regimes.L, 8 * n, load, law, beta=beta)
        quiet.setLevel(logging.ERROR)  # restored after: a level left raised silences later tests' warnings
        try:
            run = run_inplane(problem, int(6 * period / problem.dt))
        finally:
            quiet.setLevel(level)
        V = np.abs(np.fft.rfft(run.slip_rate, axis=1)[:, n])
        S = np.abs(np.fft.rfft(run.normal_traction, axis=1)[:, n])
        late = run.t > 4 * period
        ratios.append(float(np.median(V[late] / S[late])) * regimes.MU / regimes.CS)
    assert abs(ratios[1] - expected) < 0.7 * abs(ratios[0] - expected)  # first order
    assert 2 * ratios[1] - ratios[0] == pytest.approx(expected, rel=0.005)


@pytest.mark.slow
def test_the_regime_checks_pass_and_catch_a_wrong_first_event_or_a_grid_dependent_outcome():
    data = regimes.compute(quick=True)
    assert _failed(regimes.check(data)) == []
    swapped = data.copy(deep=True)  # the run furthest below s* opens first
    swapped["first_opening"][0, 0] = swapped["first_stick"][0, 0] * 0.5
    assert any("which comes first" in name for name in _failed(regimes.check(swapped)))
    drifting = data.copy(deep=True)  # the finest grid's first stick 5 % later
    drifting["refined"][0, -1, 0] = drifting["refined"][0, -2, 0] * 1.05
    assert any("converge" in name for name in _failed(regimes.check(drifting)))
    converged = data.copy(deep=True)  # Coulomb's first events as converged as the regularised ones
    converged["coulomb"][-1] = converged["coulomb"][-2]
    assert any("Coulomb" in name for name in _failed(regimes.check(converged)))
    stayed = data.copy(deep=True)  # the shortest relaxation's run at s = 0.1 never left steady sliding
    stayed["reg_first_stick"][0, 0] = stayed["reg_first_opening"][0, 0] = np.nan
    assert any("regularised longer or shorter" in name for name in _failed(regimes.check(stayed)))
    late = data.copy(deep=True)  # it left twice as late
    late["reg_first_stick"][0, 0] *= 2
    late["reg_first_opening"][0, 0] *= 2
    assert any("e-foldings" in name for name in _failed(regimes.check(late)))
    other = data.copy(deep=True)  # its pattern a mode growing at half the fastest rate
    other["reg_mode_growth"][0, 0] = 0.5 * other["reg_growth"][0]
    assert any("pattern" in name for name in _failed(regimes.check(other)))


def test_a_long_relaxation_time_keeps_steady_sliding_and_a_short_one_leaves_it():
    """Prakash-Clifton's relaxation time sets the growth (1 / t_r at most): at k1 c_s t_r = 4 the relation
    grows the perturbation by e^0.29 over 10 L / c_s and the run stays in steady sliding; at 0.5, by e^14, and
    the run leaves it (a run regularised alike whatever t_r is asked fails one or the other)."""
    def left(kappa1):  # whether a node stuck or opened within 10 L / c_s
        stick, opening = regimes.events(2.0, 0.1, 64, 10.0, kappa1=kappa1)[:2]
        return bool(np.isfinite(stick) or np.isfinite(opening))

    assert not left(4.0) and left(0.5)


def test_a_run_that_sticks_and_never_opens_counts_as_stick_first():
    """Found by a review: NaN (never) compared as a time made such a run 'opening first'."""
    stick, opening = np.array([1.0, np.nan, 2.0, np.nan]), np.array([np.nan, 1.0, 1.0, np.nan])
    assert regimes.stick_first(stick, opening).tolist() == [True, False, False, False]


def test_the_wave_in_time_checks_pass_and_catch_a_converging_departure_or_an_interface_still_sliding():
    from stickslip.figures.beyond import wave_in_time

    data = wave_in_time.compute(quick=True)
    assert _failed(wave_in_time.check(data)) == []
    shrinking = data.copy(deep=True)  # the departure falling with the grid: the scheme's, not the continuum's
    shrinking["departure"][-1, -1] = 0.5 * float(shrinking.departure[0, -1])
    assert any("same amount" in name for name in _failed(wave_in_time.check(shrinking)))
    onset = data.copy(deep=True)  # half the departure's growth away from the healing edge
    onset["growth_near_healing"][0] = 0.5
    assert any("healing edge:" in name for name in _failed(wave_in_time.check(onset)))
    loose = data.copy(deep=True)  # no patch growing: as stuck at the end as at the start
    loose["stuck_in_rear"][:, -1] = loose.stuck_in_rear[:, 0]
    assert any("stuck patch" in name for name in _failed(wave_in_time.check(loose)))
    sliding = data.copy(deep=True)
    sliding["long_stuck"][-1] = 0.9
    assert any("sticks for good" in name for name in _failed(wave_in_time.check(sliding)))
    over = data.copy(deep=True)  # a stuck node beyond Coulomb's strength
    over["end_closeness"][3] = 1.2
    assert any("sticks for good" in name for name in _failed(wave_in_time.check(over)))
    flat = data.copy(deep=True)  # the first step not approaching the wave
    flat["departure"][-1, 0] = float(flat.departure[0, 0])
    assert any("starts on the wave" in name for name in _failed(wave_in_time.check(flat)))
