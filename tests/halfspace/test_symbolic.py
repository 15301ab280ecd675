"""Symbolic checks of the Radok representation and of the interface relations ([25], [27]-[37], [41]-[42])."""

import sympy as sp

x, y, k = sp.symbols("x y k", real=True, positive=True)
b1, b2 = sp.symbols("beta1 beta2", positive=True)
p1, q1, p2, q2 = sp.symbols("p1 q1 p2 q2", real=True)
c2sq = 1 - b2**2                  # c^2 / c2^2 (units: G = rho = c2 = 1)
c1sq = c2sq / (1 - b1**2)         # c1^2 / c2^2
lame = c1sq - 2                   # lambda / G


def _wave(p, q, beta):
    """Real and imaginary parts of (p + i q) exp(i k (x + i beta y))."""
    e = sp.exp(-k * beta * y)
    return e * (p * sp.cos(k * x) - q * sp.sin(k * x)), e * (p * sp.sin(k * x) + q * sp.cos(k * x))


def _fields():
    r1, i1 = _wave(p1, q1, b1)             # phi1(z1)
    r2, i2 = _wave(p2, q2, b2)             # phi2(z2)
    d1r, d1i = _wave(-k * q1, k * p1, b1)  # phi1'(z1) = i k (p1 + i q1) e^{ikz1}
    d2r, d2i = _wave(-k * q2, k * p2, b2)  # phi2'(z2)
    d2r_z1, _ = _wave(-k * q2, k * p2, b1)  # phi2'(z1), as printed in [29]
    kk = (1 + b2**2) / 2
    ux = -(r1 + kk * r2)                    # [27]
    uy = b1 * i1 + kk / b2 * i2             # [28]
    exx, eyy, exy2 = sp.diff(ux, x), sp.diff(uy, y), sp.diff(ux, y) + sp.diff(uy, x)
    sxx = lame * (exx + eyy) + 2 * exx
    syy = lame * (exx + eyy) + 2 * eyy
    sxy = exy2
    return dict(ux=ux, uy=uy, sxx=sxx, syy=syy, sxy=sxy, d1r=d1r, d1i=d1i, d2r=d2r, d2i=d2i, d2r_z1=d2r_z1)


def _zero(expr):
    return sp.simplify(sp.expand(expr)) == 0


def test_radok_displacements_solve_the_steady_wave_equations():
    f = _fields()
    # steady state in x = X - c t: rho u_tt = c^2 u_xx
    mx = sp.diff(f["sxx"], x) + sp.diff(f["sxy"], y) - c2sq * sp.diff(f["ux"], x, 2)
    my = sp.diff(f["sxy"], x) + sp.diff(f["syy"], y) - c2sq * sp.diff(f["uy"], x, 2)
    assert _zero(mx) and _zero(my)


def test_radok_stresses_29_31():
    f = _fields()
    kk = (1 + b2**2) / 2
    s29 = -2 * ((2 * b1**2 - b2**2 + 1) / 2 * f["d1r"] + kk * f["d2r"])
    s30 = (1 + b2**2) * (f["d1r"] + f["d2r"])
    s31 = 2 * (b1 * f["d1i"] + (1 + b2**2) ** 2 / (4 * b2) * f["d2i"])
    assert _zero(f["sxx"] - s29) and _zero(f["syy"] - s30) and _zero(f["sxy"] - s31)


def test_eq29_as_printed_has_phi2_of_z1():
    """[29] prints phi2'(z1); with phi2'(z1) it is not sigma_xx off the interface."""
    f = _fields()
    kk = (1 + b2**2) / 2
    printed = -2 * ((2 * b1**2 - b2**2 + 1) / 2 * f["d1r"] + kk * f["d2r_z1"])
    assert not _zero(f["sxx"] - printed)


def test_interface_relations_34_37():
    """[33] phi2 = -2 beta1 beta2/(1 + beta2^2) phi1 on y = 0 gives [34]-[37] and u_y = 0."""
    f = _fields()
    sub = {p2: -2 * b1 * b2 / (1 + b2**2) * p1, q2: -2 * b1 * b2 / (1 + b2**2) * q1}
    at0 = lambda e: sp.simplify(e.subs(sub).subs(y, 0))  # noqa: E731
    re_phi, re_dphi, im_dphi = p1 * sp.cos(k * x) - q1 * sp.sin(k * x), -k * q1 * sp.cos(k * x) - k * p1 * sp.sin(k * x), \
        -k * q1 * sp.sin(k * x) + k * p1 * sp.cos(k * x)
    gamma1, gamma2 = b1 * (1 - b2**2), 1 + b2**2 - 2 * b1 * b2
    assert at0(f["uy"]) == 0
    assert sp.simplify(at0(f["ux"]) + (1 - b1 * b2) * re_phi) == 0                               # [34]
    assert sp.simplify(at0(f["syy"]) - gamma2 * re_dphi) == 0                                    # [35]
    assert sp.simplify(at0(f["sxx"]) - ((-1 + b2**2) + 2 * b1 * (b2 - b1)) * re_dphi) == 0       # [36]
    assert sp.simplify(at0(f["sxy"]) - gamma1 * im_dphi) == 0                                    # [37]


def test_slip_condition_gives_41_42():
    """[40] with Phi+ = -conj(Phi-) ([39]) is Phi+ - g Phi- = f2 with [41]-[42]."""
    g1, g2, mu, T = sp.symbols("gamma1 gamma2 mu T", positive=True)
    p, q = sp.symbols("p q", real=True)
    minus, plus = p + sp.I * q, -p + sp.I * q
    g = -(g1 + sp.I * mu * g2) / (g1 - sp.I * mu * g2)
    f2 = 2 * sp.I * T / (g1 - sp.I * mu * g2)
    lhs = plus - g * minus - f2
    # zero exactly when sigma_xy + mu sigma_yy = gamma1 q + mu gamma2 p = T
    assert sp.simplify(lhs.subs(T, g1 * q + mu * g2 * p)) == 0
    assert sp.simplify(sp.expand_complex(sp.Abs(g)) - 1) == 0


def test_remote_strain_25_plane_strain():
    """[25]: eps*_xx = -nu (1 + nu) tau*_yy / E is plane strain with tau*_xx = 0."""
    E, nu, t = sp.symbols("E nu tau", real=True)
    S = sp.Matrix([[1, -nu, -nu], [-nu, 1, -nu], [-nu, -nu, 1]]) / E      # 3-D compliance, normal part
    sxx, szz = 0, sp.symbols("szz")
    szz_ps = sp.solve((S * sp.Matrix([sxx, t, szz]))[2], szz)[0]          # eps_zz = 0
    eps_xx = sp.simplify((S * sp.Matrix([sxx, t, szz_ps]))[0])
    assert sp.simplify(eps_xx + nu * (1 + nu) * t / E) == 0
    assert sp.simplify((S * sp.Matrix([sxx, t, 0]))[0] + nu * t / E) == 0  # plane stress differs


def test_limits_of_gamma_ratio_keep_alpha_inside_its_range():
    """c -> 0: gamma2/gamma1 -> c2^2/c1^2; c -> c2: gamma1 -> beta1, gamma2 -> 1. So mu gamma2/gamma1
    stays finite and positive on the closed interval: 0 < alpha < 1/2, K = pi lam/sin(pi lam) in (1, pi/2),
    and H = gamma1 b (K - 1) > 0 up to both ends."""
    c, r = sp.symbols("c r", positive=True)            # r = c2^2/c1^2 < 1/2
    be1, be2 = sp.sqrt(1 - c**2 * r), sp.sqrt(1 - c**2)
    ga1, ga2 = be1 * (1 - be2**2), 1 + be2**2 - 2 * be1 * be2
    assert sp.simplify(sp.limit(ga2 / ga1, c, 0) - r) == 0
    assert sp.simplify(sp.limit(ga1, c, 1, "-") - sp.sqrt(1 - r)) == 0
    assert sp.limit(ga2, c, 1, "-") == 1
