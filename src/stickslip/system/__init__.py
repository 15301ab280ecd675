"""Linear structures with several frictional contacts: exact event-driven switching.

`System` (``M x'' + C x' + K x = f(t) + sum_i w_i F_i``) with its `Contact` s (and a force in
time: `Harmonic` s, a `ForceHistory`); `simulate` advances it
through closed-form flows between contact events (`Flow`); `monodromy` differentiates a run
(saltation matrices at its events) and `limit_cycle` finds the periodic orbit a motion settles
on, with its Floquet multipliers; `steady_sliding` the resting state under sliding contacts and its
linear stability; `relative_cycle` a wave moving by one cell of a symmetric structure and
its multipliers; `continue_system` follows a cycle along a parameter; `load_system` reads a
system from a TOML file. With rate-and-state laws (`stickslip.rsf.RateState`) at its contacts,
`rate_state_simulate` and `rate_state_steady` give its motion and its steady sliding. One contact
on one degree of freedom is the oscillator of `stickslip.oscillator`.
"""

from .chains import burridge_knopoff
from .config import load_system, system_from_dict
from .continuation import SystemBranch, continue_system, file_parameter
from .floquet import SystemCycle, limit_cycle, monodromy, saltation, without_own
from .forced import ForcedResponse, forced_response
from .flow import Flow
from .model import Contact, ForceHistory, Harmonic, System
from .rate_state import (RateStateRun, RateStateSteady, integrated, is_rate_state, rate_state_simulate,
                         rate_state_steady)
from .rate_state_cycle import RateStateCycle, rate_state_cycle
from .simulate import Segment, SystemRun, choose_states, simulate
from .steady import SteadySliding, steady_sliding
from .symmetry import RelativeCycle, cell_symmetry, relative_cycle

__all__ = ["Contact", "System", "Harmonic", "ForceHistory", "Flow", "SystemRun", "Segment", "simulate", "choose_states", "monodromy",
           "saltation", "SystemCycle", "limit_cycle", "load_system", "system_from_dict",
           "SteadySliding", "steady_sliding", "burridge_knopoff", "RelativeCycle", "cell_symmetry",
           "relative_cycle", "without_own", "SystemBranch", "continue_system", "file_parameter", "RateStateRun",
           "RateStateSteady", "is_rate_state", "integrated", "rate_state_simulate", "rate_state_steady", "ForcedResponse",
           "forced_response", "RateStateCycle", "rate_state_cycle"]
