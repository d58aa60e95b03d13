"""A displayed line of LaTeX read with its decorations: ``\\Rightarrow`` before it, ``\\boxed{}``
around it, ``\\tag{}`` after it, the marks the caller counts, and its relations (:mod:`.parser`)."""

from __future__ import annotations

import re

from derive.mathtext.parser import Parser
from derive.mathtext.tree import Display, ParsedRelation

TAG = re.compile(r"\\tag\{([^{}]*)\}\s*$")


def strip_boxed(body: str) -> tuple[str, bool]:
    """``\\boxed{X}`` (the whole line) -> X (its braces found by the tokens of the parser)."""
    s = body.strip()
    if not s.startswith(r"\boxed{"):
        return s, False
    p = Parser(s)
    p.take()
    p.group_tokens()  # LatexError where the braces do not close
    return (s[len(r"\boxed{") : p.spans[p.i - 1][0]], True) if p.at_end() else (s, False)


def parse_display(body: str, mark: str = "") -> Display:
    """A displayed line (the text between its delimiters) read into a :class:`Display`;
    each ``mark`` in it (text that flags an answer) is counted in ``answer_marks`` and left out."""
    s = body.strip()
    tag = None
    m = TAG.search(s)
    if m:
        tag, s = m.group(1).strip(), s[: m.start()].rstrip()
    marks = s.count(mark) if mark else 0
    s = s.replace(mark, "").strip() if mark else s
    implies = s.startswith(r"\Rightarrow")
    s = re.sub(r"^\\Rightarrow(?:\\quad|\\qquad|\\,|\s)*", "", s)
    s, boxed = strip_boxed(s)
    if re.fullmatch(r"\\text\{[^{}]*\}", s):
        return Display(implies, boxed, marks, tag, (), True, body)
    relations = Parser(s).relations()
    return Display(implies, boxed, marks, tag, tuple(relations), False, body)


def parse_inline(body: str) -> ParsedRelation:
    """Inline mathematics (a given, a carried value) read as one relation."""
    rels = Parser(body.strip()).relations()
    return rels[0]
