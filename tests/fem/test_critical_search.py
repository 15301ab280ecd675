"""The critical values' search of a tracked CEA sweep (issue 44): multisection on the pool's
workers finds the closed-form onsets of modes whose eigenvalues are known (as bisection does,
in fewer rounds), and a search killed midway and resumed from the sweep's store computes no
CEA twice."""

import logging
import math

import numpy as np
import pytest
import zarr

from stickslip.fem.cea import NEUTRAL
from stickslip.fem.critical import search, stored_solve, unpack
from stickslip.fem.tracking import track
from stickslip.sweep.offgrid import OffGrid

from .test_tracking import stiff_block  # noqa: F401 - the fixture

VALUES = np.linspace(0.0, 1000.0, 6)
TOL = 1e-2
RNG = np.random.default_rng(3)
SHAPES = RNG.standard_normal((3, 32)) + 1j * RNG.standard_normal((3, 32))
#: Three modes s = g (v - c) + i w: one turns unstable (g > 0), one stable, one never changes.
MODES = [(2.0, 473.0, 900.0), (-0.5, 612.0, 400.0), (0.0, 0.0, 100.0)]
CALLS = []


def onset(g, c, w):
    """Where g (v - c) = NEUTRAL |s|: v = c + NEUTRAL w / (|g| sqrt(1 - NEUTRAL^2)) sign(g)."""
    return c + math.copysign(NEUTRAL * w / (abs(g) * math.sqrt(1 - NEUTRAL ** 2)), g)


def modes(v):
    """The CEA of the model at ``v``: its eigenvalues sorted by frequency, their shapes."""
    s = np.array([g * (v - c) + 1j * w for g, c, w in MODES])
    order = np.argsort(s.imag)
    return s[order], SHAPES[order]


def counted(v):
    CALLS.append(v)
    if len(CALLS) == counted.fail_after + 1:
        raise RuntimeError("killed")
    return modes(v)


counted.fail_after = -1


def grid():
    points = [modes(v) for v in VALUES]
    s, _ = track([p[0] for p in points], [p[1] for p in points])
    return s, [p[0] for p in points], [p[1] for p in points]


class Pool:
    """A pool of ``width`` workers run in this process; records each round's CEAs."""

    def __init__(self):
        self.rounds = []

    def __call__(self, calls):
        self.rounds.append(len(calls))
        return tuple(c.compute(scheduler="synchronous") for c in calls)


@pytest.mark.parametrize("width", [1, 2, 3, 4])
def test_multisection_finds_the_closed_form_onsets_as_bisection_does_in_fewer_rounds(width):
    """Two branches change state in brackets of 200 (step): each onset within half the final
    bracket (1 % of the step: 1) of its closed form. One worker: bisection, ceil(log2 100) = 7
    rounds of 2 CEAs. w workers over 2 brackets: ceil(w/2) values a bracket, so a round has >= w
    CEAs (but the last, which places only what closes a bracket) and a bracket shrinks
    ceil(w/2) + 1 times a round: 7, 7, 5, 5 rounds."""
    s, points, sketches = grid()
    pool = Pool()
    found = search(VALUES, s, points, sketches, TOL, modes, pool, width)
    order = np.argsort([m[2] for m in MODES])  # branches in the order of the first point's modes
    for b, (g, c, w) in enumerate(MODES[i] for i in order):
        if g == 0:
            assert np.isnan(found.onset[b]) and found.turn[b] == 0
            continue
        assert abs(found.onset[b] - onset(g, c, w)) <= 0.5 * TOL * 200.0
        assert found.turn[b] == (1 if g > 0 else -1)
        assert found.frequency[b] == pytest.approx(w / (2 * math.pi))
    k = math.ceil(width / 2)
    assert found.rounds == math.ceil(math.log(100) / math.log(k + 1)) == len(pool.rounds)
    assert all(n >= width for n in pool.rounds[:-1])
    assert found.computed == sum(pool.rounds) and found.reused == 0


def test_a_killed_search_resumed_from_the_store_computes_no_cea_twice(tmp_path):
    """Each CEA is kept in the store as it finishes: killed at its 4th CEA (the second of a round
    of 2), the resumed search reuses the 3 and computes the rest, none again; the whole is the
    uninterrupted search's CEAs and onsets (tolerance 5 %: 10 CEAs,
    each write some 10-50 ms)."""
    s, points, sketches = grid()
    whole = search(VALUES, s, points, sketches, 0.05, modes, Pool(), 2)
    zarr.open_group(str(tmp_path / "s.zarr"), mode="w", zarr_format=2)
    keep = OffGrid(tmp_path / "s.zarr", "search")
    solve = lambda v: stored_solve(counted, keep, v)  # noqa: E731 - in this process
    CALLS.clear()
    counted.fail_after = 3
    with pytest.raises(RuntimeError, match="killed"):
        search(VALUES, s, points, sketches, 0.05, solve, Pool(), 2)
    first = list(CALLS[:3])
    CALLS.clear()
    counted.fail_after = -1
    stored = {v: unpack(a) for v, a in OffGrid(tmp_path / "s.zarr", "search").load().items()}
    assert sorted(stored) == sorted(first)
    again = search(VALUES, s, points, sketches, 0.05, solve, Pool(), 2, stored)
    assert not set(CALLS) & set(first)
    assert again.reused == 3 and again.computed == len(CALLS) == whole.computed - 3
    assert np.array_equal(again.onset, whole.onset, equal_nan=True)


@pytest.mark.slow
def test_a_killed_cea_sweep_resumes_its_search_from_the_store(stiff_block, tmp_path, monkeypatch, caplog):  # noqa: F811
    """The FE sweep of test_tracking killed at its search's 3rd CEA: the resumed sweep computes
    none of the 6 points and 2 CEAs again, says it reused 2, and finds the closed-form critical
    damping N (f_s - f_d) e^(-V/v_s) / (v_s m) = 673.79 within the tolerance (2)."""
    from stickslip.fem import tracking

    solve, calls = tracking.complex_eigenvalues, []

    def counting(problem, *args, **kwargs):  # each CEA, by the value of alpha it is solved at
        calls.append(next(iter(problem.system.materials.values())).alpha)
        if len(calls) == counting.fail_after + 1:
            raise RuntimeError("killed")
        return solve(problem, *args, **kwargs)

    counting.fail_after = 8
    monkeypatch.setattr(tracking, "complex_eigenvalues", counting)
    with pytest.raises(RuntimeError, match="killed"):
        tracking.cea_sweep(stiff_block, "alpha", VALUES, tmp_path / "s.zarr", workers=1)
    first, calls[:] = list(calls[:8]), []
    counting.fail_after = -1
    with caplog.at_level(logging.INFO, logger="stickslip.fem"):
        tracked = tracking.cea_sweep(stiff_block, "alpha", VALUES, tmp_path / "s.zarr", workers=1)
    assert len(first) == 8 and calls and not set(calls) & set(first)
    assert "2 reused" in caplog.text
    exact = 1.0e5 * (0.6 - 0.4) * math.exp(-1.0 / 0.2) / 0.2
    assert abs(tracked.critical[0] - exact) <= 2.0


def test_a_search_cea_changed_in_the_store_is_computed_again_and_said(tmp_path, caplog):
    """A kept CEA whose numbers no longer match its checksum (an edited value) is not reused."""
    zarr.open_group(str(tmp_path / "s.zarr"), mode="w", zarr_format=2)
    keep = OffGrid(tmp_path / "s.zarr", "search")
    stored_solve(modes, keep, 300.0)
    stored_solve(modes, keep, 500.0)
    assert sorted(keep.load()) == [300.0, 500.0]
    group = zarr.open_group(str(tmp_path / "s.zarr"), mode="r+")
    point = next(g for _, g in group["search"].groups() if g.attrs["value"] == 500.0)
    point["s_real"][0] = 1.0
    with caplog.at_level(logging.WARNING, logger="stickslip.sweep"):
        assert sorted(keep.load()) == [300.0]
    assert "1 stored off-grid point(s)" in caplog.text
