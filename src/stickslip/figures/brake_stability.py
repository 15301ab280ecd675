"""Beyond the paper: flutter of steady sliding in the brake-like system (growth rate per mode)."""

from ..brake.figures import check_stability, plot_stability, stability_figure_data
from . import FigureSpec, register

register(FigureSpec(
    key="brake-stability", title="Section 3 — flutter instability of steady sliding (reduced model)",
    model="brake-like system, reduced model [12]-[13]",
    claim="The steady sliding solution [11] of the annulus on the rotating shaft is unstable (Moirot 1998, "
          "Moirot et al. 2002), which gives rise to stick, slip and separation zones.",
    method="Linearisation of the corrected reduced model about [16] with all points slipping: per Fourier mode n, "
           "s² + a n² + h + i n f D = 0 (dimensionless time Ωt). Growth rates for the three regimes of §3.1 on a steel "
           "ring R = 0.1 m, R* = 0.15 m; cross-checked against the eigenvalues of the penalised operator on a θ-grid; "
           "the sign of the coupling D against ξ for several ν.",
    compute=stability_figure_data, plot=plot_stability, check=check_stability, errata=("B1", "B3"),
))
