"""Frictional contact dynamics on any 2-D geometry (`docs/tutorial-your-body.md`).

* `body`: a 2-D elastic body from a mesh file or a `meshio.Mesh` (`read_body`,
  `body_from_meshio`), with named boundary groups, checked on the way in;
* `assembly`: its stiffness, lumped mass and Rayleigh damping in SI units (`Material`,
  `assemble`), plane strain or plane stress;
* `boundary`: springs to the ground and uniform pressure or traction loads on boundary
  groups (`Spring`, `Load`), added by `assemble`;
* `surfaces`: rigid counter-surfaces with prescribed motion (`RigidCylinder`: a shaft, a
  disc rim or a drum; `RigidFlat`: a belt) and the contact frames of a boundary group;
* `static`: the static preload and steady sliding (``q = f p``) with the contact active set
  (`steady_contact`);
* `scheme`: the shared explicit contact scheme on the body's sparse matrices
  (`ContactProblem`, `BodyScheme`);
* `pair`: two deformable bodies in frictional contact (a pad on a disc turning at Omega):
  dual mortar coupling of non-matching meshes, steady sliding and the CEA (`PairProblem`);
* `pair_run`: explicit runs of a pair, the partner Eulerian (`PairScheme`, `integrate_pair`);
* `pair_run3`: explicit runs of two solids, a Coulomb disc per contact node (`SolidPairScheme`, `SolidPairRun`;
  `integrate_pair` takes them);
* `cea`: complex eigenvalue analysis of steady sliding over a frequency band, shift-invert
  Arnoldi (`complex_eigenvalues`), of a body on a rigid surface or of a pair;
* `run`: explicit dynamics with the shared run books, checkpoints and classification
  (`integrate_body`, `classify_body`), from perturbed steady sliding or the preload
  (`perturbed_steady_body`, `preload_body`);
* `paraview`: XDMF time series of a run's volume snapshots and of the CEA mode shapes;
* `solid_stress`: the cells' mean stresses and von Mises stress of a solid at a displacement;
* `prestress`: the stress stiffening of a turning solid's centrifugal prestress (`centrifugal_stiffness`;
  a pair's ``prestress``);
* `config`: the TOML config of `stickslip fem steady | cea | run`;
* `solid`: a 3-D elastic body (tetrahedra or hexahedra, linear or quadratic, a material per cell group,
  its length unit stated), its stiffness and lumped mass, clamps and rollers on face groups and its
  modes (`read_solid`, `assemble_solid`, `supported_dofs`, `solid_supports`, `solid_modes`,
  `solid_static`; orthotropic linings, `OrthotropicSolid`);
* `supports`: the held degrees of freedom of a body or a pair, rollers along coordinate axes or along
  any direction (nodes in frames of their own, `Supports`);
* `cad`: a STEP file's solids meshed in metres by gmsh's OpenCASCADE kernel (`mesh_step`);
* `mortar3`: the mortar coupling of two solids' faces (`PairProblem` takes two solids: steady sliding
  and the full CEA as for 2-D bodies);
* `reduced`: the modally reduced CEA of a pair and its friction sweeps (`modal_basis`, `reduced_modes`,
  `reduced_sweep`);
* `shares`: each mode's kinetic and strain energy by body and cell group (`energy_shares`);
* `uff`: complex mode shapes to the Universal File Format for NVH tools (`write_modes_uff`).
"""

from .assembly import BodySystem, Material, assemble
from .body import CELL_KINDS, Body, body_from_meshio, read_body
from .boundary import Load, Spring
from .cea import CeaModes, complex_eigenvalues
from .pair import PairProblem, PairSteady, Rotation, Translation, steady_pair
from .pair_run import PairRun, PairScheme, integrate_pair
from .pair_run3 import SolidPairRun, SolidPairScheme
from .run import BodyInitial, BodyRun, classify_body, integrate_body, perturbed_steady_body, preload_body
from .scheme import BodyScheme, ContactProblem
from .solid import (OrthotropicSolid, Solid, SolidSystem, assemble_solid, read_solid, solid_damped_modes,
                    solid_from_meshio, solid_modes, solid_static, solid_supports, supported_dofs)
from .supports import Supports
from .reduced import ModalBasis, modal_basis, reduced_modes, reduced_sweep
from .shares import energy_shares
from .static import SteadyContact, steady_contact
from .uff import write_modes_uff
from .surfaces import ContactFrames, RigidCylinder, RigidFlat, contact_frames

__all__ = ["Body", "read_body", "body_from_meshio", "CELL_KINDS", "Material", "BodySystem", "assemble",
           "RigidCylinder", "RigidFlat", "ContactFrames", "contact_frames", "SteadyContact", "steady_contact",
           "ContactProblem", "BodyScheme", "CeaModes", "complex_eigenvalues", "BodyInitial", "BodyRun",
           "integrate_body", "classify_body", "perturbed_steady_body", "preload_body", "Spring", "Load",
           "PairProblem", "PairSteady", "Rotation", "Translation", "steady_pair", "PairScheme", "PairRun",
           "integrate_pair", "ModalBasis", "modal_basis", "reduced_modes", "reduced_sweep", "energy_shares",
           "write_modes_uff", "Solid", "SolidSystem", "read_solid", "solid_from_meshio", "assemble_solid",
           "supported_dofs", "solid_modes", "solid_static", "OrthotropicSolid", "solid_damped_modes", "SolidPairScheme",
           "SolidPairRun", "solid_supports", "Supports"]
