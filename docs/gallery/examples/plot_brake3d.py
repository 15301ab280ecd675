"""
A disc brake in three dimensions: which modes squeal, from what friction
========================================================================

A cast-iron disc clamped at its bore and turning, a transversely isotropic lining on a steel
backplate pressed at 1 MPa, drawn in millimetres as one STEP file (``examples/brake3d``), meshed
coarsely so that the page builds in seconds. The modally reduced CEA (60 real modes with the contact
springs, and two static vectors per mode) sweeps the friction coefficient from 0 to 0.8; each mode is
tracked by its shape and its critical friction found by multisection. Left: the growth rates along
the sweep. Right: the out-of-plane displacement of the disc's rubbing face in the mode that grows
fastest at friction 0.8 (its real part; the imaginary part is the same pattern turned: a travelling
wave round the disc).
"""

import sys
import tempfile
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

import stickslip
from stickslip.fem import modal_basis, reduced_modes, reduced_sweep

sys.path.insert(0, str(Path(stickslip.__file__).resolve().parents[2] / "examples" / "brake3d"))
import brake  # noqa: E402  (the example's geometry and materials)

with tempfile.TemporaryDirectory() as folder:
    problem = brake.build(brake.write_step(Path(folder) / "brake.step"), folder, pad_size=8.0, disc_size=15.0)
basis = modal_basis(problem, 60)
tracked = reduced_sweep(basis, np.linspace(0.0, 0.8, 41), band=(1e3, 12e3))
for b in np.flatnonzero(~np.isnan(tracked.critical)):
    print(f"branch {b:2d}: unstable above friction {tracked.critical[b]:.4f} at {tracked.critical_frequency[b]:7.1f} Hz")

modes = reduced_modes(basis, 0.8, band=(1e3, 12e3), mode_shapes=True)
u = problem.displacements(modes.shapes)[:, 0]
disc = problem.master.body
face = disc.nodes("rubbing")
w = u[problem.slave.n_dofs:].reshape(-1, 3)[face, 2]
w = w / np.abs(w).max()
print(f"fastest at friction 0.8: {modes.frequency[0]:.1f} Hz, growth rate {modes.growth_rate[0]:.1f} 1/s")

fig = Figure(figsize=(9, 3.6), layout="constrained")
left, right = fig.subplots(1, 2, width_ratios=[1.3, 1])
for b in range(len(tracked.s)):
    left.plot(tracked.values, tracked.s[b].real, lw=1)
left.axhline(0.0, color="k", lw=0.5)
left.set_xlabel("friction coefficient [1]")
left.set_ylabel("growth rate [1/s]")
left.set_title("reduced CEA, modes tracked (1-12 kHz)")
x, y = 1e3 * disc.points[face, 0], 1e3 * disc.points[face, 1]
dots = right.scatter(x, y, c=w.real, s=6, cmap="coolwarm", vmin=-1, vmax=1)
right.set_aspect("equal")
right.set_xlabel("x [mm]")
right.set_ylabel("y [mm]")
right.set_title(f"disc, out of plane: {modes.frequency[0]:.0f} Hz")
fig.colorbar(dots, ax=right, label="Re w_z (scaled)")
fig

# %%
# A stability map over the friction and the lining's modulus through its thickness (``e3``, of
# the transversely isotropic lining): the brake written as a `stickslip fem` config
# (``brake.write_config``, the reduced CEA of 60 modes), one reduction basis per modulus, the
# friction swept on it, the modes tracked and the onset (the least friction at which a mode turns
# unstable, however slowly it grows there) found by multisection. As ``stickslip fem map brake.toml
# --over e3=1.5e9:4.5e9:5 --friction 0:0.8:17 --store map.zarr`` does, resumably.
from stickslip.fem.maps import stability_map  # noqa: E402
from stickslip.plotting import plot_friction_map  # noqa: E402

with tempfile.TemporaryDirectory() as folder:
    brake.build(brake.write_step(Path(folder) / "brake.step"), folder, pad_size=8.0, disc_size=15.0)
    config = brake.write_config(folder, reduced_modes=60)
    smap = stability_map(config, "material[0].e3", np.linspace(1.5e9, 4.5e9, 5), np.linspace(0.0, 0.8, 17),
                         Path(folder) / "map.zarr", workers=1)
for e3, onset, f in zip(smap["value"].values, smap["onset"].values, smap["onset_frequency"].values):
    print(f"e3 = {e3 / 1e9:.2f} GPa: first unstable at friction {onset:.3f} ({f:.0f} Hz)")
map_figure = plot_friction_map(smap)
map_figure

# %%
# An explicit run of the same brake from steady sliding perturbed by noise (friction 0.4, central
# differences, ``beta2 = 1/2``, which adds no numerical damping): the shared explicit scheme with a
# Coulomb disc per contact node of the lining (`stickslip.fem.pair_run3`). While every node slips the
# run grows as the fastest-growing mode of the whole mesh, here one near 46 kHz (of this coarse mesh,
# far above the squeal band of the sweep above): the CEA that lets the friction force turn with a slip
# across the sliding direction (``transverse_damping``, the disc's linearisation) predicts its rate; the
# default CEA, as commercial codes compute it, finds a faster mode instead. Then nodes separate and the
# growth stops: a limit regime of slip and separation.
import dataclasses  # noqa: E402

from stickslip.fem import complex_eigenvalues, integrate_pair  # noqa: E402
from stickslip.fem.run import classify_body  # noqa: E402

fastest = {}
for across in (False, True):
    cea = complex_eigenvalues(dataclasses.replace(problem, transverse_damping=across), (40e3, 52e3), count=30)
    k = int(np.argmax(cea.growth_rate))
    fastest[across] = (float(cea.growth_rate[k]), float(cea.frequency[k]))
    print(f"CEA {'with' if across else 'without'} transverse_damping: fastest {fastest[across][0]:.0f} 1/s at "
          f"{fastest[across][1]:.0f} Hz")
run = integrate_pair(problem, transits=1500.0, beta2=0.5, amplitude=1e-6, seed=0)
t, energy, separated = run.t, run.energy, run.fractions[:, 3]
low = int(np.argmin(energy[: len(energy) // 4]))  # the noise's decaying part gone, the growth begins
linear = low + int(np.argmax(energy[low:] > 1e6 * energy[low]))  # still small against the saturation
window = slice(low + int(np.argmax(energy[low:] > 1e3 * energy[low])), linear)  # the fastest mode ahead
growth = np.polyfit(t[window], np.log(energy[window]), 1)[0] / 2
print(f"the run grows at {growth:.0f} 1/s from {1e3 * t[window.start]:.2f} to {1e3 * t[linear]:.2f} ms")
regime = classify_body(run, 200.0)
print(f"limit regime over the last 200 transits: {regime.regime}, "
      f"{100 * regime.fractions['separation']:.0f} % of node-time separated")

run_figure = Figure(figsize=(9, 3.4), layout="constrained")
ax, states = run_figure.subplots(1, 2)
ax.semilogy(1e3 * t, energy, lw=1, color="k", label="run")
t0, e0 = t[window.start], energy[window.start]
span = slice(low, min(len(t), linear + (linear - low) // 2))
for across, style in ((False, "--"), (True, ":")):
    rate, hz = fastest[across]
    ax.semilogy(1e3 * t[span], e0 * np.exp(2 * rate * (t[span] - t0)), style,
                label=f"CEA{' + transverse_damping' if across else ''}: {rate:.0f} 1/s ({hz / 1e3:.1f} kHz)")
ax.set_xlabel("time [ms]")
ax.set_ylabel("energy of the deviation [J]")
ax.set_ylim(energy.min() / 2, energy.max() * 5)
ax.legend(fontsize=8)
ax.set_title("from steady sliding to a limit regime")
states.plot(1e3 * t, separated, lw=0.8)
states.set_xlabel("time [ms]")
states.set_ylabel("fraction of lining nodes separated [1]")
states.set_title("contact states")
run_figure
