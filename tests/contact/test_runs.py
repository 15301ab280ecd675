"""The run books of `stickslip.contact.runs`, for both models that keep them (the ring of the
reduced model and the FE annulus): checkpoint and resume bit for bit, extension, refusal of
another run's checkpoint, the netCDF format, and the options every run validates."""

import numpy as np
import pytest
import xarray as xr

from stickslip.cf import load_result
from stickslip.errors import ParameterError

from .models import CASE2, MODELS


class Stop(Exception):
    pass


def _same(a, b, parts=("series", "snapshots", "kernel")):
    for part in parts:
        da, db = getattr(a, part), getattr(b, part)
        assert da.keys() == db.keys()
        for key in da:
            assert np.array_equal(da[key], db[key]), (part, key)


@pytest.fixture(params=MODELS, ids=lambda m: m.name)
def model(request):
    return request.param


def test_interrupted_run_resumes_bitwise_from_its_checkpoint(model, tmp_path):
    path = tmp_path / "run.nc"
    T = model.scheme(CASE2).transit_time
    kwargs = dict(checkpoint=path, every=5 * T)
    reference = model.run(CASE2, 30)
    seen = []

    def stop_half_way(t, t_end):
        seen.append(t)
        if t > 0.55 * t_end:
            raise Stop

    with pytest.raises(Stop):
        model.run(CASE2, 30, progress=stop_half_way, **kwargs)
    saved = type(reference).from_xarray(load_result(path, group="checkpoint"))
    assert not saved.complete and saved.samples_done == len(seen)  # saved at interruption: nothing lost
    resumed = model.run(CASE2, 30, progress=lambda t, te: seen.append(t), **kwargs)
    assert resumed.complete and np.all(np.diff(seen) > 0) and seen[-1] >= reference.t[-1]
    _same(resumed, reference)
    _same(model.run(CASE2, 30, **kwargs), reference)  # complete: read back, nothing recomputed


def test_a_checkpoint_can_be_extended_and_another_run_is_refused(model, tmp_path):
    path = tmp_path / "run.nc"
    model.run(CASE2, 10, checkpoint=path)
    _same(model.run(CASE2, 20, checkpoint=path), model.run(CASE2, 20), parts=("series", "kernel"))
    other_start = model.perturbed(model.scheme(CASE2), seed=1)
    for options, says in ((dict(beta2=0.6), "beta2: stored"), (dict(initial=other_start), "initial condition: stored"),
                          (dict(courant=0.8), "courant: stored 0.9, now 0.8")):
        with pytest.raises(ParameterError) as err:
            model.run(CASE2, 2, checkpoint=path, **options)
        assert err.value.name == "checkpoint" and says in err.value.allowed and "overwrite it" in err.value.allowed
    with pytest.raises(ParameterError) as err:  # a shorter run: not the longer one handed back as if it were
        model.run(CASE2, 5, checkpoint=path)
    assert err.value.name == "checkpoint" and "no longer than the one asked for" in err.value.allowed
    with pytest.raises(ParameterError) as err:
        model.run(CASE2.replace(friction=0.5), 2, checkpoint=path)
    assert err.value.name == "checkpoint" and "friction: stored" in err.value.allowed


def test_a_file_that_is_not_a_run_of_this_model_is_refused(model, tmp_path):
    """Another model's checkpoint, a netCDF of something else, a file that is not netCDF."""
    other = [m for m in MODELS if m is not model][0]
    foreign = tmp_path / "other_model.nc"
    other.run(CASE2, 2, checkpoint=foreign)
    unrelated = tmp_path / "unrelated.nc"
    xr.Dataset({"x": ("t", np.arange(3.0))}).to_netcdf(unrelated)
    text = tmp_path / "text.nc"
    text.write_text("not netCDF")
    for path in (foreign, unrelated, text):
        with pytest.raises(ParameterError) as err:
            model.run(CASE2, 2, checkpoint=path)
        assert err.value.name == "checkpoint"


def test_result_dataset_has_units_and_round_trips(model, tmp_path):
    run = model.run(CASE2, 6, snapshot_every=2.0, tail=1.0)
    ds = run.to_xarray()
    assert ds["U"].dims == ("snap_t", "theta") and ds["fraction"].dims == ("t", "kind")
    assert ds["t"].attrs["scale"] == "1/Omega" and ds["P"].attrs["scale"] == model.units_P
    assert list(ds["kind"].values) == ["stick", "slip", "reverse_slip", "separation"]
    assert list(ds["state"].attrs["flag_values"]) == [0, 1, 2, 3]
    assert ds.attrs["physical_omega"] == 50.0 and ds.attrs["complete"] == 1
    assert np.allclose(ds["fraction"].sum("kind"), 1.0)
    tail = run.settings["tail_samples"]  # snapshots: every 2 transits and at every sample of the last one
    assert tail + 2 <= ds.sizes["snap_t"] <= tail + 3
    assert np.all(np.diff(ds["snap_t"].values[-tail:]) == pytest.approx(run.settings["chunk"] * run.scheme.dt))
    path = tmp_path / "run.nc"
    ds.to_netcdf(path)
    back = type(run).from_xarray(xr.load_dataset(path))
    _same(back, run)
    assert back.params == run.params and back.params.omega == 50.0


@pytest.mark.parametrize("options, name", [
    (dict(), "t_end"), (dict(t_end=1.0, transits=1.0), "t_end"), (dict(t_end=-1.0), "t_end"),
    (dict(transits=0.0), "transits"), (dict(transits=1, samples_per_transit=2), "samples_per_transit"),
    (dict(transits=1, initial="noise"), "initial"), (dict(transits=1, beta2=0.3), "beta2"),
    (dict(transits=1, courant=1.5), "courant"), (dict(transits=1, every=0.0), "every"),
    (dict(transits=1, tail=-1.0), "tail"), (dict(transits=1, progress=3), "progress"),
    (dict(transits=1, modes=0), "modes")])
def test_runs_reject_bad_options(model, options, name):
    with pytest.raises(ParameterError) as err:
        model.integrate(CASE2, **(model.mesh | options))
    assert err.value.name == name


@pytest.mark.parametrize("request_", [{"transits": 1e11}, {"transits": float("inf")}, {"t_end": 1e300}])
def test_an_absurd_run_length_is_refused_up_front_with_the_limit(model, request_):
    """More than MAX_WORK dof-steps is refused before any step, naming the option and the limit
    for this mesh (it used to run until killed)."""
    from stickslip.contact.runs import MAX_WORK

    s = model.scheme(CASE2)
    name = next(iter(request_))
    with pytest.raises(ParameterError) as err:
        model.integrate(CASE2, **model.mesh, **request_)
    assert err.value.name == name and ("<=" in err.value.allowed or not np.isfinite(request_[name]))
    if name == "transits" and np.isfinite(request_[name]):
        limit = float(err.value.allowed.split()[1])
        assert limit == pytest.approx(MAX_WORK / s.sparse_operator.shape[0] * s.dt / s.transit_time, rel=1e-3)


def _tamper(path, how):
    if how == "bytes":  # 64 bytes flipped at each eighth of the file (the file has slack an edit may miss)
        data = bytearray(path.read_bytes())
        for k in range(1, 8):
            at = k * len(data) // 8
            data[at:at + 64] = bytes(b ^ 0xFF for b in data[at:at + 64])
        path.write_bytes(bytes(data))
        return
    def edit(ds):
        values = ds["kernel_u"].values.copy()
        if how == "nan":
            values.flat[values.size // 2] = np.nan
        else:  # one field scaled by 1e6
            values *= 1e6
        ds["kernel_u"] = (ds["kernel_u"].dims, values, ds["kernel_u"].attrs)

    _rewrite(path, state=edit)


def _rewrite(path, results=lambda ds: None, state=lambda ds: None):
    """The run file with its results (root) and its state (group checkpoint) edited in place."""
    root, group = xr.load_dataset(path), xr.load_dataset(path, group="checkpoint")
    results(root)
    state(group)
    tmp = path.with_suffix(".tmp.nc")
    root.to_netcdf(tmp)
    group.to_netcdf(tmp, mode="a", group="checkpoint")
    tmp.replace(path)


@pytest.mark.parametrize("how", ["bytes", "nan", "scaled"])
def test_a_damaged_or_edited_checkpoint_is_refused_not_resumed(model, how, tmp_path):
    """Issue 9: these were resumed silently and gave another answer (or NaN with exit 0)."""
    path = tmp_path / "run.nc"
    model.run(CASE2, 4, checkpoint=path)
    model.run(CASE2, 6, checkpoint=path)  # an intact checkpoint resumes
    _tamper(path, how)
    with pytest.raises(ParameterError) as err:
        model.run(CASE2, 8, checkpoint=path)
    assert err.value.name == "checkpoint"


def test_a_checkpoint_in_another_run_format_is_refused(model, tmp_path):
    """Its content intact (checksum valid) but written with another layout: refused, not misread."""
    path = tmp_path / "run.nc"
    model.run(CASE2, 4, checkpoint=path)
    _rewrite(path, lambda ds: ds.attrs.update(run_format="stickslip-run-1"))
    with pytest.raises(ParameterError) as err:
        model.run(CASE2, 6, checkpoint=path)
    assert err.value.name == "checkpoint" and "stickslip-run-1" in err.value.allowed


def test_a_checkpoint_from_another_version_is_refused(model, tmp_path):
    """The checkpoint records the stickslip version that wrote it; another version's is refused
    (`test_runs` shows ``overwrite`` starting afresh on any refused checkpoint)."""
    path = tmp_path / "run.nc"
    model.run(CASE2, 2, checkpoint=path)
    _rewrite(path, state=lambda ds: ds.attrs.update(source="stickslip 0.0.9"))
    with pytest.raises(ParameterError, match="written by stickslip") as err:
        model.run(CASE2, 2, checkpoint=path)
    assert err.value.name == "checkpoint"


# -- issue 44: the books of a free ring against its exact discrete motion --------------------------------------

def _free_ring(transits=3.0, **options):
    """A free (contact off) ring of 16 nodes, undamped central differences, from steady sliding
    plus a mode-3 pattern and noise: a linear problem whose discrete motion the test steps itself."""
    from stickslip.brake.ring import RingScheme, integrate, perturbed_steady
    start = perturbed_steady(CASE2, 16, amplitude=0.3, mode=3, noise=0.1)
    run = integrate(CASE2, 16, transits=transits, initial=start, contact=False, **options)
    return run, RingScheme(CASE2, 16), start


def _stepped(scheme, u0, steps):
    """u_0 .. u_steps of u_{m+1} = 2 u_m - u_{m-1} + dt^2 a(u_m), u_1 = u_0 + dt^2 a(u_0)/2 (from
    rest), a(u) = M^-1 (-K u + f): central differences, written here."""
    load = 0.0 if scheme.load is None else scheme.load
    acc = lambda u: scheme.apply(u) + load  # noqa: E731
    dt2, out = scheme.dt ** 2, [np.array(u0, float)]
    out.append(out[0] + 0.5 * dt2 * acc(out[0]))
    for _ in range(steps - 1):
        out.append(2 * out[-1] - out[-2] + dt2 * acc(out[-1]))
    return np.array(out)


def test_a_free_runs_snapshots_are_its_discrete_motion_at_their_times():
    """Each snapshot's U, V at ``snap_t`` and its step velocities are those of the test's own
    central-difference stepping at step snap_t/dt (a time label one step off moves them by about
    omega dt of the motion: far above the 1e-9 of round-off over a few hundred steps)."""
    run, scheme, start = _free_ring(snapshot_every=0.5, tail=1.0)
    steps = np.rint(run.snap_t / scheme.dt).astype(int)
    assert np.allclose(steps * scheme.dt, run.snap_t, rtol=0, atol=1e-9 * scheme.dt)
    u = _stepped(scheme, scheme.dofs(start.U, start.V), int(steps.max()) + 1)
    scale = np.abs(u).max()
    for k, m in enumerate(steps):
        U, V = scheme.fields(u[m])
        assert np.abs(run.U[k] - U).max() < 1e-9 * scale and np.abs(run.V[k] - V).max() < 1e-9 * scale
        Ud, Vd = scheme.fields((u[m + 1] - u[m]) / scheme.dt)
        assert np.abs(run.Vd[k] - Vd).max() < 1e-9 * scale / scheme.dt


def test_a_free_undamped_run_keeps_its_energy_and_its_kinetic_part_is_half_m_w_squared():
    """Central differences conserve |w|^2/2 + (u_m - u_e) K (u_{m+1} - u_e)/2 of a free linear
    problem exactly (round-off aside): the series ``energy`` is constant, and ``kinetic`` in the
    tail (where every sample is a snapshot) is m |w|^2/2 of the snapshot's step velocities."""
    run, scheme, _ = _free_ring(tail=1.0)
    assert np.ptp(run.energy) < 1e-9 * np.abs(run.energy).max() and np.ptp(run.kinetic) > 1e-3 * run.energy.max()
    tail = run.settings["tail_samples"]
    w = np.hstack([run.Vd[-tail:], run.Ud[-tail:]])
    np.testing.assert_allclose(run.kinetic[-tail:], 0.5 * scheme.mass * np.sum(w**2, axis=1), rtol=1e-9)


def test_the_series_modes_are_the_fourier_coefficients_of_the_snapshots():
    """Parseval: with every mode kept (0..N/2), mean(V^2) over the nodes is |c_0|^2 + 2 sum
    |c_k|^2 (0 < k < N/2) + |c_{N/2}|^2 for c = rfft(V)/N, at each sample of the tail."""
    run, _, _ = _free_ring(tail=1.0, modes=8)
    tail = run.settings["tail_samples"]
    c = run.modes_V[-tail:]
    weights = np.r_[1.0, np.full(7, 2.0), 1.0]
    np.testing.assert_allclose(np.abs(c) ** 2 @ weights, np.mean(run.V[-tail:] ** 2, axis=1), rtol=1e-12)
    np.testing.assert_allclose(run.t[-tail:], run.snap_t[-tail:], rtol=0, atol=0)


@pytest.mark.parametrize("transits", [2.0, 2.3])
def test_a_run_ends_within_one_sample_past_the_time_asked_and_its_tail_is_every_sample(transits):
    """`schedule`: the last sample at or past t_end (less than one sample beyond), and the tail's
    snapshots exactly the samples of the last ``tail`` transits, rounded (no snapshot otherwise:
    ``snapshot_every`` beyond the run)."""
    run, scheme, _ = _free_ring(transits=transits, tail=0.5, snapshot_every=100.0)
    t_end, sample = transits * scheme.transit_time, run.settings["chunk"] * scheme.dt
    assert t_end - 1e-9 * t_end <= run.t_end < t_end + sample
    tail = round(0.5 * scheme.transit_time / sample)  # the samples of half a transit
    assert run.snap_t.size == tail and np.array_equal(run.snap_t, run.t[-tail:])
