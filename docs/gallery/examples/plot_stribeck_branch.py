"""
Cycles along the belt speed under Stribeck's law
================================================

With a friction coefficient that falls with the slip speed (Stribeck's law,
:math:`\\mu(v) = f_d + (f_s - f_d)e^{-|v|/v_s}`), steady sliding loses stability at a Hopf point
and stick-slip cycles exist below a belt speed. `continue_cycle` follows the cycle in any
parameter, with the multipliers of each point.
"""

from stickslip import plotting
from stickslip.friction import Stribeck
from stickslip.oscillator import Oscillator, continue_cycle

osc = Oscillator(mass=1.0, stiffness=1.0, normal_force=1.0, belt_speed=0.2, damping=0.05,
                 friction=Stribeck(fs=0.6, fd=0.4, vs=0.1))
branch = continue_cycle(osc, 0.6, parameter="belt_speed")
ds = branch.to_xarray()
print(f"{ds.sizes['point']} cycles, belt speed {float(ds.parameter_value.min()):.3g} to "
      f"{float(ds.parameter_value.max()):.3g} m/s")
fig = plotting.plot_branch(ds)
