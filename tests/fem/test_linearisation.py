"""The CEA's linearised operators against finite differences of the nonlinear equations of
motion, written out here from the physics and not from the package's operators (issue 24).

About steady sliding, a contact node in contact is held on the surface (its displacement
along the normal ``n`` fixed) and slides along the surface's motion ``t``; every other free
dof moves. With ``r = K u + C u' - F`` (the assembled Cartesian stiffness, Rayleigh damping
and load) and the lumped nodal mass ``m``, the equations are, per free dof off the contact,
``m u'' + r = 0``, and per contact node in contact (coordinate ``a`` along ``t``):

    m a'' + t . r  =  mu(V - a') n . r,

the normal reaction ``n . r`` (the mass has no normal acceleration) times the friction law at
the slip speed (with a pressure-dependent law, times ``(P / P_ref)^(-n)`` at the node's pressure
``P = n . r / L``, ``L`` its tributary length: half of each adjacent edge, computed here). Their Jacobians in ``(z, z', z'')`` by central differences must equal the
``K_eff``, ``C_eff`` and mass of `stickslip.fem.cea.linearised` entry by entry: a wrong
damping row, a missing or wrong-signed slope term, or a friction row on the wrong dof fails.
Tolerances (set before the first run): 1e-7 of each matrix's largest entry.
"""

import numpy as np
import pytest
import scipy.sparse as sp

from stickslip.brake.fem import FemScheme
from stickslip.fem import (
    ContactProblem,
    Material,
    RigidFlat,
    assemble,
    contact_frames,
    read_body,
)
from stickslip.fem.cea import linearised
from stickslip.fem.config import load_config
from stickslip.fem.scheme import BodyScheme
from stickslip.friction import LinearWeakening, PressurePower, Stribeck

from .test_friction_law import block  # noqa: F401 - the block example, meshed (a fixture)
from .test_scheme import PARAMS, general_annulus


def _coordinates(problem):
    """The generalised coordinates: ``(dof, node, direction)``, ``u[node's pair] += z direction``.
    Off the contact a Cartesian dof (unit vector); a contact node in contact: one coordinate
    along ``t``; a contact node off the surface: two, along ``n`` and ``t``. Sorted as the
    node's dofs (normal or x first)."""
    system, frames, steady = problem.system, problem.frames, problem.steady
    fixed = np.zeros(system.n_dofs, bool)
    for name in problem.clamped:
        fixed[system.dofs(system.body.nodes(name, "clamped"))] = True
    line = {int(node): k for k, node in enumerate(frames.nodes)}
    out = []
    for node in range(len(system.body.points)):
        for comp in (0, 1):
            dof = 2 * node + comp
            if fixed[dof]:
                continue
            if node not in line:
                out.append((dof, node, np.eye(2)[comp]))
                continue
            k = line[node]
            if comp == 0 and steady.active[k]:
                continue  # held on the surface
            out.append((dof, node, (frames.normal, frames.tangent)[comp][k]))
    return out


def _equations(problem, consistent=False):
    """``R(z, zd, zdd)``: the equations of motion above, about steady sliding (with the
    consistent mass matrix, assembled here with scikit-fem, if ``consistent``)."""
    system, frames, steady = problem.system, problem.frames, problem.steady
    coords = _coordinates(problem)
    n_dofs = system.n_dofs
    rows, cols, vals = [], [], []
    for j, (_, node, direction) in enumerate(coords):
        rows += [2 * node, 2 * node + 1]
        cols += [j, j]
        vals += list(direction)
    P = sp.csr_matrix((vals, (rows, cols)), shape=(n_dofs, len(coords)))
    K = system.K
    C = sp.csr_matrix(K.shape) if system.C is None else system.C
    m = system.mass
    if consistent:
        from skfem import BilinearForm, asm
        from skfem.helpers import dot

        basis, order = system.basis
        rho = system.cell_values("density")[:, None] * np.ones(basis.X.shape[1])
        Mc = asm(BilinearForm(lambda u, v, w: w.rho * dot(u, v)), basis, rho=rho)[order][:, order].tocsr()
    u0 = steady.u
    held = {int(frames.nodes[k]): k for k in np.flatnonzero(steady.active)}
    law = problem.law
    speed = float(np.max(frames.speed))
    mu = (lambda v: law.kinetic(v)) if law is not None else (lambda v: problem.friction)
    share = np.zeros(len(system.body.points))  # each node's half of its adjacent contact edges
    for a, b in system.body.group(frames.group):
        half = 0.5 * np.hypot(*(system.body.points[a] - system.body.points[b]))
        share[a] += half
        share[b] += half
    power = problem.pressure_law
    g = (lambda P: 1.0) if power is None else (lambda P: (P / power.reference) ** -power.exponent)

    held_j = [j for j, (_, node, _) in enumerate(coords) if node in held]  # the coordinates along t
    held_k = [held[coords[j][1]] for j in held_j]
    held_pairs = [slice(2 * coords[j][1], 2 * coords[j][1] + 2) for j in held_j]

    def R(z, zd, zdd):
        u, v, acc = u0 + P @ z, P @ zd, P @ zdd
        r = K @ u + C @ v - system.load + (Mc @ acc if consistent else m * acc)  # inertia, internal minus load
        out = P.T @ r  # each coordinate's direction . its node's row (t . row for a held node)
        for j, k, pair in zip(held_j, held_k, held_pairs):
            n, t = frames.normal[k], frames.tangent[k]
            N = n @ r[pair]  # the normal reaction (inertia in it: consistent mass)
            out[j] -= mu(speed - t @ v[pair]) * g(N / share[coords[j][1]]) * N
        return out

    return R, coords


def test_steady_sliding_with_a_pressure_dependent_coefficient_solves_the_equations(block):  # noqa: F811
    """The residual of the equations above (with the test's own tributary lengths and power law) at
    the package's steady sliding: zero to 1e-9 of the load, where the pressures under the block
    differ from node to node by more than 5 % (so each node has its own coefficient)."""
    problem = _block(block, Stribeck(0.6, 0.4, 0.2), 0.0, 0.0, 0.0, 0.3, PressurePower(1e6, 0.3))
    R, _ = _equations(problem)
    load = np.abs(problem.system.load).max()
    assert np.abs(R(*[np.zeros(len(_coordinates(problem)))] * 3)).max() < 1e-9 * load
    st = problem.steady
    on = st.active
    assert np.ptp(st.pressure[on] / problem.tributary[on]) > 0.05 * np.mean(st.pressure[on] / problem.tributary[on])
    assert np.ptp(st.coefficients[on]) > 0.01 * np.mean(st.coefficients[on])


def _jacobians(problem, h_u, h_v, consistent=False):
    R, coords = _equations(problem, consistent)
    n = len(coords)
    zero = np.zeros(n)
    J = []
    for which, h in ((0, h_u), (1, h_v), (2, 1.0)):
        cols = []
        for j in range(n):
            e = np.zeros(n)
            e[j] = h
            args_p, args_m = [zero, zero, zero], [zero, zero, zero]
            args_p[which], args_m[which] = e, -e
            cols.append((R(*args_p) - R(*args_m)) / (2 * h))
        J.append(np.column_stack(cols))
    return J, coords


def _check(problem, h_u, h_v, consistent=False):
    (JK, JC, JM), coords = _jacobians(problem, h_u, h_v, consistent)
    K_eff, C_eff, mass, kept = linearised(problem, "consistent" if consistent else "lumped")
    mass = mass.toarray() if consistent else np.diag(mass)
    scheme = BodyScheme(problem)
    # the same coordinates in the same order as the package's kept dofs (of its nodal frames)
    assert np.array_equal(np.asarray(scheme.free)[kept], [dof for dof, _, _ in coords])
    C_eff = sp.csr_matrix(K_eff.shape) if C_eff is None else C_eff
    for mine, theirs, name in ((JK, K_eff.toarray(), "K"), (JC, C_eff.toarray(), "C"), (JM, mass, "M")):
        scale = np.abs(mine).max()
        assert scale > 0 and np.abs(mine - theirs).max() <= 1e-7 * scale, (name, np.abs(mine - theirs).max() / scale)
    return JC


def _block(folder, law, friction, alpha, beta, speed, pressure_law=None):
    cfg = load_config(folder / "block.toml")
    body = read_body(folder / "block.msh")
    system = assemble(body, Material(1e9, 0.3, 1000.0, alpha=alpha, beta=beta), cfg.springs, cfg.loads)
    surface = RigidFlat((0.0, 0.0), (0.0, 1.0), (speed, 0.0))
    return ContactProblem(system, contact_frames(body, "bottom", surface), friction, law=law, pressure_law=pressure_law)


@pytest.mark.parametrize("law, friction, pressure_law", [
    (None, 0.4, None), (Stribeck(0.6, 0.4, 0.2), 0.0, None), (LinearWeakening(0.5, 0.3, 0.1), 0.0, None),
    (Stribeck(0.6, 0.4, 0.2), 0.0, PressurePower(1e6, 0.3)), (None, 0.4, PressurePower(1e6, -0.2))],
    ids=["coulomb", "stribeck", "linear-weakening", "stribeck-pressure", "coulomb-pressure-rising"])
@pytest.mark.parametrize("consistent", [False, True], ids=["lumped", "consistent"])
def test_the_block_on_a_belt_linearises_as_its_equations_of_motion(block, law, friction, pressure_law,
                                                                   consistent):  # noqa: F811
    """With the consistent mass the friction rows carry the normal rows' inertia too."""
    problem = _block(block, law, friction, alpha=40.0, beta=2e-6, speed=0.3, pressure_law=pressure_law)
    JC = _check(problem, h_u=1e-9, h_v=1e-5, consistent=consistent)
    assert np.abs(JC).max() > 0


def test_a_clamped_annulus_on_a_turning_shaft_with_damping_linearises_as_its_equations_of_motion():
    """Curved contact (every node its own frame), a clamped rim, Rayleigh damping."""
    plain = general_annulus(FemScheme(PARAMS, 24, 2, 0.9)).params
    system = assemble(plain.system.body, Material(1.0, PARAMS.nu, PARAMS.gamma, alpha=0.3, beta=1e-3, scaled=True))
    problem = ContactProblem(system, plain.frames, plain.friction, plain.clamped)
    _check(problem, h_u=1e-6 * PARAMS.delta, h_v=1e-6)
