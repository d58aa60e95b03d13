"""Two right relations combined with a sign lost, the result written with a bracket taken out
(``2v_A = u(1 + e)`` from ``v_A + v_B = u`` and ``v_B − v_A = eu``): ``algebra``, as when it is
written ``u + eu``, not the impact rule reversed, which the student's own right restitution
line denies. Values by hand."""

from __future__ import annotations

from support.checked import worst_lines

#: WJEC 2019: equal spheres, A at u hits B at rest: v_A + v_B = u, v_B - v_A = eu, so
#: (1) - (2) is 2v_A = u - eu = u(1 - e), v_A = u(1 - e)/2, v_B = u(1 + e)/2. With the sign
#: lost: v_A = u(1 + e)/2, then v_B = u - v_A = u(1 - e)/2 (carried).
EQUAL = "wjec-further-unit3-2019-june-q7-equal-spheres-b-at-rest"


def test_a_sign_lost_combining_two_right_relations_with_a_bracket_taken_out_is_algebra() -> None:
    work = "v_A + v_B = u\nv_B - v_A = eu\n(1) - (2): 2v_A = u(1 + e)\nv_A = u(1 + e)/2\nv_B = u - v_A = u(1 - e)/2\n"
    found = worst_lines(EQUAL, work)
    assert found[1][0] == found[2][0] == "correct"
    assert found[3] == ("wrong", "algebra")
    assert found[4][0] == found[5][0] == "carried"
