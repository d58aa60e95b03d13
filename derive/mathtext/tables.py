"""A row of a Markdown table as a teacher reads it: each cell a piece of its own (``| after |
$\\frac12 (4.02)(1.39)^2 = 3.88$ |``: the label, then the relation), the bars between cells no
part of the mathematics (an absolute value's bars, ``|v_A|``, are kept)."""

from __future__ import annotations

import re

#: A row of a table: a bar first and last, and one between cells at least.
_ROW = re.compile(r"^\s*\|.*\|\s*$")
#: Mathematics in a row, kept whole (``$|v| = 2$``).
_MATH = re.compile(r"\$\$.*?\$\$|\$[^$]*\$")
#: A bar between cells: first, last, or with a space on each side.
_BAR = re.compile(r"^\s*\||\|\s*$|(?<=\s)\|(?=\s)")


def table_cells(line: str) -> str:
    """``line`` with a table row's bars between cells as ``;`` (outside its mathematics); any
    other line as it was."""
    if not _ROW.match(line) or line.count("|") < 3:
        return line
    out, end = [], 0
    for m in _MATH.finditer(line):
        out += [_BAR.sub(" ; ", line[end : m.start()]) if end == 0 else _cells(line[end : m.start()]), m.group(0)]
        end = m.end()
    out.append(_BAR.sub(" ; ", line[end:]) if end == 0 else _cells(line[end:], last=True))
    return "".join(out)


def _cells(text: str, last: bool = False) -> str:
    """The text between two pieces of mathematics (or after the last) with its bars as ``;``."""
    text = re.sub(r"(?<![\w)])\|(?![\w(])|(?<=\s)\|", " ; ", text)
    return re.sub(r"\|\s*$", " ; ", text) if last else text
