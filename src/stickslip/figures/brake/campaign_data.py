"""Where the figures of the FE campaign (`stickslip.brake.fem.campaign`) find their data.

In order of preference:

1. a campaign run with ``stickslip brake campaign`` into ``<out>/data/brake-fem-campaign/``
   (the default of that command), once every point of its sweep is done;
2. the campaign result stored with the package (``figures/brake/data/*.nc``, exported by
   ``stickslip brake campaign --export``), if the present code computes what the code that
   produced it did: `model_fingerprint` hashes the bits of short FE runs of the three cases
   (state, reactions, classification), so a refactor that changes no number keeps the
   stored result valid and any change of the numbers makes it stale;
3. otherwise a small version computed on the spot (fewer runs, the coarse mesh only), in
   which the paper's claims cannot be settled; the report says so.

`source` describes which one was used, `inputs` fingerprints it for the report's cache.
"""

from __future__ import annotations

import ast
import contextlib
import functools
import hashlib
import tempfile
from pathlib import Path

import numpy as np
import xarray as xr

from ...brake import BrakeParams
from ...cf import for_file, from_file, stamp
from ...files import to_netcdf
from ...brake.fem import FemScheme, classify_fem, integrate_fem, perturbed_steady
from ...brake.fem.campaign import limit_regime
from ...contact import REGIME_ATTRS, REGIME_CODES
from ...sweep import verify_store
from .paper import CASES, PAPER_REGIMES

_REGIME_NAMES = {v: k for k, v in REGIME_CODES.items()}

__all__ = ["CAMPAIGN_DIR", "STORED_DIR", "model_fingerprint", "find", "inputs", "export", "outcome_counts",
           "small_store", "summary"]

#: The campaign's folder inside the report's data folder (``stickslip brake campaign --out``'s default).
CAMPAIGN_DIR = "brake-fem-campaign"
#: The results stored with the package.
STORED_DIR = Path(__file__).parent / "data"


@functools.lru_cache(maxsize=1)
def model_fingerprint() -> str:
    """SHA-256 (16 hex digits) of what the FE code computes: the bits of the final state, the
    reactions and the classification of 12-transit runs of the three cases on a 32 x 2 mesh,
    started as the campaign's runs are (white noise, seed 0), and of the campaign's outcome
    record of a run stopped at its first check."""
    digest = hashlib.sha256()
    for f, d, om in CASES:
        p = BrakeParams.from_physical(om, d, f)
        run = integrate_fem(p, 32, 2, transits=12.0, initial=perturbed_steady(FemScheme(p, 32, 2), seed=0))
        for name in ("u", "v", "a"):
            digest.update(run.kernel[name].tobytes())
        digest.update(run.P.tobytes() + run.Q.tobytes() + run.state.tobytes())
        digest.update(repr(classify_fem(run).to_dict()).encode())
        digest.update(repr(sorted((k, v) for k, v in limit_regime(p, 32, 2, 0, min_transits=6.0, chunk=2.0,
                                                                     max_transits=6.0).items()
                                  if k != "seconds")).encode())
    return digest.hexdigest()[:16]


def _complete_store(path: Path) -> xr.Dataset | None:
    if not path.exists():
        return None
    verify_store(path)  # a damaged campaign is refused, never read silently
    try:
        ds = xr.open_zarr(path, consolidated=False).load()
    except (OSError, ValueError, KeyError):
        return None
    return ds if "done" in ds and bool(ds["done"].all()) else None


def find(kind: str, data_dir: Path | None) -> tuple[xr.Dataset | None, str]:
    """The campaign dataset ``kind`` (``statistics`` or ``geometry``) and where it comes from,
    or ``(None, reason)`` when only the small version is possible."""
    if data_dir is not None:
        store = Path(data_dir) / CAMPAIGN_DIR / f"{kind}.zarr"
        ds = _complete_store(store)
        if ds is not None:
            return ds, f"the campaign in {store} ({int(ds['done'].size)} runs)"
    stored = STORED_DIR / f"fem_{kind}.nc"
    if stored.exists():
        ds = _tidy(from_file(xr.load_dataset(stored)))
        if ds.attrs.get("model_fingerprint") == model_fingerprint():
            return ds, (f"the campaign stored with the package ({int(ds['regime'].size)} runs, computed "
                        f"{ds.attrs.get('computed', '?')}, {ds.attrs.get('compute_seconds', float('nan')) / 3600:.1f} h "
                        "of compute; rerun with `stickslip brake campaign`)")
        return None, (f"no campaign for the present code: the stored one was computed with other FE code "
                      f"(fingerprint {ds.attrs.get('model_fingerprint')}, now {model_fingerprint()}); "
                      "rerun `stickslip brake campaign`")
    return None, "no campaign found: run `stickslip brake campaign` (about an hour)"


def _tidy(ds: xr.Dataset) -> xr.Dataset:
    """A campaign stored by an earlier version in the present layout: its parameters written as
    Python text become numbers, its regime codes get their flags (the values are unchanged)."""
    for key in ("cases", "meshes", "budgets", "budget"):
        text = ds.attrs.pop(key, None)
        if not isinstance(text, str):
            continue
        value = ast.literal_eval(text)
        if key == "budgets":
            ds.attrs.update({f"mesh{m}_{k}": float(v) for m, b in enumerate(value) for k, v in sorted(b.items())})
        elif key == "budget":
            ds.attrs.update({f"budget_{k}": float(v) for k, v in sorted(value.items())})
    for key in ("regime_codes", "regime_code_values"):
        ds.attrs.pop(key, None)
    ds["regime"].attrs.update(REGIME_ATTRS)
    return ds


@contextlib.contextmanager
def small_store(cache: Path | None):
    """Where the small version's sweep is stored: the report's cache folder (kept, so a killed
    report resumes), else a temporary folder removed afterwards (with the runs' checkpoints)."""
    if cache is not None:
        yield Path(cache) / "small.zarr"
        return
    with tempfile.TemporaryDirectory(prefix="stickslip-campaign-") as tmp:
        yield Path(tmp) / "small.zarr"


def inputs(kind: str, data_dir: Path | None) -> str:
    """A fingerprint of the data `find` would use (the report recomputes a figure when it changes)."""
    ds, where = find(kind, data_dir)
    if ds is None:
        return "small"
    return hashlib.sha256((where + repr(np.asarray(ds["regime"].values).tolist())).encode()).hexdigest()[:16]


def export(ds: xr.Dataset, kind: str, folder: Path, computed: str) -> Path:
    """Write a finished campaign dataset as ``fem_<kind>.nc`` with its provenance."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    out = ds.copy()
    out.attrs.update({"model_fingerprint": model_fingerprint(), "computed": computed,
                      "compute_seconds": float(np.nansum(ds["seconds"].values))})
    path = folder / f"fem_{kind}.nc"
    to_netcdf(for_file(stamp(out, f"exported by stickslip brake campaign ({kind})")), path)
    return path


def outcome_counts(ds, case: int, mesh: int) -> dict:
    """``{(regime name, n_zones): (runs, stationary runs)}`` for one case and mesh."""
    sel = ds.isel(case=case, mesh=mesh)
    out: dict = {}
    for code, n, st in zip(sel["regime"].values, sel["n_zones"].values, sel["stationary"].values):
        key = (_REGIME_NAMES.get(int(code), "other") if np.isfinite(code) else "unclassified",
               int(n) if np.isfinite(n) else -1)
        runs, stationary = out.get(key, (0, 0))
        out[key] = (runs + 1, stationary + int(st))
    return dict(sorted(out.items(), key=lambda kv: -kv[1][0]))


def summary(ds: xr.Dataset, kind: str) -> dict:
    """Runs, compute hours and, for the statistics, the fraction of runs per case and mesh that
    reach the paper's regime and mode number (what ``stickslip brake campaign`` prints)."""
    out = {"runs": int(ds["regime"].size), "compute_hours": float(np.nansum(ds["seconds"].values) / 3600)}
    if kind != "statistics":
        return out
    reached = {}
    for c, (regime, modes) in enumerate(PAPER_REGIMES):
        for m, (a, b) in enumerate(zip(ds.attrs["mesh_n_theta"], ds.attrs["mesh_n_r"])):
            counts = outcome_counts(ds, c, m)
            runs = sum(k for k, _ in counts.values())
            reached[f"case {c + 1} on {a} x {b}"] = {
                "paper": f"{regime} {modes}", "reached": counts.get((regime, modes), (0, 0))[0] / runs,
                "stationary": float(ds["stationary"].isel(case=c, mesh=m).mean()),
                "most_frequent": " ".join(map(str, next(iter(counts))))}
    out["paper_outcome"] = reached
    return out
