"""
The stick-slip cycle of the friction oscillator
===============================================

A block of mass :math:`m` on a spring :math:`k`, pressed with :math:`N` on a belt moving at
:math:`V`, with static and kinetic coefficients :math:`f_s > f_d`:
:math:`m\\ddot x + kx = N\\mu(V - \\dot x)`. The limit cycle is found with exact switching
between stick and slip; its Floquet multipliers are computed with saltation matrices.
For :math:`f_s=0.6, f_d=0.4, V=0.2` the closed form gives a period of
:math:`2 + 3\\pi/2 \\approx 6.7124` s (2 s of stick).
"""

from stickslip import plotting
from stickslip.friction import Coulomb
from stickslip.oscillator import Oscillator, limit_cycle, simulate

osc = Oscillator(mass=1.0, stiffness=1.0, normal_force=1.0, belt_speed=0.2, friction=Coulomb(fs=0.6, fd=0.4))
cycle = limit_cycle(osc)
print(f"period {cycle.period:.6f} s, Floquet multipliers {cycle.floquet_multipliers}")

# %%
# The cycle in the phase plane (stick on the line :math:`\dot x = V`):
fig = plotting.plot_cycle(cycle.to_xarray())

# %%
# A run from a start away from the cycle: it joins the cycle at its first stick.
run = simulate(osc, 40.0, x0=-1.5)
fig_run = plotting.plot_trajectory(run.to_xarray(2001))
