"""The check `make docs` runs on the built HTML (docs/check_html.py) finds what it is for."""

import importlib.util
from pathlib import Path

import pytest

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


# A class of the API reference as Sphinx writes it: the fields' table (docs/field_docs.py), then what
# autodoc added from the constructor's annotations (the fields listed again before issue 44).
_TABLE = ('<dl class="py class">\n<dt class="sig sig-object py" id="stickslip.x.Run">\n<span>Run</span></dt>\n<dd>'
          '<p class="rubric">Fields</p>\n<table><tbody>\n'
          '<tr class="row-even"><td><p><code class="docutils literal notranslate"><span class="pre">period</span></code></p></td>\n'
          '<tr class="row-odd"><td><p><code class="docutils literal notranslate"><span class="pre">stable</span></code></p></td>\n'
          '</tbody>\n</table>\n')
_PARAMETERS = ('<dl class="field-list simple">\n<dt class="field-odd">Parameters<span class="colon">:</span></dt>\n'
               '<dd class="field-odd"><ul class="simple">\n<li><p><strong>period</strong> (<em>float</em>)</p></li>\n'
               '<li><p><strong>stable</strong> (<em>bool</em>)</p></li></ul></dd></dl>\n')
_METHOD = ('<dl class="py method">\n<dt class="sig sig-object py" id="stickslip.x.Run.to_dict">to_dict</dt>\n'
           '<dd><dl class="field-list simple"><dt class="field-odd">Parameters</dt><dd><ul><li><p><strong>period'
           '</strong> (<em>float</em>)</p></li></ul></dd></dl></dd></dl>\n')


def test_a_field_listed_again_as_a_parameter_or_an_attribute_is_found():
    assert check_html.repeated_fields(_TABLE + _PARAMETERS + "</dd></dl>") == [
        "stickslip.x.Run: field 'period' listed twice", "stickslip.x.Run: field 'stable' listed twice"]
    attribute = '<dl class="py attribute">\n<dt class="sig sig-object py" id="stickslip.x.Run.stable">stable</dt></dl>'
    assert check_html.repeated_fields(_TABLE + attribute + "</dd></dl>") == ["stickslip.x.Run: field 'stable' listed twice"]
    # the table alone, and a method's own parameter of the same name, are not a field listed twice
    assert check_html.repeated_fields(_TABLE + _METHOD + "</dd></dl>") == []
    assert check_html.problems(_TABLE + _PARAMETERS) != []


def test_an_executed_page_without_output_or_picture_is_found():
    output = '<div class="cell_output docutils container"><pre>period 6.71</pre></div>'
    image = '<img alt="_images/x.png" src="_images/x.png" />'
    assert check_html.problems(output + image, executed=True) == []
    assert check_html.problems(image, executed=True) == ["an executed page without any cell output"]
    assert check_html.problems(output, executed=True) == ["an executed page without a picture"]
    assert check_html.problems("<p>text</p>") == []  # a page that runs no code needs neither
    assert all((ROOT / "docs" / f"{name}.md").exists() for name in check_html.EXECUTED)


def test_the_field_lines_napoleon_writes_go_into_the_table():
    import sys
    sys.path.insert(0, str(ROOT / "docs"))
    try:
        import field_docs
    finally:
        sys.path.remove(str(ROOT / "docs"))
    lines = ["A run.", "", ":param period: the period,", "    in seconds", ":type period: float",
             ":ivar stable: whether it is stable", ":vartype stable: bool", ":param other: not a field", ""]
    described = field_docs.take_field_lines(lines, {"period", "stable"})
    assert described == {"period": "the period, in seconds", "stable": "whether it is stable"}
    assert lines == ["A run.", "", ":param other: not a field", ""]


def test_a_field_autodoc_lists_as_an_attribute_or_a_method_is_dropped_and_a_method_kept():
    """`RunFormat.scales` is a field with a ``#:`` comment whose default is a staticmethod: autodoc
    listed it as a method, after the table that has it (the build of issue 44 found it)."""
    import sys

    from docutils import nodes

    addnodes = pytest.importorskip("sphinx.addnodes", reason="the docs extra (sphinx) is not installed")
    sys.path.insert(0, str(ROOT / "docs"))
    try:
        import field_docs
    finally:
        sys.path.remove(str(ROOT / "docs"))
    page = nodes.section()
    for objtype, fullname in [("method", "RunFormat.scales"), ("attribute", "RunFormat.notes"),
                              ("method", "RunFormat.not_a_field"), ("attribute", "ExplicitScheme.PARAMS")]:
        page += addnodes.index(entries=[])
        desc = addnodes.desc(domain="py", objtype=objtype)
        desc += addnodes.desc_signature(module="stickslip.contact", fullname=fullname)
        page += desc
    field_docs.drop_field_attributes(None, page)
    kept = [d.children[0]["fullname"] for d in page.findall(addnodes.desc)]
    assert kept == ["RunFormat.not_a_field", "ExplicitScheme.PARAMS"]
    assert len(list(page.findall(addnodes.index))) == 2  # their index entries went with them
