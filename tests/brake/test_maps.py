"""Regime maps of the brake over friction and mismatch (resumable sweeps of waves and ring runs)."""

from stickslip.brake.maps import REGIME_CODES, regime_code, ring_regime_map, wave_regime_map


def test_codes():
    assert regime_code("stick-slip") == 1 and regime_code("slip-separation") == REGIME_CODES["other"]


def test_maps_follow_the_paper_trends(tmp_path):
    f, d = [0.2, 2.0], [1e-7, 1e-4]
    w = wave_regime_map(f, d, tmp_path / "w.zarr", scheduler="synchronous")
    r = ring_regime_map(f, d, tmp_path / "r.zarr", scheduler="synchronous", transits=60.0, nodes=64)
    assert w.wave_regime.sel(friction=0.2, mismatch=1e-4) == REGIME_CODES["stick-slip"]
    assert r.ring_regime.sel(friction=0.2, mismatch=1e-4) == REGIME_CODES["stick-slip"]
    sep = [REGIME_CODES["stick-slip-separation"], REGIME_CODES["stick-slip-separation-reverse-slip"]]
    assert int(w.wave_regime.sel(friction=2.0, mismatch=1e-7)) in sep
