"""A number judged at the precision it is written with (or within a relative tolerance).

8.4 is right for 8.398 (two figures), and so are 8.40 and 8.41: ±1 in the last
digit written allows for rounded intermediates. Decimals inside a formula or an
equation are allowed the same slack (:func:`literal_tolerance`).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from decimal import ROUND_HALF_UP, Decimal, InvalidOperation, localcontext

import sympy

from derive.checking.numeric import pct_plain
from derive.numbers import to_decimal

_LITERAL = re.compile(r"[A-Za-z_][A-Za-z0-9_]*|((?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)")


def figures(d: Decimal) -> int:
    """The significant figures written (``8.40`` has 3; zero has none)."""
    digits = d.as_tuple().digits
    return len(digits) if d != 0 else 0


def last_place(d: Decimal) -> Decimal:
    """One unit in the last place written (0.01 for 8.40)."""
    return Decimal(1).scaleb(d.as_tuple().exponent)


def round_figures(d: Decimal, n: int) -> Decimal:
    """``d`` rounded half up to ``n`` significant figures (9.996 to 3 is 10.0)."""
    r = d.quantize(Decimal(1).scaleb(d.adjusted() - n + 1), rounding=ROUND_HALF_UP)
    if r.adjusted() != d.adjusted():
        r = r.quantize(Decimal(1).scaleb(r.adjusted() - n + 1), rounding=ROUND_HALF_UP)
    return r


def judge(u: Decimal, x: sympy.Expr, tolerance: sympy.Rational | None) -> bool:
    """Whether the written ``u`` is the exact ``x`` at the figures written (±1 in the
    last digit), or within the relative ``tolerance`` where one is given."""
    xd = to_decimal(x)
    with localcontext() as ctx:
        ctx.prec = 60
        if tolerance is not None:
            tol = to_decimal(tolerance)
            return abs(u - xd) <= tol * abs(xd) if xd != 0 else abs(u) <= tol
        if u == 0 or xd == 0:  # a zero is judged at the last place written (a unit or finer: not 0e9)
            return u == 0 if xd == 0 else u.as_tuple().exponent <= 0 and abs(xd) * 2 < last_place(u)
        try:
            r = round_figures(xd, figures(u))
        except InvalidOperation:
            return False
        return abs(u - r) <= slack(u, xd) or any(at_fewer(u, xd, n) for n in zeros_figures(u))


def zeros_figures(u: Decimal) -> range:
    """The fewer figures a whole number's trailing zeros may stand for: 5600 is 5.6e3 or 5.60e3
    as much as 5600 exactly; a single figure before the zeros (20, 6000) is not read as rounded."""
    t = u.as_tuple()
    if t.exponent != 0 or not t.digits or t.digits[-1] != 0:
        return range(0)
    core = len(u.normalize().as_tuple().digits)
    return range(max(core, 2), len(t.digits))


def at_fewer(u: Decimal, x: Decimal, n: int) -> bool:
    """Whether ``u`` is ``x`` rounded to ``n`` figures (no slack: the zeros are read as
    rounding only where they are exactly that)."""
    return u == round_figures(x, n)


def slack(u: Decimal, x: Decimal) -> Decimal:
    """±1 in the last digit written, at the value's own magnitude: "1" is not 10.65, and
    "-1e1" (one figure, at the tens) is not -1.109 (one figure, at the units)."""
    if u == 0 or x == 0:
        return last_place(u) if u.as_tuple().exponent <= 0 else Decimal(0)
    return min(last_place(u), last_place(round_figures(x, figures(u))))


def method(u: Decimal, tolerance: sympy.Rational | None) -> str:
    """How :func:`judge` decided, in words."""
    if tolerance is not None:
        return f"within the relative tolerance of {pct_plain(tolerance)}"
    n = figures(u)
    if n == 0:
        return "as written (zero, to the last place written)"
    fewer = zeros_figures(u)
    if fewer:
        return f"at the {fewer.start} to {n} significant figures {u} may stand for (rounded exactly)"
    return f"at the {n} significant figure{'s' if n > 1 else ''} written (±1 in the last digit)"


def literal_tolerance(text: str, data: set[sympy.Rational]) -> float:
    """Relative slack for the decimals written in ``text``: ±1 in the last digit of each,
    except numbers with one significant figure and numbers that are the problem's data
    as given (0.6 for e = 0.6); at most 5 %."""
    tol = 0.0
    for m in _LITERAL.finditer(text):
        tok = m.group(1)
        place = rounded_whole(tok or "")
        if place is not None and sympy.Rational(tok) not in data:
            tol += float(place / Decimal(tok))
            continue
        if not tok or not re.search(r"[.eE]", tok):
            continue
        if len(tok) > 30 or abs(Decimal(tok).adjusted()) > 30:
            continue  # the parser has refused such numbers already
        d = Decimal(tok)
        if d == 0 or figures(d) < 2 or sympy.Rational(tok) in data:
            continue  # one figure (0.5, 0.6) is data, not a rounded intermediate
        if copied_given(d, data):
            continue  # 2.4 for B's 2.9: a given written as another number, a slip, not a rounding
        tol += float(last_place(d) / abs(d))
    return min(tol, 0.05)


def copied_given(d: Decimal, data: set[sympy.Rational]) -> bool:
    """Whether ``d`` is a given of ``data`` written with one digit changed by more than one unit
    (2.4 or 3.9 for 2.9; not 2.8, which may be a value near it rounded)."""
    x = format(d.normalize(), "f")
    for g in data:
        if not g.is_Rational or g == 0 or abs(sympy.Rational(x) - g) <= sympy.Rational(str(last_place(d))):
            continue
        y = format(Decimal(str(sympy.Float(abs(g), 15))).normalize(), "f")
        if len(x) == len(y) and sum(p != q for p, q in zip(x, y, strict=True)) == 1:
            return True
    return False


def side_slack(side: str, data: set[sympy.Rational], read: Callable[[str], float | None]) -> float | None:
    """How far a side of numbers only moves when each rounded decimal in it moves by one unit
    in its last place (the decimals :func:`literal_tolerance` allows for), absolute: 1.49 in
    ``½(0.020)(300 - 1.49)²`` moves it by 0.06, not by 0.7 % of it. ``read`` gives a side's
    value (None where it does not read); None where a changed side does not read."""
    total = 0.0
    start = read(side)
    if start is None:
        return None
    alone = re.fullmatch(r"\s*[-+−]?\s*(?:\d+\.?\d*|\.\d+)\s*", side) is not None  # a number as written
    for m in _LITERAL.finditer(side):
        tok = m.group(1)
        place = rounded_whole(tok or "")
        if place is not None and sympy.Rational(tok) not in data:
            moved = read(side[: m.start(1)] + str(Decimal(tok) + place) + side[m.end(1) :])
            if moved is None:
                return None
            total += abs(moved - start)
            continue
        if not tok or not re.search(r"[.eE]", tok) or len(tok) > 30:
            continue
        d = Decimal(tok)
        if abs(d.adjusted()) > 30 or d == 0 or figures(d) < 2 or sympy.Rational(tok) in data:
            continue
        if figures(d) == 2 and not alone:  # 6.3 worked on: two figures carried are rounded too early
            continue
        moved = read(side[: m.start(1)] + str(d + last_place(d)) + side[m.end(1) :])
        if moved is None:
            return None
        total += abs(moved - start)
    return total


def rounded_whole(tok: str) -> Decimal | None:
    """One unit in the last place of a whole number rounded to the tens or further with at
    least three figures before its zeros (2130 for 2133.3, as 3 figures are written), as
    :func:`literal_tolerance` allows a decimal's; None for any other (12000 and 7452 are exact)."""
    if not tok.isdigit() or not tok.endswith("0") or len(tok) > 30:
        return None
    core = tok.rstrip("0")
    return Decimal(10) ** (len(tok) - len(core)) if len(core) >= 3 else None


# Working that uses a number rounded to two figures (rounded too early) ----------------------
# The notes round intermediates to three figures and carry them: a line that ends in a number is
# allowed a unit in its last place for them (``J = 0.3(5.24 + 6.26) = 3.45``). A decimal the
# student rounded to two figures and worked on (``v1 = 6.3`` for 6.261, then
# ``J = 0.3(5.24 + 6.3) = 3.46``) earns no such slack: the name the line works out is put to the
# working itself, at the slack of its other decimals only, and where it misses, the line is the
# slip (:func:`.rounding.rounded_early` names it). The problem's data at the figures given
# (``0.3`` for m = 0.3 kg, ``9.8`` for g) is not a rounding, and an exact decimal needs no slack.

#: A decimal as typed, with or without its leading zero (``6.3``, ``.87``).
DECIMAL = re.compile(r"(?<![\d.])\d*\.\d+(?![\d.])")


def two_figure(text: str, data: set) -> list[str]:
    """The decimals of ``text`` written to two significant figures that are not the problem's data."""
    known = {abs(x) for x in data if getattr(x, "is_Rational", False)}
    return [t for t in DECIMAL.findall(text) if figures(Decimal(t)) == 2 and abs(sympy.Rational(t)) not in known]


def working_side(sides: tuple[str, ...], exprs: list, data: set, letters: set) -> int | None:
    """The first side between the name (``sides[0]``, a name alone) and the number the line ends
    in that is working in numbers only (no symbol but ``letters``) with a two-figure decimal."""
    if len(sides) < 3 or not exprs or not isinstance(exprs[0], sympy.Symbol):
        return None
    for j in range(1, len(sides) - 1):
        if not (getattr(exprs[j], "free_symbols", {None}) - letters) and two_figure(sides[j], data):
            return j
    return None


#: The key of ``ctx.memo`` under which a line worked from a two-figure decimal keeps it.
EARLY = "worked from two figures"
