"""The CEA options engineers compare with (issue 24): the consistent mass matrix and penalty
contact.

* Consistent mass: without friction the pad held on a flat (normal dofs of its face fixed,
  its back clamped) is a symmetric problem; its frequencies from scipy's dense ``eigh`` of
  the stiffness and a consistent mass assembled here with scikit-fem equal the CEA's with
  ``mass_matrix="consistent"`` (every mode of the band, 1e-8); with friction the linearisation
  is checked against finite differences (`test_linearisation`).
* Penalty contact converges to the constraint at first order in the penalty: each tenfold
  stiffer spring cuts the largest eigenvalue difference by 5 to 20 (theory: 10), and at 1e4
  it is below 1e-4 of |s| (thresholds from the first-order theory, set before the run).
* Refusals name the option.
"""

import numpy as np
import pytest
import scipy.linalg as sla

from stickslip.errors import ParameterError
from stickslip.fem import ContactProblem, Material, RigidFlat, assemble, contact_frames, read_body
from stickslip.fem.cea import complex_eigenvalues, linearised

from .meshes import rectangle

BAND = (0.0, 150000.0)


@pytest.fixture(scope="module")
def pad(tmp_path_factory):
    path = tmp_path_factory.mktemp("pad") / "pad.msh"
    rectangle(path, width=0.04, height=0.01, size=0.002)
    body = read_body(path)

    def problem(friction, **material):
        system = assemble(body, Material(1e10, 0.25, 2500.0, **material))
        frames = contact_frames(body, "bottom", RigidFlat((0.0, 2e-6), (0.0, 1.0), (1.0, 0.0)))
        return ContactProblem(system, frames, friction, ("top",))

    return problem


def test_the_consistent_mass_gives_the_frequencies_of_a_dense_solver(pad):
    from skfem import BilinearForm, asm
    from skfem.helpers import dot

    problem = pad(0.0)
    system, body = problem.system, problem.system.body
    assert problem.steady.active.all()
    basis, order = system.basis
    M = asm(BilinearForm(lambda u, v, w: 2500.0 * dot(u, v)), basis)[order][:, order].toarray()
    held = np.zeros(system.n_dofs, bool)
    held[system.dofs(body.nodes("top"))] = True
    held[2 * body.nodes("bottom") + 1] = True  # the flat's normal is y: the face's y dofs held
    free = ~held
    lam = sla.eigh(system.K.toarray()[np.ix_(free, free)], M[np.ix_(free, free)], eigvals_only=True)
    dense = np.sqrt(lam) / (2 * np.pi)
    dense = dense[(dense >= BAND[0]) & (dense <= BAND[1])]
    modes = complex_eigenvalues(problem, BAND, count=30, mass_matrix="consistent")
    found = np.sort(modes.frequency)
    assert len(found) == len(dense) >= 10 and np.all(modes.neutral)
    assert np.abs(found - dense).max() < 1e-8 * BAND[1]
    lumped = np.sort(complex_eigenvalues(problem, BAND, count=30).frequency)
    assert len(lumped) != len(found) or np.abs(lumped - found).max() > 1e-3 * BAND[1]  # it is another mass


def test_penalty_contact_converges_to_the_constraint_at_first_order(pad):
    problem = pad(0.3, alpha=50.0, beta=1e-8)
    exact = complex_eigenvalues(problem, BAND, count=30)
    assert exact.unstable.sum() >= 3
    errors = []
    for penalty in (1e2, 1e3, 1e4):
        s = complex_eigenvalues(problem, BAND, count=30, contact_model="penalty", penalty=penalty).s
        assert len(s) == len(exact.s)
        errors.append(max(np.min(np.abs(s - x)) / abs(x) for x in exact.s))
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    assert np.all((ratios > 5) & (ratios < 20)) and errors[-1] < 1e-4, (errors, ratios)


@pytest.mark.parametrize("options, name", [({"mass_matrix": "diagonal"}, "mass_matrix"),
                                           ({"contact_model": "mortar"}, "contact_model"),
                                           ({"contact_model": "penalty", "penalty": 0.5}, "penalty"),
                                           ({"contact_model": "penalty", "penalty": float("nan")}, "penalty"),
                                           ({"penalty": 1e3}, "penalty")])
def test_bad_options_name_themselves(pad, options, name):
    with pytest.raises(ParameterError) as err:
        linearised(pad(0.3), **options)
    assert err.value.name == name


def test_the_config_takes_the_options_and_refuses_bad_ones(tmp_path, capsys):
    import json
    import shutil
    import subprocess
    import sys

    from stickslip.cli import run

    from .test_examples import EXAMPLES

    shutil.copy(EXAMPLES / "block_on_belt" / "block.toml", tmp_path)
    subprocess.run([sys.executable, str(EXAMPLES / "block_on_belt" / "mesh.py"), "block.msh"], cwd=tmp_path, check=True)
    text = (tmp_path / "block.toml").read_text()
    results = {}
    for name, extra in (("plain", ""), ("consistent", 'mass_matrix = "consistent"\n'),
                        ("penalty", 'contact_model = "penalty"\npenalty = 1e4\n')):
        (tmp_path / f"{name}.toml").write_text(text.replace("[cea]\n", "[cea]\n" + extra))
        assert run(["fem", "cea", str(tmp_path / f"{name}.toml"), "--json"]) == 0
        data = json.loads(capsys.readouterr().out)
        results[name] = np.array([m["growth_rate"] + 2j * np.pi * m["frequency"] for m in data["modes"]])
        assert data["params"]["mass_matrix"] == ("consistent" if name == "consistent" else "lumped")
    a, b = results["plain"], results["penalty"]
    assert len(a) == len(b) and max(np.min(np.abs(b - x)) / abs(x) for x in a) < 1e-3
    for extra, words in (('mass_matrix = "diagonal"\n', "cea.mass_matrix = 'diagonal' must be one of lumped"),
                         ("penalty = 10.0\n", 'cea.penalty applies with cea.contact_model = "penalty" only'),
                         ('contact_model = "penalty"\npenalty = 0.1\n', "cea.penalty = 0.1 must be in [1, 1e12]")):
        (tmp_path / "bad.toml").write_text(text.replace("[cea]\n", "[cea]\n" + extra))
        assert run(["fem", "cea", str(tmp_path / "bad.toml")]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and words in err, err
