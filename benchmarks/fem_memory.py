"""Peak memory and wall time of `stickslip fem run` and `stickslip fem cea` on large meshes
(issue 24: at 100k and 300k dofs; 300k once took >= 2.3 GB and did not finish in 10 minutes).

The paper's annulus meshed by gmsh (`examples/annulus`) at the sizes asked; each command runs
in a fresh process whose peak resident memory (``ru_maxrss``) and wall time are printed, with
the memory per dof and the size of the stiffness matrix's arrays for scale (the ratio).

Usage: ``python benchmarks/fem_memory.py [--sizes 0.001 0.00055] [--transits 2]``
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "examples" / "annulus"))
import mesh as annulus_mesh  # noqa: E402  (the example's gmsh script)

ROOT = Path(__file__).resolve().parents[1]

#: Runs one command of the CLI in this process and prints its peak memory [kB] on stderr's last line.
PROBE = """
import resource, sys
from stickslip.cli import run
code = run(sys.argv[1:])
print("MAXRSS", resource.getrusage(resource.RUSAGE_SELF).ru_maxrss, code, file=sys.stderr)
"""


def peak(args: list[str]) -> tuple[float, float, int]:
    """``(peak MB, seconds, exit code)`` of ``stickslip ARGS`` in a fresh process."""
    t0 = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", PROBE, *args], capture_output=True, text=True)
    seconds = time.perf_counter() - t0
    line = [x for x in done.stderr.splitlines() if x.startswith("MAXRSS")]
    if not line:
        raise RuntimeError(done.stderr[-2000:])
    _, kb, code = line[-1].split()
    return int(kb) / 1024.0, seconds, int(code)


def main(argv=None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", type=float, nargs="+", default=[0.001, 0.00055], help="gmsh mesh sizes [m]")
    ap.add_argument("--transits", type=float, default=2.0, help="length of the run [P-wave transits]")
    args = ap.parse_args(argv)
    base, _, _ = peak(["--version"])
    print(f"a fresh process that imports the CLI: {base:.0f} MB")
    for size in args.sizes:
        with tempfile.TemporaryDirectory() as tmp:
            folder = Path(tmp)
            annulus_mesh.make(folder / "annulus.msh", size)
            config = folder / "annulus.toml"
            config.write_text((ROOT / "examples" / "annulus" / "annulus.toml").read_text()
                              .replace("count = 30", "count = 10"))
            from stickslip.fem.config import load_config

            system = load_config(config).problem().system
            dofs, matrix_mb = system.n_dofs, (system.K.data.nbytes + system.K.indices.nbytes) / 2**20
            print(f"mesh size {size:g} m: {dofs} dofs, K {system.K.nnz} entries ({matrix_mb:.0f} MB)")
            for name, extra in (("fem run", ["--transits", f"{args.transits:g}", "--out", str(folder / "r.nc")]),
                                ("fem cea", ["--json"])):
                mb, seconds, code = peak(name.split() + [str(config), *extra])
                print(f"  {name}: peak {mb:.0f} MB ({(mb - base) * 2**20 / dofs:.0f} bytes per dof above a bare "
                      f"process; {mb / matrix_mb:.1f}x K's arrays), {seconds:.1f} s, exit {code}")
    print(json.dumps({"note": "peaks are ru_maxrss of one process per command"}))


if __name__ == "__main__":
    main()
