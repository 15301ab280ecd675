"""Steady sliding of a general body against closed forms: the annulus on a turning shaft
(Lamé with friction, `stickslip.brake.reduced.steady`, an independent closed form) and the
Signorini conditions on a pad pressed by a tilted flat (some of it lifts off)."""

import numpy as np
import pytest

from stickslip.brake.reduced.steady import steady_sliding
from stickslip.errors import NoSolutionError, ParameterError
from stickslip.fem import ContactProblem, Material, assemble, body_from_meshio, read_body
from stickslip.fem.static import steady_contact
from stickslip.fem.surfaces import RigidCylinder, RigidFlat, contact_frames

from .meshes import annulus, rectangle

XI, NU, DELTA = 1.5, 0.3, 1e-3


@pytest.mark.parametrize("friction", [0.0, 0.5])
def test_the_annulus_on_a_turning_shaft_slides_as_lame_says(friction, tmp_path):
    exact = steady_sliding(XI, NU, DELTA, friction)
    errors = []
    for size in (0.1, 0.05):
        body = body_from_meshio(annulus(tmp_path / f"a{size}.msh", outer=XI, size=size), "annulus")
        system = assemble(body, Material(1.0, NU, 1.0, scaled=True))  # E = R = 1: lengths in R, forces in E R
        frames = contact_frames(body, "bore", RigidCylinder(1.0 + DELTA, 100.0))
        st = steady_contact(system, frames, friction, clamped=["rim"])
        u = st.u.reshape(-1, 2)[frames.nodes]
        assert st.active.all() and np.allclose(np.sum(u * frames.normal, axis=1), DELTA, rtol=1e-12)
        assert np.allclose(st.shear, friction * st.pressure, rtol=0, atol=1e-15)
        p = st.pressure.sum() / (2 * np.pi)  # the mean bore pressure
        x, y = body.points[frames.nodes].T  # the hoop direction of a counter-clockwise shaft, from the geometry
        v = np.mean((-y * u[:, 0] + x * u[:, 1]) / np.hypot(x, y))
        errors.append(abs(p / exact.p_e - 1))
        assert (v == pytest.approx(exact.V_e, rel=2e-3)) if friction else abs(v) < 1e-3 * DELTA  # mesh asymmetry
    assert errors[1] < 1e-4 and errors[1] < errors[0] / 4  # the pressure converges at order >= 2


@pytest.mark.parametrize("friction", [0.0, 0.5])
def test_on_quadratic_cells_the_annulus_pressure_converges_faster(friction, tmp_path):
    """6-node triangles with their middle nodes on the circles, every contact node (corners
    and middles) held on the shaft: the mean bore pressure converges to Lamé's at order >= 3
    (measured 3.7 from R/5 to R/10 and 3.9 from R/10 to R/20; linear cells: about 2), and at
    R/10 it is within 1e-5 where linear cells are within 1e-3."""
    exact = steady_sliding(XI, NU, DELTA, friction)
    errors = []
    for size in (0.2, 0.1):
        body = body_from_meshio(annulus(tmp_path / f"q{size}.msh", outer=XI, size=size, order=2), "annulus")
        system = assemble(body, Material(1.0, NU, 1.0, scaled=True))
        frames = contact_frames(body, "bore", RigidCylinder(1.0 + DELTA, 100.0))
        assert len(frames.nodes) == 2 * len(body.group("bore"))  # the middle nodes are contact nodes
        st = steady_contact(system, frames, friction, clamped=["rim"])
        assert st.active.all() and np.allclose(st.shear, friction * st.pressure, rtol=0, atol=1e-15)
        errors.append(abs(st.pressure.sum() / (2 * np.pi) / exact.p_e - 1))
    assert errors[1] < 1e-5 and errors[1] < errors[0] / 8, errors


@pytest.mark.parametrize("friction, omega", [(0.0, 100.0), (0.5, 100.0), (0.5, -100.0)])
def test_an_annulus_in_a_turning_drum_slides_as_lame_says(friction, omega, tmp_path):
    """The annulus 1 < r < b = 1.5 with its bore clamped, inside a drum of radius b - delta
    (``body_inside``). Plane strain, E = 1: the radial and the hoop problems separate. Radially
    u = A (r - 1/r) with u(b) = -delta, and the drum presses with p = -2 (lambda + mu) A - 2 mu
    A / b^2; the friction f p drags the rim along the drum's turn, u_theta = C (r - 1/r) with
    2 mu C / b^2 = f p (sign of omega). Thresholds set before the run: pressure within 1e-3,
    hoop displacement within 5e-3 at size 0.05, the pressure error falling with the size
    (measured: pressure 5.6e-4 at 0.1, 1.7e-4 at 0.05; hoop 1.6e-3, 6.8e-4). A normal out of
    the body, the drum's gap of a shaft or a tangent that ignores the sign of omega fail it."""
    b, lam, mu = XI, NU / ((1 + NU) * (1 - 2 * NU)), 1 / (2 * (1 + NU))
    A = -DELTA / (b - 1 / b)
    p = -2 * (lam + mu) * A - 2 * mu * A / b**2
    hoop = np.sign(omega) * friction * p * b**2 / (2 * mu) * (b - 1 / b)
    errors = []
    for size in (0.1, 0.05):
        body = body_from_meshio(annulus(tmp_path / f"d{size}.msh", outer=b, size=size), "annulus")
        system = assemble(body, Material(1.0, NU, 1.0, scaled=True))
        frames = contact_frames(body, "rim", RigidCylinder(b - DELTA, omega, body_inside=True))
        st = steady_contact(system, frames, friction, clamped=["bore"])
        u = st.u.reshape(-1, 2)[frames.nodes]
        x, y = body.points[frames.nodes].T
        r = np.hypot(x, y)
        assert st.active.all() and np.allclose((x * u[:, 0] + y * u[:, 1]) / r, -DELTA, rtol=1e-12)
        errors.append(abs(st.pressure.sum() / (2 * np.pi * b) / p - 1))
        v = np.mean((-y * u[:, 0] + x * u[:, 1]) / r)
    assert errors[1] < 1e-3 and errors[1] < errors[0], errors
    assert (v == pytest.approx(hoop, rel=5e-3)) if friction else abs(v) < 1e-3 * DELTA


def _pad(tmp_path):
    body = read_body(rectangle(tmp_path / "pad.msh") and tmp_path / "pad.msh")
    return body, assemble(body, Material(2.1e11, 0.3, 7850.0))


@pytest.mark.parametrize("case", ["clamped top", "cantilever"])
def test_a_tilted_flat_lifts_part_of_a_pad_and_signorini_holds(case, tmp_path):
    body, system = _pad(tmp_path)
    tilt = 1e-5 / 0.04  # the flat enters 1e-5 m at one end of the pad and leaves it at the other
    if case == "clamped top":
        flat, clamped = RigidFlat(point=(0.0, 1e-5), normal=(tilt, 1.0), velocity=(1.0, -tilt)), ["top"]
    else:  # clamped at its left end, pushed at its free end: the first guess of the active set is wrong
        flat, clamped = RigidFlat(point=(0.04, 1e-5), normal=(-tilt, 1.0), velocity=(1.0, tilt)), ["left"]
    frames = contact_frames(body, "bottom", flat)
    st = steady_contact(system, frames, 0.3, clamped=clamped)
    assert st.iterations > 1 or case == "clamped top"
    u = st.u.reshape(-1, 2)[frames.nodes]
    gap = np.sum(u * frames.normal, axis=1) + frames.gap  # >= 0, zero where in contact
    scale = np.abs(frames.gap).max()
    assert 0 < st.active.sum() < len(frames.nodes)  # part of the pad lifts off
    assert np.all(st.pressure >= 0) and np.all(gap >= -1e-9 * scale)
    assert np.abs(gap[st.active]).max() < 1e-9 * scale and np.all(st.pressure[~st.active] == 0)
    assert np.all(st.shear == 0.3 * st.pressure)


def test_a_surface_that_does_not_touch_and_a_free_body_are_refused(tmp_path):
    body, system = _pad(tmp_path)
    with pytest.raises(ParameterError) as err:
        contact_frames(body, "bottom", RigidFlat(point=(0.0, -0.01), normal=(0.0, 1.0), velocity=(1.0, 0.0)))
    assert err.value.name == "surface" and "touching" in str(err.value)
    frames = contact_frames(body, "bottom", RigidFlat(point=(0.0, 1e-6), normal=(0.0, 1.0), velocity=(1.0, 0.0)))
    with pytest.raises(NoSolutionError, match="not held"):
        steady_contact(system, frames, 0.0)
    with pytest.raises(ParameterError) as err:
        RigidFlat(point=(0.0, 0.0), normal=(0.0, 1.0), velocity=(1.0, 0.5))
    assert err.value.name == "velocity"
    at_rest = contact_frames(body, "bottom", RigidFlat(point=(0.0, 1e-6), normal=(0.0, 1.0), velocity=(0.0, 0.0)))
    with pytest.raises(ParameterError, match="surface at rest") as err:
        ContactProblem(system, at_rest, 0.3)
    assert err.value.also == ("friction",)
    ContactProblem(system, at_rest, 0.0)  # frictionless: a surface at rest is a plain obstacle
