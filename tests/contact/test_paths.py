"""The two operator paths of the shared explicit kernel: the stencil of structured rings of
nodes (the fast path) and the CSR matrix (the general path, any mesh) must give the same
run, and the ring's stencil must be the centred differences of [12]."""

import numpy as np
import pytest

from stickslip.brake import BrakeParams
from stickslip.brake.fem import FemScheme
from stickslip.brake.fem import perturbed_steady as fem_perturbed
from stickslip.brake.ring import RingScheme, perturbed_steady

PARAMS = BrakeParams(xi=1.5, nu=0.3, gamma=1.0, delta=0.03, friction=0.7)  # all four states occur


def _ring_state(scheme):
    ini = perturbed_steady(PARAMS, scheme.nodes, amplitude=1.0, mode=3, noise=0.1)
    return scheme.initial_state(scheme.dofs(ini.U, ini.V), scheme.dofs(ini.Ud, ini.Vd))


def test_ring_stencil_is_the_centred_differences_of_eq12():
    """``apply`` (stencil) and ``apply(sparse=True)`` against the numpy centred differences,
    written independently of the stencil."""
    s = RingScheme(PARAMS, 48)
    rng = np.random.default_rng(4)
    U, V = rng.standard_normal(48), rng.standard_normal(48)
    AU, AV = s.accelerations(U, V)
    for sparse in (False, True):
        got_U, got_V = s.fields(s.apply(s.dofs(U, V), sparse=sparse))
        assert np.abs(got_U - AU).max() < 1e-12 * np.abs(AU).max()
        assert np.abs(got_V - AV).max() < 1e-12 * np.abs(AV).max()


def _scheme(make, amplitude):
    if make == "ring":
        s = RingScheme(PARAMS, 64)
        ini = perturbed_steady(PARAMS, s.nodes, amplitude=amplitude, mode=3, noise=0.1 * amplitude)
        return s, s.initial_state(s.dofs(ini.U, ini.V), s.dofs(ini.Ud, ini.Vd))
    s = FemScheme(BrakeParams.from_physical(50.0, 1e-5, 0.7), 32, 2)
    ini = fem_perturbed(s, amplitude=amplitude, mode=2, noise=0.1 * amplitude)
    return s, s.initial_state(ini.u, ini.v)


def _both_paths(s, start, chunks, steps, contact=True):
    runs, seen = [], np.zeros(4)
    for sparse in (False, True):
        k = start.copy()
        for _ in range(chunks):
            seen += np.bincount(s.advance(k, steps, contact, sparse=sparse).state, minlength=4)
        runs.append(k.u)
    return np.abs(runs[0] - runs[1]).max() / np.abs(runs[0]).max(), seen


@pytest.mark.parametrize("make", ["ring", "fem"])
def test_stencil_and_sparse_paths_agree_over_ten_thousand_free_steps(make):
    """Contact off (a stable, conservative problem): 10^4 steps, the two paths agree to 1e-12
    relative; they differ only in the order of floating-point sums."""
    s, start = _scheme(make, 1.0)
    err, _ = _both_paths(s, start, 100, 100, contact=False)
    assert err <= 1e-12


@pytest.mark.parametrize("make", ["ring", "fem"])
def test_stencil_and_sparse_paths_agree_through_stick_and_separation(make):
    """With contact: stick, slip and separation within 400 steps, and the two paths agree to
    1e-12. (Not over 10^4 steps: steady sliding is unstable at every wavelength, so round-off
    differences grow; the saturated regime is chaotic.)"""
    s, start = _scheme(make, 0.5 if make == "ring" else 10.0)
    err, seen = _both_paths(s, start, 40, 10)
    assert err <= 1e-12 and np.count_nonzero(seen[[0, 1, 3]]) == 3
