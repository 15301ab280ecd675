"""
Figure 3: velocity-weakening friction
=====================================

With friction falling linearly with the slip speed, the cycles spiral onto the stick-slip cycle.
"""

from stickslip.figures.oscillator import fig3

ds = fig3.compute(quick=True)
for check in fig3.check(ds):
    print(f"{'pass' if check.passed else 'FAIL'}: {check.name}: {check.measured} (expected {check.expected})")
fig = fig3.plot(ds)
