"""Errata of the paper: every printed formula found wrong, and the test that settles it.

This list is the single source: ``docs/errata.md`` is generated from it
(``python -m stickslip.errata > docs/errata.md``; a test keeps them in sync) and
`stickslip reproduce` prints it in the report.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Erratum:
    id: str
    where: str
    printed: str
    corrected: str
    evidence: str
    tests: tuple[str, ...]


ERRATA: list[Erratum] = [
    Erratum(
        "E1", "Section 2, slip duration of the Coulomb stick-slip cycle",
        "Δt_g = 2π Arctan(Δt_a w/2) / w",
        "Δt_g = (2π − 2 arctan(Δt_a w/2)) / w",
        "The slip arc of the limit cycle is an ellipse arc about x_e from (x_a, V) to (2x_e − x_a, V); "
        "it sweeps 2π − 2 arctan(Δt_a w/2) radians at angular speed w. The event-driven simulation, "
        "an independent solve_ivp integration and the corrected formula agree to 1e-9; the printed "
        "formula is off by 4.7 % for the parameters of Figure 2 and tends to 0 as f_s → f_d, where the "
        "true slip time tends to 2π/w.",
        ("tests/oscillator/test_cycle.py::test_coulomb_cycle_matches_closed_form",
         "tests/oscillator/test_cycle.py::test_printed_slip_time_is_wrong"),
    ),
    Erratum(
        "E2", "Section 2, eq. [9] and the centre of the reverse-slip spirals",
        "F((V − ẋ) ≤ 0) = −f_d (1 − τ(V − ẋ)) N, spirals centred at x_e^- = f_d (1 + τV) N / k",
        "F = −f_d (1 − τ|V − ẋ|) N = −f_d (1 + τ(V − ẋ)) N; centre x_e^- = −f_d (1 + τV) N / k",
        "As printed, [9] makes the friction coefficient grow with reverse slip speed, which gives positive "
        "damping and a centre at −f_d(1 − τV)N/k, contradicting the paper's own 'divergent spirals "
        "centred at f_d(1+τV)N/k'. The odd law f_d(1 − τ|v_r|) gives negative damping f_d τ N in both slip "
        "directions and the centre −f_d(1+τV)N/k (the printed centre lacks the minus sign, as for "
        "Coulomb's −x_e). The test fits the centre and the growth rate of a reverse-slip arc.",
        ("tests/oscillator/test_simulate.py::test_reverse_slip_spiral_centre_and_growth",),
    ),
    Erratum(
        "E3", "Section 2, eq. [7] versus the text on the stick segment for the linear law",
        "[7]: stick while |F| ≤ f_d N; text: stick segment [−x_a, x_a] with x_a = f_s N / k",
        "Both readings are supported: `LinearWeakening(fs, fd, tau)` sticks while |F| ≤ f_s N; "
        "Figure 3 uses f_s = f_d, as [7] prints, so the two agree there.",
        "With f_s = f_d the friction is continuous at the stick limit and the slip arc leaves the stick "
        "segment tangentially (zero initial acceleration); the tests check that no chattering occurs.",
        ("tests/oscillator/test_simulate.py::test_tangential_departure_does_not_chatter",),
    ),
    Erratum(
        "B1", "Section 3, eq. [11]: sign of the steady contact pressure",
        "p_e = δ · 1/(1 − ξ²) · 1/(1 + μ) · (ξ² + 1/(1 − 2μ))",
        "p_e = δ (ξ² + 1/(1 − 2ν)) / ((1 + ν)(ξ² − 1)) > 0 for δ > 0",
        "As printed p_e < 0 for every ξ > 1 (the shaft would pull on the ring), against p ≥ 0 in [10]. A sympy "
        "Lamé solution of [10] (static, axisymmetric, u(ξ) = v(ξ) = 0, u(1) = δ, q = f p) gives −σ_rr(1) equal "
        "to the corrected formula; the printed value is exactly −p_e.",
        ("tests/brake/reduced/test_steady.py::test_contact_pressure_is_positive_and_printed_eq11_has_the_wrong_sign",
         "tests/brake/reduced/test_steady.py::test_steady_state_is_the_lame_solution"),
    ),
    Erratum(
        "B2", "Section 3, eq. [11]: μ printed for Poisson's ratio ν",
        "v_e = δ f X(r) (1 + 1/(ξ²(1 − 2μ))), and μ in p_e",
        "ν in both places: v_e = δ f X(r) (1 + 1/(ξ²(1 − 2ν)))",
        "In [10] μ is Lamé's shear modulus (a stress), so 1 + μ and 1 − 2μ are dimensionally inconsistent. With ν, "
        "v_e matches the sympy Lamé solution exactly and equals δ f g/h of [16].",
        ("tests/brake/reduced/test_steady.py::test_reduced_steady_state_eq16_agrees_with_lame",),
    ),
    Erratum(
        "B3", "Section 3, eq. [12]: second derivatives swapped",
        "Ü − bV'' − DV' + gU = P,  V̈ − aU'' + DU' + hV = Q",
        "Ü − bU'' − DV' + gU = P,  V̈ − aV'' + DU' + hV = Q (as in [15])",
        "A sympy Galerkin projection of plane-strain elastodynamics on u = X U, v = X V: the radial equation has "
        "−b U'' (shear modulus), the tangential one −a V'' (P-modulus); the coupling −DV'/+DU' is antisymmetric, "
        "as a symmetric stiffness operator requires, with D of [13] (all of [13] confirmed to 1e-10).",
        ("tests/brake/reduced/test_coefficients.py::test_printed_eq12_has_its_second_derivatives_swapped",
         "tests/brake/reduced/test_coefficients.py::test_galerkin_equations_have_the_structure_of_eq15",
         "tests/brake/reduced/test_coefficients.py::test_code_and_printed_eq13_match_the_galerkin_projection"),
    ),
    Erratum(
        "B4", "Section 3, eqs. [12], [16]: P, Q and P_e never defined; typography",
        "P, Q in [12] without definition; P = P_e in [16] without value; P(u − δ) = 0 in [12]; 'P ≥,' in [15]",
        "P = p/M, Q = q/M with the modal mass M = γ∫X² r dr = γB/(ξ² − 1); P_e = gδ, Q_e = f g δ; P(U − δ) = 0; P ≥ 0",
        "The Galerkin projection gives M Ü + … = p (X(1) = 1); dividing by M gives the coefficients of [13] exactly, "
        "and M P_e equals the Lamé p_e of B1.",
        ("tests/brake/reduced/test_coefficients.py::test_modal_mass_is_gamma_B_over_xi2_minus_1",
         "tests/brake/reduced/test_steady.py::test_reduced_steady_state_eq16_agrees_with_lame"),
    ),
    Erratum(
        "B5", "Section 3.1, eqs. [22]-[23]: the explicit beta-scheme and its multipliers",
        "[22]: u̇_m = (1/(1+2β1)){u̇_{m−1} + Δt(1−β1)ü_{m−1} + (2β1/Δt)(u_{m+1} − u_m)}, "
        "ü_{m+1} = (2/Δt²)(u_{m+1} − u_m − Δt u̇_m), with 0.5 ≤ β2 ≤ 1; [23]: λ_m = [Δt² C M⁻¹ Cᵀ]⁻¹ C(u*_{m+1} + X)",
        "β1 is β2, and the second line of [22] defines ü_m (not ü_{m+1}): [22] is then the explicit Newmark scheme "
        "with γ = β2. With β2 ≠ 1/2 the correction of [23] moves the displacement by (β2 + 1/2)Δt² M⁻¹Cᵀλ, so the "
        "multiplier needs [(β2 + 1/2)Δt² C M⁻¹ Cᵀ]⁻¹ for the constraint to hold exactly at t_{m+1}.",
        "Substituting ü_m = 2(u_{m+1} − u_m − Δt u̇_m)/Δt² into u̇_m = u̇_{m−1} + Δt((1−β2)ü_{m−1} + β2 ü_m) gives the "
        "first line of [22] exactly. The ring and FE integrators built on this reading converge at order 2 (β2 = 1/2) "
        "and 1 (β2 = 0.9) in Δt and are stable up to the CFL limit they predict. With the printed Δt² instead of "
        "(β2 + 1/2)Δt² (derivation in docs/theory/contact.md), at β2 = 0.9: a block stuck under a load carries "
        "1/1.4 of it at the first step; the reactions recomputed from the motion through M a + K u = Cᵀλ (M, K "
        "assembled independently) differ from the kernel's and break Coulomb's law; the discrete energy balance "
        "no longer closes. Each of these tests fails with the printed factor.",
        ("tests/brake/ring/test_scheme.py::test_observed_order_in_time",
         "tests/brake/ring/test_scheme.py::test_stability_limit_is_the_cfl_condition",
         "tests/contact/test_exact.py::test_a_stuck_block_does_not_creep_and_carries_the_load_from_the_first_step",
         "tests/contact/test_motion.py::test_implied_reactions_vanish_off_the_contact_and_equal_the_kernels",
         "tests/contact/test_exact.py::test_discrete_energy_balance_closes"),
    ),
    Erratum(
        'H1', "Section 4.1, eq. [29]: argument of φ2'",
        "σ_xx = −2 Re( (2β1² − β2² + 1)/2 φ1'(z1) + (1 + β2²)/2 φ2'(z1) )",
        "… + (1 + β2²)/2 φ2'(z2) )",
        "sympy: the displacements [27]–[28] built from φ1(z1) = P e^{ikz1}, φ2(z2) = Q e^{ikz2} satisfy the steady plane-strain wave equations in the moving frame, and Hooke's law gives [29]–[31] exactly with φ2'(z2); with φ2'(z1) as printed σ_xx differs off the interface (on y = 0, where z1 = z2, the two coincide, so [36] is unaffected).",
        ('tests/halfspace/test_symbolic.py::test_radok_stresses_29_31', 'tests/halfspace/test_symbolic.py::test_eq29_as_printed_has_phi2_of_z1', 'tests/halfspace/test_symbolic.py::test_radok_displacements_solve_the_steady_wave_equations', ),
    ),
    Erratum(
        'H2', 'Section 4.2, after [49]: definition of α (already in SPEC; tests for it)',
        '"F2 ≡ f1(−γ1 sin(απ) + μγ2 cos(απ)) = 0 because tan(απ) = 0"; α is never defined',
        'tan(πα) = μγ2/γ1, 0 < α < 1/2: g of [42] equals −e^{2iπα}, and α is the exponent of the Riemann–Hilbert problem [41]',
        '|g| = 1 and g = −e^{2iπα} to 1e-14; the periodic canonical function X = s^{−(1/2 − α)} jumps by g on SL and 1 on ST; the density f/X⁺ of [46] is real only for this α, which keeps the continuation [39] consistent (checked on the quadrature of [46]).',
        ('tests/halfspace/test_waves.py::test_alpha_is_the_exponent_of_g', 'tests/halfspace/test_fields.py::test_canonical_function_jumps_and_period', 'tests/halfspace/test_fields.py::test_symmetry_39_holds_for_the_quadrature', ),
    ),
    Erratum(
        'H3', 'Section 4.2, eq. [48]: sign of the T* term on the stick zone',
        'Φ(z ∈ ST) = −f1/2 − i{ −(f1/2) μγ2/γ1 + f1 |X|/(2 cos πα) + (T*/γ1)(1 − |X|) }',
        'Φ(z ∈ ST) = −f1/2 − i{ −(f1/2) μγ2/γ1 + f1 |X|/(2 cos πα) − (T*/γ1)(1 − |X|) }',
        "Φ⁻ is bounded at the stick→slip point a (X(a) = 0), hence continuous there. [47] at |X| = 0 gives Im Φ = T*/γ1 + (f1/2) μγ2/γ1; the printed [48] gives −T*/γ1 + (f1/2) μγ2/γ1: a jump of 2T*/γ1 in σ_xy at a bounded end, impossible for a Cauchy integral. With the sign corrected, [47]–[48] are exactly Φ⁻ = A' + iβ0 X⁻ with A' = (f2 − f1)/(1 − g) and β0 = R/cos πα − T*/γ1 (R = −f1/2), the form the periodic solution also has.",
        ('tests/halfspace/test_fields.py::test_corrected_48_is_continuous_at_the_stick_to_slip_point', ),
    ),
    Erratum(
        'H4', 'Section 5, eq. [55] versus [53]: factor 2',
        '[53]: (v − v*) Gm / (c̄(1 − β1β2)) + T(b − 1) = 0; [55]: 2 Gm/(1 − β1β2) · v/c̄ + (b − 1)T = 2 Gm v*/((1 − β1β2) c̄), Gm = γ1 cos απ + μγ2 sin απ',
        'The two cannot both be right: [55] doubles the v-terms of [53] but not its T-term. [49] → [50] → [53] is consistent (no factor 2), and so is the exact periodic decay condition at b = 2 (see H6); [56]–[58] and the claims "H > 0, D < 0 for all b > 1, −1 < c̄ < 0" and "v* = 0 ⇒ only the trivial solution" hold for [55] as printed (then H = γ1 b (K − 1) > 0) and fail for [53] (then H = γ1((K − 1)b − K/2) vanishes on b = K/(2(K − 1)) ∈ (1.38, ∞), where the homogeneous system has a non-trivial solution). The library implements both (`system="printed"` default, `"text"`).',
        "sympy: [55] − 2·[53] + (b − 1)T = 0; det([54], [55]) = (b − 1)H/(γ1 c̄) with H of [57], det([54], [53]) ≠ that; singular-value test on the D = 0 curve for [53]; the exact periodic field built with [53]'s (v, T) at b = 2 leaves no stress at depth, with [55]'s it does (relative residual > 1e-2).",
        ('tests/halfspace/test_inverse.py::test_eq55_is_twice_eq53', 'tests/halfspace/test_inverse.py::test_determinant_56_57_belongs_to_54_55', 'tests/halfspace/test_inverse.py::test_text_system_determinant_vanishes_inside_the_domain', 'tests/halfspace/test_inverse.py::test_H_is_gamma1_b_K_minus_1_and_positive', 'tests/halfspace/test_fields.py::test_exact_decay_condition_agrees_with_53_at_b_2_not_with_55', ),
    ),
    Erratum(
        'H5', 'Section 5, closed form of T after [58]',
        'T = −4bγ1(γ1 + γ1 cos 2απ + μγ2 sin 2απ)/((b − 1)(−1 + β1β2)) × v*/(c̄(4bγ1 cos απ + π(−1 + 2α)(μγ2 sin(πα) + γ1(−1 + 2b + cos(πα)))))',
        'the last factor of the denominator has μγ2 sin(2πα) + γ1(−1 + 2b + cos(2πα)), as in A(b, c̄); with tan πα = μγ2/γ1 this is T = 2γ1 v*/(sin(πλ)(K − 1)(1 − β1β2)(−c̄)(b − 1)), λ = 1/2 − α, K = πλ/sin πλ',
        'sympy solution of [54]–[55]: v = v*/(1 + A) with A as printed (A simplifies to −1/K, so v = v*K/(K − 1) does not depend on b); T equals the corrected formula exactly and differs from the printed one (by up to 30 % over the (b, c̄) grid for ν = 0.3, μ = 0.5; 1.8 % at b = 2, c̄ = −0.7); numerically the corrected formula matches the linear solve to 1e-9 on a (b, c̄) grid.',
        ('tests/halfspace/test_inverse.py::test_closed_form_58_solves_54_55', 'tests/halfspace/test_inverse.py::test_printed_T_formula_is_misprinted', 'tests/halfspace/test_inverse.py::test_v_does_not_depend_on_b_and_loading_is_admissible', ),
    ),
    Erratum(
        'H6', 'Section 4.2, eqs. [49]–[50] (and [53]): not the exact condition for the periodic wave',
        'G(V − V*) Gm/(c(1 − β1β2)) + T*(δ − 1) = 0',
        'for the periodic stick/slip wave (period b, a = 1) the perturbation vanishes at depth iff G(V − V*) Gm/(c(1 − β1β2)) · sin(πλ/b) + T* sin(πλ(b − 1)/b) = 0, λ = 1/2 − α; [50] is this at b = 2 (and in the limit λ → 0); elsewhere the ratio of the two T*-coefficients ranges over (1/K, K), K = πλ/sin πλ ∈ (1, π/2). A modelling approximation rather than a misprint (the paper works with a single-slip-zone X, normalised X(∞) = 1).',
        "closed form Φ = A' + iβ0 X of the periodic Cauchy integral [46] (C0 = 0), checked against its quadrature to 1e-11; its value at depth equals its mean over a period on every horizontal line and equals X∞ Re(A'/X∞); the wave whose v solves the corrected condition decays to 1e-13. With the paper's (v, T) the Figure 14 wave keeps σ_xy/G = 2.9e-4 at depth (8 % of τ*_xy, 31 % of T); the v that makes it decay is 4.83e-3 instead of 3.51e-3.",
        ('tests/halfspace/test_fields.py::test_closed_form_equals_quadrature_of_cauchy_integral', 'tests/halfspace/test_fields.py::test_far_field_and_mean_over_a_period', 'tests/halfspace/test_fields.py::test_decaying_wave_decays_and_keeps_u_x_periodic', 'tests/halfspace/test_fields.py::test_exact_decay_condition_agrees_with_53_at_b_2_not_with_55', ),
    ),
    Erratum(
        'H7', 'Section 5, text before Figure 14: sign of the "slip velocity" singularity',
        '"the slip velocity has a negative singularity at x = b. Therefore, the normal stress shows a positive singularity"',
        'the relative slip velocity V − U̇ = c(1 − β1β2)β0 sin(πλ)|X| is positive on the whole slip zone and tends to +∞ at b, together with σ_yy → +∞; what tends to −∞ is the material velocity U̇ = V* − c u_x,x (and u_x,x itself), of opposite sign to σ_yy by [34]–[35]',
        'closed form on SL; the positive σ_yy singularity and forward slip both require β0 < 0, checked for five waves, with U̇ < −1 (in c2) and V − U̇ > 1 at b − x = 1e-9.',
        ('tests/halfspace/test_fields.py::test_positive_singularity_and_forward_slip', ),
    ),
    Erratum(
        'H8', 'Section 4.2, eqs. [51]–[52]: the second relation (unsettled)',
        '−(V/c)δ + {(V − V*)/c − (1 − β1β2) cos(πα) T*/(2Gγ1)} π(1/2 − α)(δ − 1)/cos(πα) = 0',
        'not settled. [51] equals "the mean over a period of ε*_xx + u_x,x vanishes" (zero mean material velocity) evaluated with [47] and ∫_SL |X| = K(δ − 1), except that this reading gives T*/(Gγ1), not T*/(2Gγ1). In the exact periodic solution the mean of u_x,x vanishes identically (H6), so that mean is ε*_xx = −V*/c ≠ 0 and the reading cannot hold together with decay unless V* = 0; the exact solution has no second relation (a one-parameter family of waves per loading). The library keeps [52] as printed: it is the paper\'s model and fixes b in Figure 14.',
        'derivation in `docs/theory/halfspace.md` §6; mean u_x,x = 0 checked on the exact field.',
        ('tests/halfspace/test_fields.py::test_decaying_wave_decays_and_keeps_u_x_periodic', 'tests/halfspace/test_inverse.py::test_eq54_is_eq52_rearranged', ),
    ),
    Erratum(
        'W1', 'Eq. [15]: the friction law is written with `V̇`, which is not a variable of [15]',
        '`|Q| ≤ fP, Q(1 − V̇) − fP|1 − V̇| = 0` in [15], whose unknowns are `U(Φ), V(Φ)`.',
        "for the wave `V(θ − ct)`, `V̇ = −cV'`, so the slip velocity is `1 − V̇ = 1 + cV'`: stick [17] is `V' = −1/c`, positive slip [18] is `1 + cV' > 0`, reverse slip [19] is `1 + cV' < 0`. The equations of motion in [15] are right (`U̇ = −cU'` gives `(c² − b)U''` and `(c² − a)V''`).",
        'substitution; the closed forms built on it agree with `solve_ivp` of [15] and satisfy the energy balance to `1e−15`.',
        ('tests/brake/waves/test_solve.py::test_inequalities_hold_on_a_fine_grid_in_paper_units', 'tests/brake/waves/test_solve.py::test_zone_closed_forms_agree_with_solve_ivp', ),
    ),
    Erratum(
        'W2', '§3.2: the switching conditions at the end of separation are incomplete',
        '"`P = 0` at the start of the separation zone and `U = δ` and `U\'` jumps back to 0 at the end".',
        "in time order (which is the `φ` order only when `c < 0`) — at lift-off `U = δ`, `U' = 0`, `P = 0`; at landing `U = δ`, `U'` jumps to 0 with the normal impulse `Π = (c² − b)[U']_φ ≥ 0`, **and `V'` jumps too**: `(c² − a)[V']_φ = Q_Π`, `|Q_Π| ≤ fΠ` (Coulomb's law for impulses). The impact either stops the sliding (then stick, or slip at once if `|hV| > fP`) or leaves it in its direction with `Q_Π = ±fΠ`. Without the tangential jump the multiple-shooting system is not closed.",
        'integrating [15] across the landing point; the impulses make the energy balance (shaft work = sliding + impact dissipation) close to `1e−15`, with a positive impact loss; a `solve_ivp` integration that applies this impact law closes after one period to `1e−11`.',
        ('tests/brake/waves/test_solve.py::test_energy_balance_over_a_period', 'tests/brake/waves/test_solve.py::test_closed_forms_agree_with_solve_ivp_across_the_zones', ),
    ),
    Erratum(
        'W3', 'Figure 6: caption copied from Figure 5',
        'caption of Figure 6 "The phase diagram (V, V\') for the stick-slip regime for different angular velocity Ω" (identical to Figure 5); the text says Figure 6 shows "phase diagrams for stick-slip-separation wave in the plane of the normal velocity and normal displacement".',
        "stick-slip-separation waves in the `(U, U')` plane (and `(V, V')` alongside) for several `Ω`.",
        '(see the tests)',
        ('tests/figures/brake/test_waves.py::test_checks_pass_on_computed_data', ),
    ),
    Erratum(
        'W4', 'Figure 5: "different normal contact pressure" vs "different angular velocity Ω"',
        'the text says Figure 5 shows stick-slip phase diagrams "for different normal contact pressure"; the caption says "for different angular velocity Ω".',
        "in the reduced model the stick-slip waves do not depend on the mismatch (hence on the pressure `P_e = gδ`) except through the shift `V_e = fgδ/h` of `V`: changing the pressure only translates the `(V, V')` diagram. Distinct diagrams come from `Ω`, and they are homothetic (`cΩ` fixed, amplitudes ∝ `Ω`). The caption is the consistent reading.",
        'with `V = V_e + W` the slip equation and the stick-exit condition are free of `δ` (`docs/theory/brake-waves.md` §7); numerically `c` is constant to `1e−12` along the stick-slip part of a `δ`-family.',
        ('tests/brake/waves/test_solve.py::test_stick_slip_waves_do_not_depend_on_the_mismatch', 'tests/brake/waves/test_continuation.py::test_stick_slip_part_has_a_constant_speed', 'tests/figures/brake/test_waves.py::test_figure_5_waves_are_self_similar_in_omega', ),
    ),
    Erratum(
        'W5', '§3.1 "stick-separation" (Figure 8) has no counterpart in the reduced model [12]',
        'a stick-separation wave with 2 modes (`f = 2`, `δ = 0.004`, `Ω = 80`) from the finite-element model; §3 lists the reduced model as able to "construct different families of stick-slip and stick-slip-separation waves".',
        "in the reduced model the stick pressure is constant, `P = gδ + D/c`, so lift-off directly from stick (which needs `P → 0`) would need `P = 0` in the whole stick zone. There is no stick-separation travelling wave of [15]; a slip zone always precedes lift-off. At the paper's parameters the reduced model gives a stick-slip wave and near-sonic stick-slip-separation waves whose slip zone is 0.4–3.5 % of the period.",
        '(see the tests)',
        ('tests/brake/waves/test_solve.py::test_stick_separation_waves_do_not_exist', ),
    ),
]


def anchor(erratum_id: str) -> str:
    """The HTML id of erratum ``erratum_id`` in a document made by ``to_markdown(anchors=True)``."""
    return f"erratum-{erratum_id}"


def to_markdown(anchors: bool = False) -> str:
    """The errata as Markdown (the content of ``docs/errata.md``).

    With ``anchors``, each entry's heading is preceded by ``<a id="erratum-E1"></a>`` (see
    `anchor`), which the report links each figure's errata to.
    """
    lines = ["# Errata of the paper", "",
             "Generated from `src/stickslip/errata.py` by `python -m stickslip.errata`; do not edit by hand.",
             "Each entry names the test(s) that settle it.", ""]
    for e in ERRATA:
        lines += [f'<a id="{anchor(e.id)}"></a>', ""] if anchors else []
        lines += [f"## {e.id}. {e.where}", "", f"- **Printed:** {e.printed}", f"- **Correct:** {e.corrected}",
                  f"- **Evidence:** {e.evidence}", "- **Settled by:** " + ", ".join(f"`{t}`" for t in e.tests), ""]
    return "\n".join(lines)


if __name__ == "__main__":
    print(to_markdown(), end="")
