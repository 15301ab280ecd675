"""CF-style datasets (issue 10): the rules of `tests/cf_rules.py` hold for every result's
``to_xarray`` and for every file the command line writes; the checker itself catches each
broken rule. The files of ``reproduce --quick`` are checked in `tests/test_report.py`."""

import json

import numpy as np
import pytest
import xarray as xr

from stickslip import cf
from stickslip.brake import BrakeParams, growth_rates, travelling_wave
from stickslip.brake.fem import classify_fem, integrate_fem, steady_state
from stickslip.brake.ring import classify as classify_ring, integrate
from stickslip.cli import run
from stickslip.friction import Coulomb
from stickslip.halfspace import direct_problem, inverse_problem, wave_from_inverse
from stickslip.oscillator import Oscillator, continue_cycle, limit_cycle, simulate
from stickslip.sweep import run_sweep

from .cf_rules import compliance_errors, file_problems, problems
from .fuzz_harness import DAMPER_FILE, SYSTEM_FILE, example_config

CASE = BrakeParams.from_physical(50.0, 1e-4, 0.7)


def _good() -> xr.Dataset:
    ds = xr.Dataset({"x": ("t", np.arange(3.0), {"units": "m", "long_name": "position"}),
                     "state": ("t", np.array([0, 1, 0], np.int8), {"long_name": "state", "flag_values": np.array(
                         [0, 1], np.int8), "flag_meanings": "stick slip"})},
                    coords={"t": ("t", [0.0, 1.0, 2.0], {"units": "s", "long_name": "time"})})
    return cf.finish(ds, "a test", "oscillator")


@pytest.mark.parametrize("break_it, says", [
    (lambda ds: ds.attrs.pop("Conventions"), "Conventions"),
    (lambda ds: ds.attrs.pop("history"), "history"),
    (lambda ds: ds.attrs.update(source="someone"), "version"),
    (lambda ds: ds["x"].attrs.update(units="R"), "UDUNITS"),
    (lambda ds: ds["x"].attrs.pop("long_name"), "long_name"),
    (lambda ds: ds.attrs.update(codes="{'a': 1, 'b': 2}"), "repr"),
    (lambda ds: ds["state"].attrs.pop("flag_values"), "codes without"),
])
def test_the_checker_finds_each_broken_rule(break_it, says):
    ds = _good()
    assert problems(ds) == []
    break_it(ds)
    assert any(says in p for p in problems(ds)), problems(ds)


def test_the_checker_finds_repeated_times_float_codes_and_a_missed_index():
    t = np.array([0.0, 1.0, 1.0, 2.0])
    ds = xr.Dataset({"x": ("t", t, {"units": "m", "long_name": "x"})}, coords={"t": ("t", t, {"units": "s",
                                                                                            "long_name": "time"})})
    ds.attrs.update(Conventions="CF-1.10", title="t", history="h", source=cf.SOURCE)
    assert any("repeats" in p for p in problems(ds))
    ds = xr.Dataset({"regime": ("p", [0.0, 1.0], {"long_name": "r", "flag_values": [0, 1], "flag_meanings": "a b"})},
                    coords={"p": ("p", [0, 1], {"units": "1", "long_name": "p"})},
                    attrs=dict(Conventions="CF-1.10", title="t", history="h", source=cf.SOURCE))
    assert any("holds codes but is float64" in p for p in problems(ds))
    ds = xr.Dataset({"x": ("sample", [1.0, 2.0], {"units": "m", "long_name": "x"})},
                    coords={"time": ("sample", [0.0, 1.0], {"units": "s", "long_name": "t"})},
                    attrs=dict(Conventions="CF-1.10", title="t", history="h", source=cf.SOURCE))
    assert any("no index" in p for p in problems(ds))
    assert problems(cf.finish(ds, "t")) == []  # finish makes the monotone coordinate the index


@pytest.mark.parametrize("t", [[0.0, 1.0, 1.0, 2.0], [3.0, 2.0, 2.0, 1.0], [0.0, 0.0]], ids=["up", "down", "flat"])
def test_a_coordinate_with_a_repeated_value_is_not_made_an_index(t):
    """Issue 44: CF 1.10 (section 1.3) wants a coordinate variable strictly monotone: a time that
    repeats a value (two switches at one instant) stays an auxiliary coordinate of its dimension,
    never its index (which the checker would find repeating)."""
    ds = xr.Dataset({"x": ("sample", np.arange(len(t), dtype=float), {"units": "m", "long_name": "x"})},
                    coords={"time": ("sample", np.array(t), {"units": "s", "long_name": "time"})})
    out = cf.finish(ds, "t")
    assert out["time"].dims == ("sample",) and "sample" in out.dims and "time" not in out.indexes
    assert problems(out) == []


def test_finish_scales_units_and_codes():
    ds = xr.Dataset({"U": ("theta", [1.0, 2.0], {"units": "R", "long_name": "radial displacement"}),
                     "regime": ((), np.float64(np.nan), {"flag_values": [0, 1], "flag_meanings": "a b"})},
                    coords={"theta": ("theta", [0.0, 1.0])})
    out = cf.finish(ds, "t", "brake", params={"flag": True, "nested": {"a": 1.0}})
    assert out["U"].attrs["units"] == "1" and out["U"].attrs["scale"] == "R"
    assert out["regime"].dtype == np.int8 and int(out["regime"]) == -1 and out["regime"].attrs["flag_meanings"] == "none a b"
    assert out.attrs["flag"] == 1 and out.attrs["nested_a"] == 1.0 and out["theta"].attrs["units"] == "rad"
    assert cf.is_udunits("N s/m") and cf.is_udunits("m s-1") and not cf.is_udunits("E R^2 / M")



def test_a_missing_code_never_takes_a_code_that_means_something():
    # a contact mode uses -1 for reverse slip: a padded sample (NaN) must not become reverse slip
    mode = ("sample", [1.0, -1.0, np.nan], {"flag_values": [-1, 0, 1], "flag_meanings": "reverse_slip stick slip"})
    out = cf.finish(xr.Dataset({"mode": mode}), "t")["mode"]
    meanings = dict(zip(out.attrs["flag_values"].tolist(), out.attrs["flag_meanings"].split()))
    assert [meanings[int(c)] for c in out.values] == ["slip", "reverse_slip", "none"]
    # a code list that already has its own "none" keeps it
    kept = ("sample", [0.0, np.nan], {"flag_values": [-2, 0], "flag_meanings": "none stick"})
    out = cf.finish(xr.Dataset({"mode": kept}), "t")["mode"]
    assert out.values.tolist() == [0, -2] and out.attrs["flag_meanings"] == "none stick"

def _results():
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.6, 0.4), damping=0.05)
    yield "simulate", simulate(osc, 20.0).to_xarray(501)
    yield "limit_cycle", limit_cycle(osc).to_xarray(201)
    yield "continue_cycle", continue_cycle(osc, 0.25).to_xarray()
    yield "growth_rates", growth_rates(CASE).to_xarray()
    yield "coefficients", CASE.coefficients().to_xarray()
    yield "steady", CASE.steady().to_xarray(11)
    yield "travelling_wave", travelling_wave(CASE, 8).to_xarray(201)
    ring = integrate(CASE, 32, transits=2.0)
    yield "ring run", ring.to_xarray()
    yield "ring regime", classify_ring(ring, transits=1.0).to_xarray()
    fem = integrate_fem(CASE, 16, 1, transits=2.0)
    yield "fem run", fem.to_xarray()
    yield "fem regime", classify_fem(fem, transits=1.0).to_xarray()
    yield "fem steady", steady_state(CASE, n_theta=16, n_r=1).to_xarray()
    yield "inverse", inverse_problem(np.array([2.0, 3.0]), np.array([-0.7, -0.7]), 0.001, nu=0.25, mu=0.5).to_xarray()
    yield "direct", direct_problem(9.52e-4, 3.514e-3, 0.001, nu=0.25, mu=0.5).to_xarray()
    yield "fields", wave_from_inverse(11.358, -0.7, 0.001, nu=0.25, mu=0.5).fields(n=101).to_xarray()
    from stickslip.system import Contact, System, simulate as system_simulate

    system = System(np.eye(2), [[2.0, -1.0], [-1.0, 1.0]], [Contact([1.0, 0.0], 1.0, Coulomb(0.6, 0.4), 0.2)])
    yield "system run", system_simulate(system, t_end=5.0, samples=51).to_xarray()
    from stickslip.system import limit_cycle as system_cycle

    yield "system cycle", system_cycle(system, transient=40.0).to_xarray()
    from stickslip.system import steady_sliding

    yield "system steady sliding", steady_sliding(system).to_xarray()


def test_every_result_dataset_follows_the_rules():
    bad = [p for name, ds in _results() for p in problems(ds, name)]
    assert bad == []


def _point(friction, mismatch):
    return {"sum": friction + mismatch, "kind": float(friction > mismatch)}


def test_a_sweep_store_follows_the_rules_and_is_consolidated(tmp_path):
    store = tmp_path / "s.zarr"
    run_sweep(_point, {"friction": [1.0, 2.0], "mismatch": [1.5]}, store, outputs={"sum": "m", "kind": {"low": 0,
              "high": 1}}, scheduler="synchronous", attrs={"omega": 50.0, "material": {"young": 2e11}}, model="brake")
    assert file_problems(store) == []
    with xr.open_zarr(store, consolidated=True) as ds:
        assert ds["kind"].dtype == np.int8 and list(ds["kind"].values.ravel()) == [0, 1]
        assert ds.attrs["material_young"] == 2e11


OSC = ["--mass", "1", "--stiffness", "1", "--normal-force", "1", "--belt-speed", "0.2", "--fs", "0.6", "--fd", "0.4"]
BRAKE = ["--omega", "50", "--mismatch", "1e-4", "--friction", "0.7"]
#: Every command that writes a file, with the files it writes.
WRITERS = [
    (["oscillator", "simulate", *OSC, "--t-end", "5", "--out", "{tmp}/s.nc"], ["s.nc"]),
    (["oscillator", "cycle", *OSC, "--out", "{tmp}/c.nc"], ["c.nc"]),
    (["oscillator", "continue", *OSC, "--stop", "0.3", "--out", "{tmp}/b.nc"], ["b.nc"]),
    (["oscillator", "map", *OSC[:6], *OSC[8:], "--x", "belt_speed=0.2:0.3:2", "--y", "damping=0.01:0.02:2", "--out", "{tmp}/m.zarr",
      "--workers", "1"], ["m.zarr"]),
    (["brake", "integrate", *BRAKE, "--nodes", "32", "--transits", "1", "--out", "{tmp}/i.nc"], ["i.nc"]),
    (["brake", "wave", *BRAKE, "--wave-number", "8", "--out", "{tmp}/w.nc"], ["w.nc"]),
    (["brake", "spectrum", "--omega", "100", "--mismatch", "1e-4", "--friction", "0.2", "--nodes", "32",
      "--out", "{tmp}/sp.nc"], ["sp.nc"]),
    (["brake", "continue", "--omega", "50", "--mismatch", "1e-5", "--friction", "0.7", "--wave-number", "4", "--stop",
      "9e-6", "--points", "3", "--out", "{tmp}/bc.nc"], ["bc.nc"]),
    (["brake", "map", "--out", "{tmp}/wm.zarr", "--x", "friction=0.2:0.7:2", "--y", "mismatch=1e-5:1e-4:2:log",
      "--workers", "1"], ["wm.zarr"]),
    (["brake", "fem", *BRAKE, "--n-theta", "16", "--n-r", "1", "--transits", "1", "--out", "{tmp}/f.nc",
      "--xdmf", "{tmp}/f.xdmf"], ["f.nc"]),
    (["halfspace", "fields", "--b", "11.358", "--c", "-0.7", "--v-star", "0.001", "--points", "101", "--out",
      "{tmp}/h.nc"], ["h.nc"]),
    (["halfspace", "run", "--elements", "32", "--duration", "2", "--out", "{tmp}/hr.nc"], ["hr.nc"]),
    (["fem", "steady", "{config}", "--out", "{tmp}/fs.nc"], ["fs.nc"]),
    (["fem", "cea", "{config}", "--out", "{tmp}/fc.nc"], ["fc.nc"]),
    (["fem", "run", "{config}", "--transits", "2", "--out", "{tmp}/fr.nc"], ["fr.nc"]),
    (["system", "simulate", SYSTEM_FILE, "--t-end", "5", "--out", "{tmp}/ys.nc"], ["ys.nc"]),
    (["system", "cycle", SYSTEM_FILE, "--transient", "30", "--out", "{tmp}/yc.nc"], ["yc.nc"]),
    (["system", "stability", SYSTEM_FILE, "--out", "{tmp}/yt.nc"], ["yt.nc"]),
    (["system", "continue", SYSTEM_FILE, "--parameter", "contact[0].surface_speed", "--stop", "0.25", "--points", "3",
      "--transient", "30", "--out", "{tmp}/yb.nc"], ["yb.nc"]),
    (["system", "cycle", DAMPER_FILE, "--transient", "30", "--out", "{tmp}/yf.nc"], ["yf.nc"]),
    (["system", "continue", DAMPER_FILE, "--parameter", "harmonic[0].frequency", "--stop", "0.9", "--points", "3",
      "--transient", "30", "--out", "{tmp}/yr.nc"], ["yr.nc"]),
    (["rsf", "slide", "--a", "0.01", "--b", "0.015", "--dc", "1e-5", "--normal-stress", "1e7", "--stiffness", "1e10",
      "--t-end", "30", "--history", "0:1e-6,10:1e-5", "--out", "{tmp}/rs.nc"], ["rs.nc"]),
]


def _leaves(data: dict, prefix: str = ""):
    """The dotted keys of a JSON result (a list of records counts its records' keys)."""
    for key, value in data.items():
        path = f"{prefix}{key}"
        if isinstance(value, dict):
            yield from _leaves(value, path + ".")
        elif isinstance(value, list) and value and all(isinstance(x, dict) for x in value):
            yield from {f"{path}.{k}" for x in value for k in x}
        else:
            yield path


#: Every other writer in `make test` (a second each: a command and the compliance checker), all in the slow set.
_WRITERS = [pytest.param(a, f, id=" ".join(a[:2]), marks=[pytest.mark.slow] if k % 2 else [])
            for k, (a, f) in enumerate(WRITERS)]


@pytest.mark.parametrize("args, files", _WRITERS)
def test_every_file_the_command_line_writes_follows_the_rules(args, files, tmp_path, capsys):
    """Our own rules (cf_rules), compliance-checker's CF 1.10 (high and medium priority: none),
    and units and a meaning for every key of the command's JSON."""
    args = [example_config() if a == "{config}" else a.replace("{tmp}", str(tmp_path)) for a in args]
    assert run(args + ["--json"]) == 0, capsys.readouterr().err
    result = json.loads(capsys.readouterr().out)
    units = result.pop("units")
    assert sorted(k for k in set(_leaves(result)) if k not in units) == []
    assert all(u["long_name"] for u in units.values())
    bad = [p for name in files for p in file_problems(tmp_path / name)]
    bad += [p for name in files if name.endswith(".nc") for p in compliance_errors(tmp_path / name)]
    assert bad == []
    for name in files:
        if name.endswith(".nc"):
            with xr.open_dataset(tmp_path / name) as ds:
                assert "stickslip" in ds.attrs["history"].splitlines()[-1]
