"""Finite elements for the brake-like system (paper section 3.1, eqs. [10], [21]-[23]).

The elastic annulus ``R < r < R*`` (plane strain, clamped at ``r = R*``) in unilateral
contact with Coulomb friction on a rigid shaft of radius ``R + d`` turning at ``Omega``,
discretised with scikit-fem (bilinear quadrilaterals on a structured mesh, lumped mass,
polar nodal frames) and integrated with the explicit beta2 scheme [22] and
forward-increment Lagrange multipliers [23], node by node. Units are the paper's:
lengths ``R``, stresses ``E``, time ``1/Omega``. See ``docs/theory/brake-fem.md``.

* `annulus_mesh`, `assemble`: mesh and matrices (`FemSystem`, the general body's assembly in
  polar frames, read as a stencil);
* `annulus_problem`: the annulus as a problem of the general body (`stickslip.fem.ContactProblem`
  in the paper's units), on which its steady sliding, scheme and ParaView output stand;
* `steady_state`: steady sliding (static contact problem), to compare with `brake.reduced.steady`;
* `annulus_frequencies` (exact, Bessel), `fem_frequencies`, `fem_growth_rates`
  (flutter of steady sliding per mode), `slip_wave_rate` (half-space slip waves);
* `FemScheme`, `integrate_fem`, `perturbed_steady`, `FemRun`: time integration with
  checkpoint/resume and progress callback;
* `write_xdmf`: the volume snapshots of a run as an XDMF time series for ParaView (meshio);
* `classify_fem`: the limit regime on the contact nodes (`FemRegime`).

The annulus is a specialisation of the general body (`stickslip.fem`): its assembly, steady
sliding, explicit scheme (`FemScheme` is a `stickslip.fem.scheme.BodyScheme`), run books and
ParaView fields are the general ones; it keeps what is its own: the structured mesh, the
block-circulant stencil (the fast path), the Fourier-block modes, the paper's units and the
campaign. The time stepping, run books and classification are those of `stickslip.contact`. The
paper's Figures 7-10 are in `stickslip.figures.brake`.
"""

from .classify import FemRegime, classify_fem
from .exact import annulus_frequencies
from .halfspace import slip_wave_rate
from .mesh import AnnulusMesh, FemSystem, annulus_mesh, assemble
from .modes import FemGrowth, fem_frequencies, fem_growth_rates, fourier_block, max_frequency
from .paraview import write_xdmf
from .problem import annulus_problem
from .run import FemInitial, FemRun, integrate_fem, perturbed_steady
from .scheme import FemScheme
from .static import FemSteady, steady_state

__all__ = ["AnnulusMesh", "FemSystem", "annulus_mesh", "assemble", "annulus_problem", "FemSteady", "steady_state",
           "annulus_frequencies", "fem_frequencies", "fourier_block", "max_frequency", "FemGrowth",
           "fem_growth_rates", "slip_wave_rate", "FemScheme", "FemInitial", "FemRun", "integrate_fem",
           "perturbed_steady", "FemRegime", "classify_fem", "write_xdmf"]
