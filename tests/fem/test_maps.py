"""Stability maps over the friction and one more number of a config (`stickslip.fem.maps`, issue 45).

* The full-CEA map of a pad on a block (3-D, linear tetrahedra, matching interface) over the block's
  Young's modulus: each row's onset friction equals the critical friction of the pencil assembled
  independently in `test_solid_pair` (constant-strain tetrahedra written out, node-to-node contact),
  found there by bisection of its dense eigenvalues. Threshold, set before the run: 2e-3 (the
  multisection stops within 1e-2 of the friction step of 0.1).
* The reduced map with a complete basis equals the full map with penalty contact (a consistency
  check of the two paths: 2e-3, the same bracket).
* A store of another map is refused; `stickslip fem map` prints the onsets and draws the map.
"""

import json
import math

import numpy as np
import pytest
import scipy.linalg as la

from stickslip.cli import run
from stickslip.errors import ParameterError
from stickslip.fem import Material
from stickslip.fem.config import load_config
from stickslip.fem.critical import NEUTRAL
from stickslip.fem.maps import stability_map

from . import test_solid_pair
from .test_solid import box
from .test_solid_config import to_msh

L, H, T = test_solid_pair.L, test_solid_pair.H, test_solid_pair.T
GAP = 2e-7  # the pad's interference [m]
YOUNGS = [1.5e11, 2.1e11]

CONFIG = """
dimension = 3
units = "m"
mesh = "pad.msh"
clamped = ["z1"]

[material]
young = 5e9
poisson = 0.25
density = 2500.0

[contact]
group = "z0"
friction = 0.5

[partner]
mesh = "block.msh"
group = "z1"
clamped = ["z0"]
velocity = [1.0, 0.0]
[partner.material]
young = 2.1e11
poisson = 0.3
density = 7850.0

[cea]
band = [0.0, 60000.0]
count = 20
{cea}
"""


@pytest.fixture()
def config(tmp_path):
    pad = box((L, L, T), (2, 2, 1))
    pad.points[:, 2] += H - GAP
    to_msh(pad, tmp_path / "pad.msh")
    to_msh(box((L, L, H), (2, 2, 2)), tmp_path / "block.msh")

    def write(cea=""):
        (tmp_path / "pair.toml").write_text(CONFIG.format(cea=cea))
        return tmp_path / "pair.toml"

    return write


def _critical(young, monkeypatch):
    """The independent pencil's critical friction, by bisection of its dense eigenvalues."""
    monkeypatch.setattr(test_solid_pair, "STEEL", Material(young, 0.3, 7850.0))
    cfg_pad = test_solid_pair.solid_from_meshio(test_solid_pair.solid_mesh((2, 2, 1), "tetra", T, lift=H - GAP),
                                                "pad", units="m")
    base = test_solid_pair.solid_from_meshio(test_solid_pair.solid_mesh((2, 2, 2), "tetra", H), "block", units="m")

    def grows(f):
        Kr, Mr, _ = test_solid_pair.independent_pencil(cfg_pad, base, f, GAP)
        s = np.sqrt(-la.eigvals(Kr, Mr).astype(complex))
        s = np.where(s.imag < 0, -s, s)
        s = s[s.imag / (2 * math.pi) <= 60e3]
        return bool(np.any(s.real > NEUTRAL * np.abs(s)))

    lo, hi = 0.0, 1.0
    assert not grows(lo) and grows(hi)
    while hi - lo > 1e-7:
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if grows(mid) else (mid, hi)
    return 0.5 * (lo + hi)


def test_the_full_map_s_onsets_are_theindependent_pencil_s_critical_frictions(config, tmp_path, monkeypatch):
    ds = stability_map(config(), "partner.material.young", YOUNGS, np.linspace(0.0, 1.0, 11), tmp_path / "m.zarr",
                       workers=1)
    exact = [_critical(young, monkeypatch) for young in YOUNGS]
    assert abs(exact[1] - exact[0]) > 1e-2  # the block's modulus moves the onset: the rows are not one row
    for onset, want in zip(ds["onset"].values, exact):
        assert onset == pytest.approx(want, abs=2e-3)
    assert np.all(ds["unstable_modes"].values[:, 0] == 0) and np.all(ds["unstable_modes"].values[:, -1] > 0)
    with pytest.raises(ParameterError, match="store"):  # another map's store
        stability_map(config(), "partner.material.young", YOUNGS, np.linspace(0.0, 1.0, 6), tmp_path / "m.zarr",
                      workers=1)


@pytest.mark.slow
def test_the_reduced_map_with_a_complete_basis_is_the_full_map_with_penalty_contact(config, tmp_path):
    frictions = np.linspace(0.0, 1.0, 11)
    full = stability_map(config('contact_model = "penalty"'), "partner.material.young", YOUNGS, frictions,
                         tmp_path / "full.zarr", workers=1)
    free = int(np.sum(~load_config(config()).problem().fixed))
    reduced = stability_map(config(f'reduced_modes = {free - 2}\naugment = "none"'), "partner.material.young", YOUNGS,
                            frictions, tmp_path / "reduced.zarr", workers=1)
    assert np.all(np.isfinite(full["onset"].values))
    assert np.allclose(reduced["onset"].values, full["onset"].values, atol=2e-3)


def test_fem_map_prints_the_onsets_and_draws_the_map(config, tmp_path, capsys):
    path = config("reduced_modes = 40")  # (the reduced CEA: seconds)
    args = ["fem", "map", str(path), "--over", "partner.material.young=1.5e11:2.1e11:2", "--friction", "0:1:6",
            "--store", str(tmp_path / "c.zarr"), "--workers", "1"]
    assert run([*args, "--plot", str(tmp_path / "map.png"), "--out", str(tmp_path / "map.nc"), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["swept_key"] == "partner.material.young" and len(data["onsets"]) == 2
    assert (tmp_path / "map.png").stat().st_size > 0 and (tmp_path / "map.nc").exists()
    assert run(["fem", "map", str(path), "--over", "friction=0:1:3", "--friction", "0:1:6", "--store",
                str(tmp_path / "d.zarr")]) == 2
    assert "other than contact.friction" in capsys.readouterr().err
