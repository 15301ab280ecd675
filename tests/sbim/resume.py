"""A killed in-plane run resumed from its run file (`killed_and_resumed`), for the tests that ask it to
give back the uninterrupted run to the bit."""

from __future__ import annotations

import pytest

from stickslip.sbim import run_inplane
from stickslip.sbim.inplane import partial_run
from stickslip.sbim.runfile import Checkpoint


class Killed(Exception):
    """The run's death, raised by its checkpoint right after a save."""


def killed_and_resumed(problem, steps: int, every: int, kill_at: int, path):
    """``(whole, resumed)``: ``problem()`` run uninterrupted, and run again writing ``path`` at every step,
    killed once its state before step ``kill_at`` is saved, then resumed from the file by a new run."""
    whole = run_inplane(problem(), steps, every=every)
    first = Checkpoint(path, "k", lambda state: partial_run(problem(), state).to_xarray(), seconds=0.0)
    save = first.save

    def dying(state):
        save(state)
        if int(state["step"]) == kill_at:
            raise Killed

    first.save = dying
    with pytest.raises(Killed):
        run_inplane(problem(), steps, every=every, checkpoint=first)
    resumed = run_inplane(problem(), steps, every=every,
                          checkpoint=Checkpoint(path, "k", lambda s: partial_run(problem(), s).to_xarray()))
    return whole, resumed
