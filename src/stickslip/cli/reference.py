"""The command-line reference of the docs, generated from the commands themselves.

``python -m stickslip.cli.reference docs/cli`` writes one MyST page per command group (and one
for the top-level commands): each command's help, usage, options under the headings its
``--help`` prints them (`stickslip.cli.helptext.PANELS`), and its example. ``make docs`` runs it
before Sphinx, and a test keeps the committed pages equal to what it writes.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

from . import app
from .helptext import ARGUMENTS, EXAMPLES, command_tree, help_sections

_SPECIAL = re.compile(r"([\\`*_\[\]<>|#])")


def _text(text: str) -> str:
    """Prose of a help text as Markdown: paragraphs kept, lines joined, specials escaped."""
    paragraphs = [" ".join(p.split()) for p in re.split(r"\n\s*\n", text or "") if p.strip()]
    return "\n\n".join(_escaped(p) for p in paragraphs)


def _escaped(text: str) -> str:
    return _SPECIAL.sub(r"\\\1", text)


def _cell(text: str) -> str:
    return " ".join(text.split()).replace("|", "\\|")


def _command(command, path: str, level: int) -> list[str]:
    ctx = command.make_context(f"stickslip {path}", [], resilient_parsing=True)
    lines = [f"{'#' * level} `stickslip {path}`", "", _text(command.help), "", "```text",
             f"{ctx.command_path} {' '.join(command.collect_usage_pieces(ctx))}", "```", ""]
    for heading, rows in help_sections(command, ctx).items():
        if rows and heading != "Other":
            kind = "Argument" if heading == ARGUMENTS else "Option"
            lines += [f"**{heading}**", "", f"| {kind} | Meaning |", "|---|---|"]
            lines += [f"| `{_cell(flag)}` | {_cell(_escaped(meaning))} |" for flag, meaning in rows]
            lines.append("")
    if path in EXAMPLES:
        lines += ["Example:", "", "```sh", EXAMPLES[path], "```", ""]
    return lines


def pages() -> dict[str, str]:
    """File name -> MyST text: ``index.md`` (the top-level commands and the list of groups) and
    one page per group."""
    root = command_tree(app)
    ctx = root.make_context("stickslip", [], resilient_parsing=True)
    groups = {n: c for n, c in root.commands.items() if hasattr(c, "commands")}
    top = ["# Command-line reference", "",
           "Generated from the commands (`python -m stickslip.cli.reference docs/cli`): what `stickslip COMMAND "
           "--help` prints, with the options under the same headings. Every command also takes `--help`; "
           "`stickslip --install-completion` installs shell completion.", "",
           "```text", f"stickslip {' '.join(root.collect_usage_pieces(ctx))}", "```", "",
           "```{toctree}", ":maxdepth: 1", "", *groups, "```", ""]
    for name, command in root.commands.items():
        if name not in groups:
            top += _command(command, name, 2)
    out = {"index.md": "\n".join(top).rstrip() + "\n"}
    for name, group in groups.items():
        lines = [f"# `stickslip {name}`", "", _text(group.help), ""]
        for sub_name, sub in group.commands.items():
            lines += _command(sub, f"{name} {sub_name}", 2)
        out[f"{name}.md"] = "\n".join(lines).rstrip() + "\n"
    return out


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print("usage: python -m stickslip.cli.reference FOLDER", file=sys.stderr)
        return 2
    folder = Path(argv[0])
    folder.mkdir(parents=True, exist_ok=True)
    for name, text in pages().items():
        (folder / name).write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
