"""The critical values of a tracked CEA sweep (`stickslip.fem.tracking`): where each branch first
turns unstable or stable, located between two points of the sweep by multisection.

Each round places ``k`` values inside every open bracket, splitting it into ``k + 1`` equal
parts, and solves their CEAs together on the pool (``evaluate``); ``k`` is the workers over the
open brackets (rounded up, at least 1: one worker is bisection), so a round keeps every worker
busy and a bracket shrinks ``k + 1`` times per round instead of twice. At each value the
branch's mode is the one of largest MAC with the branch's mode at the next value up (the
bracket's top, then each value down from it); the new bracket is the part where the branch's
state changes, the one nearest the top. A bracket closes when it is within ``tol`` of the
sweep's step (no more values than that takes: the last round of a bracket may place fewer).
A value shared by several brackets (partners turn in the same one) is solved once.

Every CEA can be kept as it finishes (`stored_solve`: in the sweep's store, `OffGrid`) and a
search given the kept ones (``stored``) reuses them instead of solving them again: a search
killed midway and resumed makes the same rounds and computes only what it had not.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import dask
import numpy as np

from .cea import NEUTRAL

__all__ = ["Search", "search", "stored_solve", "unpack", "mac", "unstable", "COUPLING"]

#: A partner's frequency within this (relative) of the branch's at its onset.
COUPLING = 0.05


def mac(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The MAC of every row of ``a`` with every row of ``b``."""
    dot = np.abs(np.conj(a) @ b.T) ** 2
    return dot / np.outer(np.sum(np.abs(a) ** 2, axis=1), np.sum(np.abs(b) ** 2, axis=1))


def unstable(s) -> np.ndarray:
    """Growing: a growth rate above ``NEUTRAL |s|``."""
    return s.real > NEUTRAL * np.abs(s)


@dataclass(frozen=True, eq=False)
class Search:
    """Each branch's ``onset`` (NaN: none), the ``frequency`` there [Hz], its ``partner`` (-1) and
    ``turn`` (+1 unstable, -1 stable as the value grows, 0); the ``rounds`` of the search, the
    CEAs it ``computed`` and those it ``reused`` (kept by an earlier, killed search)."""

    onset: np.ndarray
    frequency: np.ndarray
    partner: np.ndarray
    turn: np.ndarray
    rounds: int
    computed: int
    reused: int


def pack(result) -> dict:
    """A CEA ``(s, sketches)`` as the 1-D float arrays a store keeps."""
    z, x = result
    return {"s_real": z.real, "s_imag": z.imag, "sketch_real": x.real.ravel(), "sketch_imag": x.imag.ravel()}


def unpack(arrays) -> tuple:
    """The CEA ``(s, sketches)`` of `pack`'s arrays."""
    z = arrays["s_real"] + 1j * arrays["s_imag"]
    x = (arrays["sketch_real"] + 1j * arrays["sketch_imag"]).reshape(z.size, -1)
    return z, x


def stored_solve(solve, keep, value: float):
    """``solve(value)``, kept (``keep.add(value, arrays)``, an `OffGrid`) as soon as it is solved."""
    result = solve(value)
    keep.add(value, pack(result))
    return result


def _brackets(values, s, s_points, sketches) -> dict:
    """branch -> [p, lo, hi, mode at hi, its shape, its state]: the first change of state."""
    jobs = {}
    for b in range(len(s)):
        up, known = unstable(s[b]), ~np.isnan(s[b])
        for p in range(len(values) - 1):
            if known[p] and known[p + 1] and up[p] != up[p + 1]:
                shape = sketches[p + 1][int(np.argmin(np.abs(s_points[p + 1] - s[b, p + 1])))]
                jobs[b] = [p, values[p], values[p + 1], s[b, p + 1], shape, up[p + 1]]
                break
    return jobs


def _inside(lo: float, hi: float, step: float, tol: float, per: int) -> list:
    """The values a round places in ``[lo, hi]``: ``per``, or fewer if fewer close it."""
    k = max(1, min(per, math.ceil((hi - lo) / (tol * step)) - 1))
    if k == 1:
        return [0.5 * (lo + hi)]
    return [lo + (hi - lo) * j / (k + 1) for j in range(1, k + 1)]


def search(values, s, s_points, sketches, tol: float, solve, evaluate, width: int = 1, stored=None) -> Search:
    """The critical values of the branches ``s[branch, point]`` over ``values`` (module docstring).

    ``solve(value) -> (s, sketches)`` is one CEA (a top-level callable for a process pool),
    ``evaluate(delayed calls) -> results`` runs a round (`stickslip.sweep.worker_pool`),
    ``width`` is its workers, ``stored`` the ``{value: (s, sketches)}`` solved before."""
    values = np.asarray(values, float)
    jobs = _brackets(values, s, s_points, sketches)
    stored, solved = dict(stored or {}), {}
    rounds = computed = reused = 0
    while True:
        step = {b: values[job[0] + 1] - values[job[0]] for b, job in jobs.items()}
        active = [b for b, job in jobs.items() if job[2] - job[1] > tol * step[b]]
        if not active:
            break
        spans = {tuple(jobs[b][1:3]) + (step[b],) for b in active}
        per = max(1, math.ceil(width / len(spans)))
        inside = {span: _inside(*span, tol, per) for span in spans}
        needed = sorted({v for points in inside.values() for v in points} - set(solved))
        for v in needed:
            if v in stored:
                solved[v] = stored[v]
                reused += 1
        todo = [v for v in needed if v not in solved]
        for v, result in zip(todo, evaluate([dask.delayed(solve)(v) for v in todo])):
            solved[v] = result
        computed += len(todo)
        rounds += 1
        for b in active:
            job = jobs[b]
            for v in reversed(inside[(job[1], job[2], step[b])]):  # down from the top
                z, x = solved[v]
                if not len(z):
                    job[1] = job[2] = v  # no mode at all there: the bracket stops
                    break
                k = int(np.argmax(mac(job[4][None, :], x)[0]))
                if unstable(z[k: k + 1])[0] != job[5]:
                    job[1] = v
                    break
                job[2], job[3], job[4] = v, z[k], x[k]
    return _finish(jobs, s, rounds, computed, reused)


def _finish(jobs, s, rounds, computed, reused) -> Search:
    nb = len(s)
    onset, freq, partner, turn = np.full(nb, np.nan), np.full(nb, np.nan), np.full(nb, -1), np.zeros(nb, int)
    for b, (p, lo, hi, at, _, target) in jobs.items():
        onset[b], freq[b], turn[b] = 0.5 * (lo + hi), at.imag / (2 * math.pi), 1 if target else -1
        rising = bool(target)  # the partner's growth rate goes the other way
        falling = [c for c in range(nb) if c != b and not np.isnan(s[c, p])
                   and not np.isnan(s[c, p + 1]) and (s[c, p + 1].real < s[c, p].real) == rising
                   and abs(s[c, p + 1].imag - s[b, p + 1].imag) <= COUPLING * abs(s[b, p + 1].imag)]
        if falling:
            partner[b] = min(falling, key=lambda c: abs(s[c, p + 1].imag - s[b, p + 1].imag))
    return Search(onset, freq, partner, turn, rounds, computed, reused)
