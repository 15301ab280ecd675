"""
Section 3.1: FE limit regimes from unseeded starts
==================================================

Statistics of the finite element runs of the campaign stored with the package: which regimes the paper's cases reach.
"""

from stickslip.figures.brake import fem_statistics

ds = fem_statistics.compute(quick=True)
for check in fem_statistics.check(ds):
    print(f"{'pass' if check.passed else 'FAIL'}: {check.name}: {check.measured} (expected {check.expected})")
fig = fem_statistics.plot(ds)
