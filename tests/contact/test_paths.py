"""The operator paths of the shared explicit kernel: the stencil of structured rings of
nodes (the fast path) and the sparse matrix (the general path, any mesh: in 2 x 2 blocks, or
in CSR) must give the same run, and the ring's stencil must be the centred differences of [12]."""

import numpy as np
import pytest
import scipy.sparse as sp

from stickslip.contact.kernel import block2_apply, csr_apply

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


def _csr(s):
    """``s`` with its sparse path in CSR (`csr_apply`) instead of 2 x 2 blocks."""
    assert s.kernel_operator[3] == 2  # both models pair their dofs by node
    A = s.sparse_operator
    s.__dict__["kernel_operator"] = (A.indptr, A.indices, A.data, 1)  # the cached property's slot
    return s


def _both_paths(s, start, chunks, steps, contact=True):
    """The largest difference of the sparse paths (blocks, then CSR) from the stencil's run."""
    runs, seen = [], np.zeros(4)
    for sparse in (False, True, "csr"):
        k = start.copy()
        if sparse == "csr":
            _csr(s)
        for _ in range(chunks):
            seen += np.bincount(s.advance(k, steps, contact, sparse=bool(sparse)).state, minlength=4)
        runs.append(k.u)
    return max(np.abs(runs[0] - r).max() for r in runs[1:]) / np.abs(runs[0]).max(), seen


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


def _paired(rng, nodes):
    """A random sparse matrix of ``2 nodes`` rows whose entries come in 2 x 2 node blocks."""
    blocks = sp.random(nodes, nodes, density=0.2, random_state=rng, format="coo")
    return sp.kron(blocks, rng.standard_normal((2, 2)) + 3.0, format="csr")


def test_the_sparse_forms_apply_minus_the_matrix():
    """`block2_apply` and `csr_apply` against scipy's product, each with its own layout of the
    matrix (scipy's block sparse rows), on random matrices; blocks are kept for 2-D meshes and
    declined where the dofs do not pair up by node."""
    rng = np.random.default_rng(7)
    A = _paired(rng, 40)
    u = rng.standard_normal(80)
    want = -(A @ u)
    B = A.tobsr(blocksize=(2, 2))
    out = np.empty(80)
    block2_apply(B.indptr.astype(np.int64), B.indices.astype(np.int64), B.data.reshape(-1), u, out)
    assert np.abs(out - want).max() <= 1e-13 * np.abs(want).max()
    csr_apply(A.indptr.astype(np.int64), A.indices.astype(np.int64), A.data, u, out)
    assert np.abs(out - want).max() <= 1e-13 * np.abs(want).max()

    s = FemScheme(BrakeParams.from_physical(50.0, 1e-5, 0.7), 32, 2)
    assert s.kernel_operator[3] == 2
    u = rng.standard_normal(s.sparse_operator.shape[0])
    want = -(s.sparse_operator @ u)
    assert np.abs(s.apply(u, sparse=True) - want).max() <= 1e-13 * np.abs(want).max()
    # the matrix of the same mesh with its dofs shifted by one: its node blocks straddle the pairs
    shift = np.roll(np.arange(u.size), 1)
    s.__dict__["sparse_operator"] = s.sparse_operator[shift][:, shift].tocsr()  # the cached properties' slots
    del s.__dict__["kernel_operator"]
    assert s.kernel_operator[3] == 1
    assert np.abs(s.apply(u[shift], sparse=True) - want[shift]).max() <= 1e-13 * np.abs(want).max()
