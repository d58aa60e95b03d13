"""A relation ``k x = E`` (the unknown alone on its side, k a whole number) followed by ``x = E``,
the division by k not done, is ``arithmetic``, as teachers mark it, in a single impact and in a
chain; a ½ dropped or one term left undivided stays ``algebra``. Values by hand."""

from __future__ import annotations

from support.checked import worst_lines

#: WJEC 2019: equal spheres, A at u hits B at rest: v_A + v_B = u, v_B - v_A = eu; adding,
#: 2v_B = u + eu, v_B = u(1 + e)/2 (not u + eu).
EQUAL = "wjec-further-unit3-2019-june-q7-equal-spheres-b-at-rest"
#: Three equal particles, A at 7 m/s hits B at rest: x + y = 7, y - x = 7e, so 2y = 7 + 7e and
#: y = (7 + 7e)/2 = 3.5 + 3.5e (not 7 + 7e; 3.5 + 7e leaves one term undivided).
CHAIN = "chain-edexcel-m2-three-particles"


def test_a_whole_number_coefficient_not_divided_out_is_arithmetic() -> None:
    found = worst_lines(EQUAL, "v_A + v_B = u\nv_B - v_A = eu\n2v_B = u + eu\nv_B = u + eu\n")
    assert found[3][0] == "correct"
    assert found[4] == ("wrong", "arithmetic")


def test_in_a_chain_the_other_side_not_divided_is_arithmetic_and_one_term_is_algebra() -> None:
    found = worst_lines(CHAIN, "A hits B: x + y = 7 and y - x = 7e\nadding, 2y = 7 + 7e\ny = 7 + 7e\n")
    assert found[2][0] == "correct"
    assert found[3] == ("wrong", "arithmetic")
    found = worst_lines(CHAIN, "A hits B: x + y = 7 and y - x = 7e\nadding, 2y = 7 + 7e\ny = 3.5 + 7e\n")
    assert found[3] == ("wrong", "algebra")
