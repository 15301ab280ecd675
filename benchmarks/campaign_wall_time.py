"""The FE campaign's wall time on its workers against its compute time (issue 25).

Reads a campaign folder written by ``stickslip brake campaign --out FOLDER`` (its Zarr
stores): the compute time is the sum of the runs' own ``seconds``, the wall time from the
store's creation (its ``history``) to its last write. Their ratio is how many workers were
busy on average (2 workers: at most 2).

Usage: ``python benchmarks/campaign_wall_time.py FOLDER``
"""

from __future__ import annotations

import datetime
import sys
from pathlib import Path

import numpy as np
import xarray as xr


def main(folder: str) -> None:
    total_wall = total_compute = 0.0
    for store in sorted(Path(folder).glob("*.zarr")):
        ds = xr.open_zarr(store, consolidated=False)
        created = datetime.datetime.strptime(ds.attrs["history"].split()[0], "%Y-%m-%dT%H:%M:%SZ")
        created = created.replace(tzinfo=datetime.timezone.utc).timestamp()
        last = max(p.stat().st_mtime for p in store.rglob("*") if p.is_file())
        done = int(ds["done"].sum())
        compute = float(np.nansum(ds["seconds"].values))
        wall = last - created
        total_wall += wall
        total_compute += compute
        print(f"{store.name}: {done} of {int(ds['done'].size)} runs, compute {compute / 3600:.2f} h, wall "
              f"{wall / 3600:.2f} h, workers busy on average {compute / wall:.2f}")
    print(f"campaign: compute {total_compute / 3600:.2f} h, wall {total_wall / 3600:.2f} h, ratio "
          f"{total_compute / total_wall:.2f}")


if __name__ == "__main__":
    main(sys.argv[1])
