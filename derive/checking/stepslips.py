"""A chain's line of working named by the one step of it that does not follow.

A line such as ``v1^2 = u^2 + 2gh = 21 + 2(9.8)(40) = 805`` holds at every ``=`` but one.
Where that one is from a rule in letters to its numbers, the numbers tell the slip as a
teacher reads it: a speed put in without its square (``21`` for ``21^2``) is a number
worked wrongly, ``arithmetic``; a term whose factor 2 is lost or put in (``5^2 + 9.8(1.6)``
for ``u^2 + 2gh``: the rule written ``v^2 = u^2 + gh``) is a slip in the rule, ``algebra``.
Where the step is between two sides of numbers (``21^2 + 2(9.8)(40) = 441 + 748``), it is
``arithmetic``. Any other line is left as it is (a wrong name is worse than none).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace
from functools import partial
from typing import Any

import sympy

from derive.mathtext.notation import student
from derive.problem.expr import ParseError, parse

#: What a report says of a line whose one wrong step is named, by the slip's name.
WORDS = {
    "arithmetic": ": a step of its working does not follow from the one before it (an arithmetic slip: "
    "a number worked wrongly).",
    "squared": ": a number is put in without its square (an arithmetic slip: a number worked wrongly).",
    "algebra": ": its numbers hold with a term's factor of 2 put right (a slip in the rule: a factor lost).",
    "decimal": ": a number in its working is ten times too large or too small (an arithmetic slip: a decimal "
    "point moved).",
}
_NUMBER = re.compile(r"(?<![\w.^])\d+(?:\.\d+)?(?![\w.(]|\s*\^)")


def working_step(exprs: list[sympy.Expr], sides: tuple[str, ...], holds: Callable) -> tuple[str, str]:
    """The name and words of a chain's line (``holds``: ``partial(_holds, ctx, sides, subs=…)``
    of :mod:`.chainlines`) whose ``=`` all hold but one, a step to a side of numbers; ("", "")
    otherwise."""
    if len(exprs) < 3 or len(exprs) != len(sides) or not isinstance(holds, partial) or len(holds.args) != 2:
        return "", ""
    found = _one_step(exprs, sides, holds)
    keep = [0] + [k for k in range(1, len(exprs)) if not exprs[k].free_symbols]
    if not found[0] and 2 <= len(keep) < len(exprs):  # ``u^2 + 2gh``: the student's u, h, not the chain's
        found = _one_step([exprs[k] for k in keep], tuple(sides[k] for k in keep), holds)
    return found


def _one_step(exprs: list[sympy.Expr], sides: tuple[str, ...], holds: partial) -> tuple[str, str]:
    def step(k: int, b: sympy.Expr, text: str) -> bool | None:
        return holds.func(holds.args[0], (sides[k], text), [exprs[k], b], **holds.keywords)

    ok = [step(k, exprs[k + 1], sides[k + 1]) for k in range(len(exprs) - 1)]
    bad = [k for k, h in enumerate(ok) if h is False]
    if len(bad) != 1 or None in ok or exprs[bad[0] + 1].free_symbols:
        return "", ""
    k = bad[0]
    if not exprs[k].free_symbols:
        return "arithmetic", WORDS["arithmetic"]
    found = {name for name, text in _variants(sides[k + 1]) if _holds_as(step, k, text)}
    if len(found) != 1:
        return "", ""
    name = found.pop()
    return ("arithmetic" if name in ("squared", "decimal") else name), WORDS[name]


def _holds_as(step: Callable, k: int, text: str) -> bool:
    try:
        value = parse(text, {}).expr
    except (ParseError, ValueError, TypeError, ZeroDivisionError):
        return False
    return not value.free_symbols and bool(step(k, value, text))


def _variants(text: str) -> list[tuple[str, str]]:
    """The side of numbers ``text`` with one of its numbers squared (``squared``) or with its
    decimal point moved one place (``decimal``: 3.136 for 31.36), or one of its terms doubled or
    halved (``algebra``), each as text in the parser's grammar."""
    s = student(text.strip())
    out = [("squared", f"{s[: m.start()]}({m.group()})^2{s[m.end() :]}") for m in _NUMBER.finditer(s)]
    for m in _NUMBER.finditer(s):
        out += [("decimal", f"{s[: m.start()]}({m.group()}{k}){s[m.end() :]}") for k in ("*10", "/10")]
    for a, b in _terms(s):
        for k in ("2*", "(1/2)*"):
            out.append(("algebra", f"{s[:a]}{k}({s[a:b]}){s[b:]}"))
    return out


def _terms(s: str) -> list[tuple[int, int]]:
    """The spans of the top-level terms of ``s`` (split at ``+`` and ``-`` outside brackets)."""
    spans, depth, start = [], 0, 0
    for i, c in enumerate(s):
        depth += (c == "(") - (c == ")")
        if c in "+-" and depth == 0 and i > 0 and s[i - 1] not in "*/^(eE":
            spans.append((start, i))
            start = i + 1
    spans.append((start, len(s)))
    return [(a, b) for a, b in spans if s[a:b].strip()]


#: What a report says of a line that divides through the relation before it but for one term.
UNDIVIDED = (
    ": it divides the line before through by the unknown's coefficient but for one term (a slip in rearranging)."
)


#: What a report says of a line that leaves the other side undivided by the unknown's coefficient.
NOT_DIVIDED = (
    ": it leaves the other side of the line before undivided by the unknown's coefficient (a slip in arithmetic)."
)


def halved(item: Any, exprs: list[sympy.Expr], previous: list[sympy.Expr]) -> Any:
    """``item`` (a chain's wrong line, not yet named) named ``algebra`` where it is the relation
    just before (which held), ``c x = a + b``, halved (divided through by ``c``) but for one term
    (``v2 = 3.5 + 7e`` from ``2 v2 = 7 + 7e``: the 7e not halved); ``arithmetic`` where the
    other side is not divided at all by a whole number ``c`` (``v2 = 7 + 7e``); None otherwise."""
    if len(exprs) != 2 or len(previous) != 2 or not exprs[0].is_Symbol:
        return None
    x = exprs[0]
    for lhs, rhs in (previous, previous[::-1]):
        c = sympy.expand(lhs).coeff(x)
        if not c.is_number or c in (0, 1, -1) or sympy.expand(lhs - c * x) != 0 or rhs.has(x):
            continue
        if c.is_Integer and sympy.expand(exprs[1] - rhs) == 0:  # q = 7 + 7e from 2q = 7 + 7e: not divided
            lead = item.message.split(":")[0]
            return replace(item, slip="arithmetic", message=f"{lead}{NOT_DIVIDED}")
        terms = sympy.Add.make_args(sympy.expand(rhs))
        if len(terms) < 2:
            continue
        for t in terms:
            if sympy.expand(exprs[1] - ((rhs - t) / c + t)) == 0:
                lead = item.message.split(":")[0]
                return replace(item, slip="algebra", message=f"{lead}{UNDIVIDED}")
    return None
