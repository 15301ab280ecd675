"""What every periodic interface of `stickslip.sbim` shares: its grid in space and time (`PeriodicGrid`),
its run's samples as a CF dataset (`space_time`) and the check of a run's checkpoint and progress hooks
(`check_hooks`)."""

from __future__ import annotations

import math

import numpy as np

__all__ = ["PeriodicGrid", "space_time", "check_hooks", "check_resumed"]


class PeriodicGrid:
    """The grid of a problem with ``length``, ``elements``, ``beta`` and ``shear_wave_speed``."""

    @property
    def dx(self) -> float:
        return self.length / self.elements

    @property
    def dt(self) -> float:
        return self.beta * self.dx / self.shear_wave_speed

    @property
    def x(self) -> np.ndarray:
        return np.arange(self.elements) * self.dx

    @property
    def wavenumbers(self) -> np.ndarray:
        """``|k|`` of the real FFT's modes [1/m]."""
        return 2.0 * math.pi * np.arange(self.elements // 2 + 1) / self.length


def space_time(run, names: tuple[str, ...], title: str):
    """The fields ``names`` of ``run`` (each ``(t, x)``) with the run's numbers as attributes."""
    import xarray as xr

    from ..cf import finish

    ds = xr.Dataset({name: (("t", "x"), getattr(run, name)) for name in names},
                    coords={"t": run.t, "x": run.problem.x})
    return finish(ds, title, "sbim", params={k: v for k, v in run.to_dict().items() if not isinstance(v, str)})


def check_hooks(checkpoint, progress, call: str = "progress(done, total)", run_format: tuple = ()) -> None:
    """Refuse a ``checkpoint`` without ``resume()``, ``due(step)`` and ``save(state)`` (None: no checkpoint),
    or one whose ``run_format`` (where it has one) is not ``run_format``'s (its value and where it is
    declared), and a ``progress`` that is neither None nor callable (``call`` says how it is called)."""
    from ..errors import ParameterError

    if checkpoint is not None and not all(callable(getattr(checkpoint, m, None)) for m in ("resume", "due", "save")):
        raise ParameterError("checkpoint", checkpoint, "None or an object with resume(), due(step) and save(state) "
                             "(stickslip.sbim.runfile.Checkpoint)")
    kind = getattr(checkpoint, "run_format", None)
    if run_format and kind is not None and kind != run_format[0]:
        raise ParameterError("checkpoint", f"a Checkpoint of run_format {kind!r}", f"one with run_format="
                             f"{run_format[1]} ({run_format[0]!r}): a file keeps one kind of run")
    if progress is not None and not callable(progress):
        raise ParameterError("progress", progress, f"a callable {call} or None")


def check_resumed(state: dict, steps: int, every: int, elements: int, slip: str) -> None:
    """Refuse a resumed ``state`` whose samples or nodes are not those of a run of ``steps`` sampled every
    ``every`` on ``elements`` (another run's kept under the same key); ``slip``: the state's slip array."""
    from ..errors import ParameterError

    done = int(state["step"])
    expected = sum(1 for k in range(min(done, steps + 1)) if k % every == 0 or k == steps)
    if done > steps + 1 or np.size(state["out_t"]) != expected or np.size(state[slip]) != elements:
        raise ParameterError("checkpoint", f"a state at step {done} with {np.size(state['out_t'])} samples of "
                             f"{np.size(state[slip])} nodes", f"one of a run of {steps} steps sampled every {every} "
                             f"on {elements} nodes (another run's kept under the same key)")
