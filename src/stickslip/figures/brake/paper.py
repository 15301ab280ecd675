"""The parameter sets of the paper's brake figures (SI units, steel ring ``R = 0.1 m``).

The paper prints no geometry for section 3; the figures use the steel ring of
`stickslip.brake.PhysicalParams` (``R = 0.1 m``, ``R* = 0.15 m``, ``E = 2.1e11 Pa``,
``rho = 7850 kg/m^3``, ``nu = 0.3``). For Figures 5, 6, 11 and 12 it prints no parameters
either (except mode 8 for Figure 12): the cases below were chosen from the event maps of
`stickslip.brake.continue_waves` (see ``docs/theory/brake-waves.md``).
"""

__all__ = ["CASES", "PAPER_REGIMES", "FIG5", "FIG6", "FIG11", "FIG12", "GEOMETRY"]

#: (friction f, mismatch d [m], Omega [rad/s]) of the three regimes of section 3.1 (delta = d / R).
CASES = ((0.2, 4e-4, 1.0), (0.7, 1e-4, 50.0), (2.0, 4e-4, 80.0))
#: What the paper's FE gave for CASES: (regime, number of modes).
PAPER_REGIMES = (("stick-slip", 4), ("stick-slip-separation", 8), ("stick-separation", 2))
#: Figure 5, stick-slip: ``delta/sqrt(gamma)`` from 1.03 to 0.26 (reverse slip appears below 0.143).
FIG5 = {"friction": 0.2, "mismatch": 1e-4, "modes": 4, "omegas": (50.0, 100.0, 150.0, 200.0)}
#: Figure 6, stick-slip-separation: ``delta/sqrt(gamma)`` from 0.013 to 0.005 (below the death of reverse slip).
FIG6 = {"friction": 0.7, "mismatch": 1e-6, "modes": 4, "omegas": (40.0, 60.0, 80.0, 100.0)}
#: Figure 11: continuation in the mismatch from 10 um down to 0.25 um.
FIG11 = {"friction": 0.7, "omega": 50.0, "modes": 4, "mismatch": (1e-5, 2.5e-7)}
#: Figure 12: a stick-slip-separation-reverse-slip wave of mode 8.
FIG12 = {"friction": 0.2, "mismatch": 1e-5, "omega": 100.0, "modes": 8}
GEOMETRY = "steel ring R = 0.1 m, R* = 0.15 m, E = 2.1e11 Pa, rho = 7850 kg/m^3, nu = 0.3"
