"""Linear structures with several frictional contacts: exact event-driven switching.

`System` (``M x'' + C x' + K x = f + sum_i w_i F_i``) with its `Contact` s; `simulate` advances it
through closed-form flows between contact events (`Flow`). One contact on one degree of
freedom is the oscillator of `stickslip.oscillator`.
"""

from .flow import Flow
from .model import Contact, System
from .simulate import SystemRun, choose_states, simulate

__all__ = ["Contact", "System", "Flow", "SystemRun", "simulate", "choose_states"]
