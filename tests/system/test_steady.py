"""Steady sliding of a system and its linear stability: against the closed form of one degree
of freedom, and against a finite-difference Jacobian of the equations of motion written here
(not the library's effective damping)."""

import json
from pathlib import Path

import numpy as np
import pytest

from stickslip.cli import run
from stickslip.errors import NoSolutionError, ParameterError
from stickslip.friction import Coulomb, LinearWeakening
from stickslip.system import Contact, System, steady_sliding

from ..fuzz_harness import SYSTEM_FILE


@pytest.mark.parametrize("m, c, k, N, V, tau", [(1.0, 0.0, 1.0, 2.0, 0.2, 0.3), (2.0, 0.5, 30.0, 3.0, -0.4, 0.5),
                                                (0.1, 0.01, 4.0, 1.0, 0.5, 0.0)])
def test_one_dof_eigenvalues_are_the_roots_of_its_characteristic_polynomial(m, c, k, N, V, tau):
    """mu = fd (1 - tau |v_r|): m s^2 + (c - N fd tau) s + k = 0, and x = N sign(V) mu(|V|) / k."""
    fd = 0.4
    result = steady_sliding(System([[m]], [[k]], [Contact([1.0], N, LinearWeakening(0.5, fd, tau), V)],
                                   damping=[[c]]))
    roots = np.roots([m, c - N * fd * tau, k])
    np.testing.assert_allclose(np.sort_complex(result.eigenvalues), np.sort_complex(roots), rtol=1e-12)
    assert result.x[0] == pytest.approx(N * np.sign(V) * fd * (1 - tau * abs(V)) / k, rel=1e-13)
    assert result.stable == (c - N * fd * tau > 0) and result.marginal == (c - N * fd * tau == 0)


@pytest.mark.parametrize("c, tau", [(0.0, 0.0), (0.2 * 0.4 * 0.5, 0.5)])
def test_undamped_or_exactly_cancelled_damping_is_marginal_not_stable(c, tau):
    """Eigenvalues +-i omega (no damping, Coulomb; or a damping that the falling law cancels): the
    verdict is 'marginal', not a sign of round-off (it was True or False by the rounding)."""
    for k in (1.0, 3.0, 7.0, 1e6):
        result = steady_sliding(System([[1.0]], [[k]], [Contact([1.0], 0.2, LinearWeakening(0.5, 0.4, tau), 0.3)],
                                       damping=[[c]]))
        assert result.marginal and not result.stable
        assert result.to_dict()["marginal"] is True
    rng = np.random.default_rng(0)  # seeded: 3-DOF undamped structures, one Coulomb contact; in some all real
    for _ in range(40):              # parts come out below zero by round-off (trial 24: -4.2e-17)
        B = rng.normal(size=(3, 3))
        undamped = steady_sliding(System(np.eye(3), B @ B.T + 3 * np.eye(3), [Contact(np.eye(3)[0], 1.0,
                                                                                        Coulomb(0.5, 0.4), 0.3)]))
        assert undamped.marginal and not undamped.stable
    damped = steady_sliding(System([[1.0]], [[1.0]], [Contact([1.0], 0.2, LinearWeakening(0.5, 0.4, tau), 0.3)],
                                   damping=[[c + 0.01]]))
    assert not damped.marginal and damped.stable


def _field(M, C, K, f, contacts, y):
    """The equations of motion while every contact slips, written out: y = (x, v)."""
    n = M.shape[0]
    x, v = y[:n], y[n:]
    force = f - C @ v - K @ x
    for w, N, law, V in contacts:
        vr = V - w @ v
        force = force + w * N * np.sign(vr) * law.kinetic(vr)
    return np.concatenate([v, np.linalg.solve(M, force)])


def test_three_dofs_against_a_finite_difference_jacobian_of_the_equations():
    rng = np.random.default_rng(7)  # seeded: one fixed, generic structure
    a = rng.normal(size=(3, 3))
    M = a @ a.T + 3 * np.eye(3)
    b = rng.normal(size=(3, 3))
    K = b @ b.T + 2 * np.eye(3)
    C = 0.05 * np.eye(3)
    f = np.array([0.3, -0.2, 0.1])
    contacts = [(np.array([1.0, 0.0, -0.5]), 2.0, LinearWeakening(0.6, 0.4, 0.8), 0.3),
                (np.array([0.0, 1.0, 1.0]), 1.5, LinearWeakening(0.6, 0.5, 0.4), -0.5),
                (np.array([0.2, 0.0, 1.0]), 1.0, Coulomb(0.6, 0.3), 0.1)]
    system = System(M, K, [Contact(w, N, law, V) for w, N, law, V in contacts], damping=C, force=f)
    result = steady_sliding(system)
    y0 = np.concatenate([result.x, np.zeros(3)])
    assert np.abs(_field(M, C, K, f, contacts, y0)).max() < 1e-13  # at rest
    h = 1e-6
    J = np.stack([(_field(M, C, K, f, contacts, y0 + h * e) - _field(M, C, K, f, contacts, y0 - h * e)) / (2 * h)
                  for e in np.eye(6)], axis=1)
    np.testing.assert_allclose(np.sort_complex(result.eigenvalues), np.sort_complex(np.linalg.eigvals(J)),
                               rtol=1e-7, atol=1e-8)
    assert not result.stable and result.growth_rate == pytest.approx(np.linalg.eigvals(J).real.max(), abs=1e-8)


def test_a_surface_at_rest_and_a_free_structure_are_said():
    law = Coulomb(0.5, 0.3)
    with pytest.raises(ParameterError, match=r"contacts\[1\].surface_speed"):
        steady_sliding(System(np.eye(2), np.eye(2), [Contact([1.0, 0.0], 1.0, law, 0.2),
                                                      Contact([0.0, 1.0], 1.0, law, 0.0)]))
    with pytest.raises(NoSolutionError, match="singular"):
        steady_sliding(System(np.eye(2), [[1.0, -1.0], [-1.0, 1.0]], [Contact([1.0, 0.0], 1.0, law, 0.2)]))
    with pytest.raises(ParameterError, match="friction law ends"):
        steady_sliding(System([[1.0]], [[1.0]], [Contact([1.0], 1.0, LinearWeakening(0.5, 0.3, 2.0), 0.6)]))


def test_the_command_line_prints_what_the_library_computes(capsys):
    from stickslip.system import load_system

    assert run(["system", "stability", SYSTEM_FILE, "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    expected = steady_sliding(load_system(SYSTEM_FILE))
    np.testing.assert_allclose(printed["eigenvalue_real"], expected.eigenvalues.real, rtol=1e-15)
    assert printed["stable"] == expected.stable and printed["units"]["growth_rate"]["units"] == "1/s"


@pytest.mark.parametrize("args, named", [
    (["simulate", SYSTEM_FILE, "--t-end", "5", "--x0", "0.1"], "--x0"),
    (["simulate", SYSTEM_FILE, "--t-end", "5", "--v0", "0.1,a"], "--v0"),
    (["simulate", SYSTEM_FILE, "--t-end", "5", "--x0", "0.1,1e301"], "--x0"),
    (["cycle", SYSTEM_FILE, "--transient", "0"], "--transient"),
    (["cycle", "no such file.toml"], "system file"),
])
def test_bad_command_lines_exit_2_naming_the_option(args, named, capsys):
    assert run(["system", *args]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and named in err[0]


def test_a_key_of_the_file_is_named(tmp_path, capsys):
    text = Path(SYSTEM_FILE).read_text().replace("fd = 0.4\n", "fd = 0.7\n", 1)
    (tmp_path / "s.toml").write_text(text)
    assert run(["system", "cycle", str(tmp_path / "s.toml")]) == 2
    assert "contact[0].fs" in capsys.readouterr().err


def test_a_problem_found_after_reading_names_the_files_key(tmp_path, capsys):
    """Steady sliding refuses a contact on a surface at rest: the command line names it as the file
    does (contact[1]), not as Python does (contacts[1])."""
    text = Path(SYSTEM_FILE).read_text().replace("surface_speed = 0.1", "surface_speed = 0.0")
    (tmp_path / "s.toml").write_text(text)
    assert run(["system", "stability", str(tmp_path / "s.toml")]) == 2
    err = capsys.readouterr().err
    assert "contact[1].surface_speed" in err and "contacts[" not in err


def test_a_cycle_looked_for_too_early_says_a_longer_transient(capsys):
    """Issue 44: `system cycle` failed from the transient's last event without saying that a longer
    --transient lets the motion settle (the same file settles with --transient 12)."""
    from stickslip.system import limit_cycle, load_system

    with pytest.raises(NoSolutionError, match="a longer transient"):
        limit_cycle(load_system(SYSTEM_FILE), transient=4.0)
    assert run(["system", "cycle", SYSTEM_FILE, "--transient", "4"]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "a longer --transient" in err
    assert run(["system", "cycle", SYSTEM_FILE, "--transient", "12", "--json"]) == 0
