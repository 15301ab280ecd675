"""A general body from a mesh (`stickslip.fem`): assembly, one explicit step, and complex
eigenvalue analysis, each against its baseline in the same run.

* Assembly of the paper's annulus meshed by gmsh (triangles) at about 10k and 100k dofs:
  wall time of `stickslip.fem.assemble` (target: <= 5 s at 100k dofs).
* One explicit step with contact and Coulomb friction on the general sparse path
  (`BodyScheme.advance`) against the bare scipy CSR product ``K @ u`` of the same
  operator (target: ratio <= 2).
* CEA: 30 eigenvalues near one shift (shift-invert Arnoldi, `stickslip.fem.cea`) on about
  5k and 100k dofs, against `scipy.sparse.linalg.eigs` on the same pencil without shift-invert
  (the 30 smallest in magnitude, ``which="SM"``), stopped after a fixed budget of iterations
  when it does not converge (then the ratio is a lower bound).

Usage: ``python benchmarks/fem_general.py [--sizes 0.003 0.001] [--cea-sizes 0.0042 0.001]``
(gmsh mesh sizes in m for R = 0.1 m).
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as sla

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "examples" / "annulus"))
import mesh as annulus_mesh  # noqa: E402  (the example's gmsh script)
from timing import best_of  # noqa: E402

from stickslip.fem import (BodyScheme, ContactProblem, Material, RigidCylinder, assemble,  # noqa: E402
                           contact_frames, read_body)
from stickslip.fem.cea import eigenvalues_near, linearised  # noqa: E402


def problem(size: float, folder: Path):
    path = folder / f"annulus-{size:g}.msh"
    annulus_mesh.make(path, size)
    body = read_body(path)
    t0 = time.perf_counter()
    system = assemble(body, Material(2.1e11, 0.3, 7850.0))
    seconds = time.perf_counter() - t0
    frames = contact_frames(body, "bore", RigidCylinder(0.1 + 1e-4, 50.0))
    return ContactProblem(system, frames, 0.7, ("rim",)), seconds


def step_ratio(p: ContactProblem, steps: int = 200):
    scheme = BodyScheme(p)
    w_e, _, _ = scheme.steady_reference()
    rng = np.random.default_rng(0)
    start = w_e + 1e-3 * np.abs(w_e).max() * rng.standard_normal(w_e.size)
    state = scheme.initial_state(start, np.zeros_like(start))
    scheme.advance(state, 10)  # compile and settle
    A = scheme.stiffness  # the bare scipy CSR matrix (as scipy builds it) of the same free dofs
    u = state.u.copy()
    t_mv, _ = best_of(lambda: [A @ u for _ in range(steps)])
    t_step, _ = best_of(lambda: scheme.advance(state, steps))
    return t_step / steps, t_mv / steps


def cea_times(p: ContactProblem, budget: int):
    K, C, m, _ = linearised(p)
    shift = 20000.0
    t_si, _ = best_of(lambda: eigenvalues_near(K, C, m, shift, 30, False), repeat=1)
    n = K.shape[0]
    A = sp.bmat([[None, sp.identity(n)], [-K, sp.csr_matrix((n, n))]], format="csr")
    Minv = np.concatenate([np.ones(n), 1.0 / m])
    op = sla.LinearOperator((2 * n, 2 * n), matvec=lambda x: Minv * (A @ x), dtype=float)
    t0 = time.perf_counter()
    try:
        sla.eigs(op, k=30, which="SM", maxiter=budget, tol=1e-8)
        converged = True
    except sla.ArpackNoConvergence:
        converged = False
    return t_si, time.perf_counter() - t0, converged, n


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=float, nargs="+", default=[0.003, 0.001])
    parser.add_argument("--cea-sizes", type=float, nargs="+", default=[0.0042, 0.001])
    parser.add_argument("--budget", type=int, default=100, help="Arnoldi restarts of the baseline eigs")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for size in args.sizes:
            p, seconds = problem(size, folder)
            per_step, per_mv = step_ratio(p)
            print(f"mesh {size:g} m: {p.system.n_dofs} dofs; assembly {seconds:.2f} s; step with contact and "
                  f"Coulomb {per_step * 1e6:.1f} us vs K @ u {per_mv * 1e6:.1f} us: ratio {per_step / per_mv:.2f}")
        for size in args.cea_sizes:
            p, _ = problem(size, folder)
            t_si, t_plain, converged, n = cea_times(p, args.budget)
            bound = "" if converged else f" (not converged after {args.budget} restarts: a lower bound)"
            print(f"CEA on {n} kept dofs: 30 eigenvalues near one shift {t_si:.2f} s; eigs without shift-invert "
                  f"{t_plain:.2f} s{bound}: ratio {t_plain / t_si:.1f}")


if __name__ == "__main__":
    main()
