"""A run's samples in space and time as a CF dataset: one builder for every run of `stickslip.sbim`."""

from __future__ import annotations

__all__ = ["space_time"]


def space_time(run, names: tuple[str, ...], title: str):
    """The fields ``names`` of ``run`` (each ``(t, x)``) with the run's numbers as attributes."""
    import xarray as xr

    from ..cf import finish

    ds = xr.Dataset({name: (("t", "x"), getattr(run, name)) for name in names},
                    coords={"t": run.t, "x": run.problem.x})
    return finish(ds, title, "sbim", params={k: v for k, v in run.to_dict().items() if not isinstance(v, str)})
