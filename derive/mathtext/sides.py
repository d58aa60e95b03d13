"""What a side of a relation holds besides its mathematics, as students type it: a name's marks
typed another way (``v_{A2}``, ``v_{A,2}``, ``v_(A2)``, ``v'_A``), a unit after each number inside
it (``352 J − 288 J``), and a direction in words after its number (``= 1.04 m/s to the left``).

>>> typed_names("v'_A + v_{B,2}"), units_inside("352 J − 288 J"), direction_of("2 m/s to the left")
("v_A' + v_B2", '352 − 288 J', -1)
"""

from __future__ import annotations

import re
from collections.abc import Callable

from derive.mathtext.units import UNIT

#: A subscript or power in braces typed in plain text (``v_{A2} = 4``, ``u^{2}``), as it is in LaTeX.
_BRACED = re.compile(r"([_^])\{\s*([A-Za-z0-9]{1,6}|-?\d{1,3})\s*\}")


#: A subscript with a comma or in brackets (``v_{A,2}``, ``v_(A2)``, ``v_(A,2)``).
_SUBSCRIPT_MARKED = re.compile(r"_[{(]\s*([A-Za-z])\s*,?\s*([A-Za-z0-9]{0,2})\s*[})]")
#: A prime before the subscript (``v'_A``, ``v'_(A)``).
_PRIME_FIRST = re.compile(r"(?<![\w'])([A-Za-z])('+)\s*_\s*[({]?([A-Za-z][A-Za-z0-9]{0,2})[)}]?")


#: A mass, weight, velocity or momentum letter with a body's capital glued on (``mA``, ``WA``, ``vB``,
#: ``mP``), alone or after a number (``2WB``: 2 W_B); not a product of two names (``mM``, ``mV``: m times M,
#: m times the common velocity).
_GLUED_BODY = re.compile(r"(?<![A-Za-z_'\\])([muvwpW])([ABPQ])(?![\w'])")
#: A velocity letter with a body's capital and its component or time glued on (``vAx``, ``vBy``,
#: ``uAx1``, ``vB2``, ``vBt'``, ``VAx``): one name, ``v_Ax``, as ``v_Ax`` is.
_GLUED_MARKS = re.compile(r"(?<![A-Za-z_'\\])([uvwV])([ABPQ])([xynt][12]?|[12][xynt]?)(?![\w])")
#: A number with its thousands set apart by a space (``20 000``, ``1 500 000``; a thin space too).
_THOUSANDS = re.compile(r"(?<![\d.^/_])\d{1,3}(?:[ \u00a0\u2009\u202f]\d{3})+(?![\d.])")


#: The same with commas (``20,000``, ``1,581.25``), no space after them: not a pair ``(3, 4)``, nor
#: a decimal comma after a nought (``0,250``).
_THOUSANDS_COMMA = re.compile(r"(?<![\d.^_,])(?!0,)\d{1,3}(?:,\d{3})+(?![\d,])")
#: A decimal comma as European students type it (``0,25``, ``3,46``, ``-0,0761``): digits either side,
#: no space; not a list of three or more (``1,2,3``), nor thousands (read before it).
_DECIMAL_COMMA = re.compile(r"(?<![\d.,^_])(\d+),(\d+)(?![\d,]|\.\d)")
#: A pair in brackets of its own (``= (3,4)``, ``[2,5]``): a vector or an interval, not a decimal.
_PAIR = re.compile(r"(?:^|(?<=[\s=,;:]))[(\[<⟨{]\s*-?\d+,\d+\s*[)\]>⟩}]")


#: A number and its unit alone before a comma (``35.0 m/s, M = 70.0 kg``): no relation's side.
LONE_VALUE = re.compile(r"\s*[-+]?\d[\d.]*\s*(?:[A-Za-z]{1,3}(?:\s*/\s*[A-Za-z]{1,3})?)?\s*")


#: HTML's subscripts and powers, as a Markdown page types them (``v<sub>A2</sub>``, ``s<sup>-1</sup>``).
_HTML_MARK = re.compile(r"<(sub|sup)>\s*([^<>]{1,12}?)\s*</\1>", re.I)


def html_marks(text: str) -> str:
    """``text`` with HTML's ``<sub>`` and ``<sup>`` written as ``_`` and ``^`` (``v_A2``, ``s^(-1)``):
    their angle brackets are no inequality."""
    return _HTML_MARK.sub(lambda m: f"_{m[2]}" if m[1].lower() == "sub" else f"^({m[2]})", text)


def thousands(text: str) -> str:
    """``text`` with each number written in groups of three (``20 000``, ``20,000``) as one
    number: a teacher reads ``(20 000)(0.5)^2`` as twenty thousand, never 20 times 0."""
    text = _THOUSANDS_COMMA.sub(lambda m: m.group(0).replace(",", ""), text)
    return _THOUSANDS.sub(lambda m: re.sub(r"\s", "", m.group(0)), text)


def decimal_commas(text: str) -> str:
    """``text`` with each decimal comma written as a point (``0,25`` as ``0.25``): a teacher in
    Germany, France or Spain reads ``m(0,2 - 3)`` as nought point two; a pair in brackets of its
    own (``v = (3,4)``) stays a pair."""
    pairs = [m.span() for m in _PAIR.finditer(text)]
    return _DECIMAL_COMMA.sub(
        lambda m: m.group(0) if any(a <= m.start() < b for a, b in pairs) else f"{m[1]}.{m[2]}", text
    )


#: A name with the index i for "each body", after (``v_i'``) and before (``v_i``) in one relation.
_EACH_AFTER = re.compile(r"(?<![\w\\])[A-Za-z]_i'")
_EACH_BEFORE = re.compile(r"(?<![\w\\])[A-Za-z]_i(?![\w'])")


def each_body(sides: tuple[str, ...], text: str) -> list[tuple[str, ...]]:
    """A relation for each body written once with the index i (``v_i' = 2v_S - v_i``: the rule for
    body 1 and body 2, or A and B as the text names them); any other relation as it is. ``v_f =
    2v_cm - v_i`` (i for initial: no ``v_i'``) stays one."""
    joined = " = ".join(sides)
    if not (_EACH_AFTER.search(joined) and _EACH_BEFORE.search(joined)):
        return [sides]
    bodies = ("1", "2") if re.search(r"_\{?[12](?![\w.])", text) else ("A", "B")
    each = re.compile(r"(?<![\w\\])([A-Za-z])_i(?!\w)")
    return [tuple(each.sub(rf"\1_{b}", side) for side in sides) for b in bodies]


#: A point between thousands, as Germany writes it (``1.200 kg``), where commas are the decimals.
_THOUSANDS_POINT = re.compile(r"(?<![\d.,])\d{1,3}(?:\.\d{3})+(?![\d.,])")


def european_points(text: str) -> Callable[[str], str]:
    """How to read the points of ``text``'s numbers: where it writes its decimals with a comma
    (``0,25``, ``0{,}25``) and every point has three digits after it, ``1.200 kg`` is twelve
    hundred (the points dropped); elsewhere a point is a decimal point (nothing changed)."""
    decimal = r"(?<![\d.,])0,\d|\d,(?:\d{1,2}|\d{4,})(?![\d,])|\d\{,\}\d"  # 0,250; 0,5; 0{,}25: not 4,500
    commas = re.search(decimal, text) and not re.search(r"\d\.(?:\d{1,2}|\d{4,})(?!\d)", text)
    if not commas or not _THOUSANDS_POINT.search(text):
        return lambda plain: plain
    return lambda plain: _THOUSANDS_POINT.sub(lambda m: m[0].replace(".", ""), plain)


def glued_marks(text: str) -> str:
    """``text`` with a velocity's body and component or time glued to its letter written as one
    name (``2 vAx + 8`` -> ``2 v_Ax + 8``): a name, not words after a number."""
    return _GLUED_MARKS.sub(r"\1_\2\3", text)


def typed_names(text: str) -> str:
    """``text`` with names whose subscript or prime is typed another way written as one name
    (``mA`` as ``m_A``: the body glued to the letter)."""
    text = _GLUED_BODY.sub(r"\1_\2", text)  # mA(vA)1: m_A
    text = glued_marks(text)  # 2 vAx + 8: 2 v_Ax
    text = _BRACED.sub(lambda m: f"{m[1]}{m[2]}" if m[1] == "_" else f"^({m[2]})", text)  # v_{A2}, u^{2}
    text = _SUBSCRIPT_MARKED.sub(lambda m: f"_{m[1]}{m[2]}", text)  # v_{A,2}, v_(A2): one subscript
    return _PRIME_FIRST.sub(r"\1_\3\2", text)  # v'_A: v_A', the prime after the subscript


#: A unit after a number inside a side, before an operator or a closing bracket (``352 J − 288 J``,
#: ``(12 m/s − 4 m/s)``, a mass's ``(20 Mg) v_A2``, a momentum's ``7200 kg·m/s + 6 m_B``, its product sign
#: no operator (``0.58 kg*m/s − 0.3 kg*m/s``, ``kg×m/s``, ``kg-m/s``); not g nor t,
#: which are letters too: ``(2 g)``).
_UNIT_MID = re.compile(
    r"(?<=\d)\s+(?:kJ|J|m\s*/\s*s|m\s*s\^-1|ms\^-1|N\s?[·.*]?\s?s|kg\s*[·.*×⋅-]?\s*m\s*/\s*s|kg(?!\s*[·.*×⋅-]\s*m\s*/)|(Mg|tonnes?))"
    r"(?=\s*(?:[-+−×*](?!\s*$)|\)))"  # a side's last factor too, in brackets: (110 kg)(-0.120 m/s)
)


#: A compound unit after a number inside a side (``2(9.8 m/s^2)(1.6 m)``): a line that writes its units.
_COMPOUND_MID = re.compile(rf"(?<=\d)\s*(?:{UNIT.pattern})(?=\s*(?:[-+−×*](?!\s*$)|\)))")
#: A length alone after a number closing a bracket (``(1.6 m)``), in a line that writes its units.
_LENGTH_MID = re.compile(r"(?<=\d)\s+(?:m|ft)(?=\s*\))")


def units_inside(text: str) -> str:
    """``text`` without the unit after a number that an operator or a bracket follows (a
    thousand kilograms, ``Mg`` or tonnes, written as the factor of the SI unit: ``20*1000``);
    in a line that writes a compound unit inside it (``(9.8 m/s^2)``), a length alone in brackets
    after a number (``(1.6 m)``) is metres too, not a mass m."""
    text = _UNIT_MID.sub(lambda m: "*1000" if m[1] else "", text)
    if _COMPOUND_MID.search(text):
        text = _LENGTH_MID.sub("", _COMPOUND_MID.sub("", text))
    return text


#: A direction in words after a number (``= 1.04 m/s to the left``, ``= 2 (backwards)``).
#: "Back" and "on" (to the left, to the right) as students abroad write them after a speed.
_BACK_ABROAD = (
    r"zurück|nach\s+links|vers\s+la\s+gauche|à\s+gauche|en\s+sens\s+inverse|hacia\s+(?:la\s+)?izquierda|hacia\s+atrás"
)
#: Away from a fixed body (derive's +n points into it): "1.6 m/s (back) away from the wall", "off the cushion".
_OFF_THE_WALL = r"(?:back\s+)?(?:away\s+from|off)\s+the\s+(?:wall|cushion|barrier|ground|floor|plane|surface)"
#: Toward a fixed body, derive's +n: "1.2 m/s (towards the wall)", "towards the cushion".
_INTO_THE_WALL = r"towards?\s+the\s+(?:wall|cushion|barrier|ground|floor|plane|surface)"
_ON_ABROAD = r"nach\s+rechts|vers\s+la\s+droite|à\s+droite|hacia\s+(?:la\s+)?derecha"
_DIRECTION = re.compile(
    r"^[-+]?\s*\d[\d.]*\s*(?:[A-Za-z/^\-\s·*1]*?)?\s*\(?\s*(?:(to\s+the\s+left|leftwards?|backwards?"
    r"|in\s+the\s+opposite\s+direction|the\s+other\s+way|left(?=\s*\)?\s*[.,;]?\s*$)|"
    + _OFF_THE_WALL
    + "|"
    + _BACK_ABROAD
    + r")|(to\s+the\s+right|rightwards?"
    r"|forwards?|in\s+the\s+same\s+direction|right(?=\s*\)?\s*[.,;]?\s*$)|"
    + _INTO_THE_WALL
    + "|"
    + _ON_ABROAD
    + r"))(?!\w)",
    re.I,
)


_DIRECTION_END = re.compile(
    r"\s*\(?\s*(?:(?:to\s+the\s+)?(?:left|right)|(?:left|right)wards?|backwards?|forwards?"
    r"|in\s+the\s+(?:opposite|same)\s+direction|the\s+other\s+way|"
    + _BACK_ABROAD
    + "|"
    + _ON_ABROAD
    + r")\s*\)?\s*[.,;]?\s*$",
    re.I,
)


#: A direction in words at the end of a side in letters (``= \\tfrac89 mu, backwards.``,
#: ``= m(8u/9) to the left``): the size in letters, its sign in the words.
_DIRECTION_AFTER_LETTERS = re.compile(
    r"^[-+−]?\s*(?=[A-Za-z\\(])[\w\\{}()/^*+\-−·.'\s]{1,60}?\s*,?\s*\(?\s*(?:(to\s+the\s+left|leftwards?|backwards?"
    r"|in\s+the\s+opposite\s+direction|the\s+other\s+way)|(to\s+the\s+right|rightwards?|forwards?"
    r"|in\s+the\s+same\s+direction))\s*\)?\s*[.,;]?\s*$",
    re.I,
)


def direction_of(tail: str) -> int:
    """-1 where the number of ``tail`` (what follows a relation's last ``=``) is followed by a
    direction against the usual positive one ("to the left", "backwards", "in the opposite
    direction"), +1 by the usual one ("to the right", "forwards"), else 0; the same after a
    side in letters that the words end."""
    m = _DIRECTION.match(tail.strip()) or _DIRECTION_AFTER_LETTERS.match(tail.strip())
    if not m:
        return 0
    return -1 if m.group(1) else 1


def without_direction(text: str) -> str:
    """``text`` without the direction in words at its end (:func:`direction_of` reads it)."""
    return _DIRECTION_END.sub("", text)
