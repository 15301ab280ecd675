"""The built HTML as a reader uses it: no option printed with a typographic dash, nothing fetched
from another host (the pages render offline, math included). `make docs` runs it on the build.

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


def problems(html: str) -> list[str]:
    """What is wrong in one page's HTML: each finding with its context."""
    found = [f"an option with a typographic dash: ...{html[max(0, m.start() - 30):m.end() + 20]!r}..."
             for m in DASHED_OPTION.finditer(html)]
    found += [f"loaded from another host: {m.group(0)[:160]}" for m in REMOTE.finditer(html)]
    return found


def main(argv: list[str]) -> int:
    if len(argv) != 1 or not Path(argv[0]).is_dir():
        print("usage: python docs/check_html.py BUILD_HTML_FOLDER", file=sys.stderr)
        return 2
    pages = sorted(Path(argv[0]).rglob("*.html"))
    bad = [(page, p) for page in pages for p in problems(page.read_text(encoding="utf-8", errors="replace"))]
    for page, problem in bad:
        print(f"{page}: {problem}", file=sys.stderr)
    print(f"{len(pages)} pages checked: {len(bad)} problems", file=sys.stderr)
    return 1 if bad or not pages else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
