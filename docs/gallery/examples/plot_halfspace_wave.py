"""
A stick-slip wave at the interface of an elastic half-space
===========================================================

A rigid body slides on an elastic half-space; a periodic wave of stick and slip zones runs
along the interface (paper, sections 4-5). From the wave's parameters :math:`(b, \\bar c)` the
inverse problem gives the loading, and the interface fields follow in closed form.
"""

from stickslip import plotting
from stickslip.halfspace import wave_from_inverse

wave = wave_from_inverse(11.358, -0.7, 0.001, nu=0.3, mu=0.5)
print(wave.summary())
fig = plotting.plot_interface_fields(wave.fields(n=2001).to_xarray())
