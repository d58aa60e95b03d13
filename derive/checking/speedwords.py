"""The one moving body's speed after the impact named in words beside the word "after" (a ball
on a cushion, a wall, the ground): "After (speed $V$): parallel $V\\cos\\beta$ …", "after the
impact: speed V", "it rebounds with speed w", "let V be the speed after the impact", "let the
speed after the impact with DC be V"; and whether a line that could not be read is
prose (words a teacher does not mark) or mathematics (``V cos beta = e_1 U cos alpha``, whose
words are a function's and a Greek letter's names).

>>> sorted(_after_names("Before: parallel U cos a. After (speed $V$): parallel $V\\\\cos\\\\beta$"))
['V']
>>> looks_like_prose("V cos beta = e_1 U cos alpha"), looks_like_prose("the ball moves off = fast")
(False, True)
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context
from derive.mathtext.reader import MATH_WORDS

_NAME = r"([A-Za-z](?:_?\{?[^\W¹²³]{1,2}\}?)?|\\[a-z]+)"
#: The end of the name: no more of a word, but its square may follow (``speed after: V² = …``).
_END = r"(?:(?=[²³^])|(?![\w'(]))"
#: "After (speed V)", "afterwards speed V", "after the impact: speed V", "speed after V", "speed V
#: afterwards", "rebounds with speed V".
_AFTER_SPEED = (
    re.compile(rf"\bafter(?:wards?)?\b[^.;=]{{0,40}}?\bspeed\s+(?:is\s+|of\s+|=\s*)?{_NAME}{_END}", re.I),
    re.compile(
        rf"\bspeed\s+(?:just\s+)?after(?:wards?\b)?(?:\s+the\s+(?:impact|collision|bounce)(?:\s+(?:with|off|on|against)\s+(?:the\s+)?\w+(?!\w))?)?"
        rf"\s*(?:is\s+|be\s+|=\s*|:\s*)?{_NAME}{_END}",
        re.I,
    ),
    re.compile(  # "let V be the speed after", "V is its speed after the impact", "V = the speed after"
        rf"(?<![\w\\]){_NAME}\s+(?:is|be|=|denotes?|represents?|for)\s+(?:the\s+|its\s+)?(?:new\s+|final\s+)?"
        r"speed\s+(?:just\s+|immediately\s+)?after",
        re.I,
    ),
    re.compile(
        rf"\bspeed\s+(?:is\s+|of\s+)?{_NAME}\s+(?:just\s+|immediately\s+)?after(?:wards?)?\b", re.I
    ),  # "speed V afterwards"
    re.compile(rf"\b(?:rebounds?|bounces?|moves?\s+off|leaves?)\b[^.;=]{{0,30}}?\bwith\s+speed\s+{_NAME}{_END}", re.I),
)
#: Words that are never the name of a speed.
_NOT_NAMES = frozenset({"is", "of", "at", "in", "on", "to", "and", "the", "be", "so", "it", "an", "as"})
#: Prose: two words of three letters or more with only words between them.
_PROSE = re.compile(r"[A-Za-z]{3,}\s+(?:[A-Za-z]+\s+)*[A-Za-z]{3,}")
#: The signs a student writes for a word (``∥ cpt``, ``⊥ mom.``), standing alone as a word does, not a
#: name's mark (``v_⊥``, ``v∥``): read as the words they stand for.
_SAID = {"∥": "parallel", "⊥": "perpendicular"}
_SYMBOL_WORD = re.compile(r"(?<![\w_{^])[∥⊥](?![\w_}])")
#: A side that only says a sign: "+ve", "+", "positive (direction)", "-ve".
_WAY_SIDE = re.compile(r"\s*\(?\s*(?:[+\-−]\s*(?:ve)?|positive|negative)(?:\s+(?:direction|way|sense))?\s*\)?\s*", re.I)


def _after_names(line: str) -> set[str]:
    plain = re.sub(r"\$|\\[()]|[{}]", " ", line)
    out = set()
    for pattern in _AFTER_SPEED:
        for m in pattern.finditer(plain):
            name = m[1].lstrip("\\")
            if name.lower() not in _NOT_NAMES and name not in MATH_WORDS:
                out.add(name)
    return out


def one_speed_after(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """The name ``line`` gives in words to the one moving body's speed after the impact (a body
    on a fixed surface) -> derive's expression for that speed; {} where there are two bodies."""
    names = ctx.equation_names()
    if not ctx.problem.fixed_B or "v_A2" not in names:
        return {}
    said = _after_names(line) | _along_the_path_after(line, getattr(ctx.problem, "statement", "") or "")
    return {n: names["v_A2"][0] for n in said if n not in names}


#: The path the statement says the body takes after the impact, by its two points ("It rebounds
#: from DC and moves along PQ"): a speed "along PQ" is the speed after.
_PATH_AFTER = re.compile(r"\b(?:rebounds?|bounces?|leaves?|returns?)\b[^.]{0,60}?\balong\s+([A-Z]{2})\b")


def _along_the_path_after(line: str, statement: str) -> set[str]:
    """The name ``line`` gives the speed along the statement's path after the impact ("Let the
    speed along PQ be V", "V = speed along PQ")."""
    m = _PATH_AFTER.search(statement)
    if m is None:
        return set()
    plain, path = re.sub(r"\$|\\[()]|[{}]", " ", line), m[1]
    found = re.findall(rf"\bspeed\s+along\s+{path}\s*(?:is\s+|be\s+|=\s*|:\s*)?{_NAME}{_END}", plain)
    found += re.findall(rf"(?<![\w\\]){_NAME}\s+(?:is|be|=|for)\s+(?:the\s+)?speed\s+along\s+{path}\b", plain)
    return {n for n in found if n.lower() not in _NOT_NAMES and n not in MATH_WORDS}


def looks_like_prose(text: str) -> bool:
    """Whether ``text`` (a line's sides that could not be read) is prose with an "=" in it: words,
    not counting the names of functions, Greek letters and angle units, which are mathematics."""
    if any(_WAY_SIDE.fullmatch(side) for side in text.split("=")):
        return True  # "right = +ve", "+ve = away from wall": which way is positive, said
    text = text.replace("=", " ")
    words = re.sub(r"[A-Za-z]+", lambda m: " " if m[0] in MATH_WORDS else m[0], text)
    words = _SYMBOL_WORD.sub(lambda m: f" {_SAID[m[0]]} ", words)  # "∥ cpt = ⊥ cpt": parallel, perpendicular
    return _PROSE.search(words) is not None
