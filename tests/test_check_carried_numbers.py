"""A carried line whose last side is working (``= 2(70.0)(35.0)/70.15``) states none of the numbers
the student had right before it: a later line worked from those numbers alone is correct, not
carried; one worked from the number the slip gave is carried.

The problem (OpenStax 8.30: a 0.150 kg puck at 35.0 m/s strikes a 70.0 kg goalie at rest,
elastically): the goalie's velocity after is 2(0.150)(35.0)/70.15 = 0.1497 m/s; with the masses
swapped in the formula, 2(70.0)(35.0)/70.15 = 69.85, 69.9 m/s. KE before ½(0.150)(35.0²) =
91.875 J, 91.9 J; the goalie's KE from the slipped speed ½(70.0)(69.9²) = 171010 J, 171000 J.
"""

from __future__ import annotations

from support.checked import lines

PROBLEM = "openstax-cp-8-30-puck-bounces-off-goalie"
WORK = """momentum before = 0.150 x 35.0 = 5.25 kg m/s
goalie after: v2 = 2 m2 u1/(m1 + m2)
   = 2(70.0)(35.0)/70.15
   = 69.9 m/s
KE before = 0.5(0.150)(35.0)^2 = 91.9 J
goalie's KE after = 0.5(70.0)(69.9)^2 = 171000 J
"""


def test_numbers_right_before_a_carried_working_line_stay_right() -> None:
    found = lines(PROBLEM, WORK)
    assert found[1][0] == "correct", found
    assert found[2][0] == "wrong", found
    assert (found[3][0], found[4][0]) == ("carried", "carried"), found
    assert found[5][0] == "correct", found  # 0.150 and 35.0, as on line 1
    assert found[6][0] == "carried", found  # 69.9, the slip's
