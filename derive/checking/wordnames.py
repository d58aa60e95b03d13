"""Names a student declares in words, not with ``=``: "Let a and b be the velocities of A and B
along the line of centres after" (an oblique impact's components), "let x, y be the speeds of P
and Q after the collision", "x = velocity of A after" (a direct impact's velocities).

:func:`in_words` is what :func:`.naming.declarations` asks of each line.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context


def in_words(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """The names ``line`` declares in words, each with derive's name for what it stands for:
    a direct impact's velocities by body and time, an oblique impact's components along the line
    of centres (where the line says so)."""
    out = _direct(line, ctx)
    for name, x in _along(line, ctx).items():
        out.setdefault(name, x)
    return out


#: "Let $a$ and $b$ be the velocities of A and B along the line of centres after": names in words.
_IN_WORDS = re.compile(
    r"\blet\s+(\w+)(?:\s+and\s+(\w+))?\s+be\s+(?:the\s+)?(?:final\s+)?velocit(?:y|ies)\s+of\s+([AB])"
    r"(?:\s+and\s+([AB]))?(\s+along\s+the\s+line\s+of\s+(?:centres|impact))?\s*,?\s*"
    r"(?:just\s+|immediately\s+)?(after|afterwards|before)\b",
    re.I,
)


def _along(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """``Let a and b be the velocities of A and B along the line of centres after`` -> {a: v_A2n,
    b: v_B2n}: a name declared in words, where they say whose, when, and (an oblique impact)
    along which line."""
    m = _IN_WORDS.search(re.sub(r"\$|\\[()]", "", line))
    if not m or (ctx.problem.oblique and not m.group(5)) or bool(m.group(2)) != bool(m.group(4)):
        return {}
    when = "1" if m.group(6).lower() == "before" else "2"
    out = {}
    for name, body in ((m.group(1), m.group(3)), (m.group(2), m.group(4))):
        x = getattr(ctx.model.nm, f"{body.upper()}{when}n", None) if name else None
        if x is not None:
            out[name] = x
    return out


#: Names declared in words: "let x, y be the speeds of P and Q after the collision", "x and y are
#: the velocities of A and B after", "x = velocity of A after".
_NAME_WORD = r"([A-Za-z](?:_\{?\w{1,3}\}?)?)"
_WHAT = (
    r"(?:be|are|is|as|=|denote|represent|for)\s+(?:the\s+)?(?:final\s+)?(?:speeds?|velocit(?:y|ies)|vels?\.?)\s+of\s+"
)
_PAIR_WORDS = re.compile(
    rf"\b{_NAME_WORD}\s*(?:,|and)\s*{_NAME_WORD}\s+{_WHAT}(.{{1,30}}?)\s+and\s+(.{{1,30}}?)\s+(after|before)\b", re.I
)
_ONE_WORDS = re.compile(rf"\b{_NAME_WORD}\s*{_WHAT}(.{{1,30}}?)\s+(after|before)\b", re.I)
_BODY_WORDS = re.compile(r"\b(?:the|sphere|ball|particle|disc|body|puck|car|trolley)s?\b", re.I)


def _direct(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """The names a line declares in words (``Let $x$, $y$ be the speeds of P and Q after the
    collision``), for a direct impact: each the velocity of the body it names (by its letter,
    P and Q for A and B, or its mass: "the 3m particle"), after or before."""
    if ctx.problem.oblique:
        return {}
    plain = re.sub(r"\\[A-Za-z]+\{[^{}]*\}|\$|\\[()]|[{}]", " ", line)
    names = ctx.equation_names()
    out: dict[str, sympy.Expr] = {}
    found = [((m[1], m[3]), (m[2], m[4]), m[5]) for m in _PAIR_WORDS.finditer(plain)]
    found += [((m[1], m[2]), None, m[3]) for m in _ONE_WORDS.finditer(plain)]
    for first, second, when in found:
        for name, body in (first, second) if second else (first,):
            b = _body(body, ctx)
            key = f"v_{b}{'2' if when.lower() == 'after' else '1'}"
            if b and key in names:
                out.setdefault(name.replace("{", "").replace("}", ""), names[key][0])
    return out


def _body(words: str, ctx: Context) -> str:
    """ "A", "B" or "" for the words that name a body: its letter, P or Q, first or second, its mass."""
    w = re.sub(r"(?<=\d)(?:kg|g|lb)$", "", re.sub(r"\s+", "", _BODY_WORDS.sub(" ", words)))  # the 4 kg ball
    a, b = ctx.problem.labels
    if w in (a, "A", "P", "first"):
        return "A"
    if w in (b, "B", "Q", "second"):
        return "B"
    masses = {}
    for g in ctx.problem.givens:
        if g.name in ("m_A", "m_B"):
            x = g.value if g.value is not None else getattr(g, "definition", None)
            masses[g.name[-1]] = re.sub(r"[\s*]", "", str(x))
    hits = [k for k, v in masses.items() if v == w.replace("*", "")]
    return hits[0] if len(hits) == 1 else ""
