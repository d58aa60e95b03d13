"""Random admissible values of a problem's givens, for comparing formulas where SymPy cannot decide."""

from __future__ import annotations

import random
from collections.abc import Iterable, Mapping

import sympy

from derive.problem import Problem
from derive.problem.units import ACCELERATION, ANGLE, FORCE, LENGTH, MASS, VELOCITY

#: Random points at which two formulas are compared when simplification cannot decide.
POINTS = 8

#: The range of each kind of given, in the working units (angles in radians).
_RANGES = {MASS: (0.5, 5.0), ANGLE: (0.1, 1.45), FORCE: (5.0, 50.0), ACCELERATION: (9.0, 33.0), LENGTH: (0.5, 3.0)}


class Sampler:
    """Random admissible values of the givens: masses positive, 0 < e < 1, speeds positive,
    angles between 6° and 83°, bodies that approach along n, and the file's conditions on its
    givens met."""

    def __init__(self, problem: Problem, ind: Mapping[sympy.Symbol, sympy.Expr], fixed: Mapping | None = None) -> None:
        self.fixed = dict(fixed or {})  # givens the student put a number for ("putting m = 1")
        self.by_symbol = {g.symbol: g for g in problem.givens}
        self.approach = (problem.motion_A.n - problem.motion_B.n).xreplace(dict(ind))
        self.numeric = problem.numeric()
        given = set(self.by_symbol)  # the file's conditions on its givens ("e > 1/2": P reverses)
        self.conditions = [c for c in problem.conditions if (c.lhs - c.rhs).free_symbols <= given]

    def range(self, s: sympy.Symbol) -> tuple[float, float]:
        """The interval the values of ``s`` are drawn from."""
        g = self.by_symbol.get(s)
        dim = g.dim if g is not None else None
        if s.name == "e":
            return (0.05, 0.95)
        if dim == VELOCITY:
            return (0.5, 10.0) if s.is_nonnegative else (-10.0, 10.0)
        return _RANGES.get(dim, (0.5, 3.0))

    def points(self, symbols: Iterable[sympy.Symbol], n: int = POINTS, seed: int = 7) -> list[dict]:
        """``n`` points (fewer where too few are admissible), the same for the same seed."""
        rng = random.Random(seed)
        syms = sorted(set(symbols), key=lambda s: s.name)
        out: list[dict] = []
        tries = 0
        while len(out) < n and tries < 50 * n:
            tries += 1
            pt = {}
            for s in syms:
                lo, hi = self.range(s)
                pt[s] = sympy.Rational(rng.randint(int(lo * 1000), int(hi * 1000)), 1000)
                pt[s] = self.fixed.get(s, pt[s])
            if self._approaching(pt) and all(self._meets(c, pt) for c in self.conditions):
                out.append(pt)
        return out

    def _meets(self, c, pt: dict) -> bool:
        try:
            d = float((c.lhs - c.rhs).xreplace(pt).xreplace(self.numeric).evalf(20))
        except (TypeError, ValueError):
            return True
        return {"<": d < 0, "<=": d <= 0, ">": d > 0, ">=": d >= 0}[c.op]

    def _approaching(self, pt: dict) -> bool:
        a = self.approach.xreplace(pt).xreplace(self.numeric)
        if a.free_symbols:
            return True
        try:
            return float(a.evalf(20)) > 0
        except (TypeError, ValueError):
            return False
