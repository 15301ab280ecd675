"""
Earthquake cycles on a strike-slip fault
========================================

A vertical strike-slip fault in a half-space with the parameters of the SCEC SEAS benchmark BP1-QD
(quasi-dynamic, antiplane): regularised rate-and-state friction with the aging law, velocity
weakening (``a = 0.010 < b = 0.015``) down to 15 km, ``a`` rising to 0.025 at 18 km, 50 MPa of normal
stress, ``D_c`` = 8 mm, the fault creeping at the plate rate (1e-9 m/s) below 40 km. Its cells are
200 m long, coarser than the benchmark asks (25 m; the run says so): the page builds in about half a
minute. Left: the largest slip rate on the fault. Right: the slip profiles, every 5 years while the
fault is locked (blue) and every second during the events (orange).
"""

import numpy as np
from matplotlib.figure import Figure

from stickslip.rsf import RateState
from stickslip.sbim.fault import YEAR, StrikeSlipFault, run_fault


def a_profile(z, H=15e3, h=3e3):
    return np.clip(0.010 + 0.015 * (z - H) / h, 0.010, 0.025)


law = RateState(a=0.010, b=0.015, dc=0.008, f0=0.6, v_ref=1e-6, regularized=True)
fault = StrikeSlipFault(shear_modulus=2670.0 * 3464.0**2, shear_wave_speed=3464.0, depth=40e3, elements=200, law=law,
                        a_profile=a_profile, normal_stress=50e6, plate_rate=1e-9, domain_depth=80e3)
run = run_fault(fault, 540 * YEAR)

print(f"{run.event_start.size} events, starting at {np.round(run.event_start / YEAR, 1)} years")
print(f"recurrence intervals {np.round(run.recurrence / YEAR, 2)} years")
print(f"peak slip rates {np.round(run.event_peak, 2)} m/s")
i, j = np.searchsorted(run.profile_t, run.event_start[[-3, -1]])
gained = run.slip[j - 1] - run.slip[i - 1]
span = run.profile_t[j - 1] - run.profile_t[i - 1]
print(f"over the last two cycles (the first ones still carry the start's stress) the slip at every depth is "
      f"{gained.min() / (1e-9 * span):.3f} to {gained.max() / (1e-9 * span):.3f} times the plate's motion")

fig = Figure(figsize=(9, 4.2), layout="constrained")
left, right = fig.subplots(1, 2)
left.semilogy(run.t / YEAR, run.max_slip_rate, "k-", lw=0.8)
left.set_xlabel("t [years]")
left.set_ylabel("largest slip rate [m/s]")
fast = np.interp(run.profile_t, run.t, run.max_slip_rate) > run.event_rate
for t, slip, quick in zip(run.profile_t, run.slip, fast):
    right.plot(slip, fault.z / 1e3, color="C1" if quick else "C0", lw=0.5)
right.invert_yaxis()
right.set_xlabel("slip [m]")
right.set_ylabel("depth [km]")
