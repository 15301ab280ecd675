"""Mesh, assembly and the FE steady sliding state against the Lamé solution (eq. [11] corrected)."""

import numpy as np
import pytest

from stickslip.brake import steady_sliding
from stickslip.brake.fem import FemInitial, FemScheme, annulus_mesh, assemble, integrate_fem, steady_state
from stickslip.errors import ParameterError

from .helpers import case, orders


def test_mesh_and_matrices():
    mesh = annulus_mesh(32, 4, 1.5)
    assert mesh.mesh.p.shape == (2, 32 * 5) and mesh.mesh.t.shape == (4, 32 * 4)
    r = np.hypot(*mesh.mesh.p)
    assert r.min() == pytest.approx(1.0) and r.max() == pytest.approx(1.5)
    s = assemble(mesh, 0.3)
    assert s.n_free == 2 * 32 * 4 and abs(s.K - s.K.T).max() == 0.0
    # lumped mass of the free nodes + half the outer layer = area of the polygonal annulus
    area = 0.5 * 32 * np.sin(2 * np.pi / 32) * (1.5**2 - 1.0)
    assert s.mass[0::2].sum() < area and s.mass[0::2].sum() > 0.8 * area and np.all(s.mass > 0)
    # the clamped annulus has no rigid motion: K is positive definite
    assert np.linalg.eigvalsh(s.K.toarray()).min() > 0.0


@pytest.mark.parametrize("kwargs, name", [(dict(n_theta=20), "n_theta"), (dict(n_theta=8), "n_theta"),
                                          (dict(n_r=0), "n_r"), (dict(xi=1.0), "xi"), (dict(n_theta=32.5), "n_theta")])
def test_mesh_rejects_bad_input(kwargs, name):
    with pytest.raises(ParameterError) as err:
        annulus_mesh(**(dict(n_theta=32, n_r=2) | kwargs))
    assert err.value.name == name


def test_assemble_and_steady_reject_bad_input():
    with pytest.raises(ParameterError):
        assemble("mesh")
    with pytest.raises(ParameterError) as err:
        assemble(annulus_mesh(16, 1), nu=0.5)
    assert err.value.name == "nu"
    with pytest.raises(ParameterError) as err:
        steady_state(case(1).replace(nu=0.25), assemble(annulus_mesh(16, 1), 0.3))
    assert err.value.name == "system"


def test_steady_sliding_matches_lame_with_order_two():
    """``u = delta X(r)``, ``v = V_e X(r)``, ``p = p_e`` (max-norm errors), refining both directions."""
    p = case(1)
    lame = steady_sliding(p.xi, p.nu, p.delta, p.friction)
    grids = [(32, 2), (64, 4), (128, 8), (256, 16)]
    errs = np.array([[e[k] for k in ("u", "v", "p")] for e in
                     (steady_state(p, assemble(annulus_mesh(N, nr), p.nu)).errors() for N, nr in grids)])
    assert errs[-1].max() < 2e-4  # 256 x 16: p within 2e-5 p_e, v within 1.2e-4 V_e
    for k in range(3):  # observed orders (u, v: 1.93-2.00; p: 1.83, 1.96, 1.99)
        o = orders([1.0 / g[0] for g in grids], errs[:, k])
        assert np.all(o > 1.8) and abs(o[-1] - 2.0) < 0.05, (errs[:, k], o)
    st = steady_state(p, n_theta=64, n_r=4)
    assert st.pressure == pytest.approx(np.full(64, lame.p_e), rel=5e-4)  # uniform, positive
    assert st.reaction_t == pytest.approx(p.friction * st.reaction_n, rel=1e-14)
    interior = np.ones(st.u.size, bool)
    interior[: 2 * 64] = False
    assert np.abs(st.forces[interior]).max() < 1e-12 * st.reaction_n.max()  # equilibrium off the contact
    ds = st.to_xarray()
    assert ds["pressure"].attrs["scale"] == "E" and ds.attrs["p_e"] == pytest.approx(lame.p_e)


def test_steady_state_is_a_fixed_point_of_the_scheme():
    """Unperturbed steady sliding stays put: the scheme's reactions at rest are the static ones."""
    p = case(1)
    s = FemScheme(p, 64, 4, beta2=0.9)
    ini = FemInitial(s.steady.u, np.zeros_like(s.steady.u), "steady")
    run = integrate_fem(p, 64, 4, transits=2, initial=ini, tail=1.0)
    assert np.abs(run.U - p.delta).max() <= 1e-15 * p.delta
    assert np.abs(run.V - s.steady.u[1]).max() < 1e-12 * s.steady.u[1]
    assert run.P == pytest.approx(np.broadcast_to(s.steady.pressure, run.P.shape), rel=1e-10)
    assert np.all(run.state == 1)  # forward slip everywhere
    assert np.abs(run.energy).max() < 1e-20 * (s.steady.u @ (s.system.K @ s.steady.u))
