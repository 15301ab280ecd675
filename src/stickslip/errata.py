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
        ("tests/brake/test_brake_steady.py::test_contact_pressure_is_positive_and_printed_eq11_has_the_wrong_sign",
         "tests/brake/test_brake_steady.py::test_steady_state_is_the_lame_solution"),
    ),
    Erratum(
        "B2", "Section 3, eq. [11]: μ printed for Poisson's ratio ν",
        "v_e = δ f X(r) (1 + 1/(ξ²(1 − 2μ))), and μ in p_e",
        "ν in both places: v_e = δ f X(r) (1 + 1/(ξ²(1 − 2ν)))",
        "In [10] μ is Lamé's shear modulus (a stress), so 1 + μ and 1 − 2μ are dimensionally inconsistent. With ν, "
        "v_e matches the sympy Lamé solution exactly and equals δ f g/h of [16].",
        ("tests/brake/test_brake_steady.py::test_reduced_steady_state_eq16_agrees_with_lame",),
    ),
    Erratum(
        "B3", "Section 3, eq. [12]: second derivatives swapped",
        "Ü − bV'' − DV' + gU = P,  V̈ − aU'' + DU' + hV = Q",
        "Ü − bU'' − DV' + gU = P,  V̈ − aV'' + DU' + hV = Q (as in [15])",
        "A sympy Galerkin projection of plane-strain elastodynamics on u = X U, v = X V: the radial equation has "
        "−b U'' (shear modulus), the tangential one −a V'' (P-modulus); the coupling −DV'/+DU' is antisymmetric, "
        "as a symmetric stiffness operator requires, with D of [13] (all of [13] confirmed to 1e-10).",
        ("tests/brake/test_brake_coefficients.py::test_printed_eq12_has_its_second_derivatives_swapped",
         "tests/brake/test_brake_coefficients.py::test_galerkin_equations_have_the_structure_of_eq15",
         "tests/brake/test_brake_coefficients.py::test_code_and_printed_eq13_match_the_galerkin_projection"),
    ),
    Erratum(
        "B4", "Section 3, eqs. [12], [16]: P, Q and P_e never defined; typography",
        "P, Q in [12] without definition; P = P_e in [16] without value; P(u − δ) = 0 in [12]; 'P ≥,' in [15]",
        "P = p/M, Q = q/M with the modal mass M = γ∫X² r dr = γB/(ξ² − 1); P_e = gδ, Q_e = f g δ; P(U − δ) = 0; P ≥ 0",
        "The Galerkin projection gives M Ü + … = p (X(1) = 1); dividing by M gives the coefficients of [13] exactly, "
        "and M P_e equals the Lamé p_e of B1.",
        ("tests/brake/test_brake_coefficients.py::test_modal_mass_is_gamma_B_over_xi2_minus_1",
         "tests/brake/test_brake_steady.py::test_reduced_steady_state_eq16_agrees_with_lame"),
    ),
]


def to_markdown() -> str:
    """The errata as Markdown (the content of ``docs/errata.md``)."""
    lines = ["# Errata of the paper", "",
             "Generated from `src/stickslip/errata.py` by `python -m stickslip.errata`; do not edit by hand.",
             "Each entry names the test(s) that settle it.", ""]
    for e in ERRATA:
        lines += [f"## {e.id}. {e.where}", "", f"- **Printed:** {e.printed}", f"- **Correct:** {e.corrected}",
                  f"- **Evidence:** {e.evidence}", "- **Settled by:** " + ", ".join(f"`{t}`" for t in e.tests), ""]
    return "\n".join(lines)


if __name__ == "__main__":
    print(to_markdown(), end="")
