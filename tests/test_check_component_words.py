"""An oblique impact's components after named in words (:mod:`derive.checking.wordnames`) where
the words say the line of centres by a pronoun after naming it ("Line of centres: from A to B.
a, b = components along it after (A, B)", "along this line"), call the components velocities
("p, q = velocities along ..."), or abbreviate the line with its dots ("along the l.o.c. after
impact": the dot after "c" ends no sentence). The names were not known, so a line with a slip
in them (its names not inferred from a line that holds) was not read (the corpus's yd11).

Worked by hand (ocr-m3-2007-oblique-sin-alpha-0p8: A 4 kg at 15 m/s at α to the line of
centres, sin α = 0.8, so cos α = 0.6 and 15 cos α = 9 along it; B 3 kg at 12 m/s along it toward
A; e = 0.5): momentum 4(9) + 3(-12) = 4p + 3q; restitution q - p = 0.5(9 + 12) = 10.5; so
p = -4.5, q = 6. B's momentum taken positive, 4(9) + 3(12) = 4p + 3q, is false (the slip).
"""

from __future__ import annotations

import pytest
from support.checked import lines

OCR = "ocr-m3-2007-oblique-sin-alpha-0p8"


SAID = [
    ("Line of centres: positive from A to B. p, q = components along it after (A, B).", "p", "q"),
    ("n along the line of centres; x and y are the components along this line after the impact (A, B)", "x", "y"),
    ("p, q = velocities along the l.o.c. after impact (A and B respectively)", "p", "q"),
    ("Along the line of centres (A to B), let a and b be the velocities along it after, of A and B.", "a", "b"),
]


@pytest.mark.parametrize(("said", "p", "q"), SAID)
def test_components_named_in_words_are_known_when_the_first_line_is_wrong(said: str, p: str, q: str) -> None:
    found = lines(OCR, f"{said}\n4(9) + 3(12) = 4{p} + 3{q}")
    assert found[2][:2] == ("wrong", "b_sign")


@pytest.mark.parametrize(("said", "p", "q"), SAID)
def test_components_named_in_words_are_read_in_working_that_holds(said: str, p: str, q: str) -> None:
    found = lines(OCR, f"{said}\n4(9) + 3(-12) = 4{p} + 3{q}\n{q} - {p} = 0.5(9 + 12)\n{p} = -4.5\n{q} = 6")
    assert [found[n][0] for n in (2, 3, 4, 5)] == ["correct"] * 4
