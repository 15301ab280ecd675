"""Continuation of wave families: zone births and deaths, consistency with direct solves."""

import json
import math

import numpy as np
import pytest

from stickslip.brake import BrakeParams
from stickslip.brake.waves.continuation import continue_waves, with_parameter
from stickslip.brake.waves.zones import Scaling
from stickslip.brake.waves.solve import solve_layout, travelling_wave
from stickslip.errors import ParameterError

START = BrakeParams(xi=1.5, nu=0.3, gamma=1.0, delta=0.12, friction=0.7)


@pytest.fixture(scope="module")
def branch():
    return continue_waves(START, 4, "delta", 0.008, num=30, spacing="log")


def test_branch_goes_through_the_zone_sequences_of_figure_11(branch):
    seqs = [w.structure for w in branch.waves]
    assert seqs[0] == "stick|slip" and seqs[-1] == "stick|slip|separation"
    events = [(e.kind, e.zones, e.before, e.after) for e in branch.events]
    assert events == [
        ("birth", ("reverse-slip",), "stick|slip", "stick|slip|reverse-slip"),
        ("birth", ("slip", "separation"), "stick|slip|reverse-slip", "stick|slip|separation|slip|reverse-slip"),
        ("death", ("slip",), "stick|slip|separation|slip|reverse-slip", "stick|slip|separation|reverse-slip"),
        ("death", ("reverse-slip",), "stick|slip|separation|reverse-slip", "stick|slip|separation"),
    ]
    assert branch.stopped == "" and branch.values[-1] == pytest.approx(0.008)
    assert all(w.valid and w.residual < 1e-9 for w in branch.waves)


def _march(wave, event, offset):
    """Natural continuation of ``wave``'s zone sequence to ``event (1 + offset)``, with steps
    shrinking geometrically toward the event (where a dying zone of zero length is also a
    root of the equations: the steps keep Newton on the branch)."""
    d0 = wave.params.delta
    for d in event * (1 + np.geomspace(d0 / event - 1, offset, 30)):
        wave = solve_layout(with_parameter(START, "delta", d), 4, wave.layout, wave.x)
    return wave


def test_events_are_where_the_old_sequence_stops_being_a_wave(branch):
    for e in branch.events:
        before = [w for v, w in zip(branch.values, branch.waves) if v > e.parameter and w.structure == e.before][-1]
        at = _march(before, e.parameter, 1e-5)
        past = solve_layout(with_parameter(START, "delta", e.parameter * (1 - 1e-3)), 4, at.layout, at.x)
        assert at.valid and not past.valid
        if e.kind == "death":  # two switching points coalesce: the dead zone's length -> 0
            dead = [z.length for z in at.zones if z.kind == e.zones[0]]
            assert min(dead) < 1e-3 * at.period
        if e.cause == "pressure":  # separation is born where P touches 0 inside a slip zone
            assert at.margins["pressure"] < 1e-3


def test_continuation_agrees_with_direct_solves(branch):
    for i in (3, 12, 20, len(branch.waves) - 1):
        w = branch.waves[i]
        direct = travelling_wave(w.params, 4, guess=w.c)
        assert direct.structure == w.structure and direct.c == pytest.approx(w.c, rel=1e-10)


def test_stick_slip_part_has_a_constant_speed(branch):
    c = [w.c for w in branch.waves if w.structure == "stick|slip"]
    assert len(c) >= 3 and np.ptp(c) < 1e-12 * abs(c[0])


def test_continuation_in_omega_follows_the_same_internal_family():
    p = BrakeParams.from_physical(40.0, 1e-6, 0.7)
    br = continue_waves(p, 4, "omega", 100.0, num=6)
    for om, w in zip(br.values, br.waves):
        sc = Scaling(w.params)
        ref = travelling_wave(BrakeParams(1.5, 0.3, 1.0, sc.delta, 0.7), 4, guess=w.c * sc.root_gamma)
        assert w.params.omega == pytest.approx(om)
        assert w.c * sc.root_gamma == pytest.approx(ref.c, rel=1e-10) and w.structure == ref.structure


def test_branch_outputs(branch):
    ds = branch.to_xarray()
    assert ds.sizes["point"] == len(branch.waves) and "delta" in ds.coords
    assert ds["zone_start"].attrs["units"] == "rad" and ds["U_max"].attrs["scale"] == "R"
    assert float(ds["length_separation"][0]) == 0 and float(ds["length_separation"][-1]) > 0
    assert "death of slip" in ds.attrs["events"]
    d = json.loads(json.dumps(branch.to_dict()))
    assert len(d["events"]) == 4 and d["parameter"] == "delta"


def test_end_of_a_family_is_reported():
    br = continue_waves(START.replace(delta=0.03, friction=0.2), 8, "delta", 1e-3, num=12, spacing="log")
    # the stick zone shrinks to nothing: waves without stick are not followed
    assert "stick zone shrinks to nothing" in br.stopped and 1e-3 < br.values[-1] < 0.03
    assert math.isfinite(br.waves[-1].c)


@pytest.mark.parametrize("kwargs, name", [
    (dict(parameter="xi", stop=2.0), "parameter"), (dict(stop=None), "stop"), (dict(num=1), "points"),
    (dict(spacing="cubic"), "spacing"), (dict(stop=-1.0), "delta"), (dict(parameter="omega", stop=3.0), "parameter"),
    (dict(stop=0.0), "stop"), (dict(parameter="friction", stop=0.0, spacing="log"), "spacing")])
def test_bad_input(kwargs, name):
    args = dict(parameter="delta", stop=0.05) | kwargs
    with pytest.raises(ParameterError, match=name):
        continue_waves(START, 4, **args)


def test_start_wave_must_match(branch):
    with pytest.raises(ParameterError, match="wave"):
        continue_waves(START.replace(delta=0.1), 4, "delta", 0.05, wave=branch.waves[0])


def test_continuation_in_friction_agrees_with_direct_solves():
    p = START.replace(delta=1.0, friction=0.2)
    br = continue_waves(p, 4, "friction", 0.3, num=5)
    assert [w.structure for w in br.waves] == ["stick|slip"] * 5 and not br.events
    c = [w.c for w in br.waves]
    assert np.all(np.diff(c) != 0)
    end = travelling_wave(p.replace(friction=0.3), 4, guess=c[-1])
    assert end.c == pytest.approx(c[-1], rel=1e-10)
