"""A friction sweep of a pad on an elastic disc (issue 24): `stickslip fem cea --sweep` on 2
workers against the same points as separate `stickslip fem cea` calls, in one run.

The model is `examples/pad_on_disc/pad_disc.toml` with meshes sized to about 20k dofs in all
(the pad at 2 mm, the disc's rim at ``--rim`` m). The sweep is `friction=0.1:0.8:POINTS`
through `stickslip.sweep.run_sweep` (parallel, with its tracking and the bisections of the
critical values, which cost extra CEAs); the separate calls run one after another, each a
fresh process (as a user running one CEA per edited config would). Printed: the model's size,
both wall times, their ratio (separate / sweep) and the sweep's cost per point.

Usage: ``python benchmarks/fem_pair_sweep.py [--points 41] [--rim 0.001] [--workers 2] [--sweep-only]``
(``--sweep-only``: the sweep's time alone, for comparing versions of it).
"""

from __future__ import annotations

import argparse
import json
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "pad_on_disc"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, default=41)
    parser.add_argument("--rim", type=float, default=0.001)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--sweep-only", action="store_true", help="skip the separate calls")
    args = parser.parse_args()
    stickslip = [sys.executable, "-m", "stickslip"]
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        shutil.copy(EXAMPLE / "pad_disc.toml", tmp)
        subprocess.run([sys.executable, str(EXAMPLE / "mesh.py"), "pad.msh", "0.002"], cwd=tmp, check=True)
        subprocess.run([sys.executable, str(EXAMPLE / "disc.py"), "disc.msh", str(args.rim), "2e-5"], cwd=tmp,
                       check=True)
        from stickslip.fem.config import load_config

        problem = load_config(tmp / "pad_disc.toml").problem()
        dofs = problem.slave.n_dofs + problem.master.n_dofs
        values = np.linspace(0.1, 0.8, args.points)
        start = time.perf_counter()
        done = subprocess.run([*stickslip, "fem", "cea", str(tmp / "pad_disc.toml"), "--sweep",
                               f"friction=0.1:0.8:{args.points}", "--store", str(tmp / "s.zarr"), "--workers",
                               str(args.workers), "--json"], capture_output=True, text=True, check=True)
        sweep = time.perf_counter() - start
        result = json.loads(done.stdout)
        if args.sweep_only:
            print(f"pad on disc, {dofs} dofs, {args.points} friction values, {args.workers} workers: sweep "
                  f"{sweep:.1f} s ({sweep / args.points:.2f} s per point)")
            return
        start = time.perf_counter()
        for value in values:
            text = (tmp / "pad_disc.toml").read_text().replace("friction = 0.5", f"friction = {float(value)!r}")
            (tmp / "one.toml").write_text(text)
            subprocess.run([*stickslip, "fem", "cea", str(tmp / "one.toml"), "--json"], capture_output=True, check=True)
        separate = time.perf_counter() - start
    print(f"pad on disc, {dofs} dofs, {args.points} friction values, {args.workers} workers: sweep {sweep:.1f} s "
          f"({sweep / args.points:.2f} s per point, {len(result.get('critical', []))} critical values located); "
          f"{args.points} separate fem cea calls {separate:.1f} s; ratio separate / sweep = {separate / sweep:.2f}")


if __name__ == "__main__":
    main()
