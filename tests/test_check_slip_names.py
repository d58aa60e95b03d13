"""Slips named as a teacher names them, in the forms students write them (issue #31): the
impact rule upside down, algebra (a sign or a factor lost in rearranging) against arithmetic
(a number worked wrongly), the kinetic energy's wrong formulas. Every number is worked by hand
from the problem files' givens (in the comments), never from derive's output."""

from __future__ import annotations

from support.checked import lines


def test_restitution_with_e_on_the_separations_side_is_restitution_reversed() -> None:
    # Byju's: 4 kg at 12 catches 8 kg at 4, e = 0.5: approach 12 - 4 = 8, separation 4.
    # Upside down: 0.5(v_B2 - v_A2) = 8, so v_B2 - v_A2 = 16 (carried); also as a ratio.
    work = "4(12) + 8(4) = 4 v_A2 + 8 v_B2\n0.5(v_B2 - v_A2) = 12 - 4\nv_B2 - v_A2 = 16\n"
    found = lines("byjus-4kg-ball-catches-8kg-ball", work)
    assert found[1][0] == "correct"
    assert found[2][:2] == ("wrong", "restitution_reversed")
    assert found[3][0] == "carried"
    found = lines("byjus-4kg-ball-catches-8kg-ball", "e = (12 - 4)/(v_B2 - v_A2)\n")
    assert found[1][:2] == ("wrong", "restitution_reversed")
    # AQA 2014 (symbolic): 2m at 2u hits m at rest, e = 2/3: (2/3)(v_B - v_A) = 2u, upside down
    found = lines("aqa-m3-2014-symbolic-2m-hits-m", "(2/3)(v_B2 - v_A2) = 2u\n")
    assert found[1][:2] == ("wrong", "restitution_reversed")
    # Edexcel M2 wall: 4 m/s into the wall, e = 0.4: the rebound is -1.6; 4/0.4 = 10 divides by e
    found = lines("edexcel-m2-ball-rebounds-from-wall", "v_A2 = 4/0.4 = 10\n")
    assert found[1][:2] == ("wrong", "restitution_reversed")
    # OCR M2 2006 (find e): 2 kg at 5 hits 1 kg at rest, then 2 and 6: e = (6 - 2)/5 = 0.8;
    # approach over separation, 5/(6 - 2) = 1.25, is the ratio upside down
    work = "2(5) + 0 = 2(2) + v_B2\nv_B2 = 6\ne = 5/(6 - 2) = 1.25\n"
    found = lines("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work)
    assert found[3][:2] == ("wrong", "restitution_reversed")


def test_a_term_moved_across_without_its_sign_changed_is_algebra() -> None:
    # OCR M2 2006: 2 kg at 5 hits 1 kg at rest, A after at 2: 10 = 4 + v_B2, so v_B2 = 6;
    # 10 + 4 = v_B2 moves the 4 across with its sign kept (algebra, not arithmetic), and
    # v_B2 = 14 is carried.
    work = "2(5) + 0 = 2(2) + v_B2\n10 = 4 + v_B2\n10 + 4 = v_B2\nv_B2 = 14\n"
    found = lines("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work)
    assert found[2][0] == "correct"
    assert found[3][:2] == ("wrong", "algebra")
    assert found[4][0] == "carried"
    # Beer & Johnston 13.13 (Mg): 10 = 20 v + 10.5, the 10.5 kept positive on the left
    work = "20(0.5) + 0 = 20 v_A2 + 35(0.3)\n10 = 20 v_A2 + 10.5\n10 + 10.5 = 20 v_A2\n"
    found = lines("beer-johnston-13-13-railroad-cars-find-e", work)
    assert found[3][:2] == ("wrong", "algebra")


def test_the_unknowns_coefficient_lost_in_rearranging_is_algebra() -> None:
    # Young & Freedman 8.96: 0.0400 kg at 0.200 m/s, 0.050 m/s after, red puck at rest, e = 1:
    # 0.008 = 0.002 + m_B v_B2; v_B2 = 0.250 (e = 1: 0.200 = v_B2 - 0.050), so m_B = 0.024.
    # 0.008 = 0.002 + 0.250 m_B is right; 0.006 = m_B drops m_B's coefficient 0.250 (algebra)
    work = "0.008 = 0.002 + 0.250 m_B\n0.006 = m_B\n"
    found = lines("young-freedman-8-96-pucks-find-mass", work)
    assert found[1][0] == "correct"
    assert found[2][:2] == ("wrong", "algebra")


def test_a_letter_lost_in_taking_a_factor_out_is_algebra_a_number_is_arithmetic() -> None:
    # Edexcel M2 2010: P (2m) at 2u, Q (m) at -u: 3u = 2 v_P + v_Q and v_Q - v_P = 3eu, so
    # 3u = 3 v_P + 3eu, u = v_P + eu and v_P = u - eu = u(1 - e). u(1 - e^2) has a letter too
    # many in one term (algebra); u(1 - 3e) has its letters right and a number wrong (arithmetic).
    base = "3u = 2 v_A2 + v_B2\nv_B2 - v_A2 = 3eu\n3u = 3 v_A2 + 3eu\nu = v_A2 + eu\n"
    found = lines("edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u", base + "v_A2 = u(1 - e^2)\n")
    assert found[4][0] == "correct"
    assert found[5][:2] == ("wrong", "algebra")
    found = lines("edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u", base + "v_A2 = u(1 - 3e)\n")
    assert found[5][:2] == ("wrong", "arithmetic")


def test_a_number_moved_across_with_its_sign_kept_unshown_is_algebra() -> None:
    # OCR M2 2006 again: 10 = 4 + v_B2 then v_B2 = 14 is 10 + 4: the 4 moved across with its
    # sign kept, though the line does not show it (most teachers of the corpus mark it algebra,
    # a sign lost in rearranging; one marked the sum). 10 - 4 = 5 is a number worked wrongly.
    work = "2(5) + 0 = 2(2) + v_B2\n10 = 4 + v_B2\nv_B2 = 14\n"
    found = lines("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work)
    assert found[3][:2] == ("wrong", "algebra")
    found = lines("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work.replace("= 14", "= 5"))
    assert found[3][:2] == ("wrong", "arithmetic")
    # AQA M3 2007: 0.3 kg at 3, 0.2 kg at 2 toward it, e = 0.8: 0.5 = 0.3 v_A + 0.2 v_B and
    # v_B = v_A + 4, so 0.5 = 0.5 v_A + 0.8 and 0.5 v_A = -0.3. Written 0.5 v_A = 1.3 (0.5 + 0.8:
    # the 0.8 moved with its sign kept), v_A = 2.6 carried.
    work = (
        "0.3(3) + 0.2(-2) = 0.3 v_A + 0.2 v_B\nv_B - v_A = 0.8(3 + 2) = 4\n0.5 = 0.3 v_A + 0.2(v_A + 4)\n"
        "0.5 = 0.5 v_A + 0.8\n0.5 v_A = 1.3\nv_A = 2.6\n"
    )
    found = lines("aqa-m3-2007-spheres-approach-head-on", work)
    assert [found[n][0] for n in (1, 2, 3, 4)] == ["correct"] * 4
    assert found[5][:2] == ("wrong", "algebra")
    assert found[6][0] == "carried"


def test_a_product_worked_wrongly_with_the_unknowns_term_kept_is_arithmetic() -> None:
    # OCR MEI 2021 (find e): A (2 kg) at 6, B (4 kg) leaves along the line at 2.5: 12 = 2 v_A + 10,
    # v_A = 1. Written 12 = 2 v_A + 8 (4 x 2.5 worked as 8), the 2 v_A kept as it was: a number
    # worked wrongly, though 12 = v_A + 10 (the 2 dropped) would give the same v_A = 2.
    work = "\\[ 2 \\times 6 + 4 \\times 0 = 2 v_{A} + 4 \\times 2.5 \\]\n\\[ 12 = 2 v_{A} + 8 \\]\n\\[ v_{A} = 2 \\]\n"
    found = lines("ocr-mei-fmm-2021-b-at-45deg-find-e", work)
    assert found[1][0] == "correct"
    assert found[2][:2] == ("wrong", "arithmetic")
    assert found[3][0] == "carried"


def test_kinetic_energy_after_as_e_times_the_energy_before_is_ke_formula() -> None:
    # Edexcel M2 wall: 2 kg at 4 m/s, e = 0.4: rebound 1.6 m/s, KE before ½(2)(16) = 16 J,
    # after ½(2)(1.6²) = 2.56 J; e x 16 = 6.4 J scales the energy by e, not e² (ke_formula),
    # and the loss 16 - 6.4 = 9.6 J is carried.
    work = "KE before = 0.5(2)(4)^2 = 16\nKE after = 0.4 x 16 = 6.4\nKE lost = 16 - 6.4 = 9.6\n"
    found = lines("edexcel-m2-ball-rebounds-from-wall", work)
    assert found[1][0] == "correct"
    assert found[2][:2] == ("wrong", "ke_formula")
    assert found[3][0] == "carried"


def test_one_bodys_kinetic_energy_for_both_is_ke_formula() -> None:
    # MSU: a 0.020 kg bullet at 300 m/s lodges in a 4.0 kg block: V = 6/4.02 = 1.4925 m/s,
    # KE after ½(4.02)(1.4925²) = 4.478 J; the block's mass alone, ½(4.0)(1.4925²) = 4.455 J
    work = "T_2 = 0.5(4.0)(1.4925)^2 = 4.455\n"
    found = lines("msu-lectureonline-bullet-lodges-in-block", work)
    assert found[1][:2] == ("wrong", "ke_formula")
    # AQA 2007 head-on (0.3 kg at 3, 0.2 kg at 2 toward it): KE before 1.35 + 0.4 = 1.75 J;
    # A's alone, 0.5(0.3)(3)^2 = 1.35, is one body's energy for the two
    found = lines("aqa-m3-2007-spheres-approach-head-on", "KE before = 0.5(0.3)(3)^2 = 1.35\n")
    assert found[1][:2] == ("wrong", "ke_formula")


def test_a_chains_energy_without_its_half_is_ke_formula_and_a_half_lost_cancelling_is_algebra() -> None:
    # OCR M2 2006 chain: 0.3 kg dropped from 2 m: ½(0.3) v1² = 0.3(9.8)(2), v1² = 39.2,
    # v1 = 6.26 m/s. 0.3 v1² (the ½ of the kinetic energy dropped) gives v1² = 19.6, 4.43.
    work = "0.3(9.8)(2) = 0.3 v1^2\nv1 = sqrt(19.6) = 4.43\n"
    found = lines("chain-ocr-m2-2006-drop-rebound", work)
    assert found[1][:2] == ("wrong", "ke_formula")
    assert found[2][0] == "carried"
    # the masses cancelled and the ½ lost with them: v1² = g h, no mass with the square
    work = "0.3(9.8)(2) = 0.5(0.3) v1^2\nv1^2 = 9.8(2) = 19.6\nv1 = 4.43\n"
    found = lines("chain-ocr-m2-2006-drop-rebound", work)
    assert found[1][0] == "correct"
    assert found[2][:2] == ("wrong", "algebra")
    assert found[3][0] == "carried"


def test_a_number_worked_wrongly_with_two_unknowns_kept_is_arithmetic() -> None:
    # Byju's: 4 kg at 12 catches 8 kg at 4: 4(12) + 8(4) = 48 + 32 = 80, not 90; the unknowns'
    # terms 4 v_A2 + 8 v_B2 as they were: arithmetic, on one line ("i.e.") or two
    for work in (
        "4(12) + 8(4) = 4 v_A2 + 8 v_B2, i.e. 90 = 4 v_A2 + 8 v_B2\n",
        "4(12) + 8(4) = 4 v_A2 + 8 v_B2\n90 = 4 v_A2 + 8 v_B2\n",
    ):
        found = lines("byjus-4kg-ball-catches-8kg-ball", work)
        assert max(found.items())[1][:2] == ("wrong", "arithmetic"), work


def test_a_value_put_in_with_its_sign_lost_in_a_lines_working_is_algebra() -> None:
    # OCR M2 2014: 2m at 4 meets 3m at 2 the other way, e = 0.4: 2 = 2a + 3b, b - a = 2.4, so
    # a = -1.04, b = 1.36: 3b = 2 - 2a = 2 + 2.08 = 4.08. 2 - 2.08 puts a in with its sign
    # lost (algebra); 2 + 2.08 = 4.8 is a sum worked wrongly (arithmetic).
    work = "v_A2 = -1.04\n3 v_B2 = 2 - 2 v_A2 = 2 - 2.08 = -0.08\n"
    found = lines("ocr-m2-2014-particles-2m-3m-ke-lost", work)
    assert found[1][0] == "correct"
    assert found[2][:2] == ("wrong", "algebra")
    work = "v_A2 = -1.04\n3 v_B2 = 2 - 2 v_A2 = 2 + 2.08 = 4.8\n"
    found = lines("ocr-m2-2014-particles-2m-3m-ke-lost", work)
    assert found[2][:2] == ("wrong", "arithmetic")


def test_kinetic_energy_lost_by_one_body_only_or_scaled_by_e_squared_is_ke_formula() -> None:
    # AQA 2007 head-on: 0.3 kg at 3, 0.2 kg at 2 toward it, e = 0.8: after -0.6 and 3.4;
    # KE 1.35 + 0.4 = 1.75 before, 0.054 + 1.156 = 1.21 after, 0.54 lost. A's loss alone,
    # 0.5(0.3)(3² - 0.6²) = 1.296, is one body's energy for the two.
    found = lines("aqa-m3-2007-spheres-approach-head-on", "KE lost = 0.5(0.3)(3^2 - 0.6^2) = 1.296\n")
    assert found[1][:2] == ("wrong", "ke_formula")
    # Byju's: 4 kg at 12, 8 kg at 4, e = 0.5: after 4 and 8; KE 288 + 64 = 352 before, 32 + 256
    # = 288 after. e² x 352 = 88 scales two bodies' energy as a wall's.
    found = lines("byjus-4kg-ball-catches-8kg-ball", "KE before = 288 + 64 = 352\nKE after = 0.25 x 352 = 88\n")
    assert found[1][0] == "correct"
    assert found[2][:2] == ("wrong", "ke_formula")


def test_a_walls_impulse_with_the_rebound_speed_as_the_velocity_is_b_sign() -> None:
    # Edexcel M2 wall: 2 kg at 4 m/s toward the wall, e = 0.4: rebound speed 0.4(4) = 1.6, the
    # velocity -1.6; I = 2(-1.6 - 4) = -11.2. I = m(v - u) = 2(1.6 - 4) = -4.8 puts the speed in
    # as the velocity: a velocity the wrong way (b_sign), and its size 4.8 is carried.
    work = "speed after: |v| = 0.4 x 4 = 1.6\nI = m(v - u) = 2(1.6 - 4) = -4.8\nmagnitude of impulse = 4.8 N s\n"
    found = lines("edexcel-m2-ball-rebounds-from-wall", work)
    assert found[1][0] == "correct"
    assert found[2][:2] == ("wrong", "b_sign")
    assert found[3][0] == "carried"
    work = (
        "The ball rebounds with speed $v = eu = 0.4(4) = 1.6$ m/s.\n\nImpulse $I = m(v - u) = 2(1.6 - 4) = -4.8$ N s\n"
    )
    found = lines("edexcel-m2-ball-rebounds-from-wall", work)
    assert found[3][:2] == ("wrong", "b_sign")
    # the velocity after written as +e u (the rule itself) stays restitution_reversed
    found = lines("edexcel-m2-ball-rebounds-from-wall", "v_A2 = 0.4(4) = 1.6\n")
    assert found[1][:2] == ("wrong", "restitution_reversed")


def test_a_value_solved_wrongly_that_happens_to_be_a_mistakes_is_algebra() -> None:
    # Edexcel M2 2010: u = v_P + eu (right) gives v_P = u(1 - e); u(1 + e) loses the sign of eu
    # moving it across. It is also what the impact rule reversed gives P, but this line does not
    # state the impact rule, and the line before it held: algebra.
    work = "3u = 2 v_A2 + v_B2\nv_B2 - v_A2 = 3eu\nu = v_A2 + eu\nv_A2 = u(1 + e)\n"
    found = lines("edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u", work)
    assert found[3][0] == "correct"
    assert found[4][:2] == ("wrong", "algebra")


def test_a_chains_e_is_its_one_coefficient_and_its_ratio_upside_down_is_restitution_reversed() -> None:
    # OCR M2 2006 chain: dropped from 2 m, v1 = sqrt(2(9.8)(2)) = 6.26; back up to 1.4 m, v2 =
    # sqrt(2(9.8)(1.4)) = 5.24; e = 5.24/6.26 = 0.837. The student's "e" is the chain's e_floor:
    # 6.26/5.24 = 1.19 is not a name of their own but e worked upside down.
    work = "v1 = 6.26\nv2 = 5.24\ne = 6.26/5.24 = 1.19\n"
    found = lines("chain-ocr-m2-2006-drop-rebound", work)
    assert found[1][0] == found[2][0] == "correct"
    assert found[3][:2] == ("wrong", "restitution_reversed")
    found = lines("chain-ocr-m2-2006-drop-rebound", "v1 = 6.26\nv2 = 5.24\ne = 5.24/6.26 = 0.837\n")
    assert found[3][0] == "correct"
    found = lines("chain-ocr-m2-2006-drop-rebound", "v1 = 6.26\nv2 = 5.24\ne = 5.24/6.26 = 0.873\n")
    assert found[3][:2] == ("wrong", "arithmetic")


def test_a_term_moved_across_and_summed_on_the_same_line_is_algebra() -> None:
    # A line that moves a term across with its sign kept and works the sum at once
    # (``12 v = 80 + 32 = 112``) shows the term moved: a teacher names it algebra, whatever the
    # sum that follows, in numbers or letters, the unknown's side first or last.
    # Byju's: 4 kg at 12 catches 8 kg at 4, e = 0.5: 80 = 4 v_A2 + 8 v_B2, v_B2 = v_A2 + 4,
    # 80 = 12 v_A2 + 32, so 12 v_A2 = 48, v_A2 = 4; 80 + 32 = 112 keeps the 32's sign (v_A2 = 28/3).
    head = "4(12) + 8(4) = 4 v_A2 + 8 v_B2\nv_B2 - v_A2 = 0.5(12 - 4)\n80 = 12 v_A2 + 32\n"
    found = lines("byjus-4kg-ball-catches-8kg-ball", head + "12 v_A2 = 80 + 32 = 112\nv_A2 = 112/12 = 9.33\n")
    assert found[3][0] == "correct"
    assert found[4][:2] == ("wrong", "algebra")
    assert found[5][0] == "carried"
    found = lines("byjus-4kg-ball-catches-8kg-ball", head + "v_A2 = (80 + 32)/12 = 9.33\n")
    assert found[4][:2] == ("wrong", "algebra")
    # OCR M2 2006: 2 kg at 5 hits 1 kg at rest, A after at 2: 10 = 4 + v_B2, so v_B2 = 6;
    # v_B2 = 10 + 4 = 14 moves the 4 with its sign kept (the unknown alone on the left)
    work = "2(5) + 0 = 2(2) + v_B2\nv_B2 = 10 + 4 = 14\n"
    found = lines("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work)
    assert found[2][:2] == ("wrong", "algebra")
    # AQA M3 2014 (letters): 2m at 2u hits m at rest, e = 2/3: 4u = 2 v_A2 + v_B2,
    # v_B2 = v_A2 + 4u/3, 4u = 3 v_A2 + 4u/3, so 3 v_A2 = 8u/3 (v_A2 = 8u/9);
    # 3 v_A2 = 4u + 4u/3 = 16u/3 keeps the 4u/3's sign (then v_A2 = 16u/9, carried)
    work = (
        "2m(2u) = 2m v_A2 + m v_B2\nv_B2 - v_A2 = (2/3)(2u)\n4u = 3 v_A2 + \\tfrac43 u\n"
        "3 v_A2 = 4u + \\tfrac43 u = \\tfrac{16}{3} u\nv_A2 = \\frac{16u}{9}\n"
    )
    found = lines("aqa-m3-2014-symbolic-2m-hits-m", work)
    assert found[3][0] == "correct"
    assert found[4][:2] == ("wrong", "algebra")
    assert found[5][0] == "carried"


def test_a_number_worked_wrongly_putting_numbers_into_a_law_in_letters_is_arithmetic() -> None:
    # A law in letters with an unknown found earlier (the line before has two unknowns), then
    # the numbers put in and one worked wrongly: arithmetic, with the earlier value put in.
    # Beer & Johnston 13.13 (Mg): 20(0.5) = 20 v_A2 + 35(0.3), v_A2 = -0.5/20 = -0.025;
    # 0.3 - (-0.025) = e(0.5 - 0): 0.325 = 0.5e, e = 0.65; 0.35 = 0.5e works 0.3 + 0.025 wrongly.
    work = (
        "20(0.5) + 35(0) = 20 v_A2 + 35(0.3)\nv_A2 = (10 - 10.5)/20 = -0.025\n"
        "v_B2 - v_A2 = e(v_A1 - v_B1)\n0.35 = 0.5 e\ne = 0.70\n"
    )
    found = lines("beer-johnston-13-13-railroad-cars-find-e", work)
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3
    assert found[4][:2] == ("wrong", "arithmetic")
    assert found[5][0] == "carried"
    # OCR M2 2011: A (m_A) at 3 meets B, 0.2 kg at 1.5, head on; after, A at 2 on, B at 2.9 back:
    # e = (2.9 - 2)/(3 + 1.5) = 0.2; momentum in letters, then 3 m_A - 0.3 = 2 m_A + 0.58 worked
    # with 0.2(2.9) = 0.058: m_A = 0.88 kg (true 3 m_A - 0.3 = 2 m_A + 0.58, m_A = 0.88; slip 0.358)
    work = (
        "e = (2.9 - 2)/(3 + 1.5) = 0.2\nm_A v_A1 + m_B v_B1 = m_A v_A2 + m_B v_B2\n"
        "3 m_A - 0.3 = 2 m_A + 0.058\nm_A = 0.358\n"
    )
    found = lines("ocr-m2-2011-spheres-find-e-and-mass", work)
    assert found[3][:2] == ("wrong", "arithmetic")
    assert found[4][0] == "carried"


def test_a_velocity_before_taken_the_wrong_way_in_the_approach_alone_is_b_sign() -> None:
    # The momentum right, then B's velocity before taken the other way in the restitution line
    # only (the approach added where it is a difference, or the other way round): b_sign, and
    # the lines worked from it carried (the momentum as it was, the approach as the student has it).
    # AQA M3 2007: 0.3 kg at 3 meets 0.2 kg at 2 head on, e = 0.8: 0.5 = 0.3 v_A2 + 0.2 v_B2,
    # approach 3 + 2 = 5, v_B2 - v_A2 = 4; with 3 - 2: v_B2 - v_A2 = 0.8, 0.5 = 0.5 v_A2 + 0.16,
    # v_A2 = 0.68.
    work = (
        "0.3(3) + 0.2(-2) = 0.3 v_A2 + 0.2 v_B2\nv_B2 - v_A2 = 0.8(3 - 2) = 0.8\n"
        "0.5 = 0.3 v_A2 + 0.2(v_A2 + 0.8)\nv_A2 = 0.34/0.5 = 0.68\n"
    )
    found = lines("aqa-m3-2007-spheres-approach-head-on", work)
    assert found[1][0] == "correct"
    assert found[2][:2] == ("wrong", "b_sign")
    assert found[3][0] == "carried"
    assert found[4][0] == "carried"
    # Byju's: 4 kg at 12 catches 8 kg at 4, e = 0.5: approach 12 - 4 = 8; 12 + 4 takes B's 4 the
    # other way: v_B2 - v_A2 = 8, 80 = 12 v_A2 + 64, v_A2 = 16/12 = 1.33 (true 4)
    work = "4(12) + 8(4) = 4 v_A2 + 8 v_B2\nv_B2 - v_A2 = 0.5(12 + 4)\n80 = 12 v_A2 + 64\nv_A2 = 1.33\n"
    found = lines("byjus-4kg-ball-catches-8kg-ball", work)
    assert found[2][:2] == ("wrong", "b_sign")
    assert found[3][0] == "carried"
    assert found[4][0] == "carried"


def test_a_velocity_taken_the_wrong_way_in_an_inverse_restitution_in_numbers_is_b_sign() -> None:
    # Find e, the velocities after in numbers: one velocity's sign lost in the separation (or the
    # approach) of the restitution line alone is b_sign, the e it gives carried.
    # AQA FM specimen: 0.8 kg and 0.4 kg meet head on, each at 6; A moves back at 1.2:
    # 4.8 - 2.4 = -0.96 + 0.4 v_B2, v_B2 = 3.36/0.4 = 8.4; e = (8.4 + 1.2)/(6 + 6) = 0.8;
    # 8.4 - 1.2 = 12e takes A's -1.2 as +1.2: e = 7.2/12 = 0.6.
    work = "0.8(6) + 0.4(-6) = 0.8(-1.2) + 0.4 v_B2\nv_B2 = 3.36/0.4 = 8.4\n8.4 - 1.2 = e(6 + 6)\ne = 7.2/12 = 0.6\n"
    found = lines("aqa-fm-specimen-discs-show-e-0p8", work)
    assert found[2][0] == "correct"
    assert found[3][:2] == ("wrong", "b_sign")
    assert found[4][0] == "carried"


def test_equations_subtracted_with_the_signs_the_wrong_way_is_algebra_not_b_sign() -> None:
    # The two laws written right, then subtracted with the signs the wrong way round: the line
    # holds in a world with A's velocity before reversed, but the student's own laws just written
    # do not; a teacher names the subtraction (algebra), not a velocity taken the wrong way.
    # AQA M3 2014 (letters): 2m at 2u hits m at rest, e = 2/3: (1) 4u = 2 v_A2 + v_B2,
    # (2) v_B2 - v_A2 = 4u/3; (1) - (2): 3 v_A2 = 4u - 4u/3 = 8u/3 (v_A2 = 8u/9); written
    # 3 v_A2 = 4u/3 - 4u, then v_A2 = -8u/9 (carried).
    work = (
        "2m(2u) = 2m v_A2 + m v_B2 \\Rightarrow 4u = 2 v_A2 + v_B2 ...(1)\n"
        "v_B2 - v_A2 = \\tfrac23 (2u) ...(2)\n"
        "(1) - (2): 3 v_A2 = \\tfrac43 u - 4u\nv_A2 = -\\tfrac89 u\n"
    )
    found = lines("aqa-m3-2014-symbolic-2m-hits-m", work)
    assert found[1][0] == "correct" and found[2][0] == "correct"
    assert found[3][:2] == ("wrong", "algebra")
    assert found[4][0] == "carried"


def test_dividing_through_with_one_term_left_undivided_is_algebra() -> None:
    # Dividing a relation through by the unknown's coefficient and leaving one term as it was
    # (``2v = u + eu`` -> ``v = u/2 + eu``) is algebra (a term not divided), not a number worked
    # wrongly; the same for multiplying through.
    # WJEC 2019: equal spheres, A at u, B at rest: u = v_A + v_B, v_B - v_A = eu; added:
    # 2 v_B = u + eu, v_B = (1 + e)u/2; written v_B = u/2 + eu.
    work = "u = v_A + v_B\nv_B - v_A = eu\n2v_B = u + eu\nv_B = u/2 + eu\n"
    found = lines("wjec-further-unit3-2019-june-q7-equal-spheres-b-at-rest", work)
    assert found[3][0] == "correct"
    assert found[4][:2] == ("wrong", "algebra")
    # CIE 2014 Nov: 2m at 4u meets m at 3u: 5u = 2 v_A2 + v_B2, v_B2 - v_A2 = 7eu, so
    # 3 v_A2 = 5u - 7eu and v_A2 = (5 - 7e)u/3; written v_A2 = 5u/3 - 7eu (the 7eu not divided)
    work = "8u - 3u = 2 v_A2 + v_B2\nv_B2 - v_A2 = 7eu\n3 v_A2 = 5u - 7eu\nv_A2 = 5u/3 - 7eu\n"
    found = lines("cie-9231-p2-2014-november-q1-2m-at-4u-meets-m-at-3u-a-reverses", work)
    assert found[3][0] == "correct"
    assert found[4][:2] == ("wrong", "algebra")


def test_a_given_copied_with_a_digit_changed_into_working_in_numbers_is_copied_wrong() -> None:
    # A line of numbers (no unknown) whose working writes a given with one digit changed, and
    # that is right with the given put back: the given is copied wrongly (not a sum worked
    # wrongly), whatever the size of the given.
    # Byju's: 4 kg at 12 catches 8 kg at 4, e = 0.5: the approach is 12 - 4 = 8; 12 - 5 = 7
    # copies B's 4 as 5; then v_B2 - v_A2 = 0.5(7) = 3.5 is carried.
    work = "speed of approach = 12 - 5 = 7\nv_B2 - v_A2 = 0.5 \\times 7 = 3.5\n"
    found = lines("byjus-4kg-ball-catches-8kg-ball", work)
    assert found[1][:2] == ("wrong", "copied_wrong")
    assert found[2][0] == "carried"
    # KE before = ½(4)(12²) + ½(8)(4²) = 288 + 64 = 352 J; with A's 12 copied as 13:
    # ½(4)(13²) + ½(8)(4²) = 338 + 64 = 402
    work = "KE before = \\tfrac12(4)(13^2) + \\tfrac12(8)(4^2) = 402\n"
    found = lines("byjus-4kg-ball-catches-8kg-ball", work)
    assert found[1][:2] == ("wrong", "copied_wrong")


def test_the_unknowns_coefficient_used_the_wrong_way_is_arithmetic() -> None:
    # Solving c x = k for x the wrong way (multiplied by c, or k/c turned over) is a division of
    # numbers worked wrongly, nothing moved across: arithmetic, as the corpus's teachers mark
    # ``sin²α = 0.4 × 7/16`` from ``(7/16) sin²α = 0.4`` and ``v_A = 0.025`` from ``20 v_A = −0.5``.
    # OCR M2 2006 (find e): 2 kg at 5 hits 1 kg at rest, A then at 2: 10 = 4 + v_B2, v_B2 = 6;
    # 6 - 2 = e(5 - 0): 4 = 5e, e = 4/5; e = 5/4 divides the wrong way.
    work = "2(5) + 0 = 2(2) + v_B2\nv_B2 = 6\n6 - 2 = e(5 - 0)\n4 = 5e\ne = 5/4\n"
    found = lines("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work)
    assert found[4][0] == "correct"
    assert found[5][:2] == ("wrong", "arithmetic")
    # AQA M3 2007: 0.3 kg at 3 meets 0.2 kg at 2 head on, e = 0.8: 0.5 = 0.3 v_A2 + 0.2 v_B2,
    # v_B2 = v_A2 + 4: 0.5 = 0.5 v_A2 + 0.8, 0.5 v_A2 = -0.3, v_A2 = -0.6; v_A2 = -0.15
    # multiplies by 0.5 instead of dividing.
    work = (
        "0.3(3) + 0.2(-2) = 0.3 v_A2 + 0.2 v_B2\nv_B2 - v_A2 = 0.8(3 + 2)\n"
        "0.5 = 0.5 v_A2 + 0.8\n0.5 v_A2 = -0.3\nv_A2 = -0.15\n"
    )
    found = lines("aqa-m3-2007-spheres-approach-head-on", work)
    assert found[4][0] == "correct"
    assert found[5][:2] == ("wrong", "arithmetic")


def test_a_bracket_with_a_number_in_it_not_multiplied_out_is_algebra() -> None:
    # Expanding k(x + n) as k x + n (the number in the bracket not multiplied) is algebra.
    # AQA M3 2007 (as above): 0.5 = 0.3 v_A2 + 0.2(v_A2 + 4) = 0.5 v_A2 + 0.8;
    # written 0.5 = 0.5 v_A2 + 4, then v_A2 = -7 (carried).
    work = (
        "0.3(3) + 0.2(-2) = 0.3 v_A2 + 0.2 v_B2\nv_B2 = v_A2 + 4\n"
        "0.5 = 0.3 v_A2 + 0.2(v_A2 + 4)\n0.5 = 0.5 v_A2 + 4\nv_A2 = -7\n"
    )
    found = lines("aqa-m3-2007-spheres-approach-head-on", work)
    assert found[3][0] == "correct"
    assert found[4][:2] == ("wrong", "algebra")
    assert found[5][0] == "carried"


def test_dividing_through_by_a_letter_with_one_term_missed_is_algebra() -> None:
    # Dividing a relation through by a mass in letters and leaving it on one term (or taking
    # another letter off with it) is algebra, in one unknown or two.
    # AQA M3 2014: 2m at 2u hits m at rest: 4mu = 2m v_A2 + m v_B2, so 4u = 2 v_A2 + v_B2;
    # 4u = 2 v_A2 + m v_B2 leaves the m on B's term.
    work = "2m(2u) = 2m v_A2 + m v_B2\n4u = 2 v_A2 + m v_B2\n"
    found = lines("aqa-m3-2014-symbolic-2m-hits-m", work)
    assert found[1][0] == "correct"
    assert found[2][:2] == ("wrong", "algebra")
    # WJEC 2019: equal spheres (m), A at u, B at rest: mu = m v_A + m v_B; u = v_A + m v_B
    work = "mu = m v_A + m v_B\nu = v_A + m v_B\n"
    found = lines("wjec-further-unit3-2019-june-q7-equal-spheres-b-at-rest", work)
    assert found[2][:2] == ("wrong", "algebra")


def test_a_total_of_the_data_copied_with_its_digits_moved_is_copied_wrong() -> None:
    # A sum of two masses (or a product of the data) written in working with its digits in
    # another order: the number is copied wrongly, not worked wrongly.
    # OpenStax 8 (train cars couple): 150000 kg at 0.300 and 110000 kg at -0.120 m/s:
    # V = (45000 - 13200)/(150000 + 110000) = 31800/260000 = 0.122; 206000 for 260000 gives 0.154.
    work = "V = \\frac{m_A v_A1 + m_B v_B1}{m_A + m_B} = \\frac{45000 - 13200}{206000} = 0.154\n"
    found = lines("openstax-cp-8-train-cars-couple", work)
    assert found[1][:2] == ("wrong", "copied_wrong")


def test_a_chain_rule_of_motion_with_a_terms_2_lost_is_algebra() -> None:
    # OCR M2 2007 chain: thrown down at 21 m/s from 40 m, g = 9.8: v1^2 = 21^2 + 2(9.8)(40) =
    # 441 + 784 = 1225. The rule written v^2 = u^2 + gh gives 441 + 392 = 833 (the 2 of 2gh lost:
    # a slip in the rule), and v1 = sqrt(833) = 28.86 is carried from it.
    work = "down positive\n\nv1^2 = u^2 + gh = 21^2 + 9.8(40) = 833\nv1 = 28.86\n"
    found = lines("chain-ocr-m2-2007-rebounds-to-start", work)
    assert found[3][:2] == ("wrong", "algebra")
    assert found[4][0] == "carried"


def test_a_chain_speed_put_in_without_its_square_is_arithmetic() -> None:
    # OCR M2 2015 chain: 5 m/s down from 1.6 m, e = 0.7, g = 9.8: v_1^2 = 25 + 31.36 = 56.36,
    # v_1 = 7.507, v_2 = 0.7(7.507) = 5.255, and h_2 = 5.255^2/19.6 = 1.409. Put in as 5.255
    # (the square left off) it is 5.255/19.6 = 0.268: a number worked wrongly.
    work = (
        "down positive\n\nv_1^2 = 5^2 + 2(9.8)(1.6) = 56.36\nv_1 = 7.507\nv_2 = 0.7(7.507) = 5.255\n"
        "h_2 = v_2^2/(2g) = 5.255/(2(9.8)) = 0.268\n"
    )
    found = lines("chain-ocr-m2-2015-thrown-down-bounce", work)
    assert [found[n][0] for n in (3, 4, 5)] == ["correct"] * 3
    assert found[6][:2] == ("wrong", "arithmetic")


def test_a_chain_sum_of_numbers_worked_wrongly_after_its_rule_is_arithmetic() -> None:
    # OCR M2 2015 chain: 5 m/s down from 1.6 m, g = 9.8: v_1^2 = 25 + 2(9.8)(1.6) = 25 + 31.36.
    # Written 25 + 13.36 = 38.36 (a number worked wrongly, the rule and the numbers put in right),
    # then v_1 = sqrt(38.36) = 6.19 carried. The u and h declared are the student's own.
    work = (
        "down = +ve.   u = 5 m/s, h = 1.6 m, g = 9.8\n\n"
        "v_1^2 = u^2 + 2gh = 5^2 + 2(9.8)(1.6) = 25 + 13.36 = 38.36\nv_1 = 6.19\n"
    )
    found = lines("chain-ocr-m2-2015-thrown-down-bounce", work)
    assert found[3][:2] == ("wrong", "arithmetic")
    assert found[4][0] == "carried"


def test_a_given_velocity_put_in_with_its_sign_lost_is_b_sign() -> None:
    # AQA FM specimen: A 0.8 kg at 6, B 0.4 kg at 6 toward A, A comes back at 1.2:
    # 4.8 - 2.4 = -0.96 + 0.4 v_B, v_B = 8.4, e = (8.4 - (-1.2))/(6 - (-6)) = 0.8. A's -1.2 put
    # in as +1.2 in the separation, (8.4 - 1.2)/12 = 0.6: a velocity the wrong way, carried on.
    work = (
        "0.8(6) + 0.4(-6) = 0.8(-1.2) + 0.4 v_B\nv_B = 8.4\n"
        "e = (v_B - v_A)/(u_A - u_B) = (8.4 - 1.2)/(6 + 6)\ne = 0.6\n"
    )
    found = lines("aqa-fm-specimen-discs-show-e-0p8", work)
    assert found[3][:2] == ("wrong", "b_sign")
    assert found[4][0] == "carried"


def test_bs_component_before_worked_with_its_sign_lost_is_b_sign() -> None:
    # Notes 4.C.11: B at 15 m/s, at 142.4 deg to n: its n component is 15 cos 142.4 = -11.88
    # (B moves against n). Written +11.88 it is B's velocity the wrong way; A's 5 cos 142.4 =
    # -3.96 written 3.96 is no velocity of the problem (A's is +3.96): an arithmetic slip.
    found = lines("notes-4c11-two-spheres", "B before, along n: 15 cos 142.4° = 11.88\n")
    assert found[1][:2] == ("wrong", "b_sign")
    found = lines("notes-4c11-two-spheres", "5 cos 142.4° = 3.96\n")
    assert found[1][:2] == ("wrong", "arithmetic")


def test_e_upside_down_after_an_earlier_slip_is_restitution_reversed_on_the_carried_values() -> None:
    # OCR M2 2006 (find e): 2 kg at 5 hits 1 kg at rest, A goes on at 2: 10 = 4 + v_B2, v_B2 = 6,
    # e = (6 - 2)/5 = 0.8. Written v_B2 = 5 (a number worked wrongly), then e as approach over
    # separation with that 5: 5/(5 - 2) = 1.67, the ratio upside down on the student's values
    # (right side up it would be 3/5 = 0.6, carried).
    work = "2(5) + 1(0) = 2(2) + 1 v_B2\nv_B2 = 5\ne = 5/(5 - 2) = 1.67\n"
    found = lines("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work)
    assert found[2][:2] == ("wrong", "arithmetic")
    assert found[3][:2] == ("wrong", "restitution_reversed")
    found = lines(
        "ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work.replace("e = 5/(5 - 2) = 1.67", "e = 3/5 = 0.6")
    )
    assert found[3][0] == "carried"


def test_weights_as_masses_in_a_result_after_an_earlier_slip_is_weight_as_mass() -> None:
    # Two cars (M. Casco): 4500 lb at 3 ft/s, 3000 lb at 6 ft/s toward it, lock together;
    # g = 32.2: masses 139.75 and 93.17 slug. B's sign lost in the momentum: (419.25 + 559.0)/232.92
    # = 4.2 ft/s (carried). The energy after with the weights as masses on that 4.2:
    # ½(7500)(4.2²) = 66150: the weights' mistake made afresh on the student's own velocity.
    work = "139.75(3) + 93.17(6) = 232.92 V\nV = 4.2\nKE after = 1/2 (7500)(4.2)^2 = 66150\n"
    found = lines("mcasco-two-cars-no-bounce", work)
    assert found[1][:2] == ("wrong", "b_sign")
    assert found[2][0] == "carried"
    assert found[3][:2] == ("wrong", "weight_as_mass")


def test_a_two_figure_number_that_is_not_the_value_rounded_is_arithmetic_not_rounded_too_early() -> None:
    # OCR M2 2006 (find e): 2(5) + 1(0) = 2(2) + v_B2, so 10 = 4 + v_B2. Written 9.8 = 4 + v_B2:
    # 9.8 has two figures, but 10 rounded to two figures is 10, not 9.8: a number worked wrongly,
    # and v_B2 = 5.8 is carried from it.
    work = "2(5) + 1(0) = 2(2) + v_B2\n9.8 = 4 + v_B2\nv_B2 = 5.8\n"
    found = lines("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work)
    assert found[2][:2] == ("wrong", "arithmetic")
    assert found[3][0] == "carried"


def test_a_sign_lost_inside_a_formula_is_algebra() -> None:
    # Edexcel M4 (identical spheres, A at 30 deg to the line of centres, B at rest): along the
    # line A keeps (sqrt3/4) u (1 - e), across it u/2, so tan(beta) = 2/(sqrt3 (1 - e)) and the
    # deflection theta = beta - 30 has tan(theta) = (tan beta - tan 30)/(1 + tan beta tan 30).
    # Written with 1 - tan beta tan 30 below: one sign inside the formula lost (algebra). With
    # the denominator squared as well, no one sign puts it right: no name.
    work = (
        "Along the line of centres after: v_1 = (sqrt(3)/4) u (1 - e); across it A keeps u/2.\n\n"
        "tan(beta) = (u/2)/v_1 = 2/(sqrt(3)(1 - e))\n\nA is deflected through theta = beta - 30°\n\n"
        "tan(theta) = (tan(beta) - tan(30°))/(1 - tan(beta) tan(30°))\n"
    )
    problem = "edexcel-m4-undated-q3-deflected-through-theta-line-at-30deg"
    found = lines(problem, work)
    assert [found[n][0] for n in (1, 3, 5)] == ["correct"] * 3
    assert found[7][:2] == ("wrong", "algebra")
    found = lines(problem, work.replace("(1 - tan(beta) tan(30°))", "(1 - tan(beta) tan(30°))^2"))
    assert found[7][:2] == ("wrong", "")


def test_a_chain_line_halved_but_for_one_term_is_algebra() -> None:
    # Edexcel M2 three particles (equal masses, A at 7 hits B, B hits C, C leaves at 4): after the
    # first impact 2 v2 = 7 + 7e, v2 = 7(1 + e)/2; after the second 2 w2 = v2 + e v2, so
    # w2 = v2(1 + e)/2. Written w2 = v2/2 + e v2, the e v2 not halved: a slip in rearranging.
    work = (
        "all masses m, -> positive\nA hits B:  A 7 -> , B at rest. After: A v1, B v2\n"
        "v1 + v2 = 7\nv2 - v1 = 7e\n2 v2 = 7 + 7e\nv2 = 7/2 + 7e/2\n"
        "B hits C:  B at v2, C at rest. After: B w1, C w2\nw1 + w2 = v2\nw2 - w1 = e v2\n"
        "2 w2 = v2 + e v2\nw2 = v2/2 + e v2\n"
    )
    found = lines("chain-edexcel-m2-three-particles", work)
    assert all(found[n][0] == "correct" for n in (3, 4, 5, 6, 8, 9, 10))
    assert found[11][:2] == ("wrong", "algebra")
