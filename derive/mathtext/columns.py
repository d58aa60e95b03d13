"""Two relations side by side in one row of an ``align`` display: ``a &= b & c &= d``.

``align`` pairs its columns (right-aligned, then left-aligned), so a row of four columns holds
two relations, each starting at an even column: ``(v_A)_{n1} &= 4\\cos 30^\\circ & (v_A)_{t1} &=
4\\sin 30^\\circ``. Read with the ``&`` dropped, the two would run together (``4 cos 30° (v_A)_t1
= …``); here each is kept a relation of its own. A row whose later pair is no relation of its own
(a label, ``& = c`` lining up a third side) is left as it is."""

from __future__ import annotations

import re

_SIGN = re.compile(r"=|\\approx|\\simeq|≈")
_LEADS = re.compile(r"\s*(?:=|\\approx|\\simeq|≈|<|>|\\le|\\ge|\\Rightarrow|\\implies|\\therefore)")


def side_by_side(row: str) -> str:
    """``row`` with its relations in pairs of columns joined by `` ; `` (the reader's separator
    of relations on a line); unchanged unless every pair of columns holds a relation with a
    left side of its own."""
    cells = re.split(r"(?<!\\)&", row)
    if len(cells) < 4:
        return row
    lefts = cells[::2]
    pairs = ["&".join(cells[k : k + 2]) for k in range(0, len(cells), 2)]
    if any(not _SIGN.search(p) or not left.strip() or _LEADS.match(left) for left, p in zip(lefts, pairs, strict=True)):
        return row
    return " ; ".join(pairs)
