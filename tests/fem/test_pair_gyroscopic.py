"""A turning disc's transport terms in an explicit run of a pad on the disc (issue 24).

With ``gyroscopic = true`` the Eulerian disc of `stickslip.fem.pair_run` carries its transport
softening (in the stiffness) and its gyroscopic matrix (on the velocity ``v_{m-1}``, as the
Rayleigh damping). Checked against the exact solution of the linear equations of motion
``M u'' + G u' + (K - B) u = 0`` (contact off: both bodies vibrating freely; the matrices from
`PairProblem`, the solution by ``scipy.sparse.linalg.expm_multiply`` of the first-order system,
not by our scheme): at 3000 rad/s, from the static deflection of the disc under a uniform body
force, over 0.2 ms. The scheme converges to it at first order in the step (the explicit
velocity term, as the damping's); the gyroscopic terms move the solution by 28 %, some
60 times the scheme's error at the finest step; without them the scheme converges to the
other solution. First measured: errors 1.9e-2, 9.3e-3, 4.6e-3 at Courant 0.8, 0.4, 0.2
(orders 1.01, 1.00); the bounds (orders in [0.8, 1.3], the finest error below 1e-2 and below a
tenth of the effect) are what first order and a visible effect require, written after that
first measurement. A planted sign of the gyroscopic matrix fails it."""


import numpy as np
import pytest
import scipy.sparse as sp
from scipy.sparse.linalg import expm_multiply, spsolve

from stickslip.fem.config import load_config
from stickslip.fem.pair import PairProblem, Rotation
from stickslip.fem.pair_run import PairScheme

from .test_pair_config import pad_disc
from .test_transport import rigid_fields, transport_by_hand

OMEGA, T_END = 3000.0, 2e-4


@pytest.fixture(scope="module")
def base(tmp_path_factory):
    folder = pad_disc(tmp_path_factory.mktemp("gyro"), disc_size="0.006")
    return load_config(folder / "pad_disc.toml").problem()


def _problem(base, gyroscopic):
    return PairProblem(base.slave, base.slave_group, base.master, base.master_group, Rotation(OMEGA, (0.0, 0.0)),
                       0.5, base.clamped_slave, base.clamped_master, gyroscopic)


def _exact(problem, u0, damped):
    free = np.flatnonzero(~problem.fixed)
    K, m, n = problem.K[free][:, free], problem.mass[free], free.size
    C = problem.C[free][:, free] if damped else sp.csr_matrix((n, n))
    A = sp.bmat([[None, sp.identity(n)], [-sp.diags(1 / m) @ K, -sp.diags(1 / m) @ C]], format="csr")
    return expm_multiply(A, np.concatenate([u0, np.zeros(n)]), start=0.0, stop=T_END, num=2, endpoint=True)[-1][:n]


def test_the_turning_discs_transport_terms_in_a_run_converge_to_the_exact_motion(base):
    turning = _problem(base, True)
    free = np.flatnonzero(~turning.fixed)
    load = np.where((free >= turning.n_slave) & (free % 2 == 1), turning.mass[free], 0.0)  # g along y on the disc
    u0 = spsolve(turning.K[free][:, free].tocsc(), load)
    exact = _exact(turning, u0, True)
    effect = np.abs(_exact(turning, u0, False) - exact).max() / np.abs(exact).max()
    errors = []
    for courant in (0.8, 0.4, 0.2):
        steps = int(round(T_END / PairScheme(turning, 0.5, courant).dt))
        scheme = PairScheme(turning, 0.5, time_step=T_END / steps)
        full = np.zeros(turning.fixed.size)
        full[free] = u0
        w = (scheme.rotation.T @ full)[scheme.free]
        state = scheme.initial_state(w, np.zeros_like(w), contact=False)
        scheme.advance(state, steps, contact=False)
        errors.append(np.abs(scheme.cartesian(state.u)[free] - exact).max() / np.abs(exact).max())
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all((orders > 0.8) & (orders < 1.3)), (errors, orders)
    assert errors[-1] < 1e-2 and errors[-1] < 0.1 * effect, (errors, effect)


def test_the_turning_discs_stiffness_and_damping_carry_its_transport_terms_as_derived(base):
    """Issue 44: the pair's matrices with ``gyroscopic`` against a derivation written out, not
    against exact solutions of its own matrices: the turning disc (7200 kg/m^3, about the origin
    at 3000 rad/s) adds ``-B`` to the stiffness and ``+G`` to the damping (``M u'' + G u' +
    (K - B) u``) on its own dofs, nothing on the pad's. On the disc's rigid fields
    (`transport_by_hand`): ``r.(dK) r = e.(dK) e = -Omega^2 I``, ``e.(dC) r = -2 Omega I``,
    ``t.(dC) r = -Omega int rho (x - c)``, with ``I = int rho |x - c|^2`` summed over the
    disc's triangles by the edge-midpoint rule (exact for quadratics), written here."""
    turning, plain = _problem(base, True), _problem(base, False)
    disc = turning.master
    rho = disc.materials[next(iter(disc.materials))].density
    assert rho == 7200.0 and disc.body.cells.shape[1] == 3  # straight 3-node triangles
    I = m = 0.0
    first = np.zeros(2)
    for corners in disc.body.points[disc.body.cells]:
        (x1, y1), (x2, y2), (x3, y3) = corners
        area = 0.5 * abs((x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1))
        mids = 0.5 * (corners + np.roll(corners, -1, axis=0))
        I += rho * area / 3 * np.sum(mids**2)
        m += rho * area
        first += rho * area * corners.mean(axis=0)
    dK = (turning.K - plain.K).tocsr()
    dC = turning.C if plain.C is None else (turning.C - plain.C).tocsr()
    n = turning.n_slave
    assert abs(dK[:n]).max() == 0 and abs(dC[:n]).max() == 0 and abs(dK[:, :n]).max() == 0
    fields = {}
    for name, field in zip(("r", "e", "t_x", "t_y"), rigid_fields(disc.body.points, (0.0, 0.0))):
        fields[name] = np.concatenate([np.zeros(n), field])
    for (a, which, b), exact in transport_by_hand(OMEGA, I, m, first).items():
        M = {"G": dC, "B": -dK}[which]
        got = fields[a] @ (M @ fields[b])
        roundoff = 1e-12 * (np.abs(fields[a]) @ (abs(M) @ np.abs(fields[b])))
        assert got == pytest.approx(exact, rel=1e-10, abs=roundoff), (a, which, b)
