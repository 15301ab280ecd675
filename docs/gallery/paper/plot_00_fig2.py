"""
Figure 2: the stick-slip phase diagram
======================================

Phase trajectories of the friction oscillator with Coulomb friction: the stick-slip cycle and the closed orbits around it.
"""

from stickslip.figures.oscillator import fig2

ds = fig2.compute(quick=True)
for check in fig2.check(ds):
    print(f"{'pass' if check.passed else 'FAIL'}: {check.name}: {check.measured} (expected {check.expected})")
fig = fig2.plot(ds)
