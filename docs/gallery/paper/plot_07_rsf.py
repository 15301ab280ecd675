"""
Beyond the paper: the rate-and-state slider
===========================================

The spring-slider with rate-and-state friction: steady sliding's stability, its Hopf point and the cycles beyond.
"""

from stickslip.figures.beyond import rsf_slider

ds = rsf_slider.compute(quick=True)
for check in rsf_slider.check(ds):
    print(f"{'pass' if check.passed else 'FAIL'}: {check.name}: {check.measured} (expected {check.expected})")
fig = rsf_slider.plot(ds)
