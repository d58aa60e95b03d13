"""A factor that reaches only some of the terms it multiplies, named as teachers name it: algebra.

``4u = x + 3(x + 4eu) = 4x + 4eu`` (the 3 taken to x, not to 4eu), ``10u = 2(y − 5eu) + 3y``
then ``10u = 2y − 5eu + 3y``, ``6(1200 + m_B)`` worked as ``7200 + m_B``: a bracket multiplied
out on some of its terms only. Most teachers of the corpus call it algebra (a slip in the
rule of multiplying a bracket out), as they call a line divided through but for one term; a
bracket multiplied out on every term with a number worked wrongly (``3(x + 4eu) = 3x + 15eu``)
stays arithmetic. The unknowns cancel from such a side (x on both sides), or the line works on
the relation before it, so the checker's rules for numbers would call it arithmetic; here the
side is read again as typed, the bracket's factor put on some of its terms only.
"""

from __future__ import annotations

import re
from itertools import combinations, pairwise

import sympy

from derive.checking import termsigns
from derive.checking.naming import rewrite
from derive.checking.worlds import Pair
from derive.mathtext.notation import student

#: The most brackets of one side, and terms of one bracket, tried (each subset of the terms once).
MAX_BRACKETS = 4
MAX_TERMS = 4
#: A factor written before a bracket: a number, with letters after it or not (``3*``, ``2*m*``).
FACTOR = re.compile(r"(?<![\w.)])(\d+(?:\.\d+)?(?:\*[A-Za-z]\w*)*)\*?$")
#: A minus alone before a bracket (``u - (u + e*u)/2``): the bracket times -1, not a function's.
MINUS = re.compile(r"-\s*$")


def _closing(text: str, start: int) -> int | None:
    depth = 0
    for i in range(start, len(text)):
        depth += {"(": 1, ")": -1}.get(text[i], 0)
        if depth == 0:
            return i
    return None


def _terms(inside: str) -> list[str]:
    """The top-level terms of a bracket's inside as typed, each with its sign."""
    cuts = [0, *termsigns.signs(inside), len(inside)]
    return [inside[a:b].strip() for a, b in pairwise(cuts) if inside[a:b].strip()]


def _times(factor: str, term: str) -> str:
    sign, body = (term[0], term[1:].strip()) if term[:1] in "+-" else ("+", term)
    if factor.startswith("-"):  # the minus before the bracket reaches the term: its sign turned
        sign, factor = "-" if sign == "+" else "+", factor[1:]
    return f"{sign}{factor}*({body})" if factor != "1" else f"{sign}({body})"


def variants(text: str) -> list[str]:
    """``text`` with the factor of one of its brackets put on a part of the bracket's terms only
    (``3*(x+4*e*u)`` → ``(3*(x)+4*e*u)``, ``(x+3*(4*e*u))``)."""
    out: list[str] = []
    for start in [i for i, ch in enumerate(text) if ch == "("][:MAX_BRACKETS]:
        factor, minus, end = FACTOR.search(text[:start]), MINUS.search(text[:start]), _closing(text, start)
        if (factor is None and minus is None) or end is None:
            continue
        terms = _terms(text[start + 1 : end])
        if not 2 <= len(terms) <= MAX_TERMS:
            continue
        head, tail = text[: (factor or minus).start()] + ("" if factor else "+"), text[end + 1 :]
        ways = [(factor.group(1) if factor else "-1", "")]  # a minus alone before the bracket: -1
        if factor and (signed := MINUS.search(text[: factor.start()])):  # ``- 3(x - 4)``: the minus
            ways.append((f"-{factor.group(1)}", factor.group(1)))  # reaching some terms, the 3 all
            signed_head = text[: signed.start()] + "+"
        for k in range(1, len(terms)):
            for chosen in combinations(range(len(terms)), k):
                for by, rest in ways:
                    inside = " ".join(
                        _times(by, t) if i in chosen else _times(rest, t) if rest else _plain(t, i)
                        for i, t in enumerate(terms)
                    )
                    out.append(f"{signed_head if rest else head}({inside}){tail}")
    return out


def _plain(term: str, i: int) -> str:
    return term if term[:1] in "+-" or i == 0 else "+" + term


def _reads(ctx, text: str, known: set[str]) -> sympy.Expr | None:
    return termsigns._read(ctx, student(rewrite(text, known)).strip()) if text.strip() else None


def partly_multiplied(ctx, bad: Pair) -> bool:
    """Whether one side of ``bad`` as typed, a bracket's factor put on some of its terms only, is
    the other side (``x + 3(x + 4eu) = 4x + 4eu``)."""
    sides = bad.text.split(" = ")
    if bad.raw is None or len(sides) != 2:
        return False
    known = set(ctx.equation_names())
    read = [_reads(ctx, s, known) for s in sides]
    if any(x is None for x in read) or termsigns._same(read[0], read[1]):
        return False  # not read again as a false relation: nothing said
    for i in (0, 1):
        for text in variants(student(rewrite(sides[i], known)).strip()):
            x = termsigns._read(ctx, text)
            if x is not None and termsigns._same(x, read[1 - i]):
                return True
    return False


def from_previous(trace, bad: Pair) -> bool:
    """Whether ``bad`` is the relation just before it (which held) with a bracket's factor put on
    some of its terms only, up to a factor of the whole (``10u = 2(y − 5eu) + 3y`` then ``10u =
    2y − 5eu + 3y``)."""
    if trace.previous is None or bad.difference == 0:
        return False
    ctx, known = trace.ctx, set(trace.ctx.equation_names())
    sides, now = trace.previous[0].split(" = "), [_reads(ctx, s, known) for s in bad.text.split(" = ")]
    if len(sides) > 4 or len(now) != 2 or any(x is None for x in now) or termsigns._same(now[0], now[1]):
        return False
    read = [_reads(ctx, s, known) for s in sides]
    for i, side in enumerate(sides):
        for text in variants(student(rewrite(side, known)).strip()):
            x = _reads(ctx, text, known)
            for y in (y for j, y in enumerate(read) if j != i and y is not None and x is not None):
                ratio = sympy.simplify((x - y) / (now[0] - now[1]))
                if ratio.is_number and ratio != 0:
                    return True
    return False
