"""Explicit dynamics with exact unilateral contact and Coulomb friction, shared by every model.

The brake models (the reduced model on the ring, the FE annulus) and a general 2-D FE
model use the same machinery; a new geometry plugs in by defining an `ExplicitScheme`.

* `states`: the four node states (stick, slip, reverse slip, separation) and regime names;
* `kernel`: the compiled beta2 step with node-wise forward-increment multipliers [22], [23];
* `scheme`: `ExplicitScheme`, the interface a model's discretisation meets (time step and
  CFL limit, steps per transit, order, numerical damping, energies, start of a run);
* `runs`: checkpointed run books (series, snapshots, resume bit for bit);
* `classify`: the limit regime of a run (zones, mode number, wave speed, stationarity);
* `energy`: step-by-step traces and their discrete energy balance (for verification);
* `verify`: reactions recomputed from the motion, and the contact laws checked on them.
"""

from .classify import RegimeResult, classify, pattern_shift, pattern_speed
from .runs import RunFormat, RunRecord, prepare, run_explicit
from .scheme import ExplicitScheme, StepOutput, StepState, amplification_matrix, discrete_rates, stencil_matrix
from .states import (REGIME_ATTRS, REGIME_CODES, SEPARATION, SLIP_NEG, SLIP_POS, STATE_ATTRS, STATE_NAMES, STICK,
                     count_zones, regime_code, regime_name, state_fractions)

__all__ = ["ExplicitScheme", "StepState", "StepOutput", "amplification_matrix", "discrete_rates", "stencil_matrix",
           "RunFormat", "RunRecord", "prepare", "run_explicit", "RegimeResult", "classify", "pattern_shift",
           "pattern_speed", "STICK", "SLIP_POS", "SLIP_NEG", "SEPARATION", "STATE_NAMES", "STATE_ATTRS",
           "count_zones", "regime_name", "state_fractions", "REGIME_CODES", "REGIME_ATTRS", "regime_code"]
