"""ParaView output of FE runs (`write_xdmf`, ``brake fem --xdmf``): read back with meshio, the
fields of steady sliding against the Lamé solution, resume, the command line."""

import json

import meshio
import numpy as np
import pytest

from stickslip.brake import BrakeParams, steady_sliding
from stickslip.brake.fem import FemInitial, FemScheme, integrate_fem, perturbed_steady, write_xdmf
from stickslip.cli import run as cli
from stickslip.contact import SLIP_POS
from stickslip.errors import ParameterError

CASE2 = BrakeParams.from_physical(50.0, 1e-4, 0.7)  # f = 0.7, delta = 0.001
POINT_FIELDS = {"displacement", "u_r", "u_theta", "velocity", "contact_pressure", "contact_shear", "contact_traction",
                "contact_state"}
CELL_FIELDS = {"stress", "sigma_rr", "sigma_thth", "sigma_rth",  # the annulus's own, and the general body's:
               "stress_xx", "stress_yy", "stress_xy", "von_mises", "material"}


def read(path):
    """``(points, cells, [(t, point_data, cell_data), ...])`` of an XDMF time series."""
    with meshio.xdmf.TimeSeriesReader(path) as reader:
        points, cells = reader.read_points_cells()
        frames = [reader.read_data(k) for k in range(reader.num_steps)]
    return points, cells, frames


def test_the_file_reads_back_with_the_mesh_the_cadence_and_the_fields(tmp_path):
    n_theta, n_r, every = 16, 2, 0.5
    run = integrate_fem(CASE2, n_theta, n_r, transits=3, samples_per_transit=8, volume_every=every)
    path = write_xdmf(run, tmp_path / "run.xdmf")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.h5", "run.xdmf"]  # no temporary left
    points, cells, frames = read(path)
    assert points.shape == ((n_r + 1) * n_theta, 3) and np.all(points[:, 2] == 0)
    r = np.hypot(points[:, 0], points[:, 1])
    assert r.min() == pytest.approx(1.0) and r.max() == pytest.approx(CASE2.xi)  # units of R
    assert len(cells) == 1 and cells[0].type == "quad" and cells[0].data.shape == (n_r * n_theta, 4)
    # the cadence, predicted from the schedule: every round(T x samples per transit) samples, and the last one
    s, st = run.scheme, run.settings
    per_sample = st["chunk"] * s.dt
    stride = round(every * s.transit_time / per_sample)
    total = st["samples_total"]
    due = [k for k in range(1, total + 1) if k % stride == 0 or k == total]
    times = np.array([t for t, _, _ in frames])
    assert len(frames) == len(due) + 1 == int(np.ceil(total / stride)) + 1  # and the start, at t = 0
    assert times[0] == 0.0
    # in seconds: the paper's time Omega t over Omega = 50 rad/s (issue 44: it was Omega t, the netCDF seconds)
    assert times[1:] == pytest.approx((np.array(due) * st["chunk"] - 1) * s.dt / 50.0, rel=1e-14)
    assert np.all(np.diff(times) > 0)
    for _, point_data, cell_data in frames:
        assert set(point_data) == POINT_FIELDS and set(cell_data) == CELL_FIELDS
        assert point_data["displacement"].shape == points.shape and point_data["velocity"].shape == points.shape
        assert cell_data["stress"][0].shape == (n_r * n_theta, 9)
        assert all(np.isfinite(v).all() for v in point_data.values())
    # where a frame and a snapshot of the contact nodes (kept apart by the run) coincide, they agree
    paper = times * 50.0
    common = [(k, int(np.flatnonzero(np.isclose(run.snap_t, t, rtol=1e-13, atol=0))[0])) for k, t in enumerate(paper)
              if np.isclose(run.snap_t, t, rtol=1e-13, atol=0).any()]
    assert len(common) >= 3
    for k, j in common:
        pd = frames[k][1]
        for name, snap in (("u_r", run.U), ("u_theta", run.V), ("contact_pressure", run.P), ("contact_shear", run.Q),
                           ("contact_state", run.state)):
            assert np.array_equal(pd[name][:n_theta], snap[j]), (name, k)
    assert not np.array_equal(frames[0][1]["displacement"], frames[-1][1]["displacement"])  # it moves


def _lame_cartesian(lame, r, phi):
    """Closed-form stress (9 components, Cartesian) at radius ``r``, angle ``phi``."""
    srr, stt, srt, szz = lame.stress(r)
    c, s = np.cos(phi), np.sin(phi)
    sxx, syy = c * c * srr + s * s * stt - 2 * c * s * srt, s * s * srr + c * c * stt + 2 * c * s * srt
    sxy = c * s * (srr - stt) + (c * c - s * s) * srt
    zero = np.zeros_like(sxx)
    return np.column_stack([sxx, sxy, zero, sxy, syy, zero, zero, zero, szz * np.ones_like(sxx)])


def test_steady_sliding_written_matches_the_fe_static_state_and_lame(tmp_path):
    """From exact FE steady sliding (a fixed point of the scheme) every snapshot is the shrink fit
    with forward slip. Tolerances set before the first run: displacement = FE static solution to
    1e-8 delta, u_r = Lamé to 2 % of delta; cell stresses = Lamé at the cell's mid radius to 5 %
    of p_e; pressure = p_e, and = -sigma_rr at the bore extrapolated from the written stresses,
    to 5 % of p_e, and so the von Mises stress (32 x 4 mesh)."""
    n_theta, n_r = 32, 4
    scheme = FemScheme(CASE2, n_theta, n_r)
    steady = scheme.steady
    run = integrate_fem(CASE2, n_theta, n_r, transits=0.5, initial=FemInitial(steady.u, 0 * steady.u, "steady"),
                        samples_per_transit=8, volume_every=0.25)
    points, cells, frames = read(write_xdmf(run, tmp_path / "steady.xdmf"))
    lame = steady_sliding(CASE2.xi, CASE2.nu, CASE2.delta, CASE2.friction)
    delta, p_e, q_e = CASE2.delta, lame.p_e, lame.q_e
    r, phi = np.hypot(points[:, 0], points[:, 1]), np.arctan2(points[:, 1], points[:, 0])
    ur = np.concatenate([steady.u[0::2], np.zeros(n_theta)])  # the clamped ring r = xi comes last
    ut = np.concatenate([steady.u[1::2], np.zeros(n_theta)])
    expected = np.column_stack([ur * np.cos(phi) - ut * np.sin(phi), ur * np.sin(phi) + ut * np.cos(phi)])
    centre = points[cells[0].data].mean(axis=1)
    r_mid, phi_mid = r[cells[0].data].mean(axis=1), np.arctan2(centre[:, 1], centre[:, 0])  # mid radius, angle
    surface = np.isclose(r, 1.0)
    assert surface.sum() == n_theta
    assert len(frames) >= 3 and frames[0][0] == 0.0  # the start (its reactions: the steady ones) and the run
    for _, pd, cd in frames:
        disp = pd["displacement"]
        assert np.abs(disp[:, :2] - expected).max() < 1e-8 * delta and np.all(disp[:, 2] == 0)
        u_r = disp[:, 0] * np.cos(phi) + disp[:, 1] * np.sin(phi)
        assert np.abs(u_r - lame.u(r)).max() < 0.02 * delta
        assert pd["u_r"] == pytest.approx(u_r, abs=1e-15) and np.abs(pd["velocity"]).max() < 1e-8 * delta
        stresses = {name: cd[name][0] for name in ("sigma_rr", "sigma_thth", "sigma_rth")}
        for name, exact in zip(stresses, lame.stress(r_mid)):
            assert np.abs(stresses[name] - exact).max() < 0.05 * p_e, name
        assert np.abs(cd["stress"][0] - _lame_cartesian(lame, r_mid, phi_mid)).max() < 0.05 * p_e
        # the general body's fields reach the annulus: its von Mises stress against Lame's, to 5 % of p_e
        srr, stt, srt, szz = lame.stress(r_mid)
        exact = np.sqrt(srr**2 + stt**2 + szz**2 - srr * stt - stt * szz - szz * srr + 3 * srt**2)
        assert np.abs(cd["von_mises"][0] - exact).max() < 0.05 * p_e and np.all(cd["material"][0] == 0)
        # the contact surface: pressure and shear, traction p e_r + q e_theta, states; nothing elsewhere
        p, q = pd["contact_pressure"], pd["contact_shear"]
        assert np.abs(p[surface] - p_e).max() < 0.05 * p_e and np.abs(q[surface] - q_e).max() < 0.05 * p_e
        r1, r2 = np.unique(np.round(r_mid, 9))[:2]  # mid radii of the first two layers
        bore = {}
        for name in ("sigma_rr", "sigma_rth"):  # linear extrapolation of the first two layers to r = 1
            s1, s2 = (stresses[name][np.isclose(r_mid, x)].mean() for x in (r1, r2))
            bore[name] = s1 + (s1 - s2) * (r1 - 1.0) / (r2 - r1)
        assert abs(p[surface].mean() + bore["sigma_rr"]) < 0.05 * p_e
        assert abs(q[surface].mean() + bore["sigma_rth"]) < 0.05 * p_e
        trac = pd["contact_traction"]
        assert trac[:, 0] * np.cos(phi) + trac[:, 1] * np.sin(phi) == pytest.approx(p, abs=1e-12)
        assert -trac[:, 0] * np.sin(phi) + trac[:, 1] * np.cos(phi) == pytest.approx(q, abs=1e-12)
        assert np.all(pd["contact_state"][surface] == SLIP_POS) and np.all(pd["contact_state"][~surface] == -1)
        assert np.all(p[~surface] == 0) and np.all(q[~surface] == 0)


class Stop(Exception):
    pass


def _stop_at(sample, per_sample):
    """A progress callback that interrupts a run when it has done ``sample`` samples in all."""
    def progress(t, t_end):
        if round(t / per_sample) >= sample:
            raise Stop
    return progress


def test_a_resumed_run_writes_the_same_file_and_another_cadence_is_refused(tmp_path):
    """Interrupted twice before its first volume snapshot and once after it, resumed each time:
    the same XDMF content as an uninterrupted run, bit for bit."""
    scheme = FemScheme(CASE2, 16, 2)
    options = dict(n_theta=16, n_r=2, transits=3, samples_per_transit=8, volume_every=1.0,
                   initial=perturbed_steady(scheme, 0.3, mode=2))
    full = integrate_fem(CASE2, **options)
    stride, total = full.settings["volume_every"], full.settings["samples_total"]
    assert 6 <= stride <= total // 2 and total % stride  # about 8 samples per transit, and an extra last one
    reference = read(write_xdmf(full, tmp_path / "reference.xdmf"))
    ck, per_sample = tmp_path / "ck.nc", full.settings["chunk"] * scheme.dt
    for sample in (3, 5, stride + 3):
        with pytest.raises(Stop):
            integrate_fem(CASE2, checkpoint=ck, every=1e9, progress=_stop_at(sample, per_sample), **options)
    resumed = read(write_xdmf(integrate_fem(CASE2, checkpoint=ck, **options), tmp_path / "resumed.xdmf"))
    assert np.array_equal(resumed[0], reference[0]) and np.array_equal(resumed[1][0].data, reference[1][0].data)
    assert len(resumed[2]) == len(reference[2]) == total // stride + 2  # with the start's, at t = 0
    for (t1, pd1, cd1), (t2, pd2, cd2) in zip(resumed[2], reference[2]):
        assert t1 == t2 and pd1.keys() == pd2.keys() and cd1.keys() == cd2.keys()
        assert all(np.array_equal(pd1[k], pd2[k]) for k in pd1)
        assert all(np.array_equal(cd1[k][0], cd2[k][0]) for k in cd1)
    with pytest.raises(ParameterError) as err:  # the cadence is part of the run's settings
        integrate_fem(CASE2, checkpoint=ck, **(options | dict(volume_every=0.5)))
    assert err.value.name == "checkpoint"


def test_bad_input_is_refused(tmp_path):
    run = integrate_fem(CASE2, 16, 1, transits=1, samples_per_transit=8)
    with pytest.raises(ParameterError) as err:
        write_xdmf(run, tmp_path / "x.xdmf")  # no volume snapshots
    assert err.value.name == "run"
    with pytest.raises(ParameterError) as err:
        write_xdmf("run", tmp_path / "x.xdmf")
    assert err.value.name == "run"
    run = integrate_fem(CASE2, 16, 1, transits=1, samples_per_transit=8, volume_every=1)
    for bad in (tmp_path / "x.vtu", tmp_path / "missing" / "x.xdmf"):
        with pytest.raises(ParameterError) as err:
            write_xdmf(run, bad)
        assert err.value.name == "path"
    for value in (0, -1.0, np.nan, np.inf):
        with pytest.raises(ParameterError) as err:
            integrate_fem(CASE2, 16, 1, transits=1, volume_every=value)
        assert err.value.name == "volume_every"
    with pytest.raises(ParameterError) as err:  # more volume snapshots than memory: refused up front
        integrate_fem(CASE2, 16, 1, transits=1e6, volume_every=1e-3)
    assert err.value.name == "volume_every" and "transits" in err.value.allowed
    assert list(tmp_path.iterdir()) == []


def test_an_interrupted_write_keeps_the_previous_file(tmp_path, monkeypatch):
    run = integrate_fem(CASE2, 16, 1, transits=2, samples_per_transit=8, volume_every=0.5)
    path = write_xdmf(run, tmp_path / "run.xdmf")
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}

    def fail(*args, **kwargs):
        raise Stop

    monkeypatch.setattr(meshio.xdmf.TimeSeriesWriter, "write_data", fail)
    with pytest.raises(Stop):
        write_xdmf(run, path)
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before  # and no temporary folder left


BASE = ["brake", "fem", "--omega", "50", "--mismatch", "1e-4", "--friction", "0.7", "--n-theta", "16", "--n-r", "2",
        "--transits", "2"]


def test_the_command_writes_a_readable_file(tmp_path, capsys):
    path = tmp_path / "fem.xdmf"
    assert cli(BASE + ["--xdmf", str(path), "--xdmf-every", "0.5", "--json"]) == 0
    out, err = capsys.readouterr()
    assert json.loads(out)["regime"] and err == ""
    points, cells, frames = read(path)
    assert points.shape == (48, 3) and cells[0].data.shape == (32, 4)
    assert len(frames) in (5, 6)  # the start, every 0.5 transits of 2, and the last sample if it falls between
    assert set(frames[0][1]) == POINT_FIELDS and set(frames[0][2]) == CELL_FIELDS
    assert cli(BASE + ["--xdmf", str(tmp_path / "default.xdmf"), "--json"]) == 0  # every transit by default
    capsys.readouterr()
    assert len(read(tmp_path / "default.xdmf")[2]) in (3, 4)


@pytest.mark.parametrize("extra, option, words", [
    (["--xdmf-every", "0"], "--xdmf-every", "in (0, "),
    (["--xdmf-every", "-1"], "--xdmf-every", "in (0, "),
    (["--xdmf-every", "nan"], "--xdmf-every", "finite"),
    (["--xdmf-every", "inf"], "--xdmf-every", "finite"),
    (["--xdmf-every", "1e-9", "--transits", "1e6"], "--xdmf-every", "transits"),
    (["--xdmf-every", "0.5", "--no-xdmf"], "--xdmf-every", "--xdmf"),
    (["--xdmf", "{tmp}/x.vtu"], "--xdmf", ".xdmf"),
    (["--xdmf", "{tmp}/missing/x.xdmf"], "--xdmf", "folder"),
    (["--xdmf", "{tmp}/f.xdmf", "--out", "{tmp}/f.txt"], "--out", ".nc"),
])
def test_the_command_refuses_bad_input_in_one_line_before_any_work(extra, option, words, tmp_path, capsys,
                                                                    monkeypatch):
    import stickslip.brake.fem as fem

    def no_work(*args, **kwargs):
        raise AssertionError("the run started")

    if "--transits" not in extra:
        monkeypatch.setattr(fem, "integrate_fem", no_work)
    args = [a.replace("{tmp}", str(tmp_path)) for a in extra]
    if "--no-xdmf" in args:
        args.remove("--no-xdmf")
    else:
        args = ["--xdmf", str(tmp_path / "x.xdmf")] * ("--xdmf" not in args) + args
    assert cli(BASE + args) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and option in err and words in err, err
    assert list(tmp_path.iterdir()) == []


def test_the_command_checks_the_data_file_beside_the_xdmf_file_too(tmp_path, capsys, monkeypatch):
    import stickslip.brake.fem as fem

    monkeypatch.setattr(fem, "integrate_fem", None)  # never reached
    (tmp_path / "run.h5").mkdir()
    assert cli(BASE + ["--xdmf", str(tmp_path / "run.xdmf")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--xdmf" in err and "run.h5" in err and "folder" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.h5"]
