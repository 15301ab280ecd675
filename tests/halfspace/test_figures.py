"""Figure 14 and the maps: data, checks and plots (quick mode)."""

import pytest

from stickslip.halfspace import figures as F


@pytest.fixture(scope="module")
def fig14():
    return F.figure14_data(quick=True)


def test_figure14_checks_pass(fig14):
    rows = F.check_figure14(fig14)
    assert len(rows) >= 10
    for name, passed, measured, expected, detail in rows:
        assert isinstance(passed, bool) and isinstance(name, str)
        assert passed, (name, measured, expected, detail)


def test_figure14_b_follows_from_the_loading(fig14):
    a = fig14.attrs
    assert a["T"] == pytest.approx((0.5 - 0.4) * 2 * 1e-3 / (0.7 * 0.3), rel=1e-14)
    assert a["b"] == pytest.approx(11.358175, rel=1e-6)
    assert fig14.Sigma_yy.attrs["units"] == "1"


def test_figure14_plot(fig14, tmp_path):
    path = tmp_path / "fig14.png"
    F.plot_figure14(fig14, path)
    assert path.stat().st_size > 10_000


@pytest.mark.parametrize("name", ["inverse_map", "direct_map"])
def test_maps(name, tmp_path):
    ds = getattr(F, f"{name}_data")(True)
    for row in getattr(F, f"check_{name}")(ds):
        assert row[1], row
    path = tmp_path / f"{name}.png"
    getattr(F, f"plot_{name}")(ds, path)
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
    F.plot_fields(ds, tmp_path / "fields.png")
    assert (tmp_path / "fields.png").stat().st_size > 10_000
