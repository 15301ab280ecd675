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
    return fem_cases.case_data(1, (None, 4), mesh=(128, 8, 40))


def test_case_dataset_has_runs_units_and_residuals(small):
    ds = small
    assert list(ds["run"].values) == ["noise", "mode 4"] and ds.sizes["theta"] == 128
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
    assert int(ds["n_zones"].sel(run="mode 4")) == 4 and int(ds["n_zones"].sel(run="noise")) == 3
    assert_png(fig7.plot, ds, tmp_path / "fig7.png")


@pytest.mark.slow
def test_fig9_quick_is_stick_slip_separation_with_zero_pressure_in_separation():
    ds = fig9.compute(quick=True)
    checks = fig9.check(ds) + fig10.check(ds)
    by_name = {c.name: c.passed for c in checks}
    assert by_name["stick-slip-separation from every initial condition (paper)"]
    assert by_name["the contact pressure vanishes exactly in the separation zones and is positive elsewhere"]
    assert not by_name["8 modes (paper)"]  # 5 waves on this mesh (see docs/theory/brake-fem.md)


@pytest.mark.slow
def test_regime_map_quick(tmp_path):
    ds = fem_regimes.compute(quick=True)
    assert all(c.passed for c in fem_regimes.check(ds))
    assert_png(fem_regimes.plot, ds, tmp_path / "map.png")
