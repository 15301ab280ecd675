import json

from stickslip.cli import run


def test_integrate_command_classifies_and_checkpoints(tmp_path, capsys):
    out = tmp_path / "run.nc"
    args = ["brake", "integrate", "--omega", "50", "--mismatch", "1e-4", "--friction", "0.7", "--nodes", "64",
            "--transits", "20", "--out", str(out), "--json"]
    assert run(args) == 0
    first = json.loads(capsys.readouterr().out)
    assert first["regime"].startswith("stick") and out.exists()
    assert run(args) == 0  # resumed from the finished checkpoint: same answer
    assert json.loads(capsys.readouterr().out)["fractions"] == first["fractions"]


def test_integrate_rejects_bad_input(capsys):
    assert run(["brake", "integrate", "--xi", "1.5", "--gamma", "1e-6", "--delta", "0.001", "--nodes", "2"]) == 2
    assert "nodes" in capsys.readouterr().err


def test_fem_command(tmp_path, capsys):
    args = ["brake", "fem", "--omega", "50", "--mismatch", "1e-4", "--friction", "0.7", "--n-theta", "64", "--n-r",
            "4", "--transits", "10", "--out", str(tmp_path / "fem.nc"), "--json"]
    assert run(args) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["regime"] and abs(data["p_mean_over_pe"] - 1) < 0.1 and (tmp_path / "fem.nc").exists()
    assert run(["brake", "fem", "--omega", "50", "--mismatch", "1e-4", "--friction", "0.7", "--n-theta", "30"]) == 2


def test_a_checkpoint_of_another_run_is_refused_and_overwrite_starts_afresh(tmp_path, capsys):
    ck = tmp_path / "ck.nc"
    base = ["brake", "integrate", "--omega", "50", "--mismatch", "1e-4", "--nodes", "32", "--transits", "2",
            "--out", str(ck), "--json"]
    assert run(base + ["--friction", "0.7"]) == 0
    capsys.readouterr()
    assert run(base + ["--friction", "0.5"]) == 2  # another friction: not this run's checkpoint
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and "--out" in err and "overwrite" in err
    assert run(base + ["--friction", "0.5", "--overwrite"]) == 0
    fresh = json.loads(capsys.readouterr().out)
    assert fresh["params"]["friction"] == 0.5
    assert run(base + ["--friction", "0.5"]) == 0  # and now it resumes
    assert json.loads(capsys.readouterr().out) == fresh


def test_overwrite_without_a_checkpoint_is_refused_not_ignored(capsys):
    for command in ("integrate", "fem"):
        assert run(["brake", command, "--omega", "50", "--mismatch", "1e-4", "--overwrite"]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "--overwrite" in err and "without --out" in err, err


def test_a_mesh_whose_step_outruns_the_classification_window_is_refused_up_front(capsys):
    """xi = 1000 on one radial element: one stable step is 11.7 transits, longer than the 2-transit
    window the limit regime is read from (was: refused after the run, naming --transits with a
    value the user never typed)."""
    args = ["brake", "fem", "--omega", "50", "--mismatch", "1e-4", "--friction", "0.7", "--n-theta", "16", "--n-r", "1",
            "--transits", "1", "--xi", "1000"]
    assert run(args) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "invalid mesh" in err and "refine it" in err and "--transits" not in err, err
