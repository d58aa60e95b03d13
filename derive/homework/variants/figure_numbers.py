"""A figure's numbers for the variants of one problem, compiled once (see
:func:`derive.homework.variants.fill.drawing`)."""

from __future__ import annotations

import math
from typing import Any

import sympy


class FigureNumbers:
    """A figure's numbers for the variants of one problem: each expression the figure
    evaluates is compiled once to a float function of the varied givens, read as
    :func:`derive.writers.figure.frame.number` reads it (the numbers known put in at once,
    any other symbol taken as 1). Where the function cannot give a number (a root of a
    negative number), the expression is evaluated as a figure of a solve does."""

    def __init__(self, varied: tuple[sympy.Symbol, ...]) -> None:
        self.dummies = {s: sympy.Dummy(s.name) for s in varied}
        self.fns: dict[tuple, Any] = {}
        # the last numbers known (a figure asks with the same mapping, never changed, many
        # times) and the symbols in it not varied; the values of the last variant's arguments
        self.known: Any = None
        self.names: frozenset = frozenset()
        self.args: list[float] | None = None
        self.values: dict[tuple, complex] = {}

    def __call__(self, expr: object, known: Any, args: list[float]) -> float | None:
        if expr is None:
            return None
        if known is not self.known:
            self.known, self.names = known, frozenset(k for k in known if k not in self.dummies)
        key = (expr, self.names)
        if args != self.args:  # another variant: its figures before and after ask alike
            self.args, self.values = list(args), {}
        z = self.values.get(key)
        if z is None:
            fn = self.fns.get(key)
            if fn is None:
                fn = self.fns[key] = self._compile(expr, known)
            try:
                z = complex(fn(*args))
            except (ArithmeticError, ValueError, TypeError):
                from derive.writers.figure.frame import number

                return number(expr, known)
            self.values[key] = z
        return z.real if abs(z.imag) < 1e-9 and math.isfinite(z.real) else None

    def _compile(self, expr: object, known: Any) -> Any:
        e = sympy.sympify(expr).xreplace({k: self.dummies.get(k, v) for k, v in known.items()})
        inner = set(self.dummies.values())
        e = e.xreplace({s: sympy.Integer(1) for s in e.free_symbols if s not in inner})
        return sympy.lambdify(tuple(self.dummies.values()), e, modules=["math"])
