"""The built HTML as a reader uses it: no option printed with a typographic dash, nothing fetched
from another host (the pages render offline, math included); each tutorial page shows what its
code printed and at least one picture; no API page lists a dataclass's field twice (its table of
fields, then again as a parameter or an attribute). `make docs` runs it on the build.

    python docs/check_html.py build/docs/html
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

#: An en or em dash that starts a word: "–law" is "--law" turned typographic, which a shell refuses.
DASHED_OPTION = re.compile(r"(?<![\w\u2013\u2014-])[\u2013\u2014]{1,2}(?=[A-Za-z])")
#: A script, or a stylesheet, loaded from another host (MathJax from a CDN: raw TeX offline).
REMOTE = re.compile(r"<script\b[^>]*\bsrc=\"(?:https?:)?//[^\"]*\"|<link\b[^>]*\brel=\"stylesheet\"[^>]*"
                    r"\bhref=\"(?:https?:)?//[^\"]*\"", re.I)


#: The pages whose code runs at the build (myst-nb): each shows its cells' output and a picture.
EXECUTED = ("tutorial-oscillator", "tutorial-brake", "tutorial-fem", "tutorial-halfspace", "tutorial-your-body",
            "systems", "rsf", "sweeps-on-a-cluster", "brakes-3d")
#: An output a cell printed or showed (myst-nb), and a picture.
CELL_OUTPUT = re.compile(r'<div class="cell_output\b')
IMAGE = re.compile(r"<img\b[^>]*\bsrc=")
#: A class of the API reference, its own text up to its first member.
API_CLASS = re.compile(r'<dl class="py class">\s*<dt class="sig sig-object py" id="([\w.]+)">')
MEMBER = re.compile(r'<dt class="sig sig-object py"')
TABLE_ROW_NAME = re.compile(r'<tr class="row-(?:even|odd)"><td><p><code[^>]*><span class="pre">(\w+)</span>')


def repeated_fields(html: str) -> list[str]:
    """Fields of a class's table of fields (``field_docs.py``) listed again in its own text (a
    parameter, a variable) or as an attribute of it."""
    found = []
    for m in API_CLASS.finditer(html):
        rest = html[m.end():]
        own = rest[:(nxt.start() if (nxt := MEMBER.search(rest)) else len(rest))]
        start = own.find('rubric">Fields</p>')
        if start < 0:
            continue
        end = own.find("</table>", start)
        names = TABLE_ROW_NAME.findall(own[start:end])
        again = set(re.findall(r"<strong>(\w+)</strong>", own[:start] + own[end:]))
        found += [f"{m.group(1)}: field {name!r} listed twice" for name in names
                  if name in again or f'id="{m.group(1)}.{name}"' in html]
    return found


def problems(html: str, executed: bool = False) -> list[str]:
    """What is wrong in one page's HTML: each finding with its context. ``executed``: a page
    whose code runs at the build."""
    found = [f"an option with a typographic dash: ...{html[max(0, m.start() - 30):m.end() + 20]!r}..."
             for m in DASHED_OPTION.finditer(html)]
    found += [f"loaded from another host: {m.group(0)[:160]}" for m in REMOTE.finditer(html)]
    found += repeated_fields(html)
    if executed and not CELL_OUTPUT.search(html):
        found.append("an executed page without any cell output")
    if executed and not IMAGE.search(html):
        found.append("an executed page without a picture")
    return found


def main(argv: list[str]) -> int:
    if len(argv) != 1 or not Path(argv[0]).is_dir():
        print("usage: python docs/check_html.py BUILD_HTML_FOLDER", file=sys.stderr)
        return 2
    root = Path(argv[0])
    pages = sorted(root.rglob("*.html"))
    bad = [(page, p) for page in pages for p in problems(page.read_text(encoding="utf-8", errors="replace"),
                                                         executed=page.parent == root and page.stem in EXECUTED)]
    for page, problem in bad:
        print(f"{page}: {problem}", file=sys.stderr)
    print(f"{len(pages)} pages checked: {len(bad)} problems", file=sys.stderr)
    return 1 if bad or not pages else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
