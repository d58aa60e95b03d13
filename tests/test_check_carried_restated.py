"""Two ways a line after a slip carries it without making it again (docs/checking.md): a
component before the impact said again with the value the student stated for it on a wrong
line (``v_Q2t = v_Q1t = u cos(alpha)`` after ``v_Q1t = u cos(alpha)`` swapped) is carried, not
the same mistake made again; and a line that goes on from a carried one after words of what
the step does up to a colon (``factorising: = u(1 + e)/2 = …``) is carried as a line opening with
"=" is. Every value is worked by hand from the problem files' givens."""

from __future__ import annotations

from support.checked import lines

# Edexcel M4 2005 Q3: Q (m, u at alpha to the line of centres) hits P (m) at rest. True: along
# the line u cos(alpha), across it u sin(alpha); Q's t component after is its t before. Swapped:
# v_Q1n = u sin(alpha) (the slip), v_Q1t = u cos(alpha) (the same mistake again); then
# v_Q2t = v_Q1t = u cos(alpha) only says again the value stated: carried.
SWAPPED = (
    "Q before: along the line of centres u sin(alpha), across it u cos(alpha)\n"
    "v_Q1n = u sin(alpha)\n"
    "v_Q1t = u cos(alpha)\n"
    "v_Q2t = v_Q1t = u cos(alpha)\n"
)


def test_a_component_said_again_with_its_wrong_stated_value_is_carried_not_again() -> None:
    found = lines("edexcel-m4-2005-june-q3-show-1-minus-e-tan-beta", SWAPPED)
    assert found[2][:2] == ("wrong", "sin_cos_swapped")
    assert found[3][0] == "wrong" and found[3][2]  # the same mistake again
    assert found[4][0] == "carried"


# WJEC 2019 Q7: A (m, u) hits B (m) at rest. True: v_A = (1 - e)u/2. Restitution reversed
# (v_A - v_B = eu): 2 v_A = u + eu, v_A = (1 + e)u/2; the factorised line goes on from it.
REVERSED = (
    "v_A + v_B = u\nv_A - v_B = e u\n2 v_A = u + e u\nv_A = (u + e u)/2\nfactorising: = u(1 + e)/2 = (1 + e)u/2\n"
)


def test_a_line_going_on_after_words_and_a_colon_from_a_carried_one_is_carried() -> None:
    found = lines("wjec-further-unit3-2019-june-q7-equal-spheres-b-at-rest", REVERSED)
    assert found[2][:2] == ("wrong", "restitution_reversed")
    assert [found[n][0] for n in (3, 4, 5)] == ["carried"] * 3


def test_the_same_line_going_on_from_a_correct_one_is_correct() -> None:
    right = (
        REVERSED.replace("v_A - v_B = e u", "v_B - v_A = e u").replace("+ e u", "- e u").replace("(1 + e)", "(1 - e)")
    )
    found = lines("wjec-further-unit3-2019-june-q7-equal-spheres-b-at-rest", right)
    assert [found[n][0] for n in (1, 2, 3, 4, 5)] == ["correct"] * 5
