"""The modally reduced CEA of a pair of bodies (2-D or solids): the reduction commercial tools use.

About steady sliding (`stickslip.fem.pair.steady_pair`: its active set), the contact is the
penalty model of the full CEA (`PairProblem.linearised(contact_model="penalty")`): each active
slave node's normal force a spring on its gap, ``k = penalty x`` the stiffness' largest diagonal
entry, so that on the free degrees of freedom the stiffness at a Coulomb friction ``mu`` is

    K(mu) = K0 + mu F,    K0 = K + k G_A^T W^-2 G_A (symmetric),    F = k T_A^T W^-2 G_A,

(``G_A``, ``T_A`` the active nodes' weighted normal and sliding rows, ``W`` their weights). The basis
is the ``count`` lowest real modes ``Phi`` of the undamped structure with its contact springs,
``K0 Phi = M Phi Omega^2`` (a sparse shift-invert Lanczos), by default with static responses to
the modes' contact forces (``augment``: see `modal_basis`), as Ritz vectors ``Psi``
(``Psi^T M Psi = I``), and the complex problem is solved in that subspace,
``(s^2 I + s Psi^T C Psi + Psi^T K(mu) Psi) q = 0``
(``C`` the bodies' Rayleigh damping; with the pair's ``transverse_damping`` plus ``mu`` times the
damping of the friction turning across per unit coefficient, about the problem's steady pressures), densely: cheap enough that a friction sweep costs one
eigen-solve of size ``2 count`` per point. What is left out: the modes above the basis (the error
the full CEA shows: `reduced_error`), and the change of the active set with the friction (held at
the steady sliding's, as those tools hold the preload's).

`reduced_sweep(basis, frictions, band)` tracks the modes from point to point by the MAC of their
modal coordinates (`stickslip.fem.tracking.track`) and locates each branch's critical friction by
the shared multisection (`stickslip.fem.critical.search`) on the reduced problem.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.linalg as la
import scipy.sparse as sp

from ..errors import NoSolutionError, ParameterError
from ..quantities import FEM as Q
from ..validation import count as checked_count
from .cea import PENALTY, CeaModes
from .critical import search
from .pair import PairProblem
from .tracking import Tracked, track

__all__ = ["ModalBasis", "modal_basis", "config_basis", "reduced_modes", "reduced_sweep", "MAX_BASIS"]

#: The most real modes of a basis (dense problems of twice this size).
MAX_BASIS = 2000


@dataclass(frozen=True, eq=False)
class ModalBasis:
    """A pair's reduction basis: ``frequencies`` [Hz] (the real modes', then with ``augment`` the Ritz
    values of the basis that holds them and the static vectors), ``shapes`` (free dofs x vectors,
    mass-orthonormal, ``K0``-orthogonal), the reduced ``stiffness`` ``Psi^T K0 Psi``, ``friction_stiffness``
    ``Psi^T F Psi`` (per unit friction coefficient), ``damping`` ``Psi^T C Psi`` (None: undamped); ``modes``
    the real modes computed, ``top`` [Hz] the highest of them, ``augmented`` the static vectors kept;
    the problem's ``friction``, ``free`` dofs, ``penalty`` and attributes ``params``."""

    frequencies: np.ndarray
    shapes: np.ndarray
    stiffness: np.ndarray
    friction_stiffness: np.ndarray
    damping: np.ndarray | None
    friction: float
    free: np.ndarray
    penalty: float
    params: dict
    modes: int = 0
    top: float = 0.0
    augmented: int = 0
    structural: np.ndarray | None = None  # Psi^T S Psi of the materials' loss factors (None: none)
    transverse: np.ndarray | None = None  # Psi^T C_b Psi per unit friction: the force turning across (None: left out)

    @property
    def count(self) -> int:
        return len(self.frequencies)


def _parts(problem: PairProblem, penalty: float):
    """``(K0, F, M, C, free, active, springs)`` on the free degrees of freedom (see the module
    docstring; ``springs = K0 - K``, the contact's)."""
    st = problem.steady
    if not st.loaded:
        raise NoSolutionError("steady sliding of the pair carries no contact force: press the bodies together")
    sup = problem.supports
    A = np.flatnonzero(st.active)
    K = sup.restrict(problem.K)
    k = penalty * float(np.abs(K.diagonal()).max())
    G = sup.columns(problem.G[A])
    W2G = sp.diags(1.0 / problem.coupling.weight[A] ** 2) @ G
    springs = (k * G.T @ W2G).tocsc()
    K0 = (K + springs).tocsc()
    F = (k * sup.columns(problem.T[A]).T @ W2G).tocsc()
    C = None if problem.C is None else sup.restrict(problem.C)
    return K0, F, sup.mass(problem.mass), C, sup.free, A, springs


#: Static vectors solved at once (a block of right-hand sides).
BLOCK = 64


def modal_basis(problem: PairProblem, count: int, penalty: float | None = None, augment: str = "modes") -> ModalBasis:
    """The ``count`` lowest real modes of ``problem`` about its steady sliding with the contact's
    penalty springs (one more where the last is one of a repeated pair), (``penalty`` as the full CEA's, default `stickslip.fem.cea.PENALTY`), and the
    reduced operators (see the module docstring).

    The friction forces' local, static part is what the modes of a stiff contact reach only through
    its stiffest modes, so by default static vectors are added and the basis is the Ritz vectors of
    all (``(K0 - sigma M)^-1 loads``, ``sigma`` just below the lowest mode):
    ``augment="modes"`` (the default): two per mode, the responses to its friction forces ``F phi``
    and to its contact springs' forces ``(K0 - K) phi``; ``augment="nodes"``: two per active contact
    node, the responses to a unit normal and a unit sliding force there (every contact force is in
    their span; costly where the contact has thousands of nodes); ``augment="none"``: the modes alone,
    the reduction commercial tools use. On a pad on a block of 240 dofs, 80 modes alone left a growth
    rate 110 1/s off the full CEA's 3552 and the critical friction 0.9 % off (1-5 % from 20 to 160
    modes, not converging); with the nodes' static vectors 0.03 1/s and 1.3e-4, the modes' 0.04 1/s
    and 1.2e-4; but with 20 modes the modes' static vectors gave a spurious instability (a critical
    friction 43 % low): check a result against a basis of twice the modes (or the full CEA).
    Coulomb friction only: a friction law or a pressure law is refused (their coefficients vary with
    the sliding speed and the pressure)."""
    from scipy.sparse.linalg import LinearOperator, eigsh, splu

    if not isinstance(problem, PairProblem):
        raise ParameterError("problem", problem, "a stickslip.fem.PairProblem")
    if problem.law is not None or problem.pressure_law is not None:
        raise ParameterError("problem", "a pair with a friction or pressure law", "a pair with Coulomb friction "
                             "(the reduced CEA of laws comes in a later release; the full CEA takes them)")
    if augment not in ("modes", "nodes", "none"):
        raise ParameterError("augment", augment, "'modes' (static vectors of each mode's contact forces), 'nodes' "
                             "(of unit forces at each contact node) or 'none'")
    penalty = Q.check("penalty", PENALTY if penalty is None else penalty)
    K0, F, mass, C, free, active, springs = _parts(problem, penalty)
    count = checked_count("count", count, max(2, min(MAX_BASIS, free.size - 2)), "modes")
    # below the lowest mode (the pair may still move freely), by the structure's typical stiffness over mass
    # (not the largest: the contact springs' would put the shift far below the modes, and Lanczos would crawl)
    shift = -1e-6 * float(np.median(K0.diagonal() / mass))
    start = np.random.default_rng(20261128).standard_normal(free.size)  # the same basis in every run
    lu = splu((K0 - shift * sp.diags(mass)).tocsc())  # one factorisation for Lanczos and the static vectors
    inverse = LinearOperator(K0.shape, matvec=lu.solve, dtype=float)
    values, phi = eigsh(K0, k=min(count + 2, free.size - 1), M=sp.diags(mass).tocsc(), sigma=shift, which="LM",
                        v0=start, OPinv=inverse)
    order = np.argsort(values)
    values, phi = values[order], phi[:, order]
    while count < len(values) and values[count] - values[count - 1] <= 1e-6 * values[count]:
        count += 1  # a repeated mode (a disc's doublet) is kept whole: half of one makes the basis arbitrary
    values, phi = values[:count], phi[:, :count]
    top = float(np.sqrt(max(values.max(), 0.0)) / (2 * math.pi))
    vectors = [phi]
    if augment != "none":
        if augment == "nodes":
            sup = problem.supports
            loads = sp.vstack([sup.columns(problem.G[active]), sup.columns(problem.T[active])]).T.tocsc()
        else:
            loads = sp.csc_matrix(np.hstack([F @ phi, springs @ phi]))
        vectors += [lu.solve(loads[:, j:j + BLOCK].toarray()) for j in range(0, loads.shape[1], BLOCK)]
    V = np.hstack(vectors)
    root = np.sqrt(mass)[:, None]
    V = V / np.linalg.norm(root * V, axis=0)[None, :]
    U, sigma, _ = la.svd(root * V, full_matrices=False)  # mass-orthonormal, dependent vectors dropped
    V = U[:, sigma > 1e-10 * sigma[0]] / root
    Kv = V.T @ (K0 @ V)
    ritz, Y = la.eigh(0.5 * (Kv + Kv.T))
    psi = V @ Y
    Cr = None if C is None else psi.T @ (C @ psi)
    Sr = None if problem.S is None else psi.T @ (problem.supports.restrict(problem.S) @ psi)
    Tr = None
    if problem.transverse_damping:  # per unit friction, about the problem's steady sliding (its pressures)
        unit = problem.supports.restrict(problem.transverse_matrix(np.ones(len(problem.coupling.weight))))
        Tr = psi.T @ (unit @ psi)
    return ModalBasis(np.sqrt(np.clip(ritz, 0.0, None)) / (2 * math.pi), psi, np.diag(ritz), psi.T @ (F @ psi),
                      Cr, float(problem.friction), free, float(penalty), problem.to_attrs(), count, top,
                      psi.shape[1] - count, Sr, Tr)


def config_basis(config, problem: PairProblem) -> ModalBasis:
    """The basis of ``problem`` as its config (`stickslip.fem.config.FemConfig`) asks in ``[cea]``:
    ``reduced_modes`` real modes, ``augment``, ``penalty``."""
    if getattr(config, "reduced", None) is None:
        raise ParameterError("cea.reduced_modes", None, "given in the config for a reduced CEA")
    return modal_basis(problem, config.reduced["count"], config.cea_options.get("penalty"), config.reduced["augment"])


def _eigen(basis: ModalBasis, friction: float):
    """``(s, q)``: every eigenvalue of the reduced problem at ``friction`` with ``Im s >= 0`` and its
    modal coordinates (columns)."""
    n = basis.count
    K = basis.stiffness + friction * basis.friction_stiffness
    if basis.structural is not None:  # loss factors: K + i S (its eigenvalues below the axis are no modes)
        K = K + 1j * basis.structural
    C = np.zeros((n, n)) if basis.damping is None else basis.damping
    if basis.transverse is not None:  # the friction's turning across: in proportion to the coefficient
        C = C + friction * basis.transverse
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-K, -C]])
    s, v = la.eig(A)
    keep = s.imag >= 0
    q = v[:n, keep]
    return s[keep], q / np.linalg.norm(q, axis=0)[None, :]


def reduced_modes(basis: ModalBasis, friction: float | None = None, band=None, mode_shapes: bool = False) -> CeaModes:
    """The modes of the reduced problem at ``friction`` (default the problem's) with frequencies in
    ``band`` [Hz] (default up to half the highest real mode of the basis: above it the truncation shows),
    most unstable first, as the full CEA's `CeaModes` (the shapes ``Phi q`` on the free dofs)."""
    if not isinstance(basis, ModalBasis):
        raise ParameterError("basis", basis, "a ModalBasis (modal_basis)")
    friction = basis.friction if friction is None else Q.check("friction", friction)
    lo, hi = (0.0, 0.5 * basis.top) if band is None else Q["band"].check_pair(band)
    if not hi > lo:
        raise ParameterError("band", band, "(lo, hi) with hi > lo >= 0 [Hz]")
    s, q = _eigen(basis, friction)
    f = s.imag / (2 * math.pi)
    inside = np.flatnonzero((f >= lo) & (f <= hi))
    order = inside[np.argsort(-s.real[inside], kind="stable")]
    shapes = basis.shapes @ q[:, order] if mode_shapes else None
    return CeaModes(s[order], shapes, np.zeros(0), (lo, hi), math.inf, 0.0,
                    {**basis.params, "friction": friction, "contact_model": "penalty", "penalty": basis.penalty,
                     "reduced_modes": basis.modes, "static_vectors": basis.augmented, "basis_top_hz": basis.top})


def reduced_sweep(basis: ModalBasis, frictions, band=None, tol: float = 1e-4) -> Tracked:
    """The reduced CEA at each of ``frictions`` (increasing), its modes in ``band`` tracked by the
    MAC of their modal coordinates, each branch's critical friction found to ``tol`` of the sweep's
    step (`stickslip.fem.critical.search`, on the reduced problem)."""
    import dask

    if not isinstance(basis, ModalBasis):
        raise ParameterError("basis", basis, "a ModalBasis (modal_basis)")
    try:
        values = np.asarray(frictions, dtype=float).ravel()
    except (TypeError, ValueError):
        raise ParameterError("frictions", frictions, "increasing friction coefficients") from None
    if values.size < 2 or np.any(np.diff(values) <= 0):
        raise ParameterError("frictions", frictions, "at least two increasing friction coefficients")
    for v in values:
        Q.check("friction", float(v), "frictions")
    tol = Q.check("onset_tolerance", tol, "tol")
    band = reduced_modes(basis, values[0], band).band

    lo, hi = band

    def solve(value):
        s, q = _eigen(basis, value)
        f = s.imag / (2 * math.pi)
        inside = np.flatnonzero((f >= lo) & (f <= hi))
        order = inside[np.argsort(-s.real[inside], kind="stable")]
        return s[order], q[:, order].T

    points = [solve(v) for v in values]
    s, _ = track([p[0] for p in points], [p[1] for p in points])
    found = search(values, s, [p[0] for p in points], [p[1] for p in points], tol, solve,
                   lambda calls: dask.compute(*calls, scheduler="synchronous"))
    return Tracked("friction", values, s, found.onset, found.frequency, found.partner, found.turn, tol, band)
