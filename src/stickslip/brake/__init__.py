"""Model 2: the brake-like system (paper section 3).

An elastic annulus clamped on its outer radius, pressed on a rotating rigid shaft with
Coulomb friction. This package holds the parameters, the steady sliding state
([11], [16]), the reduced-model coefficients ([13]) and the linear stability of steady
sliding (flutter), the travelling waves [14]-[20] by multiple shooting (`travelling_wave`,
`continue_waves`), and the time integration of [12] on the ring (`integrate`, `classify`);
`figures` and `ring_figures` turn them into figures and their checks.
"""

from .coefficients import ReducedCoefficients, coefficients, coupling, neutral_radius_ratio, shape_integrals
from .params import STEEL, BrakeParams, PhysicalParams
from .ring import InitialCondition, RingRun, integrate, perturbed_steady, transit_time
from .ring_classify import RegimeResult, classify
from .wave_continuation import WaveBranch, continue_waves
from .wave_result import REGIMES as WAVE_REGIMES
from .wave_stability import wave_persistence
from .waves import TravellingWave, find_waves, travelling_wave
from .stability import GrowthRates, ModeGrowth, growth_rate_limit, growth_rates, most_unstable_mode
from .steady import SteadySliding, steady_sliding

__all__ = ["BrakeParams", "PhysicalParams", "STEEL", "ReducedCoefficients", "coefficients", "coupling",
           "neutral_radius_ratio", "shape_integrals", "SteadySliding", "steady_sliding", "GrowthRates",
           "ModeGrowth", "growth_rates", "growth_rate_limit", "most_unstable_mode",
           "InitialCondition", "RingRun", "integrate", "perturbed_steady", "transit_time", "RegimeResult", "classify",
           "TravellingWave", "find_waves", "travelling_wave", "WaveBranch", "continue_waves", "WAVE_REGIMES",
           "wave_persistence"]
