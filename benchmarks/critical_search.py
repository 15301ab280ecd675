"""The critical values' search of a tracked CEA sweep (`stickslip.fem.tracking.cea_sweep`) on a
pool of workers: bisection (one CEA per bracket a round, the search before issue 44) against
multisection (each round as many CEAs as the workers: a bracket shrinks k + 1 times a round).

The case: the block on the belt made stiff and damped (the sweep of tests/fem/test_tracking.py:
one branch turns stable at alpha = 673.8 1/s), swept over alpha = 0 ... 1000 in 6 points,
tolerance 1 % of the step, meshed finer than the example (default 0.5 mm: 8.4k dofs, so that a
CEA outweighs handing it to a worker; at the example's 2.5 mm a CEA takes 0.1 s and the
rounds saved are lost in the pool's overhead). The grid's points are computed once; each search then runs on a
copy of that store without any search CEA kept, on the same number of workers, in this run.

``python benchmarks/critical_search.py [WORKERS] [SIZE]`` (default 2 workers, 0.0005 m).
"""

import logging
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from stickslip.fem.tracking import SEARCH, cea_sweep
from stickslip.sweep.offgrid import OffGrid

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "block_on_belt"


class Rounds(logging.Handler):
    def emit(self, record):
        self.message = record.getMessage()


def config(folder: Path, size: float) -> Path:
    subprocess.run([sys.executable, str(EXAMPLE / "mesh.py"), "block.msh", str(size)], cwd=folder, check=True)
    text = (EXAMPLE / "block.toml").read_text()
    text = text.replace("young = 1.0e9", "young = 1.0e12")
    text = text.replace("density = 1000.0", "density = 1000.0\nalpha = 100.0")
    text = text.replace("static_friction = 0.6", 'static_friction = 0.6\nlaw = "stribeck"\nstribeck_speed = 0.2')
    text = text.replace("band = [0.0, 40000.0]", "band = [0.0, 400.0]").replace("count = 30", "count = 10")
    (folder / "stiff.toml").write_text(text)
    return folder / "stiff.toml"


def main(workers: int, size: float) -> None:
    values = np.linspace(0.0, 1000.0, 6)
    handler = Rounds()
    logging.getLogger("stickslip.fem").addHandler(handler)
    logging.getLogger("stickslip.fem").setLevel(logging.INFO)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        cfg = config(tmp, size)
        cea_sweep(cfg, "alpha", values, tmp / "grid.zarr", workers=workers)  # the grid, once
        OffGrid(tmp / "grid.zarr", SEARCH).clear()
        out = {}
        for name, multi in (("bisection", False), ("multisection", True)):
            shutil.copytree(tmp / "grid.zarr", tmp / f"{name}.zarr")
            start = time.perf_counter()
            tracked = cea_sweep(cfg, "alpha", values, tmp / f"{name}.zarr", workers=workers, multisection=multi)
            out[name] = (time.perf_counter() - start, handler.message, float(tracked.critical[0]))
            print(f"{name:13s} {out[name][0]:6.2f} s  critical {out[name][2]:.4f}  ({out[name][1]})")
    exact = 1.0e5 * 0.2 * np.exp(-5.0) / 0.2
    print(f"closed form   critical {exact:.4f}")
    ratio = out["bisection"][0] / out["multisection"][0]
    print(f"wall time bisection / multisection on {workers} workers: {ratio:.2f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 2, float(sys.argv[2]) if len(sys.argv) > 2 else 0.0005)
