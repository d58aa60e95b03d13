"""Equation lines and blocks of sentences as the templates lay them out."""

from __future__ import annotations

import re
from collections.abc import Collection
from typing import Any

from derive.steps.model import Eqn, Math
from derive.symbols import latex_name
from derive.writers.printing import IMPLIES, Row, Style, block_style, latex_eqn, latex_inline, latex_rows
from derive.writers.targets import GITHUB, Layout
from derive.writers.width import width_pt

ANSWER_MARK = r"\quad\longleftarrow\ \text{ANSWER}"


def line_view(eqn: Eqn, style: Style, layout: Layout, *, answer: bool = False, extra: int = 1) -> dict[str, Any]:
    """One equation line as the templates need it: ``latex`` on one row (with ⇒, box
    and ANSWER mark), its ``tag``, and, where the layout sets a width the line does
    not fit, ``rows`` to lay out (``before`` and ``after`` them: the box and the mark)."""
    body, tag = latex_eqn(eqn, style, extra)
    mark = ANSWER_MARK if answer else ""
    rows: tuple[Row, ...] = ()
    if layout.width is not None and (layout.long_lines == "aligned" or not eqn.boxed):
        rows = latex_rows(eqn, style, layout.width, extra, reserve=width_pt(mark) if mark else 0.0)
    return {
        "latex": body + mark,
        "tag": tag,
        "boxed": eqn.boxed,
        "rows": rows,
        "before": r"\boxed{" if eqn.boxed else "",
        "after": ("}" if eqn.boxed else "") + mark,
        "cancels": bool(eqn.cancel) and style.strike,
    }


#: Around an optional line of a compiled variant page, for the variant to keep or drop.
def blocks_view(blocks_in: tuple, style: Style, layout: Layout = GITHUB) -> list[dict[str, Any]]:
    """Blocks of sentences and equation lines, printed: what blocks.*.j2 lays out."""
    blocks = []
    for block in blocks_in:
        bstyle = block_style(block, style)
        lines: list[dict[str, Any]] = []
        for eqn in block.lines:
            if eqn.optional and bstyle.hide_optional:
                continue
            line = line_view(eqn, bstyle, layout, answer=eqn.mark, extra=bstyle.extra)
            bare = line["latex"].removeprefix(IMPLIES)
            if lines and lines[-1]["latex"].removeprefix(IMPLIES) == bare and not lines[-1]["boxed"]:
                kept = lines[-1]
                lines[-1] = {**kept, "tag": line["tag"] or kept["tag"], "boxed": eqn.boxed}
                continue  # the same line again (numbers in, but none to put in): once is enough
            lines.append(line)
        text = None
        if block.text is not None:
            text = [("math", latex_inline(t.expr, style)) if isinstance(t, Math) else ("text", t) for t in block.text]
        blocks.append({"text": text, "lines": lines})
    return blocks


#: A word that may be a symbol's name: letters, an underscore, letters or digits (e_floor, m_A),
#: or one small letter but the article "a" (e, u).
_NAME = re.compile(r"(?<![\w\\])([A-Za-z]+_[A-Za-z0-9]+|[b-z])(?![\w'’])")


def heading_parts(title: str, names: Collection[str]) -> list[tuple[str, str]]:
    """A heading's text and mathematics: each of the page's symbol names in it (``names``)
    typeset as the page writes that symbol ("Solve for e_floor" -> "Solve for $e_{\\mathrm{floor}}$"),
    so that no raw name reaches a heading; other words as they are."""
    out: list[tuple[str, str]] = []
    at = 0
    for m in _NAME.finditer(title):
        if m[1] not in names:
            continue
        if m.start() > at:
            out.append(("text", title[at : m.start()]))
        out.append(("math", latex_name(m[1])))
        at = m.end()
    if at < len(title) or not out:
        out.append(("text", title[at:]))
    return out
