"""Boundary springs and loads (`stickslip.fem.boundary`) against integrals done by hand, and a
block pressed on a flat by a pressure against the exact uniform compression."""

import numpy as np
import pytest

from stickslip.errors import NoSolutionError, ParameterError
from stickslip.fem import Body, Material, assemble, body_from_meshio
from stickslip.fem.boundary import Load, Spring, boundary_load, boundary_springs
from stickslip.fem.static import steady_contact
from stickslip.fem.surfaces import RigidCylinder, RigidFlat, contact_frames

from .meshes import rectangle

W, H = 0.04, 0.01


@pytest.fixture(scope="module", params=[1, 2], ids=["triangles", "triangle6"])
def block(request, tmp_path_factory):
    """A triangle mesh graded along both axes: boundary edges of unequal lengths (on 6-node
    triangles the middle nodes then sit off the middle of their straight edges)."""
    b = body_from_meshio(rectangle(tmp_path_factory.mktemp("b") / "b.msh", W, H, 0.0023, order=request.param), "block")
    x, y = b.points.T
    # monotone, with a slope bounded away from zero: the (isoparametric) cells stay counter-clockwise
    graded = np.stack([x * (0.5 + 0.5 * x / W), y * (0.3 + 0.7 * y / H)], axis=1)
    turn = [1, 0] + list(range(2, b.order + 1))  # the ends swapped, the middle node kept
    flipped = {name: e[:, turn] if name in ("top", "left") else e for name, e in b.groups.items()}  # any orientation
    return Body(graded, b.cells, b.kind, flipped, "block")


def _tributary(body, group):
    """The nodal weights of a uniform load on a straight ``group``, by hand: on linear edges half
    of each edge to each end; on quadratic ones the integrals of the shape functions of the
    edge's parametrisation ``x(xi)``, ``|x'(xi)|`` linear in ``xi`` on a straight edge:
    ``∫ N |x'| dxi`` with ``|x'| = (L/2)(1 + c xi)``, ``c = 2 (|b - m| - |m - a|) / L``
    (ends ``a``, ``b``, middle ``m``)."""
    share = np.zeros(len(body.points))
    for e in body.group(group):
        a, b = body.points[e[0]], body.points[e[1]]
        L = np.hypot(*(b - a))
        if len(e) == 2:
            share[e] += L / 2
            continue
        m = body.points[e[2]]
        c = 2 * (np.hypot(*(b - m)) - np.hypot(*(m - a))) / L
        share[e[0]] += L / 2 * (1 / 3 - c / 3)  # ∫ xi (xi - 1) / 2 (1 + c xi) dxi
        share[e[1]] += L / 2 * (1 / 3 + c / 3)  # ∫ xi (xi + 1) / 2 (1 + c xi) dxi
        share[e[2]] += L / 2 * (4 / 3)          # ∫ (1 - xi^2) (1 + c xi) dxi
    return share


def test_a_spring_meets_a_linear_field_with_its_exact_integral(block):
    kx, ky = 3e6, 5e5
    S = boundary_springs(block, [Spring("left", (kx, ky))])
    x, y = block.points.T
    for field, exact in ((np.ones_like(y), 1.0), (y, H / 2), (y**0 + 2 * y / H, 2.0)):  # the mean over the face
        u = np.zeros(2 * len(x))
        u[0::2], u[1::2] = field, -field
        f = S @ u
        assert f[0::2].sum() == pytest.approx(kx * exact, rel=1e-12)
        assert f[1::2].sum() == pytest.approx(-ky * exact, rel=1e-12)
    off = np.zeros(2 * len(x))
    off[0::2] = x != 0
    assert not (S @ off).any()  # only the group's nodes


def test_a_uniform_load_gives_its_resultant_and_moment(block):
    P, (tx, ty) = 2e6, (3e5, -1e5)
    x, y = block.points.T
    cases = {"top": ((0.0, -P * W), (tx * W, ty * W)), "left": ((P * H, 0.0), (tx * H, ty * H)),
             "right": ((-P * H, 0.0), (tx * H, ty * H)), "bottom": ((0.0, P * W), (tx * W, ty * W))}
    for group, (pressure, traction) in cases.items():
        f = boundary_load(block, [Load(group, P)]).reshape(-1, 2)
        assert f.sum(axis=0) == pytest.approx(pressure, rel=1e-12, abs=1e-6)
        f = boundary_load(block, [Load(group, 0.0, (tx, ty))]).reshape(-1, 2)
        assert f.sum(axis=0) == pytest.approx(traction, rel=1e-12, abs=1e-6)
    # the moment of the pressure on the top about the origin: -P W * W/2 (at its centre)
    f = boundary_load(block, [Load("top", P)]).reshape(-1, 2)
    assert np.sum(x * f[:, 1] - y * f[:, 0]) == pytest.approx(-P * W * W / 2, rel=1e-12)


@pytest.mark.parametrize("gap", [0.0, 3e-6], ids=["touching", "gap"])
def test_a_block_pressed_on_a_flat_is_compressed_uniformly(block, gap):
    """Frictionless flat under the bottom, pressure on the top, a weak spring along x on the left:
    the exact state is uniform compression, ``sigma_yy = -P`` (linear elements represent it).
    With the flat ``gap`` below the block, the load first closes the gap (a rigid motion)."""
    E, nu, P = 2e9, 0.3, 1e6
    system = assemble(block, Material(E, nu, 1000.0), [Spring("left", (1e3, 0.0))], [Load("top", P)])
    frames = contact_frames(block, "bottom", RigidFlat((0.0, -gap), (0.0, 1.0), (1.0, 0.0)))
    st = steady_contact(system, frames, 0.0)
    share = _tributary(block, "bottom")[frames.nodes]
    assert st.active.all() and st.pressure == pytest.approx(P * share, rel=1e-9)
    u = st.u.reshape(-1, 2)
    top = np.isclose(block.points[:, 1], H)
    assert u[top, 1] == pytest.approx(-gap - P * H * (1 - nu**2) / E, rel=1e-9)  # plane strain, sigma_xx = 0


def test_a_surface_on_the_wrong_side_of_the_body_is_refused(block):
    """The normal must point into the body at the contact group: a flat under the block pointing
    down, or a cylinder under it with the body "inside", would pull; on the top, the flat's normal
    points down."""
    contact_frames(block, "bottom", RigidFlat((0.0, 0.0), (0.0, 1.0), (1.0, 0.0)))
    contact_frames(block, "top", RigidFlat((0.0, H), (0.0, -1.0), (1.0, 0.0)))
    with pytest.raises(ParameterError, match=r"invalid normal = \[0.0, -1.0\].*try normal = \[0, 1\]"):
        contact_frames(block, "bottom", RigidFlat((0.0, 0.0), (0.0, -1.0), (1.0, 0.0)))
    with pytest.raises(ParameterError, match=r"invalid normal.*try normal = \[0, -1\]"):
        contact_frames(block, "top", RigidFlat((0.0, H), (0.0, 1.0), (1.0, 0.0)))
    R = 1.0
    contact_frames(block, "bottom", RigidCylinder(R, 1.0, (W / 2, -R)))
    with pytest.raises(ParameterError, match="invalid body_inside = True.*try body_inside = false"):
        contact_frames(block, "bottom", RigidCylinder(R, 1.0, (W / 2, -R), body_inside=True))


def test_a_tethered_block_slides_where_its_spring_holds_the_friction(block):
    """Springs on the contact nodes themselves balance the friction node by node: with nu = 0 (no
    lateral expansion under the pressure) steady sliding is a rigid translation by ``f N / k``.
    Part of the load sits on the contact face itself (a suction ``Pb`` onto the belt)."""
    k, f, P, Pb = 2e7, 0.4, 1e6, 3e5
    loads = [Load("top", P), Load("bottom", -Pb)]  # negative: along the outward normal, onto the belt
    system = assemble(block, Material(2e9, 0.0, 1000.0), [Spring("bottom", (k, 0.0))], loads)
    frames = contact_frames(block, "bottom", RigidFlat((0.0, 0.0), (0.0, 1.0), (1.0, 0.0)))
    st = steady_contact(system, frames, f)
    assert st.pressure.sum() == pytest.approx((P + Pb) * W, rel=1e-9)
    assert st.u.reshape(-1, 2)[:, 0] == pytest.approx(f * (P + Pb) * W / k, rel=1e-9)


def test_bad_springs_and_loads_name_their_option(block):
    with pytest.raises(ParameterError, match="spring.stiffness"):
        Spring("left", (-1.0, 0.0))
    with pytest.raises(ParameterError, match="spring.stiffness"):
        Spring("left", (0.0, 0.0))
    with pytest.raises(ParameterError, match="load.pressure"):
        Load("top", float("nan"))
    with pytest.raises(ParameterError, match="load.traction"):
        Load("top", 0.0, (1e300, 0.0))
    with pytest.raises(ParameterError, match="spring.group.*it has: bottom, left, right, top"):
        assemble(block, Material(1e9, 0.3, 1e3), [Spring("side", (1.0, 1.0))])
    with pytest.raises(ParameterError, match="loads"):
        assemble(block, Material(1e9, 0.3, 1e3), loads=[("top", 1.0)])
    system = assemble(block, Material(1e9, 0.3, 1e3), loads=[Load("top", 1e6)])  # nothing holds it along x
    with pytest.raises(NoSolutionError, match="not held"):
        steady_contact(system, contact_frames(block, "bottom", RigidFlat((0, 0), (0, 1), (1, 0))), 0.0)


def test_a_contact_line_held_by_a_clamp_is_refused(block):
    """A clamped node is held by the clamp, not the contact: clamping the contact group leaves no
    contact; clamping a side that shares one corner with it is fine."""
    from stickslip.fem.scheme import ContactProblem

    system = assemble(block, Material(1e9, 0.3, 1e3), loads=[Load("top", 1e6)])
    frames = contact_frames(block, "bottom", RigidFlat((0.0, 0.0), (0.0, 1.0), (1.0, 0.0)))
    ContactProblem(system, frames, 0.0, ("left",))
    with pytest.raises(ParameterError, match=r"invalid clamped = \['left', 'bottom'\].*they hold \d+ of its \d+ nodes"):
        ContactProblem(system, frames, 0.0, ("left", "bottom"))
