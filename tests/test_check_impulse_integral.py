"""The impulse written as the integral of the force over the time (``\\int F\\,dt``, ``∫F dt``,
with limits or none): read as the impulse, not left unread.

Values worked by hand: OCR M2 June 2011 Q4 (chain-ocr-m2-2011-find-e-mass-then-wall): A at 3 m/s,
B (0.2 kg) at 1.5 m/s toward it; after, A at 2 m/s and B at 2.9 m/s the way A was going:
e = (2.9 - 2)/(3 + 1.5) = 0.2, and the impulse on B is 0.2(2.9 + 1.5) = 0.88 N s.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

from derive.mathtext.reader import read_relations

PROBLEM = "chain-ocr-m2-2011-find-e-mass-then-wall"


@pytest.mark.parametrize("typed", ["∫F dt = 0.2(4.4)", r"$\int_0^T F\,dt = 0.2(4.4)$", r"$\int F(t)\,dt = 0.2(4.4)$"])
def test_the_integral_of_the_force_is_the_impulse(typed: str) -> None:
    assert [r.sides for r in read_relations(typed)] == [("impulse", "0.2(4.4)")]


def test_the_impulse_as_an_integral_is_judged() -> None:
    work = "e = (2.9 - 2)/(3 + 1.5) = 0.2\nimpulse on B: ∫F dt = 0.2(2.9 + 1.5) = 0.88 N s\n"
    assert worst_lines(PROBLEM, work)[2][0] == "correct"
    assert worst_lines(PROBLEM, work.replace("= 0.88 N s", "= 0.98 N s"))[2][0] == "wrong"
