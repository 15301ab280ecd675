"""An independent solver for the tests of the paper's waves in time: explicit finite elements of a
periodic elastic strip on a rigid body, and the steady elastodynamic field of a wave in its bulk.
Nothing here comes from `stickslip.sbim`; scikit-fem assembles the strip.

**The steady field** (`SteadyField`). The half-space ``y > 0`` above a rigid body at rest, its surface
held in contact (``u_y = 0``) with ``u_x = W t + f(x - c t)``, ``|c| < c_s``. From Navier's equations,
with potentials ``u = grad phi + curl(psi e_z)`` and, for a mode ``E = exp(i k (x - c t))``,
``phi = A exp(-|k| a_p y) E``, ``psi = B exp(-|k| a_s y) E``, ``a_p = sqrt(1 - c^2/c_p^2)``,
``a_s = sqrt(1 - c^2/c_s^2)``: ``u_y(0) = 0`` gives ``B = i sign(k) a_p A`` and ``u_x(0) = F_k`` gives
``A = F_k / (i k (1 - a_p a_s))``; the surface tractions are then

    sigma_xy = -G |k| a_p (c / c_s)^2 / (1 - a_p a_s) F_k,
    sigma_yy = i k F_k [lambda - (lambda + 2 G) a_p (a_p - a_s) / (1 - a_p a_s)],

plus the mean part, a plane S wave ``u_x = W (t - y / c_s)`` (``sigma_xy = -G W / c_s``), plus a
uniform prestress. ``f`` is the integral of the slip rate's travelling part: ``-c f' = V - W``.

**The strip** (`Strip`): ``0 <= x < L`` periodic, ``0 <= y <= H``, plane strain, bilinear quadrilaterals
(uniform ``h = L / N`` to 0.7 m deep, then graded), lumped mass, central differences. The far side
``y = H`` follows the steady field (what it carries there), the surface ``y = 0`` is pressed on the
rigid body: each step the normal reaction that keeps it closed, and the tangential one that holds a node
stuck unless it exceeds ``mu`` times the normal one, when the node slides against it at that value
(Coulomb, the static coefficient the kinetic one); or, ``kinematic``, the surface's motion prescribed.

**The friction step's grid-scale modes.** With the strength taken node by node from the normal
reaction, uniform sliding grows at the grid's scale (about ``0.04 c_s k_max``: from 1e-6 noise, 7.7e-7,
4.9e-6, 3.8e-4 and 1.7 after 2.5e-4 s on 64, 128, 256 and 512 elements), though the continuum's
held sliding has no growing mode at these frictions. ``smooth`` passes of a (1/4, 1/2, 1/4) filter
on the normal reaction the strength is taken from (about 1.4 cells wide after 4 passes, so shrinking
with the grid) keep it stable to 1024 elements; the runs below 256 elements agree with and without it.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp


class SteadyField:
    """The steady field of a stick-slip wave (`stickslip.halfspace.StickSlipWave`) in the run's frame: the
    half-space (``G`` [Pa], ``c_s`` [m/s], Poisson's ratio the wave's) above a rigid body at rest, a stick
    zone ``a`` [m] long; ``M`` points of the surface per period (``M`` a power of two)."""

    def __init__(self, wave, G: float, cs: float, a: float, M: int = 2**16, modes: np.ndarray | None = None):
        self.wave, self.G, self.cs, self.a, self.M = wave, G, cs, a, M
        nu = wave.nu
        self.lam = 2 * G * nu / (1 - 2 * nu)
        self.cp = cs * np.sqrt((self.lam + 2 * G) / G)
        self.rho = G / cs**2
        self.L, self.c, self.mu = wave.b * a, wave.cbar * cs, wave.mu
        self.ap, self.as_ = np.sqrt(1 - self.c**2 / self.cp**2), np.sqrt(1 - self.c**2 / cs**2)
        self.k = 2 * np.pi * np.fft.fftfreq(M, self.L / M)
        if modes is None:  # the wave's own surface: f from its slip rate, by Gauss-Legendre cell by cell
            self.W, self.F = self._wave_modes()
            self.sig0 = (-G * wave.tau_xy + G / cs * self.W, G * wave.tau_yy)  # the uniform load
        else:  # given Fourier coefficients of f (numpy's fft over M, divided by M), no mean slip, no load
            self.W, self.F, self.sig0 = 0.0, np.asarray(modes, complex), (0.0, 0.0)
        k, ap, as_ = self.k, self.ap, self.as_
        with np.errstate(divide="ignore", invalid="ignore"):
            self.A = np.where(k != 0, self.F / (1j * k * (1 - ap * as_)), 0)
        self.B = 1j * np.sign(k) * ap * self.A
        self.Cs = -G * ap * (self.c / cs) ** 2 / (1 - ap * as_)
        self.Cn = self.lam - (self.lam + 2 * G) * ap * (ap - as_) / (1 - ap * as_)

    def data(self, X):
        """The wave's slip rate, shear and normal tractions at pattern positions ``X`` [m] (run frame: the
        wave reflected, seen from the rigid body), and whether each is on the slip zone."""
        f = self.wave.fields(np.mod(np.asarray(X) / self.a, self.wave.b))
        return {"slip_rate": -self.cs * f.slip_velocity, "shear_stress": -self.G * f.Sigma_xy,
                "normal_traction": self.G * f.Sigma_yy, "slip": np.asarray(f.slip, bool)}

    def _wave_modes(self):
        from numpy.polynomial.legendre import leggauss

        M, L = self.M, self.L
        h = L / M
        gx, gw = leggauss(6)
        edges = np.arange(M) * h
        points = edges[:, None] + h * (gx[None, :] + 1) / 2
        cell = (self.data(points)["slip_rate"] * gw).sum(axis=1) * h / 2
        last = 0.0  # the last cell, against the healing edge's singular rate: halved 60 times towards it
        for j in range(60):
            lo, hi = L - h * 2.0**-j, L - h * 2.0 ** -(j + 1)
            last += (self.data(lo + (hi - lo) * (gx + 1) / 2)["slip_rate"] * gw).sum() * (hi - lo) / 2
        cell[-1] = last
        W = cell.sum() / L
        f = -np.concatenate([[0.0], np.cumsum(cell - W * h)])[:-1] / self.c
        f -= f.mean()
        return W, np.fft.fft(f) / M

    def surface_tractions(self, modes: int, shift: float = 0.0):
        """The shear and normal tractions of the field at ``X = m L / M + shift``, from its modes up to
        ``modes``."""
        index = np.abs(np.fft.fftfreq(self.M, 1.0 / self.M))
        keep = (index <= modes) * np.exp(1j * self.k * shift)
        sxy = np.fft.ifft(keep * self.Cs * np.abs(self.k) * self.F).real * self.M
        syy = np.fft.ifft(keep * self.Cn * 1j * self.k * self.F).real * self.M
        return self.sig0[0] - self.G * self.W / self.cs + sxy, self.sig0[1] + syy

    def rows(self, N: int, ys, t: float, velocity: bool = False):
        """``u`` (or its rate) at ``x_i = i L / N`` (pattern ``X = x_i + L / (2 N) - c t``) at each depth."""
        M, k, kap = self.M, self.k, np.abs(self.k)
        phase = np.exp(1j * k * (self.L / (2 * N) - self.c * t)) * ((-1j * k * self.c) if velocity else 1.0)
        ux, uy = np.empty((len(ys), N)), np.empty((len(ys), N))
        for j, y in enumerate(ys):
            ep, es = np.exp(-kap * self.ap * y), np.exp(-kap * self.as_ * y)
            cx = (1j * k * self.A * ep - kap * self.as_ * self.B * es) * phase
            cy = (-kap * self.ap * self.A * ep - 1j * k * self.B * es) * phase
            ux[j] = (np.fft.ifft(cx).real * M)[:: M // N] + (self.W if velocity else self.W * (t - y / self.cs))
            uy[j] = (np.fft.ifft(cy).real * M)[:: M // N]
        return ux, uy


class Strip:
    """The periodic strip of ``N`` elements along ``L`` [m], ``H`` [m] deep, of ``field``'s solid."""

    def __init__(self, field: SteadyField, N: int, H: float = 1.5):
        from skfem import Basis, BilinearForm, ElementQuad1, ElementVector, MeshQuad, asm
        from skfem.helpers import dot
        from skfem.models.elasticity import linear_elasticity

        self.field, self.N, self.h = field, N, field.L / N
        ys, dy = [0.0], self.h
        while ys[-1] < H - 1e-12:
            if ys[-1] >= 0.7:
                dy = min(dy * 1.05, 8 * self.h, max(0.05, self.h))
            ys.append(ys[-1] + dy)
        self.ys = np.array(ys) * H / ys[-1]
        mesh = MeshQuad.init_tensor(np.arange(N + 1) * self.h, self.ys)
        basis = Basis(mesh, ElementVector(ElementQuad1()))
        rho = field.rho
        K = asm(linear_elasticity(field.lam, field.G), basis)
        Mc = asm(BilinearForm(lambda u, v, w: rho * dot(u, v)), basis)
        node = np.round(mesh.p[0] / self.h).astype(int) % N + N * np.searchsorted(self.ys, mesh.p[1] - 1e-12 * H)
        n = mesh.p.shape[1]
        dofs = basis.nodal_dofs
        P = sp.csr_matrix((np.ones(2 * n), (np.concatenate(dofs), np.concatenate([2 * node, 2 * node + 1]))),
                          shape=(2 * n, 2 * N * len(self.ys)))  # the right edge's nodes are the left's
        self.K = (P.T @ K @ P).tocsr()
        self.m = np.asarray((P.T @ Mc @ P).sum(axis=1)).ravel()
        self.size = 2 * N * len(self.ys)

    def stable_dt(self) -> float:
        """0.9 of the central-difference limit, 2 / sqrt(the largest eigenvalue of M^-1 K) (power iteration)."""
        x, eig = np.random.default_rng(0).standard_normal(self.size), 0.0
        for _ in range(300):
            y = (self.K @ x) / self.m
            new = np.linalg.norm(y) / np.linalg.norm(x)
            x = y / np.linalg.norm(y)
            if abs(new - eig) < 1e-7 * new:
                break
            eig = new
        return 0.9 * 2.0 / np.sqrt(1.02 * new)

    def state(self, t: float, velocity: bool = False, rows=None):
        ux, uy = self.field.rows(self.N, self.ys if rows is None else rows, t, velocity)
        return ux.ravel(), uy.ravel()

    def run(self, T: float, report, kinematic: bool = False, smooth: int = 0) -> dict:
        """From the steady field at ``t = 0`` to ``T`` [s]: the surface's velocity along x (the mean of the
        half steps around each time in ``report``), the first half step's, and, ``kinematic`` (the surface
        moved as the field's), its tractions at ``report``; ``smooth``: the filter's passes (module
        docstring)."""
        f, N = self.field, self.N
        steps = int(np.ceil(T / self.stable_dt() / 16.0)) * 16
        dt = T / steps
        at = {int(round(t / dt)) for t in report}
        u, v = np.empty(self.size), np.empty(self.size)
        u[0::2], u[1::2] = self.state(0.0)
        v[0::2], v[1::2] = self.state(-dt / 2, velocity=True)
        sx, sy = 2 * np.arange(N), 2 * np.arange(N) + 1
        top = N * (len(self.ys) - 1) + np.arange(N)
        tx, ty = 2 * top, 2 * top + 1
        ms = self.m[sx]
        load = np.zeros(self.size)
        load[sx], load[sy] = self.h * f.sig0[0], self.h * f.sig0[1]
        out = {"t": [], "V": [], "shear": [], "normal": [], "first": None}
        for n in range(steps + 1):
            t = n * dt
            w = v + dt * (load - self.K @ u) / self.m
            far = self.state(t + dt, rows=self.ys[-1:])
            w[tx], w[ty] = (far[0] - u[tx]) / dt, (far[1] - u[ty]) / dt
            if kinematic:
                vx = (self.state(t + dt, rows=[0.0])[0] - u[sx]) / dt
                Rx, Ry = ms * (vx - w[sx]) / dt, -ms * (u[sy] / dt + w[sy]) / dt
            else:
                Ry = np.maximum(-ms * (u[sy] / dt + w[sy]) / dt, 0.0)  # what keeps the node closed, if pressing
                stick = -ms * w[sx] / dt
                strength = Ry
                for _ in range(smooth):
                    strength = 0.5 * strength + 0.25 * (np.roll(strength, 1) + np.roll(strength, -1))
                strength = f.mu * strength
                Rx = np.where(np.abs(stick) <= strength, stick, strength * np.sign(stick))
            w[sx] += dt * Rx / ms
            w[sy] += dt * Ry / ms
            if n == 0:
                out["first"] = w[sx].copy()
            if n in at:
                out["t"].append(t)
                out["V"].append(0.5 * (v[sx] + w[sx]))
                out["shear"].append(-Rx / self.h)
                out["normal"].append(-Ry / self.h)
            v = w
            u = u + dt * v
        out["dt"] = dt
        return out
