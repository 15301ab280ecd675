"""Complex eigenvalue analysis (CEA) of steady sliding on a general body.

Linearised about steady sliding, every contact node in contact is held normally (its
normal dof is removed) and its friction ``f lambda_n`` acts on its tangential dof, with
``lambda_n`` the normal row of ``K w + C w'`` (the lumped mass has no coupling there). The
tangential rows therefore become ``K_t - f K_n`` and ``C_t - f C_n``: a non-symmetric
(circulatory) stiffness. A friction law that depends on the slip speed adds
``N_i mu'(V)`` to the damping of each tangential dof in contact (``N_i`` the node's steady
normal force): a falling law is negative damping. A coefficient that depends on the pressure
too (``mu(V) g(P)``, `stickslip.friction.PressurePower`) puts each node's ``d(mu g P)/dP =
mu g (1 - n)`` in place of ``f`` in its tangential row, and ``g`` on its slope term. Modes ``w e^{s t}`` solve

    (s^2 M + s C_eff + K_eff) w = 0.

As the linear pencil of ``(w, s w)`` (twice the size), the eigenvalues nearest a shift
``i 2 pi f`` in the complex ``s`` plane are found by shift-invert Arnoldi (a sparse LU of ``K + sigma C + sigma^2 M``, ARPACK
through `scipy.sparse.linalg.eigs`); the shifts step up through the frequency band so that
the discs of the eigenvalues found cover a strip ``|Re s| < complete_below`` along it (more
eigenvalues are asked for where a disc is too small). An eigenvalue found twice is merged
by its eigenvector, never by its value alone (`ModeSet`): a repeated eigenvalue (the
doublets of a symmetric body) is reported once per independent mode.
Reported: ``growth_rate = Re s`` [1/s] and ``frequency = Im s / 2 pi`` [Hz] >= 0, one mode per
complex-conjugate pair; ``growth_rate > NEUTRAL |s|`` is flutter (squeal), within
``NEUTRAL |s|`` of zero the mode is neutral (its sign is round-off).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as sla
import lazy_loader as lazy

from ..quantities import FEM as Q
from ..cf import finish
from ..errors import NoSolutionError, ParameterError
from ..results import Result
from .scheme import BodyScheme, ContactProblem

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["CeaModes", "linearised", "count_sketch", "eigenvalues_near", "covered", "complex_eigenvalues", "NEUTRAL"]

#: Growth rates within ``NEUTRAL |s|`` of zero are neutral (neither flutter nor decay): an
#: eigenvalue is found to about the Arnoldi tolerance (1e-12) times its condition number
#: (1e5 on the examples, from a dense eigensolver's left and right eigenvectors).
NEUTRAL = 1e-7

#: Arnoldi restarts allowed per shift: shift-invert converges in a few where the eigenvalues near
#: the shift are apart; where they crowd (heavy damping) it would grind through ARPACK's default
#: (10 n) for minutes before giving up.
MAX_RESTARTS = 300
#: The band's top at most this times the mesh's highest frequency (no mode lies beyond it).
BAND_MARGIN = 1.5
#: The default penalty of ``contact_model="penalty"``: the springs' stiffness over the stiffness'
#: largest diagonal entry.
PENALTY = 1e3
#: The most eigenvalues a shift asks for by default (a shift costs its pencil's size times the
#: count squared: 1000 on a pad of 6k dofs took minutes).
MAX_COUNT = 400


def linearised(problem: ContactProblem, mass_matrix: str = "lumped", contact_model: str = "constraint",
               penalty: float | None = None):
    """``(K_eff, C_eff or None, mass, kept)``: the linearised operators on the kept dofs
    (the free dofs of `BodyScheme` less the normal dofs of the contact nodes in contact).
    ``mass`` is the lumped mass (a vector) or, with ``mass_matrix="consistent"``, the consistent
    mass matrix with the friction rows applied to it too (its normal rows couple). With
    ``contact_model="penalty"`` the normal dofs in contact are kept, each on a spring of
    ``penalty`` times the stiffness' largest diagonal entry, whose force ``-k w_n`` drives the
    friction ``f`` times it on the tangential dof (converging to the constraint as the penalty grows).
    A steady state that carries no load (`SteadyContact.loaded`) is a `NoSolutionError`: which
    nodes touch it is round-off."""
    mass_matrix = Q.check("mass_matrix", mass_matrix)
    contact_model = Q.check("contact_model", contact_model)
    if contact_model == "penalty":
        penalty = Q.check("penalty", PENALTY if penalty is None else penalty)
    elif penalty is not None:
        raise ParameterError("penalty", penalty, 'left out unless contact_model = "penalty"', also=("contact_model",))
    scheme = BodyScheme(problem)
    K = scheme.stiffness
    if problem.system.S is not None:  # loss factors: K + i S, in the scheme's frames on the free dofs as K
        S = (scheme.rotation.T @ problem.system.S @ scheme.rotation).tocsr()[scheme.free][:, scheme.free]
        K = (K + 1j * S).tocsr()
    normal, tangent = scheme.contact_dofs
    steady = problem.steady
    if not steady.loaded:
        raise NoSolutionError(f"steady sliding carries no contact force (in total {steady.pressure.sum():.3g} N/m, "
                              f"at most {steady.load_floor:.3g} N/m: 1e-10 x young x the body's size), so which nodes "
                              "touch is round-off and there is nothing to linearise about: push the surface into the "
                              "body (surface.interference > 0) or press the body on it with a load")
    touching = steady.active[scheme.contact_nodes]
    normal, tangent = normal[touching], tangent[touching]
    nodes = scheme.contact_nodes[touching]  # positions in frames.nodes
    factor = np.ones(len(nodes))  # a pressure-dependent coefficient: F_t = mu(V) g(P) P, dF_t/dP = mu g (1 - n)
    rate = 1.0
    if problem.pressure_law is not None:
        factor = problem.pressure_law.factor(steady.pressure[nodes] / problem.tributary[nodes])
        rate = problem.pressure_law.rate
    f = problem.friction * factor * rate  # d(friction force) / d(normal force), node by node
    P = sp.csr_matrix((f, (tangent, normal)), shape=K.shape)  # P[t, n] = f_j
    if contact_model == "penalty":  # every free dof kept; the springs' force -k w_n, and f times it on t
        keep = np.arange(scheme.free.size)
        k = penalty * float(np.abs(K.real.diagonal()).max())
        K = K + k * sp.csr_matrix((np.ones(len(normal)), (normal, normal)), shape=K.shape) + k * P
        rows = sp.identity(K.shape[0], format="csr")
    else:  # each tangential row less f times its node's normal row: (I - P) A
        keep = np.setdiff1d(np.arange(scheme.free.size), normal)
        rows = sp.identity(K.shape[0], format="csr") - P

    def effective(A):
        return (rows @ A).tocsr()[keep][:, keep]

    K_eff = effective(K)
    C = problem.system.C
    C_eff = None
    if C is not None:  # in the scheme's frames on the free dofs, as K
        C_eff = effective((scheme.rotation.T @ C @ scheme.rotation).tocsr()[scheme.free][:, scheme.free])
    slope = problem.friction_slope
    if slope != 0.0:  # F = N mu(V - w_t'): d F / d w_t' = -N mu'(V), damping N mu'(V) on the tangential dof
        force = steady.pressure[nodes] * factor
        extra = sp.csr_matrix((force * slope, (np.searchsorted(keep, tangent), np.searchsorted(keep, tangent))),
                              shape=K_eff.shape)
        C_eff = extra if C_eff is None else (C_eff + extra).tocsr()
    if mass_matrix == "consistent":  # in the scheme's frames on the free dofs, as K
        M = (scheme.rotation.T @ problem.system.consistent_mass @ scheme.rotation).tocsr()[scheme.free][:, scheme.free]
        return K_eff, C_eff, effective(M), keep
    return K_eff, C_eff, scheme.mass[keep], keep


@dataclass(frozen=True, eq=False, repr=False)
class CeaModes(Result):
    """Modes of steady sliding in a band: ``s`` (complex, 1/s, ``Im s >= 0``), sorted by growth
    rate (largest first), their ``shapes`` on the kept dofs (if asked) and the ``shifts`` used [Hz].

    Every mode of the band with ``|Re s| < complete_below`` [1/s] (the strip the shifts' trusted
    discs cover) is found; one farther from the frequency axis may be missed. ``asked_below``
    is what was asked for; ``complete`` says whether the sweep covered it."""

    MODEL: ClassVar[str] = "fem"

    s: np.ndarray
    shapes: np.ndarray | None
    shifts: np.ndarray
    band: tuple
    complete_below: float = math.inf
    asked_below: float = 0.0  # the complete_below asked for [1/s]
    params: dict | None = None  # the problem (`ContactProblem.to_attrs`)

    @property
    def growth_rate(self) -> np.ndarray:
        return self.s.real

    @property
    def frequency(self) -> np.ndarray:
        return self.s.imag / (2.0 * np.pi)

    @property
    def complete(self) -> bool:
        """The discs covered the strip asked for (``complete_below >= asked_below``)."""
        return bool(self.complete_below >= self.asked_below)

    @property
    def neutral(self) -> np.ndarray:
        """``|Re s| <= NEUTRAL |s|``: no growth or decay the analysis can resolve."""
        return np.abs(self.growth_rate) <= NEUTRAL * np.abs(self.s)

    @property
    def unstable(self) -> np.ndarray:
        """Growing (flutter) — ``Re s > NEUTRAL |s|``."""
        return self.growth_rate > NEUTRAL * np.abs(self.s)

    def to_dict(self) -> dict:
        return {"modes": [{"growth_rate": float(g), "frequency": float(f)}
                          for g, f in zip(self.growth_rate, self.frequency)],
                "unstable": int(np.sum(self.unstable)), "neutral": int(np.sum(self.neutral)), "band_lo": float(self.band[0]), "band_hi": float(self.band[1]),
                "complete_below": float(self.complete_below), "asked_below": float(self.asked_below),
                "shifts": [float(x) for x in self.shifts], **({"params": self.params} if self.params else {})}

    def to_xarray(self) -> xr.Dataset:
        """The modes along ``mode`` (most unstable first): growth rate [1/s], frequency [Hz],
        flags ``unstable`` and ``neutral``; the shifts [Hz] along ``shift``; the band and
        ``complete_below`` as attributes (the shapes go to ParaView: `stickslip.fem.paraview`)."""
        ds = xr.Dataset({"growth_rate": ("mode", self.growth_rate), "frequency": ("mode", self.frequency),
                         "unstable": ("mode", self.unstable.astype(np.int8), {"units": "1", "long_name":
                                      "mode grows (growth rate above 1e-7 |s|)"}),
                         "neutral": ("mode", self.neutral.astype(np.int8), {"units": "1", "long_name":
                                     "mode neither grows nor decays within 1e-7 |s|"}),
                         "shift": ("shift", self.shifts, {"units": "Hz", "long_name": "shift of the eigenvalue search"})},
                        coords={"mode": ("mode", np.arange(self.s.size), {"units": "1", "long_name":
                                         "index of the mode, most unstable first"})})
        d = self.to_dict()
        return finish(ds, "complex eigenvalue analysis of steady sliding", "fem",
                      params={**(self.params or {}), "unstable_count": d["unstable"], "neutral_count": d["neutral"],
                              **{k: d[k] for k in ("band_lo", "band_hi", "complete_below", "asked_below")
                                 if math.isfinite(d[k])}})  # (a reduced CEA's: every mode of its band, no bound)


def eigenvalues_near(K_eff, C_eff, mass, shift_hz: float, count: int, vectors: bool):
    """The eigenvalues ``s`` found about ``i 2 pi shift_hz``: ``(s, vectors, trusted, upper)``.

    The pencil ``[[0, om I], [-K, -om C]] x = s [[I, 0], [0, om M]] x`` of ``x = (w, s w / om)`` is
    shift-inverted about ``sigma = i 2 pi shift_hz`` (one sparse LU of
    ``K + sigma C + sigma^2 M``, in real arithmetic where ``C`` is zero), so that Arnoldi returns the ``count``
    eigenvalues nearest ``sigma`` in the complex ``s`` plane: a strongly unstable mode (far
    from the imaginary axis) is as near as a neutral one at the same distance. The farthest
    of them may have neighbours just as far that were not returned, so only those nearer than
    0.9 of the farthest are ``trusted``; ``upper`` [Hz] is where that disc meets the axis.
    """
    w0 = 2.0 * math.pi * shift_hz
    n = K_eff.shape[0]
    C = sp.csr_matrix((n, n)) if C_eff is None else C_eff
    M = mass if sp.issparse(mass) else sp.diags(np.asarray(mass, dtype=float))  # lumped (a vector) or a matrix
    sigma = 1j * w0
    lu = _factor(K_eff, C, M, sigma)
    # x = (w, s w / om): with om of the order of the frequencies, both halves of an
    # eigenvector are of one size (with om = 1 Arnoldi loses 1e-6 of s near sigma = 0)
    om = max(w0, math.sqrt(np.mean(np.abs(K_eff.diagonal())) / np.mean(np.abs(M.diagonal()))))

    def solve(x):
        """``(A - sigma B)^-1 B x`` of the scaled pencil, through one solve with
        ``Q(sigma) = K + sigma C + sigma^2 M``."""
        b1, b2 = x[:n], om * (M @ x[n:])
        y1 = -lu.solve(b2 + C @ b1 + sigma * (M @ b1))
        return np.concatenate([y1, (b1 + sigma * y1) / om])

    op = sla.LinearOperator((2 * n, 2 * n), matvec=solve, dtype=complex)
    try:
        nu, vec = sla.eigs(op, k=min(count, 2 * n - 2), return_eigenvectors=True, tol=1e-12, maxiter=MAX_RESTARTS)
    except (sla.ArpackError, sla.ArpackNoConvergence) as err:
        raise NoSolutionError(f"the eigenvalue search did not converge near {shift_hz:.6g} Hz with {count} "
                              f"eigenvalues ({' '.join(str(err).split()[:6])}...): eigenvalues crowd the "
                              "shift") from None
    s = sigma + 1.0 / nu
    dist = np.abs(s - sigma)
    radius = 0.9 * dist.max()
    upper = (w0 + radius) / (2.0 * math.pi)
    flip = s.imag < 0
    trusted = dist < radius
    if np.iscomplexobj(K_eff.data):  # a loss factor: K (1 + i eta) holds for Im s > 0 only, and its pencil's
        trusted &= ~flip  # eigenvalues below the axis are no modes (their conjugates would grow): dropped
    s = np.where(flip, np.conj(s), s)  # one of each conjugate pair: Im s >= 0
    vec = np.where(flip, np.conj(vec), vec)[:n]
    return s, (vec if vectors else None), trusted, upper, radius


class _RealLU:
    """The LU of a real ``Q(sigma)`` solving complex right-hand sides by parts (undamped problems: half
    the memory of a complex LU, and on the 3-D brake a quarter of its time)."""

    def __init__(self, A):
        self.lu = sla.splu(A.tocsc())

    def solve(self, b):
        return self.lu.solve(np.ascontiguousarray(b.real)) + 1j * self.lu.solve(np.ascontiguousarray(b.imag))


def _factor(K, C, M, sigma):
    """The sparse LU of ``Q(sigma) = K + sigma C + sigma^2 M`` (SuperLU): real where ``C`` is zero and
    ``sigma`` imaginary (``Q = K - w^2 M``), complex otherwise."""
    if (C.nnz == 0 or not np.any(C.data)) and not np.iscomplexobj(K.data):
        return _RealLU(K + (sigma**2).real * M)
    return sla.splu((K + sigma * C + sigma**2 * M).astype(complex).tocsc())


def count_sketch(n: int, size: int):
    """A fixed count sketch of vectors of ``n`` entries into ``size`` rows: each entry added, with
    a random sign, to one row (rows ``min(size, n)`` and up stay 0); returns the function giving a
    vector's sketch of unit length. Seeded: the same sketch in every process and every run."""
    rng = np.random.default_rng(20261125)
    row, sign = rng.integers(0, min(size, n), size=n), rng.choice([-1.0, 1.0], size=n)

    def sketch(v) -> np.ndarray:
        x = np.zeros(size, dtype=complex)
        np.add.at(x, row, sign * v)
        return x / np.linalg.norm(x)

    return sketch


class ModeSet:
    """The modes found so far, each eigenvalue with its multiplicity. An eigenvalue found again
    (by an overlapping shift, or as the conjugate of one found) is the same mode only if its
    eigenvector lies in the span of the vectors already found for eigenvalues within
    ``SAME`` (relative) of it; otherwise it is one more member of a repeated eigenvalue (the doublets of a
    symmetric body, which friction splits). The spans are compared in a fixed count sketch
    of ``SKETCH`` rows (each dof added, with a sign, to one row: distances kept to some 5 %,
    memory that does not grow with the mesh)."""

    #: Eigenvalues within this of each other (relative) may be one mode found twice.
    SAME = 1e-6
    #: A vector whose part outside the span of its cluster is below this (relative) is in it.
    IN_SPAN = 1e-6
    SKETCH = 512

    def __init__(self, n: int):
        self._sketch = count_sketch(n, self.SKETCH)
        self.s: list = []
        self.sketches: list = []

    def add(self, s, v) -> bool:
        """Add the eigenpair ``(s, v)`` unless it is a mode already found; True if added."""
        x = self._sketch(v)
        near = [i for i, z in enumerate(self.s) if abs(s - z) <= self.SAME * abs(s)]
        if near:
            q, _ = np.linalg.qr(np.column_stack([self.sketches[i] for i in near]))
            if np.linalg.norm(x - q @ (q.conj().T @ x)) <= self.IN_SPAN:
                return False
        self.s.append(s)
        self.sketches.append(x)
        return True


def covered(centres, radii, lo: float, hi: float) -> float:
    """The half-width [1/s] of the strip ``|Re s| < h`` over the frequencies ``[lo, hi]`` [Hz]
    that the discs about ``i centres`` [rad/s] with ``radii`` [1/s] cover: the lowest point over
    ``[2 pi lo, 2 pi hi]`` of the upper envelope of their circles. Each circle is concave, so
    that lowest point is at an end of the stretch or where two circles cross (any two: a third
    may reach over a neighbour), unless the discs leave part of the stretch uncovered (0)."""
    centres, radii = np.asarray(centres, float), np.asarray(radii, float)
    bottom, top = 2.0 * math.pi * lo, 2.0 * math.pi * hi
    reach = sorted(zip(centres - radii, centres + radii))
    end = bottom
    for a, b in reach:  # the union of the discs' diameters must hold the whole stretch
        if a > end:
            break
        end = max(end, b)
    if end < top:
        return 0.0
    points = [bottom, top]
    for i in range(len(centres)):
        for j in range(i + 1, len(centres)):
            d = centres[j] - centres[i]
            if d == 0:
                continue
            x = centres[i] + (d * d + radii[i] ** 2 - radii[j] ** 2) / (2.0 * d)  # where the circles cross
            if bottom < x < top:
                points.append(x)
    w = np.asarray(points)
    envelope = np.sqrt(np.maximum(radii[:, None] ** 2 - (w[None, :] - centres[:, None]) ** 2, 0.0)).max(axis=0)
    return float(envelope.min())


def complex_eigenvalues(problem: ContactProblem, band: tuple[float, float], count: int = 30,
                        mode_shapes: bool = False, max_shifts: int = 100, complete_below: float | None = None,
                        max_count: int | None = None, mass_matrix: str = "lumped", contact_model: str = "constraint",
                        penalty: float | None = None) -> CeaModes:
    """The modes of steady sliding of ``problem`` with frequencies in ``band`` [Hz] (see the
    module docstring), every one with ``|growth rate| < complete_below`` [1/s] found (default:
    0.1 x 2 pi x the band's top, a mode that grows by a factor 1.9 per period there).

    The first shift asks for ``count`` eigenvalues, doubled (up to ``max_count``, default 16 x
    ``count``, at most 1000) until its trusted disc reaches 1.25 ``complete_below`` off the
    axis (or until doubling widens the disc by less than 1.3: eigenvalues crowd the shift), and
    the next shift starts with the number that sufficed (or afresh, if none did); the next shift sits where that disc's edge crosses ``|Re s| = complete_below``.
    Where ``max_count`` does not suffice the sweep goes on with what it has: the result's
    ``complete_below`` is then what the discs cover (lower than asked)."""
    if not isinstance(problem, ContactProblem) and not callable(getattr(problem, "linearised", None)):
        raise ParameterError("problem", problem, "a ContactProblem or a PairProblem")
    materials = problem.system.materials if isinstance(problem, ContactProblem) else problem.materials
    lo, hi = Q["band"].check_pair(band)
    if not hi > lo:
        raise ParameterError("band", band, "(lo, hi) with hi > lo >= 0 [Hz]")
    top = BAND_MARGIN * problem.omega_max / (2.0 * math.pi)
    if hi > top:
        raise ParameterError("band", [lo, hi], f"[lo, hi] with hi at most {top:.6g} Hz, {BAND_MARGIN:g} x the mesh's "
                             f"highest frequency (beyond it the mesh has no modes; a finer mesh has higher ones)")
    overdamped = _overdamped_band(materials, lo, hi)
    if overdamped:
        raise NoSolutionError(overdamped)
    reach = 0.1 * 2.0 * math.pi * hi if complete_below is None else \
        Q.check("complete_below", complete_below)
    count = Q.check("count", count)
    max_count = None if max_count is None else Q.check("max_count", max_count)
    max_shifts = Q.check("max_shifts", max_shifts)
    if isinstance(problem, ContactProblem):
        K_eff, C_eff, mass, _ = linearised(problem, mass_matrix, contact_model, penalty)
    else:
        K_eff, C_eff, mass, _ = problem.linearised(mass_matrix, contact_model, penalty)
    most = K_eff.shape[0] - 2
    count = min(count, most)
    max_count = min(MAX_COUNT, 16 * count, max(count, most // 2)) if max_count is None else \
        max_count  # (beyond a quarter of the pencil Arnoldi gains nothing)
    max_count = max(count, min(max_count, most))
    modes, shapes, shifts, radii, shift, k = ModeSet(K_eff.shape[0]), [], [], [], lo, count
    while True:
        if len(shifts) >= max_shifts:
            raise NoSolutionError(f"the band {lo:g}-{hi:g} Hz needs more than {max_shifts} shifts of up to "
                                  f"{max_count} eigenvalues: narrow it or raise count")
        before = 0.0
        while True:
            try:
                s, vec, trusted, _, radius = eigenvalues_near(K_eff, C_eff, mass, shift, k, True)
            except NoSolutionError as err:
                raise NoSolutionError(f"{err}{_overdamped(materials)}") from None
            crowded = 0 < before and radius < 1.3 * before  # eigenvalues crowd the shift (heavy damping)
            if radius >= 1.25 * reach or k >= max_count or crowded:
                break
            k, before = min(2 * k, max_count), radius
        if radius < 1.25 * reach:
            k = count  # doubling did not suffice here: the next shift starts afresh
        shifts.append(shift)
        radii.append(radius)
        for j in np.flatnonzero(trusted):
            if modes.add(s[j], vec[:, j]):
                shapes.append(vec[:, j] if mode_shapes else None)
        step = math.sqrt(radius**2 - min(reach, 0.8 * radius) ** 2) / (2.0 * math.pi)  # [Hz]
        if shift + step >= hi:
            break
        shift = max(shift + step, shift * (1 + 1e-9) + 1e-9)
    s = np.array(modes.s, dtype=complex)
    inside = (s.imag / (2 * math.pi) >= lo) & (s.imag / (2 * math.pi) <= hi)
    order = np.argsort(-s.real[inside], kind="stable")
    s = s[inside][order]
    vecs = np.array([shapes[i] for i in np.flatnonzero(inside)[order]]).T if mode_shapes and s.size else None
    reached = covered(2.0 * math.pi * np.array(shifts), np.array(radii), lo, hi)
    options = {"mass_matrix": mass_matrix, "contact_model": contact_model,
               **({} if penalty is None else {"penalty": float(penalty)})}
    return CeaModes(s, vecs, np.array(shifts), (lo, hi), reached, reach, {**problem.to_attrs(), **options})


def _overdamped_band(materials: dict, lo: float, hi: float) -> str:
    """Why no mode of the band ``[lo, hi]`` [Hz] can oscillate, or "": Rayleigh damping gives a
    mode of angular frequency ``w`` the damping ratio ``alpha / (2 w) + beta w / 2``, convex in
    ``w`` (least, ``sqrt(alpha beta)``, at ``w = sqrt(alpha / beta)``). Where it is at least 1
    over the whole band, for every material of the body, every mode there is overdamped, and the
    eigenvalues crowd the real axis, where a shift-invert search only grinds (it took minutes to
    give up). (A body of several materials: each material's least ratio; the band is called
    overdamped only if all of them are at least 1.)"""
    w_lo, w_hi = 2.0 * math.pi * lo, 2.0 * math.pi * hi
    least = math.inf
    for m in materials.values():
        alpha, beta = m.alpha, m.beta

        def ratio(w):
            if w == 0:
                return math.inf if alpha > 0 else 0.0
            return alpha / (2.0 * w) + beta * w / 2.0

        one = min(ratio(w_lo), ratio(w_hi))
        if alpha > 0 and beta > 0 and w_lo < math.sqrt(alpha / beta) < w_hi:
            one = math.sqrt(alpha * beta)
        least = min(least, one)
    if least < 1.0:
        return ""
    said = "; ".join(f"alpha = {m.alpha:g} 1/s, beta = {m.beta:g} s" for m in materials.values())
    return (f"Rayleigh damping ({said}) overdamps every mode of the band {lo:g}-{hi:g} "
            f"Hz (least damping ratio {least:.3g}): no mode there oscillates{_overdamped(materials)}")


def _overdamped(materials: dict) -> str:
    """Where Rayleigh damping overdamps the modes (a mode of frequency ``w`` is overdamped when
    ``alpha + beta w^2 > 2 w``), as advice for a search that failed; of each material."""
    said = [x for x in (_overdamped_one(name, m) for name, m in materials.items()) if x]
    if not said:
        return ""
    return (f": Rayleigh damping overdamps every mode {'; '.join(said)}, and a shift near them finds only that "
            "crowd; keep the band well inside, or damp less")


def _overdamped_one(name: str, material) -> str:
    alpha, beta = material.alpha, material.beta
    if alpha == 0 and beta == 0:
        return ""
    where = f" of {name}" if name else ""
    if alpha * beta >= 1:
        return f"at every frequency{where} (alpha beta >= 1)"
    root = math.sqrt(1.0 - alpha * beta)
    parts = []
    if beta > 0:
        parts.append(f"above {(1 + root) / beta / (2 * math.pi):.4g} Hz (beta puts their eigenvalues near -1/beta)")
    if alpha > 0:
        parts.append(f"below {alpha / (1 + root) / (2 * math.pi):.4g} Hz (alpha puts theirs near 0 and -alpha)")
    return " and ".join(parts) + where
