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


def _chain_expr(text: str, values: dict) -> sympy.Expr | None:
    """A stage's given (``"-v_B"``, ``"s_B"``) in the chain's names, None where it is not one."""
    words = set(re.findall(r"[A-Za-z_]\w*", text))
    names = {str(k) for k in values}
    if not words or not words <= names:
        return None
    try:
        return sympy.sympify(text, locals={w: sympy.Symbol(w) for w in words})
    except (sympy.SympifyError, SyntaxError, TypeError):
        return None


def _stage_impulse(st: dict, values: dict) -> sympy.Expr | None:
    """An impact stage's impulse along n on B (derive's J_n) in the chain's names: its result
    where the stage names it, else worked from a body's mass and its velocities before and after."""
    results = st.get("results", {})
    if "J_n" in results:
        return sympy.Symbol(results["J_n"])
    given = st.get("given", {})
    for body, sign in (("B", 1), ("A", -1)):
        parts = []
        for name in (f"m_{body}", f"v_{body}1", f"v_{body}2"):
            if name in results:
                parts.append(sympy.Symbol(results[name]))
            elif isinstance(given.get(name), str):
                parts.append(_chain_expr(given[name], values))
            else:
                parts.append(None)
        if None not in parts:
            m, before, after = parts
            return sign * m * (after - before)
    return None


def _by_value(ctx, exprs: tuple) -> sympy.Expr | None:
    """In a chain of several impacts, the one impulse whose size is the number the line ends with."""
    stages = [st for st in getattr(ctx.problem, "stages", ()) if st.get("type") == "impact"]
    values = {sympy.Symbol(str(k)): v for k, v in ctx.solution.values.items()}
    last = exprs[-1]
    if len(stages) < 2 or last.free_symbols:
        return None
    matched = []
    for st in stages:
        J = _stage_impulse(st, values)
        size = J.xreplace(values) if J is not None else None
        if size is not None and not size.free_symbols and abs(abs(last) - abs(size)) <= 1e-2 * abs(size):
            matched.append(J)
    return matched[0] if len(matched) == 1 else None


def impulse_said(ctx, read: list, said: dict) -> dict[sympy.Symbol, sympy.Expr]:
    """The student's name for the impulse in words, as the chain's one impact impulse (signed
    as the first line it is worked out on ends); empty where the chain has no one impulse. In a
    chain of several impacts, the impulse is the one whose size the line's number is (the impact's
    on B, worked from its velocities, where only the wall's is a result; the one with a fixed body
    where the words say "from the wall"), or none."""
    several = sum(st.get("type") == "impact" for st in getattr(ctx.problem, "stages", ())) > 1
    J = None if several else _impulse(ctx)
    named: set[str] = set()  # the chain's names the lines before have used
    for _r, sides, exprs in read:
        p = exprs[0]
        if p.is_Symbol and p.name.startswith(PREFIX) and p not in said and _IMPULSE.fullmatch(sides[0]):
            J = (_impulse(ctx, sides[0]) or _by_value(ctx, exprs) or _by_place(ctx, named)) if several else J
            if J is None:
                return {}
            return {p: -J if sides[-1].strip()[:1] in "-−" else J}
        named |= {str(s) for x in exprs for s in x.free_symbols}
    return {}


def _by_place(ctx, named: set[str]) -> sympy.Expr | None:
    """The impulse of the impact a line stands in, where its number is no impulse's (a slip): the
    first impact stage from the last stage whose found values the lines before it name."""
    stages, specs = list(getattr(ctx.solution, "stages", ())), list(getattr(ctx.problem, "stages", ()))
    values = {sympy.Symbol(str(k)): v for k, v in ctx.solution.values.items()}
    k = 0
    for j, st in enumerate(stages):
        after = (stages[j + 1].values if j + 1 < len(stages) else ctx.solution.values) or {}
        if ({str(n) for n in after} - {str(n) for n in st.values or {}}) & named:
            k = j
    impacts = [spec for spec in specs[k:] if spec.get("type") == "impact"]
    return _stage_impulse(impacts[0], values) if impacts and len(specs) == len(stages) else None


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
