"""Planted bugs: does the fast test suite still catch them?

A list of realistic physics and numerics bugs ("mutants"), each one exact text substitution in
one source file, and a runner that plants each of them in a temporary copy of the repository and
runs the fast suite (``pytest -m "not slow or slow_by_time"``: with the tests moved to the slow set by time) against it. It is there to show that a change to
the tests (smaller problems, shared fixtures) keeps catching every planted bug the suite caught
before: run it before and after, and compare the tables (``tests/planted_bugs_before.md`` is the
"before").

Run from the repository root with the project's virtual environment::

    .venv/bin/python -m tests.planted_bugs                          # every mutant of MUTANTS
    .venv/bin/python -m tests.planted_bugs --only osc-saltation-sign,kernel-beta2-factor --out table.md
    .venv/bin/python -m tests.planted_bugs --uncaught               # the bugs not caught today
    .venv/bin/python -m tests.planted_bugs --uncaught --together    # ... all planted at once, one run
    .venv/bin/python -m tests.planted_bugs --check                  # do the substitutions still apply?

For each mutant the runner copies the repository (``--root``, by default the one this file lives
in; ``.git`` and ``.venv`` left out) with ``shutil.copy2``, so that ``__pycache__`` folders and
file modification times, hence numba's on-disk caches, stay valid; it then plants the bug (the
``old`` text must occur exactly once), deletes the numba caches of the mutated module and of
every module that imports it, directly or not (numba does not notice that a compiled function it
calls, or a constant it froze, changed), checks that ``stickslip`` is imported from the copy
(``PYTHONPATH=<copy>/src:<copy>``), and runs

    python -m pytest -x -q -m "not slow or slow_by_time" -p no:cacheprovider <hint tests>

with `NOT_A_CHECK` deselected (the FE campaign's code fingerprint fails on any edit of the FE
and contact code, by design: it would "catch" every mutant there). If the hint tests pass, the
whole fast suite runs (``-n 2``, ``-x``); a hint that no longer exists or selects nothing falls
back to it too. The table records the first failing test's node id (``(full)`` when the
fallback found it) and the seconds taken; a mutant that runs past ``--timeout`` is "timeout".
Before the mutants, the hint tests of all of them run once on the unmutated copy, as a control:
they must pass (the table's header says whether they did). One pytest at a time unless
``--jobs`` says more.

``--uncaught --together`` plants every bug of `UNCAUGHT` in one copy and runs the suite once: if
it passes, none of them is caught (a cheap check that they are still not caught; if it fails, run
them one by one to see which).

Each entry of `MUTANTS` (caught today) and `UNCAUGHT` (not caught today; ``why`` says why) has ``id``, ``file`` (relative to the repository root), ``old`` (occurring exactly
once in the file), ``new``, ``what`` (the bug, one line) and ``hint`` (test files or node ids run
first, most likely catcher first).
"""

from __future__ import annotations

import argparse
import ast
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
#: What a copy of the repository leaves out (the rest is copied, ``__pycache__`` folders included).
SKIP = (".git", ".venv", ".pytest_cache", ".hypothesis", "build", "results", "*.egg-info", ".mypy_cache",
        ".ruff_cache", ".ipynb_checkpoints")
#: Tests that fail on any change of the code by design, not because its numbers went wrong: the
#: stored FE campaign's code fingerprint (every file under brake/fem, brake/reduced, fem, contact,
#: friction.py), and the report's use of that campaign (stale, it falls back to the small version).
#: Left out (``--deselect``), or the full-suite fallback would "catch" every mutant there.
NOT_A_CHECK = ("tests/figures/brake/test_fem_campaign.py::test_the_stored_campaign_was_computed_by_the_present_code",
               "tests/figures/brake/test_fem_campaign.py::test_the_report_says_a_campaign_figure_used_the_stored_campaign",
               # since issue 47 the stored campaign is judged by its canary, which moves with any change of
               # the FE numbers (rightly: the campaign is stale then); deselected so that a mutant there
               # counts as caught only by a physics check, as before
               "tests/figures/brake/test_fem_campaign.py::test_the_stored_campaign_is_what_the_present_code_computes")
# the fast suite as it was before its tests of 2 s or more moved to the slow set by measured time
# (tests/slow_by_time.txt, marked slow_by_time as well): the plants' catchers among them still run
PYTEST = ["-m", "pytest", "-x", "-q", "-m", "not slow or slow_by_time", "-p", "no:cacheprovider",
          *(arg for test in NOT_A_CHECK for arg in ("--deselect", test))]


def _m(id, file, old, new, what, hint, why=""):
    return {"id": id, "file": file, "old": old, "new": new, "what": what, "hint": list(hint),
            **({"why": why} if why else {})}


OSC = "src/stickslip/oscillator/"
B = "src/stickslip/brake/"
C = "src/stickslip/contact/"
S = "src/stickslip/system/"
F = "src/stickslip/fem/"
T = "tests/"
MUTANTS: list[dict] = [
    _m("osc-reverse-slip-centre", OSC + "kernel.py",
       "x_c = (s * n_f * mu0 - mu1 * n_f * V) / k", "x_c = (n_f * mu0 - mu1 * n_f * V) / k",
       "compiled event loop: slip-mode centre without the slip sign (Coulomb force has the wrong sign in reverse slip)",
       [T + "oscillator/test_simulate.py::test_switching_states_obey_coulomb_law",
        T + "oscillator/test_simulate.py::test_reverse_slip_spiral_centre_and_growth", T + "oscillator/test_flows.py"]),
    _m("osc-stick-release-damping", OSC + "kernel.py",
       "x_hi = (fs * n_f - c * V) / k", "x_hi = (fs * n_f + c * V) / k",
       "compiled event loop: stick releases at k x = fs N + c V (damping force with the wrong sign in the stick condition)",
       [T + "oscillator/test_continuation.py::test_damped_coulomb_branch_ends_where_the_return_arc_grazes",
        T + "oscillator/test_cycle.py"]),
    _m("osc-sigma-factor2", OSC + "kernel.py",
       "sigma = -(c - mu1 * n_f) / (2 * m)", "sigma = -(c - mu1 * n_f) / m",
       "compiled event loop: decay rate of a slip segment twice too large (missing 1/2 in sigma = -c_eff/2m)",
       [T + "oscillator/test_simulate.py::test_a_falling_law_run_is_not_stopped_by_the_speed_its_closed_form_reaches_after_the_segment", T + "oscillator/test_simulate.py::test_reverse_slip_spiral_centre_and_growth", T + "oscillator/test_simulate.py"]),
    _m("osc-saltation-sign", OSC + "simulate.py",
       "np.eye(2) + np.outer(f_plus - f_minus, grad_h) / denom", "np.eye(2) + np.outer(f_minus - f_plus, grad_h) / denom",
       "oscillator saltation matrix with the jump of the vector field reversed (f- - f+)",
       [T + "oscillator/test_cycle.py::test_stick_slip_multipliers_are_one_and_zero", T + "oscillator/test_cycle.py::test_nontrivial_multiplier_is_the_slope_of_the_return_map", T + "oscillator/test_cycle.py"]),
    _m("osc-saltation-transpose", OSC + "simulate.py",
       "np.eye(2) + np.outer(f_plus - f_minus, grad_h) / denom", "np.eye(2) + np.outer(grad_h, f_plus - f_minus) / denom",
       "oscillator saltation matrix transposed (grad_h (f+ - f-)^T)",
       [T + "oscillator/test_cycle.py::test_stick_slip_multipliers_are_one_and_zero", T + "oscillator/test_cycle.py::test_nontrivial_multiplier_is_the_slope_of_the_return_map", T + "oscillator/test_cycle.py"]),
    _m("osc-effective-damping-sign", OSC + "model.py",
       "return self.damping + self.normal_force * float(self.friction.slope(self.belt_speed))",
       "return self.damping - self.normal_force * float(self.friction.slope(self.belt_speed))",
       "effective damping c - N mu'(V) about steady sliding (Hopf point and equilibrium stability with the wrong sign)",
       [T + "oscillator/test_stability.py::test_linear_law_is_negative_damping", T + "oscillator/test_stability.py"]),
    _m("osc-hopf-d3-factor", OSC + "stability.py",
       "return d1, N * mu3 / 6.0", "return d1, N * mu3 / 2.0",
       "cubic damping coefficient d3 = N mu'''/2 instead of /6 (Hopf point's small-cycle amplitude)",
       [T + "oscillator/test_stability.py::test_stribeck_hopf_speed_and_criticality", T + "oscillator/test_stability.py", T + "oscillator/test_continuation.py::test_small_cycles_near_hopf_follow_the_averaged_amplitude"]),
    _m("osc-release-direction", OSC + "kernel.py",
       "mode_next = 0 if abs(force) <= fs * n_f else (1 if force > 0 else -1)",
       "mode_next = 0 if abs(force) <= fs * n_f else (-1 if force > 0 else 1)",
       "compiled event loop: the mass crossing v = V without sticking slips on in the wrong direction",
       [T + "oscillator/test_simulate.py::test_switching_states_obey_coulomb_law", T + "oscillator/test_simulate.py", T + "oscillator/test_cycle.py"]),
    _m("fric-stribeck-slope-sign", "src/stickslip/friction.py",
       "return -np.sign(v_r) * (self.fs - self.fd) / self.vs * np.exp(-np.abs(v_r) / self.vs)",
       "return np.sign(v_r) * (self.fs - self.fd) / self.vs * np.exp(-np.abs(v_r) / self.vs)",
       "Stribeck law: derivative d mu/d v_r with the wrong sign",
       [T + "test_friction.py::test_slope_matches_finite_difference", T + "oscillator/test_stability.py"]),
    _m("fric-linear-affine", "src/stickslip/friction.py",
       "return (self.fd, self.fd * self.tau)", "return (self.fd, self.tau)",
       "linear weakening: affine form (mu0, mu1) = (fd, tau) instead of (fd, fd tau)",
       [T + "test_friction.py::test_affine_representation_reproduces_the_law", T + "oscillator/test_simulate.py"]),
    _m("brake-lame-pressure", B + "reduced/steady.py",
       "p_e = delta * (xi**2 + 1.0 / (1.0 - 2.0 * nu)) / ((1.0 + nu) * (xi**2 - 1.0))",
       "p_e = delta * (xi**2 - 1.0 / (1.0 - 2.0 * nu)) / ((1.0 + nu) * (xi**2 - 1.0))",
       "Lame steady state: contact pressure p_e with the printed sign of the 1/(1 - 2 nu) term",
       [T + "brake/reduced/test_steady.py::test_steady_state_is_the_lame_solution", T + "brake/reduced/test_steady.py"]),
    _m("brake-coef-h", B + "reduced/coefficients.py",
       "h=2.0 * xi**2 * bt / gB", "h=2.0 * xi * bt / gB",
       "Galerkin coefficient h = 2 xi b~/(gamma B) instead of 2 xi^2 b~/(gamma B)",
       [T + "brake/reduced/test_coefficients.py::test_code_and_printed_eq13_match_the_galerkin_projection", T + "brake/reduced/test_coefficients.py"]),
    _m("brake-coef-D-sign", B + "reduced/coefficients.py",
       "D=(at * C1 - bt * C2) / gB", "D=(at * C1 + bt * C2) / gB",
       "Galerkin coupling D = (a~ C1 + b~ C2)/(gamma B): wrong sign of the shear term",
       [T + "brake/reduced/test_coefficients.py::test_code_and_printed_eq13_match_the_galerkin_projection", T + "brake/reduced/test_coefficients.py"]),
    _m("brake-flutter-rate", B + "reduced/flutter.py",
       "alpha = np.abs(eps) / (2.0 * beta)  # Re s >= 0", "alpha = np.abs(eps) / beta  # Re s >= 0",
       "flutter growth rate Re s = |eps|/Im s instead of |eps|/(2 Im s) (factor 2)",
       [T + "brake/reduced/test_flutter.py::test_growth_rates_match_the_penalised_grid_operator", T + "brake/reduced/test_flutter.py"]),
    _m("brake-flutter-limit", B + "reduced/flutter.py",
       "return float(params.friction * abs(c.D) / (2.0 * np.sqrt(c.a)))", "return float(params.friction * abs(c.D) / (2.0 * c.a))",
       "flutter: the growth-rate limit f|D|/(2a) instead of f|D|/(2 sqrt(a))",
       [T + "brake/reduced/test_flutter.py::test_growth_rate_increases_with_n_toward_its_limit", T + "brake/reduced/test_flutter.py"]),
    _m("waves-stick-pressure", B + "waves/zones.py",
       "return self.g * self.delta + self.D / self.c", "return self.g * self.delta - self.D / self.c",
       "travelling waves: stick-zone pressure g delta - D/c (sign of the coupling term)",
       [T + "brake/waves/test_solve.py::test_stick_pressure_is_constant_and_traction_linear", T + "brake/waves/test_solve.py"]),
    _m("waves-putzer", B + "waves/zones.py",
       "v = e * (ch * v0 + sh * (-det * x0 + tau * v0))", "v = e * (ch * v0 + sh * (-det * x0 - tau * v0))",
       "travelling waves: closed-form slip flow (Putzer) with the wrong sign of the damping term in V'",
       [T + "brake/waves/test_solve.py::test_zone_closed_forms_agree_with_solve_ivp", T + "brake/waves/test_solve.py"]),
    _m("ring-stencil-swap", B + "ring/scheme.py",
       "C[0, 1, dj + 1] = [[-c.b / d**2, -dj * c.D / (2 * d)], [dj * c.D / (2 * d), -c.a / d**2]]",
       "C[0, 1, dj + 1] = [[-c.a / d**2, -dj * c.D / (2 * d)], [dj * c.D / (2 * d), -c.b / d**2]]",
       "ring stencil: the off-diagonal Laplacian weights of U and V swapped (a for b)",
       [T + "contact/test_paths.py::test_ring_stencil_is_the_centred_differences_of_eq12", T + "brake/ring/test_scheme.py"]),
    _m("ring-steady-V", B + "ring/scheme.py",
       "u[0::2], u[1::2] = p.delta, p.delta * p.friction * c.g / c.h", "u[0::2], u[1::2] = p.delta, p.delta * p.friction * c.h / c.g",
       "ring: steady sliding V_e = delta f h/g instead of delta f g/h",
       [T + "brake/ring/test_run.py::test_initial_conditions", T + "brake/ring/test_run.py", T + "brake/ring/test_scheme.py"]),
    _m("contact-cfl", C + "scheme.py",
       "undamped = float(np.sqrt(2.0 / self.beta2) / self.omega_max)", "undamped = float(np.sqrt(1.0 / self.beta2) / self.omega_max)",
       "explicit scheme: CFL limit sqrt(1/beta2)/omega_max instead of sqrt(2/beta2)/omega_max",
       [T + "brake/ring/test_scheme.py::test_stability_limit_is_the_cfl_condition", T + "brake/ring/test_scheme.py"]),
    _m("contact-initial-velocity", C + "scheme.py",
       "return StepState(u0, v0 - self.dt * a, a)", "return StepState(u0, v0 + self.dt * a, a)",
       "explicit scheme: start velocity v_{-1} = v0 + dt a_{-1} (sign)",
       [T + "brake/ring/test_scheme.py::test_observed_order_in_time", T + "brake/ring/test_scheme.py", T + "contact/test_exact.py"]),
    _m("contact-slip-work", C + "scheme.py",
       "slip = du[..., tangent] - speed * self.dt", "slip = du[..., tangent] + speed * self.dt",
       "energy books: slip measured as du_t + s dt (friction dissipation wrong)",
       [T + "contact/test_exact.py::test_discrete_energy_balance_closes", T + "contact/test_conditions.py"]),
    _m("kernel-beta2-factor", C + "kernel.py",
       "return (beta2 + 0.5) * dt * dt", "return (beta2 + 1.0) * dt * dt",
       "contact kernel: multiplier factor (beta2 + 1) dt^2 instead of (beta2 + 1/2) dt^2 (erratum B5 undone)",
       [T + "contact/test_exact.py::test_a_stuck_block_does_not_creep_and_carries_the_load_from_the_first_step", T + "contact/test_exact.py", T + "contact/test_conditions.py"]),
    _m("kernel-static-coefficient", C + "kernel.py",
       "held = fs * g * p\n", "held = f * g * p\n",
       "contact kernel: a node sticks while |r*| <= f r_n (kinetic) instead of fs r_n (static coefficient ignored)",
       [T + "contact/test_kinetic_law.py::test_a_falling_law_in_the_kernel_converges_to_the_oscillators_stick_slip_cycle", T + "contact/test_exact.py", T + "contact/test_kinetic_law.py"]),
    _m("kernel-bilateral", C + "kernel.py",
       "p = on * max((gap0[j] - u[r]) / cdt2, 0.0)", "p = on * ((gap0[j] - u[r]) / cdt2)",
       "contact kernel: normal multiplier not clipped at 0 (the contact pulls: bilateral instead of unilateral)",
       [T + "contact/test_motion.py::test_implied_reactions_vanish_off_the_contact_and_equal_the_kernels", T + "contact/test_motion.py", T + "contact/test_exact.py"]),
    _m("kernel-predictor-beta2", C + "kernel.py",
       "vs = v[k] + dt * ((1.0 - beta2) * a[k] + beta2 * A[k])", "vs = v[k] + dt * (beta2 * a[k] + (1.0 - beta2) * A[k])",
       "explicit predictor: beta2 and 1 - beta2 swapped (invisible at beta2 = 1/2)",
       [T + "brake/ring/test_scheme.py::test_stability_limit_is_the_cfl_condition", T + "contact/test_conditions.py", T + "brake/ring/test_scheme.py"]),
    _m("kernel-state-codes", C + "kernel.py",
       "SLIP_POS * (trial > held) + SLIP_NEG * (trial < -held)", "SLIP_NEG * (trial > held) + SLIP_POS * (trial < -held)",
       "contact kernel: slip and reverse-slip node states swapped",
       [T + "contact/test_motion.py::test_the_run_meets_every_state", T + "contact/test_motion.py", T + "contact/test_conditions.py"]),
    _m("kernel-ring-wrap", C + "kernel.py",
       "jp = j + 1 if j < N - 1 else 0", "jp = j + 1 if j < N - 1 else 1",
       "single-ring stencil: periodic wrap of the last node to node 1 instead of node 0 (off by one)",
       [T + "contact/test_paths.py::test_ring_stencil_is_the_centred_differences_of_eq12", T + "contact/test_paths.py"]),
    _m("kernel-block-transpose", C + "kernel.py",
       "a1 += data[b + 2] * x0 + data[b + 3] * x1", "a1 += data[b + 1] * x0 + data[b + 3] * x1",
       "2x2 block sparse product: reads the block's (0,1) entry for (1,0) (a transposed block)",
       [T + "contact/test_paths.py::test_ring_stencil_is_the_centred_differences_of_eq12", T + "contact/test_paths.py"]),
    _m("kernel-weakening-speed", C + "kernel.py",
       "x = cdt * (excess - f * p) / slope", "x = cdt * (excess - f * p)",
       "contact kernel: linear-weakening slip speed of the step without its 1/(1 - cdt p f tau) factor",
       [T + "contact/test_kinetic_law.py::test_the_kinetic_coefficient_is_taken_at_the_slip_speed_it_makes", T + "contact/test_kinetic_law.py"]),
    _m("coupled-reaction-sign", C + "coupled.py",
       "u[i] -= scale * mw[k] * fx * inv_mass[i]", "u[i] += scale * mw[k] * fx * inv_mass[i]",
       "two-body contact: the master's x reaction with the slave's sign (action without reaction)",
       [T + "fem/test_pair_run.py::test_steady_sliding_of_the_pair_is_a_state_of_the_scheme", T + "fem/test_pair_run.py"]),
    _m("energy-strain-index", C + "energy.py",
       "strain = 0.5 * np.einsum(\"mi,mi->m\", Ku, tr.u[1:])", "strain = 0.5 * np.einsum(\"mi,mi->m\", Ku, tr.u[:-1])",
       "energy books: strain energy u_m K u_m instead of the scheme's u_m K u_{m+1}",
       [T + "contact/test_exact.py::test_discrete_energy_balance_closes", T + "contact/test_conditions.py"]),
    _m("energy-numerical", C + "energy.py",
       "numerical = (beta2 - 0.5) * np.einsum", "numerical = (beta2 - 1.0) * np.einsum",
       "energy books: numerical dissipation (beta2 - 1) instead of (beta2 - 1/2)",
       [T + "contact/test_exact.py::test_discrete_energy_balance_closes", T + "contact/test_conditions.py"]),
    _m("classify-speed-sign", C + "classify.py",
       "corr = np.real(np.fft.ifft(np.conj(np.fft.fft(a)) * np.fft.fft(b)))",
       "corr = np.real(np.fft.ifft(np.fft.fft(a) * np.conj(np.fft.fft(b))))",
       "regime classification: cross-correlation conjugated on the wrong side (wave speed with the wrong sign)",
       [T + "contact/test_classify.py::test_synthetic_travelling_wave_is_recognised", T + "contact/test_classify.py"]),
    _m("classify-mode-offset", C + "classify.py",
       "n_fft = int(np.argmax(power[1:]) + 1)", "n_fft = int(np.argmax(power[1:]))",
       "regime classification: dominant Fourier mode off by one",
       [T + "contact/test_classify.py::test_synthetic_travelling_wave_is_recognised", T + "contact/test_classify.py"]),
    _m("rsf-aging-sign", "src/stickslip/rsf/law.py",
       "return self.v_ref / dc * np.exp(-psi) - v / dc", "return self.v_ref / dc * np.exp(psi) - v / dc",
       "rate-and-state aging law: healing term exp(+psi) instead of exp(-psi)",
       [T + "rsf/test_slider.py::test_a_velocity_step_of_a_stiff_slider_is_the_rigid_closed_form", T + "rsf/test_slider.py"]),
    _m("rsf-slip-law", "src/stickslip/rsf/law.py",
       "return -(v / dc) * (psi + log_v - math.log(self.v_ref))", "return -(v / dc) * (psi - log_v + math.log(self.v_ref))",
       "rate-and-state slip law: ln(V/V0) with the wrong sign in the state evolution",
       [T + "rsf/test_slider.py::test_a_velocity_step_of_a_stiff_slider_is_the_rigid_closed_form", T + "rsf/test_slider.py", T + "system/test_rate_state.py"]),
    _m("rsf-regularised", "src/stickslip/rsf/law.py",
       "log_z = log_v - math.log(2.0 * self.v_ref) + big_psi / self.a", "log_z = log_v - math.log(self.v_ref) + big_psi / self.a",
       "regularised rate-and-state friction: asinh(V/V0 e^(Psi/a)) without the factor 1/2",
       [T + "rsf/test_kernel.py", T + "rsf/test_slider.py"]),
    _m("rsf-quasistatic", "src/stickslip/rsf/slider.py",
       "- mu_psi * (law.b_values @ dpsi)) / mu_v", "+ mu_psi * (law.b_values @ dpsi)) / mu_v",
       "quasi-static spring-slider: state evolution enters the slip-rate equation with the wrong sign",
       [T + "rsf/test_slider.py::test_slide_hold_slide_against_an_independent_stiff_solve", T + "rsf/test_slider.py"]),
    _m("sys-flow-weakening", S + "flow.py",
       "c_eff = c_eff - (W * falling) @ W.T", "c_eff = c_eff + (W * falling) @ W.T",
       "system flow: a falling friction law as positive instead of negative damping",
       [T + "system/test_simulate.py::test_one_contact_on_one_dof_is_the_oscillator", T + "system/test_simulate.py", T + "system/test_floquet.py"]),
    _m("sys-saltation-transpose", S + "floquet.py",
       "return np.eye(f_minus.size) + np.outer(f_plus - f_minus, normal) / rate",
       "return np.eye(f_minus.size) + np.outer(normal, f_plus - f_minus) / rate",
       "system saltation matrix transposed: n (f+ - f-)^T",
       [T + "system/test_floquet.py::test_the_saltation_matrix_maps_the_field_before_onto_the_field_after_and_keeps_the_surface",
        T + "system/test_floquet.py"]),
    _m("sys-steady-slope", S + "steady.py",
       "c_eff += c.normal_force * slope * np.outer(c.direction, c.direction)",
       "c_eff -= c.normal_force * slope * np.outer(c.direction, c.direction)",
       "steady sliding of a system: friction slope N mu'(V) subtracted from the damping",
       [T + "system/test_steady.py::test_one_dof_eigenvalues_are_the_roots_of_its_characteristic_polynomial", T + "system/test_steady.py"]),
    _m("sys-steady-unilateral", S + "steady.py",
       "sign * mu * k_n * np.outer(w, nv)", "sign * mu * k_n * np.outer(nv, w)",
       "steady sliding on a unilateral contact: the friction-normal stiffness coupling transposed",
       [T + "system/test_unilateral.py::test_steady_sliding_eigenvalues_are_the_closed_form", T + "system/test_steady.py", T + "system/test_unilateral.py"]),
    _m("sys-forced-stick-multiplier", S + "forced.py",
       "mult = np.concatenate([np.linalg.eigvals(R), np.zeros(2 * system.dofs - Q.shape[1])])",
       "mult = np.concatenate([np.linalg.eigvals(R), np.ones(2 * system.dofs - Q.shape[1])])",
       "forced response: a contact sticking at the section gets the multiplier 1 instead of 0",
       [T + "system/test_forced.py::test_a_response_that_sticks_at_phase_zero_has_a_zero_multiplier_and_finite_differences_along_the_stick",
        T + "system/test_forced.py"]),
    _m("sys-rate-state-complex-step", S + "rate_state.py",
       "mu = law.kinetic(v) + (1j * law.slope(v) * vr[i].imag", "mu = law.kinetic(v) + (-1j * law.slope(v) * vr[i].imag",
       "rate-and-state systems: the complex-step derivative of a slip-speed law beside them with the wrong sign",
       [T + "system/test_rate_state_mixed.py::test_steady_sliding_on_two_belts_has_the_roots_of_its_characteristic_polynomial",
        T + "system/test_rate_state_mixed.py", T + "system/test_rate_state.py"]),
    _m("hs-direct-b", "src/stickslip/halfspace/direct.py",
       "return 1.0 - k * rd.gamma_mod * (v - vs) / (rd.one_minus_b1b2 * rd.cbar * T)",
       "return 1.0 + k * rd.gamma_mod * (v - vs) / (rd.one_minus_b1b2 * rd.cbar * T)",
       "direct problem: the stick length b(c) of [53] with the wrong sign of its correction",
       [T + "halfspace/test_direct.py::test_round_trip_inverse_then_direct", T + "halfspace/test_direct.py"]),
    _m("brake-fem-fourier-phase", B + "fem/modes.py",
       "phase = np.exp(1j * n * system.mesh.h_theta * np.arange(-1, 2))",
       "phase = np.exp(2j * n * system.mesh.h_theta * np.arange(-1, 2))",
       "FE annulus: Fourier block K_n with the phase of mode 2n (a factor 2 in the angle step)",
       [T + "brake/fem/test_fem_modes.py::test_fem_frequencies_converge_to_bessel_roots_with_order_two",
        T + "brake/fem/test_fem_modes.py"]),
    _m("hs-wave-speed-ratio", "src/stickslip/halfspace/waves.py",
       "return math.sqrt(2.0 * (1.0 - nu) / (1.0 - 2.0 * nu))", "return math.sqrt((1.0 - nu) / (1.0 - 2.0 * nu))",
       "half-space: c1/c2 = sqrt((1 - nu)/(1 - 2 nu)) (factor 2 lost)",
       [T + "halfspace/test_waves.py::test_wave_speeds_from_moduli", T + "halfspace/test_waves.py"]),
    _m("hs-radok-exponent", "src/stickslip/halfspace/waves.py",
       "lam = np.arctan2(gamma1, mu * gamma2) / np.pi", "lam = np.arctan2(mu * gamma2, gamma1) / np.pi",
       "Radok: the exponent lambda = 1/2 - alpha computed as alpha (arctan arguments swapped)",
       [T + "halfspace/test_waves.py::test_radok_stable_forms_match_definitions", T + "halfspace/test_waves.py", T + "halfspace/test_inverse.py"]),
    _m("hs-inverse-a12", "src/stickslip/halfspace/inverse.py",
       "a12 = -np.pi * rd.lam * bm1 * rd.one_minus_b1b2 / (2.0 * rd.gamma1)", "a12 = -np.pi * rd.lam * bm1 * rd.one_minus_b1b2 / rd.gamma1",
       "inverse problem: the T-coefficient of [54] without its 1/2",
       [T + "halfspace/test_inverse.py::test_D_negative_H_positive_dense_grid", T + "halfspace/test_inverse.py"]),
    _m("fem-plane-stress", F + "assembly.py",
       "return (2 * lam * mu / (lam + 2 * mu) if self.plane == \"stress\" else lam), mu",
       "return (lam * mu / (lam + 2 * mu) if self.plane == \"stress\" else lam), mu",
       "FE material: plane-stress lambda* = lambda mu/(lambda + 2 mu) (factor 2 lost)",
       [T + "fem/test_assembly.py::test_uniform_strain_stores_the_closed_form_energy_and_rigid_motions_none", T + "fem/test_assembly.py", T + "fem/test_materials.py"]),
    _m("fem-shear-factor", F + "assembly.py",
       "return 2.0 * w.mu * ddot(sym_grad(u), sym_grad(v)) + w.lam * div(u) * div(v)",
       "return w.mu * ddot(sym_grad(u), sym_grad(v)) + w.lam * div(u) * div(v)",
       "FE stiffness: mu eps:eps instead of 2 mu eps:eps",
       [T + "fem/test_assembly.py::test_uniform_strain_stores_the_closed_form_energy_and_rigid_motions_none", T + "fem/test_assembly.py"]),
    _m("fem-ortho-rotation", F + "orthotropic.py",
       "return T.T @ self.material_stiffness @ T", "return T @ self.material_stiffness @ T.T",
       "orthotropic material: D rotated to x-y as T D_m T^T instead of T^T D_m T (wrong transpose)",
       [T + "fem/test_orthotropic.py::test_a_turned_axis_is_the_turned_body", T + "fem/test_orthotropic.py"]),
    _m("fem-ortho-engineering-shear", F + "assembly.py",
       "a, b = (eu[0, 0], eu[1, 1], 2.0 * eu[0, 1]), (ev[0, 0]", "a, b = (eu[0, 0], eu[1, 1], eu[0, 1]), (ev[0, 0]",
       "orthotropic stiffness: tensor instead of engineering shear strain on one side of the form",
       [T + "fem/test_orthotropic.py::test_a_turned_axis_is_the_turned_body", T + "fem/test_orthotropic.py"]),
    _m("fem-spring-component", F + "boundary.py",
       "diag[1::2] += spring.stiffness[1] * share", "diag[1::2] += spring.stiffness[0] * share",
       "boundary springs: the y spring takes the x stiffness",
       [T + "fem/test_boundary.py::test_a_spring_meets_a_linear_field_with_its_exact_integral", T + "fem/test_boundary.py"]),
    _m("fem-pressure-sign", F + "boundary.py",
       "per_node = load.pressure * inward + length[..., None]", "per_node = -load.pressure * inward + length[..., None]",
       "boundary load: a pressure pulls instead of pushes",
       [T + "fem/test_boundary.py::test_a_uniform_load_gives_its_resultant_and_moment", T + "fem/test_boundary.py"]),
    _m("cea-circulatory-sign", F + "cea.py",
       "rows = sp.identity(K.shape[0], format=\"csr\") - P", "rows = sp.identity(K.shape[0], format=\"csr\") + P",
       "CEA: tangential rows K_t + f K_n instead of K_t - f K_n (friction coupling sign)",
       [T + "fem/test_linearisation.py::test_the_block_on_a_belt_linearises_as_its_equations_of_motion", T + "fem/test_linearisation.py", T + "fem/test_cea.py"]),
    _m("cea-slope-damping", F + "cea.py",
       "extra = sp.csr_matrix((force * slope,", "extra = sp.csr_matrix((-force * slope,",
       "CEA: friction slope N mu'(V) as damping with the wrong sign",
       [T + "fem/test_friction_law.py::test_a_stiff_block_on_a_falling_law_has_the_oscillators_eigenvalue", T + "fem/test_friction_law.py"]),
    _m("cea-frequency", F + "cea.py",
       "return self.s.imag / (2.0 * np.pi)", "return self.s.imag / np.pi",
       "CEA: frequency Im s / pi instead of Im s / (2 pi)",
       [T + "fem/test_stick_slip.py::test_the_complex_eigenvalue_analysis_finds_the_oscillators_mode_of_a_stiff_block",
        T + "fem/test_cea_options.py", T + "fem/test_cea.py"]),
    _m("pair-dual-shape", F + "pair.py",
       "Ns = (2.0 - 3.0 * eta, 3.0 * eta - 1.0)", "Ns = (1.0 - eta, eta)",
       "mortar: standard instead of dual shape functions in M (inconsistent with the diagonal D)",
       [T + "fem/test_pair_run.py::test_a_run_grows_at_the_rate_of_the_ceas_most_unstable_mode", T + "fem/test_pair.py"]),
    _m("pair-friction-sign", F + "pair.py",
       "B = c * sup.columns(self.G[A] + sp.diags(self.kinetic[A] * g * rate) @ self.T[A])",
       "B = c * sup.columns(self.G[A] - sp.diags(self.kinetic[A] * g * rate) @ self.T[A])",
       "pair CEA: the friction force on the multipliers with the wrong sign",
       [T + "fem/test_pair.py::test_a_stiff_partner_reproduces_the_rigid_surface", T + "fem/test_pair.py", T + "fem/test_pair_run.py"]),
    _m("store-checksum-first", "src/stickslip/sweep/store.py",
       "for col in ordered:", "for col in ordered[:1]:",
       "sweep store: a point's checksum covers only its first output",
       [T + "test_sweep.py::test_a_stored_point_whose_content_changed_is_computed_again_and_said", T + "test_sweep.py"]),
    _m("cf-scaled-units", "src/stickslip/cf.py",
       "attrs[\"scale\"] = units\n        attrs[\"units\"] = \"1\"", "attrs[\"scale\"] = units",
       "CF attributes: a scaled unit (R, 1/Omega) kept in units instead of units = 1 plus scale",
       [T + "test_cf.py::test_finish_scales_units_and_codes", T + "test_cf.py"]),
    _m("validation-at-least", "src/stickslip/validation.py",
       "    if v < bound:\n        raise ParameterError(name, v, f\">= {bound_name}",
       "    if v <= bound:\n        raise ParameterError(name, v, f\">= {bound_name}",
       "validation: fs >= fd checked as fs > fd (< for <=: Coulomb with fs = fd refused)",
       [T + "test_friction.py::test_linear_weakening_validity_range", T + "test_friction.py", T + "test_validation.py"]),
    _m("quantities-open-end", "src/stickslip/quantities/core.py",
       "above = value > self.lo if self.lo_open else value >= self.lo", "above = value >= self.lo",
       "declared ranges: an open lower end accepts its end value (0 accepted where > 0 is declared)",
       [T + "test_quantities.py::test_ranges_read_as_written_and_check_both_ends", T + "test_quantities.py"]),
    _m("cli-option-name", "src/stickslip/cli/common.py",
       "return value if value is None else quantity.check(value, flag)", "return value if value is None else quantity.check(value)",
       "CLI: a declared option's range error names the parameter, not the option as typed",
       [T + "test_quantities.py::test_a_value_just_beyond_a_declared_end_is_refused_naming_the_option_and_the_range", T + "test_quantities.py", T + "test_cli.py"]),
    _m("cli-exit-code", "src/stickslip/cli/__init__.py",
       "return fail(\"no solution\", exc, 1)", "return fail(\"no solution\", exc, 2)",
       "CLI: no solution exits 2 (bad input) instead of 1",
       [T + "test_cli.py::test_no_cycle_exits_1", T + "test_cli.py", T + "oscillator/test_cycle.py"]),
    # not caught before issue 44; caught since by the tests written for them
    _m("osc-stick-limit-strict", OSC + "model.py",
       "if lo <= x <= hi:\n            return Mode.STICK", "if lo < x < hi:\n            return Mode.STICK",
       "Filippov mode choice: a mass arriving exactly at the stick limit slips instead of sticking (< for <=)",
       [T + "oscillator/test_simulate.py::test_a_mass_moving_with_the_belt_exactly_at_a_stick_limit_sticks", T + "oscillator/test_simulate.py"]),
    _m("coupled-mass-weight", C + "coupled.py",
       "w += mw[k] * mw[k] * inv_mass[mdof[k]]", "w += mw[k] * inv_mass[mdof[k]]",
       "two-body contact: effective compliance W_j with w_jl instead of w_jl^2 of the master nodes",
       [T + "contact/test_exact.py::test_two_bodies_one_sweep_is_exact_for_nodes_that_share_no_master_node", T + "fem/test_pair_run.py"]),
    _m("store-checksum-index", "src/stickslip/sweep/store.py",
       "h = hashlib.sha256(repr(tuple(int(i) for i in idx)).encode())", "h = hashlib.sha256()",
       "sweep store: checksum without the point's grid index (swapped points pass)",
       [T + "test_sweep.py::test_two_points_whose_records_were_swapped_are_computed_again_and_said", T + "test_sweep.py"]),
    _m("cf-monotone-index", "src/stickslip/cf.py",
       "(np.all(step > 0) or np.all(step < 0))", "(np.all(step >= 0) or np.all(step <= 0))",
       "CF: a coordinate with repeated values is made a dimension's index (not strictly monotone)",
       [T + "test_cf.py::test_a_coordinate_with_a_repeated_value_is_not_made_an_index", T + "test_cf.py"]),
    # the flows' products on the constraints' rows and the saltations as rank-one updates (issue 47: the
    # waves' stability figure 232 -> 130 s)
    _m("sys-jump-rank-one-transpose", S + "floquet.py",
       "out += np.outer(u / rate, flow.rows[r][:2 * n] @ out)", "out += np.outer(flow.rows[r][:2 * n] / rate, u @ out)",
       "system monodromy: a crossing's saltation applied as (I + n (f+ - f-)^T / rate), transposed",
       [T + "system/test_floquet.py::test_the_monodromy_is_the_derivative_of_the_run", T + "system/test_floquet.py"]),
    _m("flow-constraint-stiffness-sign", S + "flow.py",
       "A[n + rows_e, :n] += ME @ LK", "A[n + rows_e, :n] -= ME @ LK",
       "system flow: the constraint forces' share of the stiffness, -P K = -M^-1 K + M^-1 E L K, with the wrong sign",
       [T + "system/test_simulate.py", T + "system/test_floquet.py"]),
    _m("flow-pinv-diagonal-factor", S + "flow.py",
       "return np.diag(np.divide(1.0, d, out=np.zeros_like(d), where=big))",
       "return np.diag(np.divide(2.0, d, out=np.zeros_like(d), where=big))",
       "system flow: the pseudo-inverse of a diagonal constraint matrix twice too large",
       [T + "system/test_simulate.py", T + "system/test_floquet.py", T + "system/test_rigid.py"]),
    # 3-D solids (issue 45's first increment)
    _m("solid-lame-swapped", F + "solid.py",
       "return ddot(2.0 * mu * eu + lam * eye(trace(eu), 3), sym_grad(v))",
       "return ddot(2.0 * lam * eu + mu * eye(trace(eu), 3), sym_grad(v))",
       "3-D solid: the Lame parameters swapped in the stiffness", [T + "fem/test_solid.py"]),
    _m("solid-shear-factor", F + "solid.py",
       "return ddot(2.0 * mu * eu + lam * eye(trace(eu), 3), sym_grad(v))",
       "return ddot(mu * eu + lam * eye(trace(eu), 3), sym_grad(v))",
       "3-D solid: the stress 2 mu eps without its factor 2", [T + "fem/test_solid.py"]),
    _m("solid-mass-density", F + "solid.py", "return m.density * dot(u, v)", "return dot(u, v)",
       "3-D solid: the mass without the density", [T + "fem/test_solid.py"]),
    _m("solid-roller-axis", F + "solid.py", "held.append(3 * solid.nodes(group, \"rollers\") + AXES[axis])",
       "held.append(3 * solid.nodes(group, \"rollers\") + (AXES[axis] + 1) % 3)",
       "3-D solid: a roller holds the degree of freedom of the next axis", [T + "fem/test_solid.py"]),
    _m("solid-units", F + "solid.py", 'UNITS = {"m": 1.0, "mm": 1e-3}', 'UNITS = {"m": 1.0, "mm": 1e3}',
       "3-D solid: a mesh in millimetres scaled up instead of down", [T + "fem/test_solid.py"]),
    _m("solid-turn", F + "solid.py", "cells[vol < 0] = cells[vol < 0][:, [0, 2, 1, 3, 6, 5, 4, 7, 9, 8]",
       "cells[vol < 0] = cells[vol < 0][:, [0, 1, 2, 3, 6, 5, 4, 7, 9, 8]",
       "3-D solid: tetrahedra numbered the other way not turned round", [T + "fem/test_solid.py"]),
    _m("solid-pressure-sign", F + "solid.py", "return -load.pressure * dot(w.n, v) + t[0]",
       "return load.pressure * dot(w.n, v) + t[0]",
       "3-D solid: a pressure pulls the face out instead of pushing it in", [T + "fem/test_solid.py"]),
    _m("solid-rigid-rotations", F + "solid.py", "rigid[:, :, 3 + k] = np.cross(w, r)", "rigid[:, :, 3 + k] = 0.0",
       "3-D solid: the static solve's support check forgets the rotations", [T + "fem/test_solid.py"]),
    _m("solid-hrz-weights", F + "solid.py", "share * (1.0 / 36.0 if k < 4 else 4.0 / 27.0)",
       "share * (4.0 / 27.0 if k < 4 else 1.0 / 36.0)",
       "3-D solid: a quadratic tetrahedron's lumped mass with the corner and edge weights swapped",
       [T + "fem/test_solid.py"]),
    _m("solid-dof-component", F + "solid.py", "return mesh, element, 3 * node + component, vertex",
       "return mesh, element, 3 * node + (component + 1) % 3, vertex",
       "3-D solid: scikit-fem's degrees of freedom mapped to the wrong component of their node",
       [T + "fem/test_solid.py"]),
    _m("solid-turn-middles", F + "solid.py", "[0, 2, 1, 3, 6, 5, 4, 7, 9, 8][:cells.shape[1]]",
       "[0, 2, 1, 3, 4, 5, 6, 7, 8, 9][:cells.shape[1]]",
       "3-D solid: a turned quadratic tetrahedron keeps its edge middles where they were", [T + "fem/test_solid.py"]),
    _m("solid-ortho-turn-transposed", F + "solid.py", 'turned = np.einsum("pi,qj,rk,sl,ijkl->pqrs", A, A, A, A, tensor)',
       'turned = np.einsum("ip,jq,kr,ls,ijkl->pqrs", A, A, A, A, tensor)',
       "3-D orthotropic solid: its stiffness turned by the inverse of its axes", [T + "fem/test_solid.py"]),
    _m("solid-ortho-shear-factor", F + "solid.py", "vu = [eu[i, j] * (1.0 if i == j else 2.0) for i, j in VOIGT]",
       "vu = [eu[i, j] for i, j in VOIGT]",
       "3-D orthotropic solid: tensor shear strains where the Voigt stiffness takes engineering ones",
       [T + "fem/test_solid.py"]),
    _m("solid-ortho-g13-g23", F + "solid.py", "S[3, 3], S[4, 4], S[5, 5] = 1 / self.g23, 1 / self.g13, 1 / self.g12",
       "S[3, 3], S[4, 4], S[5, 5] = 1 / self.g13, 1 / self.g23, 1 / self.g12",
       "3-D orthotropic solid: the 1-3 and 2-3 shear moduli swapped", [T + "fem/test_solid.py"]),
    _m("cad-step-units", F + "cad.py", 'gmsh.option.setString("Geometry.OCCTargetUnit", "M")',
       'gmsh.option.setString("Geometry.OCCTargetUnit", "MM")',
       "CAD: a STEP imported in millimetres into a mesh read as metres (a brake 1000 times too large)",
       [T + "fem/test_solid.py"]),
    _m("solid-rayleigh-beta-mass", F + "solid.py", "C = C + m.alpha * sp.diags_array(lumped) + m.beta * Kg",
       "C = C + m.alpha * sp.diags_array(lumped) + m.beta * Mg",
       "3-D solid: Rayleigh's beta times the mass instead of the stiffness", [T + "fem/test_solid.py"]),
    _m("mortar3-not-dual", F + "mortar3.py", "A = np.diag(w @ Nt) @ np.linalg.inv(Nt.T @ (w[:, None] * Nt))",
       "A = np.eye(len(face))", "3-D mortar: standard multipliers (phi = N) instead of the dual ones",
       [T + "fem/test_solid_pair.py"]),
    _m("mortar3-no-transform", F + "mortar3.py", "    a = TRANSFORM\n", "    a = 0.0\n",
       "3-D mortar: quadratic faces' shape functions not transformed (corners' int N = 0)",
       [T + "fem/test_solid_pair.py"]),
    _m("mortar3-quad-shape", F + "mortar3.py", "(1 + x) * (1 + y), (1 - x) * (1 + y)])",
       "(1 - x) * (1 + y), (1 + x) * (1 + y)])", "3-D mortar: a quadrilateral's last two shape functions swapped",
       [T + "fem/test_solid_pair.py"]),
    _m("mortar3-projection-sign", F + "mortar3.py", "gap = float(o_m[f] @ (mid - xm[m_faces[f, 0]])) / facing",
       "gap = -float(o_m[f] @ (mid - xm[m_faces[f, 0]])) / facing",
       "3-D mortar: the gap along the normal with its sign reversed (a body inside the other taken as apart)",
       [T + "fem/test_solid_pair.py"]),
    _m("pair3-tangent-rows", F + "pair.py", "cols = np.concatenate([dim * A.col + k for k in range(dim)])",
       "cols = np.concatenate([dim * A.col + (k + 1) % dim for k in range(dim)])",
       "pair: a contact row's components put on the next coordinate's degree of freedom",
       [T + "fem/test_solid_pair.py", T + "fem/test_pair.py"]),
    _m("reduced-friction-transposed", F + "reduced.py", "F = (k * sup.columns(problem.T[A]).T @ W2G).tocsc()",
       "F = (k * W2G.T @ sup.columns(problem.T[A])).tocsc()",
       "reduced CEA: the friction stiffness transposed (normal force from the slip, friction along the normal)",
       [T + "fem/test_reduced.py"]),
    _m("reduced-no-contact-springs", F + "reduced.py", "K0 = (K + springs).tocsc()",
       "K0 = K.tocsc()", "reduced CEA: the real modes without the contact's springs",
       [T + "fem/test_reduced.py"]),
    _m("reduced-augment-normal-only", F + "reduced.py",
       "loads = sp.csc_matrix(np.hstack([F @ phi, springs @ phi]))",
       "loads = sp.csc_matrix(springs @ phi)",
       "reduced CEA: the modes' static vectors of their contact springs' forces only (not of their friction)",
       [T + "fem/test_reduced.py"]) | {"slow_hints": True},
    _m("shares-offset", F + "shares.py", "            mass[offset:offset + n] = m\n", "            mass[:n] = m\n",
       "energy shares: every part's mass put on the slave's degrees of freedom", [T + "fem/test_solid_pair.py"]),
    _m("shares-strain-unconjugated", F + "shares.py", 'strain.append(np.einsum("ij,ij->j", w.conj(), K @ w).real)',
       'strain.append(np.einsum("ij,ij->j", w, K @ w).real)',
       "energy shares: the strain energy of a complex shape without its conjugate", [T + "fem/test_solid_pair.py"]),
    _m("uff-imaginary-dropped", F + "uff.py", "u = (u / np.abs(u).max()).reshape(-1, dim)",
       "u = (u.real / np.abs(u).max()).reshape(-1, dim) + 0j", "UFF: the shapes' imaginary parts dropped",
       [T + "fem/test_solid_pair.py"]),
    _m("pair-rollers-axis", "src/stickslip/fem/supports.py", "return [np.eye(dimension)[axes.index(a)] for a in value]",
       "return [np.eye(dimension)[(axes.index(a) + 1) % dimension] for a in value]",
       "pair: a roller holds the next axis, not its own", [T + "fem/test_plane_limit.py"]),
    _m("pair-interference-unchecked", F + "pair.py", "        if overlap > INTERFERENCE * thickness:",
       "        if overlap > 1e3 * INTERFERENCE * thickness:",
       "pair: meshes overlapping by a strain of several percent taken as a preload", [T + "fem/test_solid_pair.py"]),
    _m("cea-real-lu-imaginary", F + "cea.py", "+ 1j * self.lu.solve(np.ascontiguousarray(b.imag))",
       "- 1j * self.lu.solve(np.ascontiguousarray(b.imag))",
       "CEA: the real LU of an undamped problem solving a complex right-hand side's imaginary part with the "
       "wrong sign", [T + "fem/test_solid_pair.py", T + "fem/test_cea.py"]),
    _m("solid-held-truncated", F + "solid.py", "    if given.size and not np.issubdtype(given.dtype, np.integer):",
       "    if False:", "3-D solid: held degrees of freedom given as floats truncated to integers (1.5 holds 1)",
       [T + "fem/test_solid.py"]),
    _m("config3-units-ignored", F + "config_solid.py", "solid_from_meshio(mesh, path.name, units)",
       'solid_from_meshio(mesh, path.name, "m")', "3-D config: a mesh in millimetres read as metres",
       [T + "fem/test_solid_config.py"]),
    _m("config3-rollers-dropped", F + "config.py", "rollers_slave=self.rollers or None,", "rollers_slave=None,",
       "3-D config: the pad's rollers not passed to the pair", [T + "fem/test_solid_config.py"]),
    _m("config3-interference-unchecked", F + "config.py",
       "        coupling.check_interference(body.points, partner.body.points, group)\n", "",
       "config: meshes of a pair overlapping by several percent of the pad not refused before assembly",
       [T + "fem/test_solid_config.py"]),
    _m("solid-fold-unchecked", F + "solid.py", "return int(np.sum((counts == 2) & (ups != 1)))",
       "return int(np.sum((counts == 2) & (ups > 2)))", "3-D solid: a tangled mesh (a node through a face) taken",
       [T + "fem/test_solid_config.py"]),
    _m("loss-sign", F + "pair.py", "K = (K + 1j * sup.restrict(self.S)).tocsr()",
       "K = (K - 1j * sup.restrict(self.S)).tocsr()", "loss factor: the pair's stiffness times 1 - i eta",
       [T + "fem/test_loss_factor.py"]),
    _m("loss-half", F + "solid.py", "            S = m.loss_factor * Kg if S is None else S + m.loss_factor * Kg",
       "            S = 0.5 * m.loss_factor * Kg if S is None else S + 0.5 * m.loss_factor * Kg",
       "loss factor: a solid's structural damping half its loss factor", [T + "fem/test_loss_factor.py"]),
    _m("loss-lower-half-kept", F + "cea.py", "        trusted &= ~flip  # eigenvalues below the axis",
       "        trusted &= True  # eigenvalues below the axis",
       "loss factor: the pencil's eigenvalues below the axis flipped up as growing modes",
       [T + "fem/test_loss_factor.py"]),
    _m("loss-plane-dropped", F + "assembly.py", "        S = _stiffness(basis, order, eta * lame[:, 0], eta * lame[:, 1])",
       "        S = _stiffness(basis, order, eta * lame[:, 0], 0 * lame[:, 1])",
       "loss factor: a plane body's structural damping without its shear part", [T + "fem/test_loss_factor.py"]),
    _m("loss-reduced-dropped", F + "reduced.py", "        K = K + 1j * basis.structural",
       "        K = K + 0j * basis.structural", "loss factor: the reduced CEA without it",
       [T + "fem/test_loss_factor.py"]),
    _m("loss-explicit-taken", F + "scheme.py", "    if lossy:\n        raise ParameterError(\"material.loss_factor\"",
       "    if False:\n        raise ParameterError(\"material.loss_factor\"",
       "loss factor: an explicit run ignoring it silently", [T + "fem/test_loss_factor.py"]),
    _m("map-value-ignored", F + "maps.py", "solve = functools.partial(solve_point, config, {key: value},",
       "solve = functools.partial(solve_point, config, {},", "stability map: every row the config's own value",
       [T + "fem/test_maps.py"]),
    _m("map-onset-largest", F + "maps.py", "first = up[np.argmin(critical[up])] if up.size else None",
       "first = up[np.argmax(critical[up])] if up.size else None",
       "stability map: the onset the last branch to turn unstable, not the first", [T + "fem/test_maps.py"]),
    _m("solid-spring-axes", F + "solid.py", "diag[d::3] += spring.stiffness[d] * share / share.sum()",
       "diag[d::3] += spring.stiffness[(d + 1) % 3] * share / share.sum()",
       "3-D springs: each axis given the next axis' stiffness", [T + "fem/test_solid_boundary.py"]),
    _m("solid-traction-sign", F + "solid.py", "return -load.pressure * dot(w.n, v) + t[0] * v[0] + t[1] * v[1] + t[2] * v[2]",
       "return -load.pressure * dot(w.n, v) - t[0] * v[0] - t[1] * v[1] - t[2] * v[2]",
       "3-D traction: applied against its direction", [T + "fem/test_solid_boundary.py"]),
    _m("config3-springs-dropped", F + "config.py", "assemble_solid(body, self.material, self.loads, self.springs)",
       "assemble_solid(body, self.material, self.loads)", "3-D config: the body's springs not assembled",
       [T + "fem/test_solid_config.py"]),
    _m("solid-shear-modulus", F + "solid.py", "return ddot(2.0 * mu * eu + lam * eye(trace(eu), 3), sym_grad(v))",
       "return ddot(2.0 * mu * eu + (lam + 0.1 * mu) * eye(trace(eu), 3), sym_grad(v))",
       "3-D isotropic solid: lambda off by a tenth of mu (the compressional waves too fast)",
       [T + "fem/test_solid.py"]),
    _m("turning-skew-sign", F + "turning.py", "return sp.csr_matrix(A - A.T), sp.csr_matrix(B)",
       "return sp.csr_matrix(A.T - A), sp.csr_matrix(B)", "3-D gyroscopic matrix of the wrong sign",
       [T + "fem/test_turning.py"]),
    _m("turning-center-sign", F + "turning.py", "return u.grad[:, 0] * (-omega * (w.x[1] - cy)) + u.grad[:, 1] * (omega * (w.x[0] - cx))",
       "return u.grad[:, 0] * (-omega * (w.x[1] + cy)) + u.grad[:, 1] * (omega * (w.x[0] + cx))",
       "3-D transport: the turning axis mirrored through the origin", [T + "fem/test_turning.py"]),
    _m("turning-one-density", F + "turning.py", "        rho = float(m.density)\n",
       "        rho = float(next(iter(system.materials.values())).density)\n",
       "3-D transport: every material with the first one's density", [T + "fem/test_turning.py"]),
    _m("pair-turning-dropped", F + "pair.py",
       "G, B = solid_transport_operators(self.master, self.motion.omega, self.motion.center)",
       "G, B = solid_transport_operators(self.master, 0.0, self.motion.center)",
       "pair of solids: gyroscopic=True taken without the turning disc's terms", [T + "fem/test_turning.py"]),
    _m("pair-clamps-first-only", F + "pair.py", '        for name in getattr(self, f"clamped_{who}"):',
       '        for name in getattr(self, f"clamped_{who}")[:1]:',
       "pair: only the first clamped group of each body held", [T + "fem/test_solid_pair.py"]) | {"slow_hints": True},
    _m("config3-units-unhashable", F + "config_solid.py", "    if not isinstance(value, str) or value not in UNITS:",
       "    if value not in UNITS:", "3-D config: units = [] crashes (unhashable) instead of a one-line refusal",
       [T + "fem/test_solid_config.py"]) | {"slow_hints": True},
    _m("msh22-groups-ignored", F + "body.py", "    if sets or tags is None:\n        return sets",
       "    if True:\n        return sets", "meshes: an MSH 2.2 file's physical groups not read (every group missing)",
       [T + "fem/test_solid_config.py"]),
    _m("pair3-sliding-normal-kept", F + "pair.py", "v = v - np.sum(v * n, axis=1)[:, None] * n",
       "v = v + np.sum(v * n, axis=1)[:, None] * n",
       "pair of solids: the sliding direction not projected onto the tangent plane",
       [T + "fem/test_solid_pair.py"]),
    _m("disc-square", C + "coupled3.py", "            stick = size <= fs * scale * p\n",
       "            stick = max(abs(q1), abs(q2)) <= fs * scale * p\n            size = max(abs(q1), abs(q2)) if not stick else size\n",
       "3-D contact: a square of two one-dimensional laws instead of the Coulomb disc (the force across held)",
       [T + "fem/test_solid_run.py"]),
    _m("disc-master-force", C + "coupled3.py", "            u[i] -= scale * mw[k] * fx * inv_mass[i]",
       "            u[i] -= 0.9 * scale * mw[k] * fx * inv_mass[i]",
       "3-D contact: the master takes 0.9 of the slave's contact force (action is not reaction)",
       [T + "fem/test_solid_run.py"]),
    _m("disc-across-dropped", C + "coupled3.py", "                q2 *= shrink\n", "                q2 *= 0.0\n",
       "3-D contact: a slipping node's friction kept along the sliding direction (no force across)",
       [T + "fem/test_solid_run.py"]),
    _m("transverse-damping-factor", F + "pair.py",
       "weights = np.asarray(coefficient, float)[A] * st.pressure[A] / (c.weight[A] * self.tangent[1][A])",
       "weights = np.asarray(coefficient, float)[A] * st.pressure[A] / (c.weight[A] ** 2 * self.tangent[1][A])",
       "CEA of solids: the transverse damping weighted twice by the mortar's weight",
       [T + "fem/test_solid_run.py"]),
    _m("solid-run-frame-b", F + "pair_run3.py", "return n, t, np.cross(n, t)", "return n, t, np.cross(t, t)",
       "3-D run: the frame's third vector lost (b = t x t = 0)", [T + "fem/test_solid_run.py"]),
    _m("pair-run-supports-unchecked", F + "pair_run.py", "        self.validate_common()\n        check_supports(self.params)\n",
       "        self.validate_common()\n",
       "2-D pair run: a roller through the contact line taken (the node's contact dropped, or its force written "
       "into another dof)", [T + "fem/test_pair_run.py"]),
    _m("solid-stress-strain-factor", F + "solid_stress.py", "* (0.5 if i == j else 1.0)", "* (0.5 if i == j else 0.5)",
       "solid stresses: tensor shear strains taken for engineering ones (the shear stresses halved)",
       [T + "fem/test_solid_run.py"]),
    _m("solid-stress-lame", F + "solid_stress.py", "    D[[3, 4, 5], [3, 4, 5]] = mu\n", "    D[[3, 4, 5], [3, 4, 5]] = 2 * mu\n",
       "solid stresses: an isotropic shear modulus doubled", [T + "fem/test_solid_run.py"]),
    _m("pair-held-unchecked", F + "static.py", "HELD = 1e-3\n", "HELD = 1e30\n",
       "steady sliding of a pair: a pad free to slide away solved (numbers 1e16 wrong) instead of refused",
       [T + "fem/test_solid_run.py"]),
    _m("reduced-transverse-unscaled", F + "reduced.py", "        C = C + friction * basis.transverse\n",
       "        C = C + basis.friction * basis.transverse\n",
       "reduced CEA: the transverse damping of the problem's friction at every swept friction",
       [T + "fem/test_solid_run.py"]),
    _m("facets3-curvature-length", F + "facets.py", "        kappa = bend / np.where(h > 0, h * h, 1.0)",
       "        kappa = bend / np.where(h > 0, h, 1.0)",
       "3-D facets: the normal's turn over an edge taken for the curvature (no division by the length twice)",
       [T + "fem/test_facets3.py"]),
    _m("facets3-unchecked", F + "pair.py", "    if problem.dimension == 3:\n        if problem.master.body.kind",
       "    if problem.dimension == 3:\n        return 0.0\n        if problem.master.body.kind",
       "3-D pair: a curved master's flat faces never compared with the interference", [T + "fem/test_facets3.py"]),
    _m("prestress-gradient-transposed", F + "prestress.py", "(u.grad[k, i] * v.grad[k, j])",
       "(u.grad[i, k] * v.grad[j, k])", "centrifugal stiffness: the displacement gradients transposed",
       [T + "fem/test_prestress.py"]),
    _m("prestress-radius-y-dropped", F + "prestress.py", "((w.x[0] - cx) * v[0] + (w.x[1] - cy) * v[1])",
       "((w.x[0] - cx) * v[0])", "centrifugal load: its y component lost", [T + "fem/test_prestress.py"]),
    _m("mortar-rows-inconsistent", F + "pair.py", "        scale[ok] = weight[ok] / total[ok]\n",
       "        scale[ok] = 1.0\n",
       "mortar: a slave node past the master's edge keeps a row of M that does not sum to D_jj (its gap moves "
       "with a rigid translation)", [T + "fem/test_solid_run.py"]),
    _m("config-center-unchecked", F + "config.py", "            if float(np.hypot(*off)) > size:\n",
       "            if False:\n", "config: a rotation centre meant in the meshes' millimetres taken in metres",
       [T + "fem/test_solid_run.py"]),
    _m("hex20-face-middle", F + "solid.py",
       "faces.append(-0.25 * x[:, list(face)].sum(axis=1) + 0.5 * x[:, edges].sum(axis=1))",
       "faces.append(0.25 * x[:, list(face)].sum(axis=1))",
       "3-D solid: a 20-node hexahedron's added face middles at its corners' mean (the map not the cell's own)",
       [T + "fem/test_solid_quadratic_hex.py"]),
    _m("hex20-centre", F + "solid.py", "[-0.25 * corners + 0.25 * middles]", "[0.125 * corners]",
       "3-D solid: a 20-node hexahedron's added centre at its corners' mean (curved cells' map not the cell's own)",
       [T + "fem/test_solid_quadratic_hex.py"]),
    _m("hex27-numbering", F + "solid.py", "t = np.ascontiguousarray(solid.cells[:, INV_HEX_MAPPING].T)\n",
       "t = np.ascontiguousarray(solid.cells.T)\n",
       "3-D solid: a 27-node hexahedron handed to scikit-fem in meshio's numbering, not reordered",
       [T + "fem/test_solid_quadratic_hex.py"]),
    _m("hex-facet-dof-component", F + "solid.py", "for dofs in (basis.edge_dofs, basis.facet_dofs, basis.interior_dofs):",
       "for dofs in (basis.edge_dofs,):",
       "3-D solid: a 27-node hexahedron's face and centre degrees of freedom all taken as x components",
       [T + "fem/test_solid_quadratic_hex.py"]),
    _m("hex-hrz-square", F + "solid.py", "np.sum(np.asarray(phi[0]) ** 2 * dx, axis=1)",
       "np.sum(np.asarray(phi[0]) * dx, axis=1)",
       "3-D solid: a quadratic hexahedron's lumped mass by its row sums (int N), not its consistent diagonal",
       [T + "fem/test_solid_quadratic_hex.py"]),
    _m("quad8-shape-middle", F + "mortar3.py", "middle = [0.5 * (1 - x * x) * (1 - y), 0.5 * (1 + x) * (1 - y * y),",
       "middle = [0.5 * (1 - x * x) * (1 + y), 0.5 * (1 + x) * (1 - y * y),",
       "mortar: an 8-node face's first edge middle's shape function on the opposite edge",
       [T + "fem/test_solid_pair.py"]),
    _m("quad9-shape-centre", F + "mortar3.py", "(1, 2), (0, 1), (1, 1)]", "(1, 2), (0, 1), (1, 0)]",
       "mortar: a 9-node face's centre function the first edge middle's", [T + "fem/test_solid_pair.py"]),
    _m("quad8-transform", F + "mortar3.py", "8: ((4, 7), (4, 5), (5, 6), (6, 7))}", "8: ((4, 5), (5, 6), (6, 7), (4, 7))}",
       "mortar: an 8-node face's corners transformed with the edge middles of the next corner",
       [T + "fem/test_solid_quadratic_hex.py", T + "fem/test_solid_pair.py"]),
    _m("quad9-turn", F + "mortar3.py", "9: [0, 3, 2, 1, 7, 6, 5, 4, 8]}", "9: [0, 3, 2, 1, 4, 5, 6, 7, 8]}",
       "mortar: a 9-node face turned round with its edge middles left in place",
       [T + "fem/test_solid_quadratic_hex.py", T + "fem/test_solid_pair.py"]),
    _m("supports-frame-transposed", F + "supports.py", "vals.append(blocks[node].ravel())",
       "vals.append(blocks[node].T.ravel())",
       "supports: a slanted roller's node frame written transposed (u = R^T u_f)", [T + "fem/test_supports.py"]) | {"slow_hints": True},
    _m("supports-load-unrotated", F + "supports.py",
       "return f[self.free] if self.rotation is None else self.basis.T @ f", "return f[self.free]",
       "supports: a load taken on the frames' dofs as if they were Cartesian", [T + "fem/test_supports.py"]),
    _m("supports-rank-all", F + "supports.py", "rank += k < len(directions)", "rank += 1",
       "supports: a slanted roller holds its node along the frame's completing axes too",
       [T + "fem/test_supports.py"]) | {"slow_hints": True},
    _m("pair-run3-frames-ignored", F + "pair_run3.py", "return R if turned is None else sp.csr_matrix(turned @ R)",
       "return R", "explicit 3-D pair: the slanted rollers' node frames left out of the scheme's rotation",
       [T + "fem/test_supports.py"]),
    _m("reduced-columns-unrotated", F + "reduced.py", "    G = sup.columns(problem.G[A])\n",
       "    G = problem.G[A][:, sup.free]\n", "reduced CEA: the contact rows taken on the frames' dofs as Cartesian",
       [T + "fem/test_supports.py::test_slanted_rollers_through_the_contact_face_give_the_unturned_pairs_ceas",
        T + "fem/test_supports.py"]),
    _m("pair-steady-load-unrotated", F + "pair.py", "sup.restrict(problem.K), sup.load(problem.load)",
       "sup.restrict(problem.K), problem.load[free]",
       "steady pair: the load taken on the frames' dofs as if Cartesian", [T + "fem/test_supports.py"]),
    _m("config-rollers-direction-dropped", F + "config_solid.py",
       "out[group] = list(map(float, ax)) if isinstance(ax, list) else ax",
       "out[group] = ax if isinstance(ax, str) else \"x\"",
       "config: a roller's direction read as the x axis", [T + "fem/test_solid_config.py"]),
    _m("sbim-radiation-factor", "src/stickslip/sbim/antiplane.py",
       "rate = np.where(sliding, (c / mu) * np.sign(drive) * excess, 0.0)",
       "rate = np.where(sliding, (2 * c / mu) * np.sign(drive) * excess, 0.0)",
       "SBIM antiplane: the radiation damping mu / (2 c) of two half-spaces on one", [T + "sbim/test_antiplane.py"]),
    _m("sbim-kernel-sign", "src/stickslip/sbim/kernels.py", "return 1.0 - _j0_integral(T) + j1(T)",
       "return 1.0 - _j0_integral(T) - j1(T)", "SBIM kernel: H(T) with J1's sign turned", [T + "sbim/test_antiplane.py"]),
    _m("sbim-static-sign", "src/stickslip/sbim/antiplane.py", "(memory - np.fft.rfft(slip))",
       "(memory + np.fft.rfft(slip))", "SBIM antiplane: the static stiffness -mu |k| w pushing the slip on",
       [T + "sbim/test_antiplane.py"]),
    _m("sbim-stick-never", "src/stickslip/sbim/antiplane.py",
       "held = np.abs(drive) <= law.strength(slip, sliding)", "held = np.abs(drive) < 0.0",
       "SBIM antiplane: a stuck node never held by its static strength", [T + "sbim/test_antiplane.py"]),
    _m("sbim-beta-limit", "src/stickslip/sbim/antiplane.py", "math.isfinite(beta) and beta > 0.6366:",
       "math.isfinite(beta) and beta > 0.7:", "SBIM antiplane: a step above the stable limit let through to the "
       "range check, which does not name the limit", [T + "sbim/test_antiplane.py"]),
    _m("ip-stiffness-coupling", "src/stickslip/sbim/inplane_kernels.py", "return a * ab1 / D, b * ab1 / D, 2.0 - ab1 / D",
       "return a * ab1 / D, b * ab1 / D, 2.0 + ab1 / D", "SBIM in-plane: the stiffness's coupling S12 with a sign "
       "turned", [T + "sbim/test_inplane.py"]),
    _m("ip-stiffness-swap", "src/stickslip/sbim/inplane_kernels.py", "return a * ab1 / D, b * ab1 / D, 2.0 - ab1 / D",
       "return b * ab1 / D, a * ab1 / D, 2.0 - ab1 / D", "SBIM in-plane: S11 and S22 swapped (P for S)",
       [T + "sbim/test_inplane.py"]),
    _m("ip-cut-residue", "src/stickslip/sbim/inplane_kernels.py", "    c = np.array([s[0], s[1], 0.0])\n",
       "    c = np.array([0.0, 0.0, 0.0])\n", "SBIM in-plane: the half residue at p = 0 left out of the folded "
       "Bromwich integral", [T + "sbim/test_inplane.py"]),
    _m("ip-coupling-sign", "src/stickslip/sbim/surface.py",
       "fx = muk * (hx.memory(step) - self.s11 * ux) + 1j * muk * (self.s12 * uy - hy.memory(step, self.w12))",
       "fx = muk * (hx.memory(step) - self.s11 * ux) - 1j * muk * (self.s12 * uy - hy.memory(step, self.w12))",
       "SBIM in-plane run: the normal-to-shear coupling's sign turned", [T + "sbim/test_inplane.py"]),
    _m("ip-normal-radiation", "src/stickslip/sbim/surface.py", "return z, self.eta * z",
       "return z, z", "SBIM in-plane: the normal radiation damping rho c_s instead of rho c_p",
       [T + "sbim/test_inplane.py"]),
    _m("ip-gap-overshoot", "src/stickslip/sbim/interface.py", "    Vy = np.maximum(Vy, -gap / dt)  # a gap closing within "
       "the step closes at its end\n", "", "SBIM in-plane: a closing gap not stopped at contact (the surface "
       "passes into the rigid body for a step)", [T + "sbim/test_inplane.py"]),
    _m("ip-friction-kinetic", "src/stickslip/sbim/interface.py",
       "excess = np.abs(Gx) - law.coefficient(slip, np.ones(slip.shape, bool)) * P",
       "excess = np.abs(Gx) - law.coefficient(slip, sliding) * P",
       "SBIM in-plane: a node starting to slide meets its static strength, not the kinetic one",
       [T + "sbim/test_inplane.py"]),
    _m("flutter-coupling-sign", "src/stickslip/sbim/flutter.py",
       "return S11 + 1j * friction * S12 / (1.0 + relaxation * np.asarray(p, dtype=complex))",
       "return S11 - 1j * friction * S12 / (1.0 + relaxation * np.asarray(p, dtype=complex))",
       "flutter: the friction's coupling sign turned (the waves travel against the sliding)",
       [T + "sbim/test_flutter.py"]),
    _m("flutter-relaxation-static", "src/stickslip/sbim/flutter.py",
       "return S11 + 1j * friction * S12 / (1.0 + relaxation * np.asarray(p, dtype=complex))",
       "return S11 + 1j * friction * S12 / (1.0 + relaxation)",
       "flutter: the Prakash-Clifton relaxation taken as a constant factor, not a lag",
       [T + "sbim/test_flutter.py"]),
    _m("flutter-winding-turned", "src/stickslip/sbim/flutter.py",
       "return int(round(total / (2.0 * math.pi)))", "return -int(round(total / (2.0 * math.pi)))",
       "flutter: the argument principle's count of roots turned", [T + "sbim/test_flutter.py"]),
    _m("pc-pressure-unrelaxed", "src/stickslip/sbim/interface.py",
       "P = N if pressure is None or not isinstance(law, PrakashClifton) else pressure",
       "P = N", "Prakash-Clifton: the strength sees the contact pressure at once (the regularisation dropped)",
       [T + "sbim/test_flutter.py"]),
    _m("pc-speed-dropped", "src/stickslip/sbim/interface.py",
       "rate = (np.abs(slip_rate) + law.relaxation_speed) / law.relaxation_slip",
       "rate = np.abs(slip_rate) / law.relaxation_slip",
       "Prakash-Clifton: the reference speed V* left out of the relaxation rate",
       [T + "sbim/test_flutter.py", T + "sbim/test_inplane_ratestate.py"]),
    _m("ill-posed-kinetic-only", "src/stickslip/sbim/interface.py",
       "return np.linspace(self.kinetic_friction, self.static_friction, 17)",
       "return np.array([self.kinetic_friction])",
       "ill-posedness: a slip-weakening law judged by its weakened coefficient only (it slides at the static one "
       "first)", [T + "sbim/test_flutter.py"]),
    _m("ill-posed-unsaid", "src/stickslip/sbim/inplane.py",
       "    if ill:\n        log.warning(\"%s\", ill)\n", "",
       "an ill-posed in-plane run not saying so on the log", [T + "sbim/test_flutter.py"]),
    _m("runfile-history-lost", "src/stickslip/sbim/inplane.py",
       "        top.hx.buffer[:], top.hy.buffer[:] = state[\"hx\"], state[\"hy\"]\n", "",
       "a resumed in-plane run starting with its modes' history of rates empty",
       [T + "sbim/test_cli_run.py"]),
    _m("runfile-key-unchecked", "src/stickslip/sbim/runfile.py",
       "        if attrs.get(\"run_key\") != self.key:", "        if False:",
       "an in-plane run resuming another run's file", [T + "sbim/test_cli_run.py"]),
    _m("sw-lengths-mode-iii", "src/stickslip/sbim/interface.py",
       "return weakening_lengths(mu / (1.0 - nu), law.weakening_slip, drop)",
       "return weakening_lengths(mu, law.weakening_slip, drop)",
       "slip-weakening lengths with mu for mode II's mu / (1 - nu)", [T + "sbim/test_flutter.py"]),
    _m("sw-resolution-unsaid", "src/stickslip/sbim/scales.py", "    if zone < dx:", "    if zone < dx / 4:",
       "a cell up to four cohesive zones long not said", [T + "sbim/test_flutter.py"]),
    _m("sbim-weights-exact", "src/stickslip/sbim/kernels.py",
       "parts = [np.zeros(n) if w == 0.0 else dt * antiplane_kernel(w * dt * np.arange(1, n + 1, dtype=float))",
       "parts = [np.zeros(n) if w == 0.0 else np.diff(antiplane_kernel_integral(w * dt * np.arange(n + 1.0))) / w",
       "SBIM antiplane: the weights of a rate held over the step (unstable above beta = 0.2)",
       [T + "sbim/test_stability.py", T + "sbim/test_antiplane.py"]),
    _m("stab-winding-sign", "src/stickslip/sbim/stability.py", "    return d - wind\n", "    return d + wind\n",
       "SBIM stability: the argument principle's count turned", [T + "sbim/test_stability.py"]),
    _m("stab-window", "src/stickslip/sbim/inplane_kernels.py",
       "    return 0.5 + 0.5 * np.cos(math.pi * np.asarray(j, dtype=float) / window)",
       "    return 0.5 + 0.5 * np.cos(math.pi * np.asarray(j, dtype=float) / (2 * window))",
       "SBIM in-plane: the memory faded over twice its window (cut short at its end)",
       [T + "sbim/test_stability.py", T + "sbim/test_inplane.py"]),
    _m("qd-fault-stiffness", "src/stickslip/sbim/quasidynamic.py", "return self.shear_modulus * k / self.sides",
       "return self.shear_modulus * k", "quasi-dynamic: a fault's static stiffness that of one half-space",
       [T + "sbim/test_quasidynamic.py"]),
    _m("qd-radiation-sides", "src/stickslip/sbim/quasidynamic.py",
       "return self.shear_modulus / (self.sides * self.shear_wave_speed)",
       "return self.shear_modulus / self.shear_wave_speed",
       "quasi-dynamic: a fault's radiation damping that of one half-space", [T + "sbim/test_quasidynamic.py"]),
    _m("qd-static-sign", "src/stickslip/sbim/quasidynamic.py", "np.fft.irfft(-K * np.fft.rfft(slip), n)",
       "np.fft.irfft(K * np.fft.rfft(slip), n)", "quasi-dynamic: the static stress pushing the slip on",
       [T + "sbim/test_quasidynamic.py"]),
    _m("rsf-kernel-aging-heal", "src/stickslip/rsf/kernel.py",
       "return math.exp(heal) / dc - v / dc, -math.exp(heal) / dc, -v / dc",
       "return math.exp(-heal) / dc - v / dc, math.exp(-heal) / dc, -v / dc",
       "compiled slider: the aging law's healing with exp(+psi) (its Jacobian to match)",
       [T + "rsf/test_rsfmodel_cases.py", T + "rsf/test_kernel.py"]),
    _m("rsf-kernel-prz-factor", "src/stickslip/rsf/kernel.py",
       "wear = v * v * math.exp(psi - p[LOG_VREF]) / (4.0 * dc)",
       "wear = v * v * math.exp(psi - p[LOG_VREF]) / (2.0 * dc)",
       "compiled slider: the PRZ law's wear term twice too large", [T + "rsf/test_rsfmodel_cases.py"]),
    _m("rsf-kernel-jacobian-curvature", "src/stickslip/rsf/kernel.py",
       "out[0, 0] = (d_num * mu_v - num * curve) / (mu_v * mu_v)",
       "out[0, 0] = d_num / mu_v",
       "compiled slider: the Jacobian without the regularised law's curvature", [T + "rsf/test_kernel.py"]),
    _m("rsf-samples-shifted", "src/stickslip/rsf/slider.py",
       "out[inside] = ys[1:1 + int(inside.sum())]", "out[inside] = ys[:int(inside.sum())]",
       "slider: each piece's samples one output time late", [T + "rsf/test_rsfmodel_cases.py"]),
    _m("rsf-no-radau-fallback", "src/stickslip/rsf/pieces.py",
       "    if tried[-1][0] != \"calls\":", "    if False:",
       "slider: a piece LSODA cannot finish is not solved again by Radau",
       [T + "rsf/test_slider.py::test_a_light_slider_that_stops_lsoda_is_solved_by_radau_against_an_independent_solve"])
    | {"slow_hints": True},
    _m("qd-trial-step-fatal", "src/stickslip/sbim/quasidynamic.py",
       "            return np.full(y.size, np.nan)  # RK45 refuses",
       "            raise  # RK45 refuses",
       "quasi-dynamic: a trial step with no slip rate stops the run instead of being shortened",
       [T + "sbim/test_quasidynamic.py"]),
    _m("fd-rsf-aging-state", "src/stickslip/sbim/ratestate.py",
       "np.log(np.exp(psi - steady - x) - np.expm1(-x))", "np.log(np.exp(psi - steady + x) - np.expm1(-x))",
       "fully dynamic rate-and-state: the aging state's old part growing over a step instead of fading",
       [T + "sbim/test_quasidynamic.py"]),
    _m("fd-rsf-slip-state", "src/stickslip/sbim/ratestate.py",
       "return steady + (psi - steady) * np.exp(-x)", "return steady + (psi - steady) * np.exp(x)",
       "fully dynamic rate-and-state: the slip law's state departing from steady over a step instead of relaxing",
       [T + "sbim/test_quasidynamic.py"]),
    _m("init-past-reversed", "src/stickslip/sbim/initial.py", "vx, vy = self.past((j - pre) * dt)",
       "vx, vy = self.past((pre - j) * dt)", "initial state: the past rates asked at +t (the history runs backwards)",
       [T + "sbim/test_initial_state.py"]),
    _m("init-no-past", "src/stickslip/sbim/inplane.py",
       "pre = 0 if p.initial is None else int(windows[0].max())", "pre = 0",
       "in-plane run: an initial state's past never enters the history", [T + "sbim/test_initial_state.py"]),
    _m("init-slip-ignored", "src/stickslip/sbim/inplane.py",
       "Ux, Uy = p.initial.slip.copy(), p.initial.opening.copy()", "Ux, Uy = np.zeros(n), np.zeros(n)",
       "in-plane run: an initial state's slip and opening left out (its past kept)",
       [T + "sbim/test_initial_state.py"]),
    _m("wave-shear-unreflected", "src/stickslip/sbim/waves.py", '"shear_stress": -self.shear_modulus * f.Sigma_xy',
       '"shear_stress": self.shear_modulus * f.Sigma_xy',
       "paper's wave on a grid: its shear traction not reflected", [T + "sbim/test_initial_state.py"]),
    _m("wave-history-backwards", "src/stickslip/sbim/waves.py", "np.fft.irfft(vk * np.exp(-1j * k * self.speed * t)",
       "np.fft.irfft(vk * np.exp(1j * k * self.speed * t)",
       "paper's wave on a grid: its past travelling the other way", [T + "sbim/test_initial_state.py"]),
    _m("wave-slip-not-summed", "src/stickslip/sbim/waves.py", "uk[1:] = dt * vk[1:] * q[1:] / (1.0 - q[1:])",
       "uk[1:] = 0.0", "paper's wave on a grid: the slip at the start left at zero", [T + "sbim/test_initial_state.py"]),
    _m("wave-load-no-radiation", "src/stickslip/sbim/waves.py",
       "tau = -self.shear_modulus * self.wave.tau_xy + self.shear_modulus / self.shear_wave_speed * mean",
       "tau = -self.shear_modulus * self.wave.tau_xy",
       "paper's wave on a grid: the load without the radiation of the mean slip rate",
       [T + "sbim/test_initial_state.py"]),
    _m("wave-fields-sxy-gamma2", "src/stickslip/halfspace/fields.py", "syy, sxy = float(rd.gamma2) * re, float(rd.gamma1) * im",
       "syy, sxy = float(rd.gamma2) * re, float(rd.gamma2) * im",
       "paper's wave: its shear stress with the normal stress's coefficient (gamma2 for gamma1)",
       [T + "sbim/test_wave_in_time.py", T + "halfspace/test_fields.py"]),
    _m("wave-fields-uxx-unscaled", "src/stickslip/halfspace/fields.py", "u_xx = -float(rd.one_minus_b1b2) * re",
       "u_xx = -re", "paper's wave: its strain (so its slip rate) without the factor 1 - beta1 beta2",
       [T + "sbim/test_wave_in_time.py", T + "halfspace/test_fields.py"]),
    _m("wave-history-short", "src/stickslip/sbim/waves.py", "self.load(), law, beta=beta, history_periods=history_periods,",
       "self.load(), law, beta=beta, history_periods=0.5,",
       "paper's wave on a grid: each mode's memory cut after half its period (the run's history_periods ignored)",
       [T + "sbim/test_wave_in_time.py"]),
    _m("bm-lower-shear-unreflected", "src/stickslip/sbim/surface.py", "return (-fx if s < 0 else fx), fy",
       "return fx, fy", "two materials: the lower surface's shear traction not reflected",
       [T + "sbim/test_bimaterial.py"]),
    _m("bm-lower-opening-unreflected", "src/stickslip/sbim/surface.py",
       "np.fft.rfft(s * Uy if s < 0 else Uy)", "np.fft.rfft(Uy)",
       "two materials: the lower surface's normal displacement not reflected", [T + "sbim/test_bimaterial.py"]),
    _m("bm-history-unreflected", "src/stickslip/sbim/surface.py", "np.fft.rfft(-Vy if self.side < 0 else Vy)",
       "np.fft.rfft(Vy)", "two materials: the lower surface's normal rates kept unreflected",
       [T + "sbim/test_bimaterial.py"]),
    _m("bm-weights-swapped", "src/stickslip/sbim/inplane.py", "(wx * Gx + zx * Bx) / (zx + wx)",
       "(zx * Gx + wx * Bx) / (zx + wx)", "two materials: each side's traction weighted by its own impedance",
       [T + "sbim/test_bimaterial.py"]),
    _m("bm-lower-rate-sign", "src/stickslip/sbim/inplane.py", "vx, vy = (sxy - Bx) / wx, (syy - By) / wy",
       "vx, vy = (Bx - sxy) / wx, (syy - By) / wy", "two materials: the lower surface's slip rate with its sign turned",
       [T + "sbim/test_bimaterial.py"]),
    _m("bm-dt-upper", "src/stickslip/sbim/inplane.py",
       "fastest = max(self.shear_wave_speed, 0.0 if self.lower is None else self.lower.shear_wave_speed)",
       "fastest = self.shear_wave_speed", "two materials: the step from the upper solid's speed (a faster lower one "
       "unresolved)", [T + "sbim/test_bimaterial.py"]),
    _m("bm-resume-lower-history-lost", "src/stickslip/sbim/inplane.py",
       "            bottom.hx.buffer[:], bottom.hy.buffer[:] = state[\"lx\"], state[\"ly\"]\n", "",
       "two materials: a resumed run's lower surface starting with its history empty",
       [T + "sbim/test_bimaterial.py"]),
    _m("regimes-boundary-s11", "src/stickslip/figures/beyond/regimes.py",
       "return abs(p) / abs(inplane_stiffness(p, NU)[2]), m, rate",
       "return abs(p) / abs(inplane_stiffness(p, NU)[0]), m, rate",
       "beyond.regimes: the stick/opening boundary from the shear stiffness S11 instead of the coupling S12",
       [T + "figures/beyond/test_beyond.py"]),
    _m("regimes-boundary-slowest", "src/stickslip/figures/beyond/regimes.py",
       "if roots.size and roots[0].real * kappa1 * m > best[0]:",
       "if roots.size and (best[1] == 0 or roots[0].real * kappa1 * m < best[0]):",
       "beyond.regimes: the boundary from the grid's slowest growing mode, not its fastest",
       [T + "figures/beyond/test_beyond.py"]),
    _m("ip-book-coupling-sign", "src/stickslip/sbim/energy.py", "muk * (s11 * fx - 1j * s12 * fy)",
       "muk * (s11 * fx + 1j * s12 * fy)", "in-plane energy books: the static stiffness's coupling with its sign "
       "turned in the shear row", [T + "sbim/test_inplane_energy.py"]),
    _m("ip-book-lower-coupling", "src/stickslip/sbim/energy.py", "    s12 = side * s12\n", "",
       "two-material books: the lower surface's static coupling with the upper's sign (not reflected)",
       [T + "sbim/test_inplane_energy.py"]),
    _m("ip-book-lower-dropped", "src/stickslip/sbim/energy.py",
       "static = _static(p, p.upper, run.slip + lx, run.opening + ly, 1) + _static(p, p.lower, lx, ly, -1)",
       "static = _static(p, p.upper, run.slip + lx, run.opening + ly, 1)",
       "two-material books: the lower surface's static energy left out", [T + "sbim/test_inplane_energy.py"]),
    _m("ip-book-lower-solid", "src/stickslip/sbim/energy.py", "_static(p, p.lower, lx, ly, -1)",
       "_static(p, p.upper, lx, ly, -1)", "two-material books: the lower surface's static energy with the upper "
       "solid's modulus and Poisson's ratio", [T + "sbim/test_inplane_energy.py"]),
    _m("ip-lower-samples-upper", "src/stickslip/sbim/inplane.py", "out_lower.append(np.stack([Lx, Ly]))",
       "out_lower.append(np.stack([Lx + Ux, Ly + Uy]))", "two materials: the lower surface's samples are the "
       "upper's displacement", [T + "sbim/test_inplane_energy.py"]),
    _m("rsf-pc-not-relaxed", "src/stickslip/sbim/inplane.py",
       "                pressure = relaxed_pressure(p.law, pressure, -Gy, Vx, dt)\n", "",
       "rate-and-state under Prakash-Clifton: the pressure the strength sees never relaxes (held at the start's)",
       [T + "sbim/test_inplane_ratestate.py"]),
    _m("rsf-pc-at-once", "src/stickslip/sbim/inplane.py",
       "contact_step(rate, Gx, Gy, psi, log_v, rad[0], t, pressure)", "contact_step(rate, Gx, Gy, psi, log_v, rad[0], t)",
       "rate-and-state under Prakash-Clifton: the strength sees the contact pressure at once",
       [T + "sbim/test_inplane_ratestate.py"]),
    _m("cli-rsf-f0-dropped", "src/stickslip/cli/halfspace.py", 'f0=value["--f0"]', "f0=0.6",
       "halfspace run --law rate-state: --f0 not reaching the law (its default taken)", [T + "sbim/test_cli_run.py"]),
    _m("law-parameters-swapped", "src/stickslip/sbim/ratestate.py", '{"a": rs.a, "b": rs.b,', '{"a": rs.b, "b": rs.a,',
       "a run's file and JSON: rate-and-state's a and b said swapped", [T + "sbim/test_cli_run.py"]),
    _m("antiplane-resume-no-history", "src/stickslip/sbim/antiplane.py", '        history.buffer[:] = state["h"]\n', "",
       "antiplane runs: a resumed run starts each mode's history empty", [T + "sbim/test_antiplane.py"]),
    _m("antiplane-resume-no-state", "src/stickslip/sbim/antiplane.py",
       'psi, log_v, books = state["psi"].copy(), state["log_v"].copy(), state["books"].copy()',
       'log_v, books = state["log_v"].copy(), state["books"].copy()',
       "antiplane runs: a resumed rate-and-state run starts from the initial state variable",
       [T + "sbim/test_antiplane.py"]),
    _m("cli-antiplane-strength-static", "src/stickslip/cli/halfspace.py",
       "Coulomb(friction.static_friction * pressure, friction.kinetic_friction * pressure)",
       "Coulomb(friction.static_friction * pressure, friction.static_friction * pressure)",
       "halfspace run --plane antiplane: Coulomb's kinetic strength from the static coefficient",
       [T + "sbim/test_cli_run.py"]),
    _m("moving-mode-load-sign", "src/stickslip/sbim/inplane.py", "np.cos(2.0 * math.pi * mode * (x - speed * t) / length)",
       "np.cos(2.0 * math.pi * mode * (x + speed * t) / length)", "mode_load: the load moving the other way",
       [T + "sbim/test_initial_state.py"]),
    _m("moving-patch-sign", "src/stickslip/sbim/inplane.py", "d = np.abs((x - centre - speed * t + period / 2)",
       "d = np.abs((x - centre + speed * t + period / 2)", "patch_load: the patch moving the other way",
       [T + "sbim/test_initial_state.py"]),
    _m("ip-book-normal-work", "src/stickslip/sbim/inplane.py", "tau0 @ Vx + sigma0 @ Vy, sxy @ Vx + syy @ Vy",
       "tau0 @ Vx, sxy @ Vx + syy @ Vy", "in-plane energy books: the loading's work on the opening left out",
       [T + "sbim/test_inplane_energy.py"]),
    _m("ip-book-static-coefficient", "src/stickslip/sbim/inplane.py",
       "return law.kinetic_friction if isinstance(law, (CoulombFriction, SlipWeakeningFriction)) else None",
       "return law.static_friction if isinstance(law, (CoulombFriction, SlipWeakeningFriction)) else None",
       "in-plane energy books: Coulomb's friction energy at the static coefficient", [T + "sbim/test_inplane_energy.py"]),
    _m("ip-book-resume-lost", "src/stickslip/sbim/inplane.py",
       'books, out_books = state["books"].copy(), list(state["out_books"])',
       'books, out_books = np.zeros(3), list(state["out_books"])',
       "in-plane energy books: a resumed run's books restarting from zero", [T + "sbim/test_inplane_energy.py"]),
    _m("ip-book-impacts-as-fracture", "src/stickslip/sbim/inplane.py",
       "sxy @ Vx if kinetic is None else kinetic * (seen @ np.abs(Vx)), syy @ Vy])",
       "sxy @ Vx if kinetic is None else kinetic * (seen @ np.abs(Vx)), 0.0])",
       "in-plane energy books: the impacts' dissipation booked as fracture energy", [T + "sbim/test_inplane_energy.py"]),
    _m("regimes-kappa-ignored", "src/stickslip/figures/beyond/regimes.py",
       "problem_ = problem(f, s, n, regularised, kappa1)", "problem_ = problem(f, s, n, regularised)",
       "beyond.regimes: every run regularised with the default relaxation time, whatever t_r the map asks",
       [T + "figures/beyond/test_beyond.py"]),
    _m("regimes-nan-opening", "src/stickslip/figures/beyond/regimes.py",
       "return np.nan_to_num(stick, nan=np.inf) < np.nan_to_num(opening, nan=np.inf)",
       "return stick < opening", "beyond.regimes: a run that stuck and never opened counted as opening first",
       [T + "figures/beyond/test_beyond.py"]),
    _m("cli-fault-key-years", "src/stickslip/cli/fault.py", '''"years", "shear_modulus", "shear_wave_speed", "depth",''',
       '''"shear_modulus", "shear_wave_speed", "depth",''', "halfspace fault: the run's key without its duration (a "
       "run file of another duration resumed)", [T + "sbim/test_cli_fault.py"]),
    _m("cli-fault-profile-flat", "src/stickslip/cli/fault.py",
       "return np.clip(a + (deep_a - a) * (z - seismogenic_depth) / transition_width,",
       "return np.clip(a + 0.0 * (z - seismogenic_depth) / transition_width,",
       "halfspace fault: a uniform a (the deep value never reached)", [T + "sbim/test_cli_fault.py"]),
    _m("ip-rsf-fixed-pressure", "src/stickslip/sbim/ratestate.py", "log_v = slip_rates(law.law, -Gy if pressure is None else pressure, damping, Gx,",
       "log_v = slip_rates(law.law, law.normal_stress, damping, Gx,",
       "in-plane rate-and-state: the strength at the initial normal stress, not the contact pressure",
       [T + "sbim/test_inplane_ratestate.py"]),
    _m("ip-rsf-no-damping", "src/stickslip/sbim/inplane.py",
       "contact_step(rate, Gx, Gy, psi, log_v, rad[0], t, pressure)",
       "contact_step(rate, Gx, Gy, psi, log_v, 0.0, t, pressure)",
       "in-plane rate-and-state: the node's rate without the radiation damping", [T + "sbim/test_inplane_ratestate.py"]),
    _m("ip-rsf-state-frozen", "src/stickslip/sbim/inplane.py", "psi = advance_state(rate.law, psi, log_v, dt)",
       "psi = psi", "in-plane rate-and-state: the state never evolving", [T + "sbim/test_inplane_ratestate.py"]),
    _m("ip-rsf-resume-state-lost", "src/stickslip/sbim/inplane.py",
       'psi, log_v = state["psi"].copy(), state["log_v"].copy()', "pass",
       "in-plane rate-and-state: a resumed run starting from the initial state", [T + "sbim/test_inplane_ratestate.py"]),
    _m("bm-flutter-coupling", "src/stickslip/sbim/flutter.py", "1j * (S12u - m * S12l)", "1j * (S12u + m * S12l)",
       "Adams' relation: the two surfaces' coupling added instead of set against each other",
       [T + "sbim/test_bimaterial.py"]),
    _m("energy-static-no-half", "src/stickslip/sbim/energy.py",
       "static = 0.5 * p.dx * np.sum(run.slip * stiff, axis=1)", "static = p.dx * np.sum(run.slip * stiff, axis=1)",
       "energy books: the static strain energy without its half", [T + "sbim/test_energy.py"]),
    _m("energy-work-of-drive", "src/stickslip/sbim/antiplane.py", "np.array([load @ rate,", "np.array([drive @ rate,",
       "energy books: the loading's work taken with the drive (its memory included)", [T + "sbim/test_energy.py"]),
    _m("energy-dissipation-no-radiation", "src/stickslip/sbim/antiplane.py",
       "stress @ rate,", "drive @ rate,",
       "energy books: the interface's traction without the radiation damping", [T + "sbim/test_energy.py"]),
    _m("energy-friction-static", "src/stickslip/sbim/energy.py",
       "kinetic = law.kinetic_strength if", "kinetic = law.static_strength if",
       "energy books: friction counted at the static strength", [T + "sbim/test_energy.py"]),
    _m("fault-stiffness-whole", "src/stickslip/sbim/fault.py",
       "return 0.5 * self.shear_modulus * math.pi", "return self.shear_modulus * math.pi", "fault: each side's stiffness taken for the fault's (no half)",
       [T + "sbim/test_fault.py"]),
    _m("fault-deficit-sign", "src/stickslip/sbim/fault.py", "np.exp(log_v) - vp,", "np.exp(log_v) + vp,",
       "fault: the slip deficit grows with the plate's motion instead of falling",
       [T + "sbim/test_fault.py"]) | {"slow_hints": True},
    _m("fault-initial-state", "src/stickslip/sbim/fault.py", "return (big_psi - law.f0) / law.b",
       "return (big_psi + law.f0) / law.b", "fault: the initial state inverted with f0's sign turned",
       [T + "sbim/test_fault.py"]),
    _m("fault-profile-deficit", "src/stickslip/sbim/fault.py", 'rec["prof"].append(y[:n] + vp * t)',
       'rec["prof"].append(y[:n])',
       "fault: the slip profiles kept as the deficit", [T + "sbim/test_fault.py"]) | {"slow_hints": True},
    _m("fault-a-first-only", "src/stickslip/sbim/fault.py", 'a = RSF["a"].check_array(self.a)',
       "a = np.asarray(self.a, dtype=float)", "fault: only the first node's a checked against the law's range",
       [T + "sbim/test_fault.py"]),
    _m("fault-resume-fresh-step", "src/stickslip/sbim/fault.py",
       'solver.f, solver.h_abs, last[0] = state["f"], float(state["h_abs"]), state["last"]',
       'last[0] = state["last"]', "fault: a resumed run's integrator starts with a fresh step size",
       [T + "sbim/test_fault.py"]),
    _m("fd-rsf-half-step", "src/stickslip/sbim/antiplane.py",
       "psi = advance_state(law.law, psi, log_v, dt)", "psi = advance_state(law.law, psi, log_v, 0.5 * dt)",
       "fully dynamic rate-and-state: the state advanced over half of each step",
       [T + "sbim/test_quasidynamic.py"]),
    _m("rsf-always-compiled", "src/stickslip/rsf/pieces.py", "    if allowance >= 1.0:\n", "    if False:\n",
       "slider: a short run loads numba (the interpreted kernels never chosen)", [T + "rsf/test_kernel.py"]),
    _m("fd-rsf-no-damping", "src/stickslip/sbim/antiplane.py",
       "log_v = slip_rates(law.law, law.normal_stress, mu / c, drive, psi, log_v)",
       "log_v = slip_rates(law.law, law.normal_stress, 0.0, drive, psi, log_v)",
       "fully dynamic rate-and-state: the node's rate found without the radiation damping",
       [T + "sbim/test_quasidynamic.py"]),
    _m("fit-errors-of-logs", "src/stickslip/rsf/fit.py", "errors = np.concatenate([sd[:1], values[1:] * sd[1:]])",
       "errors = np.concatenate([sd[:1], sd[1:]])",
       "rsf fit: the standard errors of the logarithms reported as the parameters'", [T + "rsf/test_fit.py"])
    | {"slow_hints": True},
    _m("fit-history-early", "src/stickslip/rsf/fit.py", "np.flatnonzero(np.diff(self.load_velocity) != 0.0) + 1",
       "np.flatnonzero(np.diff(self.load_velocity) != 0.0)",
       "rsf fit: each velocity change of the record one sample early", [T + "rsf/test_fit.py"]) | {"slow_hints": True},
    _m("fit-repeated-time", "src/stickslip/rsf/fit.py", "    if np.any(np.diff(t) <= 0.0):",
       "    if np.any(np.diff(t) < 0.0):", "rsf fit: a record with a repeated time taken",
       [T + "rsf/test_fit.py"]),
]

UNCAUGHT: list[dict] = []  # every planted bug of the list is caught (issue 44 moved the last four)


def _p44(id, file, old, new, what, hint, why="", slow_hints=False):
    """A plant of issue 44's pass (`PLANTS_44`, ``--group issue44``); ``slow_hints``: its hint
    tests run with the slow ones (its catcher is a slow test), the fallback stays the fast suite."""
    return {**_m(id, file, old, new, what, hint, why), "group": "issue44", **({"slow_hints": True} if slow_hints else {})}


H = "src/stickslip/halfspace/"
#: Issue 44: a planted-bug pass over the modules changed in November 2026 (not covered by `MUTANTS`);
#: ``python -m tests.planted_bugs --group issue44`` runs them; the table is ``tests/planted_bugs_44.md``.
PLANTS_44: list[dict] = [
    _p44("runs-energy-no-kinetic", C + "runs.py",
         "\"energy\": kin + ela", "\"energy\": ela",
         "run books: the energy of the deviation from steady sliding without its kinetic part",
         [T + "contact/test_runs.py::test_a_free_undamped_run_keeps_its_energy_and_its_kinetic_part_is_half_m_w_squared",
          T + "contact/test_runs.py", T + "contact/test_exact.py", T + "brake/ring/test_run.py"]),
    _p44("runs-sample-step", C + "runs.py",
         "m = done * st[\"chunk\"] - 1  # index", "m = done * st[\"chunk\"]  # index",
         "run books: a sample's time and fields taken one step late (off by one)",
         [T + "contact/test_runs.py::test_a_free_runs_snapshots_are_its_discrete_motion_at_their_times",
          T + "contact/test_runs.py", T + "brake/ring/test_run.py", T + "fem/test_run.py"]),
    _p44("runs-modes-norm", C + "runs.py",
         "\"modes_V\": np.fft.rfft(V)[:st[\"modes\"] + 1] / V.size", "\"modes_V\": np.fft.rfft(V)[:st[\"modes\"] + 1]",
         "run books: the Fourier modes of V without the 1/N of rfft(V)/N",
         [T + "contact/test_runs.py::test_the_series_modes_are_the_fourier_coefficients_of_the_snapshots",
          T + "contact/test_runs.py", T + "brake/ring/test_run.py", T + "contact/test_classify.py"]),
    _p44("runs-schedule-floor", C + "runs.py",
         "total = int(np.ceil(t_end / (chunk * scheme.dt) - 1e-9))", "total = int(np.floor(t_end / (chunk * scheme.dt) - 1e-9))",
         "run schedule: the number of samples rounded down (a run ends short of the time asked for)",
         [T + "contact/test_runs.py::test_a_run_ends_within_one_sample_past_the_time_asked_and_its_tail_is_every_sample",
          T + "contact/test_runs.py", T + "brake/ring/test_run.py", T + "fem/test_run.py"]),
    _p44("runs-tail-offbyone", C + "runs.py",
         "done > st[\"samples_total\"] - st[\"tail_samples\"]", "done >= st[\"samples_total\"] - st[\"tail_samples\"]",
         "run books: the tail's snapshots start one sample early (> for >=)",
         [T + "contact/test_runs.py::test_a_run_ends_within_one_sample_past_the_time_asked_and_its_tail_is_every_sample",
          T + "contact/test_runs.py", T + "brake/ring/test_run.py", T + "contact/test_classify.py"]),
    _p44("sim-zero-slip-metric", S + "simulate.py",
         "z[n:2 * n] = v + MiW @ np.linalg.lstsq(", "z[n:2 * n] = v + W @ np.linalg.lstsq(",
         "system simulation: a stuck start's velocity corrected along W instead of M^-1 W (slip not zero unless M = I)",
         [T + "system/test_simulate.py::test_a_stuck_contacts_start_is_the_smallest_change_of_velocity_in_the_metric_of_the_mass",
          T + "system/test_simulate.py", T + "system/test_floquet.py"]),
    _p44("sim-release-direction", S + "simulate.py",
         "st[worst] = 1 if forces[worst] > 0 else -1", "st[worst] = -1 if forces[worst] > 0 else 1",
         "system simulation: a contact released from stick slips against the force that released it",
         [T + "system/test_simulate.py", T + "system/test_floquet.py"]),
    _p44("flow-slip-load-sign", S + "flow.py",
         "g += w * N * (s * mu0 - mu1 * V)", "g += w * N * (s * mu0 + mu1 * V)",
         "system flow: the constant part of a falling law's friction with +mu1 V (affine law's offset sign)",
         [T + "system/test_simulate.py::test_one_contact_on_one_dof_is_the_oscillator", T + "system/test_simulate.py",
          T + "system/test_floquet.py"]),
    _p44("flow-stick-limit-kinetic", S + "flow.py",
         "[system.contacts[i].friction.static for i in owners[k]]", "[system.contacts[i].friction.affine[0] for i in owners[k]]",
         "system flow: the stick limit's event at the kinetic coefficient mu0 instead of the static one",
         [T + "system/test_simulate.py", T + "system/test_floquet.py"]),
    _p44("floquet-impact-R", S + "floquet.py",
         "u, out = f_plus[:2 * n] - reset.project(f_minus[:2 * n]),", "u, out = f_plus[:2 * n] - f_minus[:2 * n],",
         "system monodromy: the saltation of a plastic impact with f- instead of R f- (the jump of the field)",
         [T + "system/test_rigid.py", T + "system/test_floquet.py", T + "system/test_unilateral.py"]),
    _p44("steady-unilateral-N0", S + "steady.py",
         "c_eff += normal * slope * np.outer(c.direction, c.direction)", "c_eff += c.normal_force * slope * np.outer(c.direction, c.direction)",
         "steady sliding on a unilateral contact: the friction slope's damping with N_0 instead of N(x)",
         [T + "system/test_unilateral.py", T + "system/test_steady.py", T + "system/test_smooth_unilateral.py"]),
    _p44("steady-force-sign", S + "steady.py",
         "forces[i] = c.normal_force * sign * mu", "forces[i] = c.normal_force * mu",
         "steady sliding: the friction force without the sign of the surface speed",
         [T + "system/test_steady.py", T + "system/test_simulate.py"]),
    _p44("rs-normal-sign", S + "rate_state.py",
         "return self.N - self.Kn.T @ y[:self.n]", "return self.N + self.Kn.T @ y[:self.n]",
         "rate-and-state systems: normal force N_0 + k_n n.x (a unilateral contact's spring with the wrong sign)",
         [T + "system/test_smooth_unilateral.py", T + "system/test_rate_state_mixed.py", T + "system/test_rate_state.py"]),
    _p44("rs-direct-slope-unit", S + "rate_state.py",
         "eq.psi(y, i))[1])) / abs(vr[i])", "eq.psi(y, i))[1]))",
         "rate-and-state steady sliding: the direct effect's damping d mu/d ln v without its 1/v",
         [T + "system/test_rate_state.py", T + "system/test_rate_state_mixed.py"]),
    _p44("rsc-amplitude", S + "rate_state_cycle.py",
         "0.5 * np.ptp(one.x, axis=0))", "np.ptp(one.x, axis=0))",
         "rate-and-state limit cycle: the amplitude as the peak-to-peak instead of half of it",
         [T + "system/test_rate_state_cycle.py::test_the_amplitude_is_half_the_swing_of_the_independent_integration"],
         slow_hints=True),
    _p44("cont-amplitude", S + "continuation.py",
         "return 0.5 * (high - low)", "return high - low",
         "cycle continuation: the amplitude as the peak-to-peak instead of half of it",
         [T + "system/test_continuation.py::test_the_coulomb_amplitude_along_the_belt_speed_is_the_closed_form_radius"],
         slow_hints=True),
    _p44("static-load-sign", F + "static.py",
         "- K_F @ wP + Fw[F]", "- K_F @ wP - Fw[F]",
         "FE steady sliding: the load on the free dofs with the wrong sign",
         [T + "fem/test_static.py", T + "brake/fem/test_fem_static.py", T + "fem/test_active_set.py"]),
    _p44("static-pressure-share", F + "static.py",
         "pressure_law.factor(np.maximum(p, 0.0) / share[active])", "pressure_law.factor(np.maximum(p, 0.0) * share[active])",
         "FE steady sliding with a pressure law: nodal force times the tributary length instead of over it",
         [T + "fem/test_friction_law.py", T + "fem/test_static.py"]),
    _p44("fscheme-omega-sqrt", F + "scheme.py",
         "return float(np.sqrt(lam[0]) * (1.0 + 1e-6))\n\n    @property", "return float(lam[0] * (1.0 + 1e-6))\n\n    @property",
         "FE scheme: the highest free frequency omega_max as omega^2 (the stable step wrong)",
         [T + "fem/test_scheme.py", T + "fem/test_run.py"]),
    _p44("fscheme-theta-pi", F + "scheme.py",
         "return 2.0 * np.pi * self.problem.frames.arclength[self.contact_nodes] / self.line_length",
         "return np.pi * self.problem.frames.arclength[self.contact_nodes] / self.line_length",
         "FE scheme: the contact nodes' angle pi s/L instead of 2 pi s/L",
         [T + "fem/test_scheme.py", T + "fem/test_run.py", T + "fem/test_records.py"]),
    _p44("cea-shift-invert", F + "cea.py",
         "s = sigma + 1.0 / nu", "s = sigma - 1.0 / nu",
         "CEA: eigenvalues from the shift-invert Ritz values as sigma - 1/nu instead of sigma + 1/nu",
         [T + "fem/test_cea.py", T + "fem/test_stick_slip.py"]),
    _p44("cea-pressure-rate", F + "cea.py",
         "f = problem.friction * factor * rate", "f = problem.friction * factor",
         "CEA with a pressure law: dF_t/dP = mu g instead of mu g (1 - n) (the rate dropped)",
         [T + "fem/test_linearisation.py::test_the_block_on_a_belt_linearises_as_its_equations_of_motion",
          T + "fem/test_friction_law.py", T + "fem/test_cea_options.py"]),
    _p44("asm-strain-engineering", F + "assembly.py",
         "strain = np.stack([g[0, 0], g[1, 1], g[0, 1] + g[1, 0]], axis=-1)",
         "strain = np.stack([g[0, 0], g[1, 1], g[0, 1]], axis=-1)",
         "FE stresses: the engineering shear strain as u_x,y alone (u_y,x dropped)",
         [T + "fem/test_assembly.py", T + "fem/test_orthotropic.py", T + "fem/test_paraview.py"]),
    _p44("body-edge-orientation", F + "body.py",
         "return np.where(forward[:, None], edges, turned)", "return np.where(forward[:, None], turned, edges)",
         "FE mesh: boundary edges oriented against their cell (the body on the right: normals point inwards)",
         [T + "fem/test_body.py", T + "fem/test_boundary.py", T + "fem/test_static.py"]),
    _p44("frun-noise-rms", F + "run.py",
         "white /= np.sqrt(np.mean(white**2))", "white /= np.mean(white**2)",
         "FE run: the initial noise scaled by its mean square instead of its RMS (amplitude not as asked)",
         [T + "fem/test_run.py::test_the_noisy_start_has_the_rms_it_is_asked_for", T + "fem/test_run.py",
          T + "fem/test_records.py"]),
    _p44("fconfig-interference-side", F + "config.py",
         "radius = radius - push if inside else radius + push", "radius = radius + push if inside else radius - push",
         "FE config: a cylindrical surface's interference moves it away from the body instead of into it",
         [T + "fem/test_examples.py", T + "fem/test_config_fuzz.py", T + "fem/test_static.py"]),
    _p44("pair-gauss-weight", F + "pair.py",
         "weight = 0.5 * (hi - lo) * L", "weight = (hi - lo) * L",
         "mortar: the Gauss weight of a segment's overlap twice too large (M against D)",
         [T + "fem/test_pair.py", T + "fem/test_pair_run.py"]),
    _p44("cscheme-initial-damping", C + "scheme.py",
         "a = self.apply(u0 + beta * v0) - alpha * v0", "a = self.apply(u0 + beta * v0) + alpha * v0",
         "explicit scheme: the start's acceleration with the mass-proportional damping force reversed",
         [T + "contact/test_exact.py::test_the_first_step_of_a_damped_start_in_motion_is_taylors_to_second_order",
          T + "fem/test_damping.py", T + "brake/ring/test_scheme.py", T + "contact/test_exact.py"]),
    _p44("cscheme-kinetic-half", C + "scheme.py",
         "return 0.5 * float(np.einsum(\"i,i\", mass * w, w))", "return float(np.einsum(\"i,i\", mass * w, w))",
         "explicit scheme: kinetic energy m w^2 instead of m w^2 / 2",
         [T + "contact/test_exact.py", T + "brake/fem/test_fem_energy.py", T + "contact/test_conditions.py"]),
    _p44("cscheme-amplification", C + "scheme.py",
         "um = np.array([1.0, 0.0, 0.0]) + vm + 0.5 * am", "um = np.array([1.0, 0.0, 0.0]) + vm + am",
         "explicit scheme's amplification matrix: u_{m+1} with a_m dt^2 instead of a_m dt^2/2",
         [T + "brake/ring/test_scheme.py", T + "contact/test_exact.py"]),
    _p44("kernel-predictor-half", C + "kernel.py",
         "u[k] += dt * vs + 0.5 * dt * dt * A[k]", "u[k] += dt * vs + dt * dt * A[k]",
         "contact kernel: the predictor u* = u + dt v* + dt^2 A (the 1/2 lost)",
         [T + "brake/ring/test_scheme.py", T + "contact/test_exact.py"]),
    _p44("kernel-trial-surface", C + "kernel.py",
         "trial = (ut_old[j] + dt * speed[j] - u[t]) / cdt2", "trial = (ut_old[j] - dt * speed[j] - u[t]) / cdt2",
         "contact kernel: the stick trial with the surface moving the other way",
         [T + "contact/test_exact.py", T + "contact/test_conditions.py"]),
    _p44("kernel-pressure-exponent", C + "kernel.py",
         "g = (p * law[3 + j]) ** (-expo)", "g = (p * law[3 + j]) ** expo",
         "contact kernel: the pressure law (P/P_ref)^n instead of (P/P_ref)^-n",
         [T + "fem/test_friction_law.py", T + "contact/test_kinetic_law.py"]),
    _p44("kernel-velocity-corrector", C + "kernel.py",
         "v[r] += beta2 * dt * p", "v[r] += dt * p",
         "contact kernel: the normal velocity corrector dt r instead of beta2 dt r",
         [T + "contact/test_exact.py", T + "contact/test_conditions.py", T + "brake/ring/test_scheme.py"]),
    _p44("classify-parabola-sign", C + "classify.py",
         "frac = 0.5 * (cm - cp) / den", "frac = 0.5 * (cp - cm) / den",
         "regime classification: the sub-grid (parabolic) peak of the cross-correlation on the wrong side",
         [T + "contact/test_classify.py"]),
    _p44("kernelcopy-offset", "src/stickslip/kernelcopy.py",
         "dst[at + r, j] = src[r, j]", "dst[at + r - 1, j] = src[r, j]",
         "compiled row copy: rows written one row early (off by one)",
         [T + "test_kernelcopy.py", T + "oscillator/test_compiled.py", T + "oscillator/test_simulate.py"]),
    _p44("fields-A-cot", H + "fields.py",
         "self.T / float(self.rd.gamma1) - self.R / np.tan(np.pi * self.lam))",
         "self.T / float(self.rd.gamma1) + self.R / np.tan(np.pi * self.lam))",
         "half-space fields: A' = R + i(T/gamma1 + R cot(pi lam)) (sign of the cot term)",
         [T + "halfspace/test_fields.py"]),
    _p44("fields-R-sign", H + "fields.py",
         "R = -(T / rd.gamma_mod) * np.sin(np.pi * lam * (b - 1.0) / b)", "R = (T / rd.gamma_mod) * np.sin(np.pi * lam * (b - 1.0) / b)",
         "half-space fields: the bounded-stress condition's R with the wrong sign (v of a solution)",
         [T + "halfspace/test_fields.py", T + "halfspace/test_direct.py"]),
    _p44("inverse-cramer-index", H + "inverse.py",
         "T = (a11 * r2 - a21 * r1) / det", "T = (a11 * r2 - a12 * r1) / det",
         "inverse problem: Cramer's rule for T with a12 for a21 (a swapped index)",
         [T + "halfspace/test_inverse.py", T + "halfspace/test_direct.py"]),
    _p44("inverse-text-H", H + "inverse.py",
         "return rd.gamma1 * (rd.K_minus_one * b - 0.5 * rd.K)", "return rd.gamma1 * (rd.K_minus_one * b - rd.K)",
         "inverse problem: H of the text's system (k = 1) with K instead of K/2",
         [T + "halfspace/test_inverse.py"]),
    _p44("direct-F-half", H + "direct.py",
         "np.sin(np.pi * rd.lam) * T / (2.0 * rd.gamma1)", "np.sin(np.pi * rd.lam) * T / rd.gamma1",
         "direct problem: the residual F of [54] without the 1/2 of its T term",
         [T + "halfspace/test_direct.py"]),
    _p44("direct-mu-star", H + "direct.py",
         "return [self.mu - self.T / (-t) for t in", "return [self.mu + self.T / (-t) for t in",
         "direct problem: mu* = mu + T/(-tau*_yy) instead of mu - T/(-tau*_yy)",
         [T + "halfspace/test_direct.py", T + "halfspace/test_loading.py"]),
    _p44("osc-flows-jacobian", OSC + "flows.py",
         "[-self.w02 * s, c + self.sigma * s]]", "[-self.w02 * s, c - self.sigma * s]]",
         "oscillator slip flow: the closed-form Jacobian's (v, v) entry with -sigma",
         [T + "oscillator/test_flows.py", T + "oscillator/test_cycle.py"]),
    _p44("osc-flows-variational", OSC + "flows.py",
         "dacc_dv = (-s * o.normal_force * o.friction.slope(v_r) - o.damping) / o.mass",
         "dacc_dv = (s * o.normal_force * o.friction.slope(v_r) - o.damping) / o.mass",
         "oscillator numeric flow: the variational equation's dF/dv with the wrong sign (d v_r/d v = -1 lost)",
         [T + "oscillator/test_flows.py", T + "oscillator/test_cycle.py"]),
    _p44("osc-cycle-slip-time", OSC + "cycle.py",
         "slip_time=durations[Mode.SLIP_POS] + durations[Mode.SLIP_NEG]", "slip_time=durations[Mode.SLIP_POS]",
         "oscillator cycle: the slip time without the reverse slip",
         [T + "oscillator/test_cycle.py::test_a_cycle_with_reverse_slip_counts_it_in_its_slip_time"], slow_hints=True),
    _p44("ring-transit", B + "ring/integrate.py",
         "return float(2.0 * np.pi / np.sqrt(params.coefficients().a))", "return float(np.pi / np.sqrt(params.coefficients().a))",
         "ring runs: a wave transit pi/sqrt(a) instead of 2 pi/sqrt(a) (the budget in transits)",
         [T + "brake/ring/test_run.py::test_a_transit_is_once_round_the_ring_at_the_p_wave_speed_of_the_dispersion_relation",
          T + "brake/ring/test_run.py", T + "brake/ring/test_contact.py"]),
    _p44("brake-fem-profile", B + "fem/run.py",
         "X = (xi**2 / r - r) / (xi**2 - 1.0)", "X = (xi**2 / r + r) / (xi**2 - 1.0)",
         "FE annulus run: the static radial profile (xi^2/r + r) instead of (xi^2/r - r) (not zero at the outer radius)",
         [T + "brake/fem/test_fem_run.py", T + "brake/fem/test_fem_growth.py"]),
    _p44("store-axes-values", "src/stickslip/sweep/store.py",
         "ds[k].size == len(v) and np.array_equal(ds[k].values, np.asarray(v, float))", "ds[k].size == len(v)",
         "sweep store: a store with the same axes' sizes but other values taken for this sweep (old results resumed)",
         [T + "test_sweep.py"]),
]


#: The groups ``--group`` selects.
GROUPS = {"issue44": PLANTS_44}


# -- the runner ----------------------------------------------------------------------------------------------------

@dataclass
class Outcome:
    id: str
    status: str  # "caught", "not caught", "timeout", "error"
    caught_by: str = ""
    phase: str = ""  # "hint" or "full"
    seconds: float = 0.0
    detail: str = ""


def copy_tree(src: Path, dest: Path) -> Path:
    """A copy of the repository at ``src`` in ``dest`` (which must not exist), mtimes kept."""
    shutil.copytree(src, dest, symlinks=True, copy_function=shutil.copy2, ignore=shutil.ignore_patterns(*SKIP))
    return dest


def plant(root: Path, mutant: dict) -> None:
    """Apply ``mutant`` in the tree at ``root``; ValueError if ``old`` does not occur exactly once."""
    path = root / mutant["file"]
    text = path.read_text()
    count = text.count(mutant["old"])
    if count != 1:
        raise ValueError(f"{mutant['id']}: the old text occurs {count} times in {mutant['file']} (1 expected)")
    path.write_text(text.replace(mutant["old"], mutant["new"]))


def _module_imports(path: Path, package_dir: Path) -> set[str]:
    """Dotted names of the ``stickslip`` modules and packages that the module at ``path`` imports
    (function-level imports too; ``from package import name``: the package and ``package.name``)."""
    rel = path.relative_to(package_dir.parent).with_suffix("")
    parts = list(rel.parts)
    is_pkg = parts[-1] == "__init__"
    if is_pkg:
        parts = parts[:-1]
    out = set()
    try:
        tree = ast.parse(path.read_text())
    except SyntaxError:
        return out
    for node in ast.walk(tree):
        names = []
        if isinstance(node, ast.Import):
            names = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = parts if is_pkg else parts[:-1]
                base = base[:len(base) - (node.level - 1)] if node.level > 1 else base
                prefix = ".".join(base)
                mod = f"{prefix}.{node.module}" if node.module else prefix
            else:
                mod = node.module or ""
            names = [mod] + [f"{mod}.{a.name}" for a in node.names]  # `from pkg import module` too
        out.update(name for name in names if name.split(".")[0] == package_dir.name)
    return out


def stale_numba_caches(root: Path, mutated: str) -> list[Path]:
    """The numba cache files (``.nbi``, ``.nbc``) of the mutated module and of every module of
    the package that imports it, directly or through others."""
    package = root / "src" / "stickslip"
    mutated_path = (root / mutated).resolve()
    if package.resolve() not in mutated_path.parents:
        return []
    modules = {}
    for path in package.rglob("*.py"):
        rel = path.relative_to(package.parent).with_suffix("")
        name = ".".join(rel.parts[:-1] if rel.parts[-1] == "__init__" else rel.parts)
        modules[name] = path
    imports = {name: _module_imports(path, package) for name, path in modules.items()}
    target = next(name for name, path in modules.items() if path.resolve() == mutated_path)
    dirty, grew = {target}, True
    while grew:
        new = {name for name, deps in imports.items() if name not in dirty and deps & dirty}
        dirty |= new
        grew = bool(new)
    out = []
    for name in dirty:
        path = modules[name]
        cache = path.parent / "__pycache__"
        if cache.is_dir():
            out += [p for p in cache.iterdir() if p.name.startswith(path.stem + ".") and p.suffix in (".nbi", ".nbc")]
    return out


def _env(copy: Path) -> dict:
    env = dict(os.environ)
    env["PYTHONPATH"] = f"{copy / 'src'}{os.pathsep}{copy}"
    env.pop("PYTEST_ADDOPTS", None)
    env.pop("PYTEST_XDIST_WORKER", None)
    return env


def check_imports(copy: Path, python: str) -> None:
    """Raise RuntimeError unless ``stickslip`` and ``tests`` are imported from ``copy``."""
    code = "import stickslip, tests; print(stickslip.__file__); print(tests.__file__)"
    done = subprocess.run([python, "-c", code], cwd=copy, env=_env(copy), capture_output=True, text=True,
                          timeout=300)
    files = [Path(line).resolve() for line in done.stdout.split()]
    if done.returncode or len(files) != 2 or not all(copy.resolve() in f.parents for f in files):
        raise RuntimeError(f"the copy's package is not the one imported: {done.stdout.strip()!r} "
                           f"{done.stderr.strip()[-300:]!r}")


_FAILURE_LINE = re.compile(r"^(?:FAILED|ERROR) (.+)$", re.M)


def first_failure(output: str) -> str:
    """The node id of the first ``FAILED``/``ERROR`` line of pytest's short summary (a
    parametrised id may hold blanks: it runs to its closing bracket)."""
    for rest in _FAILURE_LINE.findall(output):
        if "[" in rest.split(" - ")[0]:
            end = rest.find("] - ")
            return rest[:end + 1] if end >= 0 else rest.strip()
        return rest.split(" - ")[0].strip()
    return ""


def run_pytest(copy: Path, python: str, args: list[str], timeout: float, slow: bool = False) -> tuple[str, str, str]:
    """Run pytest in ``copy``: ``(result, first failing node id, output tail)`` where result is
    ``"passed"``, ``"failed"``, ``"unusable"`` (no test ran, a hint not found) or ``"timeout"``.
    ``slow``: the slow tests too (a plant of `PLANTS_44` whose catcher is a slow test)."""
    at = PYTEST.index("not slow or slow_by_time") - 1  # the pair ``-m "not slow or slow_by_time"``
    base = PYTEST[:at] + PYTEST[at + 2:] if slow else PYTEST
    proc = subprocess.Popen([python, *base, *args], cwd=copy, env=_env(copy), stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, start_new_session=True)
    try:
        out, _ = proc.communicate(timeout=max(timeout, 1.0))
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, _ = proc.communicate()
        return "timeout", "", (out or "")[-2000:]
    tail = out[-3000:]
    if proc.returncode == 0:
        return "passed", "", tail
    if proc.returncode in (4, 5):  # usage error (a hint not found) or no test collected
        return "unusable", "", tail
    found = first_failure(out)
    if found:
        return "failed", found, tail
    if "error" in out.lower() or proc.returncode in (1, 2, 3):
        return "failed", f"(pytest exit {proc.returncode}, no test named)", tail
    return "unusable", "", tail


def run_mutant(base: Path, work: Path, mutants: list[dict], python: str, timeout: float, workers: int,
               hints_only: bool, label: str) -> Outcome:
    """Plant ``mutants`` (one, or several at once) in a copy of ``base`` and run the tests."""
    start = time.monotonic()
    copy = work / label
    try:
        copy_tree(base, copy)
        for m in mutants:
            plant(copy, m)
        for m in mutants:
            for stale in stale_numba_caches(copy, m["file"]):
                stale.unlink(missing_ok=True)
        check_imports(copy, python)
    except (ValueError, RuntimeError, OSError, subprocess.SubprocessError) as err:
        shutil.rmtree(copy, ignore_errors=True)
        return Outcome(label, "error", detail=str(err), seconds=time.monotonic() - start)
    try:
        hints = list(dict.fromkeys(h for m in mutants for h in m["hint"]))
        slow = any(m.get("slow_hints") for m in mutants)
        result, node, tail = ("unusable", "", "") if not hints else run_pytest(copy, python, hints, timeout, slow)
        if result == "failed":
            return Outcome(label, "caught", node, "hint", time.monotonic() - start)
        if result == "timeout":
            return Outcome(label, "timeout", phase="hint", seconds=time.monotonic() - start, detail=tail[-500:])
        if hints_only:
            return Outcome(label, "not caught", phase="hint", seconds=time.monotonic() - start,
                           detail="hint tests only" + ("" if result == "passed" else f": {tail[-300:]}"))
        left = timeout - (time.monotonic() - start)
        extra = ["-n", str(workers)] if workers > 1 else []
        result, node, tail = run_pytest(copy, python, extra, left)
        seconds = time.monotonic() - start
        if result == "failed":
            return Outcome(label, "caught", node, "full", seconds)
        if result == "timeout":
            return Outcome(label, "timeout", phase="full", seconds=seconds, detail=tail[-500:])
        return Outcome(label, "not caught", phase="full", seconds=seconds,
                       detail="" if result == "passed" else tail[-300:])
    finally:
        shutil.rmtree(copy, ignore_errors=True)


def area(file: str) -> str:
    """The package area of a mutated file: ``oscillator``, ``brake/reduced``, ``contact``, ``fem``,
    ... (a top-level module of the package stands for itself: ``friction``, ``cf``)."""
    parts = Path(file).with_suffix("").parts
    parts = parts[parts.index("stickslip") + 1:] if "stickslip" in parts else parts
    return "/".join(parts[:2]) if parts[0] == "brake" and len(parts) > 2 else parts[0]


def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def _caught_by(o: Outcome) -> str:
    if o.status == "caught":
        return f"`{_cell(o.caught_by)}`" + (" (full)" if o.phase == "full" else "")
    if o.status == "timeout":
        return f"timeout ({o.phase})"
    if o.status == "error":
        return f"ERROR: {_cell(o.detail)}"
    return "NOT CAUGHT" + (" (hint tests only)" if o.phase == "hint" else "")


def table(mutants: list[dict], outcomes: dict[str, Outcome]) -> str:
    rows = ["| id | what | file | caught by | seconds |", "| --- | --- | --- | --- | ---: |"]
    for m in mutants:
        o = outcomes.get(m["id"])
        if o is None:
            continue
        rows.append(f"| {m['id']} | {_cell(m['what'])} | {m['file'].removeprefix('src/stickslip/')} | {_caught_by(o)} "
                    f"| {o.seconds:.0f} |")
    return "\n".join(rows)


def report(root: Path, chosen: list[dict], outcomes: dict[str, Outcome], control: Outcome | None,
           together: Outcome | None, seconds: float, uncaught_run: bool, group_run: bool = False) -> str:
    lines = ["# Planted bugs", "",
             f"Root: `{root}`; {time.strftime('%Y-%m-%d %H:%M')}; "
             f"`python -m tests.planted_bugs {' '.join(sys.argv[1:])}`; total {seconds / 60:.1f} min.", ""]
    if control is not None:
        if control.status == "not caught":
            lines.append(f"Control (unmutated copy, the hint tests of these mutants): passed in {control.seconds:.0f} s.")
        else:
            lines.append(f"**CONTROL FAILED** (unmutated copy, the hint tests): {_caught_by(control)} "
                         "- the results below do not tell bugs from a broken suite.")
        lines.append("")
    known = [m for m in chosen if m["id"] in outcomes]
    if known:
        caught = sum(outcomes[m["id"]].status == "caught" for m in known)
        areas: dict[str, list[int]] = {}
        for m in known:
            tally = areas.setdefault(area(m["file"]), [0, 0])
            tally[0] += outcomes[m["id"]].status == "caught"
            tally[1] += 1
        spread = ", ".join(f"{k} {c}/{n}" for k, (c, n) in sorted(areas.items()))
        lines += [f"Caught: {caught} of {len(known)} (by area: {spread}).", "", table(known, outcomes), ""]
    in_mutants = {m["id"] for m in MUTANTS}
    lost = [m["id"] for m in known if m["id"] in in_mutants and outcomes[m["id"]].status != "caught"]
    if lost:
        lines += [f"**Not caught any more (or not run to the end)**: {', '.join(lost)}.", ""]
    if UNCAUGHT and not group_run:
        lines += ["## Not caught today", ""]
        if together is not None:
            state = ("none caught: the whole fast suite passed with all of them planted at once"
                     if together.status == "not caught" else f"{together.status}: {_caught_by(together)}")
            lines += [f"All {len(UNCAUGHT)} planted together in one copy, one fast-suite run "
                      f"({together.seconds / 60:.1f} min): {state}.", ""]
        elif not uncaught_run:
            lines += ["(Listed, not run this time: `--uncaught` runs them.)", ""]
        lines += ["| id | what | file | why not caught |", "| --- | --- | --- | --- |"]
        for m in UNCAUGHT:
            lines.append(f"| {m['id']} | {_cell(m['what'])} | {m['file'].removeprefix('src/stickslip/')} "
                         f"| {_cell(m.get('why', ''))} |")
        lines.append("")
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m tests.planted_bugs", description=__doc__.split("\n\n")[0])
    parser.add_argument("--only", help="comma-separated ids (from MUTANTS, UNCAUGHT or PLANTS_44)")
    parser.add_argument("--out", type=Path, help="write the Markdown table here too")
    parser.add_argument("--jobs", type=int, default=1, help="mutants run at once (default 1: one pytest at a time)")
    parser.add_argument("--workers", type=int, default=2, help="pytest-xdist workers of the full-suite fallback")
    parser.add_argument("--root", type=Path, default=REPO, help="the repository to copy (default: %(default)s)")
    parser.add_argument("--timeout", type=float, default=1200.0, help="seconds per mutant (default 1200)")
    parser.add_argument("--uncaught", action="store_true", help="run the UNCAUGHT list instead of MUTANTS")
    parser.add_argument("--group", choices=sorted(GROUPS), help="run a group of plants instead of MUTANTS "
                        "(issue44: the pass over the modules changed in November 2026, `PLANTS_44`)")
    parser.add_argument("--together", action="store_true",
                        help="with --uncaught: plant them all in one copy and run the suite once")
    parser.add_argument("--hints-only", action="store_true", help="no full-suite fallback (a quick look)")
    parser.add_argument("--no-control", action="store_true", help="skip the control run")
    parser.add_argument("--check", action="store_true", help="only check that every substitution applies once")
    parser.add_argument("--python", default=sys.executable, help="the interpreter (default: this one)")
    args = parser.parse_args(argv)
    root = args.root.resolve()

    pool = GROUPS[args.group] if args.group else UNCAUGHT if args.uncaught else MUTANTS
    ids = [m["id"] for m in MUTANTS + UNCAUGHT + PLANTS_44]
    duplicates = {i for i in ids if ids.count(i) > 1}
    if duplicates:
        parser.error(f"duplicate ids: {sorted(duplicates)}")
    if args.only:
        wanted = [i.strip() for i in args.only.split(",") if i.strip()]
        every = {m["id"]: m for m in MUTANTS + UNCAUGHT + PLANTS_44}
        unknown = [i for i in wanted if i not in every]
        if unknown:
            parser.error(f"unknown ids: {unknown}")
        chosen = [every[i] for i in wanted]
    else:
        chosen = list(pool)
    if args.check:
        bad = []
        for m in chosen:
            count = (root / m["file"]).read_text().count(m["old"])
            if count != 1:
                bad.append(f"{m['id']}: {count} occurrences in {m['file']}")
        print("\n".join(bad) or f"all {len(chosen)} substitutions apply once")
        return 1 if bad else 0

    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="planted-bugs-") as tmp:
        work = Path(tmp)
        print(f"copying {root} ...", file=sys.stderr)
        base = copy_tree(root, work / "base")  # the tree as it is now; every mutant is copied from this copy
        control = None
        if not args.no_control:
            hints = list(dict.fromkeys(h for m in chosen for h in m["hint"]))
            print(f"control: {len(hints)} hint targets on the unmutated copy ...", file=sys.stderr)
            t0 = time.monotonic()
            check_imports(base, args.python)
            result, node, tail = run_pytest(base, args.python, hints, max(args.timeout, 3600.0),
                                            any(m.get("slow_hints") for m in chosen))
            status = {"passed": "not caught", "failed": "caught"}.get(result, result)
            control = Outcome("control", status, node, "hint", time.monotonic() - t0, tail[-500:])
            print(f"control: {result} {node} ({control.seconds:.0f} s)", file=sys.stderr)
            if result != "passed":
                print(tail, file=sys.stderr)
        outcomes: dict[str, Outcome] = {}
        together = None
        if args.uncaught and args.together:
            print(f"planting all {len(chosen)} at once ...", file=sys.stderr)
            together = run_mutant(base, work, chosen, args.python, max(args.timeout, 3 * 3600.0), args.workers,
                                  args.hints_only, "together")
            print(f"together: {together.status} {together.caught_by} ({together.seconds:.0f} s)", file=sys.stderr)
        else:
            def one(m):
                o = run_mutant(base, work, [m], args.python, args.timeout, args.workers, args.hints_only, m["id"])
                print(f"{m['id']}: {o.status} {o.caught_by} [{o.phase}] ({o.seconds:.0f} s) {o.detail[-200:]}",
                      file=sys.stderr, flush=True)
                return o
            with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as ex:
                for o in ex.map(one, chosen):
                    outcomes[o.id] = o
        text = report(root, chosen, outcomes, control, together, time.monotonic() - started,
                      args.uncaught or any(m in UNCAUGHT for m in chosen), bool(args.group))
    print(text)
    if args.out:
        args.out.write_text(text + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
