"""Shared helpers of the FE tests: observed convergence orders and the paper's cases."""

import numpy as np

from stickslip.brake import BrakeParams

#: Section 3.1 cases on the default steel ring (R = 0.1 m, R* = 0.15 m): (f, d [m], Omega [rad/s]).
CASES = ((0.2, 4e-4, 1.0), (0.7, 1e-4, 50.0), (2.0, 4e-4, 80.0))


def case(i: int) -> BrakeParams:
    f, d, om = CASES[i]
    return BrakeParams.from_physical(om, d, f)


def orders(h, err):
    """Observed orders ``log(e_k / e_{k+1}) / log(h_k / h_{k+1})`` of successive refinements."""
    h, err = np.asarray(h, dtype=float), np.asarray(err, dtype=float)
    return np.log(err[:-1] / err[1:]) / np.log(h[:-1] / h[1:])
