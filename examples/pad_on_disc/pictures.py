"""The pictures of `brake.toml` in the docs: a friction sweep with tracked modes and an explicit
run from steady sliding to its limit regime, with ParaView files.

Usage: ``python pictures.py [FOLDER] [--out IMAGES]`` (FOLDER: where the meshes, stores and
runs go, default ``brake-run``; IMAGES: where the PNGs go, default ``FOLDER``). It makes the
meshes, runs

    stickslip fem cea brake.toml --sweep friction=0.1:0.9:9 --store sweep.zarr --out branches.nc --plot map.png
    stickslip fem run brake.toml --transits 300 --amplitude 0.01 --out run.nc --xdmf run.xdmf --xdmf-every 10

and draws ``brake-map.png`` (the stability map of the sweep) and ``brake-run.png`` (the run's
energy and node states over time, and the last snapshot: both bodies deformed, coloured by
their von Mises stress, near the contact). About ten minutes on two cores.
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
from pathlib import Path

import meshio
import numpy as np
import xarray as xr

from stickslip import plotting
from stickslip.contact.states import STATE_NAMES

HERE = Path(__file__).resolve().parent


def stickslip(*args, cwd):
    subprocess.run([sys.executable, "-m", "stickslip", *args], cwd=cwd, check=True)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("folder", nargs="?", default="brake-run")
    ap.add_argument("--out", default=None, help="folder of the PNGs (default: FOLDER)")
    args = ap.parse_args(argv)
    folder = Path(args.folder)
    folder.mkdir(parents=True, exist_ok=True)
    images = Path(args.out or folder)
    images.mkdir(parents=True, exist_ok=True)
    for name in ("mesh.py", "disc.py", "brake.toml"):
        shutil.copy(HERE / name, folder)
    subprocess.run([sys.executable, "mesh.py", "pad_layers.msh", "0.002", "1", "0.004"], cwd=folder, check=True)
    subprocess.run([sys.executable, "disc.py", "disc.msh"], cwd=folder, check=True)
    stickslip("fem", "cea", "brake.toml", "--sweep", "friction=0.1:0.9:9", "--store", "sweep.zarr", "--out",
              "branches.nc", "--plot", str((images / "brake-map.png").resolve()), "--overwrite", cwd=folder)
    stickslip("fem", "run", "brake.toml", "--transits", "300", "--amplitude", "0.01", "--out", "run.nc", "--xdmf",
              "run.xdmf", "--xdmf-every", "10", "--overwrite", "--json", cwd=folder)
    draw_run(folder / "run.nc", folder / "run.xdmf", images / "brake-run.png")


def draw_run(run_file: Path, xdmf: Path, png: Path) -> None:
    """The energy and the node states of the run over time, and its last volume snapshot."""
    with xr.open_dataset(run_file) as ds:
        t, energy, fraction = ds["t"].values, ds["energy"].values, ds["fraction"].values
        kinds = list(STATE_NAMES)  # the columns of fraction
    with meshio.xdmf.TimeSeriesReader(xdmf) as reader:
        points, cells = reader.read_points_cells()
        time, point_data, cell_data = reader.read_data(reader.num_steps - 1)
    fig, (a, b, c) = plotting.new_figure(ncols=3, size=(4.6, 3.8))
    a.semilogy(1e3 * t, np.maximum(energy, 1e-30), lw=1.0)
    a.set(xlabel="time t [ms]", ylabel="energy of the deviation [J/m]", title="growth and saturation")
    for k, name in enumerate(kinds):
        b.plot(1e3 * t, fraction[:, k], lw=0.6, label=name.replace("_", " "))
    b.set(xlabel="time t [ms]", ylabel="fraction of the pad's face [1]", title="contact node states")
    plotting.legend_beside(b, fontsize=9)
    u = point_data["displacement"][:, :2]
    scale = 0.001 / max(np.abs(u).max(), 1e-300)  # the largest displacement drawn as 1 mm
    xy = points[:, :2] + scale * u
    stress = np.concatenate([np.asarray(v) for v in cell_data["von_mises"]])
    triangles = np.concatenate([blk.data for blk in cells if blk.type == "triangle"])
    near = np.all(xy[triangles][:, :, 1] > 0.12, axis=1) & np.all(np.abs(xy[triangles][:, :, 0]) < 0.04, axis=1)
    shown = c.tripcolor(xy[:, 0] * 1e3, xy[:, 1] * 1e3, triangles[near], facecolors=stress[near] / 1e6,
                        cmap="viridis", shading="flat")
    c.set_aspect("equal")
    shown_xy = xy[np.unique(triangles[near])] * 1e3
    c.set_xlim(shown_xy[:, 0].min() - 2, shown_xy[:, 0].max() + 2)
    c.set_ylim(shown_xy[:, 1].min() - 2, shown_xy[:, 1].max() + 2)
    c.set(xlabel="x [mm]", ylabel="y [mm]", title=f"t = {1e3 * time:.2f} ms, u x {scale:.0f}")
    fig.colorbar(shown, ax=c, label="von Mises stress [MPa]")
    plotting.save(fig, png)


if __name__ == "__main__":
    main()
