"""The unit after an equation line: none where its letters give its dimension, the rest
where they give part of it."""

from __future__ import annotations

from collections.abc import Mapping

import sympy

from derive.problem.units import latex_unit, parse_unit
from derive.steps.model import Eqn
from derive.writers.printing.style import Style

_UNITLESS = {sympy.Symbol(f"vec:e_{a}", commutative=True) for a in "tnxy"}


def _unit_beside_letters(eqn: Eqn, style: Style) -> str | None:
    """The unit a value in letters still needs: none where its letters give its dimension
    (v_A2 = 0.6 u), the whole unit where they are pure numbers (3.5 + 3.5 e m/s), the rest
    where one letter gives part of it (T_1 = 22 m J/kg, m a mass in kg)."""
    last = eqn.sides[-1]
    if not eqn.unit or eqn.unit in ("%", "deg") or last.mode == "symbolic" or len(last.terms) != 1:
        return None
    term = last.terms[0].xreplace(dict(style.values))
    letters = term.free_symbols - _UNITLESS
    # by name: a speed kept as a letter is positive in the closed forms, real in the style
    known = {x.name: x for x in style.letters | set(style.letter_units)}
    if not letters or not all(x.name in known for x in letters):
        return None
    units = {x: style.letter_units.get(known[x.name]) for x in letters}
    dims = {x: parse_unit(units[x]).dim if units[x] else (0, 0, 0, 0) for x in letters}
    have = _dimension(term, dims)
    if have is None or have == parse_unit(eqn.unit).dim:
        return None
    if not any(have):
        return eqn.unit
    if have == tuple(w - m for w, m in zip(parse_unit(eqn.unit).dim, (1, 0, 0, 0), strict=True)):
        # a mass short (T_1 = 4.8 v_A1^2 with the masses in numbers): the mass unit
        return "slug" if any("ft" in u for u in style.letter_units.values()) else "kg"
    alone = [x for x in letters if units[x] and dims[x] == have and not any(c in units[x] for c in "/*^")]
    return f"{eqn.unit}/{units[alone[0]]}" if alone and "/" not in eqn.unit else None


def _dimension(expr: sympy.Expr, dims: Mapping[sympy.Symbol, tuple[int, ...]]) -> tuple[int, ...] | None:
    """The dimension of a value in letters of known dimensions (None where it cannot tell)."""
    if expr.is_number:
        return (0, 0, 0, 0)
    if isinstance(expr, sympy.Symbol):
        return tuple(dims[expr]) if expr in dims else None
    if isinstance(expr, sympy.Add):
        found = {_dimension(a, dims) for a in expr.args if not a.is_number}
        return found.pop() if len(found) == 1 else None
    if isinstance(expr, sympy.Mul):
        total = [0, 0, 0, 0]
        for a in expr.args:
            d = _dimension(a, dims)
            if d is None:
                return None
            total = [t + x for t, x in zip(total, d, strict=True)]
        return tuple(total)
    if isinstance(expr, sympy.Pow) and expr.exp.is_Rational:
        d = _dimension(expr.base, dims)
        return None if d is None or any(x * expr.exp % 1 for x in d) else tuple(int(x * expr.exp) for x in d)
    return None


def struck(eqn: Eqn, style: Style) -> frozenset[sympy.Symbol]:
    """The symbols the line strikes out, unless the style prints no strokes."""
    return eqn.cancel if style.strike else frozenset()


def line_unit(eqn: Eqn, style: Style) -> tuple[str | None, bool]:
    """The unit after the line's last side, and whether that side, a sum in letters, goes in
    brackets before it ((3.5 + 3.5 e) m/s)."""
    last = eqn.sides[-1]
    symbolic = last.mode == "symbolic" or any(
        t.xreplace(dict(style.values)).free_symbols - _UNITLESS for t in last.terms
    )
    if not symbolic:
        return eqn.unit, False
    unit = _unit_beside_letters(eqn, style)
    return unit, bool(unit) and isinstance(last.terms[0].xreplace(dict(style.values)), sympy.Add)


def unit_latex(eqn: Eqn, style: Style) -> str:
    """The unit after the line's last side ('' where that side is still in symbols and its
    letters give its dimension)."""
    unit, _ = line_unit(eqn, style)
    if not unit:
        return ""
    if unit == "%":
        return r"\ \%"
    return latex_unit(unit) if unit == "deg" else r"\ " + latex_unit(unit)


#: Around an optional side of a compiled variant page (with the " = " before it), for
#: the variant to keep where its numbers add up to the total after it (:func:`adds_up`).
