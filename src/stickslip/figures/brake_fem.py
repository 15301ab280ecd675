"""Figures 7-10: the finite element model of section 3.1 (scikit-fem), and a regime map."""

from ..brake.fem import figures as ff
from . import FigureSpec, register

METHOD = ("Plane-strain annulus meshed with bilinear quadrilaterals (scikit-fem assembly, lumped mass, outer radius "
          "clamped), explicit β2-scheme [22] with β2 = 0.9 as in the paper and forward-increment Lagrange "
          "multipliers [23] solved exactly node by node (erratum B5); steel ring R = 0.1 m, R* = 0.15 m (the paper "
          "gives no geometry); runs from FE steady sliding (checked against Lamé) perturbed by noise and by a seeded "
          "mode, budgeted in P-wave transits; the contact conditions verified at every node; the limit regime "
          "classified on the contact nodes. Mesh 512 × 32, 400 transits (quick: 256 × 16, 300).")

register(FigureSpec(
    key="fig7", title="Figure 7 — FE: stick-slip wave with 4 modes (f = 0.2, δ = 0.004, Ω = 1 rad/s)",
    model="brake-like system, finite elements",
    claim="For f = 0.2, δ = 0.004 and Ω = 1 rad/s the limit cycle is a stick-slip wave with 4 modes.",
    method=METHOD, compute=ff.fig7_data, plot=ff.plot_fig7, check=ff.check_fig7, errata=("B5",),
))
register(FigureSpec(
    key="fig8", title="Figure 8 — FE: stick-separation wave with 2 modes (f = 2, δ = 0.004, Ω = 80 rad/s)",
    model="brake-like system, finite elements",
    claim="For a very high friction (f > 1.5), a high angular velocity and a small mismatch, a stick-separation wave; "
          "with 2 modes for f = 2, δ = 0.004, Ω = 80 rad/s.",
    method=METHOD + " For f > 1 steady sliding is ill-posed (half-space slip waves grow at every wavelength), "
                    "so the wavelength is set by the mesh and β2: this is measured and reported.",
    compute=ff.fig8_data, plot=ff.plot_fig8, check=ff.check_fig8, errata=("B5", "W5"),
))
register(FigureSpec(
    key="fig9", title="Figure 9 — FE: stick-slip-separation wave with 8 modes, radial displacement",
    model="brake-like system, finite elements",
    claim="For Ω = 50 rad/s, δ = 0.001 and f = 0.7 a stick-slip-separation wave with 8 modes; the radial "
          "displacement shows the propagation.",
    method=METHOD, compute=ff.fig9_data, plot=ff.plot_fig9, check=ff.check_fig9, errata=("B5",),
))
register(FigureSpec(
    key="fig10", title="Figure 10 — FE: contact pressure of the stick-slip-separation wave",
    model="brake-like system, finite elements",
    claim="The normal contact pressure of the stick-slip-separation wave (zero in the separation zones).",
    method=METHOD + " Same runs as Figure 9.",
    compute=None, data_from="fig9", plot=ff.plot_fig10, check=ff.check_fig10,
))
register(FigureSpec(
    key="brake-fem-regimes", title="Section 3.1 — FE regimes over geometry and shaft speed",
    model="brake-like system, finite elements",
    claim="(Asked by the specification: the paper gives no geometry.) How the limit regime moves when the ring's "
          "thickness ξ = R*/R and the shaft speed Ω change.",
    method="FE runs from noise (f = 0.7, d = 0.1 mm) over ξ and Ω, which enter only through ξ and "
           "κ = d sqrt(E/ρ)/(R² Ω); classification of each limit regime.",
    compute=ff.regime_map_data, plot=ff.plot_regime_map, check=ff.check_regime_map,
))
