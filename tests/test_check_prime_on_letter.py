"""A prime on the base letter, before the subscript (``v'_A``, ``v'_{Ax}``, ``u^\\prime_B``), marks
the velocity after as a prime after the subscript does; the same name unprimed beside it is the
velocity before (the students' "v before, v' after"), not the habit's v after.

Values worked by hand from the givens. AQA M3 2007 (head-on): 0.3 kg at 3 m/s, 0.2 kg at 2 m/s
toward it, e = 0.8: 0.3(3) + 0.2(-2) = 0.5 = 0.3 v_A' + 0.2 v_B', v_B' - v_A' = 0.8(5) = 4, so
v_B' = (0.5 + 1.2)/0.5 = 3.4 and v_A' = -0.6.
"""

from __future__ import annotations

from tests.support.checked import lines

HEAD_ON = """\
Before: v_A = 3 m/s, v_B = -2 m/s (A toward B positive)
0.3 v_A + 0.2 v_B = 0.3 v'_A + 0.2 v'_B
0.3(3) + 0.2(-2) = 0.5 = 0.3 v'_A + 0.2 v'_B
v'_B - v'_A = 0.8(v_A - v_B) = 0.8(5) = 4
v'_A = -0.6 m/s, v'_B = 3.4 m/s
"""


def test_prime_on_the_letter_in_plain_text() -> None:
    got = lines("aqa-m3-2007-spheres-approach-head-on", HEAD_ON)
    assert {n: got[n][0] for n in (1, 2, 3, 4, 5)} == dict.fromkeys((1, 2, 3, 4, 5), "correct")


# Notes 4.C.11 in LaTeX with x along the line of centres: A at 5 m/s and B at 15 m/s at 37.6 deg,
# so v_Ax = 5 cos 37.6 = 3.962, v_Bx = -15 cos 37.6 = -11.885; 20(3.962) + 5(-11.885) = 19.82;
# e(approach) = 0.6(15.847) = 9.508: v'_Ax = (19.82 - 5(9.508))/25 = -1.11, v'_Bx = 8.40.
TWO_SPHERES = r"""
Before: $v_{Ax} = 5\cos 37.6^\circ = 3.962$ m/s, $v_{Bx} = -15\cos 37.6^\circ = -11.885$ m/s
$$20(3.962) + 5(-11.885) = 20\,v'_{Ax} + 5\,v'_{Bx} = 19.82$$
$$v'_{Bx} - v'_{Ax} = 0.6\,(v_{Ax} - v_{Bx}) = 9.508$$
$$v'_{Ax} = -1.11 \text{ m/s}, \quad v'_{Bx} = 8.40 \text{ m/s}$$
"""


def test_prime_on_the_letter_in_latex_components() -> None:
    got = lines("notes-4c11-two-spheres", TWO_SPHERES)
    assert {n: got[n][0] for n in (2, 3, 4, 5)} == dict.fromkeys((2, 3, 4, 5), "correct")


# A wrong value after is still wrong when the prime sits on the letter: v'_B = 3.0 (not 3.4).
SLIP = """\
Before: v_A = 3 m/s, v_B = -2 m/s (A toward B positive)
0.3(3) + 0.2(-2) = 0.3 v'_A + 0.2 v'_B
v'_B = 3.0 m/s
"""


def test_a_wrong_value_after_is_still_wrong() -> None:
    got = lines("aqa-m3-2007-spheres-approach-head-on", SLIP)
    assert got[3][0] == "wrong"
