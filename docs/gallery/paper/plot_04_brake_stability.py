"""
Section 3: flutter of steady sliding
====================================

The growth rate of each mode of the annulus in steady sliding: the reduced model's flutter instability.
"""

from stickslip.figures.brake import stability

ds = stability.compute(quick=True)
for check in stability.check(ds):
    print(f"{'pass' if check.passed else 'FAIL'}: {check.name}: {check.measured} (expected {check.expected})")
fig = stability.plot(ds)
