"""A killed run resumed from its run file (`killed_and_resumed`), for the tests that ask it to give back
the uninterrupted run to the bit: an in-plane run by default, an antiplane one with ``antiplane=True``."""

from __future__ import annotations

import pytest

from stickslip.sbim import run_antiplane, run_inplane
from stickslip.sbim.antiplane import RUN_FORMAT, partial_antiplane
from stickslip.sbim.inplane import partial_run
from stickslip.sbim.runfile import Checkpoint


class Killed(Exception):
    """The run's death, raised by its checkpoint right after a save."""


def killed_and_resumed(problem, steps: int, every: int, kill_at: int, path, antiplane: bool = False):
    """``(whole, resumed)``: ``problem()`` run uninterrupted, and run again writing ``path`` at every step,
    killed once its state before step ``kill_at`` is saved, then resumed from the file by a new run."""
    run, partial = (run_antiplane, partial_antiplane) if antiplane else (run_inplane, partial_run)
    kind = {"run_format": RUN_FORMAT} if antiplane else {}
    whole = run(problem(), steps, every=every)
    first = Checkpoint(path, "k", lambda state: partial(problem(), state).to_xarray(), seconds=0.0, **kind)
    save = first.save

    def dying(state):
        save(state)
        if int(state["step"]) == kill_at:
            raise Killed

    first.save = dying
    with pytest.raises(Killed):
        run(problem(), steps, every=every, checkpoint=first)
    resumed = run(problem(), steps, every=every,
                  checkpoint=Checkpoint(path, "k", lambda s: partial(problem(), s).to_xarray(), **kind))
    return whole, resumed
