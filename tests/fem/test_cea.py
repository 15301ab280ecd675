"""Complex eigenvalue analysis on a general mesh against the annulus' Fourier-block analysis
(`stickslip.brake.fem.fem_growth_rates`, an independent method on the same discrete
problem): every mode found is one of its modes to 1e-8, and every one of its modes in the
band is found, with or without Rayleigh damping (then against the damped blocks built here)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.linalg import eigvals

from stickslip.brake.fem import FemScheme, fem_growth_rates
from stickslip.errors import ParameterError
from stickslip.fem.cea import complex_eigenvalues, covered

from .test_scheme import PARAMS, general_annulus
from ..budget import examples


def _reference(fem):
    """The annulus' modes as the general analysis reports them: one per conjugate pair, Im s >= 0."""
    s = fem_growth_rates(PARAMS, fem.system, modes=range(0, fem.n_theta // 2 + 1)).s.ravel()
    both = np.concatenate([np.abs(s.real) + 1j * np.abs(s.imag), -np.abs(s.real) + 1j * np.abs(s.imag)])
    out = []
    for z in both:
        if not any(abs(z - x) <= 1e-9 * abs(z) for x in out):
            out.append(z)
    return np.array(out)


@pytest.mark.parametrize("count", [2, 8])
def test_cea_on_the_annulus_finds_exactly_the_fourier_block_modes(count):
    """With 2 eigenvalues per shift to start with, the sweep asks for more until its discs cover
    the strip asked for."""
    fem = FemScheme(PARAMS, 32, 2, 0.9)
    ref = _reference(fem)
    f_ref = np.sort(ref.imag / (2 * np.pi))
    band = (0.0, 0.5 * (f_ref[14] + f_ref[15]))  # the band's edge between two modes
    res = complex_eigenvalues(general_annulus(fem).params, band, count=count)
    assert len(res.shifts) >= 2 and res.complete  # the band needs several shifts
    assert res.asked_below == pytest.approx(0.1 * 2 * np.pi * band[1], rel=1e-12)
    for z in res.s:
        assert np.min(np.abs(ref - z)) <= 1e-8 * abs(z)
    expected = ref[ref.imag / (2 * np.pi) <= band[1]]
    sure = expected[np.abs(expected.real) < res.complete_below]  # the modes the sweep promises to find
    assert len(sure) >= 10 and all(np.min(np.abs(res.s - z)) <= 1e-8 * abs(z) for z in sure)
    assert np.all(np.diff(res.growth_rate) <= 0) and res.unstable.sum() >= np.sum(sure.real > 0) > 0
    assert res.to_dict()["modes"][0]["growth_rate"] == pytest.approx(res.s.real.max(), rel=1e-12)


def test_a_bad_band_is_refused():
    fem = FemScheme(PARAMS, 32, 2, 0.9)
    for band in ((100.0, 50.0), (-1.0, 10.0), "wide"):
        with pytest.raises(ParameterError) as err:
            complex_eigenvalues(general_annulus(fem).params, band)
        assert err.value.name == "band"


def test_cea_with_rayleigh_damping_matches_a_dense_solution_of_the_quadratic_problem():
    """With damping the pencil has twice the size; a dense QZ of the same linearised operators
    (`linearised`, checked above without damping) is the reference."""
    from stickslip.fem import Material, assemble
    from stickslip.fem.cea import linearised
    from stickslip.fem.scheme import ContactProblem

    fem = FemScheme(PARAMS, 32, 2, 0.9)
    base = general_annulus(fem).params
    w1 = 2 * np.pi * 400.0
    material = Material(1.0, PARAMS.nu, PARAMS.gamma, alpha=0.02 * w1, beta=0.02 / w1, scaled=True)
    problem = ContactProblem(assemble(base.system.body, material), base.frames, base.friction, base.clamped)
    K, C, m, _ = linearised(problem)
    n = K.shape[0]
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-K.toarray(), -C.toarray()]])
    B = np.block([[np.eye(n), np.zeros((n, n))], [np.zeros((n, n)), np.diag(m)]])
    dense = eigvals(A, B)
    dense = dense[dense.imag >= 0]
    band = (300.0, 700.0)
    res = complex_eigenvalues(problem, band, count=8, mode_shapes=True)
    for z, w in zip(res.s, res.shapes.T):  # each shape solves (s^2 M + s C + K) w = 0
        residual = z**2 * (m * w) + z * (C @ w) + K @ w
        assert np.linalg.norm(residual) <= 1e-8 * abs(z) ** 2 * np.linalg.norm(m * w)
    expected = dense[(dense.imag / (2 * np.pi) >= band[0]) & (dense.imag / (2 * np.pi) <= band[1])]
    assert len(res.s) == len(expected) > 4
    for z in res.s:
        assert np.min(np.abs(expected - z)) <= 1e-8 * abs(z)
    undamped = complex_eigenvalues(base, band, count=8)
    assert np.max(res.growth_rate) < np.max(undamped.growth_rate)  # damping lowers the growth


def test_the_most_unstable_mode_travels_the_way_the_fourier_analysis_says():
    """The sets of growth rates cannot tell the friction's direction (a mirror image of the
    annulus has the same spectrum); the travelling direction of the unstable mode can: its
    shape along the bore is ``e^{i n theta}`` with the sign of ``Im s`` of the Fourier block."""
    fem = FemScheme(PARAMS, 32, 2, 0.9)
    general = general_annulus(fem)
    blocks = fem_growth_rates(PARAMS, fem.system, modes=range(1, fem.n_theta // 2))
    n_idx, b_idx = np.unravel_index(np.argmax(blocks.s.real), blocks.s.shape)
    s_ref, n_ref = blocks.s[n_idx, b_idx], int(blocks.n[n_idx])
    hi = abs(s_ref.imag) / (2 * np.pi) * 1.05
    res = complex_eigenvalues(general.params, (0.0, hi), count=30, mode_shapes=True,
                              complete_below=1.2 * s_ref.real)
    assert res.complete_below > s_ref.real and res.s[0].real == pytest.approx(s_ref.real, rel=1e-8)
    from stickslip.fem.cea import linearised

    _, _, _, keep = linearised(general.params)
    tangential = np.searchsorted(keep, general.contact_dofs[1])  # the contact nodes' hoop dofs among the kept
    along = res.shapes[tangential, 0]
    spectrum = np.fft.fft(along)
    peak = int(np.argmax(np.abs(spectrum)))
    wavenumber = peak if peak <= fem.n_theta // 2 else peak - fem.n_theta
    assert abs(wavenumber) == n_ref and np.sign(wavenumber) == np.sign(s_ref.imag)


def _envelope_minimum(centres, radii, lo, hi, points=200001):
    """The lowest point over ``[2 pi lo, 2 pi hi]`` of the upper envelope of the discs, sampled."""
    w = np.linspace(2 * np.pi * lo, 2 * np.pi * hi, points)
    h = np.sqrt(np.maximum(radii[:, None] ** 2 - (w[None, :] - centres[:, None]) ** 2, 0.0)).max(axis=0)
    return h.min()


@settings(max_examples=examples(200))
@given(st.lists(st.tuples(st.floats(0.01, 10.0), st.floats(0.1, 20.0)), min_size=1, max_size=6),
       st.floats(0.1, 1.0))
def test_the_covered_strip_is_never_wider_than_the_discs_cover(steps, end):
    """Discs along the axis (each a step past the previous, the first at the band's bottom): the
    strip reported lies under every point of the discs' envelope, sampled finely; for discs
    that overlap only with their neighbours it is the envelope's lowest point."""
    centres = np.cumsum([0.0] + [d for d, _ in steps[:-1]])
    radii = np.array([r for _, r in steps])
    hi = (centres[-1] + end * radii[-1]) / (2 * np.pi)
    got = covered(centres, radii, 0.0, hi)
    truth = _envelope_minimum(centres, radii, 0.0, hi)
    assert got <= truth + 1e-6 * radii.max()


def test_equal_discs_cover_the_height_where_they_cross():
    r, d = 5.0, 6.0
    centres = np.arange(4) * d
    hi = centres[-1] / (2 * np.pi)
    assert covered(centres, np.full(4, r), 0.0, hi) == pytest.approx(np.sqrt(r**2 - (d / 2) ** 2), rel=1e-12)
    assert covered(centres, np.full(4, r), 0.0, hi) == pytest.approx(_envelope_minimum(centres, np.full(4, r), 0.0, hi),
                                                                     rel=1e-6)
    assert covered(centres, np.array([r, r, 0.1, r]), 0.0, hi) == 0.0  # a gap between two discs


def test_a_sweep_held_to_few_eigenvalues_says_what_it_covered():
    """Held to 4 eigenvalues per shift, the sweep cannot cover the strip asked for: it says so,
    every reference mode inside the strip it reports is found, and some outside are not."""
    fem = FemScheme(PARAMS, 32, 2, 0.9)
    ref = _reference(fem)
    band = (0.0, 900.0)
    res = complex_eigenvalues(general_annulus(fem).params, band, count=4, max_count=4, complete_below=1e4)
    assert not res.complete and 0 < res.complete_below < 1e4
    in_band = ref[ref.imag / (2 * np.pi) <= band[1]]
    expected = in_band[np.abs(in_band.real) < res.complete_below]
    assert len(expected) >= 8 and all(np.min(np.abs(res.s - z)) <= 1e-8 * abs(z) for z in expected)
    assert len(res.s) < len(in_band)  # the strip is what it says: a sweep this small misses modes


def test_an_eigenvalue_search_that_fails_is_a_no_solution_error(monkeypatch):
    """ARPACK giving up (as it does where heavy damping crowds eigenvalues about a shift) is told
    as a NoSolutionError naming the shift, not an internal error."""
    import scipy.sparse.linalg as sla

    from stickslip.errors import NoSolutionError

    def give_up(*args, **kwargs):
        raise sla.ArpackError(3)

    fem = FemScheme(PARAMS, 32, 2, 0.9)
    problem = general_annulus(fem).params
    monkeypatch.setattr(sla, "eigs", give_up)
    with pytest.raises(NoSolutionError, match="did not converge near 0 Hz"):
        complex_eigenvalues(problem, (0.0, 100.0))
