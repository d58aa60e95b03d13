"""A chain's mass given as a letter (``m``, no number) written beside the student's own names:
``7m = mp + mq`` is m times p plus m times q (issue #31), and m is a mass, never inferred as 0
(which made any relation with m in every term hold).

Worked by hand (chain-edexcel-m2-three-particles): A (mass m) at 7 m/s strikes B (mass m) at rest;
p, q are A's and B's velocities after. Momentum 7m = m p + m q (so 7 = p + q); restitution
q - p = 7e; so 2q = 7 + 7e and u_B = q = 3.5(1 + e). Wrong: 7m = m p - m q (a sign), 7 = m p + m q
(the mass dropped from one side), 7m = 2m p + m q (a mass doubled).
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

CHAIN = "chain-edexcel-m2-three-particles"
WORK = "Let p and q be the velocities of A and B after the first impact.\n{}\nq - p = 7e\n2q = 7 + 7e, so u_B = q = 3.5(1 + e)\n"


@pytest.mark.parametrize("line", ["7m = mp + mq", "7m = m(p + q)", "m(7) = mp + mq", "$7m = mp + mq$ (CLM)"])
def test_a_given_mass_letter_glued_to_own_names_is_a_product(line: str) -> None:
    assert statuses(CHAIN, WORK.format(line)) == ["correct", "correct", "correct"]


@pytest.mark.parametrize("line", ["7m = mp - mq", "7 = mp + mq", "7m = 2mp + mq", "7m = m p - m q"])
def test_a_wrong_momentum_line_with_the_mass_letter_is_wrong_not_made_true_by_m_0(line: str) -> None:
    assert statuses(CHAIN, WORK.format(line))[0] == "wrong"
