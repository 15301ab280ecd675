"""A contact state's flow (`stickslip.system.flow.Flow`) on the separating ring of the waves' stability
figure: the time to build the flows of the states its wave meets, against the same matrices written
out densely (``P = M^-1 - M^-1 E (G^T M^-1 E)^+ G^T M^-1``, then ``-P K``: the products of 2N-square
matrices the flows took before issue 47), and the two ``A`` compared (they must agree to round-off).

``python benchmarks/system_flows.py [NODES]`` (default 128: 2N = 256 degrees of freedom).
Prints the seconds of each and their ratio, measured in one run.
"""

import sys
import time

import numpy as np

from stickslip.brake import BrakeParams, travelling_wave
from stickslip.brake.waves import ring_system, sampled_ring
from stickslip.figures.brake.paper import FIG11
from stickslip.system import simulate
from stickslip.system.flow import OPEN, Flow


def dense_stiffness_block(system, states):
    """``-P K`` written out with n x n products (no contact changes K: the ring's rigid contacts)."""
    W, Minv, K = system.directions, system.inverse_mass, system.stiffness
    stuck = [i for i, s in enumerate(states) if s == 0]
    closed = [j for j, (c, s) in enumerate(zip(system.contacts, states)) if c.rigid and s != OPEN]
    if not stuck and not closed:
        return -Minv @ K
    pressed = [c.normal_direction + (s * c.friction.affine[0] * c.direction if s else 0.0)
               for c, s in ((system.contacts[j], states[j]) for j in closed)]
    G = np.hstack([W[:, stuck], system.normal_units[:, closed]])
    E = np.hstack([W[:, stuck], np.array(pressed).T.reshape(system.dofs, len(closed))])
    P = Minv - Minv @ E @ np.linalg.pinv(G.T @ Minv @ E) @ G.T @ Minv
    return -P @ K


def main():
    nodes = int(sys.argv[1]) if len(sys.argv) > 1 else 128
    params = BrakeParams.from_physical(FIG11["omega"], 1.2e-6, FIG11["friction"])
    wave = travelling_wave(params, FIG11["modes"])
    system = ring_system(wave.params, nodes, separation=True)
    x0, v0, _ = sampled_ring(wave, nodes)
    run = simulate(system, x0, v0, 0.3 * (2 * np.pi / wave.n) / abs(float(wave.x[0])), samples=2, segments=True)
    states = list(dict.fromkeys(seg.states for seg in run.segments))[:60]
    n = system.dofs
    start = time.perf_counter()
    flows = [Flow(system, s) for s in states]
    ours = time.perf_counter() - start
    start = time.perf_counter()
    dense = [dense_stiffness_block(system, s) for s in states]
    written_out = time.perf_counter() - start
    scale = max(float(np.abs(d).max()) for d in dense)
    worst = max(float(np.abs(f.A[n:2 * n, :n] - d).max()) for f, d in zip(flows, dense)) / scale
    print(f"the separating ring of {nodes} nodes ({n} degrees of freedom), {len(states)} contact states of its wave")
    print(f"Flow (whole flow: A, events, constraints): {ours:.3f} s")
    print(f"written out densely (its -P K block alone): {written_out:.3f} s")
    print(f"ratio (dense block / whole flow): {written_out / ours:.1f}")
    print(f"largest difference of the -P K blocks: {worst:.1e} of their largest entry")


if __name__ == "__main__":
    main()
