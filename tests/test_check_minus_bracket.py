"""A minus before a bracket taken to some of its terms only (``u − (u + eu)/2`` written
``(2u − u + eu)/2``; ``0.5 − 0.3(v − 4)`` written ``0.5 − 0.3v − 1.2``): the bracket's factor −1
(or −0.3) reached one term and not the other, a slip in the rule of multiplying a bracket out,
``algebra``, as a bracket's number taken to some terms only is. Every number is worked by hand
from the problem files' givens, never taken from derive's output."""

from __future__ import annotations

from support.checked import worst_lines

#: AQA M3 2007: A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward it, e = 0.8. By hand: 0.3 v_A +
#: 0.2 v_B = 0.5 and v_B − v_A = 4: v_A = −0.6, v_B = 3.4.
HEAD_ON = "aqa-m3-2007-spheres-approach-head-on"
#: Edexcel M2: A (4m) at u hits B (5m) at rest, e = 1/2. By hand: 4u = 4 v_1 + 5 v_2 and
#: v_2 − v_1 = u/2, so v_2 = 2u/3 and v_1 = u/6.
FOUR_FIVE = "edexcel-m2-undated-q7-4m-hits-5m-b-four-times-a"


def test_a_minus_before_a_number_times_a_bracket_reaching_one_term() -> None:
    # 0.2 v_B = 0.5 − 0.3 v_A with v_A = v_B − 4: 0.5 − 0.3(v_B − 4) = 0.5 − 0.3 v_B + 1.2. The
    # student's −1.2: the 0.3 reached both terms, the minus only the first. Then 0.5 v_B = −0.7.
    work = (
        "Taking right as positive.\n"
        "0.3(3) + 0.2(-2) = 0.3 v_A + 0.2 v_B\n"
        "v_B - v_A = 0.8(3 + 2) = 4, so v_A = v_B - 4\n"
        "0.2 v_B = 0.5 - 0.3(v_B - 4) = 0.5 - 0.3 v_B - 1.2\n"
    )
    found = worst_lines(HEAD_ON, work)
    assert found[2][0] == found[3][0] == "correct", found
    assert found[4] == ("wrong", "algebra"), found


def test_a_minus_alone_before_a_bracket() -> None:
    # v_2 = v_1 + u/2 into 4v_1 = 4u − 5v_2: 4u − (5v_1 + 5u/2) = 4u − 5v_1 − 5u/2. Written
    # 4u − 5v_1 + 5u/2: the minus reached 5v_1 and not 5u/2.
    work = (
        "Positive: A's way. After: v_1 (A), v_2 (B)\n"
        "4mu = 4m v_1 + 5m v_2\n"
        "v_2 - v_1 = 1/2 (u - 0), so v_2 = v_1 + u/2\n"
        "4 v_1 = 4u - (5 v_1 + 5u/2) = 4u - 5 v_1 + 5u/2\n"
    )
    found = worst_lines(FOUR_FIVE, work)
    assert found[2][0] == found[3][0] == "correct", found
    assert found[4] == ("wrong", "algebra"), found


def test_latex_minus_before_a_fraction_over_a_common_denominator() -> None:
    # v_2 = (2v_1 + u)/2 into v_1 = u − 5v_2/4: v_1 = u − (10v_1 + 5u)/8 = (8u − 10v_1 − 5u)/8.
    # Written (8u − 10v_1 + 5u)/8: the minus reached 10v_1 and not 5u, put over the 8.
    work = (
        "Positive: A's way.\n"
        "$$4mu = 4mv_1 + 5mv_2$$\n"
        "$$v_2 - v_1 = \\tfrac12 u$$\n"
        "$$v_1 = u - \\frac{10v_1 + 5u}{8} = \\frac{8u - 10v_1 + 5u}{8}$$\n"
    )
    found = worst_lines(FOUR_FIVE, work)
    assert found[2][0] == found[3][0] == "correct", found
    assert found[4] == ("wrong", "algebra"), found
