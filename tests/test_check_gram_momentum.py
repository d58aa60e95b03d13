"""A momentum's unit with the mass in grams (``g m/s``, ``g·cm/s``) is a unit after the number,
as ``kg m/s`` is; ``g h`` stays two times g times h. Values worked by hand from the givens."""

from __future__ import annotations

from support.checked import worst_lines

from derive.mathtext.units import UNIT

#: Superballs: 22 g at 3.5 m/s hits 27 g at rest, e = 1: momentum 22(3.5) = 77 g m/s.
BALLS = "uoguelph-8-34-superballs-grams"


def test_gram_momentum_units_are_units() -> None:
    assert [bool(UNIT.fullmatch(u)) for u in ("g m/s", "g·m/s", "g cm/s", "g h", "g m")] == [
        True,
        True,
        True,
        False,
        False,
    ]


def test_a_momentum_in_grams_is_read() -> None:
    found = worst_lines(BALLS, "Momentum before: 22(3.5) + 27(0) = 77 g m/s\n")
    assert found[1][0] == "correct"


def test_a_momentum_in_grams_worked_wrongly_is_a_slip() -> None:
    found = worst_lines(BALLS, "Momentum before: 22(3.5) + 27(0) = 87 g·m/s\n")
    assert found[1][0] == "wrong"
