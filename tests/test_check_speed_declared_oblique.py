"""A letter declared in words as a body's speed before in an oblique impact ("Let A's speed
before the impact be v", "let w be the initial speed of Q") is that body's given speed, whatever
the habits make of the letter alone (v after, along n): the student then resolves it, v cos 30.

Values worked by hand from the givens: identical balls, B at rest, A at speed u at 30 deg (or
alpha) to the line of centres, e kept: v_A1n = u cos 30 = (sqrt3/2) u; (3) v_A2n + v_B2n =
(sqrt3/2) u, (4) v_B2n - v_A2n = e (sqrt3/2) u, so v_B2n = (1 + e) sqrt3 u / 4 and
v_A2n = (1 - e) sqrt3 u / 4.
"""

from __future__ import annotations

from tests.support.checked import lines

PRE_U = r"""
Let A's speed before the impact be $v$. n along the line of centres, t across it.
$$u_{An} = v\cos 30^\circ = \tfrac{\sqrt3}{2}v, \qquad u_{At} = v\sin 30^\circ = \tfrac12 v$$
$$v_{An} + v_{Bn} = \tfrac{\sqrt3}{2}v$$
$$v_{Bn} - v_{An} = e\,\tfrac{\sqrt3}{2}v$$
$$v_{Bn} = \tfrac{\sqrt3}{4}(1+e)v$$
"""


def test_a_habit_letter_declared_as_the_speed_before() -> None:
    got = lines("pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg", PRE_U)
    assert {n: got[n][0] for n in (3, 4, 5, 6)} == dict.fromkeys((3, 4, 5, 6), "correct")


# Edexcel M4 2005: Q (derive's A) at speed u at alpha to the line of centres, P (B) at rest:
# v_Q = (1 - e) u cos(alpha) / 2 along the line of centres after.
EDEXCEL = """\
Let w be the initial speed of Q.
Along the line of centres: m w cos(alpha) = m v_Q + m v_P
v_P - v_Q = e w cos(alpha)
v_Q = (1 - e) w cos(alpha) / 2
"""


def test_the_initial_speed_of_the_statements_body() -> None:
    got = lines("edexcel-m4-2005-june-q3-show-1-minus-e-tan-beta", EDEXCEL)
    assert {n: got[n][0] for n in (2, 3, 4)} == dict.fromkeys((2, 3, 4), "correct")


# The declared speed resolved with a wrong factor is still wrong: v cos 30 written as v/2.
WRONG = r"""
Let A's speed before the impact be $v$.
$$u_{An} = v\cos 30^\circ = \tfrac12 v$$
"""


def test_a_wrong_resolution_of_the_declared_speed_is_wrong() -> None:
    got = lines("pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg", WRONG)
    assert got[3][0] == "wrong"
