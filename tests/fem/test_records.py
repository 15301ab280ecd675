"""A second new user's review (issue 11): a contact that carries no load, a static coefficient
recorded wrongly, a load on a clamped group, a spring stiff enough to drown the body, a
stick-slip run classified over a window shorter than its cycle, and messages that named
internal fields. Each test guards one fix; the bug it guards against was planted and failed it."""

import json
import math

import numpy as np
import pytest
import xarray as xr

from stickslip.cli import run
from stickslip.errors import ParameterError
from stickslip.fem import ContactProblem, Material, RigidFlat, assemble, contact_frames, read_body
from stickslip.fem.boundary import Load, Spring

from .test_refusals import edited, meshes, refused  # noqa: F401  (the fixture)


def test_steady_sliding_records_the_static_coefficient_it_was_given(meshes, tmp_path, capsys):
    block = edited(meshes, tmp_path, "block_on_belt", "block.toml")  # friction 0.4, static_friction 0.6
    out = tmp_path / "steady.nc"
    assert run(["fem", "steady", str(block), "--json", "--out", str(out)]) == 0
    assert json.loads(capsys.readouterr().out)["params"]["static_friction"] == 0.6
    assert xr.open_dataset(out).attrs["static_friction"] == 0.6


def test_a_contact_that_carries_no_load_is_not_linearised(meshes, tmp_path, capsys):
    """The pad touching the disc without interference: the steady forces are round-off (16 of 33
    nodes 'active'), so the CEA refuses instead of reporting flutter of an unloaded contact."""
    bare = edited(meshes, tmp_path, "pad_on_disc", "pad.toml", ("interference = 2e-6", "interference = 0.0"))
    assert run(["fem", "steady", str(bare), "--json"]) == 0
    captured = capsys.readouterr()
    assert json.loads(captured.out)["loaded"] is False
    assert captured.err.startswith("warning: the contact carries no load")
    assert run(["fem", "cea", str(bare)]) == 1
    assert "carries no contact force" in capsys.readouterr().err
    loaded = edited(meshes, tmp_path, "pad_on_disc", "pad.toml")  # 2 micrometres: loaded
    assert run(["fem", "steady", str(loaded), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["loaded"] is True


def test_the_load_floor_sits_between_round_off_and_a_tiny_preload(meshes):
    """A block on a flat under a uniform pressure p carries p x width exactly: half the floor's
    pressure is no load, twice it is one."""
    body = read_body(meshes / "block.msh")
    young = 1e9
    pts = body.points
    size = math.hypot(*(pts.max(axis=0) - pts.min(axis=0)))
    width = float(np.ptp(pts[body.nodes("bottom"), 0]))
    floor_pressure = 1e-10 * young * size / width
    flat = RigidFlat((0.0, 0.0), (0.0, 1.0), (1.0, 0.0))
    frames = contact_frames(body, "bottom", flat)
    springs = [Spring("top", (9.5e5, 0.0))]
    for factor, loaded in ((0.5, False), (2.0, True)):
        system = assemble(body, Material(young, 0.3, 1000.0), springs, [Load("top", factor * floor_pressure)])
        steady = ContactProblem(system, frames, 0.4).steady
        assert steady.pressure.sum() == pytest.approx(factor * floor_pressure * width, rel=1e-6)
        assert steady.loaded is loaded


def test_a_load_or_spring_on_a_clamped_group_is_refused(meshes, tmp_path, capsys):
    held = edited(meshes, tmp_path, "block_on_belt", "block.toml", ('mesh = "block.msh"',
                                                                     'mesh = "block.msh"\nclamped = ["top"]'))
    refused(capsys, ["fem", "steady", str(held)], "spring[0].group = 'top': every node of it is clamped",
             "load[0].group = 'top': every node of it is clamped")
    body = read_body(meshes / "block.msh")
    system = assemble(body, Material(1e9, 0.3, 1000.0), [], [Load("top", 1e6)])
    frames = contact_frames(body, "bottom", RigidFlat((0.0, 0.0), (0.0, 1.0), (1.0, 0.0)))
    with pytest.raises(ParameterError, match=r"load\[0\] on 'top' free"):
        ContactProblem(system, frames, 0.4, ("top",))


def test_a_spring_far_stiffer_than_the_body_is_refused_at_the_bound_it_states(meshes, tmp_path, capsys):
    """The bound is a million times the elastic stiffness of the dof with the largest share: a
    spring of 0.99 of the bound the message states is accepted, 1.01 of it refused."""
    body = read_body(meshes / "block.msh")
    material = Material(1e9, 0.3, 1000.0)
    with pytest.raises(ParameterError, match=r"spring\[0\]\.stiffness") as err:
        assemble(body, material, [Spring("top", (1e20, 0.0))])
    bound = float(err.value.allowed.split("at most ")[1].split()[0])
    elastic = assemble(body, material).K.diagonal()[0::2]
    top = body.nodes("top")
    share = np.zeros(len(body.points))
    edges = body.group("top")
    lengths = np.hypot(*(body.points[edges[:, 1]] - body.points[edges[:, 0]]).T)
    np.add.at(share, edges.ravel(), np.repeat(0.5 * lengths / lengths.sum(), 2))
    expected = 1e6 * np.min(elastic[top] / share[top])  # independent of the assembly's spring code
    assert bound == pytest.approx(expected, rel=1e-3)
    assemble(body, material, [Spring("top", (0.99 * bound, 0.0))])
    with pytest.raises(ParameterError):
        assemble(body, material, [Spring("top", (1.01 * bound, 0.0))])
    stiff = edited(meshes, tmp_path, "block_on_belt", "block.toml", ("stiffness = [9.5e5, 0.0]",
                                                                      "stiffness = [1e19, 1e19]"))
    refused(capsys, ["fem", "cea", str(stiff)], "spring[0].stiffness = [1e+19, 1e+19]", "clamp the group instead")


def test_a_run_is_classified_over_the_window_asked_for(meshes, tmp_path, capsys):
    """`--window` sets the classification window (the default is the 2-transit tail); a window
    longer than the run is refused naming it."""
    block = edited(meshes, tmp_path, "block_on_belt", "block.toml")
    out = tmp_path / "run.nc"
    assert run(["fem", "run", str(block), "--start", "stick", "--transits", "6", "--out", str(out), "--json"]) == 0
    tail = json.loads(capsys.readouterr().out)
    assert run(["fem", "run", str(block), "--start", "stick", "--transits", "6", "--window", "5", "--out", str(out),
                "--json"]) == 0
    wide = json.loads(capsys.readouterr().out)
    ds = xr.open_dataset(out)
    transit = float(ds.attrs["line_length"]) / math.sqrt(1e9 * 0.7 / (1.3 * 0.4 * 1000.0))  # plane-strain P wave
    for result, span in ((tail, 2.0), (wide, 5.0)):  # from the first snapshot in the window (one a transit)
        t0, t1 = result["window"]
        assert (span - 1.05) * transit <= t1 - t0 <= (span + 0.05) * transit, (span, (t1 - t0) / transit)
    assert wide["snapshots"] > tail["snapshots"]
    refused(capsys, ["fem", "run", str(block), "--transits", "6", "--window", "7"], "--window = 7.0", "(0, 6]")


def test_the_pattern_speed_has_units_and_reference_speeds(meshes, tmp_path, capsys):
    """On a closed line `c` [rad/s of theta = 2 pi s / L] comes with c over the P-wave speed,
    whose value is checked against the plane-strain formula."""
    from stickslip.fem.config import load_config
    from stickslip.fem.run import BodyScheme

    block = edited(meshes, tmp_path, "block_on_belt", "block.toml")
    scheme = BodyScheme(load_config(block).problem())
    cp = math.sqrt(1e9 * 0.7 / (1.3 * 0.4 * 1000.0))
    assert scheme.speed_scales["cp"] == pytest.approx(2 * math.pi * cp / scheme.line_length, rel=1e-12)
    assert scheme.speed_scales["surface"] == pytest.approx(2 * math.pi * 1.0 / scheme.line_length, rel=1e-12)
    from stickslip.quantities import lookup
    assert lookup("c", "fem")[0] == "rad/s" and lookup("c_over_cp", "fem")[0] == "1"


def test_options_and_files_are_told_as_the_user_knows_them(meshes, tmp_path, capsys):
    block = edited(meshes, tmp_path, "block_on_belt", "block.toml")
    for command in ("steady", "cea", "run"):
        refused(capsys, ["fem", command, str(block), "--overwrite"], "--overwrite", "without --out")
    steady = tmp_path / "steady.nc"
    assert run(["fem", "steady", str(block), "--out", str(steady)]) == 0
    capsys.readouterr()
    refused(capsys, ["fem", "run", str(block), "--transits", "0.5", "--out", str(steady)],
             "another stickslip result")
    out = tmp_path / "run.nc"
    assert run(["fem", "run", str(block), "--transits", "0.5", "--out", str(out), "--xdmf",
                str(tmp_path / "v.xdmf"), "--json"]) == 0
    capsys.readouterr()
    refused(capsys, ["fem", "run", str(block), "--transits", "0.5", "--out", str(out)], "--xdmf")
    refused(capsys, ["fem", "run", str(block), "--transits", "0.25", "--out", str(out), "--xdmf",
                      str(tmp_path / "v2.xdmf")], " s (")
    worded = edited(meshes, tmp_path, "block_on_belt", "block.toml", ('kind = "flat"', ""),
                     ("pressure = 1.0e6", "pressure = 1.0e6\ntraction = [1e12, 0.0]"),
                     ("poisson = 0.3", "poisson = nan"))
    refused(capsys, ["fem", "steady", str(worded)], "surface.kind is missing", "load[0].traction = [1000000000000.0",
             "material.poisson = nan must be a finite real number, in [0, 0.5)")


@pytest.mark.slow  # a minute: the search runs until it stalls
def test_heavy_damping_that_stalls_the_search_says_where_modes_are_overdamped(meshes, tmp_path, capsys, monkeypatch):
    """beta = 4e-5 overdamps every mode above 1 / (pi beta) = 7958 Hz (alpha + beta w^2 > 2 w);
    the search of 0-40 kHz stalls there and says so."""
    heavy = edited(meshes, tmp_path, "block_on_belt", "block.toml", ("density = 1000.0", "density = 1000.0\n"
                                                                      "beta = 4e-5"))
    assert run(["fem", "cea", str(heavy)]) == 1
    err = capsys.readouterr().err
    assert f"above {1 / (math.pi * 4e-5):.4g} Hz" in err, err
    import scipy.sparse.linalg as sla

    def give_up(*args, **kwargs):  # ARPACK stalling, as it does in a crowd
        raise sla.ArpackError(3)

    mild = edited(meshes, tmp_path, "block_on_belt", "block.toml", ("density = 1000.0", "density = 1000.0\n"
                                                                     "alpha = 2e3"))
    monkeypatch.setattr(sla, "eigs", give_up)
    assert run(["fem", "cea", str(mild)]) == 1
    err = capsys.readouterr().err  # alpha alone: overdamped below w = alpha / 2
    assert f"below {2e3 / 2 / (2 * math.pi):.4g} Hz" in err and "above" not in err, err


def test_a_window_that_sees_one_phase_of_a_longer_cycle_is_warned_about(capsys):
    """The window's node-time fractions against the run's last half: the block's tutorial run
    (2000 transits) had stick 0.9996 over its default window and 0.87 over its last half."""
    from types import SimpleNamespace

    from stickslip.cli.fem import warn_short_window

    t = np.linspace(0.0, 0.172, 2001)
    fractions = np.tile([0.866, 0.102, 0.0, 0.032], (t.size, 1))
    run_ = SimpleNamespace(t=t, t_end=0.172, series={"fractions": fractions})
    names = ("stick", "slip", "reverse_slip", "separation")
    for window, stick, warned in (((0.17221, 0.172), 0.9996, True), ((0.17221, 0.172), 0.90, False),
                                  ((0.05, 0.172), 0.9996, False)):  # a window reaching into the last half: none
        frac = dict(zip(names, (stick, 1.0 - stick, 0.0, 0.0)))
        warn_short_window(run_, SimpleNamespace(fractions=frac, window=window))
        err = capsys.readouterr().err
        assert (err.startswith("warning: the classification window") and "--window" in err) is warned, (window, err)


def test_a_subnormal_number_in_a_config_is_named_as_such(meshes, tmp_path, capsys):
    tiny = edited(meshes, tmp_path, "block_on_belt", "block.toml", ("density = 1000.0", "density = 1e-320"),
                  ("velocity = [1.0, 0.0]", "velocity = [1e-320, 0.0]"))
    refused(capsys, ["fem", "cea", str(tiny)], "material.density = 1e-320", "surface.velocity = [1e-320, 0.0]",
            "subnormal")
