"""Section 3.1 with the reduced model: limit regimes of the ring, and their dependence on the start."""

from ..brake import ring_figures as rf
from . import FigureSpec, register

register(FigureSpec(
    key="brake-ring-regimes", title="Section 3.1 — limit regimes of the ring (reduced model, time integration)",
    model="brake-like system, reduced model [12] by the method of lines",
    claim="Direct time integration reaches limit regimes: for f = 0.2, δ = 0.004, Ω = 1 rad/s a stick-slip wave with "
          "4 modes; for f = 0.7, δ = 0.001, Ω = 50 rad/s a stick-slip-separation wave with 8 modes; for f = 2, "
          "δ = 0.004, Ω = 80 rad/s a stick-separation wave with 2 modes (FE results in the paper, Figures 7-10).",
    method="The corrected reduced model [12] on N nodes (second-order differences), explicit β2-scheme [22] with "
           "forward-increment Lagrange multipliers [23] node by node, on a steel ring R = 0.1 m, R* = 0.15 m (the paper "
           "gives no geometry), with the paper's β2 = 0.9 and with central differences (β2 = 1/2); automatic "
           "classification of the last transits (zones, mode number, wave speed, stationarity); wavelength selection "
           "by the scheme's discrete growth rates; a sweep over ξ and Ω. The paper's regimes are FE results: the "
           "report states where the reduced model agrees and where it does not.",
    compute=rf.regimes_data, plot=rf.plot_regimes, check=rf.check_regimes, errata=("B3",),
))

register(FigureSpec(
    key="brake-initial-condition", title="Section 3.1 — the limit regime depends on the initial condition",
    model="brake-like system, reduced model [12] by the method of lines",
    claim="It has been found that the limit regime may be different for two different initial conditions.",
    method="The same parameters (f = 0.7, δ = 0.001, Ω = 50 rad/s, β2 = 0.9) started from steady sliding plus a mode-2 "
           "or a mode-3 perturbation; each run classified over its last transits and checked for statistical "
           "steadiness.",
    compute=rf.initial_condition_data, plot=rf.plot_initial_condition, check=rf.check_initial_condition,
))
