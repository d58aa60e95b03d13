"""A sign convention a student states in words ("taking away from the wall as positive").

Holds the phrases for derive's n and its reverse, and a value signed by its direction in words;
imports nothing of derive.
"""

from __future__ import annotations

import re
from dataclasses import replace
from typing import TypeVar

#: Fixed bodies students name in their sign conventions.
_FIXED = r"(?:the\s+)?(?:wall|cushion|floor|ground|barrier|plate|surface|board|buffer|bank|side|goal)"
#: A body going its way, as said of the direction taken as positive ("the direction A was moving").
_GOES = (
    r"(?:(?:was\s+|is\s+|had\s+been\s+)?(?:mov|travell?|go|head|start|roll|slid|slide)(?:es|s|ed|ing)?\b"
    r"|(?:was\s+|is\s+)?(?:going|went|moved|travelled|traveled|initially)\b)"
)
#: An arrow between two bodies' letters: ``A→B``, ``A -> B``, ``A \\to B`` (from the first toward the second).
_ARROW = r"(?:→|⟶|-{1,2}>|\\to\b|\\(?:long)?rightarrow\b)"
_REVERSED = re.compile(
    rf"revers|opposite|negative|away\s+from\s+{_FIXED}|(?<!\w)from\s+b\s+to(?:wards?)?\s+a\b|-n\b"
    rf"|(?<!\w)b\s*{_ARROW}\s*a\b"
    rf"|(?:out\s+)?from\s+{_FIXED}|out\s+of\s+{_FIXED}|rebound|bounces?\s+back|(?<!\w)to(?:wards?)?\s+(?-i:A)\b(?!['’])"
    r"|\bb['’]?s\s+(?:initial\s+|original\s+)?(?:direction|motion)|(?:direction|motion)\s+of\s+b\b"
    rf"|(?:direction|way)\s+(?:that\s+|in\s+which\s+)?b\s+{_GOES}",
    re.I,
)
_FORWARD = re.compile(
    rf"to(?:wards?)?\s+{_FIXED}|from\s+a\s+to(?:wards?)?\s+b\b|\ba['’]?s\s+(?:initial\s+|original\s+)?(?:direction|motion)"
    rf"|(?<!\w)a\s*{_ARROW}\s*b\b"
    rf"|(?:direction|way)\s+(?:that\s+|in\s+which\s+)?a\s+{_GOES}"
    r"|direction\s+of\s+a\b|\+n\b|^\s*n\b|derive|(?<!\w)to(?:wards?)?\s+(?-i:B)\b(?!['’])|direction\s+of\s+approach"
    r"|(?<!['’]s\s)(?:initial|original)\s+direction(?:\s+of\s+(?:motion\s+of\s+)?(?:a|the\s+(?:ball|sphere|particle|puck)))?\b"
    r"|direction\s+of\s+motion\s+of\s+a\b",
    re.I,
)
#: Words in a clause that do not say which way is positive: a point of view ("(from the ground)",
#: "as seen from the bank") and a time ("before the rebound": the way before it, the first way).
_NOT_A_WAY = re.compile(
    rf"\(\s*(?:as\s+)?(?:seen\s+|viewed\s+|observed\s+|looking\s+)?from\s+[^)]*\)"
    rf"|(?:as\s+)?(?:seen|viewed|observed|looking)\s+from\s+{_FIXED}",
    re.I,
)
_BEFORE = re.compile(
    r"\b(?:before|prior\s+to|until|up\s+to)\s+(?:the\s+|its\s+|it\s+)?"
    r"(?:rebound|rebounds|bounces?|bouncing|impact|collision|collides|hits|strikes|hitting|striking)\b[\w\s]*?"
    r"(?=\s+(?:is|as|be|to\s+be)\b|$)",
    re.I,
)


R = TypeVar("R")  # a line read (inference.Read): its sides, exprs and direction in words


def sign_of(words: str) -> int:
    """The sign convention a phrase states: -1 reversed (away from the wall, B's direction), +1
    derive's n (from A toward B, toward the wall, A's direction), 0 where it does not say
    (up, down, left, right: inferred from the values)."""
    said = [
        c for c in re.split(r"[,;.]|\b(?:so|then|hence|giving)\b", words) if re.search(r"positive|\+\s?ve\b", c, re.I)
    ]
    words = said[0] if said else words  # "towards the wall as positive, so after the rebound …": its clause
    words = _BEFORE.sub(" initially ", _NOT_A_WAY.sub(" ", words))
    if re.search(r"\b(?:direction|motion|way)\s+initially\b", words, re.I) and not re.search(
        r"\b(?-i:B)['’]?s\s+(?:direction|motion|way)|of\s+(?-i:B)\b", words
    ):
        return 1  # "the ball's direction before the rebound": its first way, derive's n
    if _REVERSED.search(words):
        return -1
    return 1 if _FORWARD.search(words) else 0


def signed_by_words(r: R, sign: int) -> R:
    """``v_A = 1.04 m/s to the left``: the number signed by its direction in words, which is
    derive's (right along +n, from A toward B), in the student's frame (``sign``); a number
    already signed stays as written."""
    m = re.match(r"^\s*([-+]?)\s*(\d[\d.]*)", r.sides[-1]) if r.direction and r.exprs else None
    if m is not None and r.exprs[-1].free_symbols:  # "v ←", "9v/2 to the left": a size in letters, or no size
        sized = _letters_size(r.exprs[-1], r.sides[-1])
        m = re.match(r"^\s*()(.*?)\s*$", f"({r.sides[-1].strip()})") if sized else None
    elif m is None and r.direction and r.exprs and _letters_size(r.exprs[-1], r.sides[-1]):
        m = re.match(r"^\s*()(.*?)\s*$", f"({r.sides[-1].strip()})")
    if m is None or m.group(1) == "-" or _size_only(r.exprs[0]) or _impulse(r.exprs[0]):
        return r
    if _OFF_A_SURFACE_AS_SPEED.search(getattr(r, "written", "")):
        return r  # "Rebound speed: v = eu = 1.6 m/s (away from the wall)": a size, its way said
    if len(r.exprs) == 2 and type(r.exprs[0]).__name__ == "Abs":  # "A: 0.6 m/s to the left": a size with
        way = 1 if r.direction * sign > 0 else -1  # its way said is the velocity, signed by the way
        return replace(
            r, sides=(r.sides[0], f"{'-' if way < 0 else ''}{m.group(2)}"), exprs=(r.exprs[0].args[0], way * r.exprs[1])
        )
    if r.direction * sign > 0:
        return r
    if len(r.exprs) >= 3 and r.exprs[0].is_Symbol and not any(x.is_number and x < 0 for x in r.exprs[1:-1]):
        # "v = eu = 0.4 x 4 = 1.6 m/s to the left": v's size is worked out, its way said after it
        return replace(r, exprs=(-r.exprs[0], *r.exprs[1:]))
    return replace(r, sides=(*r.sides[:-1], f"-{m.group(2)}"), exprs=(*r.exprs[:-1], -r.exprs[-1]))


#: A speed named so before its number whose way is said as off a fixed surface: the size stays a size.
_OFF_A_SURFACE_AS_SPEED = re.compile(
    r"\bspeed\b[^=]*=.*\b(?:away\s+from|off)\s+the\s+(?:wall|cushion|barrier|ground|floor)", re.I
)


def _letters_size(x: object, side: str) -> bool:
    """A size written in the problem's letters (``v``, ``3u/2``, ``e u``): positive by the letters'
    own sign (a given letter is a size), typed without a sign of its own."""
    symbols = getattr(x, "free_symbols", ())
    return bool(symbols) and getattr(x, "is_positive", False) is True and not side.lstrip().startswith(("-", "+"))


def _impulse(x: object) -> bool:
    """An impulse read by its value (``impulse = 11.2 N s away from the wall``): on which body it
    acts was read from the number, so the way in words is not a sign to put on it again."""
    return any(s.name.startswith("J") for s in getattr(x, "free_symbols", ()))


def _size_only(x: object) -> bool:
    """A mass or a weight (derive's ``m_A``, ``W_B``, ``m``): a size, never signed by a way in words
    (``W_B = 3000 lb moving left at 6 ft/s``: the way is the car's velocity's)."""
    return bool(getattr(x, "is_Symbol", False)) and re.fullmatch(r"(?:m|W)(?:_[A-Za-z0-9]+)?|mass", x.name) is not None


#: A way declared positive by a bare plus: "(towards wall is +)", "towards the wall = +", "(+ away from the wall)",
#: "Take $+$ = out of the wall" (the plus in inline maths, after a verb of choosing).
_PLUS_AFTER = re.compile(r"([A-Za-z][A-Za-z'’\s]*?)\s*(?:is|as|=|:)\s*\+(?:\s*ve)?\s*(?=\)|$|[,;.])", re.I)
_PLUS_BEFORE = re.compile(
    r"(?:^|[(\[,;]|\b(?:take|taking|let|choose|choosing|with)\b)\s*\$?\+(?:\s*ve)?\$?\s*(?:is|=|:|->|→|as)?\s*"
    r"((?:to|towards|away|from|in|out)\b[A-Za-z'’\s]*)",
    re.I,
)


def plus_said(line: str) -> int:
    """The sign convention a clause of ``line`` states with a bare ``+`` (no "positive", no "+ve"
    needed): ``(towards wall is +)`` +1, ``(+ = away from the wall)`` -1; 0 where none says a way."""
    for pattern in (_PLUS_AFTER, _PLUS_BEFORE):
        for m in pattern.finditer(line):
            sign = sign_of(m.group(1))
            if sign:
                return sign
    return 0


#: The first axis laid along the line of centres (or impact) with its sense from A toward B:
#: "n along the line of impact (from A to B)", "x-axis along the line of centres (from A towards B)",
#: "Line of impact = x (A toward B)", "**i** along the line of centres from A to B".
_AXIS = re.compile(
    r"(?:\b(?:n|x|i)\b|\\(?:imath|hat\{?\\?[inx])|mathbf\{i\}|\*\*[ix]\*\*|line\s+of\s+(?:centres|centers|impact))",
)
_A_TO_B = re.compile(r"(?:\bfrom\s+(?-i:A)\s+|\(\s*(?-i:A)\s+)(?:to|towards?)\s+(?-i:B)\b", re.I)


def axis_sense(line: str) -> int:
    """+1 where ``line`` lays the line of centres' axis from A toward B without saying "positive":
    the axis's sense is the student's positive along it, declared, as ``positive: from A toward B``
    is (a reading the values would infer the other way round is not the student's); 0 otherwise."""
    return 1 if _A_TO_B.search(line) and _AXIS.search(line) else 0
