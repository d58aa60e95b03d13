"""The HTML pages of one impact and of a chain: every formula typeset by KaTeX."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from derive import escape
from derive.writers.view.jinja import environment


def _aligned(line: dict[str, Any]) -> str:
    """A line as one display: on one row, or its rows (a long line) as an ``aligned``."""
    rows = line.get("rows") or ()
    if not rows:
        return line["latex"]
    body = []
    for row in rows:
        if row.continued:
            body.append(rf"&\quad {row.rel} {row.rhs}")
        else:
            body.append((f"{row.lhs} " if row.lhs else "") + f"&{row.rel} {row.rhs}")
    return line["before"] + r"\begin{aligned}" + r" \\ ".join(body) + r"\end{aligned}" + line["after"]


def html_page(data: dict[str, Any]) -> str:
    """The HTML page: every formula typeset by KaTeX (under Node.js when there is one)."""
    from derive.writers import katex as html_mod

    items: list[tuple[str, bool]] = []

    def slot(tex: str, display: bool) -> int:
        items.append((tex, display))
        return len(items) - 1

    for g in data["givens"]:
        g["slot"] = slot(g["latex"], False)
    statement = [(k, slot(s_, False) if k == "math" else s_) for k, s_ in data["statement"] or ()]
    find = [(k, slot(s_, False) if k == "math" else s_) for k, s_ in data["find"]]
    for stage in data["stages"]:
        for block in stage["blocks"]:
            if block["text"]:
                block["text"] = [(k, slot(s_, False) if k == "math" else s_) for k, s_ in block["text"]]
            for line in block["lines"]:
                line["slot"] = slot(_aligned(line), True)
    rendered, script = _typeset(items)
    for g in data["givens"]:
        g["html"] = rendered[g.pop("slot")]
    data["statement"] = [("math", rendered[s_]) if k == "math" else (k, s_) for k, s_ in statement]
    for stage in data["stages"]:
        stage["figure"] = stage.get("figure_svg", "")
        for block in stage["blocks"]:
            if block["text"]:
                block["text"] = [("math", rendered[s_]) if k == "math" else (k, s_) for k, s_ in block["text"]]
            for line in block["lines"]:
                line["html"] = rendered[line.pop("slot")]
    data["find"] = [("math", rendered[s_]) if k == "math" else (k, s_) for k, s_ in find]
    return (
        environment("md").get_template("solution.html.j2").render(**data, katex_css=html_mod.katex_css(), script=script)
    )


def chain_html_page(data: dict[str, Any]) -> str:
    """A chain's HTML page: every formula typeset by KaTeX, as :func:`html_page` does for one impact."""
    from derive.writers import katex as html_mod

    items: list[tuple[str, bool]] = []

    def slot(tex: str, display: bool) -> int:
        items.append((tex, display))
        return len(items) - 1

    statement = _slot_chain(data, slot)
    rendered, script = _typeset(items)
    _fill_chain(data, statement, rendered)
    return environment("md").get_template("chain.html.j2").render(**data, katex_css=html_mod.katex_css(), script=script)


def _typeset(items: list[tuple[str, bool]]) -> tuple[list[str], str]:
    """Each formula (LaTeX, display or not) as HTML by KaTeX under Node.js; without Node.js,
    each as its LaTeX in a span, and the inlined script that typesets the page offline."""
    from derive.writers import katex as html_mod

    rendered = html_mod.render_math(items)
    if rendered is None:  # no Node.js: the page typesets itself, offline, with the inlined script
        rendered = [
            f'<span class="math{" display" if disp else ""}">{escape.html_text(tex)}</span>' for tex, disp in items
        ]
        return rendered, html_mod.katex_script()
    return rendered, ""


def _slot_blocks(blocks: list[dict[str, Any]], slot: Callable[[str, bool], int]) -> None:
    """Give each formula of the blocks its place in the list to typeset."""
    for block in blocks:
        block["text"] = [(k, slot(s_, False) if k == "math" else s_) for k, s_ in block["text"] or ()]
        for line in block["lines"]:
            line["slot"] = slot(_aligned(line), True)


def _fill_blocks(blocks: list[dict[str, Any]], rendered: list[str]) -> None:
    """Put each formula of the blocks, typeset, in its place."""
    for block in blocks:
        block["text"] = [("math", rendered[s_]) if k == "math" else (k, s_) for k, s_ in block["text"]]
        for line in block["lines"]:
            line["html"] = rendered[line.pop("slot")]


def _slot_chain(data: dict[str, Any], slot: Callable[[str, bool], int]) -> list[tuple[str, Any]]:
    """Give each formula of a chain's page its place in the list to typeset; the statement's parts."""
    for g in data["givens"]:
        g["slot"] = slot(g["latex"], False)
    statement = [(k, slot(s_, False) if k == "math" else s_) for k, s_ in data["statement"] or ()]
    for st in data["stages"]:
        if st["impact"]:
            for g in st["givens"]:
                g["slot"] = slot(g["latex"], False)
            for sub in st["stages"]:
                _slot_blocks(sub["blocks"], slot)
            st["carried"] = [slot(c, False) for c in st["carried"]]
        else:
            _slot_blocks(st["blocks"], slot)
    for line in data["answers"]:
        line["slot"] = slot(_aligned(line), True)
    return statement


def _fill_chain(data: dict[str, Any], statement: list[tuple[str, Any]], rendered: list[str]) -> None:
    """Put each formula of a chain's page, typeset, in its place."""
    for g in data["givens"]:
        g["html"] = rendered[g.pop("slot")]
    data["statement"] = [("math", rendered[s_]) if k == "math" else (k, s_) for k, s_ in statement]
    for st in data["stages"]:
        if st["impact"]:
            for g in st["givens"]:
                g["html"] = rendered[g.pop("slot")]
            for sub in st["stages"]:
                sub["figure"] = sub.get("figure_svg", "")
                _fill_blocks(sub["blocks"], rendered)
            st["carried"] = [rendered[c] for c in st["carried"]]
        else:
            _fill_blocks(st["blocks"], rendered)
    for line in data["answers"]:
        line["html"] = rendered[line.pop("slot")]
