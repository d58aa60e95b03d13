"""A name put in for another with the other's coefficient taken to one term only of what it
stands for (``4u = 4x + 5x + u/2`` from ``4u = 4x + 5y``, ``y = x + u/2``: the 5 not taken to
the u/2) is ``algebra``, as a bracket multiplied out with its factor on one term only is. Where
several single changes to one term make the line hold, the one that multiplies a term by the
coefficient of the name substituted away is what the student did. Values by hand."""

from __future__ import annotations

from support.checked import worst_lines

#: Edexcel M2 2003: P (2m) at u hits Q (m) at rest, e = 1/3. 2u = 2x + y, y - x = u/3.
#: x = y - u/3 into 2(y - u/3) + y: 2u = 3y - 2u/3, y = 8u/9, x = 5u/9. With the 2 on the y
#: only (2u = 2y - u/3 + y): 3y = 7u/3, y = 7u/9, then x = 7u/9 - 3u/9 = 4u/9.
EDEXCEL_2003 = "edexcel-m2-2003-january-q6-2m-hits-m-e-one-third"

#: AQA M3 2014: A (2m) at 2u hits B (m) at rest, e = 2/3. 4u = 2 v_A + v_B, v_B - v_A = 4u/3.
#: v_A = v_B - 4u/3 put in: 4u = 3 v_B - 8u/3, v_B = 20u/9. With the 2 on v_B only:
#: 4u = 3 v_B - 4u/3, v_B = 16u/9.
AQA_2014 = "aqa-m3-2014-symbolic-2m-hits-m"

#: Edexcel M2 (undated) Q7: 4m at u hits 5m at rest, e = 1/2. 4u = 4p + 5q, q = p + u/2:
#: 4u = 9p + 5u/2, p = u/6. With the 5 on p only, 4u = 9p + u/2: p = 7u/18. That line also
#: holds with its 4u halved or its 4p taken four times: the 5 of the q put in is what was lost.
EDEXCEL_4M_5M = "edexcel-m2-undated-q7-4m-hits-5m-b-four-times-a"


def test_a_given_left_out_of_the_coefficient_is_algebra() -> None:
    work = (
        "Let x = velocity of P after and y = velocity of Q after.\n"
        "2mu = 2mx + my\n"
        "y - x = u/3\n"
        "x = y - u/3\n"
        "2u = 2y - u/3 + y\n"
        "3y = 7u/3\n"
    )
    found = worst_lines(EDEXCEL_2003, work)
    assert [found[n][0] for n in (2, 3, 4)] == ["correct"] * 3
    assert found[5] == ("wrong", "algebra")
    assert found[6][0] == "carried"


def test_in_latex_with_subscripted_names() -> None:
    work = (
        "$2m(2u) = 2m v_A + m v_B$\n\n"
        "$v_B - v_A = \\tfrac{2}{3}(2u)$\n\n"
        "$v_A = v_B - \\frac{4u}{3}$\n\n"
        "$4u = 2v_B - \\frac{4u}{3} + v_B$\n\n"
        "$v_B = \\frac{16u}{9}$\n"
    )
    found = worst_lines(AQA_2014, work)
    assert [found[n][0] for n in (1, 3, 5)] == ["correct"] * 3
    assert found[7] == ("wrong", "algebra")
    assert found[9][0] == "carried"


def test_the_coefficient_of_the_name_put_in_explains_the_line() -> None:
    work = "p = A after, q = B after\n4u = 4p + 5q\nq = p + u/2\n4u = 4p + 5p + u/2\np = 7u/18\n"
    found = worst_lines(EDEXCEL_4M_5M, work)
    assert found[2][0] == found[3][0] == "correct"
    assert found[4] == ("wrong", "algebra")
    assert found[5][0] == "carried"
