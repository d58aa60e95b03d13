"""Numbers in LaTeX: at significant figures, as the file wrote them, and read back from a
printed line (whether its terms add up to its total)."""

from __future__ import annotations

import re
from decimal import Decimal

import sympy

from derive.numbers import as_written, format_number, short_decimal, to_decimal


def number_latex(value: sympy.Expr | Decimal, digits: int | None, extra: int = 0) -> str:
    """A number at ``digits`` (+``extra``) significant figures, in LaTeX."""
    return power_latex(format_number(value, digits, extra=extra))


def power_latex(text: str) -> str:
    """``1.67e-27`` as ``1.67 \\times 10^{-27}``; plain numbers as they are."""
    if "e" in text:
        mant, exp = text.split("e")
        return rf"{mant} \times 10^{{{int(exp)}}}"
    return text


def exact_latex(value: sympy.Expr, digits: int | None, extra: int, *, derived: bool = False) -> str:
    """A given's number as the file wrote it when short and exact (0.6, 20, 1.67e-27), else rounded.

    A ``derived`` number was worked out, not written (a value carried from an earlier
    stage of a chain): exact and short, it is still rounded where it has more figures
    than an intermediate shows (4.538, not the 4.5375 of 8.25 · 0.55)."""
    if value.is_Integer and abs(value) < 10**6:
        return str(value)
    if short_decimal(value) and not (derived and _longer(value, digits, extra)):
        return power_latex(as_written(value))
    return number_latex(value, digits, extra)


def _longer(value: sympy.Expr, digits: int | None, extra: int) -> bool:
    """True when ``value`` written out exactly shows more figures than ``digits`` (+``extra``)."""
    return written_figures(to_decimal(value)) > written_figures(Decimal(format_number(value, digits, extra=extra)))


def written_figures(x: Decimal) -> int:
    """Significant figures of a decimal as written (trailing zeros of a whole number not counted)."""
    return len(x.normalize().as_tuple().digits) if x else 1


_NUMBER = re.compile(r"(?:\\left\()?(-?\d+(?:\.\d+)?)(?: \\times 10\^\{(-?\d+)\})?(?:\\right\))?")


def printed_number(text: str) -> Decimal | None:
    """The number a printed term shows (``-5.926``, ``1.6 \\times 10^{-3}``, ``\\left(-3\\right)``);
    None for anything else (letters, a product)."""
    m = _NUMBER.fullmatch(text.strip())
    if m is None:
        return None
    return Decimal(m.group(1)).scaleb(int(m.group(2) or 0))


def adds_up(terms: str, total: str) -> bool:
    """True when the printed sum ``terms`` (``-5.926 + 15.21``), added as written, gives
    the printed ``total`` to the total's last figure, as a reader checks it; True also
    where a term or the total is not a plain number (nothing to add)."""
    parts = re.split(r" ([+-]) ", terms.strip())
    value = printed_number(parts[0])
    shown = printed_number(total)
    if value is None or shown is None:
        return True
    for sign, text in zip(parts[1::2], parts[2::2], strict=True):
        term = printed_number(text)
        if term is None:
            return True
        value += term if sign == "+" else -term
    m = _NUMBER.fullmatch(total.strip())
    assert m is not None
    places = len(m.group(1).partition(".")[2]) - int(m.group(2) or 0)
    return abs(value - shown) <= Decimal(1).scaleb(-places) / 2
