"""Resumable parameter sweeps: a grid of independent runs, computed with Dask, stored in Zarr.

`run_sweep(func, axes, store, outputs=...)` evaluates ``func(**point)`` at every point of
the grid spanned by ``axes`` and stores each point's outputs in a Zarr store with a ``done``
mask and a checksum per point (`store`). If the run is killed, calling it again with the
same store only computes the points that are not done yet; a stored point whose outputs
no longer match its checksum is computed again, and said so. A store from another program,
version or computation is refused, not resumed.

* `grid`: `run_sweep`: batches through ``dask.compute`` on a local pool (`pool`), or, with
  ``scheduler="distributed"``, an address ``tcp://HOST:PORT`` or a `distributed.Client`,
  every point on dask.distributed (`stream`): each stored as it finishes, one that raises
  stored with its message without stopping the sweep;
* `store`: the store's layout, its per-point checksums and what a resume may trust
  (`verify_store` refuses a damaged store to a reader);
* `pool`: local process pools, and each worker's share of BLAS threads;
* `stream`: the points on dask.distributed.
"""

from .grid import evaluate_point, run_sweep
from .pool import BLAS_THREADS, process_pool, worker_pool
from .store import NOT_COMPUTED, SWEEP_FORMAT, verify_store
from .stream import FLUSH_SECONDS

__all__ = ["run_sweep", "evaluate_point", "process_pool", "worker_pool", "verify_store", "SWEEP_FORMAT", "NOT_COMPUTED",
           "FLUSH_SECONDS", "BLAS_THREADS"]
