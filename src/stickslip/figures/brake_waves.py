"""Figures 5, 6, 11 and 12: travelling stick-slip(-separation) waves of the reduced model."""

from ..brake import wave_figures as wf
from . import FigureSpec, register

METHOD = ("Multiple shooting with the switching points as unknowns (BOUNDSCO formulation), exact closed forms "
          "inside each zone of the corrected [15], the wave speed found by scanning the period map T(c) = 2π/n; "
          "every inequality of [17]-[20] verified on a fine grid, the zones re-integrated with solve_ivp, the "
          "energy balance over a period (shaft work = sliding + impact dissipation) closed. Steel ring R = 0.1 m, "
          "R* = 0.15 m (the paper gives no parameters; values in stickslip.brake.wave_figures).")

register(FigureSpec(
    key="fig5", title="Figure 5 — phase diagrams (V, V') of stick-slip waves for several Ω",
    model="brake-like system, reduced model, travelling waves",
    claim="Stick-slip travelling waves exist; their phase diagrams (V, V') for different angular velocities Ω "
          "(the text says 'different normal contact pressure', see W4).",
    method=METHOD + " Here f = 0.2, d = 0.1 mm, n = 4, several Ω.",
    compute=wf.fig5_data, plot=wf.plot_fig5, check=wf.check_fig5, errata=("W1", "W4"),
))
register(FigureSpec(
    key="fig6", title="Figure 6 — stick-slip-separation waves in the (U, U') plane",
    model="brake-like system, reduced model, travelling waves",
    claim="Stick-slip-separation waves exist; phase diagrams in the plane of the normal displacement and velocity "
          "(the caption repeats Figure 5's, see W3).",
    method=METHOD + " Here f = 0.7, d = 1 µm, n = 4, several Ω; the landing impact (W2) is part of the wave.",
    compute=wf.fig6_data, plot=wf.plot_fig6, check=wf.check_fig6, errata=("W2", "W3"),
))
register(FigureSpec(
    key="fig11", title="Figure 11 — radial displacement and switching points vs mismatch d",
    model="brake-like system, reduced model, continuation of travelling waves",
    claim="For a very small mismatch d the switching points coalesce, the slip region right of the separation zone "
          "vanishes and one obtains the stick-slip-separation state.",
    method=METHOD + " Continuation in d (f = 0.7, n = 4, Ω = 50 rad/s) with births and deaths of zones located "
                    "where two switching points coalesce; direct solves at the end points agree with the branch.",
    compute=wf.fig11_data, plot=wf.plot_fig11, check=wf.check_fig11,
))
register(FigureSpec(
    key="fig12", title="Figure 12 — mode-8 travelling wave with reverse slip (overshooting)",
    model="brake-like system, reduced model, travelling waves",
    claim="A traveling wave in mode 8 with reverse slip (overshooting), computed by multiple shooting.",
    method=METHOD + " Here f = 0.2, d = 10 µm, Ω = 100 rad/s, n = 8.",
    compute=wf.fig12_data, plot=wf.plot_fig12, check=wf.check_fig12,
))

from ..brake import wave_ring as wr  # noqa: E402

register(FigureSpec(
    key="brake-waves-vs-ring", title="Section 3 — travelling waves against the time integration; their stability",
    model="brake-like system, reduced model: multiple shooting vs method of lines",
    claim="The reduced model admits stick-slip and stick-slip-separation travelling waves, found semi-analytically; "
          "the stability of these waves is an open problem (conclusion of the paper).",
    method="The ring integrator (central differences, contact and friction per node) is started on the waves of "
           "Figures 5, 6 and 12 and must carry them (regime, speed, stick fraction); section 3.1 case 1 integrated "
           "from noise settles on a stationary wave, compared with the shooting wave of the same mode number; the "
           "growth of a small perturbation of each wave measured with an independent Moreau-type stepper.",
    compute=wr.comparison_data, plot=wr.plot_comparison, check=wr.check_comparison,
))
