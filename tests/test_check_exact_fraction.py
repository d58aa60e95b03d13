"""A decimal followed by the exact fraction it was rounded from in brackets (``e = 0.172 (5/29)``,
``v2 = 0.174 (4/23) m/s``, ``0.174 \\;(\\tfrac{4}{23})``) says the value twice, as ``1.49 (1.4925)``
does: the bracket is a note, not a factor. A bracket that is not the value rounded (``0.2 (2/3)``,
one figure or another number) stays a product, and a decimal that is not the fraction rounded is
still wrong.

OpenStax satellites (e = 1): 4000 kg at 0.250 m/s onto 7500 kg at rest. By hand: 1000 = 4000 v1 +
7500 v2, v2 - v1 = 0.250, so 11500 v1 = -875: v1 = -7/92 = -0.07609, v2 = 4/23 = 0.17391.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

from derive.mathtext.notes import without_note

SATELLITES = "openstax-cp-8-satellites-elastic"


def test_a_decimal_and_its_exact_fraction_in_brackets() -> None:
    work = (
        "4000(0.250) = 4000 v1 + 7500 v2\nv2 - v1 = 0.250\n1000 = 4000 v1 + 7500(v1 + 0.250)\n"
        "v1 = -0.0761 (-7/92) m/s\nv2 = 0.174 (4/23) m/s\n"
    )
    found = worst_lines(SATELLITES, work)
    assert [found[n][0] for n in (1, 2, 3, 4, 5)] == ["correct"] * 5


def test_the_same_in_latex() -> None:
    work = "$$4000(0.250) = 4000 v_1 + 7500 v_2$$\n\n$$v_2 = 0.174 \\;\\left(\\tfrac{4}{23}\\right)\\text{ m/s}$$\n"
    assert worst_lines(SATELLITES, work)[3][0] == "correct"


def test_a_decimal_that_is_not_the_fraction_rounded_is_still_wrong() -> None:
    work = "4000(0.250) = 4000 v1 + 7500 v2\nv2 - v1 = 0.250\nv2 = 0.178 (4/23) m/s\n"
    assert worst_lines(SATELLITES, work)[3][0] == "wrong"


@pytest.mark.parametrize(
    ("line", "read"),
    [
        ("e_wall = 0.5/2.9 = 0.172 (5/29)", "e_wall = 0.5/2.9 = 0.172"),
        ("x = 2.25 (9/4) kg", "x = 2.25 kg"),
        ("V = 1.49 (1.4925) m/s", "V = 1.49 m/s"),
        ("x = 0.2 (2/3)", "x = 0.2 (2/3)"),  # not 2/3 rounded: a product
        ("v = 0.5 (1/2)", "v = 0.5 (1/2)"),  # one figure: a product, as written
        ("y = 0.3 (2.9) w", "y = 0.3 (2.9) w"),  # a letter after, not a unit
    ],
)
def test_which_brackets_are_the_value_again(line: str, read: str) -> None:
    assert without_note(line)[0] == read
