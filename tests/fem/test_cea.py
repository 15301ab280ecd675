"""Complex eigenvalue analysis on a general mesh against the annulus' Fourier-block analysis
(`stickslip.brake.fem.fem_growth_rates`, an independent method on the same discrete
problem): every mode found is one of its modes to 1e-8, and every one of its modes in the
band is found, with or without Rayleigh damping (then against the damped blocks built here)."""

import numpy as np
import pytest
from scipy.linalg import eigvals

from stickslip.brake.fem import FemScheme, fem_growth_rates
from stickslip.errors import ParameterError
from stickslip.fem.cea import complex_eigenvalues

from .test_scheme import PARAMS, general_annulus


def _reference(fem):
    """The annulus' modes as the general analysis reports them: one per conjugate pair, Im s >= 0."""
    s = fem_growth_rates(PARAMS, fem.system, modes=range(0, fem.n_theta // 2 + 1)).s.ravel()
    both = np.concatenate([np.abs(s.real) + 1j * np.abs(s.imag), -np.abs(s.real) + 1j * np.abs(s.imag)])
    out = []
    for z in both:
        if not any(abs(z - x) <= 1e-9 * abs(z) for x in out):
            out.append(z)
    return np.array(out)


def test_cea_on_the_annulus_finds_exactly_the_fourier_block_modes():
    fem = FemScheme(PARAMS, 32, 2, 0.9)
    ref = _reference(fem)
    f_ref = np.sort(ref.imag / (2 * np.pi))
    band = (0.0, 0.5 * (f_ref[14] + f_ref[15]))  # the band's edge between two modes
    res = complex_eigenvalues(general_annulus(fem).params, band, count=8)
    assert len(res.shifts) >= 2  # the band needs several shifts
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
    material = Material(1.0, PARAMS.nu, PARAMS.gamma, alpha=0.02 * w1, beta=0.02 / w1)
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
    res = complex_eigenvalues(general.params, (0.0, hi), count=30, mode_shapes=True)
    assert res.complete_below > s_ref.real and res.s[0].real == pytest.approx(s_ref.real, rel=1e-8)
    from stickslip.fem.cea import linearised

    _, _, _, keep = linearised(general.params)
    tangential = np.searchsorted(keep, general.contact_dofs[1])  # the contact nodes' hoop dofs among the kept
    along = res.shapes[tangential, 0]
    spectrum = np.fft.fft(along)
    peak = int(np.argmax(np.abs(spectrum)))
    wavenumber = peak if peak <= fem.n_theta // 2 else peak - fem.n_theta
    assert abs(wavenumber) == n_ref and np.sign(wavenumber) == np.sign(s_ref.imag)
