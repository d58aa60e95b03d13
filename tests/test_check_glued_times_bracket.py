"""``x`` typed for times without spaces before a bracketed number (``0.4x(-6)``, ``2x(0.5)``) is
times, as it is between two numbers (``0.3x3``): a student's own x is not written between a number
and a bracketed number.

AQA FM specimen Q4 (worked by hand): A 0.8 kg and B 0.4 kg, each at 6 m/s toward each other, A moves
back at 1.2: 0.8(6) + 0.4(-6) = 2.4 = 0.8(-1.2) + 0.4 v_B, so v_B = (2.4 + 0.96)/0.4 = 8.4 and
e = (8.4 + 1.2)/12 = 0.8.
"""

from __future__ import annotations

from derive.mathtext.notation import glued_times
from tests.support.checked import lines


def test_glued_x_before_a_bracketed_number() -> None:
    assert glued_times("0.4x(-6) + 2x( 0.5 )") == "0.4*(-6) + 2*( 0.5 )"
    assert glued_times("v2x(3) + 3x(v + 1)") == "v2x(3) + 3x(v + 1)"  # a name's x, a bracket of letters


DISCS = """\
0.8x6 + 0.4x(-6) = 0.8x(-1.2) + 0.4v_B
v_B = (2.4 + 0.96)/0.4 = 8.4 m/s
e = (8.4 - (-1.2))/(6 - (-6)) = 9.6/12 = 0.8
"""


def test_glued_x_in_a_momentum_line() -> None:
    got = lines("aqa-fm-specimen-discs-show-e-0p8", DISCS)
    assert {n: got[n][0] for n in (1, 2, 3)} == dict.fromkeys((1, 2, 3), "correct")


WRONG = """\
0.8x6 + 0.4x(-6) = 0.8x(-1.2) + 0.4v_B
v_B = (2.4 - 0.96)/0.4 = 3.6 m/s
"""


def test_a_wrong_line_after_glued_x_is_still_wrong() -> None:
    got = lines("aqa-fm-specimen-discs-show-e-0p8", WRONG)
    assert got[1][0] == "correct" and got[2][0] == "wrong"
