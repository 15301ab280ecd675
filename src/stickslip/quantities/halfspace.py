"""Stick-slip waves between a rigid body and an elastic half-space (`stickslip.halfspace`).

Scaled as in the paper: stresses by the shear modulus ``G``, speeds by the shear-wave speed
``c2``, lengths by the stick-zone length ``a``.
"""

from __future__ import annotations

from .core import Domain, declare as Q
from .materials import DENSITY_WHY, FRICTION_WHY, YOUNG_WHY

HALFSPACE = Domain("halfspace", units="scaled by G, c2 and the stick length a", quantities=[
    # parameters (scaled by the shear modulus G, the shear-wave speed c2 and the stick length a)
    Q("b", "1", "period over stick length b/a", "(1, 1e12]", symbol="b",
      why="beyond, the stick zone is under 1e-12 of the period: pure slip in double precision (the fields "
          "resolve b up to 1e6)"),
    Q("cbar", "1", "wave speed c/c2", "(-1, 0)", symbol="c",
      why="a subsonic wave, travelling backwards (c < 0) in the paper's convention"),
    Q("c", "1", "wave speed c/c2", "(-1, 0)", symbol="c",
      why="a subsonic wave, travelling backwards (c < 0) in the paper's convention"),
    Q("v_star", "1", "speed v* = V*/c2 of the longitudinal elongation [26]", "[0, 1]", symbol="v*",
      why="v* = cbar nu (tau*_yy/G)/2 is under a quarter of the remote strain, far below 1 in linear "
          "elasticity"),
    Q("v", "1", "sliding speed v = V/c2", "(0, 1)", symbol="v", why="subsonic sliding"),
    Q("T", "1", "driving traction T = T*/G", "(0, 1]", symbol="T",
      why="a traction over the shear modulus: a strain, which linear elasticity keeps far below 1"),
    Q("tau_yy_over_G", "1", "remote normal stress tau*_yy/G that [26] implies for the wave"),
    Q("unique", "", "the loading carries one wave only (true) or several (false)"),
    Q("T_result", "1", "driving traction T = T*/G of a computed solution (any finite value)"),
    Q("nu", "1", "Poisson's ratio", "[0, 0.5)", symbol="nu", why="an isotropic solid in plane strain"),
    Q("poisson", "1", "Poisson's ratio", "[0, 0.5)", symbol="nu", why="an isotropic solid in plane strain"),
    Q("mu", "1", "interface friction coefficient", "(0, 10]", symbol="mu", why=FRICTION_WHY),
    Q("mu_star", "1", "apparent friction coefficient mu* (below mu)", "[0, 10]", symbol="mu*", why=FRICTION_WHY),
    Q("young", "Pa", "Young's modulus", "[1000, 1e13]", symbol="E", why=YOUNG_WHY),
    Q("density", "kg/m3", "density", "[1, 1e5]", symbol="rho", why=DENSITY_WHY),
    Q("tau_yy", "1", "normal traction tau_yy/G (as a parameter: the remote one, a compression, scaled by G or "
      "in Pa as the function says)", "[-1e13, 0)", why="a compression, at most 1e13 Pa (or G)"),
    Q("tau_xy", "1", "shear traction tau_xy/G (as a parameter: the remote one, scaled by G or in Pa as the "
      "function says)", "[-1e13, 1e13]"),
    Q("points", "1", "interface points per period", "[3, 1e7]", integer=True),
    Q("n", "1", "interface points per period", "[3, 1e7]", integer=True),
    Q("n_grid", "1", "points of the grid the direct problem scans", "[11, 1e6]", integer=True),
    Q("v_ratio", "1", "v / v*", "(0, 1e6]"),
    Q("x", "1", "position x/a along the interface", "[-1e12, 1e12]", symbol="x"),
    Q("max_solutions", "1", "most waves kept per loading", "[1, 100]", integer=True),
    Q("T_ratio", "1", "T / v*", "(0, 1e6]"),
    Q("system", "", "the linear system: [54]-[55] as printed, or [52]-[53] of the text (errata H4)",
      choices=("printed", "text")),
    Q("plane", "", "plane strain or plane stress", choices=("strain", "stress")),
    # results
    Q('shear_modulus', 'Pa', 'shear modulus G'),
    Q('c1', 'm/s', 'dilatational (P) wave speed'),
    Q('c2', 'm/s', 'shear (S) wave speed'),
    Q('c1_over_c2', '1', 'c1 / c2'),
    Q('rayleigh_speed', 'm/s', 'Rayleigh wave speed'),
    Q('sigma_yy', '1', 'normal stress perturbation sigma_yy / G'),
    Q('sigma_xy', '1', 'shear stress perturbation sigma_xy / G'),
    Q("stress_yy", "1", "total normal stress Sigma_yy / G"),
    Q("stress_xy", "1", "total shear stress Sigma_xy / G"),
    Q('u_xx', '1', 'surface strain du_x/dx'),
    Q('slip_velocity', '1', 'slip velocity / c2'),
    Q('material_velocity', '1', 'material velocity / c2'),
    Q('alpha', '1', 'alpha of the closed form'),
    Q('beta0', '1', 'beta0 of the closed form'),
    Q('beta1', '1', 'beta1 of the closed form'),
    Q('beta2', '1', 'beta2 of the closed form'),
    Q('gamma1', '1', 'gamma1 of the closed form'),
    Q('gamma2', '1', 'gamma2 of the closed form'),
    Q('K', '1', 'K of the closed form'),
    Q('D', '1', 'determinant D [56]'),
    Q('H', '1', 'H, eq. [57]'),
    Q('n_solutions', '1', 'number of solutions'),
    Q('decay_residual', '1', 'residual of the decay condition'),
    Q('slip_residual', '1', 'residual of the slip condition'),
    Q('stick_residual', '1', 'residual of the stick condition'),
    Q('stick_violation_length', '1', 'length of the stick violation / a'),
    Q('stress_intensity', '1', 'stress intensity factor (scaled by G sqrt(a))'),
    Q('exponent_stick_to_slip', '1', 'singularity exponent at the stick-to-slip point'),
    Q('exponent_slip_to_stick', '1', 'singularity exponent at the slip-to-stick point'),
    Q('far_field', '1', 'far-field coefficient'),
    Q('tensile_zone_start', '1', 'start of the tensile zone / a'),
    Q('tensile_zone_length', '1', 'length of the tensile zone / a'),
    Q('T_58', '1', 'T from [58]'),
    Q('v_58', '1', 'v from [58]'),
    Q('T_closed', '1', 'T from the closed form'),
    Q('v_closed', '1', 'v from the closed form'),
])
