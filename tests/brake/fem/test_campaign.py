"""The FE campaign (statistics over unseeded starts): a run driven to stationarity, the sweep
resumes and refuses another campaign's store, and the command validates its options."""

import numpy as np
import pytest

from stickslip.brake import BrakeParams
from stickslip.brake.fem import classify_fem, integrate_fem, perturbed_steady
from stickslip.brake.fem.campaign import OUTCOMES, geometry_mesh, limit_regime, statistics
from stickslip.brake.fem.scheme import FemScheme
from stickslip.cli import run as cli_run
from stickslip.contact import REGIME_CODES
from stickslip.contact.runs import held_transits
from stickslip.errors import ParameterError

CASE1 = (0.2, 4e-4, 1.0)  # section 3.1 case 1: settles quickly on a stationary stick-slip wave


@pytest.mark.slow  # 8 to 14 s: the fast set's margin to its 4 minutes (issue 47)
def test_a_run_stops_when_stationary_and_is_the_same_as_one_run_straight_through(tmp_path):
    p = BrakeParams.from_physical(CASE1[2], CASE1[1], CASE1[0])
    out = limit_regime(p, 256, 16, seed=0, min_transits=100.0, chunk=20.0, max_transits=200.0,
                       checkpoint=tmp_path / "run.nc")
    assert set(out) == set(OUTCOMES) and out["stationary"] == 1.0 and out["transits"] < 200
    assert out["regime"] == REGIME_CODES["stick-slip"] and out["n_zones"] >= 1
    # the chunks, resumed from the checkpoint, are the run integrated straight to the same length
    straight = classify_fem(integrate_fem(p, 256, 16, transits=out["transits"],
                                          initial=perturbed_steady(FemScheme(p, 256, 16), seed=0)))
    assert straight.n_zones == out["n_zones"] and straight.residual == pytest.approx(out["residual"], rel=1e-12)


def test_statistics_sweep_resumes_and_refuses_another_campaign(tmp_path):
    store = tmp_path / "s.zarr"
    budget = ({"min_transits": 20.0, "chunk": 10.0, "max_transits": 30.0},)
    ds = statistics(store, [CASE1], meshes=((32, 2),), seeds=2, budgets=budget, scheduler="synchronous")
    assert ds["done"].all() and ds["regime"].dims == ("case", "mesh", "seed")
    assert np.all(np.isfinite(ds["n_zones"].values)) and list(ds.attrs["mesh_n_theta"]) == [32]
    assert not (tmp_path / "s.runs").exists() or not any((tmp_path / "s.runs").iterdir())  # checkpoints removed
    again = statistics(store, [CASE1], meshes=((32, 2),), seeds=2, budgets=budget, scheduler="synchronous")
    assert np.array_equal(again["regime"].values, ds["regime"].values)
    with pytest.raises(ParameterError) as err:
        statistics(store, [(0.3, 4e-4, 1.0)], meshes=((32, 2),), seeds=2, budgets=budget, scheduler="synchronous")
    assert err.value.name == "store"


def test_geometry_meshes_keep_the_radial_spacing():
    assert geometry_mesh(1.5) == (256, 16) and geometry_mesh(3.0) == (256, 64) and geometry_mesh(1.25) == (256, 8)


@pytest.mark.parametrize("args, option", [(["--part", "both"], "--part"), (["--seeds", "0"], "--seeds"),
                                           (["--geometry-seeds", "-1"], "--geometry-seeds"),
                                           (["--workers", "0"], "--workers")])
def test_campaign_command_rejects_bad_options(args, option, tmp_path, capsys):
    code = cli_run(["brake", "campaign", "--out", str(tmp_path / "c"), *args])
    err = capsys.readouterr().err
    assert code == 2 and option in err and len(err.strip().splitlines()) == 1


@pytest.mark.parametrize("killed_at", [20.0, 17.0])  # at the end of a lengthening step, and within one
def test_a_run_killed_past_its_first_length_resumes_to_the_same_outcome(tmp_path, killed_at):
    # found by the geometry campaign: a checkpoint longer than min_transits was refused on resume
    p = BrakeParams.from_physical(CASE1[2], CASE1[1], CASE1[0])
    budget = {"min_transits": 10.0, "chunk": 5.0, "max_transits": 30.0}
    straight = limit_regime(p, 32, 2, seed=0, **budget)
    assert straight["stationary"] == 0.0  # lengthened to the end: the kill below falls within the schedule
    path = tmp_path / "run.nc"
    integrate_fem(p, 32, 2, transits=killed_at, initial=perturbed_steady(FemScheme(p, 32, 2), 1e-3, seed=0),
                  beta2=0.9, tail=2.0, checkpoint=path)
    assert killed_at - 0.1 < held_transits(path) < killed_at  # a run of T ends within a sample past T
    out = limit_regime(p, 32, 2, seed=0, checkpoint=path, **budget)
    assert out["transits"] == straight["transits"] and out["n_zones"] == straight["n_zones"]
    assert out["residual"] == pytest.approx(straight["residual"], rel=1e-12)
