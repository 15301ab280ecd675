"""The picture of the docs' front page (docs/index.md): three models of the package, each in
the state it is known for. Run from the repository to make it again after a change that
moves these results:

    python docs/images/overview.py docs/images/overview.png

It draws on a matplotlib Figure without pyplot, as `stickslip.plotting` does.
"""

from __future__ import annotations

import sys

import numpy as np
from matplotlib.figure import Figure

from stickslip import plotting
from stickslip.brake import BrakeParams
from stickslip.brake.fem import integrate_fem, perturbed_steady, FemScheme
from stickslip.friction import Coulomb
from stickslip.oscillator import Oscillator, simulate
from stickslip.system import burridge_knopoff
from stickslip.system import simulate as simulate_system


def overview() -> Figure:
    fig = Figure(figsize=(11, 3.2))
    left, middle, right = fig.subplots(1, 3)
    # the friction oscillator settling on its stick-slip cycle (the paper's Figure 2)
    osc = Oscillator(mass=1.0, stiffness=1.0, normal_force=1.0, belt_speed=0.2, friction=Coulomb(fs=0.6, fd=0.4))
    plotting.oscillator_phase(left, simulate(osc, t_end=40.0, x0=-1.5, v0=0.0).to_xarray(),
                              title="friction oscillator: stick-slip")
    # a chain of blocks on a moving plate (Burridge-Knopoff): slip events of every block
    chain = burridge_knopoff(12, Coulomb(0.6, 0.4), coupling=4.0, pull=1.0, plate_speed=0.05)
    x0 = np.random.default_rng(3).uniform(-0.3, 0.3, 12)
    run = simulate_system(chain, x0, -0.05 * np.ones(12), t_end=20.0, samples=1001).to_xarray()
    stuck = (run.contact_state.values == 0).astype(int)
    plotting.state_image(middle, np.where(stuck, 0, 1), extent=(0, 12, 0, float(run.t[-1])))
    middle.set_xticks([0.5, 5.5, 11.5], ["1", "6", "12"])
    middle.set_xlabel("block [1]")
    middle.set_ylabel("t [s]")
    middle.set_title("block chain: each block sticks and slips", fontsize=10)
    # the paper's brake-like annulus by finite elements: a stick-slip wave around the ring
    p = BrakeParams.from_physical(omega=50.0, mismatch=1e-4, friction=0.7)
    scheme = FemScheme(p, n_theta=128, n_r=8, beta2=0.9)
    fem = integrate_fem(p, n_theta=128, n_r=8, transits=300, beta2=0.9, initial=perturbed_steady(scheme, amplitude=1e-3))
    ds = fem.to_xarray()
    last = ds.snap_t.size // 3
    plotting.state_image(right, ds.state.values[-last:], extent=(0, 2 * np.pi, float(ds.snap_t[-last]), float(ds.snap_t[-1])))
    right.set_xlabel("angle around the ring [rad]")
    right.set_ylabel("t [1/Omega]")
    right.set_title("brake annulus (FE): a stick-slip wave", fontsize=10)
    plotting.state_legend(right)
    return fig


if __name__ == "__main__":
    problems = plotting.save(overview(), sys.argv[1] if len(sys.argv) > 1 else "overview.png", dpi=90)
    print("\n".join(problems) or "legible")
