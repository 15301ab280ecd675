"""Inverse problem [52]-[58]: derivation checks, determinant, closed forms, validation."""

import numpy as np
import pytest
import sympy as sp

from stickslip.errors import NoSolutionError, ParameterError
from stickslip.halfspace import (closed_form, determinant, inverse_problem, printed_closed_form, radok,
                                 system_matrix)

NU, MU, VS = 0.3, 0.5, 1e-3

# --- symbolic: the printed equations ------------------------------------------------
b, c, vs, v, T, mu = sp.symbols("b c vstar v T mu", real=True)
g1, g2, B = sp.symbols("gamma1 gamma2 B", positive=True)       # B = beta1 beta2
al = sp.symbols("alpha", positive=True)
lam = sp.Rational(1, 2) - al
Kp = sp.pi * lam / sp.cos(sp.pi * al)
Gm = g1 * sp.cos(al * sp.pi) + mu * g2 * sp.sin(al * sp.pi)
EQ52 = -v / c * b + ((v - vs) / c - (1 - B) * sp.cos(sp.pi * al) * T / (2 * g1)) * Kp * (b - 1)
EQ53 = (v - vs) / (c * (1 - B)) * Gm + T * (b - 1)
EQ54 = (Kp * (b - 1) - b) * v / c - sp.pi * lam * (b - 1) * (1 - B) / (2 * g1) * T - lam * sp.pi * (b - 1) / sp.cos(sp.pi * al) * vs / c
EQ55 = 2 * Gm / (1 - B) * v / c + (b - 1) * T - 2 * Gm * vs / ((1 - B) * c)
H57 = -g1 * b + g1 * sp.pi * lam * (b - 1) / sp.cos(sp.pi * al) + sp.pi * lam * Gm
ALPHA_DEF = {mu: g1 * sp.tan(sp.pi * al) / g2}    # tan(pi alpha) = mu gamma2 / gamma1


def test_eq54_is_eq52_rearranged():
    assert sp.simplify(EQ52 - EQ54) == 0


def test_eq55_is_twice_eq53():
    """[55] is 2 x [53] in its v-terms but [53] in its T-term: they are different equations."""
    assert sp.simplify(EQ55 - 2 * EQ53 + (b - 1) * T) == 0
    assert sp.simplify(EQ55 - EQ53) != 0


def test_determinant_56_57_belongs_to_54_55():
    M = sp.Matrix([[sp.diff(EQ54, v), sp.diff(EQ54, T)], [sp.diff(EQ55, v), sp.diff(EQ55, T)]])
    assert sp.simplify(M.det() - (b - 1) * H57 / (g1 * c)) == 0
    M53 = sp.Matrix([[sp.diff(EQ54, v), sp.diff(EQ54, T)], [sp.diff(EQ53, v), sp.diff(EQ53, T)]])
    assert sp.simplify(M53.det() - (b - 1) * H57 / (g1 * c)) != 0


def test_H_is_gamma1_b_K_minus_1_and_positive():
    """With tan(pi alpha) = mu gamma2/gamma1, [57] is gamma1 b (K - 1), K = x/sin x, x = pi lam in (0, pi/2)."""
    H = sp.simplify(H57.subs(ALPHA_DEF))
    assert sp.simplify(H - g1 * b * (Kp - 1)) == 0
    xs = sp.symbols("x", positive=True)
    K = xs / sp.sin(xs)
    # K - 1 > 0 on (0, pi/2): x - sin x has derivative 1 - cos x > 0 and vanishes at 0
    assert sp.simplify(sp.diff(xs - sp.sin(xs), xs) - (1 - sp.cos(xs))) == 0
    assert sp.limit(K - 1, xs, 0, "+") == 0
    assert sp.series(K - 1, xs, 0, 4).removeO() == xs**2 / 6
    assert sp.limit(K, xs, sp.pi / 2, "-") == sp.pi / 2


def _trig_rational(expr):
    """``expr`` as a rational function of s = sin(pi alpha), c = cos(pi alpha)."""
    s_, c_ = sp.symbols("s_ c_")
    e = sp.cancel(sp.expand_trig(expr).subs({sp.sin(sp.pi * al): s_, sp.cos(sp.pi * al): c_}))
    return sp.cancel(sp.numer(e).subs(c_**2, 1 - s_**2)) if e != 0 else e


def test_closed_form_58_solves_54_55():
    M = sp.Matrix([[sp.diff(EQ54, v), sp.diff(EQ54, T)], [sp.diff(EQ55, v), sp.diff(EQ55, T)]])
    rhs = -sp.Matrix([EQ54.subs({v: 0, T: 0}), EQ55.subs({v: 0, T: 0})])
    sol_v, sol_T = M.LUsolve(rhs)
    A = 4 * b * g1 * sp.cos(al * sp.pi) / (sp.pi * (-1 + 2 * al) * (mu * g2 * sp.sin(2 * sp.pi * al) + g1 * (-1 + 2 * b + sp.cos(2 * sp.pi * al))))
    assert _trig_rational(sol_v - vs / (1 + A)) == 0
    num = -4 * b * g1 * (g1 + g1 * sp.cos(2 * al * sp.pi) + mu * g2 * sp.sin(2 * al * sp.pi)) / ((b - 1) * (-1 + B))

    def T58(m):
        return num * vs / (c * (4 * b * g1 * sp.cos(al * sp.pi) + sp.pi * (-1 + 2 * al)
                                * (mu * g2 * sp.sin(m * sp.pi * al) + g1 * (-1 + 2 * b + sp.cos(m * sp.pi * al)))))

    assert _trig_rational(sol_T - T58(2)) == 0          # corrected: 2 pi alpha
    assert _trig_rational(sol_T - T58(1)) != 0          # as printed: pi alpha
    point = {b: 3, c: -sp.Rational(7, 10), vs: sp.Rational(1, 1000), g1: sp.Rational(2, 5), g2: sp.Rational(1, 5),
             al: sp.Rational(1, 10), B: sp.Rational(3, 5), mu: sp.Rational(1, 2)}
    assert abs(float((sol_T - T58(1)).subs(point))) > 1e-4   # as printed: pi alpha
    # and A simplifies to -1/K once alpha is the exponent of [41]: v = v* K / (K - 1)
    assert sp.simplify(sp.expand_trig((A + 1 / Kp).subs(ALPHA_DEF))) == 0


# --- numerics ----------------------------------------------------------------------
def _grid(nb=200, nc=200):
    bb = 1 + np.geomspace(1e-9, 1e9, nb)
    cc = -(1 - np.cos(np.pi * (np.arange(nc) + 0.5) / nc)) / 2
    return np.meshgrid(bb, cc, indexing="ij")


@pytest.mark.parametrize("nu, mu", [(0.0, 0.05), (0.3, 0.5), (0.49, 3.0), (0.25, 10.0)])
def test_D_negative_H_positive_dense_grid(nu, mu):
    Bg, Cg = _grid()
    D, H = determinant(Bg, Cg, nu, mu)
    assert np.all(D < 0) and np.all(H > 0)
    M, _ = system_matrix(Bg, Cg, VS, nu, mu)
    det = M[..., 0, 0] * M[..., 1, 1] - M[..., 0, 1] * M[..., 1, 0]
    np.testing.assert_allclose(D, det, rtol=1e-8)


def test_H_printed_formula_matches():
    Bg, Cg = _grid(60, 60)
    rd = radok(Cg, NU, MU)
    al = rd.alpha
    lam = 0.5 - al
    Gm = rd.gamma1 * np.cos(np.pi * al) + MU * rd.gamma2 * np.sin(np.pi * al)
    H57 = -rd.gamma1 * Bg + rd.gamma1 * np.pi * lam * (Bg - 1) / np.cos(np.pi * al) + np.pi * lam * Gm
    _, H = determinant(Bg, Cg, NU, MU)
    np.testing.assert_allclose(H, H57, rtol=1e-9, atol=1e-12 * np.abs(rd.gamma1 * Bg).max())


def test_text_system_determinant_vanishes_inside_the_domain():
    """With [53] as printed, D = 0 on b = K/(2(K-1)) and v* = 0 has non-trivial solutions there."""
    c = np.linspace(-0.95, -0.05, 19)
    rd = radok(c, NU, MU)
    b0 = rd.K / (2 * rd.K_minus_one)
    assert np.all(b0 > 1)
    D, H = determinant(b0, c, NU, MU, system="text")
    assert np.max(np.abs(H / rd.gamma1)) < 1e-12
    lo, _ = determinant(b0 * (1 - 1e-6), c, NU, MU, system="text")
    hi, _ = determinant(b0 * (1 + 1e-6), c, NU, MU, system="text")
    assert np.all(np.sign(lo) != np.sign(hi))
    M, _ = system_matrix(b0, c, VS, NU, MU, system="text")
    sv = np.linalg.svd(M, compute_uv=False)
    assert np.all(sv[:, 1] / sv[:, 0] < 1e-12)


def test_linear_solve_matches_numpy_and_closed_forms():
    Bg, Cg = _grid(80, 80)
    sol = inverse_problem(Bg, Cg, VS, nu=NU, mu=MU)
    M, r = system_matrix(Bg, Cg, VS, NU, MU)
    ref = np.linalg.solve(M, r[..., None])[..., 0]
    np.testing.assert_allclose(sol.v, ref[..., 0], rtol=1e-9)
    np.testing.assert_allclose(sol.T, ref[..., 1], rtol=1e-9)
    v_cf, T_cf = closed_form(Bg, Cg, VS, nu=NU, mu=MU)
    np.testing.assert_allclose(sol.v, v_cf, rtol=1e-10)
    np.testing.assert_allclose(sol.T, T_cf, rtol=1e-10)


def test_printed_T_formula_is_misprinted():
    Bg, Cg = _grid(40, 40)
    sol = inverse_problem(Bg, Cg, VS, nu=NU, mu=MU)
    v58, T58 = printed_closed_form(Bg, Cg, VS, nu=NU, mu=MU)
    np.testing.assert_allclose(v58, sol.v, rtol=1e-7)
    np.testing.assert_allclose(T58, sol.T, rtol=1e-7)
    _, T_printed = printed_closed_form(Bg, Cg, VS, nu=NU, mu=MU, as_printed=True)
    assert np.max(np.abs(T_printed / sol.T - 1)) > 0.1


def test_v_does_not_depend_on_b_and_loading_is_admissible():
    Bg, Cg = _grid(50, 50)
    sol = inverse_problem(Bg, Cg, VS, nu=NU, mu=MU)
    assert np.ptp(sol.v, axis=0).max() < 1e-15
    np.testing.assert_allclose(sol.v, VS * sol.radok.K / sol.radok.K_minus_one, rtol=1e-12)
    assert np.all(sol.admissible)
    # T (b - 1) does not depend on b either
    assert np.ptp(sol.T * (Bg - 1), axis=0).max() / np.abs(sol.T * (Bg - 1)).max() < 1e-10


def test_solution_scales_with_v_star():
    a = inverse_problem(3.0, -0.4, 1e-3, nu=NU, mu=MU)
    b2 = inverse_problem(3.0, -0.4, 5e-3, nu=NU, mu=MU)
    assert float(b2.v) == pytest.approx(5 * float(a.v), rel=1e-13)
    assert float(b2.T) == pytest.approx(5 * float(a.T), rel=1e-13)


def test_v_star_zero_has_only_the_trivial_solution():
    with pytest.raises(NoSolutionError, match="trivial"):
        inverse_problem(2.0, -0.5, 0.0, nu=NU, mu=MU)


def test_contract_keys_and_xarray():
    sol = inverse_problem(2.5, -0.6, VS, nu=NU, mu=MU)
    d = sol.to_dict()
    for key in ("v", "T", "alpha", "D", "beta1", "beta2", "gamma1", "gamma2"):
        assert isinstance(d[key], float)
    import json
    json.dumps(d)
    ds = inverse_problem(np.array([2.0, 3.0]), np.array([-0.6, -0.3]), VS, nu=NU, mu=MU).to_xarray()
    assert ds.v.dims == ("point",) and ds.v.attrs["units"] == "1"


@pytest.mark.parametrize("kwargs, name", [
    (dict(b=1.0, cbar=-0.5, v_star=VS), "b"), (dict(b=[2.0, 0.5], cbar=-0.5, v_star=VS), "b"),
    (dict(b=2.0, cbar=-1.0, v_star=VS), "c"), (dict(b=2.0, cbar=0.1, v_star=VS), "c"),
    (dict(b=2.0, cbar=-0.5, v_star=-1e-3), "v_star"), (dict(b=2.0, cbar=-0.5, v_star=float("nan")), "v_star"),
    (dict(b=np.inf, cbar=-0.5, v_star=VS), "b"),
    (dict(b=2.0, cbar=-0.5, v_star=1e308), "v_star"), (dict(b=2.0, cbar=-0.5, v_star=1.01), "v_star"),
])
def test_inverse_rejects_bad_input(kwargs, name):
    with pytest.raises(ParameterError) as err:
        inverse_problem(**kwargs, nu=NU, mu=MU)
    assert err.value.name == name


def test_unknown_system_rejected():
    with pytest.raises(ParameterError, match="system"):
        inverse_problem(2.0, -0.5, VS, nu=NU, mu=MU, system="other")


@pytest.mark.parametrize("b_, c_", [(1.001, -3.86e-6), (1e6, -0.3), (2.0, -1 + 1e-12), (1 + 1e-9, -1e-4)])
def test_linear_solve_is_accurate_near_the_edges(b_, c_):
    """Against 50-digit arithmetic on the textbook formulas (beta's, gammas, Cramer)."""
    import mpmath as mp
    with mp.workdps(50):
        nu, mu, v_s, B, C = mp.mpf("0.3"), mp.mpf("0.5"), mp.mpf("1e-3"), mp.mpf(b_), mp.mpf(c_)
        c1 = mp.sqrt(2 * (1 - nu) / (1 - 2 * nu))
        be1, be2 = mp.sqrt(1 - C**2 / c1**2), mp.sqrt(1 - C**2)
        ga1, ga2 = be1 * (1 - be2**2), 1 + be2**2 - 2 * be1 * be2
        la = mp.atan2(ga1, mu * ga2) / mp.pi
        K = mp.pi * la / mp.sin(mp.pi * la)
        om = 1 - be1 * be2
        a11, a12 = (K * (B - 1) - B) / C, -mp.pi * la * (B - 1) * om / (2 * ga1)
        a21, a22 = 2 * mp.sqrt(ga1**2 + (mu * ga2) ** 2) / (om * C), B - 1
        r1, r2 = K * (B - 1) * v_s / C, a21 * v_s
        det = a11 * a22 - a12 * a21
        v_ref, T_ref = float((r1 * a22 - a12 * r2) / det), float((a11 * r2 - a21 * r1) / det)
    sol = inverse_problem(b_, c_, VS, nu=NU, mu=MU)
    assert float(sol.v) == pytest.approx(v_ref, rel=1e-11)
    assert float(sol.T) == pytest.approx(T_ref, rel=1e-9)
    v_cf, T_cf = closed_form(b_, c_, VS, nu=NU, mu=MU)
    assert float(v_cf) == pytest.approx(v_ref, rel=1e-12) and float(T_cf) == pytest.approx(T_ref, rel=1e-12)
