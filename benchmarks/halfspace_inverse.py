"""Benchmark: the half-space inverse problem and the interface fields (model 3).

    python benchmarks/halfspace_inverse.py [--points 1000000] [--loop 2000]

1. `inverse_problem` vectorised over 10^6 (b, c) points (target <= 0.5 s), best of 3;
2. the same solve in a per-point Python loop, measured on a subset of ``--loop``
   points and scaled linearly to 10^6 (stated in the output): once through the public
   scalar API, once as a bare ``math``-module loop (the cheapest Python baseline);
3. interface fields at 10^5 points (closed form), and the independent quadrature of
   the Cauchy integral [46] at 10^3 points off the axis.
Ratios are measured in this one run.
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from stickslip.halfspace import inverse_problem, wave_from_inverse
from stickslip.halfspace.waves import wave_speed_ratio
from timing import best_of

NU, MU, VS = 0.3, 0.5, 1e-3



def bare_scalar(b, c, v_star=VS, nu=NU, mu=MU):
    """[54]-[55] for one point with the math module only (Cramer's rule)."""
    c1 = wave_speed_ratio(nu)
    b1, b2 = math.sqrt(1 - c * c / (c1 * c1)), math.sqrt(1 - c * c)
    g1, g2 = b1 * (1 - b2 * b2), 1 + b2 * b2 - 2 * b1 * b2
    lam = math.atan2(g1, mu * g2) / math.pi
    K = math.pi * lam / math.sin(math.pi * lam)
    gm, omb = math.hypot(g1, mu * g2), 1 - b1 * b2
    a11, a12 = (K * (b - 1) - b) / c, -math.pi * lam * (b - 1) * omb / (2 * g1)
    a21, a22 = 2 * gm / (omb * c), b - 1
    r1, r2 = K * (b - 1) * v_star / c, 2 * gm * v_star / (omb * c)
    det = a11 * a22 - a12 * a21
    return (r1 * a22 - a12 * r2) / det, (a11 * r2 - a21 * r1) / det


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=1_000_000)
    ap.add_argument("--loop", type=int, default=2000)
    args = ap.parse_args()
    rng = np.random.default_rng(0)
    n = args.points
    b = 1.0 + 10 ** rng.uniform(-3, 3, n)
    c = -rng.uniform(1e-3, 1 - 1e-3, n)

    t_vec = best_of(lambda: inverse_problem(b, c, VS, nu=NU, mu=MU))[0]
    sol = inverse_problem(b, c, VS, nu=NU, mu=MU)
    m = args.loop
    idx = range(m)
    t_bare = best_of(lambda: [bare_scalar(float(b[i]), float(c[i])) for i in idx])[0] * n / m
    t_api = best_of(lambda: [inverse_problem(float(b[i]), float(c[i]), VS, nu=NU, mu=MU) for i in idx])[0] * n / m
    api = [inverse_problem(float(b[i]), float(c[i]), VS, nu=NU, mu=MU) for i in idx]
    bare = [bare_scalar(float(b[i]), float(c[i])) for i in idx]
    err = max(max(abs(float(a.v) / sol.v[i] - 1), abs(bare[i][1] / sol.T[i] - 1)) for i, a in enumerate(api))

    print(f"inverse problem, {n:,} (b, c) points, vectorised (best of 3): {t_vec:.3f} s "
          f"(target <= 0.5 s: {'met' if t_vec <= 0.5 else 'NOT met'})")
    print(f"per-point loop, public scalar API: {t_api:.1f} s for {n:,} points "
          f"(best of 3 on {m:,} points, scaled linearly) -> speed-up {t_api / t_vec:,.0f}x")
    print(f"per-point loop, bare math-module Cramer: {t_bare:.2f} s for {n:,} points "
          f"(best of 3 on {m:,} points, scaled linearly) -> speed-up {t_bare / t_vec:,.1f}x")
    print(f"max relative difference loop vs vectorised: {err:.1e}")

    w = wave_from_inverse(11.358175100459, -0.7, VS, nu=NU, mu=MU)
    x = np.linspace(0.0, w.b, 100_000, endpoint=False)
    t_f = best_of(lambda: w.fields(x))[0]
    print(f"interface fields at 100,000 points (closed form, all fields): {t_f * 1e3:.1f} ms "
          f"({t_f / 1e5 * 1e9:.0f} ns/point)")
    z = np.linspace(0.01, w.b - 0.01, 1000) - 0.05j
    t_q = best_of(lambda: w.phi_quadrature(z), repeat=1)[0]
    q_err = float(np.max(np.abs(w.phi_quadrature(z) - w.phi(z))) / np.max(np.abs(w.phi(z))))
    t_c = best_of(lambda: w.phi(z))[0]
    print(f"Cauchy integral [46] by quadrature at 1,000 points (Im z = -0.05): {t_q:.2f} s, "
          f"closed form {t_c * 1e3:.2f} ms -> closed form {t_q / t_c:,.0f}x faster; max rel. difference {q_err:.1e}")


if __name__ == "__main__":
    main()
