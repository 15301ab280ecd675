import json
from pathlib import Path

import pytest

from stickslip.cli import run
from stickslip.errata import ERRATA, to_markdown
from stickslip.figures import registry

ROOT = Path(__file__).resolve().parents[1]


def test_errata_doc_is_generated_from_the_list():
    assert (ROOT / "docs" / "errata.md").read_text() == to_markdown()


def test_every_erratum_names_existing_tests():
    for erratum in ERRATA:
        assert erratum.tests, erratum.id
        for node in erratum.tests:
            path, _, name = node.partition("::")
            assert name and f"def {name}(" in (ROOT / path).read_text(), node


def test_reproduce_one_figure_and_resume(tmp_path, capsys):
    code = run(["reproduce", "--out", str(tmp_path), "--quick", "--only", "fig2", "--json"])
    summary = json.loads(capsys.readouterr().out)
    assert code == 0 and summary["passed"] and summary["figures"][0]["cached"] is False
    for name in ("report.md", "report.html", "fig2.png", "data/fig2.nc"):
        assert (tmp_path / name).exists(), name
    report = (tmp_path / "report.md").read_text()
    assert "The paper's claim" in report and "E1" in report and "| pass |" in report
    # a second run (as after a kill) reuses the checkpoint
    code = run(["reproduce", "--out", str(tmp_path), "--quick", "--only", "fig2", "--json"])
    assert json.loads(capsys.readouterr().out)["figures"][0]["cached"] is True


def test_each_figure_says_when_it_starts_and_ends_as_it_goes(tmp_path, capsys, monkeypatch):
    """Issue 47: a log without a terminal (capsys is none) shows each figure's start and end as the
    run goes, not at its end: a run killed in its second figure has said that the first ended
    (with its checks) and that the second started."""
    from stickslip.figures.oscillator import fig3

    def killed(quick, **options):
        raise KeyboardInterrupt

    monkeypatch.setattr(fig3, "compute", killed)
    assert run(["reproduce", "--out", str(tmp_path), "--quick", "--only", "fig2,fig3", "--workers", "1"]) == 130
    err = capsys.readouterr().err.splitlines()
    started = [line for line in err if line.startswith("fig2: started") or line.startswith("fig3: started")]
    assert [line.split(":")[0] for line in started] == ["fig2", "fig3"] and "figure 2 of 2" in started[1], err
    ended = next(line for line in err if line.startswith("fig2: done"))
    assert "10 of 10 checks pass" in ended and err.index(ended) < err.index(started[1]), err


@pytest.mark.slow  # 8 to 14 s: the fast set's margin to its 4 minutes (issue 47)
def test_figures_computed_in_two_processes_are_recorded_as_computed_one_after_another(tmp_path, capfd):
    """Issue 47: --workers 2 computes the figures in worker processes (each logs its start) and
    this process plots, checks and records them: the same checks and numbers as one after
    another, nothing from a checkpoint."""
    together, apart = tmp_path / "together", tmp_path / "apart"
    for folder, workers in ((together, "1"), (apart, "2")):
        assert run(["reproduce", "--out", str(folder), "--quick", "--only", "fig2,fig3", "--workers", workers,
                    "--json"]) == 0
    out, err = capfd.readouterr()
    for key in ("fig2", "fig3"):
        records = [json.loads((f / "data" / f"{key}.report.json").read_text()) for f in (together, apart)]
        assert [(c["name"], c["passed"], c["measured"]) for c in records[0]["checks"]] == \
            [(c["name"], c["passed"], c["measured"]) for c in records[1]["checks"]]
        assert not records[1]["cached"] and f"{key}: started" in err and f"{key}: done" in err


def test_unknown_figure_is_a_usage_error(tmp_path, capsys):
    code = run(["reproduce", "--out", str(tmp_path), "--only", "fig99"])
    err = capsys.readouterr().err
    assert code == 2 and "fig99" in err and "fig2" in err


@pytest.mark.parametrize("only", ["", ",", " , "])
def test_an_empty_selection_is_refused_not_read_as_everything(only, tmp_path, capsys):
    code = run(["reproduce", "--out", str(tmp_path), "--only", only])
    assert code == 2 and "--only" in capsys.readouterr().err and not any(tmp_path.iterdir())


def test_registry_lists_the_paper_figures():
    keys = set(registry())
    assert {"fig2", "fig3", "oscillator-bifurcation"} <= keys


def test_unreproduced_claims_are_findings_not_failures(tmp_path):
    from stickslip.figures import Check, FigureSpec
    from stickslip.report import FigureOutcome, Summary, markdown_report

    spec = FigureSpec("x", "X", "model", "claim", "method")
    checks = [Check("numerics", True, "1", "1"), Check("paper says 8 modes", False, "5", "8", claim=True)]
    summary = Summary(tmp_path, True, [FigureOutcome(spec, checks, 0.0, False, "x.png")])
    assert summary.passed and summary.to_dict()["figures"][0]["not_reproduced"] == ["paper says 8 modes"]
    text = markdown_report(summary)
    assert "**not reproduced**" in text and "0 of 1 marked claims" in text
    failing = Summary(tmp_path, True, [FigureOutcome(spec, [Check("numerics", False, "2", "1")], 0.0, False, "x.png")])
    assert not failing.passed and "**FAIL**" in markdown_report(failing)


@pytest.mark.slow
def test_every_file_of_reproduce_quick_follows_the_cf_rules(quick_report):
    """The whole quick report (the shared `quick_report`): every data file it writes passes
    `cf_rules`, and every number it stores is finite or its variable's comment says why not."""
    from .cf_rules import file_problems
    from .fuzz_harness import files_finite

    folder, _ = quick_report
    files = sorted((folder / "data").glob("*.nc"))
    assert len(files) == len({s.data_from or s.key for s in registry().values()})
    assert [p for f in files for p in file_problems(f)] == []
    assert files_finite(folder / "data") == []


def test_the_report_says_which_data_a_figure_used_and_describes_them(tmp_path):
    """A figure whose data can come from several places (a stored campaign, one run here, a
    small version) states it, and its text is the one computed for those data."""
    from stickslip.figures import Check, FigureSpec
    from stickslip.report import FigureOutcome, Summary, markdown_report

    spec = FigureSpec("x", "X", "model", "claim", "the full campaign on two meshes")
    outcome = FigureOutcome(spec, [Check("numerics", True, "1", "1")], 0.0, False, "x.png",
                            "4 runs on one mesh", "the small version (4 runs): no campaign found")
    text = markdown_report(Summary(tmp_path, True, [outcome]))
    assert "**What was computed.** 4 runs on one mesh" in text and "two meshes" not in text
    assert "**Data used.** The small version (4 runs): no campaign found." in text


def test_a_first_run_starts_the_longest_figures_first_and_a_later_run_goes_by_its_records(tmp_path):
    import json

    from stickslip.figures import registry
    from stickslip.report import record_path, start_order

    specs = list(registry().values())
    first = [s.key for s in start_order(specs, tmp_path)]
    longest = max(specs, key=lambda s: s.cost).key  # the declared costs: no record yet
    assert first[0] == longest and first.index("fig9") < first.index("fig2")
    record_path(tmp_path, "fig2").write_text(json.dumps({"seconds": 1e4}))  # fig2 took longest last time
    assert [s.key for s in start_order(specs, tmp_path)][:2] == ["fig2", longest]


def test_a_figure_computed_apart_records_its_own_time_not_the_wait_for_it(tmp_path, monkeypatch):
    """fig3 is started first (its last record says it is long) and takes 4 s more; fig2 waits
    behind it in the one worker: fig2's record holds its computation and plot, not that wait."""
    import contextlib
    import json
    import time
    from concurrent.futures import ThreadPoolExecutor

    import stickslip.report as report
    import stickslip.sweep as sweep

    class OneThread(ThreadPoolExecutor):  # fig3's computation takes 4 s more
        def submit(self, fn, key, *args):
            return super().submit(lambda: (time.sleep(4.0) if key == "fig3" else None, fn(key, *args))[1])

    @contextlib.contextmanager
    def one_thread(workers, *args):
        with OneThread(1) as pool:
            yield pool

    monkeypatch.setattr(sweep, "process_pool", one_thread)
    (tmp_path / "data").mkdir()
    report.record_path(tmp_path / "data", "fig3").write_text(json.dumps({"seconds": 1e4}))
    calls = []
    summary = report.reproduce(tmp_path, quick=True, only="fig2,fig3", workers=2,
                               waiting=lambda keys, done, total: calls.append((keys, done, total)))
    seconds = {o.spec.key: o.seconds for o in summary.outcomes}
    assert seconds["fig2"] < 4.0, seconds
    # the status line says what is still computing while this process waits (it named the figure last plotted)
    assert calls == [(["fig2", "fig3"], 0, 2), (["fig2"], 1, 2)], calls
