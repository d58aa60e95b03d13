"""The HTML pages (a solution's, a handout's) and an LMS's fragments: every formula typeset by KaTeX
or left for MathJax."""

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


def html_pages(pages: list[tuple[str, dict[str, Any]]]) -> list[str]:
    """Several pages, each ("solution" | "handout", its data), typeset together: one KaTeX call
    for all their formulas (a variant's sheet and worked solution). A handout's data: ``title``,
    ``mode`` ("problems": a student's sheet, "answers", "solutions"), ``problems``, ``theory``;
    ``numbered`` False: no problem numbers."""
    formulas = _Formulas()
    for kind, data in pages:
        problems = data["problems"] if kind == "handout" else [data]
        for problem in problems:
            formulas.problem(problem, solution=kind == "solution" or data["mode"] == "solutions")
            for stage in (sub for st in problem["stages"] for sub in st["stages"]):
                stage["figure"] = stage.get("figure_svg", "")
        if kind == "handout" and data.get("theory"):
            formulas.theory(data["theory"])
    script = formulas.run(_typeset)
    return [_page(f"{kind}.html.j2", data, script) for kind, data in pages]


def _page(template: str, data: dict[str, Any], script: str) -> str:
    """A whole page in the page's style (templates/page-style.html.j2), its text HTML-escaped."""
    from derive.writers import katex as html_mod

    return (
        environment("md")
        .get_template(template)
        .render(**data, katex_css=html_mod.katex_css(), script=script, text=escape.html_text)
    )


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


def mathjax(items: list[tuple[str, bool]]) -> tuple[list[str], str]:
    """Each formula as TeX for MathJax (Moodle's MathJax filter, PrairieLearn): ``\\( \\)``
    inline, ``\\[ \\]`` on its own; HTML-escaped, typeset where the page is shown."""
    out = [rf"\[ {escape.html_body(tex)} \]" if display else rf"\({escape.html_body(tex)}\)" for tex, display in items]
    return out, ""


class _Formulas:
    """Every formula of a page, gathered, typeset in one go (one KaTeX call, or MathJax's
    delimiters) and put back in its place."""

    def __init__(self, inline_tags: bool = False) -> None:
        self.items: list[tuple[str, bool]] = []
        self.puts: list[Callable[[str], None]] = []
        self.inline_tags = inline_tags

    def add(self, tex: str, display: bool, put: Callable[[str], None]) -> None:
        self.items.append((tex, display))
        self.puts.append(put)

    def parts(self, parts: list[tuple[str, str]] | None) -> list[tuple[str, str]]:
        """A sentence (text and math parts); its math typeset when :meth:`run` runs."""
        out = list(parts or ())
        for i, (kind, s_) in enumerate(out):
            if kind == "math":
                self.add(s_, False, lambda h, i=i: out.__setitem__(i, ("math", h)))
        return out

    def given(self, g: dict[str, Any]) -> None:
        """A given: ``g["html"]``."""
        self.add(g["latex"], False, lambda h: g.__setitem__("html", h))

    def line(self, line: dict[str, Any]) -> None:
        """An equation line: ``line["html"]``; with ``inline_tags`` its number in the display."""
        tex = _aligned(line)
        if self.inline_tags and line.get("tag"):
            tex += rf" \tag{{{line['tag']}}}"
        self.add(tex, True, lambda h: line.__setitem__("html", h))

    def blocks(self, blocks: list[dict[str, Any]]) -> None:
        """Blocks of sentences and equation lines."""
        for block in blocks:
            block["text"] = self.parts(block["text"])
            for line in block["lines"]:
                self.line(line)

    def problem(self, data: dict[str, Any], solution: bool = True) -> None:
        """A problem's page: its givens, statement and Find, its answers, and (``solution``) its
        stages (:func:`derive.writers.view.page.view`): their givens, lines and carried results."""
        for g in data["givens"]:
            self.given(g)
        data["statement"] = self.parts(data["statement"])
        data["find"] = self.parts(data["find"])
        data["convention"] = self.parts(data.get("convention"))
        data["answer_names"] = self.parts(data.get("answer_names"))
        for line in data.get("answers", []):
            self.line(line)
        if solution:
            for st in data["stages"]:
                st["heading"] = self.parts(st.get("heading") or [("text", st["title"])])
                for g in st["givens"]:
                    self.given(g)
                for stage in st["stages"]:
                    stage["heading"] = self.parts(stage.get("heading") or [("text", stage["title"])])
                    self.blocks(stage["blocks"])
                st["carried"] = self.parts([("math", c) for c in st["carried"]])
                self.blocks(st["blocks"])

    def theory(self, page: dict[str, Any]) -> None:
        """A handout's theory page: its tables, blocks and bullets."""
        for sec in page["sections"]:
            sec["table"] = [[self.parts(cell) for cell in row] for row in sec["table"]]
            self.blocks(sec["columns"])
            self.blocks(sec["blocks"])
            sec["bullets"] = [self.parts(item) for item in sec["bullets"]]

    def run(self, math: Callable[[list[tuple[str, bool]]], tuple[list[str], str]]) -> str:
        """Typeset them all and put each in its place; the script the page then needs."""
        rendered, script = math(self.items)
        for put, h in zip(self.puts, rendered, strict=True):
            put(h)
        return script


def lms_html(data: dict[str, Any], part: str, text: Callable[[str], str]) -> str:
    """A problem's statement (``part`` "statement": Given, Find) or worked solution ("solution")
    as the HTML fragment an LMS shows (no ``<html>``): the page's pieces, the math as TeX in
    MathJax's delimiters with each number in its display, text escaped by ``text``."""
    formulas = _Formulas(inline_tags=True)
    formulas.problem(data, solution=part == "solution")
    formulas.run(mathjax)
    return environment("md").get_template("lms.html.j2").render(**data, part=part, text=text)
