"""Rigid counter-surfaces with prescribed motion, and the contact frames they give the nodes.

A surface is seen from the body: at a contact node it has the unit normal ``n`` pointing
into the body, the unit tangent ``t`` along which the surface moves (so the surface
velocity there is ``speed * t`` with ``speed >= 0``), and the signed distance ``g`` from
the surface to the node along ``n`` in the reference configuration (``g < 0``: the node
starts inside the rigid body, the interference). Signorini reads ``u . n >= -g``; the
friction of forward slip drags the node along ``t``.

* `RigidCylinder`: a cylinder of ``radius`` about ``center`` turning at ``omega`` [rad/s]
  (counter-clockwise for ``omega > 0``), the body outside it (a shaft in a bore, a disc rim
  under a pad) or, with ``body_inside=True``, inside it (a drum around a seal);
* `RigidFlat`: a straight surface through ``point`` with the normal ``normal`` into the
  body, translating at ``velocity`` (a belt; the component along the normal must be zero).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..quantities import FEM as Q
from ..errors import ParameterError

__all__ = ["RigidCylinder", "RigidFlat", "ContactFrames", "contact_frames", "order_along", "MAX_SPEED"]

#: The fastest surface [m/s] (declared: the range of a flat's velocity).
MAX_SPEED = Q["velocity"].range.hi


@dataclass(frozen=True)
class RigidCylinder:
    """A rigid cylinder turning about ``center`` (see the module docstring)."""

    radius: float
    omega: float
    center: tuple = (0.0, 0.0)
    body_inside: bool = False

    #: the option that says which side of the surface the body is on
    SIDE = "body_inside"

    def __post_init__(self):
        object.__setattr__(self, "radius", Q.check("radius", self.radius))
        object.__setattr__(self, "omega", Q.check("omega", self.omega))
        object.__setattr__(self, "center", Q["center"].check_pair(self.center, "center"))
        if not isinstance(self.body_inside, bool):
            raise ParameterError("body_inside", self.body_inside, "true or false")
        if abs(self.omega) * self.radius > MAX_SPEED:
            raise ParameterError("omega", self.omega, f"at most {MAX_SPEED:g} m/s at the surface in size: "
                                 f"|omega| <= {MAX_SPEED / self.radius:.4g} rad/s", also=("radius",))

    def describe(self) -> str:
        side = "the body inside it" if self.body_inside else "the body outside it"
        return (f"cylinder of radius {self.radius:.9g} m about ({self.center[0]:.9g}, {self.center[1]:.9g}) m turning "
                f"at {self.omega:.9g} rad/s, {side}")

    def geometry(self, points: np.ndarray):
        """``(n, t, g, speed)`` at ``points`` ``(k, 2)``."""
        d = points - np.asarray(self.center)
        r = np.hypot(d[:, 0], d[:, 1])
        if np.any(r == 0):
            raise ParameterError("center", self.center, "off the contact nodes (one sits on the axis)")
        e_r = d / r[:, None]
        n = -e_r if self.body_inside else e_r
        g = (self.radius - r) if self.body_inside else (r - self.radius)
        e_theta = np.column_stack([-e_r[:, 1], e_r[:, 0]])  # counter-clockwise
        t = e_theta if self.omega >= 0 else -e_theta
        return n, t, g, np.full(len(r), abs(self.omega) * self.radius)


@dataclass(frozen=True)
class RigidFlat:
    """A rigid flat translating in its own plane (see the module docstring)."""

    point: tuple
    normal: tuple
    velocity: tuple

    SIDE = "normal"

    def __post_init__(self):
        for name in ("point", "normal", "velocity"):
            object.__setattr__(self, name, Q[name].check_pair(getattr(self, name)))
        if math.hypot(*self.velocity) > MAX_SPEED:
            raise ParameterError("velocity", list(self.velocity), f"at most {MAX_SPEED:g} m/s in size")
        if math.hypot(*self.normal) == 0:
            raise ParameterError("normal", self.normal, "a non-zero vector")
        n = np.asarray(self.normal) / math.hypot(*self.normal)
        if abs(float(np.dot(n, self.velocity))) > 1e-12 * max(1.0, math.hypot(*self.velocity)):
            raise ParameterError("velocity", self.velocity, "along the flat (no component along its normal)")

    def describe(self) -> str:
        return (f"flat through ({self.point[0]:.9g}, {self.point[1]:.9g}) m with normal ({self.normal[0]:.9g}, "
                f"{self.normal[1]:.9g}) into the body, moving at ({self.velocity[0]:.9g}, {self.velocity[1]:.9g}) m/s")

    def geometry(self, points: np.ndarray):
        n = np.asarray(self.normal, float) / math.hypot(*self.normal)
        speed = math.hypot(*self.velocity)
        t = np.asarray(self.velocity, float) / speed if speed > 0 else np.array([-n[1], n[0]])
        g = (points - np.asarray(self.point)) @ n
        k = len(points)
        return np.tile(n, (k, 1)), np.tile(t, (k, 1)), g, np.full(k, speed)


@dataclass(frozen=True, eq=False)
class ContactFrames:
    """Contact nodes (sorted along the contact line), their frames, gaps, surface speeds and
    arclengths [m]; ``closed``: the line closes on itself (a bore); the ``surface`` and the
    boundary ``group`` they were made from (for the record)."""

    nodes: np.ndarray
    normal: np.ndarray
    tangent: np.ndarray
    gap: np.ndarray
    speed: np.ndarray
    arclength: np.ndarray
    closed: bool = False
    surface: object = None
    group: str = ""


def order_along(points: np.ndarray, edges: np.ndarray, nodes: np.ndarray) -> np.ndarray:
    """The nodes of a chain (open or closed) of edges, in order along it."""
    neighbours = {int(v): [] for v in nodes}
    for a, b in edges:
        neighbours[int(a)].append(int(b))
        neighbours[int(b)].append(int(a))
    ends = [v for v, nb in neighbours.items() if len(nb) == 1]
    if any(len(nb) > 2 for nb in neighbours.values()) or len(ends) not in (0, 2):
        raise ParameterError("contact_group", f"{len(edges)} edges", "one chain of edges (a line, open or closed)")
    start = min(ends) if ends else int(nodes[0])
    order, prev = [start], None
    while len(order) < len(nodes):
        nxt = [v for v in neighbours[order[-1]] if v != prev and v not in order[-2:]]
        if not nxt:
            raise ParameterError("contact_group", f"{len(edges)} edges", "one connected chain of edges")
        prev = order[-1]
        order.append(nxt[0])
    return np.asarray(order)


def contact_frames(body, group: str, surface, tolerance: float = 0.05) -> ContactFrames:
    """The frames of the nodes of boundary ``group`` of ``body`` against ``surface``.

    The surface must touch the group: every node within ``tolerance`` times the group's
    length of it (a `ParameterError` naming ``surface`` otherwise), and the body must lie on
    the side the surface's normal points into at every edge of the group (a `ParameterError`
    naming the surface's ``body_inside`` or ``normal`` otherwise: the surface would pull).
    """
    from .body import Body

    if not isinstance(body, Body):
        raise ParameterError("body", body, "a Body (see read_body)")
    if not isinstance(surface, (RigidCylinder, RigidFlat)):
        raise ParameterError("surface", surface, "a RigidCylinder or a RigidFlat")
    tolerance = Q.check("tolerance", tolerance)
    edges = body.segments(group, "contact_group")
    nodes = order_along(body.points, edges, np.unique(edges))
    pts = body.points[nodes]
    n, t, g, speed = surface.geometry(pts)
    seg = np.hypot(*np.diff(pts, axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(seg)])
    length = s[-1] + (np.hypot(*(pts[0] - pts[-1])) if len(edges) == len(nodes) else 0.0)
    if np.max(np.abs(g)) > tolerance * length:
        worst = int(np.argmax(np.abs(g)))
        raise ParameterError("surface", surface, f"touching boundary group {group!r} (its node {int(nodes[worst])} "
                             f"is {g[worst]:.3g} m from it, more than {tolerance:g} x the group's length "
                             f"{length:.3g} m)")
    _check_side(body, group, surface)
    return ContactFrames(nodes, n, t, g, speed, s, closed=len(edges) == len(nodes), surface=surface, group=group)


def _check_side(body, group: str, surface) -> None:
    """Refuse a surface whose normal points out of the body at some edge of ``group``."""
    edges = body.oriented(group, "contact_group")[:, :2]
    a, b = body.points[edges[:, 0]], body.points[edges[:, 1]]
    d = b - a
    inward = np.column_stack([-d[:, 1], d[:, 0]])  # the body is on the left of a counter-clockwise edge
    n = surface.geometry(0.5 * (a + b))[0]
    wrong = np.flatnonzero(np.sum(n * inward, axis=1) <= 0.0)
    if wrong.size:
        value = getattr(surface, surface.SIDE)
        fix = (f"body_inside = {str(not value).lower()}" if surface.SIDE == "body_inside"
               else f"normal = [{0.0 - value[0]:g}, {0.0 - value[1]:g}]")
        raise ParameterError(surface.SIDE, list(value) if surface.SIDE == "normal" else value,
                             f"such that the body lies on the side the surface's normal points into: at "
                             f"{wrong.size} of the {len(edges)} edges of boundary group {group!r} it lies on the "
                             f"other side, where the surface would pull it (try {fix})")
