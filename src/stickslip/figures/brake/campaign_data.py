"""Where the figures of the FE campaign (`stickslip.brake.fem.campaign`) find their data.

In order of preference:

1. a campaign run with ``stickslip brake campaign`` into ``<out>/data/brake-fem-campaign/``
   (the default of that command), once every point of its sweep is done;
2. the campaign result stored with the package (``figures/brake/data/*.nc``, exported by
   ``stickslip brake campaign --export``), if the present code computes its numbers: the
   campaign is stored with its canary (`stickslip.brake.fem.campaign.canary`: short seeded runs
   of its cases), which the present code must reproduce to `CANARY_RTOL`; a change of the FE
   code that keeps the numbers (a refactor, a rename, the 3-D work) keeps the stored campaign,
   one that moves them makes it stale and says which run moved and by how much;
3. otherwise a small version computed on the spot (fewer runs, the coarse mesh only), in
   which the paper's claims cannot be settled; the report says so.

`source` describes which one was used, `inputs` fingerprints it for the report's cache.
"""

from __future__ import annotations

import ast
import contextlib
import functools
import hashlib
import sys
import tempfile
from pathlib import Path

import numpy as np
import lazy_loader as lazy

from ...cf import for_file, from_file, stamp
from ...files import to_netcdf
from ...brake.fem.campaign import CANARY_FIELDS, CANARY_RTOL, CANARY_RUNS, CANARY_TRANSITS, canary, canary_changes
from ...contact import REGIME_ATTRS, REGIME_CODES
from ...sweep import verify_store
from .paper import PAPER_REGIMES

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

_REGIME_NAMES = {v: k for k, v in REGIME_CODES.items()}

__all__ = ["CAMPAIGN_DIR", "STORED_DIR", "model_fingerprint", "find", "inputs", "export", "outcome_counts",
           "small_store", "summary", "stored_canary", "present_canary", "canary_verdict", "with_canary"]

#: The campaign's folder inside the report's data folder (``stickslip brake campaign --out``'s default).
CAMPAIGN_DIR = "brake-fem-campaign"
#: The results stored with the package.
STORED_DIR = Path(__file__).parent / "data"


#: The code a campaign's numbers come from (relative to the package), for `model_fingerprint`.
MODEL_CODE = ("brake/fem", "brake/reduced", "fem", "contact", "friction.py", "figures/brake/paper.py")


def _without_docstrings(tree: ast.AST) -> ast.AST:
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if (isinstance(body, list) and body and isinstance(body[0], ast.Expr)
                and isinstance(body[0].value, ast.Constant) and isinstance(body[0].value.value, str)):
            node.body = body[1:] or [ast.Pass()]
    return tree


def model_fingerprint() -> str:
    """Deprecated (0.2; goes in 0.3): a stored campaign is judged by its canary (`canary_verdict`),
    not by a hash of the code's syntax, which changed with every edit of the FE code. SHA-256
    (16 hex digits) of the syntax trees of `MODEL_CODE` without their docstrings."""
    print("stickslip: campaign_data.model_fingerprint is deprecated and goes in 0.3; a stored campaign is "
          "judged by its canary (campaign_data.canary_verdict)", file=sys.stderr)
    root = Path(__file__).resolve().parents[2]
    files = sorted(f for part in MODEL_CODE
                   for f in ((root / part).rglob("*.py") if (root / part).is_dir() else [root / part]))
    digest = hashlib.sha256()
    for f in files:
        digest.update(f.relative_to(root).as_posix().encode())
        digest.update(ast.dump(_without_docstrings(ast.parse(f.read_text(encoding="utf-8")))).encode())
    return digest.hexdigest()[:16]


def _cases(ds: xr.Dataset) -> tuple:
    """The campaign's cases ``(friction, mismatch [m], Omega [rad/s])`` from its attributes."""
    return tuple(zip(*(np.atleast_1d(ds.attrs[f"case_{k}"]).astype(float).tolist()
                       for k in ("friction", "mismatch", "omega"))))


def stored_canary(ds: xr.Dataset) -> dict | None:
    """The canary numbers stored with a campaign (None: stored without one, or with other runs)."""
    if any(f"canary_{name}" not in ds for name in CANARY_FIELDS):
        return None
    runs = tuple(zip(*(ds[f"canary_{k}"].values.tolist() for k in ("case", "xi", "beta2"))))
    if runs != tuple(tuple(float(x) for x in r) for r in CANARY_RUNS) or \
            float(ds.attrs.get("canary_transits", -1)) != CANARY_TRANSITS:
        return None
    return {name: ds[f"canary_{name}"].values.astype(float).tolist() for name in CANARY_FIELDS}


@functools.lru_cache(maxsize=4)
def present_canary(cases: tuple) -> dict:
    """The canary of ``cases`` computed by the present code (once per process: a few seconds)."""
    return canary(cases)


def canary_verdict(ds: xr.Dataset) -> list[str]:
    """Why the present code does not compute the stored campaign ``ds`` (empty: it does): its
    canary's runs that moved beyond `CANARY_RTOL`, or that it has no canary."""
    stored = stored_canary(ds)
    if stored is None:
        return ["the campaign was stored without the canary of the present code's runs "
                f"({len(CANARY_RUNS)} runs of {CANARY_TRANSITS:g} transit)"]
    cases = _cases(ds)
    return canary_changes(stored, present_canary(cases), CANARY_RUNS, cases, CANARY_RTOL)


def with_canary(ds: xr.Dataset) -> xr.Dataset:
    """``ds`` with the canary of its cases computed by the present code, as variables over ``canary_run``."""
    numbers = present_canary(_cases(ds))
    out = ds.drop_vars([v for v in ds.data_vars if str(v).startswith("canary_")])
    run = "canary_run"
    for k, key in enumerate(("case", "xi", "beta2")):
        out[f"canary_{key}"] = (run, np.array([r[k] for r in CANARY_RUNS], float),
                                {"units": "1", "long_name": f"canary run: {key} (case: index of the campaign's cases)"})
    for name, meaning in CANARY_FIELDS.items():
        out[f"canary_{name}"] = (run, np.array(numbers[name]), {"units": "1", "long_name": f"canary run: {meaning}"})
    out.attrs.update({"canary_transits": CANARY_TRANSITS, "canary_rtol": CANARY_RTOL,
                      "canary": "short seeded runs of the cases (stickslip.brake.fem.campaign.canary), "
                                "which the present code must reproduce to canary_rtol"})
    return out


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
        moved = canary_verdict(ds)
        if not moved:
            return ds, (f"the campaign stored with the package ({int(ds['regime'].size)} runs, computed "
                        f"{ds.attrs.get('computed', '?')}, {ds.attrs.get('compute_seconds', float('nan')) / 3600:.1f} h "
                        "of compute; rerun with `stickslip brake campaign`)")
        return None, (f"no campaign for the present code: the stored one's canary moved ({'; '.join(moved)}); "
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
    out = with_canary(ds)
    out.attrs.pop("model_fingerprint", None)
    out.attrs.update({"computed": computed, "compute_seconds": float(np.nansum(ds["seconds"].values))})
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
