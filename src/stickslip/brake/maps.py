"""Regime maps of the brake-like system over friction and mismatch (beyond the paper).

Two maps over ``(f, d)`` at fixed geometry and shaft speed (the reduced model depends on
``d`` and ``Omega`` only through ``delta / sqrt(gamma)``):

* which travelling waves of ``n`` modes exist (`find_waves`, cheap), coded by the
  regime of the principal one (largest ``|c|``), with the number of waves found;
* which limit regime the ring integration from perturbed steady sliding reaches
  (`integrate` + `classify`).

Both run through `stickslip.sweep.run_sweep`: resumable and parallel (Dask).
"""

from __future__ import annotations

import functools
import math


from ..quantities import BRAKE as Q
from ..contact import REGIME_CODES, regime_code
from ..errors import NoSolutionError
from ..sweep import run_sweep
from .reduced.params import PhysicalParams
from .ring.integrate import integrate, perturbed_steady
from .ring import classify
from .waves.solve import find_waves
from .. import validation as check

__all__ = ["REGIME_CODES", "regime_code", "wave_regime_map", "ring_regime_map"]


def _params(material: dict, omega: float, friction: float, mismatch: float):
    return PhysicalParams(omega, mismatch, friction, **material).dimensionless()


def _wave_point(material, omega, modes, friction, mismatch) -> dict:
    p = _params(material, omega, friction, mismatch)
    try:
        waves = find_waves(p, modes)
    except NoSolutionError:
        waves = []
    if not waves:
        return {"wave_regime": 0.0, "waves": 0.0, "c_over_sqrt_a": math.nan}
    a = p.coefficients().a
    return {"wave_regime": float(regime_code(waves[0].regime)), "waves": float(len(waves)),
            "c_over_sqrt_a": waves[0].c / math.sqrt(a)}


def _ring_point(material, omega, nodes, transits, friction, mismatch) -> dict:
    p = _params(material, omega, friction, mismatch)
    r = classify(integrate(p, nodes, transits=transits, beta2=0.5, initial=perturbed_steady(p, nodes)))
    return {"ring_regime": float(regime_code(r.regime)), "n_fft": float(r.n_fft),
            **{f"fraction_{k}": float(v) for k, v in r.fractions.items()}}


def wave_regime_map(frictions, mismatches, store, *, omega: float = 50.0, modes: int = 4,
                    material: dict | None = None, **options):
    """Regime of the principal ``modes``-wave at every ``(f, d)``; ``options`` go to `run_sweep`."""
    frictions, mismatches = check.finite_array("frictions", frictions, 1), check.finite_array("mismatches", mismatches, 1)
    omega, modes = Q.check("omega", omega), Q.check("modes", modes)
    func = functools.partial(_wave_point, dict(material or {}), omega, modes)
    return run_sweep(func, {"friction": list(frictions), "mismatch": list(mismatches)}, store,
                     outputs={"wave_regime": REGIME_CODES, "waves": "1", "c_over_sqrt_a": "1"},
                     attrs={"omega": omega, "modes": modes, "material": dict(material or {})},
                     title="travelling-wave regimes over friction and mismatch", model="brake", **options)


def ring_regime_map(frictions, mismatches, store, *, omega: float = 50.0, nodes: int = 128,
                    transits: float = 150.0, material: dict | None = None, **options):
    """Limit regime of the ring integration at every ``(f, d)``; ``options`` go to `run_sweep`."""
    frictions, mismatches = check.finite_array("frictions", frictions, 1), check.finite_array("mismatches", mismatches, 1)
    omega, nodes = Q.check("omega", omega), Q.check("nodes", nodes)
    transits = Q.check("transits", transits)
    func = functools.partial(_ring_point, dict(material or {}), omega, nodes, transits)
    outputs = {"ring_regime": REGIME_CODES, "n_fft": "1", **{f"fraction_{k}": "1" for k in
                                                     ("stick", "slip", "reverse_slip", "separation")}}
    return run_sweep(func, {"friction": list(frictions), "mismatch": list(mismatches)}, store, outputs=outputs,
                     attrs={"omega": omega, "nodes": nodes, "transits": transits, "material": dict(material or {})},
                     title="ring limit regimes over friction and mismatch", model="brake", **options)
