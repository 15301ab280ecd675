"""Two bodies with quadratic cells in mortar contact (issue 44: a pair refused them;
`stickslip.fem.mortar2`).

* The contact patch test: the stack of test_pair with 6-node triangles on 9-node
  quadrilaterals (non-matching: 4 and 2.7 mm), and each on a linear body, pressed by a uniform
  pressure p on rollers: the exact uniform state sigma_yy = -p (every cell of both bodies, 1e-9
  p) and the multiplier p at every slave node, middle nodes too (1e-9 p). An inexact mortar
  integral (planted: 2 Gauss points) fails it.
* Dual multipliers: on matching meshes (the master's top the slave's bottom, the same nodes) the
  mortar's ``M_jl = int phi_j N_l`` is ``D = diag(int N_j)`` exactly: 1/6, 2/3, 1/6 of a
  segment's length at its ends and middle (the biorthogonality; standard multipliers give the
  consistent mass matrix of the line, with off-diagonal terms, and fail it).
* A curved contact: the pad of examples/pad_on_disc (6-node triangles, 4 mm, its face on
  r = 0.15 m) pressed 20 micrometres into a disc of 6-node triangles with a rim of 12-mm
  segments. Straight segments of that size sag h^2 / (8 R) = 120 micrometres and give zero
  pressure at most nodes (6-mm linear disc: pressure jumps by twice its mean between
  neighbours); the curved ones follow the rim: between neighbouring nodes of the face (its
  five nodes at each end left out) the pressure changes by less than 5 % of its mean, and the
  normal force is that of a 3-mm quadratic disc to 1 % (thresholds set before the run).
"""

import logging

import numpy as np
import pytest

from stickslip.fem import Load, Material, Spring, assemble, body_from_meshio
from stickslip.fem.assembly import cell_stress
from stickslip.fem.config import load_config
from stickslip.fem.pair import PairProblem, Translation, steady_pair

from .meshes import annulus, rectangle
from .test_pair_config import pad_disc


def _body(path, dy, **options):
    mesh = rectangle(path, **options)
    mesh.points[:, 1] += dy
    return body_from_meshio(mesh, path.name)


@pytest.mark.parametrize("orders", [(2, 2), (2, 1), (1, 2)], ids=["p2-on-q2", "p2-on-q1", "p1-on-q2"])
def test_a_uniform_pressure_passes_a_quadratic_non_matching_interface_exactly(tmp_path, orders):
    upper = _body(tmp_path / "upper.msh", 0.01, width=0.04, height=0.01, size=0.004, order=orders[0])
    lower = _body(tmp_path / "lower.msh", 0.0, width=0.04, height=0.01, size=0.0027, quads=True, order=orders[1])
    p, roller = 2e6, 1e12
    slave = assemble(upper, Material(1e9, 0.3, 1000.0), springs=[Spring("left", (roller, 0.0))],
                     loads=[Load("top", p)])
    master = assemble(lower, Material(5e9, 0.25, 2000.0),
                      springs=[Spring("bottom", (0.0, roller)), Spring("left", (roller, 0.0))])
    problem = PairProblem(slave, "bottom", master, "top", Translation((1.0, 0.0)), 0.0)
    st = steady_pair(problem)
    assert st.active.all() and len(st.pressure) == len(np.unique(upper.group("bottom")))  # middle nodes too
    for system, u in ((slave, st.u[:slave.n_dofs]), (master, st.u[slave.n_dofs:])):
        assert np.abs(cell_stress(system, u) - [0.0, -p, 0.0]).max() < 1e-9 * p
    assert np.abs(st.pressure - p).max() < 1e-9 * p
    assert st.normal_force == pytest.approx(p * 0.04, rel=1e-12)


def test_the_multipliers_of_quadratic_segments_are_dual(tmp_path):
    upper = _body(tmp_path / "upper.msh", 0.01, width=0.04, height=0.01, size=0.01, quads=True, order=2)
    lower = _body(tmp_path / "lower.msh", 0.0, width=0.04, height=0.01, size=0.01, quads=True, order=2)
    material = Material(1e9, 0.3, 1000.0)
    coupling = PairProblem(assemble(upper, material), "bottom", assemble(lower, material), "top",
                           Translation((1.0, 0.0))).coupling
    xs, xm = upper.points[coupling.slave_nodes, :2], lower.points[:, :2]
    same = [int(np.argmin(np.hypot(*(xm - x).T))) for x in xs]  # the master node at each slave node
    assert np.allclose(xm[same], xs, atol=1e-12)
    M = coupling.M.toarray()[:, same]
    h = 0.01  # four segments of 1 cm: their ends carry 1/6 h from each side, their middles 2/3 h
    ends = np.isclose(xs[:, 0] / h, np.round(xs[:, 0] / h))
    expected = np.where(ends, h / 6 * np.where(np.isclose(xs[:, 0] % 0.04, 0.0), 1, 2), 2 * h / 3)
    assert np.abs(M - np.diag(expected)).max() < 1e-12 * h
    assert np.abs(coupling.D.toarray()[:, coupling.slave_nodes] - np.diag(expected)).max() < 1e-12 * h


@pytest.mark.slow
def test_a_curved_contact_of_quadratic_cells_has_a_smooth_pressure(tmp_path, caplog):
    import subprocess
    import sys

    from .test_examples import EXAMPLES

    folder = pad_disc(tmp_path)
    subprocess.run([sys.executable, str(EXAMPLES / "pad_on_disc" / "mesh.py"), "padq.msh", "0.004", "2"], cwd=folder,
                   check=True)
    text = (folder / "pad_disc.toml").read_text().replace('clamped = ["hub"]', 'clamped = ["bore"]')
    found = {}
    for name, order, size, pad in (("q12", 2, 0.012, "padq.msh"), ("q3", 2, 0.003, "padq.msh"),
                                   ("l6", 1, 0.006, "pad.msh")):
        annulus(folder / f"{name}.msh", inner=0.06, outer=0.15 + 2e-5, size=size, order=order)
        (folder / "case.toml").write_text(text.replace('"disc.msh"', f'"{name}.msh"').replace('"pad.msh"', f'"{pad}"'))
        with caplog.at_level(logging.WARNING, logger="stickslip.fem"):
            problem = load_config(folder / "case.toml").problem()
            st = problem.steady
        x = problem.slave.body.points[problem.coupling.slave_nodes]
        p = st.pressure[np.argsort(np.arctan2(x[:, 0], x[:, 1]))][5:-5]  # along the face
        found[name] = (np.abs(np.diff(p)).max() / p.mean(), st.normal_force)
    assert found["l6"][0] > 1.0  # straight segments: a checkerboard
    assert found["q12"][0] < 0.05 and found["q3"][0] < 0.05
    assert found["q12"][1] == pytest.approx(found["q3"][1], rel=0.01)
