"""Interface dynamics by the spectral boundary integral method: elastic half-spaces whose surfaces
slide, stick and slip in time, periodic along the interface (issue 46; this is its first increment).

Why a package of its own, beside `stickslip.halfspace`: the half-space package holds the paper's
steady stick-slip waves (closed forms, Radok potentials), which this one will take as initial states
and check against; the time-domain method also serves what the paper does not model (two half-spaces
of different materials, faults with rate-and-state friction), as `stickslip.fem` serves bodies of any
shape. The method's name is the one geophysics and tribology use for it (QDYN, cRacklet, uguca).

- `kernels`: the half-space surface's convolution kernels mode by mode (antiplane, mode III), their
  exact step weights and the truncation of their history;
- `antiplane`: a half-space sliding antiplane on a rigid body (or its surface free under an applied
  traction) in time, explicit, with Coulomb, slip-weakening or rate-and-state friction (`run_antiplane`);
- `ratestate`: rate-and-state friction at the nodes (the slip rate that balances the drive, the state
  over a step), shared by the quasi-dynamic and the fully dynamic antiplane runs;
- `quasidynamic`: a rate-and-state interface, antiplane, in the quasi-dynamic approximation (the static
  response and the radiation damping; adaptive steps), on a rigid body or a fault (`run_quasidynamic`).

- `inplane_kernels`: the in-plane (modes I and II) stiffness of the surface and its kernels, by folding
  the Bromwich integral onto the branch cut (the module; its function of the same name is not
  re-exported here, where the name is the module's);
- `inplane`: a half-space sliding in its plane on a rigid body or on a second half-space of another
  material, with unilateral contact (separation and closing) and Coulomb or slip-weakening friction,
  or its surface free (`run_inplane`);
- `surface`: one half-space's material (`Solid`) and its surface in a run (memory, tractions), the
  upper one or the lower one reflected, and how two surfaces meet at the interface;
- `stability`: each mode's recurrence and its roots; a run in which the scheme would grow is refused;
- `interface`: the in-plane interface laws (contact, friction, Prakash and Clifton's regularisation);
- `flutter`: the flutter instability of steady sliding on a rigid body and between two materials
  (Adams'), their dispersion relations and roots, and whether a run's law is well posed;
- `fault`: earthquake cycles on a vertical strike-slip fault with a free surface, quasi-dynamic, rate
  and state varying with depth (`stickslip.sbim.fault.StrikeSlipFault`, `run_fault`);
- `energy`: an antiplane run's energy books (work, strain energy, dissipation, waves);
- `initial`: an in-plane run's state at ``t = 0`` with a past (`InitialState`);
- `waves`: the paper's stick-slip waves (section 4) on a grid, as such a state and as the exact fields
  (`stickslip.sbim.waves.WaveOnGrid`, imported from its module: it loads the half-space's closed forms).

Rate-and-state friction runs fully dynamic antiplane and in-plane (on a rigid body, the contact held
closed, the strength the contact pressure's); not yet between two materials.
"""

from .antiplane import (AntiplaneProblem, AntiplaneRun, Coulomb, FreeSurface, SlipWeakening, mode_traction,
                        run_antiplane, uniform_traction)
from .flutter import (FLUTTER_ONSET, bimaterial_ill_posedness, bimaterial_roots, flutter_growth, flutter_roots,
                      ill_posedness)
from .initial import InitialState
from .inplane import InplaneProblem, InplaneRun, mode_load, patch_load, run_inplane, uniform_load
from .interface import CoulombFriction, PrakashClifton, SlipWeakeningFriction, slip_weakening_lengths
from .inplane_kernels import inplane_kernel_integrals, inplane_stiffness, static_stiffness
from .quasidynamic import QuasiDynamicProblem, QuasiDynamicRun, run_quasidynamic
from .ratestate import RateStateFriction
from .surface import Solid
from .stability import check_stable, growing_roots
from .kernels import antiplane_kernel, antiplane_kernel_integral, ragged_step_weights, step_weights, truncated_part

__all__ = ["AntiplaneProblem", "AntiplaneRun", "Coulomb", "FreeSurface", "SlipWeakening", "mode_traction",
           "run_antiplane", "uniform_traction", "antiplane_kernel", "antiplane_kernel_integral", "step_weights",
           "ragged_step_weights", "truncated_part", "QuasiDynamicProblem", "QuasiDynamicRun", "run_quasidynamic",
           "CoulombFriction", "InplaneProblem", "InplaneRun", "SlipWeakeningFriction", "mode_load", "patch_load",
           "run_inplane", "uniform_load", "inplane_kernel_integrals", "inplane_stiffness", "static_stiffness",
           "check_stable", "growing_roots", "PrakashClifton", "FLUTTER_ONSET", "flutter_growth", "flutter_roots",
           "ill_posedness", "slip_weakening_lengths", "RateStateFriction", "InitialState", "Solid",
           "bimaterial_roots", "bimaterial_ill_posedness"]
