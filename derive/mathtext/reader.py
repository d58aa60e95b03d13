"""The relations of a typed text, each with where it stands: plain lines, Markdown, LaTeX.

A text is read line by line. Mathematics in ``$ … $``, ``$$ … $$``, ``\\( … \\)``,
``\\[ … \\]`` or an ``align``/``equation``/``gather`` environment is read by the parser, as
plain text (:mod:`.latex`; rows split at ``\\\\`` and at line ends), text around it is kept, HTML
comments and TeX ``%`` comments dropped, HTML's ``&nbsp;`` a space. Each piece is split: at arrows
(``\\Rightarrow``, ``⇒``, ``→``), at ``;``, at "so", "hence", "then", "but", "and", and at a comma
before another relation (``v_B1n = -6 m/s, v_B1t = 0``); a tag ``(3)`` is taken off, a lead-in up to a colon
(``CLM:``, ``CLM (i):``) and a unit after a number are dropped; words stay (the caller's business).

>>> [(r.line, r.sides) for r in read_relations("2x + y = 5\\nsubtract: 3x = -3  so x = -1, y = 7")]
[(1, ('2x + y', '5')), (2, ('3x', '-3')), (2, ('x', '-1')), (2, ('y', '7'))]
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass, replace

from derive.mathtext.afterwords import after_on_line, before_on_line, body_after, body_lead
from derive.mathtext.anglevectors import angle_vectors
from derive.mathtext.arrows import starts_with_so
from derive.mathtext.asides import without_condition, without_convention
from derive.mathtext.bracketed import bracketed_names
from derive.mathtext.doing import said_doing
from derive.mathtext.entities import decoded
from derive.mathtext.givenmarks import without_doubt, without_given_mark
from derive.mathtext.inline import equals_in_brackets, without_into, words_end_it
from derive.mathtext.latex import REJECTED
from derive.mathtext.laws import law_and_letters, quoted_law
from derive.mathtext.layout import ENV, NESTED, column_vectors, row_plain
from derive.mathtext.matrices import matrices
from derive.mathtext.memories import recalled, stored
from derive.mathtext.momentumlaw import momentum_law
from derive.mathtext.notation import FUNCTIONS, glued_angles
from derive.mathtext.notes import (
    REMARK_END,
    name_after_words,
    said_is,
    unbold,
    unmarked,
    without_note,
)
from derive.mathtext.parser import GREEK
from derive.mathtext.percents import per_cent_sides
from derive.mathtext.resultlists import listed_speeds
from derive.mathtext.sides import (
    decimal_commas,
    direction_of,
    each_body,
    european_points,
    glued_marks,
    thousands,
    typed_names,
    units_inside,
    without_direction,
)
from derive.mathtext.splitting import split_relations
from derive.mathtext.subscripted import ascii_subscripts
from derive.mathtext.tables import headed, table_cells
from derive.mathtext.texwords import tex_comment, tex_row_ends, tex_text
from derive.mathtext.units import UNIT_END, glued_units, in_si, without_unit
from derive.mathtext.vectors import VectorNames, split_vectors
from derive.mathtext.whereclause import went_on_from

#: A row that continues the relation above it: ``&= 6.4``, ``&\\approx 91.7``, ``  ≈ 0.389``.
_CONTINUED = re.compile(r"^[\s&$\\\[]*(?:=|≈|\\approx|\\simeq)")
#: The most relations read from one text.
MAX_RELATIONS = 400


@dataclass(frozen=True)
class Relation:
    """One relation of a text: ``line`` (1-based) and ``column`` (0-based) where its line
    starts, ``written`` that line (or row) as typed, ``sides`` in plain syntax (``a = b = c``
    has three), ``tag`` its label ("3" for ``(3)``; "" where none)."""

    line: int
    column: int
    written: str
    sides: tuple[str, ...]
    tag: str = ""
    lead: str = ""  # a line that continues a relation (``  = 6.4``): the first side of that relation
    label: str = ""  # the words before a colon that lead in (``B before: along = -6``), on the line so far
    aside: bool = False  # after "with", "where" (``KE = ½ mu w^2 with mu = 0.4``): read before the line's relation
    direction: int = 0  # the last number's direction in words: -1 "to the left", "backwards"; +1 "to the right"


_ENV = ENV
#: Where mathematics opens (``\\[`` after a line break, ``J \\\\[2pt]``, is the break's spacing, not a display).
_OPEN = re.compile(rf"\$\$|(?<!\\)\\\[|(?<!\\)\\\(|\\begin\{{(?:{_ENV})\*?\}}(?:\{{\d+\}})?|(?<![\\$])\$")
_CLOSE = {
    "$$": re.compile(r"\$\$"),
    r"\[": re.compile(r"\\\]"),
    r"\(": re.compile(r"\\\)"),
    "$": re.compile(r"(?<!\\)\$"),
}
_ENV_CLOSE = re.compile(rf"\\end\{{(?:{_ENV})\*?\}}")
#: "with", "where": what follows defines the names of the relation before it.
_ASIDE = re.compile(r"(?<![\w.])(?:with|where)(?![\w])(?=[^=]*=)", re.I)
_TAG_END = re.compile(r"\s\(\s*([ijk])\s*\)\s*$")  # the rest: notes.without_note
#: Equations combined, leading in (``2(1) + (2):``, ``(1) - (2)×(−1):``, ``eq 1 + eq 2 ->``, ``(1) - (2)… easier:``).
_REF = r"\d*\s*[×x*]?\s*(?:\(\s*(?:\d{1,2}[a-z]?|[ivx]{1,4})\s*\)|eqn?\.?\s*\(?\d{1,2}\)?)"
_REF += r"(?:\s*[×x*]\s*(?:\(\s*[-−]?\d{1,2}\s*\)|\d{1,2}(?![\d.])))?"  # a multiplier after: "(2)×(−1)"
#: ``(1) + (2) gives``, ``2(1) - (2) ⇒``, and ``(1)+(2)  13 = 3x`` with no word: bare equation numbers
#: only, before a side (not an operator or "=").
_JOIN = r"(?:→|->|=>|⇒|\\Rightarrow\b|\\implies\b|\bgives?\b)"
_COMBINED = re.compile(
    rf"^\s*(?:(?:{_REF}\s*[-+−]\s*)+{_REF}(?:\s*(?:…|\.{{3}})\s*[A-Za-z]+(?:\s+[A-Za-z]+){{0,2}})?\s*(?::(?!=)|{_JOIN})"
    r"|(?:\(\s*\d\s*\)\s*[-+−]\s*)+\(\s*\d\s*\)(?=\s+[^\s=+\-−*/^()]))\s*"
)
#: The equation a relation comes from, leading in (``from (2) x = y - 4``, ``using (ii),``, ``rearranging eqn 1:``):
#: words, never a factor of its first side.
_FROM_REF = re.compile(
    r"^\s*(?:from|using|by|rearranging|rearrange)\s+(?:eq(?:n|uation)?\.?\s*)?"
    r"(?:\(\s*(?:\d{1,2}[a-z]?|[ivx]{1,4})\s*\)|(?<=[nN.]\s)\d{1,2}|(?<=[nN.])\d{1,2})\s*[,:]?\s+(?=[^\s=+*/^)-])",
    re.I,
)
_TAG_START = re.compile(r"^\s*(?:\(\s*(\d{1,2}[a-z]?)\s*\)\s*:?|(\d{1,2}[a-z]?)\s*:)\s+")
#: A part's label before a relation (``(a)``, ``(ii)``, ``b)``, ``Q3(b)``, ``part (c):``): not maths.
_PART = re.compile(
    r"^\s*(?:(?:(?:Q|question\s*)\d{1,2}\s*)?(?:part\s+)?"
    r"(?:\(\s*(?:[a-h]|[ivx]{1,4})\s*\)|(?:[a-h]|[ivx]{1,4})\))(?:\s*\(\s*(?:[a-h]|[ivx]{1,4})\s*\))*"
    r"|(?:Q|question\s*)\d{1,2}[a-h]?)\s*[:.]?\s+(?=[^\s=+*/^)-])",  # "Q5 m = 0.2": a question's number
    re.I,
)
_LEAD = re.compile(r"^\s*(?:(?:[-*+•]|\d{1,2}[.)])\s+)?(?:((?:[^=:()]*[A-Za-z]{2}\s?\([^=:()]{1,20}\))?[^=:()]*):\s*)?")
#: A unit in brackets after a relation: ``(m/s)``, ``(m s^(-1))``, ``(J)``.
_UNIT_BRACKET = re.compile(
    r"\s*\((?=[^()]*[A-Za-z])(?:[\s/*^·.-]|\(\s*-\s*1\s*\)|-?1\b|m|s|kg|N|J|ft|lb|slug)+\)\s*\.?\s*$"
)
_TICK = re.compile(r"\s*(?:✓|✔|✗)\s*")
_COMMENT = re.compile(r"<!--.*?-->", re.S)
#: An angle named by three points (``APB = 90°``, ``∠ABC``, ``angle PQR``): geometry in words.
_POINTS = re.compile(r"^\s*(?:∠|\\angle\s*|angle\s+)?[A-Z]{3}\s*$")
#: What a side has: a letter (Latin or Greek: ``θ + φ = 90°``) or a digit.
_SIDE = re.compile(r"[A-Za-z0-9\u0391-\u03c9\u03d5]")


def read_relations(
    text: str, axes: dict[str, tuple[str, int]] | None = None, head_on: bool = False
) -> tuple[Relation, ...]:
    """Every relation of ``text``, in order (at most :data:`MAX_RELATIONS`); ``axes``: the unit
    vectors' axes where the student placed them in words; ``head_on``: the impact has one axis
    (:func:`.vectors.split_vectors`)."""
    out: list[Relation] = []
    points = european_points(text)
    memory: dict[str, str] = {}
    vectors = VectorNames()  # the names split into components so far: u in "J = m(v - u)"; the frame
    whole: dict[int, tuple[str, ...]] = {}  # a line's last relation before it was split by component
    for line, column, written, plain in pieces(text):
        plain, letter = stored(plain)  # "= 1.08 J  [STO -> A]": the value kept in memory A
        plain = angle_vectors(plain)  # <9, 12>, ⟨9, 12⟩, \langle 9, 12\rangle: the pair (9, 12)
        plain = glued_angles(ascii_subscripts(plain))  # (v_A)ₓ₁, (v)t1: (v_A)_x1, v_t1; sin46.8: sin 46.8
        plain = said_doing(said_is(points(unmarked(unbold(without_doubt(plain))))))  # "B's speed after is 8": B's … = 8
        plain = listed_speeds(plain)  # "A: 6.94 ft/s, B: 3.60 ft/s": the speeds after, listed by body
        plain = without_given_mark(plain)  # "= mu^2(1 - e^2)  (A.G.)": the answer given (after what is withdrawn)
        plain = momentum_law(equals_in_brackets(plain))  # "= 0.346 (= 0.2 sqrt3)": one more side; Σmu = Σmv
        plain = without_condition(plain)  # "e = 2/3 (e > 0)": why the root was taken
        lead = ""
        if plain.lstrip().startswith(("=", "≈")) and _CONTINUED.match(written) and out:  # "  = 6.4": continued
            above = next((r for r in reversed(out) if not r.aside or r.line != out[-1].line), out[-1])
            above = went_on_from(above, [r for r in out if r.line == above.line and not r.aside])  # "…, μ = ⅔"
            sides = whole.get(above.line, above.sides)  # "J = 0.06(39.6 i)  = 2.376 i": the vector
            plain = f"{sides[-1]} {plain}"
            lead = above.lead or sides[0]
        m = _ASIDE.search(plain)
        main, aside = (plain[: m.start()], plain[m.end() :]) if m else (plain, "")
        if m and main.rstrip().endswith("(") and aside.rstrip().endswith(")"):  # "= 4.46 J (with V = 1.4925 it's 4.48)"
            main, aside = main.rstrip()[:-1], aside.rstrip()[:-1]
        main, aside = thousands(main), thousands(aside)  # "3,000(6)": one number, not two relations
        main, aside = decimal_commas(main), decimal_commas(aside)  # "0,25": nought point two
        parts = law_and_letters(split_relations(aside), split_relations(main))  # "v^2 = u^2 + 2as with u = 0"
        for part, is_aside in parts:
            r = after_on_line(relation(line, column, written, part), main, part)  # "After …: A = (v, 0)"
            r = replace(r, aside=True) if r is not None and is_aside else r
            r = replace(r, lead=lead) if r is not None and lead else r
            if r is not None and not r.label and out and out[-1].line == line and out[-1].label:
                r = replace(r, label=out[-1].label)  # "A: u_x = 2, u_y = 3": both of A
            split = split_vectors(r.sides, axes, head_on, vectors, r.label) if r is not None else []
            if r is not None and not r.aside and split != [r.sides]:
                whole[line] = r.sides
            for sides in (e for v in split for e in each_body(v, text)):
                said = main[: max(main.find(part), 0)] + part.split("=", 1)[0]
                out.append(before_on_line(replace(r, sides=recalled(sides, memory)), said))  # "before: vA = 4j"
                if len(out) >= MAX_RELATIONS:
                    return tuple(out)
        if letter and out and out[-1].line == line:
            memory[letter] = out[-1].sides[-1]
    return tuple(out)


#: A run of more digits than any number a student writes: the reader's patterns would take minutes
#: to try it (a run of 20000 digits took two), so it is shown shortened and the line is not read.
_LONG_NUMBER = re.compile(r"\d{40,}")


def pieces(text: str) -> Iterator[tuple[int, int, str, str]]:
    """(line, column, as written, plain text) of each line, and of each row of a display
    (a display that spans lines is one row until ``\\\\``, at the line where the row starts)."""
    text = decoded(text.replace("\r\n", "\n").replace("\r", "\n"))  # &nbsp;, &times;: a space, ×
    text = _LONG_NUMBER.sub(lambda m: f"{m.group(0)[:12]}…(a number of {len(m.group(0))} digits)", text)
    text = _COMMENT.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)
    lines = text.split("\n")
    n, close, rows = 0, None, []
    while n < len(lines):
        raw = tex_row_ends(tex_comment(lines[n]))  # "\\[4pt]": the row ends there
        if close is None:
            plain, close, rows = _line(
                table_cells(headed(lines, n) if raw == lines[n] else raw), n + 1
            )  # "| after | $… = 3.88$ |": a table's row
            if plain.strip():
                yield n + 1, len(raw) - len(raw.lstrip()), _unwrapped(lines[n]), plain
        else:
            m = close.search(raw)
            rows.append((n + 1, raw[: m.start()] if m else raw))
            if m:
                yield from _rows(rows, lines)
                plain, close, rows = _line(raw[m.end() :], n + 1)
                if plain.strip():
                    yield n + 1, m.end(), lines[n].strip(), plain
        n += 1
    if rows:
        yield from _rows(rows, lines)


def _unwrapped(line: str) -> str:
    """A line as written, without the delimiters of a display that is all of it."""
    m = re.fullmatch(r"\s*(?:\$\$(.+)\$\$|\\\[(.+)\\\])\s*", line)
    return (m.group(1) or m.group(2)).strip() if m else line.strip()


def _goes_on(part: str, row: list[str]) -> bool:
    """Whether a line of a display that starts with ``=`` goes on from a relation above it
    (``\\tan\\theta = \\frac{…}{…}`` then `` = \\frac{…}{…}`` on the next line, no ``\\\\``):
    its own row, continued from the last side as a line ``= …`` is, so each line is judged."""
    return _CONTINUED.match(part) is not None and re.search(r"=|≈|\\approx", "".join(row)) is not None


def _after_comma(part: str, row: list[str]) -> bool:
    """Whether a line of a display starts a relation of its own after a relation above it that
    ends with a comma (a matrix equation ending ``…,`` then ``\\qquad \\Delta = 5.`` below it, no
    row break): its own row, at its own line."""
    above = "".join(row).rstrip()
    return above.endswith(",") and "=" in above and "=" in part and not _CONTINUED.match(part)


def _rows(rows: list[tuple[int, str]], lines: list[str]) -> Iterator[tuple[int, int, str, str]]:
    """The rows of a display that spans lines: its text split at ``\\\\``, an arrow that means
    "so" or an ``=`` that starts a line (an arrow or ``\\\\``: a new row; ``=``: the row goes on)."""
    row: list[str] = []
    first = rows[0][0]
    for number, text in rows:
        text = NESTED.sub(" ", column_vectors(matrices(text)))
        parts = re.split(r"\\\\", text)
        for k, part in (
            (k > 0 or starts_with_so(p) or _goes_on(p, row) or _after_comma(p, row), p) for k, p in enumerate(parts)
        ):
            if k and "".join(row).strip():
                yield first, 0, lines[first - 1].strip(), row_plain(" ".join(row))
            if k:
                row, first = [], number
            if not "".join(row).strip():
                first = number
            row.append(part)
    if "".join(row).strip():
        yield first, 0, lines[first - 1].strip(), row_plain(" ".join(row))


#: LaTeX's mathematics on a line with no ``$`` (``v_{A2} = \\frac{8}{9}u``, ``4 \\times 12``).
_BARE_LATEX = re.compile(r"\\(?:[dt]?frac|sqrt|cdot|times|left|right|approx)(?![A-Za-z])")


def _line(raw: str, number: int) -> tuple[str, re.Pattern | None, list[tuple[int, str]]]:
    """One line outside a display: its text with each piece of mathematics in it made plain
    (rows of a display on one line joined by ";"); the closing mark of a display it opens
    and does not close (None where it closes all), and that display's text so far."""
    out, i = [], 0
    while True:
        m = _OPEN.search(raw, i)
        if m is None:  # LaTeX typed with no delimiters (``v_A2 = \\frac{8}{9}u``): read as mathematics
            rest = raw[i:]
            out.append(row_plain(rest) if i == 0 and _BARE_LATEX.search(rest) else tex_text(rest))
            return " ".join(out), None, []
        out.append(tex_text(raw[i : m.start()]))
        close = _CLOSE.get(m.group(0), _ENV_CLOSE)
        end = close.search(raw, m.end())
        if end is None:
            return " ".join(out), close, [(number, raw[m.end() :])]
        body = column_vectors(matrices(raw[m.end() : end.start()]))  # a column vector's "\\" is no new row
        out.append(" ; ".join(row_plain(row) for row in re.split(r"\\\\", NESTED.sub(" ", body))))
        i = end.end()
        if words_end_it(out[-1], raw[i:], " ".join(out[:-1])):
            out.append(";")  # "Sub $v_Q = v_P + 5ue$ into (1):": the words after are not the relation's


_WORD = re.compile(r"(?<![\w])(?:[A-Za-z]{3,}|to|of|at|on|in|up|by|as|is|ok|OK|it)(?![\w(^])")
#: Words that belong to the mathematics (functions, angle units, Greek letters' names).
MATH_WORDS = GREEK | FUNCTIONS | {"deg", "degree", "degrees", "rad", "radian", "radians"}


def words_after(text: str) -> str:
    """A relation without the words after its last number (``= 111° anticlockwise from i``,
    ``= 3.45 N s upwards``, ``= 0.64, i.e. 64 %``): they say what the number is."""
    last = text.rfind("=")
    rest = re.split(r"\s*(?:…|\.{3})\s*(?=[A-Za-z]{2,}\b)", text[last + 1 :])[0]  # "= 2u … not what they want"
    text = text[: last + 1] + without_into(REMARK_END.sub("", rest))  # ", i.e. 64 %", ", into (1)"
    for m in _WORD.finditer(text, last + 1):
        if m.group(0) in MATH_WORDS:
            continue
        before = text[last + 1 : m.start()].rstrip(" ,;:?!…")  # "= -0.91 J ?? gained", "= 1.69 … not 4"
        unitless = re.sub(r"\s*(?:deg(?:rees?)?|rad(?:ians?)?)$", "", UNIT_END.sub("", before).rstrip(" ,;:."))
        after_comma = re.search(r"[\w²³)'′]\s*,\s*$", text[last + 1 : m.start()])  # "(3010)V², cancel 3010"
        if after_comma or (re.search(r"\d", before) and re.search(r"[\d°)%]$", unitless.rstrip(" ie."))):
            return text[: last + 1] + re.sub(r",?\s*(?:i\.\s?e\.?)?\s*$", "", before)
        return text
    return text


#: A name in brackets with the instant or component after them (``(v_B)_2``, ``(v_{A})_{1}``, ``(v_A)_n'``).
_BRACKETED_NAME = re.compile(r"\(\s*([A-Za-z])_\(?(\w{1,2})\)?\s*\)\s*_\s*\(?([0-9nftixy])\)?(?![^\W²³])")


#: The impulse as the integral of the force over the time (``\\int F\\,dt``, ``∫F dt``, ``Int F dt``, limits or none).
_INTEGRAL = re.compile(
    r"(?:\\int|∫|\b[Ii]nt(?:egral)?(?:\s+of)?(?=\s*F\b))(?:_\{?[^\s{}]*\}?)?(?:\^\{?[^\s{}]*\}?)?\s*F(?:\s*\(t\))?\s*\*?\s*d\s*t\b"
)


def _side(text: str) -> str:
    """A side without the unit after its number; a number in a multiple of an SI unit (``22 g``,
    ``20 Mg``, ``45 km/h``) in that unit (``22/1000``)."""
    text = text.strip().rstrip(",;:.?!…").rstrip()  # "= -12 J ???", "= 1.69…": the doubt is not the value
    text = _INTEGRAL.sub("impulse", text)  # ∫F dt = m(v - u): the impulse
    text = re.sub(r"Δ\s*", "Delta ", text)  # ΔKE as LaTeX's \Delta KE is read
    text = typed_names(text)  # v_{A2}, v_{A,2}, v'_A as a name is read
    text = decimal_commas(thousands(bracketed_names(text)))  # (v_A)', (vA)1, (v_B)_2x: one name each; 20 000
    text = _BRACKETED_NAME.sub(lambda m: f"{m[1]}_{m[2]}{m[3]}", text)  # (v_B)_2: v_B2, as the textbooks write it
    text = units_inside(text)  # "352 J − 288 J": the unit of each number, not a name
    return in_si(text) or without_unit(text).strip()


def _outer(text: str) -> str:
    """A relation written inside one pair of brackets, as an aside (``(angle with the normal =
    90 - 1.27 = 88.7°)``), without them."""
    t = text.strip()
    if t.endswith(")") and _closes_nothing(t):
        return t[:-1]  # its opening bracket went with the words before it
    if not (t.startswith("(") and t.endswith(")") and "=" in t):
        return text
    depth = 0
    for i, ch in enumerate(t):
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if depth == 0 and i < len(t) - 1:
            return text  # "(a + b) = (c + d)": not one pair around it all
    return t[1:-1]


#: A sentence in brackets after a relation's full stop: ``= u(1 - e)/4. (The question has …)``.
_REMARK = re.compile(r"\s*\.\s+\((?=\s*[A-Za-z][a-z']+\s+[A-Za-z])")


def _without_remark(text: str) -> str:
    """``text`` without a remark in brackets after its full stop (a sentence, its brackets
    balanced, to the end), which is the student's aside, not part of the value."""
    m = _REMARK.search(text)
    if m is None or not text.rstrip().endswith(")"):
        return text
    tail = text[m.end() - 1 :].rstrip()
    depth = 0
    for i, ch in enumerate(tail):
        depth += {"(": 1, ")": -1}.get(ch, 0)
        if depth == 0 and i < len(tail) - 1:
            return text  # "(a) and (b)": not one bracket to the end
    return text[: m.start()] if depth == 0 else text


def _closes_nothing(t: str) -> bool:
    """Whether the last ``)`` of ``t`` closes no ``(`` of ``t`` (``1) v = 1.2 (away)``: it does)."""
    depth = 0
    for ch in t[:-1]:
        depth = max(depth + {"(": 1, ")": -1}.get(ch, 0), 0)  # "1)": a label's bracket, opening none
    return depth == 0


def relation(line: int, column: int, written: str, text: str) -> Relation | None:
    """The relation in ``text`` (plain syntax), or None where it has no ``=`` or is an
    inequality."""
    written_text = text
    text = re.sub(  # a tick, and a check word after the value ("= 91.7 J  ok"): not part of it
        r"(?<=[\w.)°])\s+(?:ok|okay|checks?(?:\s+out)?|as\s+required|as\s+expected|shown|proved|QED)[.!]?\s*$",
        "",
        _TICK.sub(" ", without_note(text)[0]),
        flags=re.I,
    )
    tag = without_note(written_text)[1]
    text = _outer(_PART.sub("", _FROM_REF.sub("", _COMBINED.sub("", text.lstrip(" ,;:")), count=1), count=1))
    m = _TAG_START.match(text)
    if m:
        tag, text = m.group(1) or m.group(2), text[m.end() :]
    m = _LEAD.match(text.strip())
    label = (m.group(1) or "").strip() if m else ""
    text = text.strip()[m.end() :] if m else text.strip()
    m = _WORD_LEAD.match(text) if not label else None
    if m and m.group(1).lower() not in MATH_WORDS and "=" not in m.group(1):
        label, text = m.group(1), text[m.end() :]
    label, text = (label, text) if label else body_lead(text)  # "so B has u = -2": B's, as "B: u = -2"
    m = _TAG_END.search(text)
    if m:
        tag, text = m.group(1), text[: m.start()]
    text = re.sub(r"\s\((?:[^()]*(?:=|[<>≤≥])[^()]*)\)\s*$", "", text)  # "(e = 1)", "(e > 0)" after it: a remark
    text = _without_remark(text)
    text = re.sub(r"(=[^=<>≤≥≠!]*?)\s*(?:[<>]|≤|≥|≠|\\neq?\b|!=)[^=]*$", r"\1", text)  # "= 2.38 > 0", "≠ 2tanα"
    if "=" not in text or re.search(r"≠|\\neq?\b|!=|[<>]=?|≤|≥", text) or REJECTED.search(text[text.rfind("=") :]):
        return None
    direction = direction_of(text[text.rfind("=") + 1 :])
    if direction:  # the words said, the number is left: "= 1.04 m/s in the opposite direction"
        text = without_direction(text)
    text = _UNIT_BRACKET.sub("", words_after(glued_marks(without_convention(text))))  # 2 vAx: a name, not words
    sides = glued_units(tuple(_side(s) for s in text.split("=")))  # = 19.98/19.6 = 1.02m: metres
    sides = (body_after(sides[0], name_after_words(sides[0], MATH_WORDS | _LEAD_WORDS), label), *sides[1:])
    sides = per_cent_sides(sides)  # "64/352 × 100 = 18.2 %": the % a label of the number
    if quoted_law(sides):
        return None  # "v^2 = u^2 + 2as": a law quoted before it is used, not marked
    if any(not re.search(_SIDE, s) or _POINTS.match(s) for s in sides):  # "\text{angle with …} = …": words
        sides = tuple(s for s in sides if re.search(_SIDE, s) and not _POINTS.match(s))
        if len(sides) < 2:
            return None
    return Relation(line, column, written, sides, tag, label=label, direction=direction)


#: Words that name a quantity before a letter (``KE T``?): not taken for prose before a name.
_LEAD_WORDS = frozenset({"delta", "sqrt", "atan", "asin", "acos"})
#: A lead-in in words without a colon, apart from the relation by a wide gap (``momentum     m(5u) = …``).
_WORD_LEAD = re.compile(r"^\s*((?:[A-Za-z][a-z']{2,}|CLM|NEL|NLR|KE|COM|CoM)(?:\s[A-Za-z][a-z']{2,})*)\s{2,}(?=[^\s=])")
