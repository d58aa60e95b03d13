"""A line that states a rule and works it through, with the slip in the working
(``then x = y + 3eu = u - 2eu + eu = u(1 - e)``): what the student carries on is the name = the
last side, the other unknown as they found it, and a later line that says that other unknown
again is carried, not the first slip made again.

Values worked by hand: Edexcel M2 January 2010 Q2, P (2m) at 2u meets Q (m) at u head-on, along
P's way. CLM 3u = 2x + y. The slip x - y = 3eu (restitution reversed) gives 3u = 3y + 6eu,
y = u(1 - 2e), and x = y + 3eu = u(1 + e); worked as u - 2eu + eu the student has x = u(1 - e).
The lines after hold with y = u(1 - 2e) (as found) and x = u(1 - e) (as worked):
x - y = u(1 - e) - u(1 - 2e) = eu.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

PROBLEM = "edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u"
WORK = """Let x be the velocity of P after and y the velocity of Q after, both in P's direction.
CLM: 2m(2u) - mu = 2mx + my
3u = 2x + y
NEL: x - y = 3eu
3u = 2(y + 3eu) + y = 3y + 6eu
y = u(1 - 2e)
then x = y + 3eu = u - 2eu + eu = u(1 - e)
{after}
"""


@pytest.mark.parametrize(
    "after",
    ["so Q moves off with y = u(1 - 2e)", "y = u - 2eu", "x - y = u(1 - e) - u(1 - 2e) = eu"],
)
def test_a_line_after_a_slip_in_the_working_holds_with_the_other_unknown_as_found(after: str) -> None:
    got = worst_lines(PROBLEM, WORK.format(after=after))
    assert got[4] == ("wrong", "restitution_reversed")
    assert got[7][0] == "wrong"
    assert got[8][0] == "carried"


def test_a_value_neither_found_nor_true_after_it_is_wrong() -> None:
    assert worst_lines(PROBLEM, WORK.format(after="so Q moves off with y = u(1 + e)"))[8][0] == "wrong"
