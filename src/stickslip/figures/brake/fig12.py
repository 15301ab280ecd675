"""Figure 12: a travelling wave of mode 8 with reverse slip (overshoot)."""

from __future__ import annotations

import lazy_loader as lazy
from matplotlib.figure import Figure

from ...brake import BrakeParams, classify, integrate, travelling_wave
from ...brake.ring import initial_from_wave
from .. import Check, FigureSpec
from .paper import FIG12
from .wave_cases import METHOD, common_checks, phase_plot, waves_dataset

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it


def compute(quick: bool = False) -> xr.Dataset:
    """A mode-8 wave with reverse slip (overshoot): phase plane ``(V, V')``."""
    ds = waves_dataset(FIG12, "stick-slip-separation-reverse-slip", quick, samples=(1000, 4000))
    # an independent solver: the ring integration [12] started on the wave, its own contact laws
    p = BrakeParams.from_physical(FIG12["omega"], FIG12["mismatch"], FIG12["friction"])
    nodes = 256 if quick else 512
    wave = travelling_wave(p, FIG12["modes"], regime="stick-slip-separation-reverse-slip")
    ring = classify(integrate(p, nodes, transits=RING_TRANSITS, beta2=0.5, initial=initial_from_wave(wave, nodes)))
    return ds.assign(ring_regime=((), ring.regime), ring_n_fft=((), ring.n_fft), ring_c=((), ring.c),
                     ring_reverse_slip=((), ring.fractions["reverse_slip"], {"long_name": "reverse-slip fraction of "
                                        "the ring run (node-steps)"}),
                     ring_stationary=((), int(ring.stationary))).assign_attrs(ring_nodes=nodes)


#: Transits of the ring run started on the wave.
RING_TRANSITS = 10


def check(ds: xr.Dataset) -> list[Check]:
    w = ds["slip_velocity"].values
    c_err = abs(float(ds["ring_c"]) / float(ds["c"].values[0]) - 1)
    return common_checks(ds, "Fig. 12") + [
        Check("Fig. 12: reverse slip (overshoot) in the wave and in the ring integration started on it",
              bool("reverse-slip" in str(ds["ring_regime"].values) and float(ds["ring_reverse_slip"]) > 1e-3
                   and w.min() < 0),
              f"ring after {RING_TRANSITS} transits on {ds.attrs['ring_nodes']} nodes: {ds['ring_regime'].values}, "
              f"reverse slip {float(ds['ring_reverse_slip']):.3f} of node-steps; wave min(1 - V_t) = {w.min():.4g}",
              "a reverse-slip zone in the ring (> 1e-3 of node-steps), min(1 - V_t) < 0 in the wave",
              "the ring is an independent solver (time integration of [12] with its own contact laws)"),
        Check("Fig. 12: the ring keeps the mode-8 pattern and the wave's speed",
              bool(int(ds["ring_n_fft"]) == 8 and c_err < 5e-3),
              f"dominant Fourier mode {int(ds['ring_n_fft'])}, |c_ring/c_wave - 1| = {c_err:.1e}", "8, < 5e-3",
              "a wave that were not a solution of [12] would drift or break up"),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    return phase_plot(ds, fig, [("V", "dV", "V [R]", "V' = dV/dφ [R/rad]"),
                                ("phi", "slip_velocity", "φ [rad]", "1 − V̇ [1]")],
                      f"Fig. 12: mode-{ds.attrs['modes']} wave with reverse slip (1 − V̇ < 0: overshoot)")


FIGURE = FigureSpec(
    key="fig12", title="Figure 12 — mode-8 travelling wave with reverse slip (overshooting)",
    model="brake-like system, reduced model, travelling waves",
    claim="A traveling wave in mode 8 with reverse slip (overshooting), computed by multiple shooting.",
    method=METHOD + " Here f = 0.2, d = 10 µm, Ω = 100 rad/s, n = 8.",
)
