"""Friction that depends on the slip speed on a body (issue 24): steady sliding at the law's
kinetic coefficient at the belt speed, and the CEA's slope term (a falling law is negative
damping) against the 1-DOF oscillator's linear analysis: a stiff block (E = 1e12 Pa, its
rigid mode on the drive spring far below its elastic ones) on a belt with Rayleigh damping
alpha has the eigenvalue of m x'' + (alpha m + N mu'(V)) x' + k x = 0, and loses stability
where alpha m + N mu'(V) = 0. Config keys and refusals."""

import json
import math
import shutil
import subprocess
import sys

import numpy as np
import pytest

from stickslip.cli import run
from stickslip.errors import ParameterError
from stickslip.fem import ContactProblem, Material, RigidFlat, assemble, contact_frames, read_body
from stickslip.fem.cea import complex_eigenvalues
from stickslip.fem.config import load_config
from stickslip.fem.scheme import BodyScheme
from stickslip.friction import LinearWeakening, PressurePower, Stribeck

from .test_examples import EXAMPLES

M, K, N, ALPHA = 1.0, 9.5e5, 1.0e5, 100.0  # the block example's mass, drive, load per metre; damping [1/s]
LAW = Stribeck(0.6, 0.4, 0.2)


@pytest.fixture(scope="module")
def block(tmp_path_factory):
    folder = tmp_path_factory.mktemp("block")
    shutil.copy(EXAMPLES / "block_on_belt" / "block.toml", folder)
    subprocess.run([sys.executable, str(EXAMPLES / "block_on_belt" / "mesh.py"), "block.msh"], cwd=folder, check=True)
    return folder


def _problem(block, speed):
    cfg = load_config(block / "block.toml")
    body = read_body(block / "block.msh")
    system = assemble(body, Material(1e12, 0.3, 1000.0, alpha=ALPHA), cfg.springs, cfg.loads)
    surface = RigidFlat((0.0, 0.0), (0.0, 1.0), (speed, 0.0))
    return ContactProblem(system, contact_frames(body, "bottom", surface), law=LAW)


def _oscillator(speed):
    """The eigenvalue (Im > 0) of m x'' + (alpha m + N mu'(V)) x' + k x = 0."""
    c = ALPHA * M + N * LAW.slope(speed)
    return complex(-c / (2 * M), math.sqrt(K / M - (c / (2 * M)) ** 2))


@pytest.mark.parametrize("speed", [0.8, 1.2, 1.6])
def test_a_stiff_block_on_a_falling_law_has_the_oscillators_eigenvalue(block, speed):
    s = complex_eigenvalues(_problem(block, speed), (0.0, 400.0), count=10).s
    exact = _oscillator(speed)
    assert len(s) == 1 and abs(s[0] - exact) <= 1e-4 * abs(exact), (s, exact)


def test_the_block_loses_stability_where_the_oscillators_linear_analysis_says(block):
    """alpha m + N mu'(V*) = 0: V* = v_s ln(N (f_s - f_d) / (v_s alpha m)) = 1.3816 m/s; growing
    1 % below it, decaying 1 % above."""
    critical = LAW.vs * math.log(N * (LAW.fs - LAW.fd) / (LAW.vs * ALPHA * M))
    below, above = (complex_eigenvalues(_problem(block, v), (0.0, 400.0), count=10).s[0].real
                    for v in (0.99 * critical, 1.01 * critical))
    assert below > 0 > above


def test_steady_sliding_slips_at_the_laws_kinetic_coefficient(block, capsys):
    config = block / "block.toml"
    text = config.read_text()
    config.write_text(text.replace("static_friction = 0.6", 'static_friction = 0.6\nlaw = "stribeck"\n'
                                   "stribeck_speed = 0.2"))
    try:
        assert run(["fem", "steady", str(config), "--json"]) == 0
        data = json.loads(capsys.readouterr().out)
        assert data["friction_force"] == pytest.approx(LAW.kinetic(1.0) * data["normal_force"], rel=1e-12)
        out = block / "law_run.nc"
        assert run(["fem", "run", str(config), "--transits", "1", "--out", str(out), "--json"]) == 0
        capsys.readouterr()
        import xarray as xr
        with xr.open_dataset(out) as ds:
            assert "Stribeck" in ds.attrs["friction_law"]
            # slipping nodes at the law's coefficient of their own slip speed, between f_d and f_s
            # (not one constant: nodes slip at many speeds), sticking ones within f_s
            state, ratio = ds["state"].values, np.abs(ds["Q"].values) / np.maximum(ds["P"].values, 1e-300)
            slipping = (state == 1) | (state == 2)
            assert slipping.sum() > 100 and (state == 0).sum() > 10
            assert LAW.fd * (1 - 1e-12) <= ratio[slipping].min() and ratio[slipping].max() <= LAW.fs * (1 + 1e-12)
            assert np.ptp(ratio[slipping]) > 0.05
            assert ratio[state == 0].max() <= LAW.fs * (1 + 1e-12)
    finally:
        config.write_text(text)


@pytest.mark.parametrize("edit, words", [
    ('law = "stribeck"', ["contact.stribeck_speed is missing"]),
    ('law = "sliding"', ["contact.law = 'sliding' must be one of coulomb, linear-weakening, stribeck"]),
    ("stribeck_speed = 0.2", ["contact.stribeck_speed needs contact.law"]),
    ('law = "stribeck"\nstribeck_speed = 0.2\nweakening = 1.0', ["contact.weakening must be left out"]),
    ('law = "stribeck"\nstribeck_speed = -1.0', ["contact.stribeck_speed = -1.0 must be"]),
    ("pressure_exponent = 0.2", ["contact.reference_pressure is missing (contact.pressure_exponent needs it)"]),
    ("pressure_exponent = 1.0\nreference_pressure = 1e6", ["contact.pressure_exponent = 1.0 must be in [-1, 1)"]),
    ("pressure_exponent = 0.1\nreference_pressure = 0.0", ["contact.reference_pressure = 0.0 must be in [0.001, "
                                                          "1e12] Pa"]),
    ('pressure_exponent = "a"\nreference_pressure = 1e300', ["contact.pressure_exponent = 'a' must be",
                                                             "contact.reference_pressure = 1e+300 must be"]),
])
def test_a_law_written_wrong_is_named_in_the_configs_one_error(block, edit, words):
    config = block / "bad.toml"
    config.write_text((block / "block.toml").read_text().replace("static_friction = 0.6",
                                                                 "static_friction = 0.6\n" + edit))
    with pytest.raises(ParameterError) as err:
        load_config(config)
    for w in words:
        assert w in str(err.value), str(err.value)


def test_a_users_law_is_refused_by_an_explicit_run_before_it_starts(block):
    from stickslip.fem import integrate_body
    from stickslip.friction import UserLaw

    problem = _problem(block, 1.0)
    user = ContactProblem(problem.system, problem.frames, law=UserLaw(lambda v: 0.4 + 0.0 * v, 0.6))
    with pytest.raises(ParameterError) as err:
        integrate_body(user, transits=0.1)
    assert err.value.name == "law" and "compiled" in str(err.value)


def test_a_law_with_a_coefficient_beside_it_is_refused(block):
    problem = _problem(block, 1.0)
    with pytest.raises(ParameterError) as err:
        ContactProblem(problem.system, problem.frames, 0.4, law=LAW)
    assert err.value.name == "friction"
    assert np.isclose(problem.friction, LAW.kinetic(1.0)) and problem.static_friction == 0.6


@pytest.mark.parametrize("law", [None, LinearWeakening(0.4, 0.4, 0.1)], ids=["coulomb", "linear-weakening"])
def test_steady_sliding_with_a_pressure_dependent_coefficient_is_a_fixed_point_of_the_scheme(block, law):
    """The explicit kernel takes each node's coefficient at its own pressure (its reaction per unit
    mass times m / (L P_ref)); steady sliding (solved by `steady_contact`, another code) must then
    be its fixed point: from it, 200 steps leave the displacement within 1e-10 and the friction
    reactions within 1e-9 of steady sliding's, every loaded node slipping (f_s = f_d, so that no
    node can stick on a step of the belt). The pressures differ from node to node by a factor of
    about 10, so a wrong scale moves the reactions of most nodes."""
    cfg = load_config(block / "block.toml")
    body = read_body(block / "block.msh")
    system = assemble(body, Material(1e9, 0.3, 1000.0), cfg.springs, cfg.loads)
    frames = contact_frames(body, "bottom", RigidFlat((0.0, 0.0), (0.0, 1.0), (1.0, 0.0)))
    friction = {"friction": 0.4} if law is None else {"law": law}
    problem = ContactProblem(system, frames, pressure_law=PressurePower(1e6, 0.3), **friction)
    scheme = BodyScheme(problem)
    w, r_n, r_t = scheme.steady_reference()
    pressure = problem.steady.pressure / problem.tributary
    assert pressure.max() > 3 * pressure[pressure > 0].min()
    state = scheme.initial_state(w, np.zeros_like(w))
    out = scheme.advance(state, 200)
    assert np.abs(state.u - w).max() < 1e-10 * np.abs(w).max()
    assert np.abs(out.lam_t - r_t).max() < 1e-9 * np.abs(r_t).max()
    assert np.all(out.state[r_n > 0] == 1)


@pytest.mark.parametrize("n, reference", [(0.999, 1e12), (-1.0, 1e-3)])
def test_a_pressure_law_at_the_edges_of_its_ranges_is_named_not_misreported(block, capsys, n, reference):
    """Both numbers within their declared ranges, together they give the block's nodes coefficients
    of about 1e6 and 4e8: refused in one line naming the law (was "the body is not held", from a
    solve the enormous friction made singular)."""
    config = block / "edge.toml"
    config.write_text((block / "block.toml").read_text().replace(
        "static_friction = 0.6", f"static_friction = 0.4\npressure_exponent = {n}\nreference_pressure = {reference}"))
    assert run(["fem", "steady", str(config)]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "pressure_exponent" in err and "beyond 10" in err, err
