"""Figure 14 and the maps of the inverse and direct problems (model 3, paper §4-5)."""

from ..halfspace import figures as hf
from . import Check, FigureSpec, register


def _checks(rows_function):
    def check(ds):
        return [Check(name, passed, f"{measured:.6g}" if isinstance(measured, float) else str(measured),
                      f"{expected:.6g}" if isinstance(expected, float) else str(expected), detail)
                for name, passed, measured, expected, detail in rows_function(ds)]
    return check


register(FigureSpec(
    key="fig14", title="Figure 14 — normal stress along the interface of a stick-slip wave",
    model="rigid body on an elastic half-space, Radok potentials",
    claim="For E = 2.1e11 Pa, ρ = 7850 kg/m³, ν = 0.3, μ = 0.5, μ* = 0.4, v* = 0.001 and c̄ = -0.7, the normalised "
          "normal stress Σ_yy/G over the stick-slip segments is weakly singular and shows a positive singularity at "
          "the slip → stick transition, i.e. a narrow zone of separation; all other stick-slip conditions hold.",
    method="The loading follows from [26] (τ*_yy from v*, c̄) and T = (μ − μ*)(−τ*_yy/G); b solves T(b, c̄) = T of "
           "the inverse problem [54]-[55]. The fields come from the periodic canonical function X(z) built here "
           "(not printed in the paper) and are cross-checked against direct quadrature of the Cauchy integral [46]; "
           "the slip condition [40] and the stick condition are verified as residuals, the singularity exponents "
           "measured, the tensile zone located. A second wave with the v that makes the perturbation decay at depth "
           "(erratum H6) is shown for comparison.",
    compute=hf.figure14_data, plot=hf.plot_figure14, check=_checks(hf.check_figure14), errata=("H3", "H6", "H7"),
))

register(FigureSpec(
    key="halfspace-inverse-map", title="Section 5 — the inverse problem over (b, c̄)",
    model="rigid body on an elastic half-space",
    claim="For any b > 1 and -1 < c̄ < 0 the determinant D(b, c̄) of [54]-[55] is negative (H > 0), so (v, T) exists "
          "and is unique; with v* = 0 only the trivial solution exists; closed forms [56]-[58].",
    method="The 2×2 system [54]-[55] solved vectorised on a dense (b, c̄) grid; D and H evaluated; the printed closed "
           "forms for v and T compared with the linear solve; H = γ1 b (K − 1) with K = πλ/sin πλ.",
    compute=hf.inverse_map_data, plot=hf.plot_inverse_map, check=_checks(hf.check_inverse_map),
    errata=("H4", "H5"),
))

register(FigureSpec(
    key="halfspace-direct-map", title="Beyond the paper — the direct problem over the loading plane",
    model="rigid body on an elastic half-space",
    claim="(The paper could not solve it: Newton fails.) Given the loading (T, v, v*), find the wave (c̄, b).",
    method="b eliminated by the second equation, every sign change in c̄ bracketed on a grid and refined by Brent; "
           "the map over (v/v*, T/v*) counts solutions; inverse → direct round trips.",
    compute=hf.direct_map_data, plot=hf.plot_direct_map, check=_checks(hf.check_direct_map), errata=("H4",),
))
