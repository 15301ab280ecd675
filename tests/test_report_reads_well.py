"""Issue 27, "a report that reads well": tables built from data (a cell's `|` or line break
cannot break them, in the Markdown nor in the HTML), runs of `--only` merged into one report,
each erratum linked to its own anchor, and an HTML page that embeds its figures.

The real runs use two of the cheapest figures, both with errata and fig5 with `|` in its
checks (timed 2026-11-27 through `reproduce --quick`, after a first figure in the process:
fig5 0.3 s, fig3 0.6 s, brake-stability 0.6 s, halfspace-inverse-map 0.8 s, fig14 1.2 s,
fig2 2.2 s; alone in a fresh process 3.6 s, 4.0 s, 4.0 s, 6.8 s)."""

import base64
import json
import re
from html import unescape
from html.parser import HTMLParser

import pytest

from stickslip.cli import run
from stickslip.errata import ERRATA
from stickslip.figures import Check, FigureSpec, registry
from stickslip.report import FigureOutcome, Summary, markdown_report, record_path, write_report

FIRST, SECOND = "fig5", "fig3"  # run in this order; the registry puts fig3 first


# --- reading the report back: Markdown tables, HTML tables, ids and links ------------------------------
def md_cells(row):
    """The cells of a Markdown table row, as a reader (GitHub, Python-Markdown) splits it: on
    every `|` not escaped by a backslash (``\\\\`` is an escaped backslash), the escapes and
    entities undone."""
    cells, current, chars = [], "", iter(row.strip().removeprefix("|").removesuffix("|"))
    for ch in chars:
        if ch == "\\":
            current += next(chars, "\\")
        elif ch == "|":
            cells.append(current)
            current = ""
        else:
            current += ch
    return [unescape(c.strip()) for c in cells + [current]]


def md_tables(text):
    """Every table of a Markdown text: its rows (header first, separator dropped) as lists of cells."""
    tables, lines = [], []
    for line in text.splitlines() + [""]:
        if line.startswith("|"):
            lines.append(line)
        elif lines:
            tables.append([md_cells(row) for i, row in enumerate(lines) if i != 1])
            lines = []
    return tables


class Page(HTMLParser):
    """Tables (rows of cell texts), element ids with the heading that follows each, internal
    links (href, text) and image sources of an HTML page."""

    def __init__(self, html):
        super().__init__(convert_charrefs=True)
        self.tables, self.ids, self.links, self.images = [], {}, [], []
        self._cell = self._link = self._heading = None
        self._pending = []  # ids waiting for the next heading
        self.feed(html)

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if "id" in attrs:
            self.ids[attrs["id"]] = None
            self._pending.append(attrs["id"])
        if tag == "table":
            self.tables.append([])
        elif tag == "tr":
            self.tables[-1].append([])
        elif tag in ("td", "th"):
            self._cell = ""
        elif tag == "a" and attrs.get("href", "").startswith("#"):
            self._link = [attrs["href"][1:], ""]
        elif tag == "img":
            self.images.append(attrs.get("src", ""))
        elif re.fullmatch(r"h[1-6]", tag):
            self._heading = ""

    def handle_endtag(self, tag):
        if tag in ("td", "th"):
            self.tables[-1][-1].append(self._cell.strip())
            self._cell = None
        elif tag == "a" and self._link:
            self.links.append(tuple(self._link))
            self._link = None
        elif re.fullmatch(r"h[1-6]", tag) and self._heading is not None:
            for name in self._pending:
                self.ids[name] = self._heading.strip()
            self._pending, self._heading = [], None

    def handle_data(self, data):
        for part in ("_cell", "_heading"):
            if getattr(self, part) is not None:
                setattr(self, part, getattr(self, part) + data)
        if self._link:
            self._link[1] += data


def assert_tables_are_whole(md, html):
    """Every row of every table, in the Markdown and in the HTML, has as many cells as its header."""
    tables = md_tables(md)
    assert tables
    for table in tables:
        assert [len(row) for row in table] == [len(table[0])] * len(table), table
    page = Page(html)
    assert len(page.tables) == len(tables)
    for table in page.tables:
        assert [len(row) for row in table] == [len(table[0])] * len(table), table
    return tables, page


def sections(md):
    """The text of each figure's section of a Markdown report, by key."""
    parts = re.split(r'^<a id="([^"]+)"></a>$', md, flags=re.M)
    keys = set(registry())
    return {key: text for key, text in zip(parts[1::2], parts[2::2]) if key in keys}


def reproduce_quick(out, key, capsys):
    code = run(["reproduce", "--out", str(out), "--quick", "--only", key, "--json"])
    assert code == 0, capsys.readouterr().err
    return json.loads(capsys.readouterr().out)


@pytest.fixture(scope="module")
def two_figures(tmp_path_factory):
    """A report of the two cheapest figures, run one after the other (the library's path)."""
    from stickslip.report import reproduce

    out = tmp_path_factory.mktemp("report")
    for key in (FIRST, SECOND):
        assert reproduce(out, quick=True, only=key).passed
    return out


# --- 1. tables -------------------------------------------------------------------------------------
AWKWARD = {"name": "a | b\nsecond line", "measured": "max|V'|/Ω = `3", "expected": "2` a\\| C:\\",
           "detail": "x <td> y\r\nz"}


def test_a_cell_holding_pipes_and_line_breaks_keeps_its_table_whole(tmp_path):
    """Planted: no escaping of `|`, of line breaks, of backslashes, of backticks or of `<`: each
    breaks a row (the Markdown's or the HTML's) and fails here."""
    spec = FigureSpec("x", "Title | with a pipe", "model\nover two lines", "claim", "method")
    outcome = FigureOutcome(spec, [Check(passed=True, **AWKWARD), Check("plain", True, "1", "1")], 0.0, False,
                            "x.png")
    write_report(Summary(tmp_path, True, [outcome]))
    md, html = (tmp_path / "report.md").read_text(), (tmp_path / "report.html").read_text()
    tables, page = assert_tables_are_whole(md, html)
    flat = {k: " ".join(line.strip() for line in v.splitlines()) for k, v in AWKWARD.items()}
    expected = [flat["name"], flat["measured"], flat["expected"], "pass", flat["detail"]]
    assert tables[1][1] == expected  # the Markdown, read back: "pass" in the Verdict column
    assert page.tables[1][1] == expected  # the HTML shows each text whole, `|` and all, in its cell
    assert page.tables[0][1][:2] == ["Title | with a pipe", "model over two lines"]


# --- 2. runs of --only merged ----------------------------------------------------------------------
def test_runs_of_only_are_merged_and_a_rerun_replaces_its_section(tmp_path, capsys, monkeypatch):
    """Planted: the report rendered from this run alone (the old overwrite), records kept per
    run instead of per figure (a rerun's section added, not replaced), records in the order
    they were run: each fails here. (The code's fingerprint is held fixed: the tree may be
    edited while the test runs, and a section by other code is marked, which is tested below.)"""
    monkeypatch.setattr("stickslip.report.source_fingerprint", lambda: "test")
    reproduce_quick(tmp_path, FIRST, capsys)
    summary = reproduce_quick(tmp_path, SECOND, capsys)
    assert summary["report_figures"] == [SECOND, FIRST]  # the registry's order, not the runs'
    records = sorted(p.name for p in (tmp_path / "data").glob("*.report.json"))
    assert records == [f"{SECOND}.report.json", f"{FIRST}.report.json"]  # one record per figure
    md = (tmp_path / "report.md").read_text()
    before = sections(md)
    assert list(before) == [SECOND, FIRST] and md.count('<a id="fig') == 2
    assert "over 2 figures" in md
    first = json.loads(record_path(tmp_path / "data", FIRST).read_text())
    second = json.loads(record_path(tmp_path / "data", SECOND).read_text())

    assert reproduce_quick(tmp_path, FIRST, capsys)["figures"][0]["cached"] is True
    md = (tmp_path / "report.md").read_text()
    after = sections(md)
    assert list(after) == [SECOND, FIRST] and md.count('<a id="fig') == 2
    assert json.loads(record_path(tmp_path / "data", FIRST).read_text())["finished"] > first["finished"]
    assert after[FIRST] != before[FIRST] and "(from the checkpoint)" in after[FIRST]
    assert "(from the checkpoint)" not in before[FIRST]
    assert json.loads(record_path(tmp_path / "data", SECOND).read_text()) == second
    assert after[SECOND] == before[SECOND]  # kept as it was
    assert_tables_are_whole(md, (tmp_path / "report.html").read_text())


def _outcome(key, quick, fingerprint, finished):
    spec = FigureSpec(key, f"Figure {key}", "model", "claim", "method")
    return FigureOutcome(spec, [Check("numerics", True, "1", "1")], 1.0, False, f"{key}.png", quick=quick,
                         finished=finished, fingerprint=fingerprint)


def test_figures_keep_the_order_of_the_registry_whatever_the_order_of_the_runs(tmp_path):
    """Neither the order of the runs nor the alphabet (planted: both fail here); a figure the
    registry no longer has comes last."""
    keys = ["fig14", "aa-gone", "brake-stability", "fig3"]
    for i, key in enumerate(keys):
        write_report(Summary(tmp_path, True, [_outcome(key, True, "", f"2026-11-27T1{i}:00:00+00:00")]))
    md = (tmp_path / "report.md").read_text()
    assert [key for key in re.findall(r'^<a id="([^"]+)"></a>$', md, flags=re.M) if not key.startswith("erratum")
            ] == ["fig3", "brake-stability", "fig14", "aa-gone", "errata"]


@pytest.mark.parametrize("quick", [True, False])
def test_a_section_from_another_kind_of_run_or_other_code_says_so(tmp_path, quick):
    """Planted: no mark for the mode, then none for the code: each fails here."""
    write_report(Summary(tmp_path, quick, [_outcome("a", quick, "code1", "2026-11-27T10:00:00+00:00")], "code1"))
    md = (tmp_path / "report.md").read_text()
    assert "other mode" not in md and "other code" not in md and "From a run" not in md

    write_report(Summary(tmp_path, not quick, [_outcome("b", not quick, "code1", "2026-11-27T11:00:00+00:00")],
                         "code1"))
    md = (tmp_path / "report.md").read_text()
    a, b = md.split("## Figure a")[1].split("## Figure b")
    kind = "quick" if quick else "full"
    assert f"**From a run in {kind} mode**" in a and "From a run" not in b.split("# Errata")[0]
    assert f"1 from a run in {kind} mode" in md and "**other mode**" in md.split("## Figure a")[0]
    assert "11:00:00 UTC" in b and "10:00:00 UTC" in a

    write_report(Summary(tmp_path, quick, [_outcome("b", quick, "code2", "2026-11-27T12:00:00+00:00")], "code2"))
    md = (tmp_path / "report.md").read_text()
    a = md.split("## Figure a")[1].split("## Figure b")[0]
    assert "**Computed by other code** (source fingerprint code1; the latest run's is code2)" in a
    assert "From a run" not in a and "1 computed by other code" in md


def test_an_unreadable_record_is_named_not_dropped_silently(tmp_path):
    write_report(Summary(tmp_path, True, [_outcome("a", True, "", "2026-11-27T10:00:00+00:00")]))
    (tmp_path / "data" / "broken.report.json").write_text("{not json")
    report = write_report(Summary(tmp_path, True, [_outcome("b", True, "", "2026-11-27T11:00:00+00:00")]))
    assert [o.spec.key for o in report.outcomes] == ["a", "b"] and report.unreadable == ["broken.report.json"]
    assert "`broken.report.json`" in (tmp_path / "report.md").read_text()


# --- 3. errata links -------------------------------------------------------------------------------
def test_every_figure_names_errata_that_exist():
    known = {e.id for e in ERRATA}
    assert {key: [e for e in spec.errata if e not in known] for key, spec in registry().items()} == {
        key: [] for key in registry()}


def test_each_errata_link_goes_to_its_own_erratum(two_figures):
    """Planted: the links to "#errata" (the old behaviour: the target exists, but is the list's
    top), then no anchors in the errata section: each fails here."""
    page = Page((two_figures / "report.html").read_text())
    known = {e.id for e in ERRATA}
    errata_links = [(href, text) for href, text in page.links if text in known]
    assert sorted(text for _, text in errata_links) == sorted(
        registry()[FIRST].errata + registry()[SECOND].errata)
    for href, text in page.links:
        assert href in page.ids, (href, text)  # every internal link resolves
    for href, text in errata_links:
        assert page.ids[href].startswith(f"{text}. "), (href, text, page.ids[href])


def test_errata_named_by_a_figure_but_missing_are_not_dangling_links(tmp_path):
    spec = FigureSpec("x", "X", "model", "claim", "method", ("E1", "Z9"))
    md = markdown_report(Summary(tmp_path, True, [FigureOutcome(spec, [], 0.0, False, "x.png")]))
    assert "Errata involved: [E1](#erratum-E1), Z9 (not in the errata)." in md


# --- 4. a self-contained HTML page -----------------------------------------------------------------
def test_the_html_embeds_its_figures_and_the_markdown_links_them(two_figures, tmp_path):
    """Planted: the HTML left linking the PNG files: fails here."""
    html = (two_figures / "report.html").read_text()
    alone = tmp_path / "elsewhere.html"  # copied alone: nothing it shows may depend on a file beside it
    alone.write_text(html)
    page = Page(alone.read_text())
    md = (two_figures / "report.md").read_text()
    assert len(page.images) == len(sections(md)) == 2
    assert [src for src in page.images if not src.startswith("data:")] == []
    for key, src in zip((SECOND, FIRST), page.images):
        assert src.startswith("data:image/png;base64,")
        assert base64.b64decode(src.split(",", 1)[1]) == (two_figures / f"{key}.png").read_bytes()
        assert f"]({key}.png)" in md  # the Markdown keeps linking the file


def test_a_missing_image_is_said_not_linked(tmp_path):
    spec = FigureSpec("x", "X", "model", "claim", "method")
    write_report(Summary(tmp_path, True, [FigureOutcome(spec, [Check("c", True, "1", "1")], 0.0, False, "x.png")]))
    html = (tmp_path / "report.html").read_text()
    assert Page(html).images == [] and "the image x.png was not found beside the report" in html
