"""Reading a typed derivation: each relation a student wrote, in the parser's syntax.

A derivation comes as plain lines (``20 v_A2n + 5 v_B2n = 19.8``, one relation a
line), or as Markdown or LaTeX whose mathematics is in ``$$ … $$``, ``\\[ … \\]``,
``$ … $`` or an ``align``/``equation``/``gather`` environment (rows split at
``\\\\``). Each relation becomes a :class:`Line`: where it starts in the file, the
text as written, its sides (``a = b = c`` has three) in the grammar of
:mod:`derive.problem.expr`, and its tag ``(3)`` if it has one. The reader knows
nothing of the problem; :mod:`.lines` judges what it reads.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass

from derive.checking.notation import student

#: The most relations of one derivation that are judged (the rest are reported as not checked).
MAX_LINES = 200


@dataclass(frozen=True)
class Line:
    """One relation of a derivation: ``number`` the line of the file it starts on,
    ``written`` the text as written, ``sides`` in the parser's syntax, ``tag`` its
    label ("3" for ``(3)``; "" where none)."""

    number: int
    written: str
    sides: tuple[str, ...]
    tag: str = ""


_MATH = re.compile(
    r"\$\$(?P<dd>.+?)\$\$|\\\[(?P<br>.+?)\\\]|\\begin\{(?P<env>align|equation|gather|eqnarray|multline)(?P<star>\*?)\}"
    r"(?P<body>.+?)\\end\{(?P=env)(?P=star)\}|(?<![\\$])\$(?P<d>[^$\n]+?)\$",
    re.S,
)
_ARROW = re.compile(r"⇒|⟹|→|=>|->|∴|\\(?:Rightarrow|Longrightarrow|implies|rightarrow|to|therefore)\b")
_TAG_END = re.compile(r"\s\(\s*(\d{1,2}[a-z]?)\s*\)\s*$")
_TAG_START = re.compile(r"^\s*(?:\(\s*(\d{1,2}[a-z]?)\s*\)\s*:?|(\d{1,2}[a-z]?)\s*:)\s+")
_UNIT_END = re.compile(r"(?<=[\d.)])\s*(?:m/s|ft/s|km/h|mi/h|N[·*]s|lb[·*]s|kg|kJ|J|ft[·*]lb|slug)\s*$")
_LEAD = re.compile(r"^\s*(?:[^=:]*:\s+|(?:so|then|hence|thus|therefore|and|gives?)\s+)", re.I)


def read_derivation(text: str) -> tuple[Line, ...]:
    """Every relation of ``text`` (Markdown/LaTeX where it has math delimiters, else plain lines)."""
    text = text.replace("\r\n", "\n").replace("≈", "=")
    latex = _MATH.search(text) is not None
    pieces = list(_latex_pieces(text)) if latex else list(_plain_pieces(text))
    out: list[Line] = []
    for number, written, plain in pieces:
        for part in _ARROW.split(plain):
            line = relation(number, written, part)
            if line is not None:
                out.append(line)
    return tuple(out)


def relation(number: int, written: str, text: str) -> Line | None:
    """The relation in ``text`` (plain syntax), or None where it has no ``=``."""
    tag = ""
    m = _TAG_START.match(text)
    if m:
        tag, text = m.group(1) or m.group(2), text[m.end() :]
    text = _LEAD.sub("", text.strip()) if "=" in text else text
    m = _TAG_END.search(text)
    if m:
        tag, text = m.group(1), text[: m.start()]
    if "=" not in text or re.search(r"≠|\\neq?\b|!=|[<>]=?", text):
        return None
    sides = tuple(student(names(_UNIT_END.sub("", s.strip()))) for s in text.split("="))
    if any(not s.strip() for s in sides):
        return None
    return Line(number, written.strip(), sides, tag)


def names(text: str) -> str:
    """The notes' spellings of names as the problem's: ``V_{At2}``, ``V_{A2t}`` -> ``v_A2t``;
    ``M_A`` -> ``m_A``; ``V_{A1}`` -> ``v_A1``."""
    text = re.sub(r"\b[vV]_\{?([AB])([12])([nt])\}?", r"v_\1\2\3", text)
    text = re.sub(r"\b[vV]_\{?([AB])([nt])([12])\}?", r"v_\1\3\2", text)
    text = re.sub(r"\b[vV]_\{?([AB])([12])?\}?(?![\w])", lambda m: f"v_{m.group(1)}{m.group(2) or ''}", text)
    return re.sub(r"\bM_\{?([AB])\}?", r"m_\1", text)


def _plain_pieces(text: str) -> Iterator[tuple[int, str, str]]:
    """(line number, as written, plain text) of each line that is not empty or a comment."""
    for n, line in enumerate(text.splitlines(), 1):
        if line.strip() and not line.lstrip().startswith("#"):
            yield n, line, line


def _latex_pieces(text: str) -> Iterator[tuple[int, str, str]]:
    """(line number, as written, plain text) of each row of each piece of mathematics."""
    for m in _MATH.finditer(text):
        group = next(g for g in ("dd", "br", "body", "d") if m.group(g) is not None)
        body, start = m.group(group), m.start(group)
        offset = 0
        for row in re.split(r"\\\\", body):
            lead = len(row) - len(row.lstrip())
            number = text.count("\n", 0, start + offset + lead) + 1
            offset += len(row) + 2
            if row.strip():
                yield number, " ".join(row.split()), latex_to_plain(row)


# ---------------------------------------------------------------- LaTeX


_DROP = re.compile(
    r"\\(?:left|right|displaystyle|quad|qquad|[,;:! ]|big|Big|bigg|Bigg)(?![A-Za-z])|&|~|\\label\{[^}]*\}|\\nonumber"
)
_WORDS = {
    r"\theta": " theta ",
    r"\beta": " beta ",
    r"\alpha": " alpha ",
    r"\phi": " phi ",
    r"\pi": " pi ",
    r"\cdot": "*",
    r"\times": "*",
    r"\div": "/",
    r"\circ": "°",
    r"\approx": "=",
    r"\degree": "°",
    r"\arctan": " atan ",
    r"\arcsin": " asin ",
    r"\arccos": " acos ",
    r"\sin": " sin ",
    r"\cos": " cos ",
    r"\tan": " tan ",
}
_WRAPPERS = ("cancel", "bcancel", "xcancel", "boxed", "vec", "bar", "mathbf", "mathit", "overline", "operatorname")


def latex_to_plain(tex: str) -> str:
    """A row of LaTeX mathematics as plain text: ``\\frac{a}{b}`` -> ``((a)/(b))``,
    ``v_{A2n}`` -> ``v_A2n``, ``5 \\cos 37.6^\\circ`` -> ``5 cos 37.6°`` …"""
    s = re.sub(r"\\tag\*?\{([^{}]*)\}", r" (\1)", tex)
    s = re.sub(r"\\(?:text|mathrm|textrm|mbox|textit)\{([^{}]*)\}", _text_tag, s)
    s = re.sub(r"\\(?:underbrace|overbrace)(\{(?:[^{}]|\{[^{}]*\})*\})(?:[_^]\{(?:[^{}]|\{[^{}]*\})*\})?", r"\1", s)
    s = _DROP.sub(" ", s)
    s = re.sub(r"\\(sin|cos|tan)\s*\^\s*(?:\{\s*-1\s*\}|-1)", r"\\arc\1", s)
    s = re.sub(r"\^\s*\{\s*\\circ\s*\}|\^\s*\\circ", "°", s)
    for cmd in _WRAPPERS:
        s = re.sub(rf"\\{cmd}\s*\{{", "{", s)
    s = _fracs(s)
    s = re.sub(r"\\sqrt\s*\{", "sqrt{", s)
    for word, plain in _WORDS.items():
        s = re.sub(re.escape(word) + r"(?![A-Za-z])", plain, s)
    s = re.sub(r"_\{([A-Za-z0-9]+)\}", r"_\1", s)
    s = re.sub(r"\s+_", "_", s)
    s = re.sub(r"\^\{", "^{", s)
    return " ".join(s.replace("{", "(").replace("}", ")").split())


def _text_tag(m: re.Match) -> str:
    """Words and units in ``\\text{…}`` are dropped; a tag in them (``m/s (4)``) is kept."""
    tag = re.search(r"\(\s*\d{1,2}[a-z]?\s*\)\s*$", m.group(1))
    return f" {tag.group(0).strip()} " if tag else " "


def _fracs(s: str) -> str:
    """``\\frac{a}{b}`` (also ``\\dfrac``, ``\\tfrac``) as ``{(a)/(b)}``, nested ones too."""
    pattern = re.compile(r"\\[dt]?frac\s*")
    while True:
        m = pattern.search(s)
        if not m:
            return s
        num, after = _group(s, m.end())
        den, end = _group(s, after)
        if num is None or den is None:
            return s[: m.start()] + s[m.end() :]
        s = s[: m.start()] + "{(" + num + ")/(" + den + ")}" + s[end:]


def _group(s: str, i: int) -> tuple[str | None, int]:
    """The brace group (or single character) at ``s[i]``, and where it ends."""
    while i < len(s) and s[i] == " ":
        i += 1
    if i >= len(s):
        return None, i
    if s[i] != "{":
        return s[i], i + 1
    depth = 0
    for j in range(i, len(s)):
        depth += {"{": 1, "}": -1}.get(s[j], 0)
        if depth == 0:
            return s[i + 1 : j], j + 1
    return None, len(s)
