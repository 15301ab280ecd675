"""`stickslip halfspace fault`: earthquake cycles from the command line, the same run as the library's,
written as it goes and resumed after a kill to the last bit; usable by `stickslip sweep`; bad options in
one line naming the option."""

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
from stickslip.rsf import RateState
from stickslip.sbim.fault import YEAR, StrikeSlipFault, run_fault

SMALL = ["--elements", "64", "--years", "240"]


def _call(args, capsys):
    code = run(args)
    out, err = capsys.readouterr()
    return code, out, err


def test_a_run_is_the_librarys_with_bp1s_profile_written_and_plotted(tmp_path, capsys):
    nc, png = tmp_path / "f.nc", tmp_path / "f.png"
    code, out, err = _call(["halfspace", "fault", "--out", str(nc), "--plot", str(png), "--json", *SMALL], capsys)
    assert code == 0, err
    data = json.loads(out)
    assert all(math.isfinite(v) for v in data.values() if isinstance(v, float))
    assert "cohesive zone" in err  # 625-m cells: said
    law = RateState(0.010, 0.015, 0.008, 0.6, 1e-6, "aging", regularized=True)

    def a_profile(z):  # BP1-QD's, written here (in the command's arithmetic: the cycles amplify a last bit)
        return np.clip(0.010 + (0.025 - 0.010) * (z - 15e3) / 3e3, 0.010, 0.025)

    fault = StrikeSlipFault(2670.0 * 3464.0**2, 3464.0, 40e3, 64, law, a_profile, 50e6, 1e-9)
    mine = run_fault(fault, 240 * YEAR)
    assert data["events"] == mine.event_start.size >= 1 and data["peak_slip_rate"] == mine.event_peak.max()
    with xr.open_dataset(nc) as ds:
        np.testing.assert_array_equal(ds.slip.values, mine.slip)
        assert ds.slip.attrs["units"] == "m" and ds.attrs["Conventions"].startswith("CF")
    assert png.stat().st_size > 10_000


KILLABLE = textwrap.dedent("""
    import sys
    import stickslip.sbim.runfile as runfile
    runfile.CHECKPOINT_SECONDS = 0.0  # write at every step, so that a kill finds a state
    from stickslip.cli import run
    sys.exit(run(sys.argv[1:]))
""")


def test_a_killed_run_resumes_to_the_uninterrupted_result_and_another_runs_file_is_refused(tmp_path, capsys):
    args = ["halfspace", "fault", "--elements", "32", "--years", "150"]
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
        if done >= 40:
            break
        time.sleep(0.05)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.wait()
    with xr.open_dataset(part) as ds:
        done = int(ds.attrs["steps_done"])
    assert 40 <= done
    code, _, err = _call([*args, "--out", str(part)], capsys)
    assert code == 0, err
    with xr.open_dataset(whole) as a, xr.open_dataset(part) as b:
        assert done < int(a.attrs["steps_done"])
        for name in ("max_slip_rate", "step_t", "slip", "profile_t"):
            np.testing.assert_array_equal(a[name].values, b[name].values)
    code, out, err = _call([*args[:-1], "151", "--out", str(part)], capsys)
    assert code == 2 and out == "" and err.count("\n") == 1 and "--out" in err and "another run" in err


@pytest.mark.parametrize("args, flag", [
    (["--normal-stress", "1e-2"], "--normal-stress"),
    (["--seismogenic-depth", "5e4"], "--seismogenic-depth"),
    (["--years", "0"], "--years"),
    (["--years", "2e6"], "--years"),
    (["--years", "nan"], "--years"),
    (["--a", "2"], "--a"),
    (["--elements", "2"], "--elements"),
    (["--domain-depth", "30e3"], "--domain-depth"),
    (["--plate-rate", "10"], "--plate-rate"),
    (["--transition-width", "0"], "--transition-width"),
    (["--b", "0"], "--b"),
])
def test_bad_options_are_one_line_naming_the_option(tmp_path, capsys, args, flag):
    code, out, err = _call(["halfspace", "fault", "--out", str(tmp_path / "f.nc"), *args], capsys)
    assert code == 2 and out == "" and err.count("\n") == 1 and flag in err, err
    assert not (tmp_path / "f.nc").exists()


def test_the_output_is_checked_before_any_work(tmp_path, capsys):
    fifo = tmp_path / "f.nc"
    os.mkfifo(fifo)
    code, _, err = _call(["halfspace", "fault", "--out", str(fifo)], capsys)
    assert code == 2 and "--out" in err


def test_a_sweep_runs_the_command_at_each_point(tmp_path, capsys):
    (tmp_path / "sweep.toml").write_text(textwrap.dedent("""
        command = "halfspace fault"
        outputs = ["events", "peak_slip_rate"]
        [fixed]
        elements = 32
        years = 150
        [axes]
        normal_stress = [30e6, 50e6]
    """))
    code, out, err = _call(["sweep", str(tmp_path / "sweep.toml"), "--out", str(tmp_path / "s.zarr"),
                            "--scheduler", "synchronous", "--json"], capsys)
    assert code == 0, err
    with xr.open_zarr(tmp_path / "s.zarr") as ds:
        assert ds.events.shape == (2,) and np.all(np.isfinite(ds.peak_slip_rate.values))
    assert len(list((tmp_path / "s.runs").glob("*.nc"))) == 2
