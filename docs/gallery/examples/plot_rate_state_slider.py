"""
Slide-hold-slide on a rate-and-state slider
===========================================

A spring slider with Dieterich's aging law, :math:`\\mu = f_0 + a\\ln(V/V_0) + b\\ln(V_0\\theta/D_c)`,
:math:`\\dot\\theta = 1 - V\\theta/D_c`: the load point moves at 1 µm/s, ten times faster, stops,
and starts again. Holding heals the contact: the peak on reloading grows with the hold.
"""

from matplotlib.figure import Figure

from stickslip.rsf import RateState, SpringSlider, slide

slider = SpringSlider(RateState(a=0.01, b=0.015, dc=1e-5), normal_stress=1e7, stiffness=1.5e10)
run = slide(slider, [1e-6, 1e-5, 0.0, 1e-6], 160.0, times=[0.0, 20.0, 60.0, 100.0], samples=4001)

fig = Figure(figsize=(7, 5))
top, bottom = fig.subplots(2, 1, sharex=True)
top.plot(run.t, run.friction)
top.set_ylabel("friction coefficient μ [1]")
bottom.semilogy(run.t, run.slip_rate)
bottom.set_ylabel("slip rate V [m/s]")
bottom.set_xlabel("t [s]")
fig.tight_layout()
