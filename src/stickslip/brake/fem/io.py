"""`FemRun` <-> `xarray.Dataset` (the result format is the checkpoint format).

Float64 throughout (and the scheme state ``u, v, a`` and the steady reference ``u_e``
stored), so that a run resumed from its checkpoint is bitwise identical to an
uninterrupted one. Fourier modes are stored as ``_re``/``_im`` (netCDF has no complex).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from ..params import BrakeParams, PhysicalParams
from ..ring_scheme import STATE_NAMES

__all__ = ["run_to_dataset", "dataset_to_run", "settings_key"]

_KEYS = ("chunk", "samples_total", "snap_every", "tail_samples", "samples_per_transit", "modes", "contact",
         "initial", "initial_hash")
_FIELDS = {"U": ("R", "radial displacement u_r at r = R"), "V": ("R", "hoop displacement u_theta at r = R"),
           "Ud": ("R Omega", "radial velocity (u_{m+1} - u_m)/dt at r = R"),
           "Vd": ("R Omega", "hoop velocity (u_{m+1} - u_m)/dt at r = R (shaft surface speed = 1)"),
           "P": ("E", "contact pressure p = lambda_n / (R dtheta)"),
           "Q": ("E", "friction shear q = lambda_t / (R dtheta), positive along the shaft motion"),
           "gap": ("R", "gap u_r - delta at t_{m+1} (where the constraint of the step acts)")}
_KERNEL = ("u", "v", "a", "ref")


def settings_key(run) -> tuple:
    """What must agree for a checkpoint to be resumed (``samples_total`` may grow)."""
    return tuple(run.scheme.key().values()) + tuple(run.settings[k] for k in _KEYS
                                                    if k not in ("samples_total", "tail_samples"))


def _params_attrs(params: BrakeParams) -> dict:
    out = {k: v for k, v in params.to_dict().items() if k != "physical"}
    if params.physical is not None:
        out.update({f"physical_{k}": v for k, v in params.to_dict()["physical"].items()})
    return out


def run_to_dataset(run) -> xr.Dataset:
    s, st, N = run.scheme, run.settings, run.scheme.n_theta
    K = st["modes"] + 1
    ser, snp = run.series, run.snapshots

    def col(store, key, shape, dtype=float):
        return np.asarray(store[key], dtype=dtype) if key in store else np.zeros(shape, dtype)

    data = {
        "energy": ("sample", col(ser, "energy", 0), {"units": "E R^2", "long_name": "energy of the deviation "
                                                     "from FE steady sliding (per unit length in z)"}),
        "kinetic": ("sample", col(ser, "kinetic", 0), {"units": "E R^2", "long_name": "kinetic energy"}),
        "fraction": (("sample", "kind"), col(ser, "fractions", (0, 4)),
                     {"units": "1", "long_name": "fraction of contact nodes in each state"}),
        "state": (("snapshot", "node"), col(snp, "state", (0, N), np.int8),
                  {"long_name": "contact node state", "flag_values": [0, 1, 2, 3],
                   "flag_meanings": " ".join(STATE_NAMES)}),
    }
    for name in ("U", "V"):
        z = col(ser, f"modes_{name}", (0, K), complex)
        for part, arr in (("re", z.real), ("im", z.imag)):
            data[f"modes_{name}_{part}"] = (("sample", "mode"), arr, {"units": "R", "long_name": f"rfft({name})/N"})
    for name, (units, long) in _FIELDS.items():
        data[name] = (("snapshot", "node"), col(snp, name, (0, N)), {"units": units, "long_name": long})
    for name in _KERNEL:
        data[f"kernel_{name}"] = ("dof", run.kernel[name], {"long_name": "scheme state for resuming (polar dofs)"})
    coords = {"t": ("sample", col(ser, "t", 0), {"units": "1/Omega", "long_name": "time Omega t"}),
              "snap_t": ("snapshot", col(snp, "snap_t", 0), {"units": "1/Omega"}),
              "theta": ("node", s.theta, {"units": "rad"}), "kind": ("kind", list(STATE_NAMES)),
              "mode": ("mode", np.arange(K))}
    attrs = {**_params_attrs(s.params), **s.key(), "dt": s.dt, "transit_time": s.transit_time,
             "p_wave_speed": s.p_wave_speed, "mesh": s.system.mesh.describe(), "samples_done": run.samples_done,
             "complete": int(run.complete), **{k: (int(v) if isinstance(v, bool) else v) for k, v in st.items()},
             "source": "FE model of eq. [10], explicit beta2 scheme [22] with multipliers [23] "
                       "(docs/theory/brake-fem.md)"}
    return xr.Dataset(data, coords=coords, attrs=attrs)


def dataset_to_run(cls, ds: xr.Dataset):
    from .scheme import FemScheme

    a = ds.attrs
    physical = {k[len("physical_"):]: float(v) for k, v in a.items() if k.startswith("physical_")}
    params = BrakeParams(float(a["xi"]), float(a["nu"]), float(a["gamma"]), float(a["delta"]), float(a["friction"]),
                         physical=PhysicalParams(**physical) if physical else None)
    scheme = FemScheme(params, int(a["n_theta"]), int(a["n_r"]), float(a["beta2"]), float(a["courant"]))
    settings = {k: (a[k].item() if hasattr(a[k], "item") else a[k]) for k in _KEYS}
    settings["contact"] = bool(settings["contact"])
    series = {"t": ds["t"].values, "energy": ds["energy"].values, "kinetic": ds["kinetic"].values,
              "fractions": ds["fraction"].values}
    for name in ("U", "V"):
        series[f"modes_{name}"] = ds[f"modes_{name}_re"].values + 1j * ds[f"modes_{name}_im"].values
    snapshots = {"snap_t": ds["snap_t"].values, "state": ds["state"].values.astype(np.int8)}
    snapshots.update({name: ds[name].values for name in _FIELDS})
    kernel = {name: ds[f"kernel_{name}"].values.copy() for name in _KERNEL}
    return cls(scheme, settings, series, snapshots, kernel, int(a["samples_done"]))
