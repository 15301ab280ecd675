"""Model 1: the one-degree-of-freedom friction oscillator (paper section 2).

>>> from stickslip.friction import Coulomb
>>> from stickslip.oscillator import Oscillator, limit_cycle
>>> osc = Oscillator(mass=1.0, stiffness=1.0, normal_force=1.0, belt_speed=0.2, friction=Coulomb(0.6, 0.4))
>>> round(limit_cycle(osc).period, 6)
6.712389
"""

from .continuation import Branch, continue_cycle, continue_from_hopf
from .cycle import LimitCycle, limit_cycle, return_map
from .model import Mode, Oscillator
from .simulate import Engine, Trajectory, simulate
from .stability import EquilibriumStability, HopfPoint, equilibrium_stability, hopf_points

__all__ = ["Branch", "Engine", "EquilibriumStability", "HopfPoint", "LimitCycle", "Mode", "Oscillator",
           "Trajectory", "continue_cycle", "continue_from_hopf", "equilibrium_stability", "hopf_points",
           "limit_cycle", "return_map", "simulate"]
