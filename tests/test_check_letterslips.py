"""A slip in letters named as a teacher names it: a term of a squared bracket lost or changed
in multiplying it out is algebra; like terms collected, or a bracket multiplied by a number,
with a number wrong (the letters kept) is arithmetic. Every value is worked by hand."""

from __future__ import annotations

from support.checked import lines, worst_lines

#: 2m at 5u hits 3m at rest (Edexcel M2 2004): 10u = 2v_A + 3v_B, v_B - v_A = 5eu, so
#: 5v_B = 10u + 10eu, v_B = 2u(1 + e), v_A = 2u(1 + e) - 5eu = 2u - 3eu = u(2 - 3e).
#: KE after = ½(2m)u²(2 - 3e)² + ½(3m)4u²(1 + e)² = mu²[(2 - 3e)² + 6(1 + e)²]
#: = mu²[4 - 12e + 9e² + 6 + 12e + 6e²] = mu²(10 + 15e²).
HITS = "edexcel-m2-2004-june-q5-2m-at-5u-hits-3m"
START = "2m(5u) = 2m v_A2 + 3m v_B2\nv_B2 - v_A2 = 5eu\nv_B2 = 2u(1 + e)\n"
KE_AFTER = "KE after = 1/2 (2m) u^2 (2 - 3e)^2 + 1/2 (3m) 4u^2 (1 + e)^2\n  = m u^2 [(2 - 3e)^2 + 6(1 + e)^2]\n"


def test_a_squared_bracket_in_letters_multiplied_out_with_a_term_wrong_is_algebra() -> None:
    # (2 - 3e)^2 with -6e for -12e (the middle term's 2 lost): algebra, and the sum from it carried
    work = KE_AFTER + "  = m u^2 [4 - 6e + 9e^2 + 6 + 12e + 6e^2]\n  = m u^2 (10 + 6e + 15e^2)\n"
    found = lines(HITS, work)
    assert found[1][0] == found[2][0] == "correct"
    assert found[3][:2] == ("wrong", "algebra")
    assert found[4][0] == "carried"
    # (a + b)^2 as a^2 + b^2, on one line: the square's cross term lost
    found = worst_lines(HITS, "T_2 = m u^2 ((2 - 3e)^2 + 6(1 + e)^2) = m u^2 (4 + 9e^2 + 6 + 12e + 6e^2)\n")
    assert found[1] == ("wrong", "algebra")


def test_like_terms_in_letters_collected_with_a_number_wrong_are_arithmetic() -> None:
    # 2u + 2ue - 5ue is u(2 - 3e); u(2 - 4e) is 2 - 5 worked as -4: arithmetic, as teachers mark it
    # (u(2 - 7e), the +2ue taken as -2ue, is a sign lost: algebra, tests/test_check_term_signs.py)
    found = worst_lines(HITS, START + "v_A2 = 2u + 2ue - 5ue = u(2 - 4e)\n")
    assert found[3][0] == "correct"
    assert found[4] == ("wrong", "arithmetic")


def test_a_number_in_letters_worked_wrongly_is_arithmetic() -> None:
    # 10u(1 + e)/5 written 3u(1 + e): the letters as they were, 10/5 worked as 3
    found = worst_lines(HITS, "10u = 2v_A2 + 3v_B2\n5v_B2 = 10u + 10eu\nv_B2 = 10u(1 + e)/5 = 3u(1 + e)\n")
    assert found[2][0] == "correct"
    assert found[3] == ("wrong", "arithmetic")


#: m at u hits 9m at rest, half the kinetic energy lost (CIE 2014): u = v_A + 9v_B, v_B - v_A = eu,
#: so v_A = u(1 - 9e)/10, v_B = u(1 + e)/10; the energy after times 200/(m u^2):
#: (1 - 9e)^2 + 9(1 + e)^2 = 50, i.e. 1 - 18e + 81e^2 + 9 + 18e + 9e^2 = 50, 90e^2 = 40, e = 2/3.
KE = "cie-9231-p2-2014-june-q3-m-hits-9m-half-ke-lost"
KE_START = "u = v_A2 + 9v_B2\nv_B2 - v_A2 = eu\nv_A2 = u(1 - 9e)/10\nv_B2 = u(1 + e)/10\n(1 - 9e)^2 + 9(1 + e)^2 = 50\n"


def test_a_power_of_the_unknown_expanded_without_its_square_is_algebra() -> None:
    # (1 - 9e)^2 expanded with 9e^2 for 81e^2 (the 9 not squared): a term's factor lost, algebra
    found = lines(KE, KE_START + "1 - 18e + 9e^2 + 9 + 18e + 9e^2 = 50\n")
    assert found[5][0] == "correct"
    assert found[6][:2] == ("wrong", "algebra")


def test_the_number_of_an_expanded_relation_worked_wrongly_is_arithmetic() -> None:
    # the terms in e right, 50 written 60: a number worked wrongly; then 50 - 10 as 30; and like
    # terms added wrongly (81e^2 + 9e^2 as 80e^2) with no square multiplied out: arithmetic
    found = lines(KE, KE_START + "1 - 18e + 81e^2 + 9 + 18e + 9e^2 = 60\n")
    assert found[6][:2] == ("wrong", "arithmetic")
    found = lines(KE, KE_START + "90e^2 + 10 = 50\n90e^2 = 30\n")
    assert found[7][:2] == ("wrong", "arithmetic")
    found = lines(KE, KE_START + "1 - 18e + 81e^2 + 9 + 18e + 9e^2 = 50\n80e^2 + 10 = 50\n")
    assert found[6][0] == "correct"
    assert found[7][:2] == ("wrong", "arithmetic")


def test_a_kinetic_energy_by_the_wrong_formula_after_a_slip_is_ke_formula_not_a_rule() -> None:
    # AQA M3 2007: 0.3 kg at 3 meets 0.2 kg at -2, e = 0.8. The rule reversed (v_A - v_B = 4)
    # gives v_B = -1.4, v_A = 2.6; then 1/2 m (u - v)^2 for each: 0.15(0.4)^2 + 0.1(0.6)^2 =
    # 0.024 + 0.036 = 0.06 (the energy lost in that world is 1.75 - 1.21 = 0.54): a formula
    # slip, never an impact rule's mistake, with its value on the lines below it
    work = (
        "0.3(3) + 0.2(-2) = 0.3 v_A2 + 0.2 v_B2\nv_A2 - v_B2 = 0.8(3 + 2)\nv_B2 = -1.4, v_A2 = 2.6\n"
        "KE lost = 1/2(0.3)(3 - 2.6)^2 + 1/2(0.2)(-2 + 1.4)^2\n  = 0.024 + 0.036\n  = 0.06 J\n"
    )
    found = lines("aqa-m3-2007-spheres-approach-head-on", work)
    assert found[2][:2] == ("wrong", "restitution_reversed")
    assert found[4][:2] == ("wrong", "ke_formula")
    assert found[5][0] == found[6][0] == "carried"
