"""The word "impulse" on the left of a chain's line, read as the chain's one impulse.

``impulse = m(v - u) = 0.2(35 - 28) = 1.4 N s`` names the impulse the ground gives the sphere:
the result of the chain's impact stage (its ``J_n``), whatever numbers follow. Left as a name
of the student's own, the line defined it and so held, and a letter in it (``v``) was fitted
to make it hold (v = -21 for the sphere thrown down at 21 m/s): the slip (the rebound speed
put in with its sign lost) was marked correct. As in a single impact (:mod:`.wordlabels`), its
size is signed as the number the line ends with.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace

import sympy

from derive.checking.naming import PREFIX
from derive.checking.report import Item
from derive.checking.slipnames import FLIPPED
from derive.mathtext.notation import student
from derive.problem.expr import ParseError, parse

#: "impulse", "the impulse on the sphere", "impulse from the ground", "impulse of the floor".
_IMPULSE = re.compile(
    r"\s*(?:the\s+)?impulse(?:\s+(?:on|from|of|by)\s+(?:the\s+)?(?:ball|sphere|particle|ground|floor|wall))?\s*",
    re.I,
)


def _impulse(ctx, words: str = "") -> sympy.Symbol | None:
    """The chain's impact impulse the words say: its one impact's (None where it has none); in
    a chain of several impacts, each has an impulse, named in its results or not, so the word
    alone says none of them, but "from the wall" (the ground, the floor) says the one impact
    with a fixed body, where there is one."""
    impacts = [st for st in getattr(ctx.problem, "stages", ()) if st.get("type") == "impact"]
    if len(impacts) > 1 and re.search(r"\b(?:wall|ground|floor)\b", words, re.I):
        impacts = [st for st in impacts if (st.get("B") or {}).get("fixed")]
    found = [st["results"]["J_n"] for st in impacts if "J_n" in st.get("results", {})]
    return sympy.Symbol(found[0]) if len(found) == 1 and len(impacts) == 1 else None


def impulse_said(ctx, read: list, said: dict) -> dict[sympy.Symbol, sympy.Expr]:
    """The student's name for the impulse in words, as the chain's one impact impulse (signed
    as the first line it is worked out on ends); empty where the chain has no one impulse."""
    for _r, sides, exprs in read:
        p = exprs[0]
        if p.is_Symbol and p.name.startswith(PREFIX) and p not in said and _IMPULSE.fullmatch(sides[0]):
            J = _impulse(ctx, sides[0])
            return {p: -J if sides[-1].strip()[:1] in "-−" else J} if J is not None else {}
    return {}


#: A number in a side of numbers with the sign before it (``- 28`` in ``0.2(35 - 28)``).
_SIGNED = re.compile(r"(?<=[\d)])\s*([-+−])\s*(?=\d)")


def impulse_sign(ctx, item: Item, sides, exprs: list, holds: Callable[[list], bool | None]) -> Item:
    """``item`` (a wrong line of the impulse, not yet named) named ``b_sign`` where a side of
    numbers holds with the sign before one of its numbers changed (``0.2(35 - 28)`` for
    ``0.2(35 + 28)``: the rebound put in as a speed, its direction lost, with down positive)."""
    J = _impulse(ctx, sides[0])
    said = _IMPULSE.fullmatch(sides[0]) is not None or (J is not None and exprs[0] == J)
    if item.status != "wrong" or item.slip or item.again or not said or len(exprs) != len(sides):
        return item
    for side in sides[1:]:
        text = student(side.strip())
        for m in _SIGNED.finditer(text):
            flipped = f"{text[: m.start(1)]}{'+' if m.group(1) in '-−' else '-'}{text[m.end(1) :]}"
            try:
                value = parse(flipped, {}).expr
            except (ParseError, ValueError, TypeError, ZeroDivisionError):
                continue
            if not value.free_symbols and holds([exprs[0], value]):
                return replace(item, slip="b_sign", message=f"{item.message.split(': ')[0]}{FLIPPED['b_sign']}")
    return item
