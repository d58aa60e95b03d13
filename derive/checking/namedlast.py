"""Names declared after what they stand for: "Let B's velocity after be v", "let the velocities
of A and B after the impact be x and y", "Let A's speed before be u, and B's speed after be w".

A teacher reads these as "let v be B's velocity after": the words are put in that order and read
as :func:`.wordnames.in_words` reads any declaration in words (by body, time and axis), so every
form it knows is known the other way round too.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context
from derive.checking.wordnames import in_words

_NAME = r"(?:\*\*|__)?\$?[A-Za-z](?:_\{?\w{1,3}\}?|\d)?['′]?\$?(?:\*\*|__)?"  # **p**: bold
#: What is named: a body's speed, velocity or component, in words (no "=" or sentence end in it).
_WHAT = (
    r"(?:the\s+)?(?:[A-Za-z]\w{0,6}['’]s\s+)?(?:final\s+|initial\s+|new\s+)?"
    r"(?:speeds?|velocit(?:y|ies)|components?)\b[^=;.$]*?"
)
_LAST = re.compile(
    rf"(?:\blet\s+|(?:,\s*)?\band\s+(?=[A-Za-z]\w{{0,6}}['’]s\s|the\s))({_WHAT})\s+be\s+({_NAME}(?:\s*(?:,|and)\s*{_NAME})*)"
    r"(?![\w'(^/*+-])",
    re.I,
)


#: "A's speed before = U.", "A's speed before is v1 (unknown) and ...": a body's quantity in words
#: set equal to a name alone, or said to be it, as a clause (a remark in brackets after the name).
_EQUALS = re.compile(
    rf"(?:^|[.;:,]\s)\s*(?:and\s+)?((?:[A-Za-z]\w{{0,6}}['’]s\s+|the\s+)(?:final\s+|initial\s+|new\s+)?"
    rf"(?:speed|velocity|component)\b[^=;.$]*?)\s*(?:=|\bis\b)\s*({_NAME})\s*(?:\([^()]*\)\s*)?"
    r"(?=[.;,]|\band\b|$)",
    re.I,
)


#: "Let P move backwards with speed v and Q move forwards with speed w after the collision", "B moves
#: off at speed x": a direct impact's name declared by how a body moves after, its way in words.
_MOVES = re.compile(
    rf"(?<![\w\\])([A-Z])\s+(?:then\s+|now\s+)?(?:moves?|travels?|goes|continues|rebounds?)"
    r"((?:\s+(?:off|on|away|back|backwards?|forwards?|in\s+the\s+opposite\s+direction|the\s+other\s+way)){0,2})"
    rf"\s+(?:at|with)\s+(?:a\s+|the\s+)?(speed|velocity)\s+(?:of\s+)?({_NAME})(?![\w'(^/*+-])"
)
_BACK = re.compile(r"\b(?:back|backwards|opposite|other\s+way)\b", re.I)


def named_last(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """The names ``line`` declares after the words for what they stand for, each with derive's
    name for it (read the other way round: "let v be B's velocity after")."""
    out: dict[str, sympy.Expr] = {}
    said = [f"Let {re.sub(r'[${}*]|__', '', m[2]).strip()} be {m[1].strip()}" for m in _LAST.finditer(line)]
    said += [f"Let {re.sub(r'[${}*]|__', '', m[2]).strip()} be {m[1].strip()}" for m in _EQUALS.finditer(line)]
    if not ctx.problem.oblique:  # "P moves backwards with speed v": "let v be the speed of P after (P goes back)"
        plain = re.sub(r"[${}]|\\[()]", "", line)
        said += [
            f"Let {m[4]} be the {m[3]} of {m[1]} after" + (f" ({m[1]} goes back)" if _BACK.search(m[2]) else "")
            for m in _MOVES.finditer(plain)
        ]
    for words in said:
        for name, x in (in_words(words, ctx) or speed_along(words, ctx)).items():
            out.setdefault(name, x)
    return out


_AXIS = re.compile(r"\b(?:line\s+of\s+cent(?:re|er)s|perpendicular|across|tangent|normal|along)\b", re.I)


def speed_along(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """An oblique impact's component named as a speed: "Let U be the speed of A before (along
    XY)", "B's speed along the line of centres after be w"; and a body's speed where it moves
    along the line of centres (its other component given as 0): "A's speed before be u"; and
    elsewhere a body's speed before with no line said, the given speed it is resolved from ("let
    A's speed before the impact be v": v cos 30 along n, whatever the habits make of v)."""
    if not ctx.problem.oblique or not re.search(r"\bspeeds?\b", line, re.I):
        return {}
    out: dict[str, sympy.Expr] = {}
    zero = {g.name for g in ctx.problem.givens if g.value == 0 and g.name.endswith("t")}
    for clause in re.split(r",?\s*\band\s+(?=let\b)|;", line, flags=re.I):  # one name's words at a time
        text = re.sub(r"\bspeed(s?)\b", lambda m: "velocities" if m.group(1) else "velocity", clause, flags=re.I)
        if _AXIS.search(text):
            found = in_words(text, ctx)
        else:  # where the body moves along the line of centres only; else its speed, the given's size
            found = in_words(f"{text.rstrip(' .')} along the line of centres", ctx)
            found = {k: x if str(x)[:-1] + "t" in zero else given_speed(ctx, x) for k, x in found.items()}
            found = {k: x for k, x in found.items() if x is not None}
        for k, x in found.items():
            out.setdefault(k, x)
    return out


#: The statement's own letters for the line of centres: "along the line of centres XY", "XY, the
#: line of centres", "the line of centres, AB,".
_LOC_LETTERS = (
    re.compile(r"\bline\s+of\s+cent(?:re|er)s\s*,?\s*([A-Z]{2})\b"),
    re.compile(r"\b([A-Z]{2})\s*,?\s*(?:is\s+|being\s+)?the\s+line\s+of\s+cent(?:re|er)s\b"),
)


def in_line_words(line: str, ctx: Context) -> str:
    """``line`` with the statement's letters for the line of centres (``along XY``) in words
    ("along the line of centres"), and a pronoun for the line of centres the line has named before
    it ("Line of centres: positive from A to B. a, b = components along it after") said in full,
    so that a declaration by them is read as by the words."""
    line = _pronoun_said(line)
    statement = getattr(ctx.problem, "statement", "") or ""
    for pattern in _LOC_LETTERS:
        m = pattern.search(statement)
        if m and m.group(1) not in ctx.problem.labels:
            return re.sub(rf"(?<![A-Za-z\\]){m.group(1)}(?![A-Za-z])", "the line of centres", line)
    return line


#: The line of centres in words, and "along it" / "along this line" after it.
_LOC_SAID = re.compile(r"\bline\s+of\s+(?:centres|centers|impact)\b|\bl\.\s?o\.\s?c\b\.?", re.I)
_ALONG_IT = re.compile(r"\b(along|parallel\s+to)\s+(?:it|this(?:\s+line)?|that\s+line)\b(?![\w'’])", re.I)


def _pronoun_said(line: str) -> str:
    """``line`` with "along it" after the line of centres is named in it written "along the line
    of centres" (the pronoun's one referent on the line); the line as it is where none is named."""
    first = _LOC_SAID.search(line)
    if first is None:
        return line
    head, tail = line[: first.end()], line[first.end() :]
    return head + _ALONG_IT.sub(lambda m: f"{m[1]} the line of centres", tail)


def given_speed(ctx: Context, component: sympy.Expr) -> sympy.Expr | None:
    """The given speed of the body whose component before along n is ``component`` (``v_A1n`` ->
    ``v_A1``, where the problem gives A's speed before), else None."""
    name = str(component)
    if not name.endswith("1n"):
        return None
    speed = ctx.equation_names().get(name[:-1])
    return None if speed is None else speed[0]
