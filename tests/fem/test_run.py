"""Runs of a general body: the shared books in SI units, a killed run resumes bitwise, a
checkpoint of another problem is refused, the files follow the CF rules, and on the annulus
the general path finds the limit regime the annulus' own path finds."""

import numpy as np
import pytest

from stickslip.brake.fem import FemScheme, classify_fem, integrate_fem
from stickslip.errors import ParameterError
from stickslip.fem.run import BodyRun, classify_body, integrate_body

from ..cf_rules import problems
from .test_scheme import PARAMS, general_annulus


@pytest.fixture(scope="module")
def annulus():
    return general_annulus(FemScheme(PARAMS, 32, 2, 0.9)).params


def test_a_killed_run_resumes_bitwise_and_another_problem_is_refused(annulus, tmp_path):
    whole = integrate_body(annulus, transits=8.0)
    path = tmp_path / "run.nc"

    def kill(t, t_end):
        if t > 0.4 * t_end:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        integrate_body(annulus, transits=8.0, checkpoint=path, progress=kill)
    resumed = integrate_body(annulus, transits=8.0, checkpoint=path)
    assert resumed.complete and np.array_equal(resumed.U, whole.U) and np.array_equal(resumed.energy, whole.energy)
    other = type(annulus)(annulus.system, annulus.frames, 0.3, annulus.clamped)
    with pytest.raises(ParameterError) as err:
        integrate_body(other, transits=8.0, checkpoint=path)
    assert err.value.name == "checkpoint"
    back = BodyRun.from_xarray(resumed.to_xarray(), resumed.scheme)
    assert np.array_equal(back.P, resumed.P)
    assert problems(resumed.to_xarray(), "body run") == []
    assert resumed.to_xarray()["t"].attrs["units"] == "s"


def test_a_step_that_fails_midway_leaves_a_checkpoint_that_resumes_bitwise(annulus, tmp_path, monkeypatch):
    """A solver that stops inside a chunk (as the coupled contact does when it does not
    converge) has already moved the state: the checkpoint must keep the last good sample, not
    the half-made one. Planted: without the restore in `stickslip.contact.runs.loop` the resumed
    run differs."""
    from stickslip.errors import NoSolutionError
    from stickslip.fem.scheme import BodyScheme

    whole = integrate_body(annulus, transits=4.0)
    path, real, calls = tmp_path / "run.nc", BodyScheme.advance, []

    def failing(self, state, *args, **kwargs):
        out = real(self, state, *args, **kwargs)
        calls.append(1)
        if len(calls) == 40:
            raise NoSolutionError("stopped midway")  # after the chunk has moved the state
        return out

    monkeypatch.setattr(BodyScheme, "advance", failing)
    with pytest.raises(NoSolutionError):
        integrate_body(annulus, transits=4.0, checkpoint=path)
    monkeypatch.setattr(BodyScheme, "advance", real)
    resumed = integrate_body(annulus, transits=4.0, checkpoint=path)
    assert np.array_equal(resumed.U, whole.U) and np.array_equal(resumed.energy, whole.energy)


def test_the_contact_line_is_stored_by_arclength_in_metres(annulus):
    """The bore's nodes are a regular polygon of 32 sides on radius a: arclengths i 2 a sin(pi/32),
    theta = 2 pi s / L with L the whole perimeter (the line is closed)."""
    ds = integrate_body(annulus, transits=1.0).to_xarray()
    pts = annulus.system.body.points[annulus.frames.nodes]
    a = float(np.hypot(*pts.T).mean())
    chord = 2 * a * np.sin(np.pi / 32)
    assert ds["arclength"].attrs["units"] == "m" and ds["arclength"].dims == ("theta",)
    assert np.allclose(ds["arclength"].values, chord * np.arange(32), rtol=1e-12, atol=1e-12 * a)
    assert ds.attrs["line_length"] == pytest.approx(32 * chord, rel=1e-12)
    assert np.allclose(ds["theta"].values, 2 * np.pi * np.arange(32) / 32, rtol=1e-12, atol=1e-12)
    assert "2 pi s / L" in ds["theta"].attrs["long_name"]


def test_the_general_path_finds_the_annulus_regime(annulus):
    """The same mesh and material through both paths, from different noise: the limit regime
    and its number of waves are a property of the problem, not of the start."""
    general = classify_body(integrate_body(annulus, transits=40.0))
    own = classify_fem(integrate_fem(PARAMS, 32, 2, transits=40.0))
    assert general.regime == own.regime and general.n == own.n


def test_a_run_that_blows_up_stops_and_keeps_its_last_good_checkpoint(annulus, tmp_path):
    """A scheme forced past its stable step (the constructor refuses it; set behind its back)
    blows up: the run stops with a diagnostic, and the checkpoint holds finite values."""
    from stickslip.errors import NoSolutionError
    from stickslip.fem.run import BodyRun, perturbed_steady_body
    from stickslip.fem.scheme import BodyScheme
    from stickslip.contact.runs import prepare, run_explicit
    import xarray as xr

    scheme = BodyScheme(annulus)
    object.__setattr__(scheme, "time_step", 1.5 * scheme.dt_max)
    initial = perturbed_steady_body(scheme)
    t_end, settings = prepare(scheme, t_end=None, transits=30.0, samples_per_transit=32, snapshot_every=1.0,
                              tail=2.0, modes=8, contact=True, initial=initial, progress=None)
    path = tmp_path / "run.nc"
    with pytest.raises(NoSolutionError, match="blew up") as err:
        run_explicit(BodyRun, scheme, initial.u, initial.v, settings, t_end, checkpoint=path)
    assert "last good state" in str(err.value)
    ds = xr.load_dataset(path)
    assert 0 < ds.attrs["samples_done"] < settings["samples_total"]
    assert all(np.all(np.isfinite(ds[name].values)) for name in ds.data_vars if ds[name].dtype.kind == "f")


def test_a_checkpoint_of_the_same_parameters_on_another_contact_is_refused(annulus, tmp_path):
    """Friction, material and start equal, the shaft pushed in twice as far: only the problem's
    digest (mesh, contact frames, clamps) tells the runs apart."""
    from stickslip.fem import RigidCylinder, contact_frames
    from stickslip.fem.run import perturbed_steady_body
    from stickslip.fem.scheme import BodyScheme, ContactProblem

    path = tmp_path / "run.nc"
    start = perturbed_steady_body(BodyScheme(annulus))
    integrate_body(annulus, transits=1.0, checkpoint=path, initial=start)
    delta = -annulus.frames.gap[0]
    frames = contact_frames(annulus.system.body, "bore", RigidCylinder(1.0 + 2 * delta, 1.0 / (1.0 + 2 * delta)))
    other = ContactProblem(annulus.system, frames, annulus.friction, annulus.clamped)
    with pytest.raises(ParameterError) as err:
        integrate_body(other, transits=1.0, checkpoint=path, initial=start)
    assert err.value.name == "checkpoint" and "the problem (mesh" in err.value.allowed
    assert "surface: stored 'cylinder of radius 1" in err.value.allowed


def test_volume_snapshots_beyond_a_gigabyte_are_refused_for_a_general_body_too(annulus):
    """The bound on a run's volume snapshots (1.25e8 numbers) is the shared run books', so a
    general body's run (not only the annulus's) is refused before it starts, naming the option."""
    with pytest.raises(ParameterError) as err:
        integrate_body(annulus, transits=1e5, volume_every=1e-3)
    assert err.value.name == "volume_every" and "transits" in err.value.allowed
    integrate_body(annulus, transits=1.0, volume_every=0.5)  # a small one runs


@pytest.mark.parametrize("amplitude", [1e-3, 0.5])
def test_the_noisy_start_has_the_rms_it_is_asked_for(annulus, amplitude):
    """`perturbed_steady_body`: steady sliding plus noise on the contact nodes' tangential dofs
    whose RMS is ``amplitude`` times the largest steady displacement of the contact line (a noise
    scaled by its mean square instead of its RMS has another RMS unless that is 1)."""
    from stickslip.fem.run import perturbed_steady_body
    from stickslip.fem.scheme import BodyScheme
    scheme = BodyScheme(annulus)
    u_e = scheme.steady_reference()[0]
    normal, tangent = scheme.contact_dofs
    start = perturbed_steady_body(scheme, amplitude, seed=3)
    size = np.abs(u_e[np.concatenate([normal, tangent])]).max()
    noise = (start.u - u_e)[tangent]
    assert np.sqrt(np.mean(noise**2)) == pytest.approx(amplitude * size, rel=1e-12)
    others = np.setdiff1d(np.arange(u_e.size), tangent)
    assert np.array_equal(start.u[others], u_e[others]) and not start.v.any()
