"""A linear structure with several frictional contacts.

    M x'' + C x' + K x = f(t) + sum_i w_i F_i,   f(t) = f + sum_k (c_k cos W_k t + s_k sin W_k t) + h(t),

``x`` the ``n`` degrees of freedom, ``f(t)`` a constant force, any number of `Harmonic` s and a
`ForceHistory` ``h(t)``, linear between given points (any force in time, to second order in its spacing).
Contact ``i`` acts along its direction ``w_i`` (a vector
of ``n`` numbers: a unit vector for a contact on one degree of freedom, a lever arm or a
difference of two for others) against a surface moving at ``V_i``: its slip velocity is
``v_r = V_i - w_i . x'`` and its friction force follows the paper's convention (eq. [1]),

    slipping (v_r != 0):  F_i = N_i sign(v_r) mu_i(v_r),
    sticking (v_r = 0):   |F_i| <= f_s,i N_i, F_i whatever keeps v_r = 0,

with ``N_i`` its normal force and ``mu_i`` its friction law (`stickslip.friction`). One contact
on a one-degree-of-freedom system is the oscillator of `stickslip.oscillator`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.linalg

from ..errors import ParameterError
from ..friction import FrictionLaw
from ..rsf import RateState
from ..quantities import MAX_CONTACTS, MAX_SYSTEM_DOFS, SYSTEM as Q

__all__ = ["Contact", "System", "Harmonic", "ForceHistory", "MAX_HARMONICS", "MAX_HISTORY_POINTS"]

#: The most harmonics of the external force (each adds two states to the flows).
MAX_HARMONICS = 64
#: The most points of a force history (each piece between two is a flow of its own).
MAX_HISTORY_POINTS = 1_000_000


def _vector(name: str, value, n: int | None, quantity: str) -> np.ndarray:
    arr = np.asarray(Q[quantity].check_array(value, name), dtype=float)
    if arr.ndim != 1 or (n is not None and arr.shape[0] != n):
        want = f"{n} numbers (one per degree of freedom)" if n is not None else "a vector of numbers"
        raise ParameterError(name, value, want)
    return arr


def _matrix(name: str, value, n: int, quantity: str) -> np.ndarray:
    arr = np.asarray(Q[quantity].check_array(value, name), dtype=float)
    if arr.shape != (n, n):
        raise ParameterError(name, value, f"a {n} x {n} matrix (one row and column per degree of freedom; "
                                          f"this one has shape {arr.shape})")
    return arr


def _members(name: str, value, kind: type, vectors: tuple, n: int, least: int, most: int, allowed: str) -> tuple:
    """``value`` as a tuple of ``least`` to ``most`` ``kind`` s whose ``vectors`` (fields, None or
    arrays) have ``n`` entries; a `ParameterError` naming ``name[i].field`` otherwise."""
    items = tuple(value) if isinstance(value, (list, tuple)) else None
    if items is None or not least <= len(items) <= most:
        raise ParameterError(name, value, allowed)
    for i, item in enumerate(items):
        if not isinstance(item, kind):
            raise ParameterError(f"{name}[{i}]", item, f"a stickslip.system.{kind.__name__}")
        for field_name in vectors:
            vec = getattr(item, field_name)
            if vec is not None and vec.shape != (n,):
                raise ParameterError(f"{name}[{i}].{field_name}", vec.tolist(),
                                     f"{n} numbers (one per degree of freedom)")
    return items


@dataclass(frozen=True, eq=False)
class Contact:
    """One frictional contact: ``direction`` ``w`` (n numbers), ``normal_force`` ``N`` [N] > 0,
    its ``friction`` law, and the ``surface_speed`` ``V`` [m/s] of what it rubs on.

    With a ``normal_direction`` ``n`` (n numbers, pointing away from the surface) and a
    ``normal_stiffness`` ``k_n`` [N/m] the contact is unilateral: its normal force is
    ``N(x) = N_0 - k_n n . x`` (``normal_force`` is ``N_0``, the force at ``x = 0``) while it
    is positive, pushes the structure along ``n``, and the contact opens (no force at all) when
    it would pull; it closes again where ``N(x)`` comes back to zero. With
    ``normal_on_structure=False`` the normal force only loads the contact and does not act on
    these degrees of freedom: the normal motion is held by a rigid constraint eliminated from
    the model, whose reaction ``N(x)`` depends on the state (the paper's ring, where ``U = delta``
    in contact and ``P = g delta - D V_theta``); such a contact opening is the constraint
    letting go, which the model does not follow (the run says so).

    With ``rigid=True`` (and ``normal_force=None``) the contact is a rigid unilateral constraint
    ``n . x >= 0`` (the surface at ``n . x = 0``): while closed, ``n . x = 0`` and the normal force is
    the constraint's reaction, whatever keeps it closed; it opens where that reaction reaches zero,
    and closes where the gap ``n . x`` does, by a plastic impact: the velocity along ``n`` is
    lost, with Coulomb's friction impulse (``s f_d`` times the normal impulse slipping the way it
    was; stuck where that would reverse the slip and ``f_s`` allows it); a closed contact nearby whose
    impulse would pull opens, and a contact without a rigid normal takes no impulse. ``n`` is the
    gradient of the gap: its normal force is conjugate to ``n . x`` (a direction twice as long
    measures the gap twice and halves the force, as ``direction`` does for the friction)."""

    direction: np.ndarray
    normal_force: float | None
    friction: FrictionLaw
    surface_speed: float = 0.0
    name: str = ""
    normal_direction: np.ndarray | None = None
    normal_stiffness: float = 0.0
    normal_on_structure: bool = True
    rigid: bool = False

    def __post_init__(self):
        w = _vector("direction", self.direction, None, "direction")
        if not np.any(w):
            raise ParameterError("direction", self.direction, "a vector with at least one entry not zero")
        object.__setattr__(self, "direction", w)
        if not isinstance(self.rigid, (bool, np.bool_)):
            raise ParameterError("rigid", self.rigid, "true or false")
        if self.rigid:
            if self.normal_force is not None:
                raise ParameterError("normal_force", self.normal_force, "None for a rigid contact (its normal force "
                                     "is the constraint's reaction)", also=("rigid",))
            if self.normal_direction is None:
                raise ParameterError("normal_direction", None, "given for a rigid contact (the constraint is "
                                     "n . x >= 0)", also=("rigid",))
            if self.normal_stiffness != 0.0 or not self.normal_on_structure:
                raise ParameterError("normal_stiffness" if self.normal_stiffness != 0.0 else "normal_on_structure",
                                     self.normal_stiffness if self.normal_stiffness != 0.0 else False,
                                     "left at its default for a rigid contact", also=("rigid",))
        else:
            object.__setattr__(self, "normal_force", Q.check("normal_force", self.normal_force))
        object.__setattr__(self, "surface_speed", Q.check("surface_speed", self.surface_speed))
        if not isinstance(self.friction, (FrictionLaw, RateState)):
            raise ParameterError("friction", self.friction, "a stickslip.friction.FrictionLaw or a "
                                 "stickslip.rsf.RateState")
        if not isinstance(self.name, str):
            raise ParameterError("name", self.name, "a text")
        if not isinstance(self.normal_on_structure, (bool, np.bool_)):
            raise ParameterError("normal_on_structure", self.normal_on_structure, "true or false")
        k_n = Q.check("normal_stiffness", self.normal_stiffness)
        object.__setattr__(self, "normal_stiffness", k_n)
        if self.normal_direction is None:
            if k_n != 0.0:
                raise ParameterError("normal_stiffness", k_n, "0 without a normal_direction", also=("normal_direction",))
            return
        nv = _vector("normal_direction", self.normal_direction, w.size, "direction")
        if not np.any(nv):
            raise ParameterError("normal_direction", self.normal_direction, "a vector with at least one entry not zero")
        object.__setattr__(self, "normal_direction", nv)
        mu = getattr(self.friction, "affine", None)
        if self.rigid and (mu is None or mu[1] != 0.0):
            raise ParameterError("friction", type(self.friction).__name__, "Coulomb on a rigid contact (its impacts "
                                 "and reactions are Coulomb's; a law of the slip speed takes a normal_stiffness)")

    @property
    def pushes(self) -> bool:
        """True when the normal force ``N(x) n`` acts on the structure (a unilateral contact
        with ``normal_on_structure``)."""
        return self.unilateral and bool(self.normal_on_structure)

    @property
    def unilateral(self) -> bool:
        """True with a normal direction — the normal force follows the structure and may vanish."""
        return self.normal_direction is not None

    def normal_row(self, n: int, extra: int = 0) -> np.ndarray:
        """``N(x)`` as a row on ``z = (x, v, e, 1)`` (``e`` the ``extra`` states of the harmonic
        forces): ``N_0 - k_n n . x`` (``N_0`` without a normal direction); for a rigid contact the
        gap ``n . x`` (its normal force is a reaction: `stickslip.system.Flow.normal_rows`)."""
        row = np.zeros(2 * n + extra + 1)
        if self.rigid:
            row[:n] = self.normal_direction
            return row
        row[-1] = self.normal_force
        if self.unilateral:
            row[:n] = -self.normal_stiffness * self.normal_direction
        return row

    def slip_velocity(self, v: np.ndarray) -> float:
        """``V - w . v``."""
        return float(self.surface_speed - self.direction @ v)


@dataclass(frozen=True, eq=False)
class Harmonic:
    """A harmonic part of the external force: ``cos * cos(frequency t) + sin * sin(frequency t)``,
    ``frequency`` in rad/s, ``cos`` and ``sin`` [N] one entry per degree of freedom (either may be
    left out: zero). In the flows it is two more states, ``(cos W t, sin W t)``, whose motion is a
    rotation: a forced system stays affine and its flows exact."""

    frequency: float
    cos: np.ndarray | None = None
    sin: np.ndarray | None = None

    def __post_init__(self):
        object.__setattr__(self, "frequency", Q.check("forcing_frequency", self.frequency, "frequency"))
        if self.cos is None and self.sin is None:
            raise ParameterError("cos", None, "an amplitude: cos, sin or both given")
        for name in ("cos", "sin"):
            if getattr(self, name) is not None:
                object.__setattr__(self, name, _vector(name, getattr(self, name), None, "harmonic_force"))


@dataclass(frozen=True, eq=False)
class ForceHistory:
    """A force given in time: ``forces[k]`` (n numbers [N]) at ``times[k]`` [s] (increasing), linear
    in between, ``forces[0]`` before the first time and ``forces[-1]`` after the last. Any force
    ``f(t)`` sampled every ``dt`` is followed to ``O(dt^2)``; between the points the motion stays
    exact: the time is one more state of the flows and each piece's force is affine in it."""

    times: np.ndarray
    forces: np.ndarray

    def __post_init__(self):
        t = np.asarray(Q["history_time"].check_array(self.times, "times"), dtype=float)
        if t.ndim != 1 or not 1 <= t.size <= MAX_HISTORY_POINTS:
            raise ParameterError("times", self.times, f"a list of 1 to {MAX_HISTORY_POINTS} times")
        if t.size > 1 and not np.all(np.diff(t) > 0):
            k = int(np.argmin(np.diff(t) > 0))
            raise ParameterError("times", self.times, f"increasing (times[{k + 1}] = {t[k + 1]:.17g} follows "
                                 f"times[{k}] = {t[k]:.17g})")
        f = np.asarray(Q["force"].check_array(self.forces, "forces"), dtype=float)
        if f.ndim == 1 and t.size == 1:
            f = f[None, :]
        if f.ndim != 2 or f.shape[0] != t.size:
            raise ParameterError("forces", self.forces, f"one list of forces per time ({t.size} lists of one number "
                                 "per degree of freedom)", also=("times",))
        for name, arr in (("times", t), ("forces", f)):
            arr.setflags(write=False)
            object.__setattr__(self, name, arr)

    @property
    def pieces(self) -> int:
        """The pieces of ``h(t)``: before the first time, between each two, after the last."""
        return self.times.size + 1

    def piece(self, k: int) -> tuple[np.ndarray, np.ndarray, float]:
        """``(offset, rate, end)``: ``h(t) = offset + rate t`` on piece ``k``, which lasts until ``end``."""
        t, f = self.times, self.forces
        if k == 0 or k >= t.size:
            return f[min(k, t.size) - 1 if k else 0], np.zeros(f.shape[1]), (t[0] if k == 0 else np.inf)
        rate = (f[k] - f[k - 1]) / (t[k] - t[k - 1])
        return f[k - 1] - rate * t[k - 1], rate, t[k]

    def piece_at(self, t: float) -> int:
        """The piece that holds the time ``t`` (a time on a point begins the next piece)."""
        return int(np.searchsorted(self.times, t, side="right"))

    def __call__(self, t: float) -> np.ndarray:
        """``h(t)``."""
        return np.array([np.interp(t, self.times, col) for col in self.forces.T])


@dataclass(frozen=True, eq=False)
class System:
    """Matrices ``mass`` M (symmetric positive definite), ``stiffness`` K and ``damping`` C
    (any n x n; default none), a constant ``force`` f (n numbers; default none), the
    ``contacts``, ``harmonics``: `Harmonic` parts of the force (default none), and a ``history``:
    a `ForceHistory` added to the force (default none). K and C need not be symmetric (follower
    forces, gyroscopic terms)."""

    mass: np.ndarray
    stiffness: np.ndarray
    contacts: tuple = ()
    damping: np.ndarray | None = None
    force: np.ndarray | None = None
    harmonics: tuple = ()
    history: ForceHistory | None = None
    _chol: np.ndarray = field(init=False, repr=False)
    _cache: dict = field(init=False, repr=False, default_factory=dict)

    def __post_init__(self):
        try:
            shape = np.shape(self.mass)
        except Exception:  # noqa: BLE001 - ragged lists
            shape = ()
        if len(shape) != 2 or shape[0] != shape[1] or not 1 <= shape[0] <= MAX_SYSTEM_DOFS:
            raise ParameterError("mass", self.mass, f"a square matrix of 1 to {MAX_SYSTEM_DOFS} rows")
        n = shape[0]
        M = _matrix("mass", self.mass, n, "mass_matrix")
        if not np.allclose(M, M.T, rtol=1e-12, atol=1e-12 * np.abs(M).max()):
            raise ParameterError("mass", self.mass, "a symmetric matrix")
        try:
            chol = np.linalg.cholesky(M)
        except np.linalg.LinAlgError:
            raise ParameterError("mass", self.mass, "positive definite (a kinetic energy that is never zero "
                                                    "for a moving structure)") from None
        object.__setattr__(self, "mass", M)
        object.__setattr__(self, "_chol", chol)
        object.__setattr__(self, "stiffness", _matrix("stiffness", self.stiffness, n, "stiffness_matrix"))
        C = np.zeros((n, n)) if self.damping is None else _matrix("damping", self.damping, n, "damping_matrix")
        object.__setattr__(self, "damping", C)
        f = np.zeros(n) if self.force is None else _vector("force", self.force, n, "force")
        object.__setattr__(self, "force", f)
        object.__setattr__(self, "contacts", _members("contacts", self.contacts, Contact,
                                                      ("direction", "normal_direction"), n, 1, MAX_CONTACTS,
                                                      f"a list of 1 to {MAX_CONTACTS} Contact"))
        object.__setattr__(self, "harmonics", _members("harmonics", self.harmonics, Harmonic, ("cos", "sin"), n, 0,
                                                       MAX_HARMONICS, f"a list of at most {MAX_HARMONICS} Harmonic"))
        if self.history is not None:
            if not isinstance(self.history, ForceHistory):
                raise ParameterError("history", self.history, "a stickslip.system.ForceHistory")
            if self.history.forces.shape[1] != n:
                raise ParameterError("history.forces", self.history.forces.tolist(),
                                     f"{n} numbers per time (one per degree of freedom)")

    @property
    def dofs(self) -> int:
        return self.mass.shape[0]

    @property
    def extra(self) -> int:
        """The states ``e = (cos W_1 t, sin W_1 t, ..., t)`` of a force changing in time: two per
        `Harmonic`, and the time itself with a `ForceHistory`."""
        return 2 * len(self.harmonics) + (self.history is not None)

    @property
    def size(self) -> int:
        """The length of the flows' state ``z = (x, v, e, 1)``."""
        return 2 * self.dofs + self.extra + 1

    @property
    def forcing_matrix(self) -> np.ndarray:
        """``B``, the harmonic forces ``B e`` (n x `extra`: each harmonic's cos and sin amplitudes, and
        a column of zeros for the time: a history's rate is its piece's, `ForceHistory.piece`; computed once)."""
        if "B" not in self._cache:
            cols = [np.zeros(self.dofs) if getattr(h, name) is None else getattr(h, name)
                    for h in self.harmonics for name in ("cos", "sin")]
            cols += [np.zeros(self.dofs)] * (self.history is not None)
            self._cache["B"] = np.stack(cols, axis=1) if cols else np.zeros((self.dofs, 0))
            self._cache["B"].setflags(write=False)
        return self._cache["B"]

    @property
    def clock(self) -> np.ndarray:
        """``e' = G e + clock``: 1 for the time state of a history, 0 for the harmonics' states."""
        out = np.zeros(self.extra)
        if self.history is not None:
            out[-1] = 1.0
        return out

    @property
    def rotation(self) -> np.ndarray:
        """``G``, the motion ``e' = G e`` of the harmonic states (a rotation at each frequency; the
        time state of a history moves by `clock`)."""
        G = np.zeros((self.extra, self.extra))
        for k, h in enumerate(self.harmonics):
            G[2 * k, 2 * k + 1], G[2 * k + 1, 2 * k] = -h.frequency, h.frequency
        return G

    def phases(self, t: float) -> np.ndarray:
        """``e(t) = (cos W_1 t, sin W_1 t, ..., t)`` (the time with a history)."""
        out = [f(h.frequency * t) for h in self.harmonics for f in (np.cos, np.sin)]
        return np.array(out + [t] * (self.history is not None), dtype=float)

    def state(self, x: np.ndarray, v: np.ndarray, t: float = 0.0) -> np.ndarray:
        """``z = (x, v, e(t), 1)``: the flows' state at time ``t``."""
        return np.concatenate([x, v, self.phases(t), [1.0]])

    def external_force(self, t: float) -> np.ndarray:
        """``f(t)``, the external force at time ``t`` (the constant ``force`` itself without harmonics:
        the rate-and-state equations ask for it at every evaluation)."""
        f = self.force if not self.harmonics else self.force + self.forcing_matrix @ self.phases(t)
        return f if self.history is None else f + self.history(t)

    @property
    def forcing_period(self) -> float | None:
        """The period of ``f(t)``: ``2 pi / W`` with ``W`` the lowest frequency when every other is
        a whole multiple of it (to 1e-12); ``None`` without harmonics, when they are not, or with a history."""
        if not self.harmonics or self.history is not None:
            return None
        low = min(h.frequency for h in self.harmonics)
        ratios = [h.frequency / low for h in self.harmonics]
        if any(abs(r - round(r)) > 1e-12 * r for r in ratios):
            return None
        return 2.0 * np.pi / low

    def unforced(self, what: str) -> None:
        """A `ParameterError` naming ``harmonics`` when the system has harmonic forces: ``what``
        (a steady state, a cycle found on an event section) needs a force constant in time; naming
        ``history`` with a `ForceHistory`."""
        if self.history is not None:
            raise ParameterError("history", f"{self.history.times.size} points", f"none for {what} (a force given in "
                                 "time has no steady state nor periodic motion; stickslip.system.simulate follows it)")
        if self.harmonics:
            raise ParameterError("harmonics", [h.frequency for h in self.harmonics],
                                 f"none for {what} (a force constant in time); the periodic response to a periodic "
                                 "force is stickslip.system.forced_response (stickslip system cycle)")

    @property
    def inverse_mass(self) -> np.ndarray:
        """``M^-1`` (computed once, from the Cholesky factor)."""
        if "minv" not in self._cache:
            self._cache["minv"] = scipy.linalg.cho_solve((self._chol, True), np.eye(self.dofs))
        return self._cache["minv"]

    def apply_inverse_mass(self, X: np.ndarray) -> np.ndarray:
        """``M^-1 X`` (``X`` a vector or columns): a diagonal (lumped) mass's by a division per row."""
        if "mdiag" not in self._cache:
            M = self.mass
            self._cache["mdiag"] = np.diag(M).copy() if not np.any(M - np.diag(np.diag(M))) else None
        d = self._cache["mdiag"]
        if d is None:
            return self.inverse_mass @ X
        return X / d if X.ndim == 1 else X / d[:, None]

    @property
    def inverse_mass_stiffness(self) -> np.ndarray:
        """``M^-1 K`` (computed once, read-only)."""
        return self._product("minvK", self.stiffness)

    @property
    def inverse_mass_damping(self) -> np.ndarray:
        """``M^-1 C`` (computed once, read-only)."""
        return self._product("minvC", self.damping)

    def _product(self, key: str, X: np.ndarray) -> np.ndarray:
        if key not in self._cache:
            self._cache[key] = self.apply_inverse_mass(X)
            self._cache[key].setflags(write=False)
        return self._cache[key]

    @property
    def directions(self) -> np.ndarray:
        """``W``: one column per contact (computed once)."""
        return self._columns("W", lambda c: c.direction)

    @property
    def normal_units(self) -> np.ndarray:
        """Each contact's normal direction ``n`` as a column (zero without one; computed once)."""
        return self._columns("n", lambda c: c.normal_direction if c.unilateral else np.zeros(self.dofs))

    @property
    def normal_directions(self) -> np.ndarray:
        """``k_n n`` of each contact as a column (zero without a normal direction; computed once)."""
        return self._columns("Kn", lambda c: c.normal_stiffness * c.normal_direction if c.unilateral
                             else np.zeros(self.dofs))

    @property
    def normal_rows(self) -> np.ndarray:
        """Each contact's normal force ``N(x)`` as a row on ``z = (x, v, e, 1)`` (`Contact.normal_row`;
        computed once)."""
        return self._columns("N", lambda c: c.normal_row(self.dofs, self.extra)).T

    def _columns(self, key: str, column) -> np.ndarray:
        """``column(contact)`` of every contact side by side, made once and read-only."""
        if key not in self._cache:
            self._cache[key] = np.stack([column(c) for c in self.contacts], axis=1)
            self._cache[key].setflags(write=False)
        return self._cache[key]
