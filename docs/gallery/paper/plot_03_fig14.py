"""
Figure 14: the interface stress of a half-space wave
====================================================

The normal stress along the interface of a periodic stick-slip wave under a rigid body sliding on an elastic half-space.
"""

from stickslip.figures.halfspace import fig14

ds = fig14.compute(quick=True)
for check in fig14.check(ds):
    print(f"{'pass' if check.passed else 'FAIL'}: {check.name}: {check.measured} (expected {check.expected})")
fig = fig14.plot(ds)
