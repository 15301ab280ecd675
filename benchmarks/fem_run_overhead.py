"""What a run of a general body costs beyond its kernel (issue 24: target <= 1.5x for runs of
>= 1e4 steps, on a loaded machine too).

The paper's annulus meshed by gmsh (`examples/annulus`, about 10k dofs), f = 0.7:

* kernel: `BodyScheme.advance` over the run's steps in one call (the compiled loop alone,
  after compiling), from a problem whose setup is done;
* `integrate_body`: the whole Python call on a fresh problem (steady sliding, the stable
  step's eigensolve, the run books, checkpoints to a file, the run's result);
* `stickslip fem run`: the command line in a fresh process (imports, config, mesh, the run,
  its file, the classification).

Each ratio is the wall time over the kernel's for the same number of steps, measured in one run,
for each run length asked (the fixed costs -- a fresh process's imports, the mesh, steady
sliding, the eigensolve of the stable step, the file -- weigh less on longer runs).

Usage: ``python benchmarks/fem_run_overhead.py [--size 0.003] [--transits 60 300]``
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "examples" / "annulus"))
import mesh as annulus_mesh  # noqa: E402  (the example's gmsh script)

from stickslip.fem import BodyScheme, integrate_body  # noqa: E402
from stickslip.fem.config import load_config  # noqa: E402
from stickslip.fem.run import perturbed_steady_body  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--size", type=float, default=0.003, help="gmsh mesh size [m] (R = 0.1 m)")
    ap.add_argument("--transits", type=float, nargs="+", default=[60.0, 300.0], help="run lengths in P-wave transits")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        annulus_mesh.make(folder / "annulus.msh", args.size)
        config = folder / "annulus.toml"
        config.write_text((ROOT / "examples" / "annulus" / "annulus.toml").read_text())

        for transits in args.transits:
            measure(config, folder, transits)


def measure(config: Path, folder: Path, transits: float) -> None:
    problem = load_config(config).problem()
    scheme = BodyScheme(problem)
    start = perturbed_steady_body(scheme)
    steps = int(np.ceil(transits * scheme.transit_time / scheme.dt))
    state = scheme.initial_state(start.u, start.v)
    scheme.advance(state, 10)  # compiled
    state = scheme.initial_state(start.u, start.v)
    t0 = time.perf_counter()
    scheme.advance(state, steps)
    kernel = time.perf_counter() - t0
    print(f"{scheme.free.size} free dofs, {steps} steps ({transits:g} transits): kernel {kernel:.2f} s "
          f"({kernel / steps / scheme.free.size * 1e9:.2f} ns per dof-step)")

    for call in ("first", "second"):  # the first in a process imports what its first file needs (xarray: dask)
        fresh = load_config(config).problem()
        t0 = time.perf_counter()
        integrate_body(fresh, transits=transits, checkpoint=folder / "api.nc", overwrite=True)
        api = time.perf_counter() - t0
        print(f"  integrate_body (fresh problem, checkpointed; {call} run of the process): {api:.2f} s, ratio "
              f"{api / kernel:.2f}")

    cli = [sys.executable, "-m", "stickslip", "fem", "run", str(config), "--transits", f"{transits:g}",
           "--out", str(folder / "cli.nc"), "--overwrite"]
    t0 = time.perf_counter()
    subprocess.run(cli, check=True, capture_output=True, env={**os.environ})
    whole = time.perf_counter() - t0
    print(f"  stickslip fem run (fresh process): {whole:.2f} s, ratio {whole / kernel:.2f}")
    print(f"  target <= 1.5 (runs of >= 1e4 steps): integrate_body {api / kernel:.2f}, fem run {whole / kernel:.2f}")

if __name__ == "__main__":
    main()
