"""A whole number written against an equation still to be solved is exact, not rounded; so is a
decimal against exact algebra whose value ends at the places written (``2v = 6.8`` where 2v is 6.9).

``7 = 0.01 + 2v`` (from ``0.5(6) + 2(2) = 0.5(0.2) + 2v``): the 7 is the known side worked
out, exactly, and the line is an equation in ``v`` with a number term of its own. Rounding
does not make a whole number of one or two figures (a student rounds to three figures and
writes the decimals): the slack of ±1 in the last digit of "7" (6.5 to 7.5) would let the
slip in the other side's number (0.01 for 0.1) pass as right.
"""

from __future__ import annotations

import re
from dataclasses import replace

import sympy

from derive.mathtext.notation import student

_WHOLE = re.compile(r"^[-+]?\(?(\d{1,2})\)?$")


def exact_whole(p, unknowns: tuple[sympy.Symbol, ...], at: tuple[sympy.Expr, sympy.Expr] = ()) -> bool:
    """Whether ``p`` (a :class:`~derive.checking.worlds.Pair`) sets a whole number of one or
    two figures, as written, against a sum of the unknowns and a number term of its own (an
    equation still being solved, ``7 = 0.01 + 2v``) or against the unknowns with no decimal
    written whose value ``at`` the point judged is a fraction (``90e^2 = 41`` where e = 2/3: exact
    algebra; not ``20 v_A2n + 5 v_B2n = 20`` where the values hold cosines and 19.8 rounds to 20):
    the number is then exact."""
    texts = p.text.split(" = ", 1)
    if len(texts) != 2:
        return False
    values = tuple(reversed(at)) if at else (None, None)
    for text, other, written, value in zip(texts, (p.right, p.left), reversed(texts), values, strict=True):
        m = _WHOLE.match(student(text.strip()))
        if m is None or int(m.group(1)) == 0:
            continue
        return _solving(other, unknowns) or _whole_letters(written, other, unknowns, value)
    return False


def exact_decimal(p, unknowns: tuple[sympy.Symbol, ...], at: tuple[sympy.Expr, sympy.Expr]) -> bool:
    """Whether ``p`` sets a decimal as written (``6.8``) against an expression in the unknowns with
    no decimal written in it (``2v``) whose value ``at`` the point judged is a decimal of exactly the
    places written (6.9): exact arithmetic from exact data, so the number is that value or a slip;
    the ±1 in its last digit is the slack of rounded intermediates, and there are none (a chain of
    working that ends in it, ``v = 6.9/2 = 3.44``, keeps the slack of its steps: not this). A number
    written to more places than its exact value has (``0.0499`` for 0.05) was worked from rounded
    decimals: it keeps its slack."""
    texts = p.text.split(" = ", 1)
    if len(texts) != 2 or len(at) != 2:
        return False
    for text, other, written, value in zip(texts, (p.right, p.left), reversed(texts), reversed(at), strict=True):
        d = _DECIMAL.match(student(text.strip()))
        places = len(d.group(1).split(".")[1]) if d is not None else 0
        if places and _terminates(value, places) and not _terminates(value, places - 1):
            return _whole_letters(written, other, unknowns, value)  # 6.8 for 6.9; not 0.0499 for 0.05
    return False


#: A decimal as written alone on a side (``6.8``, ``(3.45)``).
_DECIMAL = re.compile(r"^[-+]?\(?(\d+\.\d+)\)?$")


def _terminates(value: sympy.Expr | None, places: int) -> bool:
    """Whether ``value`` is a fraction that is a decimal of at most ``places`` places (6.9, 3.45):
    written to those places it is exact, so a number there is it or a slip, never a rounding."""
    return isinstance(value, sympy.Rational) and (value * 10**places).is_integer


def _whole_letters(written: str, x: sympy.Expr, unknowns: tuple[sympy.Symbol, ...], value: sympy.Expr | None) -> bool:
    """An expression in the unknowns with no decimal written in it (``90e^2``, ``(1 - 9e)^2 +
    9(1 + e)^2``) whose value is a fraction: exact algebra, so the whole number against it is
    exact too (41 is not 40)."""
    exact = value is not None and isinstance(value, sympy.Rational)
    return exact and "." not in written and bool(x.free_symbols & set(unknowns))


def _solving(x: sympy.Expr, unknowns: tuple[sympy.Symbol, ...]) -> bool:
    """A sum holding an unknown and a number term of its own (``0.01 + 2v``)."""
    x = sympy.expand(x)
    if not isinstance(x, sympy.Add) or not (x.free_symbols & set(unknowns)):
        return False
    constant = x.as_independent(*unknowns, as_Add=True)[0]
    return constant != 0 and not constant.free_symbols


def slip_exact(trace, pairs: list) -> bool:
    """Whether ``pairs`` (a line that holds for the problem) sets a whole number of one or two
    figures as written (``v = 3``) that holds for the problem only at that number's figures
    (3.45 is 3 at one figure) and exactly in the student's world after a slip (v = 3 there):
    the number is the slip's, worked exactly, not the true value rounded; the line is carried."""
    if trace.world is None or not any(_WHOLE.match(student(t.strip())) for p in pairs for t in p.text.split(" = ")):
        return False
    exact = [replace(p, tol=1e-6, own_figures=True) for p in pairs]
    return trace.holds(exact, trace.world) and not trace.holds(exact, trace.truth)
