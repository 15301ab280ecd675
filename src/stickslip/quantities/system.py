"""Linear structures with several frictional contacts (`stickslip.system`), in SI units (or
any consistent set: the model has no built-in scale).

The ranges are those of the 1-DOF oscillator's quantities, of which a system is the
generalisation: one contact of a one-degree-of-freedom system is that oscillator.
"""

from __future__ import annotations

from .core import Domain, declare as Q

#: The most degrees of freedom of a system (dense matrices: 4096^2 doubles are 128 MB, and
#: each mode's matrix exponential costs about a second).
MAX_SYSTEM_DOFS = 4096
#: The most contacts of a system (a ring of the reduced model has one per node).
MAX_CONTACTS = 4096

SYSTEM = Domain("system", units="SI (or any consistent units)", quantities=[
    Q("mass_matrix", "kg", "entry of the mass matrix M (symmetric positive definite)", "[-1e15, 1e15]",
      symbol="M", why="the oscillator's mass range: from a microcantilever to a crustal block"),
    Q("stiffness_matrix", "N/m", "entry of the stiffness matrix K", "[-1e15, 1e15]", symbol="K"),
    Q("damping_matrix", "N s/m", "entry of the damping matrix C", "[-1e15, 1e15]", symbol="C"),
    Q("force", "N", "entry of the constant external force f", "[-1e15, 1e15]", symbol="f"),
    Q("forcing_frequency", "rad/s", "angular frequency W of a harmonic part of the external force", "(0, 1e15]",
      symbol="W", why="from a tide to ultrasound and beyond; the event search steps a quarter of 1/W at most"),
    Q("harmonic_force", "N", "entry of the amplitude of a harmonic part of the external force (cos or sin)",
      "[-1e15, 1e15]"),
    Q("history_time", "s", "time of a point of a force history (the force linear between points)", "[0, 1e15]",
      why="a run starts at t = 0; 1e15 s is thirty million years"),
    Q("direction", "1", "entry of a contact's direction w (its slip velocity is V - w . x')", "[-1e6, 1e6]",
      symbol="w", why="a lever arm of up to a million: beyond it the contact's force dwarfs every other"),
    Q("surface_speed", "m/s", "speed of the surface a contact rubs on", "[-1e4, 1e4]", symbol="V",
      why="from rest to ballistic speeds, either way"),
    Q("normal_force", "N", "normal force of a contact (with a normal direction: at x = 0)", "(0, 1e15]", symbol="N"),
    Q("normal_stiffness", "N/m", "stiffness of a unilateral contact along its normal direction", "[0, 1e15]",
      symbol="k_n"),
    Q("t_end", "s", "end time", "(0, 1e300]", symbol="t_end"),
    Q("x0", "m", "entry of the initial displacement", "[-1e300, 1e300]", symbol="x_0"),
    Q("v0", "m/s", "entry of the initial velocity", "[-1e300, 1e300]", symbol="v_0"),
    Q("samples", "1", "uniform samples of the trajectory in the output", "[2, 1e7]", integer=True),
    Q("psi0", "1", "entry of the initial state of the rate-and-state contacts, ln(V_0 theta / D_c)", "[-1000, 1000]",
      symbol="psi_0", why="theta from e^-1000 to e^1000 times D_c/V_0: far beyond any healing or weakening"),
    Q("rtol", "1", "relative tolerance of the integration between switches (Radau IIA, or DOP853 compiled with "
      "the laws)", "[1e-13, 1e-3]",
      why="from near round-off to a quick look"),
    Q("max_events", "1", "most contact events of a simulation", "[1, 1e9]", integer=True),
    Q("transient", "s", "time simulated before a cycle is looked for", "(0, 1e300]"),
    Q("periods", "1", "forcing periods over which a periodic response repeats (1: at the forcing period; more: a "
      "subharmonic)", "[1, 1000]", integer=True),
    Q("max_iter", "1", "most returns to the section while a cycle is looked for", "[1, 1e6]", integer=True),
    Q("states", "1", "contact states to start in: 1 slip, 0 stick, -1 reverse slip, one per contact"),
    Q("parameter_value", "1", "a value of the continued parameter, in the units of the number it sets",
      "[-1e15, 1e15]", why="the widest range of the numbers of a system"),
    Q("points", "1", "parameter values along the branch", "[2, 10000]", integer=True,
      why="a cycle found by Newton's method at each: ten thousand take minutes for a large system"),
    # results
    Q("contact", "1", "contact number"),
    Q("t", "s", "time since the start"),
    Q("x", "m", "displacement"),
    Q("v", "m/s", "velocity"),
    Q("contact_state", "1", "state of a contact: 1 slip (V - w.x' > 0), 0 stick, -1 reverse slip, 2 open"),
    Q("friction_force", "N", "friction force of a contact on the structure, along its direction"),
    Q("slip_velocity", "m/s", "slip velocity V - w . x' of a contact"),
    Q("slip_rate", "m/s", "slip velocity V - w . x' of a rate-and-state contact"),
    Q("slip_rate_end", "m/s", "slip velocity of each contact at the end of the run"),
    Q("slip_rate_max", "m/s", "largest slip velocity of each contact over the samples"),
    Q("slip_rate_min", "m/s", "smallest slip velocity of each contact over the samples"),
    Q("psi", "1", "state variable ln(V_0 theta / D_c) of a rate-and-state contact (steady: ln(V_0 / V))"),
    Q("state_variable", "1", "number of a state variable of a rate-and-state contact"),
    Q("event_time", "s", "time of a contact event"),
    Q("event_contact", "1", "contact whose state changed at the event"),
    Q("event_state", "1", "its state after the event (1 slip, 0 stick, -1 reverse slip, 2 open)"),
    Q("period", "s", "period of the limit cycle (of a periodic response: the periods times the forcing period)"),
    Q("amplitude", "m", "half the peak-to-peak displacement of each degree of freedom over a period"),
    Q("x_min", "m", "least displacement of a degree of freedom over a period"),
    Q("x_max", "m", "largest displacement of a degree of freedom over a period"),
    Q("neutral", "1", "1 if a multiplier of the periodic response lies on the unit circle: a family of responses "
      "(a contact stuck through the period, anywhere) or a bifurcation"),
    Q("forced", "1", "1 for a branch of periodic responses to a periodic force (every multiplier kept)"),
    Q("multipliers_abs", "1", "moduli of the Floquet multipliers of the cycle"),
    Q("stable", "1", "1 if stable: a cycle's multipliers but the flow's own inside the unit circle (a periodic "
      "response's: all of them), steady sliding's eigenvalues in the left half-plane"),
    Q("marginal", "1", "1 if steady sliding's largest real part is zero to round-off: linear stability does not "
      "decide (an undamped structure under Coulomb contacts)"),
    Q("events", "1", "contact events (of a run, or of one period of a cycle)"),
    Q("x_end", "m", "displacement at the end of the run"),
    Q("v_end", "m/s", "velocity at the end of the run"),
    Q("states_end", "1", "contact states at the end of the run (1 slip, 0 stick, -1 reverse slip, 2 open)"),
    Q("mode", "1", "number of an eigenvalue of the linearised flow"),
    Q("eigenvalue_real", "1/s", "real part of an eigenvalue of the flow linearised about steady sliding"),
    Q("eigenvalue_imag", "rad/s", "imaginary part of an eigenvalue of the flow linearised about steady sliding"),
    Q("growth_rate", "1/s", "largest real part of the eigenvalues about steady sliding (> 0: unstable)"),
    Q("multiplier", "1", "number of a Floquet multiplier, by decreasing modulus"),
    Q("multiplier_real", "1", "real part of a Floquet multiplier of the cycle"),
    Q("multiplier_imag", "1", "imaginary part of a Floquet multiplier of the cycle"),
    Q("shift_time", "s", "time a wave takes to move by one cell of the structure"),
    Q("leading_abs", "1", "modulus of the largest multiplier but the flow's own"),
    Q("leading_growth_rate", "1/s", "ln|mu| / shift_time of the leading multiplier (> 0: unstable)"),
    Q("section_contact", "1", "contact whose event starts the period"),
    Q("section_state", "1", "the state it enters there"),
    # continuation
    Q("parameter", "", "the continued parameter, as the file names it"),
    Q("values", "1", "values of the continued parameter, in the units of the number it sets"),
    Q("value", "1", "value of the continued parameter"),
    Q("point", "1", "number of a point of the branch"),
    Q("multiplier_abs", "1", "modulus of a Floquet multiplier of the cycle (the flow's own 1 removed; a periodic "
      "response has none)"),
    Q("sequence", "", "the cycle's contact events over a period, in order: contact:state entered"),
    Q("event", "1", "number of an event along the branch"),
    Q("event_value", "1", "value of the parameter where the branch changes"),
    Q("event_kind", "", "what changes: event sequence (a grazing), cycle lost, stability"),
    Q("change", "", "what changes there: event sequence (a grazing), cycle lost, stability"),
    Q("before", "", "the cycle's contact events (or its stability) before the value"),
    Q("after", "", "the same after it"),
    Q("stopped", "", "why the branch ends"),
])
