"""Two deformable bodies in frictional contact through a mortar interface (issue 24).

* The contact patch test: two bodies of different materials with non-matching meshes (a
  triangle mesh on a quadrilateral one, element sizes 4 and 2.7 mm), on rollers,
  pressed by a uniform pressure p, are in the exact uniform state sigma_yy = -p,
  sigma_xx = sigma_xy = 0 (every cell of both bodies, 1e-9 p) with the contact multiplier p at
  every slave node (1e-9 p). One-pass node-to-segment fails this; so does an inexact mortar
  integral (planted: one Gauss point).
* A stiff partner: a pad (clamped at its back, pressed 2 micrometres in, f = 0.5: its leading
  corner lifts, seven modes flutter) on a block 1e2 and 1e3 times stiffer reproduces the pad on
  a rigid flat (the verified rigid-surface contact): the same active set, node forces and
  every CEA eigenvalue of the band (none more or fewer, as many unstable) to 10 x the
  compliance ratio, and the error first order in it (the error at 1e2 at least 5 times that at
  1e3). Standard (not dual) multipliers failed this: they lifted a corner the rigid surface
  holds. A planted sign of the friction in the linearisation or the steady state fails it.
* Refusals: groups that do not face each other, bodies that interpenetrate beyond the
  interference a contact may have, unknown groups.
"""


import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.fem import (
    ContactProblem,
    Load,
    Material,
    RigidFlat,
    Spring,
    assemble,
    body_from_meshio,
    contact_frames,
)
from stickslip.fem.assembly import cell_stress
from stickslip.fem.cea import complex_eigenvalues
from stickslip.fem.pair import PairProblem, Rotation, Translation, steady_pair
from stickslip.friction import PressurePower, Stribeck

from .meshes import rectangle


def _shifted(path, dx, dy, **options):
    mesh = rectangle(path, **options)
    mesh.points[:, 0] += dx
    mesh.points[:, 1] += dy
    return body_from_meshio(mesh, path.name)


@pytest.fixture(scope="module")
def stack(tmp_path_factory):
    folder = tmp_path_factory.mktemp("stack")
    upper = _shifted(folder / "upper.msh", 0.0, 0.01, width=0.04, height=0.01, size=0.004)
    lower = _shifted(folder / "lower.msh", 0.0, 0.0, width=0.04, height=0.01, size=0.0027, quads=True)
    return upper, lower


def test_a_uniform_pressure_passes_a_non_matching_interface_exactly(stack):
    upper, lower = stack
    p, roller = 2e6, 1e12
    slave = assemble(upper, Material(1e9, 0.3, 1000.0), springs=[Spring("left", (roller, 0.0))],
                     loads=[Load("top", p)])
    # the lower body on rollers at its bottom (y = 0) and its left side (x = 0)
    master = assemble(lower, Material(5e9, 0.25, 2000.0),
                      springs=[Spring("bottom", (0.0, roller)), Spring("left", (roller, 0.0))])
    problem = PairProblem(slave, "bottom", master, "top", Translation((1.0, 0.0)), 0.0)
    st = steady_pair(problem)
    assert st.active.all()
    u_s, u_m = st.u[:slave.n_dofs], st.u[slave.n_dofs:]
    # the exact state leaves every roller unstretched (each body's rigid motion puts u_x = 0 on its
    # left side and u_y = 0 on the lower body's bottom), so it is the solution: uniform stress
    for system, u in ((slave, u_s), (master, u_m)):
        assert np.abs(cell_stress(system, u) - [0.0, -p, 0.0]).max() < 1e-9 * p
    assert np.abs(st.pressure - p).max() < 1e-9 * p
    assert st.normal_force == pytest.approx(p * 0.04, rel=1e-12)


@pytest.fixture(scope="module")
def pad(tmp_path_factory):
    """A pad (4 x 1 cm, lining-like, clamped at its back) pressed 2 micrometres into what it
    slides on, at f = 0.5: its leading corner lifts and seven of its modes flutter."""
    folder = tmp_path_factory.mktemp("pad")
    body = _shifted(folder / "pad.msh", 0.0, 0.0, width=0.04, height=0.01, size=0.002)
    under = _shifted(folder / "under.msh", -0.005, -0.01 + 2e-6, width=0.05, height=0.01, size=0.0015)
    return assemble(body, Material(1e10, 0.25, 2500.0)), under


def _pair_and_rigid(pad, ratio, friction=0.5, **laws):
    system, under = pad
    friction = {"friction": friction} if "law" not in laws else {}
    rigid = ContactProblem(system, contact_frames(system.body, "bottom", RigidFlat((0, 2e-6), (0, 1), (1.0, 0))),
                           clamped=("top",), **friction, **laws)
    partner = assemble(under, Material(1e10 * ratio, 0.25, 2500.0))
    pair = PairProblem(system, "bottom", partner, "top", Translation((1.0, 0.0)), clamped_slave=("top",),
                       clamped_master=("bottom",), **friction, **laws)
    return rigid, pair


@pytest.mark.parametrize("laws", [{}, {"law": Stribeck(0.6, 0.5, 0.2), "pressure_law": PressurePower(2e6, 0.2)}],
                         ids=["coulomb", "stribeck-and-pressure"])
def test_a_stiff_partner_reproduces_the_rigid_surface(pad, laws):
    """With a law of the slip speed (the CEA's slope term on the relative velocity) and a
    coefficient of the pressure (its fixed point in steady sliding, ``mu (1 - n)`` in the CEA) too."""
    errors = []
    for ratio in (1e2, 1e3):
        rigid, pair = _pair_and_rigid(pad, ratio, **laws)
        order = np.searchsorted(pair.coupling.slave_nodes, rigid.frames.nodes)  # the pair's slave nodes, along the line
        assert np.array_equal(pair.steady.active[order], rigid.steady.active) and not rigid.steady.active.all()
        force = pair.coupling.D.T @ pair.steady.pressure  # on the pad's mesh nodes [N/m]
        errors.append(np.abs(force[rigid.frames.nodes] - rigid.steady.pressure).max() / rigid.steady.pressure.max())
        band = (0.0, 150000.0)
        a, b = complex_eigenvalues(rigid, band, count=30), complex_eigenvalues(pair, band, count=30)
        assert len(a.s) == len(b.s) and a.unstable.sum() == b.unstable.sum() >= 5
        errors[-1] = max(errors[-1], max(np.min(np.abs(b.s - x)) / abs(x) for x in a.s))
    assert errors[1] < 10 / 1e3 and errors[0] > 5 * errors[1]  # first order in the partner's compliance


def test_bad_pairs_are_refused(stack, tmp_path):
    upper, lower = stack
    slave = assemble(upper, Material(1e9, 0.3, 1000.0))
    master = assemble(lower, Material(1e9, 0.3, 1000.0))
    with pytest.raises(ParameterError) as err:  # the lower body's bottom faces away from the upper body
        PairProblem(slave, "bottom", master, "bottom", Translation((1.0, 0.0)))
    assert err.value.name == "master_group"
    with pytest.raises(ParameterError) as err:
        PairProblem(slave, "face", master, "top", Translation((1.0, 0.0)))
    assert err.value.name == "slave_group" and "face" in str(err.value)
    sunk = _shifted(tmp_path / "sunk.msh", 0.0, 0.005, width=0.04, height=0.01, size=0.004)
    with pytest.raises(ParameterError) as err:  # half a body deep in the other
        PairProblem(assemble(sunk, Material(1e9, 0.3, 1000.0)), "bottom", master, "top",
                    Translation((1.0, 0.0)))
    assert err.value.name == "slave_group" and "interpenetrate" in str(err.value)


@pytest.mark.parametrize("make, name", [
    (lambda: Translation((float("nan"), 0.0)), "velocity"), (lambda: Translation((1e300, 0.0)), "velocity"),
    (lambda: Translation("fast"), "velocity"), (lambda: Rotation(float("inf")), "omega"),
    (lambda: Rotation(1.0, (0.0, "x")), "center")])
def test_bad_motions_name_their_parameter(make, name):
    with pytest.raises(ParameterError) as err:
        make()
    assert err.value.name == name


def test_a_motion_that_does_not_slide_or_too_fast_is_refused(stack):
    upper, lower = stack
    slave, master = assemble(upper, Material(1e9, 0.3, 1000.0)), assemble(lower, Material(1e9, 0.3, 1000.0))
    for motion in (Translation((0.0, 0.0)), Rotation(1e6, (0.02, -10.0))):
        with pytest.raises(ParameterError) as err:
            PairProblem(slave, "bottom", master, "top", motion, 0.3)
        assert err.value.name == "motion"
    PairProblem(slave, "bottom", master, "top", Translation((0.0, 0.0)), 0.0)  # at rest without friction: a preload
    with pytest.raises(ParameterError) as err:
        PairProblem(slave, "bottom", master, "top", Translation((1.0, 0.0)), -0.1)
    assert err.value.name == "friction"
