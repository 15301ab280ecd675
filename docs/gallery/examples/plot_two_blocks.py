"""
Two blocks, two contacts: a system from a TOML file
===================================================

`stickslip.system` takes mass, stiffness and damping matrices of any size and any number of
frictional contacts. This is ``examples/two_blocks/two_blocks.toml`` of the repository, written
here so the script runs anywhere. Each contact switches exactly between stick and slip.
"""

import numpy as np
from matplotlib.figure import Figure

from stickslip.system import simulate, system_from_dict

system = system_from_dict({
    "mass": [[1.0, 0.0], [0.0, 1.5]],  # kg
    "stiffness": [[3.0, -1.0], [-1.0, 2.0]],  # N/m
    "damping": [[0.06, -0.02], [-0.02, 0.04]],  # N s/m
    "contact": [  # each block on its belt: normal force [N], belt speed [m/s], Coulomb's law
        {"direction": [1.0, 0.0], "normal_force": 2.0, "surface_speed": 0.3, "fs": 0.6, "fd": 0.4},
        {"direction": [0.0, 1.0], "normal_force": 1.0, "surface_speed": 0.1, "fs": 0.6, "fd": 0.4},
    ],
})
run = simulate(system, x0=np.array([0.1, 0.0]), t_end=30.0, samples=3001)
ds = run.to_xarray()
print(ds)

# %%
# Each block's displacement, thick where its contact sticks.
fig = Figure(figsize=(7, 4))
ax = fig.subplots()
for i in range(ds.sizes["dof"]):
    x = ds.x.isel(dof=i).values
    stuck = np.where(ds.contact_state.isel(contact=i).values == 0, x, np.nan)
    ax.plot(ds.t, x, lw=1, label=f"block {i + 1}")
    ax.plot(ds.t, stuck, lw=4, alpha=0.4, color=ax.lines[-1].get_color())
ax.set_xlabel("t [s]")
ax.set_ylabel("x [m]")
ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))
fig.tight_layout()
