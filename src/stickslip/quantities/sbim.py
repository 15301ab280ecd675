"""Interface dynamics by the spectral boundary integral method (`stickslip.sbim`), in SI units: an
elastic half-space's surface, periodic along the interface, its tractions in Pa and slips in m.

The ranges span laboratory interfaces (millimetres, megapascals) to crustal faults (hundreds of
kilometres, gigapascals).
"""

from __future__ import annotations

from .core import Domain, declare as Q

#: The explicit scheme's stable limit of ``beta = c_s dt / dx`` (see `stickslip.sbim.antiplane`).
BETA_LIMIT = 0.6366

SBIM = Domain("sbim", units="SI", quantities=[
    Q("shear_modulus", "Pa", "shear modulus mu of the half-space", "[1e3, 1e12]", symbol="mu",
      why="from soft gels (1e3 Pa) to beyond diamond's (5e11 Pa)"),
    Q("shear_wave_speed", "m/s", "shear wave speed c_s of the half-space", "[1, 2e4]", symbol="c_s",
      why="from gels (metres per second) to beyond diamond's 12 km/s"),
    Q("length", "m", "period of the interface along x (the domain)", "[1e-9, 1e9]", symbol="L"),
    Q("elements", "1", "elements along the period (a power of two is fastest)", "[4, 1048576]", integer=True,
      symbol="N"),
    Q("beta", "1", "time step in units of an element's shear-wave transit, c_s dt / dx", "(0, 0.6366]",
      symbol="beta", why="above 2/pi the explicit update of the shortest mode's static stiffness, |k| c_s dt <= 2, "
                         "is unstable"),
    Q("poisson", "1", "Poisson's ratio of the half-space (in-plane)", "[0, 0.5)", symbol="nu",
      why="an isotropic solid in plane strain"),
    Q("history_periods", "1", "periods of each mode kept in its convolution's history (the rest truncated)",
      "[0.5, 1e4]", symbol="eta"),
    Q("steps", "1", "time steps", "[1, 1e9]", integer=True),
    Q("mode_step", "1", "a mode's time step, k c_s dt (the shortest: pi beta)", "(0, 10]", symbol="a"),
    Q("history_steps", "1", "steps of a mode's history kept", "[0, 1048576]", integer=True, symbol="M"),
    Q("window_steps", "1", "steps over which a mode's in-plane memory fades (at least its history)",
      "[0, 1048576]", integer=True),
    Q("radius", "1", "modulus above which a root of a mode's recurrence counts as growing", "(0, 2]"),
    Q("every", "1", "time steps between stored samples", "[1, 1e9]", integer=True),
    Q("static_strength", "Pa", "shear strength of a stuck interface (static friction times the normal stress)",
      "[0, 1e11]", symbol="tau_s"),
    Q("kinetic_strength", "Pa", "shear strength of a sliding interface (Coulomb), or its weakened value "
      "(slip-weakening)", "[0, 1e11]", symbol="tau_d"),
    Q("weakening_slip", "m", "slip over which the strength falls from tau_s to tau_d (slip-weakening)",
      "(0, 1e3]", symbol="D_c"),
    Q("static_friction", "1", "static friction coefficient of the interface (in-plane)", "[0, 10]", symbol="f_s"),
    Q("kinetic_friction", "1", "kinetic friction coefficient, or its weakened value (in-plane)", "[0, 10]",
      symbol="f_d"),
    Q("friction", "1", "friction coefficient of steady sliding (the flutter equation)", "[0, 10]", symbol="f"),
    Q("relaxation", "1", "a mode's Prakash-Clifton relaxation, k c_s t_r (0: Coulomb's law)", "[0, 1e12]",
      symbol="kappa"),
    Q("relaxation_time", "s", "Prakash-Clifton relaxation time of steady sliding, L / (V0 + V*) (0: Coulomb's law)",
      "[0, 1e6]", symbol="t_r"),
    Q("wavenumber", "1/m", "wavenumber of a perturbation along the interface", "(0, 1e12]", symbol="k"),
    Q("relaxation_slip", "m", "slip over which the pressure the strength sees follows the contact pressure "
      "(Prakash-Clifton)", "(0, 1e3]", symbol="L"),
    Q("relaxation_speed", "m/s", "slip rate added to |V| in the Prakash-Clifton relaxation (a node at rest "
      "still relaxes)", "(0, 1e4]", symbol="V*"),
    Q("normal_traction", "Pa", "normal traction sigma_yy on the interface, applied (amplitude) or in a run (negative: compression)",
      "[-1e11, 1e11]", symbol="sigma_0"),
    Q("traction", "Pa", "applied shear traction (amplitude)", "[-1e11, 1e11]", symbol="tau_0"),
    Q("patch_traction", "Pa", "shear traction added on a patch of the interface (a nucleation patch)",
      "[-1e11, 1e11]", symbol="dtau"),
    Q("patch_width", "m", "width of the patch along x (0: none)", "[0, 1e9]", symbol="w"),
    Q("patch_centre", "m", "centre of the patch along x", "[0, 1e9]", symbol="x_c"),
    Q("mode", "1", "Fourier mode number along the period (0: uniform)", "[0, 524288]", integer=True),
    Q("stick_length", "m", "length of a stick zone of the paper's wave (its unit of length, a)", "[1e-9, 1e9]",
      symbol="a"),
    Q("periods", "1", "periods of the paper's wave along the run's interface", "[1, 4096]", integer=True),
    Q("perturbation", "m", "amplitude of a slip perturbation cos(2 pi mode x / L) added at the start",
      "[-1e3, 1e3]"),
    Q("normal_stress", "Pa", "normal stress on the interface (rate-and-state)", "[1e-3, 1e10]", symbol="sigma"),
    Q("slip_rate", "m/s", "slip rate (of steady sliding at the start: the quasi-dynamic interface's)",
      "[1e-20, 1e4]", symbol="V"),
    Q("stressing_rate", "Pa/s", "rate of the applied shear traction after the start", "[-1e11, 1e11]"),
    Q("t_end", "s", "end time", "(0, 1e300]"),
    Q("samples", "1", "uniform samples of the run in the output", "[2, 1e7]", integer=True),
    Q("rtol", "1", "relative tolerance of the adaptive integrator", "[1e-13, 1e-3]"),
    # results
    Q("t", "s", "time since the start"),
    Q("x", "m", "position along the interface"),
    Q("slip", "m", "slip (the surface's displacement along z, antiplane)"),
    Q("shear_stress", "Pa", "shear traction on the interface"),
    Q("opening", "m", "opening of the interface (the surface's displacement away from the rigid body, in-plane)"),
    Q("opening_rate", "m/s", "opening rate"),
    Q("dt", "s", "time step"),
    Q("load_work", "J/m", "the loading's work on the slip so far, per metre along z"),
    Q("static_energy", "J/m", "strain energy the slip would hold at rest, per metre along z"),
    Q("released_energy", "J/m", "energy released by the slip so far (load_work - static_energy), per metre along z"),
    Q("dissipation", "J/m", "energy dissipated by the interface's traction so far, per metre along z"),
    Q("friction_energy", "J/m", "part of the dissipation at the kinetic strength, per metre along z"),
    Q("fracture_energy", "J/m", "part of the dissipation above the kinetic strength (weakening), per metre along z"),
    Q("wave_energy", "J/m", "energy of the waves in the body, radiated once the surface is at rest "
      "(released_energy - dissipation), per metre along z"),
    Q("travel", "m^2/m", "the slip's path summed over the interface so far, per metre along z"),
    Q("kernel_truncation", "1", "part of each mode's kernel integral left out by the history's truncation"),
    Q("peak_slip_rate", "m/s", "largest slip rate anywhere in the run"),
    Q("final_max_slip", "m", "largest slip at the end of the run"),
    Q("peak_opening", "m", "largest opening anywhere in the run"),
    Q("slipped_fraction", "1", "fraction of the interface that has slipped by the end"),
    Q("open_fraction_at_end", "1", "fraction of the interface open at the end"),
    Q("law", "1", "the interface law of the run (its class in stickslip.sbim)"),
    Q("well_posed", "1", "the run's law is well posed (false: it flutters, its result depends on the grid)"),
    Q("ill_posedness", "1", "why the run's law is ill-posed (empty when it is not)"),
])
