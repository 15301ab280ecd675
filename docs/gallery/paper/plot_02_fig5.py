"""
Figure 5: stick-slip waves of the annulus
=========================================

Phase diagrams (V, V') of travelling stick-slip waves of the elastic annulus on its turning shaft, for several shaft speeds.
"""

from stickslip.figures.brake import fig5

ds = fig5.compute(quick=True)
for check in fig5.check(ds):
    print(f"{'pass' if check.passed else 'FAIL'}: {check.name}: {check.measured} (expected {check.expected})")
fig = fig5.plot(ds)
