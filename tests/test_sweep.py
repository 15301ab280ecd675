import json

import numpy as np
import pytest

from stickslip.cli import run
from stickslip.errors import ParameterError
from stickslip.friction import Stribeck
from stickslip.oscillator import Oscillator
from stickslip.oscillator.regimes import classify
from stickslip.sweep import run_sweep

CALLS = []


def _square(x, y):
    CALLS.append((x, y))
    if (x, y) == (3, 20) and CALLS.count((3, 20)) == 1:
        raise KeyboardInterrupt  # a run killed in its last batch
    return {"sum": x + y, "product": x * y}


def test_sweep_resumes_after_a_kill(tmp_path):
    store = tmp_path / "s.zarr"
    CALLS.clear()
    with pytest.raises(KeyboardInterrupt):
        run_sweep(_square, {"x": [1, 2, 3], "y": [10, 20]}, store, outputs={"sum": "1", "product": "1"},
                  batch=2, scheduler="synchronous")
    done_before = len(CALLS)
    ds = run_sweep(_square, {"x": [1, 2, 3], "y": [10, 20]}, store, outputs={"sum": "1", "product": "1"},
                   batch=2, scheduler="synchronous")
    assert ds["done"].all() and np.array_equal(ds["sum"].values, [[11, 21], [12, 22], [13, 23]])
    assert len(CALLS) - done_before == 2  # only the unfinished batch is recomputed
    with pytest.raises(ParameterError, match="store"):
        run_sweep(_square, {"x": [1, 2]}, store, outputs={"sum": "1"}, scheduler="synchronous")


def _powers(x, y):
    CALLS.append((x, y))
    if (x, y) == (2, 20) and CALLS.count((2, 20)) == 1:
        raise KeyboardInterrupt  # killed in its second batch
    return {"powers": [x, x * x, x * y], "sum": x + y}


def test_an_output_of_several_numbers_per_point_is_stored_and_resumed(tmp_path):
    """``(units, size)``: a row per point along ``<name>_index``, resumed like the others."""
    store, outputs = tmp_path / "v.zarr", {"powers": ("1", 3), "sum": "1"}
    CALLS.clear()
    with pytest.raises(KeyboardInterrupt):
        run_sweep(_powers, {"x": [1, 2], "y": [10, 20]}, store, outputs=outputs, batch=2, scheduler="synchronous")
    before = len(CALLS)
    ds = run_sweep(_powers, {"x": [1, 2], "y": [10, 20]}, store, outputs=outputs, batch=2, scheduler="synchronous")
    assert ds["powers"].dims == ("x", "y", "powers_index") and ds["done"].all()
    expected = [[[x, x * x, x * y] for y in (10, 20)] for x in (1, 2)]
    assert np.array_equal(ds["powers"].values, expected) and np.array_equal(ds["sum"].values, [[11, 21], [12, 22]])
    assert len(CALLS) - before == 2  # the killed batch again, not the first
    with pytest.raises(ParameterError, match="3 numbers"):
        run_sweep(lambda x: {"powers": [x], "sum": x}, {"x": [1.0]}, tmp_path / "w.zarr", outputs=outputs,
                  scheduler="synchronous")


def test_a_store_computed_with_other_fixed_parameters_is_refused(tmp_path):
    store = tmp_path / "s.zarr"
    axes, outputs = {"x": [1, 2], "y": [10]}, {"sum": "1", "product": "1"}
    run_sweep(_square, axes, store, outputs=outputs, scheduler="synchronous", attrs={"omega": 50.0, "law": "a"})
    again = run_sweep(_square, axes, store, outputs=outputs, scheduler="synchronous", attrs={"omega": 50.0, "law": "a"})
    assert again["done"].all()
    for attrs in ({"omega": 100.0, "law": "a"}, {"omega": 50.0, "law": "b"}, {"omega": 50.0, "law": "a", "n": 4}):
        with pytest.raises(ParameterError) as err:
            run_sweep(_square, axes, store, outputs=outputs, scheduler="synchronous", attrs=attrs)
        assert err.value.name == "store"


def test_regime_classification_matches_theory():
    base = Oscillator(1.0, 1.0, 1.0, 0.2, Stribeck(0.6, 0.4, 0.1), damping=0.05)
    assert classify(base)["regime"] == 1  # below the Hopf speed: steady sliding unstable
    assert classify(base.replace(belt_speed=0.6))["regime"] == 2  # between Hopf and grazing: bistable
    assert classify(base.replace(belt_speed=1.3))["regime"] == 0  # beyond grazing: steady sliding only


def test_map_command(tmp_path, capsys):
    args = ["oscillator", "map", "--mass", "1", "--stiffness", "1", "--normal-force", "1",
            "--fs", "0.6", "--fd", "0.4", "--law", "stribeck", "--vs", "0.1",
            "--x", "belt_speed=0.2:1.3:3", "--y", "damping=0.04:0.06:2", "--workers", "1",
            "--out", str(tmp_path / "m.zarr"), "--plot", str(tmp_path / "m.png"), "--json"]
    assert run(args) == 0
    data = json.loads(capsys.readouterr().out)
    assert sum(data["counts"].values()) == 6 and data["counts"]["stick-slip"] >= 1
    assert (tmp_path / "m.png").exists()
    assert run(args[:-6] + ["--x", "belt_speed=0.2:1.3", "--out", str(tmp_path / "n.zarr")]) == 2


@pytest.mark.parametrize("axis, words", [("belt_speed=0:1:3", "every value in [1e-12, 1e4] m/s"), ("fs=0.1:0.2:2", ">= fd"),
                                         ("foo=1:2:3", "one of mass")])
def test_map_command_checks_every_point_before_starting(axis, words, tmp_path, capsys):
    """An axis that leaves the valid range is one line naming --x, in the main process (it used to
    fail in a worker, where the error could not even be unpickled: exit 3)."""
    base = {"--mass": "1", "--stiffness": "1", "--normal-force": "1", "--belt-speed": "0.2", "--fs": "0.6", "--fd": "0.4"}
    swept = "--" + axis.split("=")[0].replace("_", "-")  # an axis' own option is left out (it would be refused)
    args = ["oscillator", "map", *[t for k, v in base.items() if k != swept for t in (k, v)], "--x", axis,
            "--out", str(tmp_path / "m.zarr")]
    assert run(args) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "--x" in err and words in err and not (tmp_path / "m.zarr").exists()


def _plain(x, y):
    return {"sum": x + y, "product": x * y}


def _store(tmp_path):
    store = tmp_path / "s.zarr"
    run_sweep(_plain, {"x": [1, 2, 3], "y": [10, 20]}, store, outputs={"sum": "1", "product": "1"},
              scheduler="synchronous")
    return store


def _again(store, **options):
    return run_sweep(_plain, {"x": [1, 2, 3], "y": [10, 20]}, store, outputs={"sum": "1", "product": "1"},
                     scheduler="synchronous", **options)


def _counted(x, y):
    CALLS.append((x, y))
    return {"sum": x + y, "product": x * y}


def _counting(store, **options):
    return run_sweep(_counted, {"x": [1, 2, 3], "y": [10, 20]}, store, outputs={"sum": "1", "product": "1"},
                     scheduler="synchronous", **options)


def test_a_stored_point_whose_content_changed_is_computed_again_and_said(tmp_path, caplog):
    """Issue 25: a value edited, or a chunk lost, in a finished store: the points that no longer
    match their checksum (and only those) are computed again, with a warning; a reader refuses
    the store until then."""
    import zarr

    from stickslip.sweep import verify_store

    store = tmp_path / "s.zarr"
    _counting(store)
    group = zarr.open_group(str(store), mode="r+")
    group["sum"][1, 1] = 999.0  # one value changed: axes and attributes all still match
    with pytest.raises(ParameterError, match="1 point"):
        verify_store(store)
    CALLS.clear()
    with caplog.at_level("WARNING", logger="stickslip.sweep"):
        ds = _counting(store)
    assert CALLS == [(2, 20)] and float(ds["sum"][1, 1]) == 22.0 and ds["done"].all()
    assert "1 stored point(s)" in caplog.text and "(1, 1)" in caplog.text
    verify_store(store)  # intact again
    group["product"][0, 0] = 0.0  # an exact number that happens to be plausible is still found
    group["sum"][2, 0] = np.nan
    CALLS.clear()
    assert float(_counting(store)["product"][0, 0]) == 10.0 and sorted(CALLS) == [(1, 10), (3, 10)]
    chunks = [p for p in (store / "sum").rglob("*") if p.is_file() and not p.name.startswith((".", "zarr"))]
    assert chunks
    for chunk in chunks:
        chunk.unlink()  # a lost chunk reads back as the fill value (NaN): every point computed again
    CALLS.clear()
    assert _counting(store)["done"].all() and len(CALLS) == 6
    ds = _counting(store, overwrite=True)
    assert ds["done"].all() and float(ds["sum"][1, 1]) == 22.0


def test_two_points_whose_records_were_swapped_are_computed_again_and_said(tmp_path, caplog):
    """Issue 44: a tampered store with two points' whole records (every output and the checksum)
    swapped: each record is intact on its own, only its place in the grid is wrong. Both points
    are found (the checksum covers the grid index), computed again and said; the others are not."""
    import zarr

    from stickslip.sweep import verify_store

    store = tmp_path / "s.zarr"
    _counting(store)
    group = zarr.open_group(str(store), mode="r+")
    a, b = (0, 0), (2, 1)  # the points x = 1, y = 10 and x = 3, y = 20
    for name in ("sum", "product", "checksum"):
        first, second = group[name][a], group[name][b]
        group[name][a], group[name][b] = second, first
    assert float(group["sum"][a]) == 23.0 and float(group["sum"][b]) == 11.0  # the swap took place
    with pytest.raises(ParameterError, match="2 point"):
        verify_store(store)
    CALLS.clear()
    with caplog.at_level("WARNING", logger="stickslip.sweep"):
        ds = _counting(store)
    assert sorted(CALLS) == [(1, 10), (3, 20)]
    assert "2 stored point(s)" in caplog.text and "(0, 0)" in caplog.text
    assert np.array_equal(ds["sum"].values, [[11, 21], [12, 22], [13, 23]])
    assert np.array_equal(ds["product"].values, [[10, 20], [20, 40], [30, 60]])
    verify_store(store)


def test_a_store_from_another_format_is_refused(tmp_path):
    import zarr

    store = _store(tmp_path)
    zarr.open_group(str(store), mode="r+").attrs["sweep_format"] = "stickslip-sweep-0"
    with pytest.raises(ParameterError, match="stickslip-sweep-0"):
        _again(store)


def test_a_store_killed_between_a_points_data_and_its_done_flag_resumes(tmp_path):
    """A point's outputs, then its checksum, then ``done``: a kill between any two leaves it not
    done (computed again), never done with unchecked values."""
    import zarr

    store = tmp_path / "s.zarr"
    _counting(store)
    group = zarr.open_group(str(store), mode="r+")
    group["done"][0, 1] = 0  # killed after the outputs and checksum, before done
    group["done"][2, 1] = 0
    group["checksum"][2, 1] = 0  # killed before the checksum
    group["sum"][2, 1] = 5.0
    CALLS.clear()
    ds = _counting(store)
    assert sorted(CALLS) == [(1, 20), (3, 20)] and float(ds["sum"][2, 1]) == 23.0
    group["checksum"][1, 0] = 0  # a done point without its checksum: not trusted
    CALLS.clear()
    assert float(_counting(store)["sum"][1, 0]) == 12.0 and CALLS == [(2, 10)]


def test_a_store_of_the_earlier_layout_is_resumed_when_intact_and_refused_when_not(tmp_path):
    """Stores written before the per-point checksums (``stickslip-sweep-1``, one checksum of
    the whole store) resume without recomputing; one whose content changed is refused (which
    point changed cannot be told)."""
    import zarr

    from stickslip.files import content_digest

    def earlier(path):
        _counting(path)
        group = zarr.open_group(str(path), mode="r+")
        del group["checksum"]
        arrays = {name: group[name][...] for name in group.array_keys()}
        group.attrs.update({"sweep_format": "stickslip-sweep-1", "content_sha256": content_digest(arrays),
                            "pending_sha256": content_digest(arrays)})
        zarr.consolidate_metadata(str(path))
        return group

    earlier(tmp_path / "a.zarr")
    CALLS.clear()
    ds = _counting(tmp_path / "a.zarr")
    assert CALLS == [] and ds["done"].all() and float(ds["sum"][2, 1]) == 23.0
    assert zarr.open_group(str(tmp_path / "a.zarr")).attrs["sweep_format"] == "stickslip-sweep-2"
    group = earlier(tmp_path / "b.zarr")
    group["sum"][0, 0] = 0.0
    with pytest.raises(ParameterError, match="checksum"):
        _counting(tmp_path / "b.zarr")


def test_axes_that_differ_in_the_last_digit_are_another_sweep(tmp_path):
    store = _store(tmp_path)
    with pytest.raises(ParameterError, match="same producer, axes"):
        run_sweep(_plain, {"x": [1, 2, 3 + 1e-9], "y": [10, 20]}, store, outputs={"sum": "1", "product": "1"},
                  scheduler="synchronous")


def _other(x, y):
    return {"sum": x + y, "product": x * y}


def test_a_store_of_another_computation_or_version_is_refused(tmp_path):
    """Another point function (another command), another stickslip version, or the same fixed
    parameters less one: each is another computation, refused in one line."""
    import zarr

    store = tmp_path / "s.zarr"
    axes, outputs = {"x": [1, 2], "y": [10]}, {"sum": "1", "product": "1"}
    run_sweep(_other, axes, store, outputs=outputs, scheduler="synchronous", attrs={"omega": 50.0, "n": 4})
    with pytest.raises(ParameterError, match="same producer"):
        run_sweep(_square, axes, store, outputs=outputs, scheduler="synchronous", attrs={"omega": 50.0, "n": 4})
    with pytest.raises(ParameterError, match="same producer"):
        run_sweep(_other, axes, store, outputs=outputs, scheduler="synchronous", attrs={"omega": 50.0})
    group = zarr.open_group(str(store), mode="r+", use_consolidated=False)
    group.attrs["source"] = "stickslip 0.0.9"
    with pytest.raises(ParameterError, match="written by stickslip"):
        run_sweep(_other, axes, store, outputs=outputs, scheduler="synchronous", attrs={"omega": 50.0, "n": 4})
    again = run_sweep(_other, axes, store, outputs=outputs, scheduler="synchronous", attrs={"omega": 50.0, "n": 4},
                      overwrite=True)
    assert again["done"].all() and again.attrs["source"].startswith("stickslip ")


@pytest.mark.parametrize("given, words", [(["--belt-speed", "0.2"], "--belt-speed"), ([], "--fs")])
def test_map_refuses_an_option_its_axis_overrides_and_needs_the_others(given, words, tmp_path, capsys):
    """--belt-speed with an axis of belt_speed used to be accepted and silently overridden."""
    args = ["oscillator", "map", "--mass", "1", "--stiffness", "1", "--normal-force", "1", "--fd", "0.4",
            *(["--fs", "0.6"] if given else []), *given, "--x", "belt_speed=0.2:0.3:2", "--y", "damping=0.01:0.02:2",
            "--out", str(tmp_path / "m.zarr")]
    assert run(args) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err and not (tmp_path / "m.zarr").exists()
