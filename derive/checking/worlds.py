"""A derivation's relations as pairs of sides in the unknowns, and the worlds they hold in:
the true velocities, or those of the student's own equations (a slip and what it carries).
Each relation holds within the precision of the decimals written, and a number written
alone on a side at its figures (±1 in its last digit)."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from decimal import Decimal

import sympy

from derive.checking import angleworld, relations
from derive.checking.figures import figures, round_figures
from derive.checking.figures import judge as at_figures_written
from derive.checking.numeric import number_of
from derive.checking.relations import Point, Values, coefficients, linear_roots, satisfied
from derive.checking.wholesides import exact_decimal, exact_whole
from derive.mathtext.notation import student
from derive.numbers import to_decimal

#: A side that is a number as written (``-1.11``, ``(37.6*deg)``).
NUMBER_SIDE = re.compile(r"^([-+]?)\(?((?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)(?:\*(deg|rad))?\)?$")


#: Just under 1: a side exactly two units in its last place off (7.1 for 6.9) is not within them.
BOUNDARY = 1 - 1e-9


@dataclass(frozen=True)
class Pair:
    """One ``=`` of a line: its sides as written and in the unknowns (everything known in)."""

    text: str
    left: sympy.Expr
    right: sympy.Expr
    tol: float
    raw: tuple[sympy.Expr, sympy.Expr] | None = None  # the sides before anything known is put in
    own_figures: bool = False  # judged at ``tol`` only, not at the figures of a side of one number
    worked: bool = False  # a side compared with the number a chain of working ends in (``v = 6.9/2 = 3.44``)

    @property
    def difference(self) -> sympy.Expr:
        return self.left - self.right


def in_letters(pairs: list[Pair]) -> bool:
    """Whether every side of ``pairs`` is written in names only (a law such as
    ``m_A v_A1n + m_B v_B1n = m_A v_A2n + m_B v_B2n``, ``½ m v²``): such a line states a law, it is
    not worked from an earlier line's numbers, so it neither follows from a slip nor fails to."""
    sides = [side for p in pairs if p.raw is not None for side in p.raw]
    if len(sides) < 2 * len(pairs):
        return False
    numbers = [a for side in sides for a in side.atoms(sympy.Number)]
    return all(isinstance(a, sympy.Rational) and abs(a.p) <= 2 and a.q <= 2 for a in numbers)


def holds_at(p: Pair, values: list[Values], pts: list[Point], U: tuple[sympy.Symbol, ...]) -> bool:
    for pt, vals in zip(pts, values, strict=True):
        sides = (p.left.xreplace(pt).xreplace(vals), p.right.xreplace(pt).xreplace(vals))
        left, right = number_of(sides[0]), number_of(sides[1])
        if left is None or right is None:
            return False
        scale = max(abs(left), abs(right))
        if not p.worked and exact_decimal(p, U, sides):  # 2v = 6.8 where 2v is 6.9 exactly: no slack for rounding
            if abs(left - right) > 1e-9 * max(scale, 1.0):
                return identity(p)
            continue
        tol = p.tol * _written_scale(p, left, right, scale) / scale if scale else p.tol
        far = abs(left - right) > 2 * tol * scale * BOUNDARY  # two units in the last place is not the value
        loose = not p.own_figures and at_figures(p, left, right) and not exact_whole(p, U, sides)
        if far and not satisfied(p.difference, vals, U, [pt], tol) and not loose:
            return identity(p)
    return True


def _written_scale(p: Pair, left: complex, right: complex, scale: float) -> float:
    """The size the slack of ``p`` is counted in: a side that is a number as written (its
    last place is the unit: 6.9 in ``2v = 6.9``, where 7.1 is two units off), else the larger."""
    written = [abs(x) for t, x in zip(p.text.split(" = ", 1), (left, right), strict=False) if _plain(t)]
    return min(written) if written and min(written) > 0 else scale


def _plain(text: str) -> bool:
    """A number as written, or a decimal times one letter (``4.3v``: its last place is 0.1v)."""
    typed = student(text.strip())
    return NUMBER_SIDE.match(typed) is not None or _SCALED.match(typed) is not None


_SCALED = re.compile(r"^[-+]?\d+\.\d+\*[A-Za-z]\w*$")


def identity(p: Pair) -> bool:
    """Whether the two sides of ``p`` are the same expression (``6x^2 - 8ux + 2u^2 =
    2(3x - u)(x - u)``): it holds wherever they are both 0, where no tolerance can say so."""
    try:
        return sympy.expand(p.difference) == 0
    except (TypeError, ValueError, RecursionError):
        return False


def three_figures(sides: tuple[str, ...], data: set) -> str:
    """The decimals of a line's middle sides written to 3 figures or more (their rounding is
    the student's own, and allowed for; 2-figure ones are rounding too early)."""
    found = re.findall(r"(?<![\w.])\d+\.\d+", " ".join(sides[1:-1]))
    if any(figures(Decimal(t)) < 3 and sympy.Rational(t) not in data for t in found):
        return ""
    return " ".join(found)


def written_right(u: Decimal, x: sympy.Expr) -> bool:
    """``u`` is ``x`` at the figures written (±1 in the last digit), and a number of one
    figure is ``x`` rounded (5 is not 6: one figure leaves no room for rounded working)."""
    if not at_figures_written(u, x, None):
        return False
    return figures(u) != 1 or round_figures(to_decimal(x), 1) == u


def at_figures(p: Pair, left: complex, right: complex) -> bool:
    """A side that is a number as written (``= -12``, ``= 20``, ``= 124°``) is right at its
    figures (±1 in its last digit): -11.88 is -12 at two figures, 123.7° is 124°."""
    for text, other in zip(p.text.split(" = ", 1)[::-1], (left, right), strict=True):
        if NUMBER_SIDE.match(student(text.strip())):
            return number_at_figures(text, other)
    return False


def number_at_figures(text: str, value: complex) -> bool:
    """Whether ``text``, a number as written (``-12``, ``294``, ``124°``), is ``value`` at its
    figures (±1 in its last digit)."""
    m = NUMBER_SIDE.match(student(text.strip()))
    if not m or abs(value.imag) >= 1e-12:
        return False
    x = value.real * 180 / math.pi if m.group(3) == "deg" else value.real  # 124°: in degrees
    try:
        return written_right(Decimal(m.group(1) + m.group(2)), sympy.Float(x, 30))
    except (ArithmeticError, ValueError):
        return False


def alike(a: dict, b: dict) -> float:
    """|cos| of the angle between two coefficient vectors (their linear parts)."""
    return relations.cosine(a, b, [m for m in set(a) | set(b) if sum(m) == 1])


def solve_world(
    equations: dict[int, sympy.Expr], U: tuple[sympy.Symbol, ...], pts: list[Point], near: list[Values]
) -> list[Values] | None:
    """The velocities that satisfy ``equations`` at each point (the root nearest ``near``)."""
    out = []
    for pt, guide in zip(pts, near, strict=True):
        roots = linear_roots([x.xreplace(pt) for x in equations.values()], U)
        if roots is None:  # an unknown angle in a sine or cosine: in tan(α/2)
            roots = angleworld.roots([x.xreplace(pt) for x in equations.values()], U)
        if roots is None:
            roots = relations.nonlinear_roots(
                [sympy.N(sympy.numer(sympy.together(x.xreplace(pt))), 30) for x in equations.values()], U
            )
        if not roots:
            return None
        target = {u: number_of(sympy.sympify(guide[u])) or 0 for u in U}
        roots.sort(key=lambda r: (_against_sign(r, U), sum(abs((number_of(r[u]) or 0) - target[u]) for u in U)))
        out.append(roots[0])
    return out


def _against_sign(root: Values, U: tuple[sympy.Symbol, ...]) -> int:
    """How many unknowns that cannot be negative (e, a mass: the symbol says so) ``root`` makes
    negative: the student's own e after a slip is the positive root (``e^2 = 1/2``: 0.707), though
    the negative one gives velocities nearer the true ones."""
    return sum(1 for u in U if u.is_nonnegative and ((number_of(root[u]) or 0).real < -1e-12))


def closest(
    F: sympy.Expr, equations: dict[int, sympy.Expr], U: tuple[sympy.Symbol, ...], pt: Point, truth: Values, held: list
) -> int | None:
    """The equation ``F`` most likely stands for: the most alike of ``equations`` in its
    unknowns whose place it can take (the others with it still determine the velocities),
    first keeping the most of the right relations ``held`` the student wrote."""
    cf = coefficients(F.xreplace(pt), U)
    if not cf and not angleworld.angles_in([F], U):
        return None
    best, score = None, (-1, 0, False, -9, -1.0)
    eliminated = len(F.free_symbols & set(U)) == 1 and all(len(G.free_symbols & set(U)) > 1 for G in equations.values())
    for j, G in equations.items():
        cg = coefficients(G.xreplace(pt), U)
        both = angleworld.angle_coefficients(F.xreplace(pt), G.xreplace(pt), U) if not (cf and cg) else None
        if not (cf and cg) and not both:
            continue
        trial = solve_world({**equations, j: F}, U, [pt], [truth])
        if trial is None:
            continue
        kept = [i + 1 for i, p in enumerate(held) if holds_at(p, trial, [pt], U)]
        near = angleworld.alike(*both) if both else alike(cf, cg)  # type: ignore[arg-type]
        # then the first of those much alike (substituted into); a line in one unknown that the
        # equations in two were combined into is alike none: it keeps the relations written last
        s = (len(kept), sum(kept) if eliminated else 0, near >= 0.5, -j, near)
        if s > score:
            best, score = j, s
    return best
