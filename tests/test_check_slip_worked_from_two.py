"""A slip in a line worked from two of the student's equations at once (the impact rule put into
the momentum, then an arithmetic slip in the one unknown left) stands for neither more than the
other: the other velocity found from either of them with the student's wrong value is carried,
and a value that follows from neither is a further slip."""

from __future__ import annotations

import pytest
from support.checked import lines

# CIE 9231 2019 June Q3: 2m at 2u meets 4m at u head-on; x, y the velocities after, in A's way.
# CLM: 4mu - 4mu = 2mx + 4my, so x = -2y; NEL: y - x = 3eu. Together 6x + 12eu = 0, x = -2eu.
# The slip: 6x = -10eu, so x = -5eu/3. Then from NEL y = x + 3eu = 4eu/3; from CLM y = -x/2 = 5eu/6.
CIE = "cie-9231-p2-2019-june-q3-2m-at-2u-meets-4m-at-u"
WORK = (
    "Let x and y be the velocities of A and B after the impact.\n"
    "CLM: 2m(2u) - 4m(u) = 2mx + 4my\n"
    "NEL: y - x = e(2u + u) = 3eu\n"
    "0 = 2x + 4(x + 3eu)\n"
    "6x = -10eu\n"
    "x = -5eu/3\n"
)


@pytest.mark.parametrize(("last", "status"), [("y = 4eu/3", "carried"), ("y = 5eu/6", "carried"), ("y = 2eu", "wrong")])
def test_the_other_velocity_from_either_equation_is_carried(last: str, status: str) -> None:
    found = lines(CIE, WORK + last + "\n")
    assert [found[n][0] for n in (2, 3, 4)] == ["correct"] * 3
    assert found[5][:2] == ("wrong", "arithmetic")
    assert found[6][0] == "carried"
    assert found[7][0] == status


def test_a_bare_number_from_the_impact_rule_after_the_slip_is_carried() -> None:
    # BYJU'S: 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5. CLM 80 = 4a + 8b, NEL b - a = 4,
    # 80 = 12a + 32, a = 4. Written 12a = 46: a = 3.83 (3 s.f.), then b = a + 4 = 7.83 in the head.
    work = "CLM: 4(12) + 8(4) = 4v_A + 8v_B\nNEL: v_B - v_A = 0.5(12 - 4) = 4\n80 = 4v_A + 8(v_A + 4)\n"
    found = lines("byjus-4kg-ball-catches-8kg-ball", work + "12 v_A = 46\nv_A = 3.83 m/s\nv_B = 7.83 m/s\n")
    assert found[4][:2] == ("wrong", "arithmetic")
    assert [found[5][0], found[6][0]] == ["carried", "carried"]
