"""Model 2: the brake-like system (paper section 3).

An elastic annulus clamped on its outer radius, pressed on a rotating rigid shaft with
Coulomb friction. One sub-package per sub-model:

* `brake.reduced`: parameters, the Lamé steady state ([11], [16]), the reduced-model
  coefficients [13] and the flutter of steady sliding;
* `brake.waves`: travelling waves [14]-[20] by multiple shooting, and their continuation;
* `brake.ring`: time integration of [12] on the ring, and the classification of its
  limit regime;
* `brake.fem`: the annulus as a finite element model (scikit-fem);
* `brake.maps`: regime maps over friction and mismatch (resumable sweeps).

The names below are the public API; the figures of the paper live in `stickslip.figures`.
"""

from .reduced import (STEEL, BrakeParams, GrowthRates, ModeGrowth, PhysicalParams, ReducedCoefficients,
                      SteadySliding, coefficients, coupling, growth_rate_limit, growth_rates, most_unstable_mode,
                      neutral_radius_ratio, separation_number, shape_integrals, steady_sliding)
from .ring import InitialCondition, RegimeResult, RingRun, RingScheme, classify, integrate, perturbed_steady, \
    transit_time
from .waves import REGIMES as WAVE_REGIMES
from .waves import TravellingWave, WaveBranch, continue_waves, find_waves, travelling_wave, wave_persistence

__all__ = ["BrakeParams", "PhysicalParams", "STEEL", "ReducedCoefficients", "coefficients", "coupling",
           "neutral_radius_ratio", "shape_integrals", "SteadySliding", "steady_sliding", "GrowthRates",
           "ModeGrowth", "growth_rates", "growth_rate_limit", "most_unstable_mode", "separation_number",
           "InitialCondition", "RingRun", "RingScheme", "integrate", "perturbed_steady", "transit_time",
           "RegimeResult", "classify", "TravellingWave", "find_waves", "travelling_wave", "WaveBranch",
           "continue_waves", "WAVE_REGIMES", "wave_persistence"]
