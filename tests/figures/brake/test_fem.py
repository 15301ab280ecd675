"""Figure data, checks and plots of the FE runs (Figures 7-10, regime map)."""

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.figures import Check
from stickslip.figures.brake import fem_cases, fem_regimes, fig7, fig8, fig9, fig10
from stickslip.figures.brake.fem_cases import common_checks

from ..helpers import assert_png


@pytest.fixture(scope="module")
def small():
    """Case 2 on a small mesh: the plumbing of data, checks and plots (not the paper's claims)."""
    return fem_cases.case_data(1, (None, 8), mesh=(128, 8, 40))


def test_case_dataset_has_runs_units_and_residuals(small):
    ds = small
    assert list(ds["run"].values) == ["noise", "mode 8"] and ds.sizes["theta"] == 128
    assert ds["U"].dims == ("run", "snapshot", "theta") and ds["energy"].dims == ("run", "transit")
    assert ds["P"].attrs["units"] == "p_e" and ds["growth"].attrs["units"] == "1/transit"
    assert ds.attrs["paper_regime"] == "stick-slip-separation" and ds.attrs["paper_modes"] == 8
    assert ds.attrs["kappa"] == pytest.approx(1.0344, rel=1e-3)
    assert np.allclose(ds["fraction"].sum("kind"), 1.0) and np.all(ds["seconds"] > 0)
    assert np.all(ds["energy"].isel(transit=-1) > 10 * ds["energy"].isel(transit=0))  # the flutter grew


def test_common_checks_pass_and_every_check_reports_numbers(small):
    common = common_checks(small)
    assert [c.passed for c in common] == [True, True, True], common
    for check in (fig9.check, fig10.check):
        out = check(small)
        assert all(isinstance(c, Check) and c.measured and c.expected for c in out)


def test_plots_are_written(small, tmp_path):
    for i, module in enumerate((fig7, fig8, fig9, fig10)):
        path = tmp_path / f"fig{i}.png"
        assert_png(module.plot, small, path)
        assert path.stat().st_size > 10_000


def test_case_data_rejects_bad_case():
    with pytest.raises(ParameterError) as err:
        fem_cases.case_data(3)
    assert err.value.name == "case"


@pytest.mark.slow
def test_fig7_quick_reaches_the_four_mode_wave_from_a_mode_4_seed(tmp_path):
    ds = fig7.compute(quick=True)
    checks = {c.name: c for c in fig7.check(ds)}
    assert all(c.passed for c in checks.values()), [c for c in checks.values() if not c.passed]
    assert_png(fig7.plot, ds, tmp_path / "fig7.png")


@pytest.mark.slow
def test_fig9_quick_obeys_the_contact_laws_on_recomputed_reactions():
    ds = fig9.compute(quick=True)
    checks = fig9.check(ds) + fig10.check(ds)
    by_name = {c.name: c.passed for c in checks}
    assert by_name["the pressure recomputed from the motion is >= 0 and vanishes where the ring separates"]
    assert by_name["the reactions the equations of motion need are the kernel's, and obey Signorini and Coulomb"]


@pytest.mark.slow
def test_regime_map_quick(tmp_path):
    ds = fem_regimes.compute(quick=True)
    assert all(c.passed for c in fem_regimes.check(ds))
    assert_png(fem_regimes.plot, ds, tmp_path / "map.png")


def _seeded(ds, mode, regime):
    """The small dataset relabelled as the runs of a figure seeded with ``mode``, its seeded run
    set to pass that figure's claim (the checks read only the data)."""
    ds = ds.assign_coords(run=["noise", f"mode {mode}"])
    return ds.assign(regime=ds["regime"].copy(data=["stick-slip", regime]),
                     n_zones=ds["n_zones"].copy(data=[3.0, float(mode)]), stationary=ds["stationary"] * 0 + 1)


def _fig7(ds):
    ds = _seeded(ds, 4, "stick-slip")
    return ds.assign(c_over_cp=ds["c_over_cp"] * 0 + np.sign(float(ds["flutter_speed"].sel(mode=4))) * 0.3)


def _fig8(ds):
    return _seeded(ds, 2, "stick-separation")


def _fig9(ds):
    return _seeded(ds, 8, "stick-slip-separation")


def _same(ds):
    return ds


# (label, a dataset the named check passes on, the corruption, the figure's check, part of the
# check's name): the corruption must make that check fail. The checks compare with something
# outside the corrupted field, so they are able to reject wrong data.
CORRUPTIONS = [
    ("lame", _same, lambda ds: ds.assign_attrs(lame_error_p=2e-3), common_checks, "Lamé"),
    ("negative pressure", _same, lambda ds: ds.assign(negative_pressure=ds["negative_pressure"] + 1e-6),
     common_checks, "Signorini and Coulomb"),
    ("reaction is not the kernel's", _same, lambda ds: ds.assign(kernel=ds["kernel"] + 1e-6), common_checks,
     "Signorini and Coulomb"),
    ("coulomb", _same, lambda ds: ds.assign(coulomb=ds["coulomb"] + 1e-6), common_checks, "Signorini and Coulomb"),
    ("penetration", _same, lambda ds: ds.assign(penetration=ds["penetration"] + 1e-9), common_checks,
     "Signorini and Coulomb"),
    ("creeping stick", _same, lambda ds: ds.assign(stick_motion=ds["stick_motion"] + 1e-6), common_checks,
     "Signorini and Coulomb"),
    ("wrong slip direction", _same, lambda ds: ds.assign(slip_direction=ds["slip_direction"] + 1), common_checks,
     "Signorini and Coulomb"),
    ("never sticks", _same, lambda ds: ds.assign(stick_count=ds["stick_count"] * 0), common_checks,
     "Signorini and Coulomb"),
    ("stable sliding", _same, lambda ds: ds.assign(fraction=ds["fraction"].where(ds["kind"] != "stick", 0.0)),
     common_checks, "unstable"),
    ("fig10 complementarity", _same, lambda ds: ds.assign(complementarity=ds["complementarity"] + 1e-6),
     fig10.check, "vanishes where the ring separates"),
    ("fig10 mean pressure", _same, lambda ds: ds.assign(p_mean_over_pe=ds["p_mean_over_pe"] * 1.1), fig10.check,
     "mean contact pressure"),
    ("fig9 other regime", _fig9, lambda ds: ds.assign(regime=ds["regime"].copy(data=["stick-slip"] * 2)),
     fig9.check, "8-mode"),
    ("fig9 other mode", _fig9, lambda ds: ds.assign(n_zones=ds["n_zones"] - 1), fig9.check, "8-mode"),
    ("fig9 not stationary", _fig9, lambda ds: ds.assign(stationary=ds["stationary"] * 0), fig9.check, "8-mode"),
    ("fig9 no wave at all", _fig9, lambda ds: ds.assign(n_zones=ds["n_zones"] * np.nan), fig9.check, "8-mode"),
    ("fig9 standing pattern", _same, lambda ds: ds.assign(c_P_over_cp=ds["c_P_over_cp"] * 0.01), fig9.check,
     "propagates"),
    ("fig7 other mode", _fig7, lambda ds: ds.assign(n_zones=ds["n_zones"] - 1), fig7.check, "limit regime"),
    ("fig7 not stationary", _fig7, lambda ds: ds.assign(stationary=ds["stationary"] * 0), fig7.check,
     "limit regime"),
    ("fig7 wrong direction", _fig7, lambda ds: ds.assign(c_over_cp=-ds["c_over_cp"]), fig7.check, "direction"),
    ("fig8 other regime", _fig8, lambda ds: ds.assign(regime=ds["regime"].copy(data=["stick-slip"] * 2)),
     fig8.check, "stick-separation wave"),
]


@pytest.mark.parametrize("label, base, corrupt, check, name", CORRUPTIONS, ids=[c[0] for c in CORRUPTIONS])
def test_every_fem_check_rejects_corrupted_data(small, label, base, corrupt, check, name):
    before = {c.name: c.passed for c in check(base(small)) if name in c.name}
    after = {c.name: c.passed for c in check(corrupt(base(small))) if name in c.name}
    assert len(before) == 1 and all(before.values()), f"{label}: the uncorrupted data must pass {before}"
    assert not any(after.values()), f"{label}: the corrupted data passed {after}"


def test_fig8_ill_posedness_check_rejects_a_well_posed_case(small):
    """Case 2 (f = 0.7 < 1) is well posed: its growth rates do not grow like the wavenumber."""
    assert not {c.name: c.passed for c in fig8.check(_fig8(small))}[
        "f = 2 > 1: steady sliding is ill-posed (growth proportional to the wavenumber)"]
