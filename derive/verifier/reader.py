"""Read a rendered page (Markdown or LaTeX) into the lines a reader checks, with their context.

Each :class:`PageLine` is one piece of mathematics a reader takes as a claim: a
displayed line, a given in a Given list, a value carried to the next stage of
a chain. It keeps where it stands: its line number in the text, the section
and the part of the page it belongs to (a chain's stage, or the chain itself),
and the sentence it follows ("Add (3) and (4): ...").
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

_MATH = re.compile(r"\$([^$]+)\$")
_STAGE = re.compile(r"Stage (\d+):")


@dataclass(frozen=True)
class PageLine:
    """One claim on the page, in its context.

    ``kind`` is 'display', 'given' or 'carried'; ``scope`` is '' (a problem),
    'chain' or 'stage N'; ``block`` numbers the sentence-and-lines groups.
    """

    number: int
    kind: str
    latex: str
    scope: str
    section: str
    sentence: str
    block: int


class _Page:
    """What the reader knows at the current point of the text."""

    def __init__(self, chain: bool) -> None:
        self.chain = chain
        self.scope = "chain" if chain else ""
        self.section = ""
        self.sentence = ""
        self.block = 0
        self.lines: list[PageLine] = []

    def heading(self, text: str, level: int) -> None:
        m = _STAGE.match(text)
        if self.chain and m:
            self.scope = f"stage {m.group(1)}"
        elif self.chain and level <= 2 and text.strip() == "Answer":
            self.scope = "chain"
        self.section = text.strip()
        self.sentence = ""
        self.block += 1

    def paragraph(self, text: str) -> None:
        self.sentence = text.strip()
        self.block += 1

    def add(self, number: int, kind: str, latex: str) -> None:
        latex = _unaligned(latex) if kind == "display" else latex
        self.lines.append(PageLine(number, kind, latex.strip(), self.scope, self.section, self.sentence, self.block))

    def display(self, rows: list[str], i: int, closes: Callable[[str], bool]) -> int:
        """Adds the display that opens at row ``i``, up to the row that ``closes`` it
        (stripped); returns the index of the row after that."""
        j = i + 1
        while j < len(rows) and not closes(rows[j].strip()):
            j += 1
        self.add(i + 2, "display", "\n".join(rows[i + 1 : j]))
        return j + 1

    def inline(self, number: int, text: str) -> None:
        """A paragraph that holds claims: a Given list of a stage, or carried values."""
        if text.startswith("Carried to the next stages:"):
            for m in _MATH.finditer(text):
                self.add(number, "carried", m.group(1))
        elif text.startswith("Given.") and "$" in text:
            for m in _MATH.finditer(text):
                self.add(number, "given", m.group(1))
        else:
            self.paragraph(text)


def read_markdown(text: str) -> list[PageLine]:
    """The claims of a Markdown page."""
    rows = text.splitlines()
    page = _Page(any(re.match(r"#{2,3} Stage \d+:", r) for r in rows))
    i = 0
    para: list[str] = []
    start = 0

    def flush() -> None:
        if para:
            page.inline(start, " ".join(para).replace("**", ""))
            para.clear()

    while i < len(rows):
        row = rows[i].rstrip()
        if row.strip() == "$$":
            flush()
            i = page.display(rows, i, lambda r: r == "$$")
            continue
        m = re.match(r"(#+) (.*)", row)
        if m:
            flush()
            page.heading(m.group(2), len(m.group(1)))
        elif row.startswith("- $"):
            flush()
            g = _MATH.search(row)
            if g:
                page.add(i + 1, "given", g.group(1))
        elif not row.strip() or row.startswith("<"):
            flush()
        else:
            if not para:
                start = i + 1
            para.append(row.strip())
        i += 1
    flush()
    return page.lines


_TEX_TEXT = [
    (r"\\textdegree\{\}", "°"),
    (r"\\textbf\{([^{}]*)\}", r"\1"),
    (r"\\emph\{([^{}]*)\}", r"\1"),
    (r"\\noindent\s*", ""),
    (r"\\par\b.*$", ""),
    (r"(?<!-)--(?!-)", "–"),
    (r"\\textquotesingle\{\}", "'"),
]


def _tex_text(row: str) -> str:
    for pattern, repl in _TEX_TEXT:
        row = re.sub(pattern, repl, row)
    return row.strip()


def _unaligned(latex: str) -> str:
    r"""A line set in ``aligned`` rows because it was too wide (``T &= a \\ &= b``, ``&\quad + c``), as one line."""
    if r"\begin{aligned}" not in latex:
        return latex
    body = re.sub(r"\\(?:begin|end)\{aligned\}", " ", latex)
    body = re.sub(r"\\\\\s*&\s*(?:\\quad\s*)?", " ", body)  # a row break and the next row's alignment
    return re.sub(r"[ \t]*\n[ \t]*", "\n", body.replace("&", " ")).strip()


def read_latex(text: str) -> list[PageLine]:
    """The claims of a LaTeX page (a document or a fragment)."""
    rows = text.splitlines()
    page = _Page(any(re.match(r"\\subsection\*\{Stage \d+:", r) for r in rows))
    i = 0
    skip_until = None
    while i < len(rows):
        row = rows[i].strip()
        if skip_until is not None:
            if row.startswith(skip_until):
                skip_until = None
            i += 1
            continue
        if row.startswith(r"\begin{equation"):
            i = page.display(rows, i, lambda r: r.startswith(r"\end{equation"))
            continue
        m = re.match(r"\\(sub)*section\*?\{(.*)\}$", row)
        if m:
            page.heading(_tex_text(m.group(2)), 1 + (m.group(0).count("sub")))
        elif row.startswith((r"\begin{center}", r"\begin{tikzpicture}", r"\begin{figure}")):
            skip_until = r"\end{" + row.split("{", 1)[1].split("}", 1)[0]
        elif row.startswith(r"\item $"):
            g = _MATH.search(row)
            if g:
                page.add(i + 1, "given", g.group(1))
        elif row.startswith(r"\noindent"):
            page.inline(i + 1, _tex_text(row))
        i += 1
    return page.lines


def read(text: str, fmt: str) -> list[PageLine]:
    """The claims of a page in ``fmt`` ('md', 'tex' or 'tex-fragment')."""
    return read_markdown(text) if fmt == "md" else read_latex(text)
