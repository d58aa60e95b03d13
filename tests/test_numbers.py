"""Significant figures: the textbook rule, half-up rounding, trailing zeros kept."""

from __future__ import annotations

from decimal import Decimal

import pytest
import sympy

from derive.numbers import format_number


@pytest.mark.parametrize(
    ("value", "digits", "text"),
    [
        (Decimal("8.398"), None, "8.40"),  # three figures, zero kept
        (Decimal("-1.1092"), None, "-1.109"),  # leading 1: four figures
        (Decimal("-1.1092"), 3, "-1.11"),  # fixed three figures, as the notes print
        (Decimal("2.345"), 3, "2.35"),  # half up, not half even
        (Decimal("2.355"), 3, "2.36"),
        (Decimal("9.9951"), None, "10.0"),  # the value's own first digit (9) decides: 3 figures
        (Decimal("1.9996"), None, "2.000"),  # first digit 1: 4 figures
        (Decimal("0.000123456"), 3, "0.000123"),
        (Decimal("812.5"), None, "813"),
        (Decimal("1234567"), 3, "1.23e+6"),
        (Decimal("0"), None, "0"),
        (Decimal("-0.0000001"), 2, "-1.0e-7"),
        (Decimal("19.8148"), 4, "19.81"),
    ],
)
def test_format_number(value: Decimal, digits: int | None, text: str) -> None:
    assert format_number(value, digits) == text


def test_exact_values_are_rounded_from_full_precision() -> None:
    # 53 cos(37.6 deg) / 5 = 8.3983: from the exact value, never from a float.
    assert format_number(sympy.Rational(53, 5) * sympy.cos(sympy.pi * sympy.Rational(376, 1800))) == "8.40"
    assert format_number(sympy.Rational(1, 8), 2) == "0.13"  # 0.125 half up


def test_extra_figures_for_intermediates() -> None:
    assert format_number(Decimal("19.8148"), None, extra=1) == "19.815"
    assert format_number(Decimal("19.8148"), 3, extra=1) == "19.81"
    assert format_number(Decimal("9.50748"), None, extra=1) == "9.507"
