"""Travelling waves against the time integration of the ring, and their stability.

Two questions meet here:

* do the multiple-shooting waves (`stickslip.brake.waves`) and the time integration of
  [12] (`stickslip.brake.ring`) agree? The ring is started on a wave and must carry it unchanged
  (same regime, speed, zone fractions); and a run from perturbed steady sliding that
  settles on a stationary wave must match the wave of the same mode number;
* are the waves stable (an open question of the paper)? `wave_persistence` measures
  the growth of a small perturbation with an independent (Moreau-type) stepper.
"""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...brake import BrakeParams, classify, find_waves, integrate, perturbed_steady, travelling_wave, wave_persistence
from ...brake.ring import initial_from_wave
from .. import Check, FigureSpec
from .paper import FIG5, FIG6, FIG12

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

CASES = (("Fig. 5 stick-slip", {**FIG5, "omega": 100.0}, "stick-slip"),
         ("Fig. 6 stick-slip-separation", {**FIG6, "omega": 60.0}, "stick-slip-separation"),
         ("Fig. 12 with reverse slip", FIG12, "stick-slip-separation-reverse-slip"))


#: Section 3.1, case 1, integrated from noise with the paper's scheme (settles on a 2-mode wave).
FROM_NOISE = {"omega": 1.0, "mismatch": 4e-4, "friction": 0.2, "nodes": 256, "beta2": 0.9, "transits": 600}


def _stick_fraction(wave) -> float:
    return sum(z.end - z.start for z in wave.zones if z.kind == "stick") / wave.period


def compute(quick: bool = False) -> xr.Dataset:
    nodes, transits = (256, 10) if quick else (512, 10)
    rows, drift, sep, times = [], [], [], []
    for label, cfg, regime in CASES:
        p = BrakeParams.from_physical(cfg["omega"], cfg["mismatch"], cfg["friction"])
        wave = travelling_wave(p, cfg["modes"], regime=regime)
        ring = classify(integrate(p, nodes, transits=transits, beta2=0.5, initial=initial_from_wave(wave, nodes)))
        pers = wave_persistence(wave, nodes=256, periods=15 if quick else 30)
        into_stick = any(i.get("into") == "stick" for i in wave.impacts())
        rows.append((label, wave.regime, ring.regime, wave.c, ring.c, _stick_fraction(wave), ring.fractions["stick"],
                     pers.growth_rate, float(np.max(pers.drift)), int(into_stick), ring.fractions["reverse_slip"]))
        times.append(pers.time), drift.append(pers.drift), sep.append(pers.separation_of_runs)
    cfg = FROM_NOISE
    p = BrakeParams.from_physical(cfg["omega"], cfg["mismatch"], cfg["friction"])
    noise = classify(integrate(p, cfg["nodes"], transits=cfg["transits"] // (3 if quick else 1), beta2=cfg["beta2"],
                               initial=perturbed_steady(p, cfg["nodes"])))
    same_n = [w for w in find_waves(p, noise.n) if w.regime == noise.regime]
    width = max(len(t) for t in times)
    pad = lambda a: np.pad(np.asarray(a, float), (0, width - len(a)), constant_values=np.nan)  # noqa: E731
    col = lambda i: [r[i] for r in rows]  # noqa: E731
    return xr.Dataset(
        {"wave_regime": ("case", col(1)), "ring_regime": ("case", col(2)),
         "wave_c": ("case", col(3), {"long_name": "wave speed, multiple shooting", "units": "rad per unit Omega t"}),
         "ring_c": ("case", col(4), {"long_name": "wave speed, ring started on the wave"}),
         "wave_stick": ("case", col(5)), "ring_stick": ("case", col(6)),
         "growth_rate": ("case", col(7), {"long_name": "growth of a small perturbation (internal time)"}),
         "max_drift": ("case", col(8), {"long_name": "max distance to the exact wave / amplitude"}),
         "lands_into_stick": ("case", col(9), {"long_name": "the wave's landing impact ends in stick"}),
         "ring_reverse": ("case", col(10), {"units": "1", "long_name": "reverse-slip fraction in the ring run"}),
         "time": (("case", "sample"), np.array([pad(t) for t in times])),
         "drift": (("case", "sample"), np.array([pad(d) for d in drift])),
         "separation": (("case", "sample"), np.array([pad(s) for s in sep])),
         "noise_regime": ((), noise.regime), "noise_n": ((), noise.n), "noise_c": ((), noise.c),
         "noise_stationary": ((), int(noise.stationary)),
         "noise_wave_c": ((), same_n[0].c if same_n else np.nan)},
        coords={"case": col(0)},
        attrs={"nodes": nodes, "transits": transits, "from_noise": dict(FROM_NOISE)})


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    fig, (a1, a2) = plotting.new_figure(fig, 2, size=(5.6, 4.3))
    for i, label in enumerate(ds.case.values):
        a1.semilogy(ds.time[i], ds.separation[i], label=f"{label} (rate {float(ds.growth_rate[i]):+.3f})")
        a2.plot(ds.time[i], ds.drift[i], label=label)
    a1.set(xlabel="time τ = Ωt / √γ [1]", ylabel="perturbed − unperturbed (aligned) / initial [1]",
           title="stability: growth of a small perturbation")
    a2.set(xlabel="time τ = Ωt / √γ [1]", ylabel="distance to the exact wave / amplitude [1]",
           title="the ring carries the wave (started on it)")
    a1.legend(fontsize=8), a2.legend(fontsize=8)
    return fig


def check(ds: xr.Dataset) -> list[Check]:
    rel = np.abs(ds.ring_c.values / ds.wave_c.values - 1)
    dstick = np.abs(ds.ring_stick.values - ds.wave_stick.values)
    same = np.array([str(a) == str(b) for a, b in zip(ds.wave_regime.values, ds.ring_regime.values)])
    landing = ds.lands_into_stick.values.astype(bool)
    rates = ds.growth_rate.values
    noise_err = abs(float(ds.noise_c) / float(ds.noise_wave_c) - 1)
    return [
        Check("started on a wave, the ring integration keeps its speed", bool(np.all(rel < 5e-3)),
              f"max |c_ring/c_wave - 1| = {rel.max():.1e}", "< 5e-3", f"after {ds.attrs['transits']} transits"),
        Check("... and its regime and stick fraction (waves without a landing into stick)",
              bool(np.all(same[~landing]) and np.all(dstick[~landing] < 0.02)),
              f"regimes {[str(r) for r in ds.ring_regime.values[~landing]]}, stick difference "
              f"{dstick[~landing].max():.3f}", "same regime, < 0.02 (node resolution)"),
        Check("a landing into stick (Fig. 6) is where the two models differ: the ring adds a thin reverse slip",
              bool(np.all(rel[landing] < 5e-3) and np.all(ds.ring_reverse.values[landing] < 0.03)),
              f"reverse slip {ds.ring_reverse.values[landing]}, stick {ds.ring_stick.values[landing]} vs "
              f"{ds.wave_stick.values[landing]}", "speed kept, reverse slip < 3 % of the ring",
              "the wave applies Coulomb's law to the landing impulse (W2); the ring spreads the impact over one "
              "time step, after which the stick margin of the wave (small) is not met at every node"),
        Check("from perturbed steady sliding the ring settles on a wave of the shooting solver",
              bool(int(ds.noise_stationary) and noise_err < 2e-2),
              f"{str(ds.noise_regime.values)}, n = {int(ds.noise_n)}, |c/c_wave - 1| = {noise_err:.1e}",
              "stationary, same n and regime, speed within 2e-2", "section 3.1 case 1 with beta2 = 0.9 on 256 nodes "
              "(the scheme's damping shifts the speed slightly)"),
        Check("stability (beyond the paper): stick-slip waves are unstable, the reverse-slip wave of Fig. 12 attracts",
              bool(rates[0] > 0 and rates[2] < 0), ", ".join(f"{r:+.3f}" for r in rates),
              "rate(Fig. 5) > 0 > rate(Fig. 12)", "numerical evidence (perturbation growth), not a proof"),
    ]


FIGURE = FigureSpec(
    key="brake-waves-vs-ring", cost=8, title="Section 3 — travelling waves against the time integration; their stability",
    model="brake-like system, reduced model: multiple shooting vs method of lines",
    claim="The reduced model admits stick-slip and stick-slip-separation travelling waves, found semi-analytically; "
          "the stability of these waves is an open problem (conclusion of the paper).",
    method="The ring integrator (central differences, contact and friction per node) is started on the waves of "
           "Figures 5, 6 and 12 and must carry them (regime, speed, stick fraction); section 3.1 case 1 integrated "
           "from noise settles on a stationary wave, compared with the shooting wave of the same mode number; the "
           "growth of a small perturbation of each wave measured with an independent Moreau-type stepper.",
)
