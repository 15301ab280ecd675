"""A disc brake in three dimensions from one STEP file: a lining on a steel backplate pressed on a
cast-iron disc turning about z (issue 45's example).

`write_step(path)` draws it in millimetres with gmsh's OpenCASCADE API and writes a STEP of three solids,
the disc, the lining and the backplate in that order (nothing is downloaded; gmsh writes no names into a
STEP, so `mesh_step` calls them ``solid1``, ``solid2``, ``solid3``: a CAD tool's STEP has its parts' names); `build(step, pad_size,
disc_size, order)` meshes the pad (lining and backplate in one mesh) and the disc apart from it
(`stickslip.fem.cad.mesh_step`, in metres), assembles both and returns the `PairProblem`: the disc
clamped at its bore (r = 60 mm), the piston face of the backplate pressed at ``pressure`` and held
in its plane (the caliper's abutments), the lining's friction face the slave of the mortar contact
on the disc's upper face, the disc turning at ``omega`` (the pad's middle slides at 110 mm x omega).

The lining is transversely isotropic about its thickness (z); the disc is grey cast iron. The turning
disc's gyroscopic and transport terms are left out here (``gyroscopic=True`` puts them in).

`write_config(folder)` writes the same brake as a config of `stickslip fem` beside the meshes
(``stickslip fem steady brake.toml``, ``stickslip fem cea brake.toml``).

Usage: ``python brake.py [out_folder] [pad_size_mm] [disc_size_mm] [order]``: the steady sliding,
the full CEA in 1-12 kHz, a reduced friction sweep, the energy shares, ParaView and UFF files, an
explicit run to a limit regime (its file and its ParaView snapshots), and the config.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from stickslip.fem import (Load, Material, OrthotropicSolid, PairProblem, Rotation, assemble_solid, read_solid)
from stickslip.fem.cad import mesh_step

#: Millimetres as the CAD draws them: the disc (bore, outer radius, thickness), the pad's footprint
#: (x from -W/2 to W/2, y from Y0 to Y0 + D) and its lining and backplate thicknesses.
BORE, OUTER, DISC = 60.0, 140.0, 12.0
W, Y0, D, LINING, BACKPLATE = 80.0, 90.0, 40.0, 10.0, 5.0
#: The solids' names in the STEP (by their places in the file).
DISC_NAME, LINING_NAME, BACKPLATE_NAME = "solid1", "solid2", "solid3"
DISC_IRON = Material(young=1.1e11, poisson=0.26, density=7200.0)
STEEL = Material(young=2.1e11, poisson=0.3, density=7850.0)
#: A lining stiffer in its plane than through its thickness (axis 3 = z), as measured linings are.
PAD_LINING = OrthotropicSolid(e1=6e9, e2=6e9, e3=2.5e9, nu12=0.25, nu13=0.1, nu23=0.1, g12=2.4e9, g13=1.2e9,
                              g23=1.2e9, density=2500.0)


def write_step(path) -> Path:
    """The disc, the lining and the backplate as one STEP file in millimetres (labelled solids)."""
    import gmsh

    gmsh.initialize(["-noenv"])
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setString("Geometry.OCCTargetUnit", "MM")  # written in millimetres, whatever was set before
        occ = gmsh.model.occ
        outer = occ.addCylinder(0, 0, 0, 0, 0, DISC, OUTER)
        bore = occ.addCylinder(0, 0, 0, 0, 0, DISC, BORE)
        (disc,), _ = occ.cut([(3, outer)], [(3, bore)])
        lining = occ.addBox(-W / 2, Y0, DISC, W, D, LINING)
        backplate = occ.addBox(-W / 2, Y0, DISC + LINING, W, D, BACKPLATE)
        occ.synchronize()
        assert [t for _, t in gmsh.model.getEntities(3)] == [disc[1], lining, backplate]
        gmsh.write(str(path))
    finally:
        gmsh.finalize()
    return Path(path)


def build(step, folder, pad_size: float = 8.0, disc_size: float = 15.0, order: int = 1, friction: float = 0.4,
          pressure: float = 1e6, omega: float = 10.0) -> PairProblem:
    """The brake of ``step`` meshed into ``folder`` (cells of ``pad_size`` and ``disc_size`` mm, of
    ``order`` 1 or 2) as a `PairProblem` (see the module docstring)."""
    folder = Path(folder)
    top = DISC / 1000.0
    pad_mesh = mesh_step(step, folder / "pad.msh", pad_size / 1000.0, order=order, solids=[LINING_NAME, BACKPLATE_NAME],
                         faces={"friction": ("z", top), "piston": ("z", top + (LINING + BACKPLATE) / 1000.0)})
    disc_mesh = mesh_step(step, folder / "disc.msh", disc_size / 1000.0, order=order, solids=[DISC_NAME],
                          faces={"rubbing": ("z", top), "bore": ("r", BORE / 1000.0)})
    pad, disc = read_solid(pad_mesh, "m"), read_solid(disc_mesh, "m")
    slave = assemble_solid(pad, {LINING_NAME: PAD_LINING, BACKPLATE_NAME: STEEL}, loads=[Load("piston", pressure=pressure)])
    master = assemble_solid(disc, DISC_IRON)
    return PairProblem(slave, "friction", master, "rubbing", Rotation(omega), friction=friction,
                       clamped_master=("bore",), rollers_slave={"piston": "xy"})


CONFIG = """# The brake of examples/brake3d as a config of `stickslip fem` (python -m pydoc stickslip.fem.config_solid)
dimension = 3
units = "m"                          # mesh_step writes metres
mesh = "pad.msh"
rollers = {{ piston = "xy" }}        # the caliper's abutments hold the backplate in its plane

[[material]]                         # the lining: transversely isotropic about z
group = "{lining}"
e1 = 6e9
e2 = 6e9
e3 = 2.5e9
nu12 = 0.25
nu13 = 0.1
nu23 = 0.1
g12 = 2.4e9
g13 = 1.2e9
g23 = 1.2e9
density = 2500.0

[[material]]                         # the steel backplate
group = "{backplate}"
young = 2.1e11
poisson = 0.3
density = 7850.0

[contact]
group = "friction"
friction = {friction}

[[load]]
group = "piston"
pressure = {pressure}

[partner]                            # the cast-iron disc, turning about z
mesh = "disc.msh"
group = "rubbing"
clamped = ["bore"]
omega = {omega}
[partner.material]
young = 1.1e11
poisson = 0.26
density = 7200.0

[cea]
band = [1000.0, 12000.0]
count = 30
{reduced}"""


def write_config(folder, friction: float = 0.4, pressure: float = 1e6, omega: float = 10.0,
                 reduced_modes: int | None = None) -> Path:
    """``brake.toml`` in ``folder`` (beside the meshes `build` wrote there): the same brake for the
    command line; with ``reduced_modes``, its CEA the reduced one."""
    path = Path(folder) / "brake.toml"
    path.write_text(CONFIG.format(lining=LINING_NAME, backplate=BACKPLATE_NAME, friction=friction, pressure=pressure,
                                  omega=omega, reduced="" if reduced_modes is None else
                                  f"reduced_modes = {int(reduced_modes)}\n"))
    return path


def main(folder="brake3d", pad_size=8.0, disc_size=15.0, order=1):
    from stickslip.fem import (classify_body, complex_eigenvalues, energy_shares, integrate_pair, modal_basis,
                               reduced_sweep, write_modes_uff)
    from stickslip.fem.paraview import write_modes_xdmf, write_run_xdmf

    folder = Path(folder)
    folder.mkdir(exist_ok=True)
    problem = build(write_step(folder / "brake.step"), folder, float(pad_size), float(disc_size), int(order))
    dofs = problem.slave.n_dofs + problem.master.n_dofs
    steady = problem.steady
    print(f"{dofs} dofs; steady sliding: {int(steady.active.sum())} of {len(steady.active)} lining nodes in contact, "
          f"normal force {steady.normal_force:.1f} N (piston {1e6 * W * D * 1e-6:.1f} N)")
    modes = complex_eigenvalues(problem, (1e3, 12e3), count=30, mode_shapes=True)
    print(f"full CEA 1-12 kHz: {len(modes.s)} modes, {int(modes.unstable.sum())} unstable")
    shares = energy_shares(problem, modes)
    for k in range(min(3, len(modes.s))):
        print(f"  {modes.frequency[k]:8.1f} Hz growth {modes.growth_rate[k]:8.2f} 1/s, strain energy:",
              ", ".join(f"{p} {v:.2f}" for p, v in zip(shares.part.values, shares.strain_share.values[k])))
    tracked = reduced_sweep(modal_basis(problem, 60), np.linspace(0.0, 0.8, 41), band=(1e3, 12e3))
    found = ~np.isnan(tracked.critical)
    for b in np.flatnonzero(found):
        print(f"  branch {b}: critical friction {tracked.critical[b]:.4f} at {tracked.critical_frequency[b]:.1f} Hz")
    write_modes_xdmf(problem, modes, folder / "modes.xdmf")
    write_modes_uff(problem, modes, folder / "modes.uff")
    # an explicit run from steady sliding to a limit regime (central differences: no numerical damping)
    run = integrate_pair(problem, transits=1200.0, beta2=0.5, checkpoint=folder / "run.nc", volume_every=100.0)
    regime = classify_body(run, 200.0)
    print(f"explicit run, {run.t_end * 1e3:.1f} ms: limit regime {regime.regime}, energy of the deviation "
          f"{run.energy[-1]:.3g} J; ParaView: {write_run_xdmf(run, folder / 'run.xdmf')}")
    print(f"the same brake for the command line: {write_config(folder)}")
    return problem, modes, tracked


if __name__ == "__main__":
    main(*sys.argv[1:])
