"""Write velocity_step.csv: a synthetic laboratory record for `stickslip rsf fit` (the quasi-static slider
with a = 0.005, b = 0.01, D_c = 10 um, k / sigma = 1e3 1/m, f0 = 0.6, a step from 1 to 10 um/s at 10 s,
plus white noise of 1e-4 from a generator seeded 46). Run from this folder: python make_record.py"""

import numpy as np

from stickslip.rsf import RateState, SpringSlider, slide

slider = SpringSlider(RateState(0.005, 0.01, 1e-5, f0=0.6, v_ref=1e-6), 1.0, 1e3)
run = slide(slider, [1e-6, 1e-5], 40.0, times=[0.0, 10.0], samples=801)
friction = run.friction + np.random.default_rng(46).normal(0.0, 1e-4, run.t.size)
velocity = np.where(run.t < 10.0, 1e-6, 1e-5)
np.savetxt("velocity_step.csv", np.column_stack([run.t, friction, velocity]), delimiter=",", fmt="%.10g",
           header="time,friction,load_velocity", comments="")
