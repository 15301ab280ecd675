"""Figure 14 and the maps: data, checks and plots (quick mode)."""

import pytest

from stickslip import plotting
from stickslip.figures.halfspace import direct_map, inverse_map
from stickslip.figures.halfspace import fig14 as fig14_module

from ..helpers import assert_png


@pytest.fixture(scope="module")
def fig14():
    return fig14_module.compute(quick=True)


def test_figure14_checks_pass(fig14):
    checks = fig14_module.check(fig14)
    assert len(checks) >= 10
    for c in checks:
        assert isinstance(c.passed, bool) and isinstance(c.name, str) and c.measured and c.expected
        assert c.passed, c


def test_figure14_b_follows_from_the_loading(fig14):
    a = fig14.attrs
    assert a["T"] == pytest.approx((0.5 - 0.4) * 2 * 1e-3 / (0.7 * 0.3), rel=1e-14)
    assert a["b"] == pytest.approx(11.358175, rel=1e-6)
    assert fig14.stress_yy.attrs["units"] == "1"


def test_figure14_plot(fig14, tmp_path):
    path = tmp_path / "fig14.png"
    assert_png(fig14_module.plot, fig14, path)
    assert path.stat().st_size > 10_000


@pytest.mark.parametrize("module", [inverse_map, direct_map])
def test_maps(module, tmp_path):
    ds = module.compute(True)
    for c in module.check(ds):
        assert c.passed, c
    name = module.FIGURE.key
    path = tmp_path / f"{name}.png"
    assert_png(module.plot, ds, path)
    assert path.stat().st_size > 10_000
    ds.to_netcdf(tmp_path / f"{name}.nc")


def test_datasets_write_to_netcdf(fig14, tmp_path):
    from stickslip.halfspace import direct_problem, inverse_problem, wave_from_inverse
    fig14.to_netcdf(tmp_path / "fig14.nc")
    wave_from_inverse(3.0, -0.5, 1e-3, nu=0.3, mu=0.5).fields(n=50).to_xarray().to_netcdf(tmp_path / "f.nc")
    inverse_problem([2.0, 3.0], -0.5, 1e-3, nu=0.3, mu=0.5).to_xarray().to_netcdf(tmp_path / "i.nc")
    inv = inverse_problem(3.0, -0.5, 1e-3, nu=0.3, mu=0.5)
    direct_problem(float(inv.T), float(inv.v), 1e-3, nu=0.3, mu=0.5).to_xarray().to_netcdf(tmp_path / "d.nc")


def test_plot_fields(tmp_path):
    from stickslip.halfspace import wave_from_inverse
    ds = wave_from_inverse(4.0, -0.6, 1e-3, nu=0.3, mu=0.5).fields(n=400).to_xarray()
    plotting.save(plotting.plot_interface_fields(ds), tmp_path / "fields.png")
    assert (tmp_path / "fields.png").stat().st_size > 10_000
