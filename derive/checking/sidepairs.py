"""The sides of a line that ends in a number, compared with each other as well as with it.

``ΔE = ½ m (v − v')² = ½(0.150)(35.0 − 0.0748)² = 91.5`` is three claims: the name is that
formula, the formula is that working, and the working comes to 91.5. Each side is put to the
last number at that number's figures (:meth:`.lines.Trace.pairs`), but a number's figures are
too coarse to tell two formulas apart whose values are near (the energy lost, 91.68 J, and
½ m (u − v')², 91.48 J, are both 91.5 at the slack of a line of three-figure numbers). So two
sides next to each other, both in letters, are compared with each other at their own slack
(none: letters are exact). A line may be right only where its sides are equal for the problem
in the student's own names, not merely each near the number it ends in. A side of numbers is
still put to the number the line ends in only: its decimals may be the student's own rounded
values (4.0 for 5 cos 37.6° at two figures), judged where they are made.
"""

from __future__ import annotations

import sympy

from derive.checking.context import DEG
from derive.checking.figures import working_side
from derive.checking.worlds import Pair


def adjacent(trace, sides: tuple[str, ...], exprs: list[sympy.Expr], raw: list[sympy.Expr]) -> list[Pair]:
    """Each side next to the one after it, but the last (the number the line ends in), where
    both are in letters: judged at the slack of the two sides' own decimals (none, mostly)."""
    out = []
    for i in range(min(len(sides) - 2, 1 if raw and raw[0].is_Symbol else 0)):  # the name and its formula
        if not (raw[i].free_symbols - {DEG} and raw[i + 1].free_symbols - {DEG}):
            continue  # a side of numbers: its rounded decimals judged against the number it ends in
        tol = max(trace._tolerance(sides, raw, (i, i + 1), ""), 1e-9)
        out.append(Pair(f"{sides[i]} = {sides[i + 1]}", exprs[i], exprs[i + 1], tol, (raw[i], raw[i + 1]), True))
    return out + rounded_working(trace, sides, exprs, raw)


def rounded_working(trace, sides: tuple[str, ...], exprs: list[sympy.Expr], raw: list[sympy.Expr]) -> list[Pair]:
    """The name a line works out put to the first side of its working that uses a decimal rounded
    to two figures (``J = 0.3(5.24 + 6.3) = 3.46`` is also J = 0.3(5.24 + 6.3)), at the slack of
    its other decimals only: rounded too early (:func:`.figures.working_side`)."""
    j = working_side(sides, raw, trace.ctx.data, {DEG})
    if j is None:
        return []
    tol = max(trace._tolerance(sides, raw, (0, j), ""), 1e-9)
    return [Pair(f"{sides[0]} = {sides[j]}", exprs[0], exprs[j], tol, (raw[0], raw[j]), True)]
