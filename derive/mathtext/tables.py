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


#: The rows of a table looked up for its header (each row looks: a longer walk, for every row, is quadratic).
MAX_ROWS = 100
#: A table's separator row (``|---|:--:|``).
_SEPARATOR = re.compile(r"^\s*\|(?:\s*:?-{2,}:?\s*\|)+\s*$")
#: A header cell that is a component (``n``, ``t before``, ``x after``).
_AXIS = re.compile(r"([ntxy])(?:\s+(before|after|initial|final))?", re.I)
#: A row's label that is a body, at a time (``A before``, ``ball B``, ``B after``, ``A``).
_BODY = re.compile(r"(?:ball\s+|sphere\s+|particle\s+)?([AB])(?:\s+(before|after|initial|final))?", re.I)
#: A cell of numbers only, up to its first ``=`` (``4 sin 30° = 2``, ``-3``): no name of its own.
_NUMBERS = re.compile(r"(?:[\d\s.,+\-−*/×·()°^√]|sin|cos|tan|sqrt)+")


def headed(lines: list[str], n: int) -> str:
    """Line ``n`` of ``lines`` with each cell of numbers named by its row and column, where it is
    a row of a table whose header names components and whose row names a body (``| A before |
    4 sin 30° = 2 | 4 cos 30° = 3.464 |`` under ``| | n | t |``: ``A_n = 4 sin 30° = 2``, A's n
    component before, and ``A_t = …``; after: ``A_n'``); any other line as it is."""
    line = lines[n]
    header = _header(lines, n)
    if header is None or "$" in line or not _ROW.match(line):
        return line
    cells = line.strip()[1:-1].split("|")
    body = _BODY.fullmatch(cells[0].strip())
    if body is None or len(cells) != len(header):
        return line
    out = [cells[0]]
    for head, cell in zip(header[1:], cells[1:], strict=True):
        axis = _AXIS.fullmatch(head.strip())
        if axis is None or not cell.strip() or not _NUMBERS.fullmatch(cell.split("=")[0]):
            out.append(cell)
            continue
        time = (body.group(2) or axis.group(2) or "before").lower()
        prime = "'" if time in ("after", "final") else ""
        out.append(f" {body.group(1).upper()}_{axis.group(1).lower()}{prime} = {cell.strip()} ")
    return "|" + "|".join(out) + "|"


def _header(lines: list[str], n: int) -> list[str] | None:
    """The cells of the header of the table line ``n`` is a body row of (None where it is not
    one, or the header has mathematics in it)."""
    k = n - 1
    while k >= max(n - MAX_ROWS, 0) and _ROW.match(lines[k]) and not _SEPARATOR.match(lines[k]):
        k -= 1
    if k < 1 or k == n or not _SEPARATOR.match(lines[k]) or not _ROW.match(lines[k - 1]) or "$" in lines[k - 1]:
        return None
    return lines[k - 1].strip()[1:-1].split("|")
