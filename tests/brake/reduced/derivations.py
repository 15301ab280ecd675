"""Independent sympy derivations for the brake-like system (no code from stickslip).

Polar strains and stresses are obtained from the Cartesian ones (chain rule and a
rotation), not typed in, so the derivations below check the textbook polar formulas too.
Lengths in units of R, stresses in units of E, time t = Omega t̄ (paper, above [10]).
"""

from __future__ import annotations

from functools import cache

import sympy as sp
from sympy.calculus.euler import euler_equations

r, th, xi = sp.symbols("r theta xi", positive=True)
nu, gamma, delta, f = sp.symbols("nu gamma delta f", positive=True)
LAM = nu / ((1 + nu) * (1 - 2 * nu))  # lambda / E
MU = 1 / (2 * (1 + nu))  # mu / E


def polar_fields(ur, ut):
    """Polar strain and stress components of the displacement ``ur e_r + ut e_theta``."""
    c, s = sp.cos(th), sp.sin(th)
    ux, uy = ur * c - ut * s, ur * s + ut * c
    ddx = lambda F: c * sp.diff(F, r) - s / r * sp.diff(F, th)  # noqa: E731
    ddy = lambda F: s * sp.diff(F, r) + c / r * sp.diff(F, th)  # noqa: E731
    grad = sp.Matrix([[ddx(ux), ddy(ux)], [ddx(uy), ddy(uy)]])
    eps = (grad + grad.T) / 2
    sig = LAM * eps.trace() * sp.eye(2) + 2 * MU * eps  # plane strain, sigma/E
    er, et = sp.Matrix([c, s]), sp.Matrix([-s, c])
    comp = lambda T, a, b: sp.simplify((a.T * T * b)[0])  # noqa: E731
    out = {"e_rr": comp(eps, er, er), "e_tt": comp(eps, et, et), "e_rt": comp(eps, er, et),
           "s_rr": comp(sig, er, er), "s_tt": comp(sig, et, et), "s_rt": comp(sig, er, et)}
    # strain energy density sigma : eps / 2 (an invariant: polar components suffice)
    out["energy"] = (out["s_rr"] * out["e_rr"] + out["s_tt"] * out["e_tt"] + 2 * out["s_rt"] * out["e_rt"]) / 2
    return out


X = (xi**2 / r - r) / (xi**2 - 1)


@cache
def galerkin():
    """Galerkin projection of plane-strain elastodynamics on ``u = X U, v = X V``.

    Virtual work: ``int gamma u_tt . w + sigma(u) : eps(w) dA = int_{r=1} (p w_r + q w_t) dtheta``.
    With ``w = X (dU, dV)`` and ``X(1) = 1`` this gives ``M U_tt + dPi/dU = p`` and
    ``M V_tt + dPi/dV = q``, ``Pi = int int W r dr dtheta``, ``M = gamma int X^2 r dr``.
    Returns the coefficients of ``(dPi/dU)/M`` and ``(dPi/dV)/M`` in the derivatives of
    ``U`` and ``V``, and ``M``.
    """
    U, V = sp.Function("U")(th), sp.Function("V")(th)
    W = sp.expand(polar_fields(X * U, X * V)["energy"])
    names = sp.symbols("U0 U1 V0 V1")
    derivs = (U, sp.Derivative(U, th), V, sp.Derivative(V, th))
    Wsym = W.subs(dict(zip(derivs[::-1], names[::-1])))  # derivatives first
    Wbar = sp.Integer(0)
    for powers, coeff in sp.Poly(Wsym, *names).terms():
        Wbar += sp.integrate(sp.expand(coeff * r), (r, 1, xi)) * sp.prod([n**k for n, k in zip(names, powers)])
    Wbar = Wbar.subs(dict(zip(names, derivs)))
    M = gamma * sp.integrate(sp.expand(X**2 * r), (r, 1, xi))
    eU, eV = (eq.lhs for eq in euler_equations(Wbar, [U, V], th))
    terms = {"U": U, "U'": U.diff(th), "U''": U.diff(th, 2), "V": V, "V'": V.diff(th), "V''": V.diff(th, 2)}
    syms = {k: sp.Symbol("T" + str(i)) for i, k in enumerate(terms)}
    out = {}
    for eq_name, expr in (("U", eU), ("V", eV)):
        e = sp.expand(expr)
        for k in ("U''", "V''", "U'", "V'", "U", "V"):  # highest derivatives first
            e = e.subs(terms[k], syms[k])
        out[eq_name] = {k: sp.diff(e, syms[k]) / M for k in terms}
    return out, M


@cache
def lame_steady():
    """Static axisymmetric plane strain on ``1 < r < xi``: ``u(xi) = v(xi) = 0``,
    ``u(1) = delta``, and ``q = f p`` on ``r = 1`` (``p = -s_rr(1)``, ``q = -s_rt(1)``).

    The equilibrium equations are the Euler-Lagrange equations of ``int W r dr``.
    Returns ``(u(r), v(r), fields)``.
    """
    u, v = sp.Function("u")(r), sp.Function("v")(r)
    fields = polar_fields(u, v)
    eqs = euler_equations(fields["energy"] * r, [u, v], r)
    sols = [sp.dsolve(eq, fn).rhs for eq, fn in zip(eqs, (u, v))]
    # each dsolve names its constants C1, C2: rename those of v
    free = lambda F: sorted(F.free_symbols - {r, xi, nu}, key=str)  # noqa: E731
    sols[1] = sols[1].subs({c: sp.Symbol("K" + c.name) for c in free(sols[1])})
    consts = free(sols[0]) + free(sols[1])
    bcs = [sols[0].subs(r, xi), sols[0].subs(r, 1) - delta, sols[1].subs(r, xi)]
    sub = lambda F: F.subs({u: sols[0], v: sols[1]}).doit()  # noqa: E731
    s_rr1, s_rt1 = sub(fields["s_rr"]).subs(r, 1), sub(fields["s_rt"]).subs(r, 1)
    bcs.append(s_rt1 - f * s_rr1)  # q = f p  <=>  -s_rt(1) = -f s_rr(1)
    sol = sp.solve(bcs, consts, dict=True)[0]
    uu, vv = sp.simplify(sols[0].subs(sol)), sp.simplify(sols[1].subs(sol))
    stress = {k: sp.simplify(sub(fields[k]).subs(sol)) for k in ("s_rr", "s_tt", "s_rt")}
    return uu, vv, stress
