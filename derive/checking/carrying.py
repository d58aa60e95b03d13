"""What a student carries on after a slip: the numbers written wrong, the own values of names
got wrong, and whether a later line is worked from them (a carried error, not a new mistake).

:class:`Carrying` is the part of :class:`~.lines.Trace` that keeps them; the trace judges a
line, and asks these whether what makes it hold, or look right, is the student's own wrong
number carried on.
"""

from __future__ import annotations

import re
from dataclasses import replace

import sympy

from derive.checking.context import Context
from derive.checking.inference import Read
from derive.checking.numeric import decimals, number_of
from derive.checking.relations import Point, Values
from derive.checking.worlds import NUMBER_SIDE, Pair
from derive.mathtext.notation import student

Line = Read


#: A value in the symbolic givens as written: ``5u``, ``-4u/3``, ``0.5mu``.
_TERM = re.compile(r"^[-+]?((?:\d+\.?\d*)[A-Za-z]{1,2}(?:/\d+)?)$")


class Carrying:
    """The numbers and values the student got wrong so far, and the tests that use them."""

    ctx: Context
    U: tuple[sympy.Symbol, ...]
    pts: list[Point]
    truth: list[Values]
    world: list[Values] | None
    wrong_values: set[str]
    wrong_numbers: set[str]
    wrong_terms: set[str]
    own: dict[sympy.Symbol, sympy.Expr]
    wrong_number: tuple[str, sympy.Expr] | None

    def pairs(self, line: Line) -> list[Pair]:  # pragma: no cover - the trace's
        raise NotImplementedError

    def holds(self, pairs: list[Pair], values: list[Values]) -> bool:  # pragma: no cover - the trace's
        raise NotImplementedError

    def _wrote_wrong(self, line: Line) -> None:
        """The numbers a wrong or carried line states: its last side, and any side that is a
        number as written (``v_t = (61.0 - 45.75)/25 = 0.61 = v_A2t``)."""
        stated = [s for s in line.sides[:-1] if NUMBER_SIDE.match(student(s.strip()))]
        self.wrong_values |= decimals([*stated, *line.sides[-1:]])
        self.wrong_numbers |= set(re.findall(r"\d+\.?\d*", line.sides[-1]))
        term = _TERM.match(line.sides[-1].replace(" ", "").replace("*", ""))
        if term and line.exprs and line.exprs[-1].free_symbols and not set(self.U) & line.exprs[-1].free_symbols:
            self.wrong_terms.add(term.group(1))  # "w = 5u": a value in the symbolic givens

    def _own_value(self, line: Line) -> None:
        """``u_n = 28 cos 45 = 14.7`` wrong: the student's own value of u_n, for the lines after."""
        left = line.exprs[0] if line.exprs else None
        m = NUMBER_SIDE.match(student(line.sides[-1].strip())) if line.sides else None
        if isinstance(left, sympy.Symbol) and m and not m.group(3) and len(line.sides) >= 2:
            self.own[left] = sympy.Rational(m.group(1) + m.group(2))
        elif isinstance(left, sympy.Symbol) and len(line.exprs or ()) >= 2 and line.exprs[-1].free_symbols:
            last = line.exprs[-1]  # "KE before = … = 28m": a value in the symbolic givens
            if not self.ctx.in_unknowns(last).free_symbols & set(self.U) and last.is_Mul:
                self.own[left] = last
        elif left is not None and len(line.exprs or ()) >= 2:
            self._worked_result(left, line.exprs[-1])

    def _worked_result(self, first: sympy.Expr, last: sympy.Expr) -> None:
        """``½(3m)(2u)^2 + ½mu^2 = … = 7/2 mu^2`` under a heading "KE before": a first side
        that is a result's true value (here T_1, 13/2 mu^2) worked to a wrong last one is the
        student's value of that result."""
        if set(self.U) & (first.free_symbols | self.ctx.in_unknowns(last).free_symbols):
            return
        x = number_of(first.xreplace(self.pts[0]))
        for name in ("T_1", "T_2", "T_lost", "J_n"):
            sym, _expr = self.ctx.derived().get(name, (None, None))
            true = number_of(self.ctx.in_unknowns(sym).xreplace(self.pts[0]).xreplace(self.truth[0])) if sym else None
            if x is not None and true is not None and abs(x - true) <= 1e-9 * max(abs(true), 1e-12):
                self.own[sym] = last
                return

    def _with_own_values(self, line: Line) -> bool:
        """Whether ``line`` holds with the values the student got wrong earlier put in."""
        if not self.own or not line.exprs:
            return False
        d = self.ctx.derived()  # the energy lost is T_1 - T_2, whichever of them the student got wrong
        lost = {d["T_lost"][0]: d["T_1"][0] - d["T_2"][0]} if "T_lost" in d else {}
        exprs = tuple(x.xreplace(lost).xreplace(self.own) for x in line.exprs)
        if exprs == line.exprs:
            return False
        return self.holds(self.pairs(replace(line, exprs=exprs)), self.world or self.truth)

    def _uses_wrong_numbers(self, line: Line, pairs: list[Pair]) -> bool:
        """A line of numbers only, right as arithmetic, worked from numbers the student got wrong
        earlier (``sqrt(12.2^2 + 9.15^2) = 15.25`` after ``v_B2n = 12.2``): carried, not correct;
        so is one in the unknowns that holds given the slip too (``v_B = sqrt(71.0^2 + 108.3^2)
        = 129.5``, near the true 128.9 only because the t component is the larger)."""
        working = " ".join(line.sides[:-1]).replace(" ", "").replace("*", "")
        terms = any(re.search(rf"(?<![\w.]){re.escape(t)}(?!\w)", working) for t in self.wrong_terms)
        if not decimals(line.sides[:-1]) & self.wrong_values and not terms:
            return False
        if any(p.difference.free_symbols & set(self.U) for p in pairs):
            return self.world is not None and self.holds(pairs, self.world) and self._moved(pairs)
        return True

    def _moved(self, pairs: list[Pair]) -> bool:
        """Whether the slip moves the value of a side of ``pairs`` (a kinetic energy lost from
        the speeds is the same whichever way the rebound is signed: it does not depend on it)."""
        assert self.world is not None
        for p in pairs:
            for side in (p.left, p.right):
                a, b = (number_of(side.xreplace(self.pts[0]).xreplace(v[0])) for v in (self.truth, self.world))
                if a is not None and b is not None and abs(a - b) > 1e-9 * max(abs(a), abs(b), 1e-12):
                    return True
        return False

    def _carries_number(self, line: Line) -> bool:
        """Whether ``line`` is true once the wrong number of an arithmetic slip is put right."""
        assert self.wrong_number is not None
        wrong, right = self.wrong_number
        value = number_of(right.xreplace(self.pts[0]))
        if value is None:
            return False
        try:
            written = sympy.Rational(wrong.lstrip("+-"))
        except (TypeError, ValueError):
            return False
        exprs = tuple(x.xreplace({written: sympy.Float(value.real, 20)}) for x in line.exprs or ())
        if exprs == line.exprs:
            return False
        return self.holds(self.pairs(replace(line, exprs=exprs)), self.truth)
