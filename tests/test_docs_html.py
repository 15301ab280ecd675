"""The check `make docs` runs on the built HTML (docs/check_html.py) finds what it is for."""

import importlib.util
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
_spec = importlib.util.spec_from_file_location("check_html", ROOT / "docs" / "check_html.py")
check_html = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(check_html)


def test_an_option_printed_with_a_typographic_dash_is_found():
    for text in ("<p>use \u2013law stribeck</p>", "<td>\u2014fd</td>", "(\u2013omega)", "<p>\u2013\u2013x-max</p>"):
        assert check_html.problems(text), text


def test_dashes_of_prose_and_of_ranges_are_not_options():
    text = ("<p>Figure 2 \u2014 phase diagram; 6\u20137.5 s; stick\u2013slip; [0, 0.5) \u2013 an isotropic solid; "
            "<code>--law</code></p>")
    assert check_html.problems(text) == []


def test_a_script_or_stylesheet_from_another_host_is_found_and_a_local_one_is_not():
    cdn = '<script defer="defer" src="https://cdn.jsdelivr.net/npm/mathjax@3/es5/tex-chtml.js"></script>'
    css = '<link rel="stylesheet" href="//fonts.example.org/a.css" />'
    assert len(check_html.problems(cdn + css)) == 2
    local = '<script src="_static/mathjax/tex-chtml.js"></script><link rel="stylesheet" href="_static/furo.css" />'
    assert check_html.problems(local + '<a href="https://example.org">a link</a>') == []


def test_the_command_fails_on_a_bad_page_and_passes_a_good_one(tmp_path):
    (tmp_path / "good.html").write_text("<p><code>--law</code></p>")
    assert check_html.main([str(tmp_path)]) == 0
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "bad.html").write_text("<p>\u2013law</p>")
    assert check_html.main([str(tmp_path)]) == 1
    assert check_html.main([str(tmp_path / "missing")]) == 2
