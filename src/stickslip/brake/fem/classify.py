"""Classification of the limit regime of an FE run, on its contact nodes (paper [17]-[20]).

A `FemRun` keeps the books of `stickslip.contact.runs`, so the shared classifier
`stickslip.contact.classify` applies unchanged: zone fractions and regime name, mode number
(stick zones counted in the frame of the wave) and dominant Fourier mode, wave speed (also
in units of the P-wave speed along ``r = R``, ``c_over_cp``), stationarity. `FemRegime`
adds what is specific to the FE: the number of stick zones per snapshot (its median: robust when the pattern is not a
rigid travelling wave, where the wave-frame count of the ring classifier merges zones), the
dominant Fourier mode of the contact pressure and the pattern speed measured on it, the
contact pressure relative to the steady ``p_e``, and the energy statistics of the window.
"""

from __future__ import annotations

from typing import ClassVar

from dataclasses import dataclass

import numpy as np

from ...results import Result
from ...errors import ParameterError
from .run import FemRun
from ...contact import SEPARATION, STICK, RegimeResult, classify, count_zones, pattern_speed

__all__ = ["FemRegime", "classify_fem"]


@dataclass(frozen=True, repr=False)
class FemRegime(Result):
    """Limit regime of an FE run (fields of `RegimeResult` plus FE-specific numbers).

    ``n_zones``: median number of stick zones (>= ``min_run`` nodes) per snapshot, or of
    contact zones if nothing sticks; ``n_fft_P``: dominant Fourier mode of the contact
    pressure; ``c_P_over_cp``: speed of the pressure pattern (shift of at most
    ``pi / n_fft_P`` between snapshots); ``p_max_over_pe``, ``p_mean_over_pe``:
    largest and mean contact pressure in the window over the steady ``p_e``;
    ``energy_mean``, ``energy_cv``: mean and coefficient of variation of the energy of the
    deviation from steady sliding in the window; ``transits``: length of the run.
    """

    MODEL: ClassVar[str] = "brake"

    result: RegimeResult
    n_zones: int
    n_fft_P: int
    c_P_over_cp: float
    p_max_over_pe: float
    p_mean_over_pe: float
    energy_mean: float
    energy_cv: float
    transits: float

    def __getattr__(self, name):
        return getattr(self.__dict__["result"], name)

    def to_dict(self) -> dict:
        out = self.result.to_dict()
        out.update({k: int(getattr(self, k)) if k.startswith("n_") else float(getattr(self, k))
                    for k in ("n_zones", "n_fft_P", "c_P_over_cp", "p_max_over_pe", "p_mean_over_pe",
                              "energy_mean", "energy_cv", "transits")})
        return out

    def to_xarray(self):
        """The fractions as a variable over ``kind``, every scalar in ``attrs``."""
        ds = self.result.to_xarray()
        ds.attrs.update({k: v for k, v in self.to_dict().items() if k.startswith(("n_", "c_", "p_", "energy_"))})
        ds.attrs["transits"] = float(self.transits)
        ds.attrs["title"] = "FE limit regime"
        return ds


def classify_fem(run, transits: float | None = None, min_fraction: float = 0.01, min_run: int = 2,
                 tol: float = 0.1) -> FemRegime:
    """Classify the last ``transits`` (default: the dense tail) of a `FemRun`.

    Parameters are those of `stickslip.contact.classify` (transits of the FE run:
    ``2 pi R / c_p``).
    """
    if not isinstance(run, FemRun):
        raise ParameterError("run", run, "a FemRun (see integrate_fem)")
    if not run.settings["contact"]:
        raise ParameterError("run", "a run without contact", "a run with contact (contact=True)")
    if run.scheme.params.delta == 0:
        raise ParameterError("delta", 0.0, "> 0 (the limit regime is measured against the steady contact pressure "
                             "p_e, which is zero without interference)")
    res = classify(run, transits, min_fraction, min_run, tol)
    t0, _ = res.window
    s = run.scheme
    snap = run.snap_t >= t0
    ser = run.t >= t0
    pe = float(s.steady.pressure.mean())
    P, state, ts = run.P[snap], run.state[snap], run.snap_t[snap]
    n_fft_P = int(np.argmax(np.mean(np.abs(np.fft.rfft(P, axis=1)[:, 1:]) ** 2, axis=0)) + 1)
    c_P = pattern_speed(P, ts, n_fft_P)
    mask = state == STICK if res.fractions["stick"] >= min_fraction else state != SEPARATION
    zones = int(np.median([count_zones(m, min_run) for m in mask]))
    energy = run.energy[ser]
    return FemRegime(res, zones, n_fft_P, c_P / s.p_wave_speed,
                     float(P.max() / pe), float(P.mean() / pe), float(energy.mean()),
                     float(energy.std() / energy.mean()) if energy.mean() > 0 else 0.0, run.transits)

