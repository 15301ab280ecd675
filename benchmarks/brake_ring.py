"""Time per step of the ring integrator (reduced model [12], 512 nodes) against the bare
vectorised update of the same arrays.

Baseline: the same explicit finite-difference update written with numpy whole-array
operations and no contact or friction logic (what "vectorised numpy" costs per step).
Measured in one run, on the same state (a saturated stick-slip-separation regime):

* compiled step with contact + Coulomb (`RingScheme.advance`: the shared kernel of
  `stickslip.contact` on the ring's stencil), the production path;
* the same step through the general sparse-matrix path (`advance(..., sparse=True)`);
* numpy step with contact + Coulomb (same algorithm, checked equal to the kernel);
* compiled step with contact switched off (`advance(..., contact=False)`);
* `integrate` end to end (kernel + sampling of energy, zone fractions, Fourier modes).

Usage: ``python benchmarks/brake_ring.py [--nodes 512] [--steps 20000]``
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from stickslip.brake import BrakeParams
from stickslip.brake.ring import integrate, perturbed_steady
from stickslip.contact import StepState
from timing import best_of


def _fields(s, k):
    """``U, V, vU, vV, aU, aV`` of the kernel state (dofs interleaved ``U_0, V_0, U_1, ...``)."""
    return [x for name in ("u", "v", "a") for x in s.fields(k[name])]


def numpy_bare(s, k, nsteps):
    """The finite-difference update alone (no contact, no friction), numpy whole-array ops."""
    c, d = s.coefficients, s.dtheta
    a, b, g, h, D = c.a, c.b, c.g, c.h, c.D
    U, V, vU, vV, aU, aV = _fields(s, k)
    dt, b2 = s.dt, s.beta2
    for _ in range(nsteps):
        Up, Um, Vp, Vm = np.roll(U, -1), np.roll(U, 1), np.roll(V, -1), np.roll(V, 1)
        AU = b * (Up - 2 * U + Um) / d**2 + D * (Vp - Vm) / (2 * d) - g * U
        AV = a * (Vp - 2 * V + Vm) / d**2 - D * (Up - Um) / (2 * d) - h * V
        vU = vU + dt * ((1 - b2) * aU + b2 * AU)
        vV = vV + dt * ((1 - b2) * aV + b2 * AV)
        U = U + dt * vU + 0.5 * dt * dt * AU
        V = V + dt * vV + 0.5 * dt * dt * AV
        aU, aV = AU, AV
    return U, V


def numpy_full(s, k, nsteps, delta, f):
    """The same update with the node-by-node contact and Coulomb projection, vectorised."""
    c, d = s.coefficients, s.dtheta
    a, b, g, h, D = c.a, c.b, c.g, c.h, c.D
    U, V, vU, vV, aU, aV = (x.copy() for x in _fields(s, k))
    dt, b2 = s.dt, s.beta2
    cdt2 = (b2 + 0.5) * dt * dt
    for _ in range(nsteps):
        Up, Um, Vp, Vm = np.roll(U, -1), np.roll(U, 1), np.roll(V, -1), np.roll(V, 1)
        AU = b * (Up - 2 * U + Um) / d**2 + D * (Vp - Vm) / (2 * d) - g * U
        AV = a * (Vp - 2 * V + Vm) / d**2 - D * (Up - Um) / (2 * d) - h * V
        vsU = vU + dt * ((1 - b2) * aU + b2 * AU)
        vsV = vV + dt * ((1 - b2) * aV + b2 * AV)
        Us = U + dt * vsU + 0.5 * dt * dt * AU
        Vs = V + dt * vsV + 0.5 * dt * dt * AV
        P = np.maximum((delta - Us) / cdt2, 0.0)
        Q = np.clip((V + dt - Vs) / cdt2, -f * P, f * P)
        aU, aV = AU + P, AV + Q
        vU, vV = vsU + b2 * dt * P, vsV + b2 * dt * Q
        U = np.where(P > 0, delta, Us)
        V = Vs + cdt2 * Q
    return U, V



def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--nodes", type=int, default=512)
    parser.add_argument("--steps", type=int, default=20000)
    args = parser.parse_args()
    N, M = args.nodes, args.steps
    p = BrakeParams.from_physical(80.0, 4e-4, 2.0)  # case 3 of section 3.1
    run = integrate(p, N, transits=60, initial=perturbed_steady(p, N))  # a saturated nonlinear state
    s, state0 = run.scheme, run.kernel
    fr = run.fractions[-1]
    fresh = lambda: {key: v.copy() for key, v in state0.items()}  # noqa: E731
    out = s.new_output()

    def compiled(n=M, contact=True, sparse=False):
        k = fresh()
        s.advance(StepState(k["u"], k["v"], k["a"]), n, contact, out, sparse=sparse)
        return k

    compiled(n=1), compiled(n=1, sparse=True)  # compile
    k_ref = compiled(n=50)
    U_ref, V_ref = s.fields(k_ref["u"])
    U_np, V_np = numpy_full(s, fresh(), 50, p.delta, p.friction)
    err = max(np.abs(U_np - U_ref).max() / p.delta, np.abs(V_np - V_ref).max() / np.abs(V_ref).max())
    U_sp, V_sp = s.fields(compiled(n=50, sparse=True)["u"])
    err_sparse = max(np.abs(U_sp - U_ref).max() / p.delta, np.abs(V_sp - V_ref).max() / np.abs(V_ref).max())
    t_bare_np = best_of(lambda: numpy_bare(s, fresh(), M // 10))[0] / (M // 10)
    t_full_np = best_of(lambda: numpy_full(s, fresh(), M // 10, p.delta, p.friction))[0] / (M // 10)
    t_full = best_of(compiled)[0] / M
    t_sparse = best_of(lambda: compiled(sparse=True))[0] / M
    t_bare = best_of(lambda: compiled(contact=False))[0] / M
    T = M / s.steps_per_transit
    t0 = time.perf_counter()
    integrate(p, N, transits=T, initial=perturbed_steady(p, N))
    t_int = (time.perf_counter() - t0) / (run.settings["chunk"] * int(np.ceil(T * s.steps_per_transit
                                                                              / run.settings["chunk"])))
    print(f"ring integrator, {N} nodes, state: stick {fr[0]:.2f}, slip {fr[1]:.2f}, reverse slip {fr[2]:.2f}, "
          f"separation {fr[3]:.2f}; numpy and compiled steps agree to {err:.1e}, stencil and sparse paths to "
          f"{err_sparse:.1e} (relative) after 50 steps")
    print(f"  bare vectorised update (numpy, no contact)  {1e6 * t_bare_np:8.2f} us/step   (baseline)")
    print(f"  numpy step with contact + Coulomb           {1e6 * t_full_np:8.2f} us/step   "
          f"ratio {t_full_np / t_bare_np:5.2f}")
    print(f"  compiled step, contact off (numba)          {1e6 * t_bare:8.2f} us/step   "
          f"ratio {t_bare / t_bare_np:5.2f}")
    print(f"  compiled step, general sparse path          {1e6 * t_sparse:8.2f} us/step   "
          f"ratio {t_sparse / t_bare_np:5.2f}")
    print(f"  compiled step with contact + Coulomb        {1e6 * t_full:8.2f} us/step   ratio {t_full / t_bare_np:5.2f}"
          f"   (vs contact off: {t_full / t_bare:4.2f})")
    print(f"  integrate() end to end, with sampling       {1e6 * t_int:8.2f} us/step   ratio {t_int / t_bare_np:5.2f}")
    print(f"RATIO time per step with contact+friction / bare vectorised update = {t_full / t_bare_np:.3f}")


if __name__ == "__main__":
    main()
