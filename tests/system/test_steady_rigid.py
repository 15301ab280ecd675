"""Steady sliding with rigid contacts (closed, their reactions the constraints'): a block whose
inertia couples its normal and tangential motion, against the closed form of its one remaining
degree of freedom; the ring whose nodes may leave the shaft, pressed on it, against the
eigenvalues of its Fourier modes in closed form; what cannot slide steadily is said (a contact
that would pull, the Painleve paradox)."""

import json
import math

import numpy as np
import pytest
from scipy.optimize import linear_sum_assignment

from stickslip.brake import BrakeParams
from stickslip.brake.waves import Scaling, ring_system
from stickslip.cli import run
from stickslip.errors import NoSolutionError
from stickslip.friction import Coulomb
from stickslip.system import Contact, System, steady_sliding


def block(m=1.0, mc=0.3, my=2.0, kx=4.0, kxy=1.5, ky=3.0, F0=2.0, mu=0.4, c=0.1, V=0.5):
    """(x along the belt, y up), the belt at y = 0 moving at V, pressed by F0; mass and stiffness
    coupling x and y."""
    contact = Contact([1.0, 0.0], None, Coulomb(mu, mu), V, normal_direction=[0.0, 1.0], rigid=True)
    return System([[m, mc], [mc, my]], [[kx, kxy], [kxy, ky]], [contact], damping=np.diag([c, 0.0]),
                  force=[0.0, -F0])


@pytest.mark.parametrize("kw", [{}, {"V": -0.5}, {"kxy": 2.0, "mu": 1.0, "mc": 0.1, "V": -2.0}, {"c": 0.0, "mc": -0.6},
                                {"kxy": -2.0, "mc": 1.2, "mu": 0.7}])
def test_a_block_coupled_through_its_inertia_has_the_closed_form_of_its_one_sliding_dof(kw):
    # y = 0: the reaction P = F0 + kxy x + mc x''; along x, with the friction s mu P (s = sign V):
    # (m - s mu mc) x'' + c x' + (kx - s mu kxy) x = s mu F0
    p = dict(m=1.0, mc=0.3, my=2.0, kx=4.0, kxy=1.5, ky=3.0, F0=2.0, mu=0.4, c=0.1, V=0.5) | kw
    s = math.copysign(1.0, p["V"])
    stiff, inertia = p["kx"] - s * p["mu"] * p["kxy"], p["m"] - s * p["mu"] * p["mc"]
    x = s * p["mu"] * p["F0"] / stiff
    result = steady_sliding(block(**p))
    assert np.allclose(result.x, [x, 0.0], rtol=1e-12, atol=1e-14)
    assert result.friction_force[0] == pytest.approx(s * p["mu"] * (p["F0"] + p["kxy"] * x), rel=1e-12)
    roots = np.roots([inertia, p["c"], stiff])
    assert result.eigenvalues.size == 2
    assert np.allclose(np.sort_complex(result.eigenvalues), np.sort_complex(roots), rtol=1e-10, atol=1e-12)
    assert result.stable == bool(np.all(roots.real < 0) and p["c"] > 0)


def test_a_contact_that_would_pull_or_whose_friction_drives_it_into_the_surface_is_said():
    with pytest.raises(NoSolutionError, match="would pull"):
        steady_sliding(block(F0=-2.0))  # lifted, not pressed
    with pytest.raises(NoSolutionError, match="Painleve"):
        steady_sliding(block(mc=3.0, my=10.0, mu=0.5))  # m - mu mc < 0: no reaction keeps y'' = 0 uniquely
    held = Contact([1.0], None, Coulomb(0.3, 0.3), 0.5, normal_direction=[1.0], rigid=True)
    with pytest.raises(NoSolutionError, match="hold every one"):  # nothing left to move (was a crash)
        steady_sliding(System([[1.0]], [[1.0]], [held], force=[-1.0]))


@pytest.mark.parametrize("nodes, friction", [(16, 0.2), (32, 0.7)])
def test_the_ring_whose_nodes_may_leave_the_shaft_pressed_on_it_has_its_fourier_modes(nodes, friction):
    # u = 0 at every node: P_j = g delta - D (V_{j+1} - V_{j-1}) / (2 dtheta), and the mode
    # exp(i k j dtheta) of V'' = a (laplacian V) - h V + f P obeys
    # lambda^2 = -(4 a sin^2(k dtheta / 2) / dtheta^2 + h) -+ i f D sin(k dtheta) / dtheta
    params = BrakeParams.from_physical(50.0, 1e-4, friction)
    co, delta, dth = Scaling(params).coefficients, Scaling(params).delta, 2 * math.pi / nodes
    k = np.arange(nodes)
    lam2 = -(4 * co.a * np.sin(k * dth / 2) ** 2 / dth**2 + co.h) - 1j * friction * co.D * np.sin(k * dth) / dth
    expected = np.concatenate([np.sqrt(lam2 + 0j), -np.sqrt(lam2 + 0j)])
    result = steady_sliding(ring_system(params, nodes, separation=True))
    assert result.eigenvalues.size == 2 * nodes
    distance = np.abs(result.eigenvalues[:, None] - expected[None, :])
    rows, cols = linear_sum_assignment(distance)  # each eigenvalue paired with one of the closed form's
    assert distance[rows, cols].max() < 1e-9 * np.abs(expected).max()
    assert np.allclose(result.x[:nodes], 0.0, atol=1e-15)  # closed
    assert np.allclose(result.x[nodes:], friction * co.g * delta / co.h, rtol=1e-10)  # h V = f g delta
    assert np.allclose(result.friction_force, friction * co.g * delta, rtol=1e-10)


def test_the_command_line_computes_a_file_with_a_rigid_contact(tmp_path, capsys):
    file = tmp_path / "block.toml"
    file.write_text('mass = [[1.0, 0.3], [0.3, 2.0]]\nstiffness = [[4.0, 1.5], [1.5, 3.0]]\nforce = [0.0, -2.0]\n'
                    'damping = [[0.1, 0.0], [0.0, 0.0]]\n[[contact]]\ndirection = [1.0, 0.0]\n'
                    'normal_direction = [0.0, 1.0]\nrigid = true\nfs = 0.4\nfd = 0.4\nsurface_speed = 0.5\n')
    assert run(["system", "stability", str(file), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    x = 0.4 * 2.0 / (4.0 - 0.4 * 1.5)
    assert out["x"] == pytest.approx([x, 0.0], rel=1e-12, abs=1e-14) and len(out["eigenvalue_real"]) == 2
