"""`stickslip halfspace run`: an in-plane interface in time from the command line, written as it goes
and resumed after a kill to the last bit; an ill-posed law said; bad options in one line."""

import json
import math
import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest
import xarray as xr

from stickslip.cli import run

SMALL = ["--elements", "64", "--duration", "3", "--every", "5"]


def _call(args, capsys):
    code = run(args)
    out, err = capsys.readouterr()
    return code, out, err


def test_a_run_writes_its_fields_and_prints_finite_numbers(tmp_path, capsys):
    nc, png = tmp_path / "run.nc", tmp_path / "run.png"
    code, out, err = _call(["halfspace", "run", "--out", str(nc), "--plot", str(png), "--json", *SMALL], capsys)
    assert code == 0, err
    data = json.loads(out)
    assert data["well_posed"] is True and data["ill_posedness"] == ""
    assert all(math.isfinite(v) for v in data.values() if isinstance(v, float))
    assert data["t_end"] == pytest.approx(3.0, rel=0.01) and png.stat().st_size > 10_000
    # the energy books at the end (stickslip.sbim.energy): the patch's slip released energy, some of it radiated
    assert data["released_energy"] == pytest.approx(data["load_work"] - data["static_energy"], rel=1e-12)
    assert 0 < data["wave_energy"] < data["released_energy"] and data["fracture_energy"] > 0  # slip-weakening
    with xr.open_dataset(nc) as ds:
        assert ds.slip_rate.shape == (data["samples"], 64) and ds.attrs["Conventions"].startswith("CF")
        assert ds.slip_rate.attrs["units"] == "m/s" and ds.attrs["well_posedness"] == "well posed"
        # the patch (3 MPa over 8 km, the default) overstressed beyond the static strength slides at once at
        # the radiation-damping rate c_s (tau - f_s sigma) / mu at its middle
        first = ds.slip_rate.isel(t=0).sel(x=20e3, method="nearest")
        assert float(first) == pytest.approx(3464.0 * (31e6 - 0.6 * 50e6) / 3e10, rel=1e-9)


def test_an_ill_posed_law_runs_and_says_so(tmp_path, capsys):
    code, out, err = _call(["halfspace", "run", "--out", str(tmp_path / "r.nc"), "--law", "coulomb",
                            "--static-friction", "2", "--kinetic-friction", "1.5", "--traction", "80e6", "--json",
                            *SMALL], capsys)
    data = json.loads(out)
    assert code == 0 and data["well_posed"] is False and "ill-posed" in data["ill_posedness"]
    assert "ill-posed" in err
    code, out, err = _call(["halfspace", "run", "--out", str(tmp_path / "p.nc"), "--law", "coulomb",
                            "--static-friction", "2", "--kinetic-friction", "1.5", "--traction", "80e6",
                            "--relaxation-slip", "1e-3", "--relaxation-speed", "0.1", "--json", *SMALL], capsys)
    assert code == 0 and json.loads(out)["well_posed"] is True and "ill-posed" not in err


def test_two_materials_run_and_say_adams_instability(tmp_path, capsys):
    lower = ["--lower-shear-modulus", "2e10", "--lower-shear-wave-speed", "2800", "--lower-poisson", "0.3"]
    code, out, err = _call(["halfspace", "run", "--out", str(tmp_path / "r.nc"), "--json", *lower, *SMALL], capsys)
    data = json.loads(out)
    assert code == 0 and data["lower_shear_wave_speed"] == 2800.0 and "Adams" in data["ill_posedness"]
    assert data["dt"] == pytest.approx(0.3 * 40e3 / 64 / 3464.0)  # the upper solid is the faster
    assert all(math.isfinite(v) for v in data.values() if isinstance(v, float)) and "Adams" in err
    with xr.open_dataset(tmp_path / "r.nc") as ds:
        assert "another elastic half-space" in ds.attrs["title"] and ds.attrs["lower_poisson"] == 0.3
        assert ds["lower_displacement_x"].attrs["units"] == "m"
    assert data["load_work"] > 0 and math.isfinite(data["wave_energy"])  # the books, between two materials too


def test_rate_and_state_holds_steady_sliding_under_its_steady_drive(tmp_path, capsys):
    """--law rate-state from steady sliding at --slip-rate under the traction that holds it, sigma (f0 + (a - b)
    ln(V / V_ref)) + (mu / c_s) V written here, and no patch: every node still slides at that rate (each of
    the law's options reaches the law: a wrong one drifts the rate)."""
    a, b, f0, v_ref, v, sigma = 0.012, 0.016, 0.55, 1e-6, 3e-5, 4e7
    drive = sigma * (f0 + (a - b) * math.log(v / v_ref)) + 3e10 / 3464.0 * v
    code, out, err = _call(["halfspace", "run", "--out", str(tmp_path / "r.nc"), "--law", "rate-state", "--a",
                            str(a), "--b", str(b), "--f0", str(f0), "--v-ref", str(v_ref), "--slip-rate", str(v),
                            "--dc", "0.01", "--normal-traction", str(-sigma), "--traction", repr(drive),
                            "--patch-traction", "0", "--json", *SMALL], capsys)
    assert code == 0, err
    with xr.open_dataset(tmp_path / "r.nc") as ds:
        assert np.abs(ds.slip_rate.values / v - 1).max() < 1e-9
        given = {"a": a, "b": b, "f0": f0, "v_ref": v_ref, "slip_rate": v, "dc": 0.01, "normal_stress": sigma}
        assert {k: ds.attrs[k] for k in given} == given and ds.attrs["slip_law"] == 0  # the file says its law
    assert json.loads(out)["law"] == "RateStateFriction"


def test_rate_and_state_starts_in_steady_sliding_by_default(tmp_path, capsys):
    """--traction's default with --law rate-state is the steady drive at --slip-rate: without a patch every
    node keeps that rate; the JSON says the traction and the law's options used."""
    code, out, err = _call(["halfspace", "run", "--out", str(tmp_path / "r.nc"), "--law", "rate-state",
                            "--slip-rate", "2e-5", "--patch-width", "0", "--json", *SMALL], capsys)
    assert code == 0, err
    data = json.loads(out)
    with xr.open_dataset(tmp_path / "r.nc") as ds:
        assert np.abs(ds.slip_rate.values / 2e-5 - 1).max() < 1e-9
    steady = 50e6 * (0.6 + (0.010 - 0.015) * math.log(2e-5 / 1e-6)) + 3e10 / 3464.0 * 2e-5  # written here
    assert data["traction"] == pytest.approx(steady, rel=1e-12) and data["a"] == 0.010 and data["slip_law"] is False
    assert "static_friction" not in data and data["units"]["dc"]["units"] == "m"


def test_rate_and_state_between_two_materials_runs_regularised_and_is_refused_without(tmp_path, capsys):
    lower = ["--lower-shear-modulus", "2e10", "--lower-shear-wave-speed", "2800", "--lower-poisson", "0.3"]
    code, out, err = _call(["halfspace", "run", "--out", str(tmp_path / "r.nc"), "--law", "rate-state",
                            "--traction", "31e6", *lower, *SMALL], capsys)
    assert code == 2 and err.count("\n") == 1 and "--relaxation-slip" in err
    code, out, err = _call(["halfspace", "run", "--out", str(tmp_path / "r.nc"), "--law", "rate-state",
                            "--traction", "31e6", "--relaxation-slip", "1e-3", "--relaxation-speed", "1e-6",
                            "--json", *lower, *SMALL], capsys)
    data = json.loads(out)
    assert code == 0 and data["law"] == "PrakashClifton" and data["well_posed"] is True, err
    assert all(math.isfinite(v) for v in data.values() if isinstance(v, float))


KILLABLE = textwrap.dedent("""
    import sys
    import stickslip.sbim.runfile as runfile
    runfile.CHECKPOINT_SECONDS = 0.0  # write at every step, so that a kill finds a state
    from stickslip.cli import run
    sys.exit(run(sys.argv[1:]))
""")


def test_a_killed_run_resumes_to_the_uninterrupted_result_and_another_runs_file_is_refused(tmp_path, capsys):
    args = ["halfspace", "run", "--elements", "64", "--duration", "12", "--every", "4"]
    whole, part = tmp_path / "whole.nc", tmp_path / "part.nc"
    assert _call([*args, "--out", str(whole)], capsys)[0] == 0
    proc = subprocess.Popen([sys.executable, "-c", KILLABLE, *args, "--out", str(part)], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    done = 0
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        try:
            with xr.open_dataset(part) as ds:
                done = int(ds.attrs["steps_done"])
        except Exception:  # noqa: BLE001 - not written yet, or being replaced
            pass
        if done >= 50:
            break
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    with xr.open_dataset(part) as ds:
        done = int(ds.attrs["steps_done"])
    assert 50 <= done  # killed part-way (a run of about 890 steps)
    code, _, err = _call([*args, "--out", str(part)], capsys)
    assert code == 0, err
    with xr.open_dataset(whole) as a, xr.open_dataset(part) as b:
        total = int(a.attrs["steps_done"])
        assert done < total
        for name in ("slip", "opening", "slip_rate", "normal_traction", "shear_stress"):
            np.testing.assert_array_equal(a[name].values, b[name].values)
    code, out, err = _call([*args[:-1], "13", "--out", str(part)], capsys)
    assert code == 2 and out == "" and err.count("\n") == 1 and "--out" in err and "another run" in err


@pytest.mark.parametrize("args, flag", [
    (["--elements", "3"], "--elements"),
    (["--poisson", "0.495"], "--poisson"),
    (["--lower-poisson", "0.3"], "--lower-shear-modulus"),
    (["--lower-poisson", "0.495", "--lower-shear-modulus", "2e10", "--lower-shear-wave-speed", "3000"],
     "--lower-poisson"),
    (["--lower-poisson", "0.3", "--lower-shear-modulus", "2e10", "--lower-shear-wave-speed", "0"],
     "--lower-shear-wave-speed"),
    (["--relaxation-slip", "1e-3"], "--relaxation-speed"),
    (["--patch-width", "1e6"], "--patch-width"),
    (["--kinetic-friction", "0.7"], "--kinetic-friction"),
    (["--duration", "1e300"], "--duration"),
    (["--duration", "nan"], "--duration"),
    (["--beta", "0.9"], "--beta"),
    (["--law", "free", "--relaxation-slip", "1", "--relaxation-speed", "1"], "--relaxation-slip"),
    (["--patch-speed", "1e7"], "--patch-speed"),
    (["--a", "0.01"], "--a"),
    (["--law", "coulomb", "--slip-law"], "--slip-law"),
    (["--law", "rate-state", "--static-friction", "0.9"], "--static-friction"),
    (["--law", "coulomb", "--weakening-slip", "0.1"], "--weakening-slip"),
    (["--law", "free", "--kinetic-friction", "0.1"], "--kinetic-friction"),
    (["--patch-speed", "3000", "--patch-width", "0"], "--patch-speed"),
    (["--duration", "1e-9"], "--duration"),
    (["--law", "rate-state", "--normal-traction", "0"], "--normal-traction"),
    (["--law", "rate-state", "--normal-traction", "-1e11"], "--normal-traction"),
    (["--law", "rate-state", "--a", "1e-8", "--traction", "28e6"], "--traction"),
    (["--law", "rate-state", "--f0", "10", "--traction", "1e6"], "--traction"),
    (["--law", "rate-state", "--patch-traction", "-40e6"], "--patch-traction"),
    (["--law", "rate-state", "--a", "2"], "--a"),
    (["--law", "rate-state", "--slip-rate", "0"], "--slip-rate"),
    (["--law", "rate-state", "--dc", "-1"], "--dc"),
    (["--plane", "antiplane", "--poisson", "0.3"], "--poisson"),
    (["--plane", "antiplane", "--relaxation-slip", "1e-3", "--relaxation-speed", "1"], "--relaxation-slip"),
    (["--plane", "antiplane", "--lower-poisson", "0.3", "--lower-shear-modulus", "2e10", "--lower-shear-wave-speed",
      "3000"], "--lower-"),
    (["--plane", "antiplane", "--law", "coulomb", "--normal-traction", "0"], "--normal-traction"),
    (["--plane", "antiplane", "--law", "rate-state", "--normal-traction", "0"], "--normal-traction"),
    (["--plane", "sideways"], "--plane"),
    (["--plane", "antiplane", "--law", "free", "--normal-traction", "1e6"], "--normal-traction"),
    (["--plane", "antiplane", "--relaxation-speed", "1"], "--relaxation-speed"),
    (["--plane", "antiplane", "--elements", "1048576"], "--duration"),
])
def test_bad_options_are_one_line_naming_the_option(tmp_path, capsys, args, flag):
    code, out, err = _call(["halfspace", "run", "--out", str(tmp_path / "r.nc"), *args], capsys)
    assert code == 2 and out == "" and err.count("\n") == 1 and flag in err
    assert not (tmp_path / "r.nc").exists()


def test_the_output_is_checked_before_any_work(tmp_path, capsys):
    code, _, err = _call(["halfspace", "run", "--out", str(tmp_path / "no" / "r.nc")], capsys)
    assert code == 2 and "--out" in err
    fifo = tmp_path / "f.nc"
    os.mkfifo(fifo)
    code, _, err = _call(["halfspace", "run", "--out", str(fifo)], capsys)
    assert code == 2 and "--out" in err


def test_a_sweep_runs_the_command_at_each_point_with_a_run_file_each(tmp_path, capsys):
    (tmp_path / "sweep.toml").write_text(textwrap.dedent("""
        command = "halfspace run"
        outputs = ["peak_slip_rate", "slipped_fraction"]
        [fixed]
        elements = 64
        duration = 3.0
        [axes]
        patch_traction = [1e6, 3e6]
    """))
    code, out, err = _call(["sweep", str(tmp_path / "sweep.toml"), "--out", str(tmp_path / "s.zarr"),
                            "--scheduler", "synchronous", "--json"], capsys)
    assert code == 0, err
    with xr.open_zarr(tmp_path / "s.zarr") as ds:
        # 28 + 1 MPa stays below the static strength 0.6 x 50 MPa: nothing slips; 28 + 3 MPa slides
        assert ds.slipped_fraction.values[0] == 0 and ds.peak_slip_rate.values[0] == 0
        assert ds.slipped_fraction.values[1] > 0.3
    assert len(list((tmp_path / "s.runs").glob("*.nc"))) == 2


def test_antiplane_coulomb_slides_at_the_radiation_rate_above_its_static_strength_and_holds_below(tmp_path, capsys):
    """--plane antiplane, no patch: above the static strength f_s sigma every node slides at (tau - f_k sigma)
    c_s / mu (the radiation-damping limit, written here); below it nothing moves. The strengths are the
    coefficients times the compression."""
    common = ["halfspace", "run", "--plane", "antiplane", "--law", "coulomb", "--static-friction", "0.6",
              "--kinetic-friction", "0.45", "--normal-traction", "-5e7", "--patch-width", "0", "--json", *SMALL]
    code, out, err = _call([*common, "--traction", "4e7", "--out", str(tmp_path / "a.nc")], capsys)
    assert code == 0, err
    data = json.loads(out)
    expected = (4e7 - 0.45 * 5e7) * 3464.0 / 3e10
    with xr.open_dataset(tmp_path / "a.nc") as ds:
        assert np.abs(ds.slip_rate.values[1:] / expected - 1).max() < 1e-12
        assert "normal_traction" not in ds and ds.attrs["kinetic_strength"] == 0.45 * 5e7
        given = {"static_friction": 0.6, "kinetic_friction": 0.45, "normal_traction": -5e7, "traction": 4e7}
        assert {k: ds.attrs[k] for k in given} == given and ds.attrs["law"] == "Coulomb"  # the file says it all
    assert data["plane"] == "antiplane" and data["static_strength"] == 0.6 * 5e7 and "peak_opening" not in data
    code, out, err = _call([*common, "--traction", "2.9e7", "--out", str(tmp_path / "b.nc")], capsys)
    assert code == 0, err
    assert json.loads(out)["final_max_slip"] == 0.0 and json.loads(out)["slipped_fraction"] == 0.0


def test_antiplane_runs_resume_from_their_file_and_an_in_plane_runs_file_is_refused(tmp_path, capsys):
    """An antiplane run's file is its checkpoint: run again, it gives the same fields; an in-plane run's file
    at the same path is refused in one line naming --out (another kind of run)."""
    args = ["halfspace", "run", "--plane", "antiplane", "--elements", "64", "--duration", "3", "--every", "5"]
    assert _call([*args, "--out", str(tmp_path / "a.nc")], capsys)[0] == 0
    with xr.open_dataset(tmp_path / "a.nc") as ds:
        first = ds.slip_rate.values.copy()
    assert _call([*args, "--out", str(tmp_path / "a.nc")], capsys)[0] == 0
    with xr.open_dataset(tmp_path / "a.nc") as ds:
        np.testing.assert_array_equal(ds.slip_rate.values, first)
    assert _call(["halfspace", "run", *SMALL, "--out", str(tmp_path / "i.nc")], capsys)[0] == 0
    code, out, err = _call([*args, "--out", str(tmp_path / "i.nc")], capsys)
    assert code == 2 and out == "" and err.count("\n") == 1 and "--out" in err


def test_a_slowly_creeping_interface_has_slipped_everywhere(tmp_path, capsys):
    """slipped_fraction counts the nodes that moved at all: rate-and-state creeping at 1e-12 m/s (slips of
    a few 1e-12 m) has slipped over the whole interface."""
    code, out, err = _call(["halfspace", "run", "--out", str(tmp_path / "r.nc"), "--law", "rate-state",
                            "--slip-rate", "1e-12", "--patch-width", "0", "--json", *SMALL], capsys)
    assert code == 0, err
    data = json.loads(out)
    assert data["final_max_slip"] < 1e-10 and data["slipped_fraction"] == 1.0
