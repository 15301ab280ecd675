"""The rate-and-state spring-slider (`stickslip.rsf.slide`) on rsfmodel's seven velocity-step cases
(tests/rsf/data/rsfmodel_cases.json: one and two state variables, Dieterich's, Ruina's and the PRZ
evolution; 40 s, 41 samples), against the way rsfmodel solves them, written here: scipy's
``odeint`` (LSODA) on ``(mu, theta_1[, theta_2])`` with the right-hand side in Python and numpy and
no Jacobian (rsfmodel's default tolerance, rtol = atol = 1.49e-8). rsfmodel itself is not in the
package registry this machine reaches; the baseline stands in for it.

Timed at the baseline's tolerance and at the package's default (rtol 1e-10), and, for scale, the
path the package took before its equations were compiled (Radau IIA, scipy's ``solve_ivp``, on
`SpringSlider.rhs` with the complex-step Jacobian). Each time is the best of ``--repeat`` runs in
one process; the compiled kernels loaded first (a short run starts interpreted, `stickslip.jit`).

    .venv/bin/python benchmarks/rsf_slider.py [--repeat 5]
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np
from scipy.integrate import odeint, solve_ivp

from stickslip.rsf import RateState, SpringSlider, slide
from stickslip.rsf.kernel import KERNELS
from stickslip.rsf.slider import jacobian

DATA = Path(__file__).resolve().parents[1] / "tests" / "rsf" / "data" / "rsfmodel_cases.json"
UM, SIGMA = 1e-6, 1e7
LAWS = {"DieterichState": "aging", "RuinaState": "slip", "PrzState": "prz"}
TIMES = np.arange(41.0)


def baseline(case: dict, rtol: float = 1.49012e-8) -> np.ndarray:
    """rsfmodel's formulation: friction and states integrated, the slip rate solved from the law each call."""
    a, k, v_ref, mu0 = case["a"], case["k"], case["vref"], case["mu0"]
    b = np.array([s["b"] for s in case["states"]])
    dc = np.array([s["Dc"] for s in case["states"]])
    law = case["states"][0]["law"]
    prz = law == "PrzState"

    def rhs(y, t):
        mu, theta = y[0], y[1:]
        scale = v_ref / (2.0 * dc) if prz else v_ref / dc
        v = v_ref * np.exp((mu - mu0 - np.sum(b * np.log(scale * theta))) / a)
        v_lp = 1.0 if t < 10.0 else 10.0
        if law == "DieterichState":
            dtheta = 1.0 - v * theta / dc
        elif law == "RuinaState":
            dtheta = -(v * theta / dc) * np.log(v * theta / dc)
        else:
            dtheta = 1.0 - (v * theta / (2.0 * dc)) ** 2
        return np.concatenate([[k * (v_lp - v)], dtheta])

    theta0 = (2.0 if prz else 1.0) * dc / case["v"]
    return odeint(rhs, np.concatenate([[mu0], theta0]), TIMES, rtol=rtol, atol=rtol, tcrit=[10.0])


def ours(case: dict, rtol: float):
    states = case["states"]
    evolution = LAWS[states[0]["law"]]
    f0 = case["mu0"] - (sum(s["b"] for s in states) * math.log(2.0) if evolution == "prz" else 0.0)
    second = states[1] if len(states) > 1 else None
    law = RateState(case["a"], states[0]["b"], states[0]["Dc"] * UM, f0=f0, v_ref=case["vref"] * UM,
                    evolution=evolution, b2=second["b"] if second else 0.0, dc2=second["Dc"] * UM if second else None)
    slider = SpringSlider(law, SIGMA, case["k"] * SIGMA / UM)
    return slider, lambda: slide(slider, [UM, 10 * UM], 40.0, times=[0.0, 10.0], samples=41, rtol=rtol)


def before(slider: SpringSlider, rtol: float = 1e-10) -> None:
    """The path before the compiled equations: Radau on the numpy right-hand side, complex-step Jacobian."""
    y = slider.steady_state(UM)
    for (t0, t1), v in (((0.0, 10.0), UM), ((10.0, 40.0), 10 * UM)):
        sol = solve_ivp(lambda t, z: slider.rhs(z, v), (t0, t1), y, method="Radau", rtol=rtol,
                        atol=rtol * np.maximum(1.0, np.abs(y)), jac=lambda t, z: jacobian(slider, z, v),
                        dense_output=True)
        y = sol.y[:, -1]


def best(func, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        func()
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    cases = json.loads(DATA.read_text())["cases"]
    KERNELS.compiled  # noqa: B018 - loaded first: every run timed compiled
    rows, totals = [], np.zeros(4)
    print(f"{'case':24s} {'baseline':>9s} {'ours@1.5e-8':>12s} {'ours@1e-10':>11s} {'before':>9s}  "
          f"{'ratio@1.5e-8':>12s} {'ratio@1e-10':>11s}  friction error vs table", file=sys.stderr)
    for name, case in sorted(cases.items()):
        slider, run_default = ours(case, 1e-10)
        _, run_loose = ours(case, 1.49012e-8)
        t = [best(lambda: baseline(case), args.repeat), best(run_loose, args.repeat), best(run_default, args.repeat),
             best(lambda: before(slider), max(1, args.repeat // 2))]
        error = float(np.max(np.abs(run_default().friction - np.array(case["friction"]))))
        totals += t
        rows.append({"case": name, "seconds": dict(zip(("baseline", "ours_rtol_1.5e-8", "ours_rtol_1e-10", "before"), t)),
                     "friction_error": error})
        print(f"{name:24s} {t[0] * 1e3:8.2f}ms {t[1] * 1e3:10.2f}ms {t[2] * 1e3:9.2f}ms {t[3] * 1e3:7.1f}ms  "
              f"{t[0] / t[1]:12.1f} {t[0] / t[2]:11.1f}  {error:.1e}", file=sys.stderr)
    print(f"{'all seven':24s} {totals[0] * 1e3:8.2f}ms {totals[1] * 1e3:10.2f}ms {totals[2] * 1e3:9.2f}ms "
          f"{totals[3] * 1e3:7.1f}ms  {totals[0] / totals[1]:12.1f} {totals[0] / totals[2]:11.1f}", file=sys.stderr)
    print(json.dumps({"cases": rows, "ratio_same_tolerance": totals[0] / totals[1],
                      "ratio_at_default_rtol": totals[0] / totals[2], "speedup_over_before": totals[3] / totals[2]}))


if __name__ == "__main__":
    main()
