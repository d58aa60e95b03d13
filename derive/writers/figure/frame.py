"""Which way the figure faces: the drawing directions of n and t, and the rule that
draws a floor level with the drop falling down onto it (docs/figures.md).

n points down, A above B, when B is a fixed body named as a floor ("floor",
"ground"), or when, in a chain, the impact follows a ``fall`` stage and a later stage
moves vertically (``rise``, ``bounces``, a ``spring`` with ``vertical = true``).
Otherwise n points to the right; with a ``[geometry]`` table n is drawn at its angle
phi from +x, x to the right, y up.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import sympy

from derive.problem import Problem
from derive.steps.model import Solution
from derive.writers.figure.model import Point

FLOOR_WORDS = ("floor", "ground")


@dataclass(frozen=True)
class Frame:
    """The drawing directions of +n and +t (t is n turned 90° counter-clockwise)."""

    n: Point
    falls: bool = False
    xy: bool = False

    @property
    def t(self) -> Point:
        return -self.n[1], self.n[0]

    def at(self, a: float, b: float) -> Point:
        """The drawing point a along n and b along t from the point of contact."""
        return a * self.n[0] + b * self.t[0], a * self.n[1] + b * self.t[1]

    def along(self, x: float, y: float) -> float:
        """The n coordinate of a drawing point (from the point of contact)."""
        return x * self.n[0] + y * self.n[1]

    def across(self, x: float, y: float) -> float:
        """The t coordinate of a drawing point."""
        return x * self.t[0] + y * self.t[1]

    def axis(self, name: str) -> Point:
        """The drawing direction of an axis named ``+n``, ``-t``, ``+x``, ..."""
        sign = -1.0 if name[0] == "-" else 1.0
        vec = {"n": self.n, "t": self.t, "x": (1.0, 0.0), "y": (0.0, 1.0)}[name[1]]
        return sign * vec[0], sign * vec[1]


def number(expr: object, values: Mapping[sympy.Symbol, sympy.Expr] | None = None) -> float | None:
    """``expr`` as a float, each symbol without a value taken as 1; None if not real."""
    if expr is None:
        return None
    e = sympy.sympify(expr)
    if values:
        e = e.xreplace(dict(values))
    e = e.xreplace(dict.fromkeys(e.free_symbols, sympy.Integer(1)))
    try:
        z = complex(sympy.N(e))
    except (TypeError, ValueError):
        return None
    return z.real if abs(z.imag) < 1e-9 and math.isfinite(z.real) else None


def is_floor(problem: Problem) -> bool:
    """True when B is fixed and its name says it is a floor."""
    name = (problem.name_B or "").lower()
    return problem.fixed_B and any(w in name for w in FLOOR_WORDS)


def chain_falls(solution: Solution) -> dict[int, bool]:
    """Stage number -> True for each impact stage of a chain that is drawn vertically."""
    stages = solution.stages
    tables = getattr(solution.problem, "stages", ())
    out = {}
    for i, st in enumerate(stages):
        if st.part is None:
            continue
        after = stages[i + 1 :]
        vertical = any(
            s.kind in ("rise", "bounces")
            or (s.kind == "spring" and i + 1 + j < len(tables) and tables[i + 1 + j].get("vertical") is True)
            for j, s in enumerate(after)
        )
        out[st.number] = is_floor(st.part.problem) or (i > 0 and stages[i - 1].kind == "fall" and vertical)
    return out


def frame(
    problem: Problem,
    falls: bool,
    values: Mapping[sympy.Symbol, sympy.Expr],
    numbers: Callable[[object, Mapping], float | None] | None = None,
) -> Frame:
    """Where n points in the drawing (``numbers``: how to evaluate, :func:`number` by default)."""
    if falls or is_floor(problem):
        return Frame((0.0, -1.0), falls=True)
    if problem.phi is not None:
        phi = (numbers or number)(values.get(problem.phi, problem.phi), values) or 0.0
        return Frame((math.cos(phi), math.sin(phi)), xy=True)
    return Frame((1.0, 0.0))
