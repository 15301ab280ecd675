"""
Beyond the paper: mode-coupling squeal
======================================

Hoffmann's two-degree-of-freedom model of brake squeal: the flutter threshold against its closed form.
"""

from stickslip.figures.beyond import squeal

ds = squeal.compute(quick=True)
for check in squeal.check(ds):
    print(f"{'pass' if check.passed else 'FAIL'}: {check.name}: {check.measured} (expected {check.expected})")
fig = squeal.plot(ds)
