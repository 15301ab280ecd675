"""Time per step of the FE brake integrator (default mesh 256 x 16) against the bare sparse
matrix-vector product of the same matrix.

Baseline: ``K @ u`` with scipy's CSR kernel on the assembled stiffness (the one operation an
explicit step cannot avoid). Measured in one run, on the same saturated state (case 2 of
section 3.1: stick, slip and separation present):

* scipy CSR ``K @ u`` (baseline) and the same product in a compiled CSR loop and in compiled
  2 x 2 node blocks (`stickslip.contact.kernel.block2_apply`, the general path's form);
* the compiled block-circulant stencil product (`stickslip.contact.kernel.stencil_apply`,
  same matrix);
* the compiled step with contact switched off (`FemScheme.advance(..., contact=False)`);
* the production step with contact and Coulomb friction (`FemScheme.advance`: the shared
  kernel of `stickslip.contact` on the annulus stencil), and the same step through the
  general sparse-matrix path (`advance(..., sparse=True)`);
* `integrate_fem` end to end (setup, kernel, and sampling of energy, zone fractions, Fourier
  modes and snapshots 32 times per transit), over 5x the steps.

Usage: ``python benchmarks/brake_fem.py [--n-theta 256] [--n-r 16] [--steps 5000]``
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from stickslip.brake import BrakeParams
from stickslip.brake.fem import integrate_fem
from stickslip.contact import StepState
from stickslip.contact.kernel import block2_apply, csr_apply, stencil_apply
from timing import best_of




def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n-theta", type=int, default=256)
    parser.add_argument("--n-r", type=int, default=16)
    parser.add_argument("--steps", type=int, default=5000)
    args = parser.parse_args()
    N, nr, M = args.n_theta, args.n_r, args.steps
    p = BrakeParams.from_physical(50.0, 1e-4, 0.7)  # case 2 of section 3.1
    run = integrate_fem(p, N, nr, transits=40)  # a saturated nonlinear state
    s, state0 = run.scheme, run.kernel
    fr = run.fractions[-1]
    K = s.system.K
    u = state0["u"].copy()
    out = np.empty_like(u)
    fresh = lambda: {key: v.copy() for key, v in state0.items()}  # noqa: E731
    buf = s.new_output()

    def step(n=M, contact=True, sparse=False):
        k = fresh()
        s.advance(StepState(k["u"], k["v"], k["a"]), n, contact, buf, sparse=sparse)
        return k

    def scipy_mv():
        for _ in range(M):
            K @ u

    def csr_mv():
        for _ in range(M):
            csr_apply(K.indptr, K.indices, K.data, u, out)  # compile

    indptr, indices, data, _ = s.kernel_operator  # M^-1 K in 2 x 2 blocks: the pattern of K

    def block_mv():
        for _ in range(M):
            block2_apply(indptr, indices, data, u, out)

    def stencil_mv():
        for _ in range(M):
            stencil_apply(s.stencil, u, out)

    step(1), step(1, sparse=True)  # compile
    err_paths = np.abs(step(50)["u"] - step(50, sparse=True)["u"]).max() / np.abs(step(50)["u"]).max()
    csr_apply(K.indptr, K.indices, K.data, u, out)  # compile
    block2_apply(indptr, indices, data, u, out)
    stencil_apply(s.stencil, u, out)
    err = np.abs(-s.mass * out - K @ u).max() / np.abs(K @ u).max()
    t_scipy, t_csr, t_block, t_sten, t_pred, t_full, t_sparse = (
        best_of(fn)[0] / M for fn in (scipy_mv, csr_mv, block_mv, stencil_mv, lambda: step(contact=False), step,
                                      lambda: step(sparse=True)))
    T = 5 * M / s.steps_per_transit  # long enough that the setup (steady solve, CFL eigenvalues) is amortised
    t0 = time.perf_counter()
    r = integrate_fem(p, N, nr, transits=T)
    t_int = (time.perf_counter() - t0) / (r.samples_done * r.settings["chunk"])
    spt = s.steps_per_transit
    print(f"FE brake integrator, mesh {s.system.mesh.describe()}: {s.system.n_free} dofs, nnz(K) = {K.nnz}, "
          f"{spt:.0f} steps per P-wave transit (beta2 = {s.beta2}, courant = {s.courant})")
    print(f"state: stick {fr[0]:.2f}, slip {fr[1]:.2f}, reverse slip {fr[2]:.2f}, separation {fr[3]:.2f}; "
          f"stencil product = K u to {err:.1e}, stencil and sparse steps agree to {err_paths:.1e} after 50 steps "
          "(relative)")
    rows = [("bare sparse matvec K @ u (scipy CSR)", t_scipy, "baseline"),
            ("same product, compiled CSR loop", t_csr, ""), ("same product, compiled 2 x 2 blocks", t_block, ""),
            ("same product, compiled stencil", t_sten, ""),
            ("compiled step, contact off", t_pred, ""),
            ("compiled step with contact + Coulomb (advance)", t_full, ""),
            ("the same step, general sparse path", t_sparse, ""),
            ("integrate_fem end to end, with sampling", t_int, "")]
    for name, t, note in rows:
        print(f"  {name:<52s} {1e6 * t:8.2f} us/step  {t * spt:7.4f} s/transit   ratio {t / t_scipy:5.2f} {note}")
    print(f"RATIO time per step with contact+friction / bare sparse matvec = {t_full / t_scipy:.3f} "
          f"(end to end: {t_int / t_scipy:.3f})")


if __name__ == "__main__":
    main()
