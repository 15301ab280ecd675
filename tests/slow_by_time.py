"""The fast set's slow tests by measured time (``tests/slow_by_time.txt``).

``python -m tests.slow_by_time JUNIT.xml [SECONDS]``: adds to the list every test of an idle fast run
(``pytest -n 2 -m "not slow" --junitxml JUNIT.xml``) that took ``SECONDS`` (2 by default) or more,
keeping the entries already there (they were not in that run: tests/conftest.py marks them slow).
"""

from __future__ import annotations

import sys
import xml.etree.ElementTree as ET
from pathlib import Path

LIST = Path(__file__).with_name("slow_by_time.txt")
ROOT = LIST.parent.parent


def listed() -> set[str]:
    """The node ids in the list."""
    return {line.strip() for line in LIST.read_text().splitlines() if line.strip() and not line.startswith("#")}


def node_id(classname: str, name: str) -> str:
    """A junit test case's pytest node id (the file is the longest prefix of ``classname`` that is one)."""
    parts = classname.split(".")
    for i in range(len(parts), 0, -1):
        path = "/".join(parts[:i]) + ".py"
        if (ROOT / path).exists():
            return "::".join([path, *parts[i:], name])
    raise ValueError(f"no test file for {classname}")


def main(junit: str, seconds: float = 2.0) -> None:
    slow = {node_id(tc.get("classname"), tc.get("name")) for tc in ET.parse(junit).getroot().iter("testcase")
            if float(tc.get("time")) >= seconds}
    lines = LIST.read_text().splitlines()
    header = [line for line in lines if line.startswith("#")]
    LIST.write_text("\n".join(header + sorted(listed() | slow)) + "\n")


if __name__ == "__main__":
    main(sys.argv[1], *(float(a) for a in sys.argv[2:3]))
