"""Travelling stick-slip(-separation, -reverse-slip) waves of the reduced model ([14]-[20]).

* `zones`: the closed-form flows of [15] inside stick, slip, reverse-slip and separation
  zones, and the landing impact (erratum W2); `Scaling`, the internal units;
* `shoot`: the stick-exit return map, an event-driven closed-form orbit (initial guesses);
* `boundsco`: multiple shooting with the switching points as unknowns (BOUNDSCO);
* `solve`: `travelling_wave` and `find_waves`, which scan, polish and verify;
* `result`: the `TravellingWave` result object;
* `continuation`: branches in ``delta``, ``gamma``, ``Omega`` or ``f`` with births and
  deaths of zones;
* `checks`: independent re-integration with ``solve_ivp`` and the energy balance;
* `stability`: growth of a small perturbation with an independent Moreau-type stepper;
* `spectrum`: the Floquet multipliers of the discrete ring's wave (node-shift map).
"""

from .checks import energy_balance, integrate_wave
from .continuation import PARAMETERS, WaveBranch, WaveEvent, continue_waves
from .result import REGIMES, TravellingWave, Zone, regime_name
from .shoot import Orbit, stick_exit_orbit
from .solve import find_waves, solve_layout, travelling_wave
from .spectrum import WaveSpectrum, moreau_difference, ring_system, sampled_ring, wave_spectra, wave_spectrum
from .stability import WavePersistence, wave_persistence
from .zones import Scaling, ZoneFlows

__all__ = ["TravellingWave", "Zone", "REGIMES", "regime_name", "travelling_wave", "find_waves", "solve_layout",
           "WaveBranch", "WaveEvent", "continue_waves", "PARAMETERS", "WavePersistence", "wave_persistence",
           "energy_balance", "integrate_wave", "WaveSpectrum", "ring_system", "wave_spectrum",
           "wave_spectra", "sampled_ring", "moreau_difference", "Scaling", "ZoneFlows", "Orbit", "stick_exit_orbit"]
