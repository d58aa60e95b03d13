"""A sign convention in brackets among a quantity's words (``impulse from ground (up +ve) = …``):
said for the line, no part of the name; the quantity is read as it would be without it.

Values worked by hand: OCR M2 June 2012 Q1, a 0.8 kg particle at 4 m/s straight into a wall, e = 0.3.
Away from the wall positive: before -4, after 0.3 x 4 = 1.2 m/s; the impulse on the particle
0.8(1.2 - (-4)) = 0.8 x 5.2 = 4.16 N s, away from the wall.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

from derive.mathtext.reader import read_relations

PROBLEM = "ocr-m2-2012-particle-hits-wall"
WORK = """Away from the wall is positive.
speed after = 0.3 x 4 = 1.2 m/s
impulse on the particle {convention} = 0.8(1.2 - (-4)) = {value} N s
"""
CONVENTIONS = ["(away +ve)", "(taking away from the wall as positive)", "(+ve away from wall)"]


@pytest.mark.parametrize("convention", CONVENTIONS)
def test_the_convention_is_no_part_of_the_name(convention: str) -> None:
    sides = [r.sides for r in read_relations(f"impulse on the particle {convention} = 0.8(1.2 - (-4))")]
    assert sides == [("impulse on the particle", "0.8(1.2 - (-4))")]


@pytest.mark.parametrize("convention", CONVENTIONS)
def test_an_impulse_named_with_its_convention_in_brackets_is_judged(convention: str) -> None:
    assert worst_lines(PROBLEM, WORK.format(convention=convention, value="4.16"))[3][0] == "correct"


def test_a_wrong_impulse_named_with_its_convention_in_brackets_is_wrong() -> None:
    work = WORK.format(convention="(away +ve)", value="4.16").replace("(1.2 - (-4))", "(1.2 - 4)")
    assert worst_lines(PROBLEM, work.replace("4.16", "-2.24"))[3][0] == "wrong"


def test_brackets_of_mathematics_stay() -> None:
    assert [r.sides for r in read_relations("(a + b) = 3")] == [("(a + b)", "3")]
