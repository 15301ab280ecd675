"""Rate-and-state friction and the spring-slider (`stickslip.rsf`), in SI units per unit area
of the interface: stresses in Pa, a spring's stiffness in Pa/m, a slider's mass in kg/m2.

The ranges span laboratory rock and polymer friction (``a`` and ``b`` about 1e-3 to 1e-1,
``D_c`` micrometres) to fault models (``D_c`` up to metres, stresses up to gigapascals).
"""

from __future__ import annotations

from .core import Domain, declare as Q

_LOG_WHY = "the law's logarithms: beyond it a slip rate of the model is further from its reference than 1e300"

RSF = Domain("rsf", units="SI, per unit area of the interface", quantities=[
    # parameters of the law
    Q("lyapunov_step", "1", "difference step of the first Lyapunov coefficient, in the units of the state",
      "(0, 1e6]"),
    Q("a", "1", "direct-effect parameter a of rate-and-state friction", "[1e-8, 1]", symbol="a",
      why="a <= 0 has no instantaneous strengthening (the slip rate is not determined by the stress); measured "
          "values are 1e-4 to 1e-1, and below 1e-8 the slip rate's response to stress overflows"),
    Q("b", "1", "evolution-effect parameter b (of the first state variable)", "[0, 1]", symbol="b",
      why="measured values are 1e-4 to 1e-1; beyond 1 friction is no longer a coefficient near f_0"),
    Q("dc", "m", "characteristic slip distance D_c (of the first state variable)", "[1e-12, 1e3]", symbol="D_c",
      why="from nanometre asperity contacts to the metres of fault models"),
    Q("b2", "1", "evolution-effect parameter of a second state variable (0: one state variable)", "[0, 1]",
      symbol="b_2"),
    Q("dc2", "m", "characteristic slip distance of the second state variable", "[1e-12, 1e3]", symbol="D_c2"),
    Q("f0", "1", "friction coefficient of steady sliding at the reference slip rate", "[0, 10]", symbol="f_0"),
    Q("v_ref", "m/s", "reference slip rate V_0 of the law", "[1e-15, 1e4]", symbol="V_0",
      why="from the slowest creep measured to ballistic speeds"),
    Q("evolution", "", "evolution law of the state: aging (Dieterich), slip (Ruina) or prz (Perrin-Rice-Zheng)",
      choices=("aging", "slip", "prz")),
    # the spring-slider
    Q("normal_stress", "Pa", "normal stress on the interface", "[1e-3, 1e10]", symbol="sigma",
      why="from a gel's interface to the deepest seismogenic faults"),
    Q("stiffness", "Pa/m", "stiffness of the loading spring per unit area", "[1e-6, 1e18]", symbol="k"),
    Q("mass", "kg/m2", "slider mass per unit area (0: quasi-static)", "[0, 1e15]", symbol="m"),
    Q("load_velocity", "m/s", "load-point velocity (0: a hold)", "[0, 1e4]", symbol="V_lp"),
    Q("history_time", "s", "time at which the load-point velocity takes its next value", "[0, 1e300]"),
    Q("v_init", "m/s", "initial slip rate (the state starts at its steady value for it)", "[1e-20, 1e4]",
      symbol="V_i", why=_LOG_WHY),
    Q("t_end", "s", "end time", "(0, 1e300]", symbol="t_end"),
    Q("samples", "1", "uniform samples of the history in the output", "[2, 1e7]", integer=True),
    Q("rtol", "1", "relative tolerance of the integrator", "[1e-13, 1e-3]"),
    Q("states", "1", "state variables fitted to a record: 1 (a, b, D_c) or 2 (and b_2, D_c2)", "[1, 2]", integer=True),
    Q("cycles", "1", "periods that must agree for a limit cycle (their mean is its period)", "[2, 1e4]", integer=True),
    # results
    Q("f0_error", "1", "standard error of the fitted f_0"),
    Q("a_error", "1", "standard error of the fitted a"),
    Q("b_error", "1", "standard error of the fitted b"),
    Q("dc_error", "m", "standard error of the fitted D_c"),
    Q("b2_error", "1", "standard error of the fitted b_2"),
    Q("dc2_error", "m", "standard error of the fitted D_c2"),
    Q("stiffness_per_stress", "1/m", "stiffness of the machine and sample per unit normal stress, k / sigma"),
    Q("stiffness_per_stress_error", "1/m", "standard error of the fitted k / sigma"),
    Q("rows", "1", "rows of the record"),
    Q("rms_residual", "1", "root mean square of the fit's residuals (record's friction less the model's)"),
    Q("t", "s", "time since the start"),
    Q("slip_rate", "m/s", "slip rate V of the slider"),
    Q("theta", "s", "state variable theta (the first)"),
    Q("theta2", "s", "second state variable theta_2"),
    Q("friction", "1", "friction coefficient tau / sigma"),
    Q("shear_stress", "Pa", "shear stress on the interface (the spring's force per unit area)"),
    Q("slip", "m", "slip of the slider since the start"),
    Q("load_point", "m", "displacement of the load point since the start"),
    Q("steady_friction", "1", "friction coefficient of steady sliding at the load-point velocity"),
    Q("critical_stiffness", "Pa/m", "critical stiffness k_c: steady sliding is unstable below it"),
    Q("critical_stiffness_quasi_static", "Pa/m", "critical stiffness without inertia, sigma (b - a) / D_c"),
    Q("hopf_frequency", "rad/s", "angular frequency of the oscillation at the critical stiffness"),
    Q("l1", "1/s", "first Lyapunov coefficient of the Hopf point (in ln V, psi and tau / sigma; > 0: subcritical)"),
    Q("l1_error", "1/s", "numerical error of the first Lyapunov coefficient (two difference steps)"),
    Q("criticality", "", "the Hopf bifurcation is subcritical, supercritical, or degenerate (l1 zero within its "
      "error)"),
    Q("hopf_period", "s", "period of the oscillation at the critical stiffness"),
    Q("eigenvalue_real", "1/s", "real part of an eigenvalue of the slider linearised about steady sliding"),
    Q("eigenvalue_imag", "rad/s", "imaginary part of an eigenvalue of the slider linearised about steady sliding"),
    Q("stable", "1", "1 if steady sliding is linearly stable"),
    Q("period", "s", "period of the slider's limit cycle"),
    Q("friction_min", "1", "smallest friction coefficient (of the run or the cycle)"),
    Q("friction_max", "1", "largest friction coefficient (of the run or the cycle)"),
    Q("slip_rate_max", "m/s", "largest slip rate among the samples (of the run or the cycle)"),
    Q("slip_rate_min", "m/s", "smallest slip rate (of the run or the cycle)"),
    Q("steps", "1", "steps the integrator took"),
    Q("slip_rate_end", "m/s", "slip rate at the end of the run"),
    Q("friction_end", "1", "friction coefficient at the end of the run"),
    Q("slip_end", "m", "slip at the end of the run"),
])
