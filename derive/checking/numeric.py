"""Small helpers shared by the checks: numbers out of SymPy, closeness, and how values are shown."""

from __future__ import annotations

import functools
import math
import re
from decimal import Decimal

import sympy

from derive.numbers import format_number
from derive.problem import units

#: Relative difference below which two exact values count as equal (30-digit evaluation).
EXACT = 1e-15


@functools.lru_cache(maxsize=8192)
def number_of(x: sympy.Expr) -> complex | None:
    """``x`` evaluated to 30 digits; None when it has no finite value (cached: the mistakes'
    velocities are compared with every wrong line)."""
    try:
        c = complex(x.evalf(30))
    except (TypeError, ValueError, ZeroDivisionError):
        return None
    if not (math.isfinite(c.real) and math.isfinite(c.imag)):
        return None
    return c


def close(a: complex, b: complex, tol: float) -> bool:
    """``a`` and ``b`` equal within the relative ``tol`` (at least :data:`EXACT`)."""
    return abs(a - b) <= max(tol, EXACT) * max(abs(a), abs(b)) + 1e-25


def simplified(d: sympy.Expr) -> sympy.Expr | None:
    """``simplify(d)``, or None when it is too big or SymPy gives up."""
    if sympy.count_ops(d) > 400:
        return None
    try:
        return sympy.simplify(d)
    except (TypeError, ValueError, NotImplementedError, RecursionError):
        return None


def tidy(x: sympy.Expr) -> sympy.Expr:
    """A short form of ``x`` for showing (simplified when that is cheap)."""
    if sympy.count_ops(x) > 80:
        return x
    try:
        return sympy.simplify(x)
    except (TypeError, ValueError, NotImplementedError):
        return x


def plain(x: sympy.Expr) -> str:
    """``x`` as the parser reads it (``^`` for powers)."""
    return str(x).replace("**", "^")


def is_negative(c: sympy.Expr) -> bool:
    """True when the number ``c`` is negative, or the expression ``c`` reads with a minus."""
    x = number_of(c) if not c.free_symbols else None
    if x is not None:
        return x.real < 0
    return c.could_extract_minus_sign()


def coefficient(c: sympy.Expr) -> str:
    """A coefficient as shown in an equation: exact where short, else four figures."""
    if c.is_Rational:
        if c.q == 1:
            return str(c.p)
        q = c.q
        for p in (2, 5):
            while q % p == 0:
                q //= p
        if q == 1 and len(str(c.q)) <= 6:
            return format(Decimal(c.p) / Decimal(c.q), "f")
    if not c.free_symbols:
        x = number_of(c)
        if x is not None:
            return format_number(sympy.Float(x.real, 30), 4)
    return plain(sympy.N(c, 4))


def with_unit(number: str, unit_text: str) -> str:
    """``8.40 m/s``, ``37.6°``."""
    if not unit_text:
        return number
    shown = units.plain_unit(unit_text)
    return number + shown if shown == "°" else f"{number} {shown}"


def pct_plain(x: sympy.Expr) -> str:
    """A fraction as a percentage: 0.01 -> ``1 %``."""
    return f"{float(x) * 100:g} %"


def listed(words: list[str]) -> str:
    """``a and b``, ``a, b and c``."""
    return " and ".join(words) if len(words) < 3 else ", ".join(words[:-1]) + " and " + words[-1]


def decimals(sides: tuple[str, ...] | list[str]) -> set[str]:
    """The decimals written in ``sides`` (``12.2``, ``-0.852``), as written, sign dropped; one
    typed without its leading zero (``.696``, ``8x.87``, phone-typed or American) is also the same
    number with it (``0.696``), so that a line writing it either way is seen to use it."""
    found = set(re.findall(r"(?<![\w.])\d+\.\d+|(?<![\d.])\.\d+", " ".join(sides)))
    return found | {"0" + d for d in found if d.startswith(".")}


def shown(x: sympy.Expr) -> str:
    """A given's value as a report quotes it (``5``, ``0.35``): an integer as it is, else its float."""
    return str(x) if x.is_Integer else f"{float(x):g}"
