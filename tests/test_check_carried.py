"""After a student's first slip, what each later line is (issue #31): a line whose values
depend on a slipped value is carried even when its own arithmetic is right; a line right
given two earlier slips is carried, not a further slip; a number near the value but from a
wrong formula is not accepted when enough figures are written to tell them apart. Every
number here is worked by hand from the problem files' givens (in the comments)."""

from __future__ import annotations

from support.checked import lines


def test_whole_numbers_from_wrong_lines_make_a_line_of_arithmetic_carried() -> None:
    # Hibbeler 15-58: W_A = 15 lb at 19.657 ft/s, W_B = 10 lb at rest, e = 0.3; g cancels in
    # the momentum, so 15(19.657) = 294.855 = 15 v_A2 + 10 v_B2 and v_B2 - v_A2 = 5.8971 give
    # v_A2 = 9.4354, v_B2 = 15.3325 with the weights too. The energies with the weights as
    # masses: 7.5(19.657^2) = 2898; 7.5(9.4354^2) + 5(15.3325^2) = 667.7 + 1175.4 = 1843;
    # the difference of those two numbers is right as arithmetic, but carries the slip.
    work = (
        "KE before = 0.5(15)(19.657)^2 = 2898\n"
        "KE after = 0.5(15)(9.435)^2 + 0.5(10)(15.33)^2 = 1843\n"
        "2898 - 1843 = 1055 ft lb lost\n"
    )
    found = lines("hibbeler-15-58-suitcases", work)
    assert found[1][:2] == ("wrong", "weight_as_mass")
    assert found[3][0] == "carried"


def test_a_number_near_the_loss_from_a_wrong_formula_is_not_accepted_and_its_working_is_carried() -> None:
    # OpenStax 8-5 goalie: 0.150 kg at 35.0 m/s caught by 70.0 kg at rest: v = 5.25/70.15
    # = 0.074840; T_1 = 0.075(1225) = 91.875, T_2 = 35.075(0.07484^2) = 0.19645, lost 91.6785.
    # ½m(u − v)² for the puck alone: 0.075(35.0 - 0.0748)^2 = 0.075(1219.77) = 91.48: 0.2 %
    # from the loss, but 0.0748 moves it by 0.0005 only: a different formula's value.
    work = (
        "0.150(35.0) = (0.150 + 70.0) v_B2\n"
        "v_B2 = 0.0748\n"
        "KE lost = 1/2 (0.150)(35.0 - 0.0748)^2\n"
        "        = 0.075 x 1219.77\n"
        "        = 91.48 J\n"
    )
    found = lines("openstax-cp-8-5-goalie-catches-puck", work)
    assert found[1][0] == found[2][0] == "correct"
    assert found[3][:2] == ("wrong", "ke_formula")
    assert found[4][0] == found[5][0] == "carried"


def test_a_line_right_given_both_earlier_slips_is_carried() -> None:
    # Hibbeler 15-58 (weights 15 and 10 lb, e = 0.3, 19.657 ft/s): the masses exchanged in
    # the momentum, 10 v_A2 + 15 v_B2 = 294.855, with v_B2 - v_A2 = 5.8971: 25 v_A2 = 206.40,
    # v_A2 = 8.256, v_B2 = 14.153. Then the weights as masses: T_1 = 7.5(19.657^2) = 2898 (a
    # further slip) and T_2 = 7.5(8.256^2) + 5(14.153^2) = 511.2 + 1001.5 = 1513: the weights
    # as masses made again (worked afresh from the weights, as a teacher marks it: corpus
    # y12), with the velocities right given the first slip; 2898 - 1513 = 1385 carried.
    work = (
        "15(19.657) = 10 v_A2 + 15 v_B2\n"
        "v_B2 - v_A2 = 0.3(19.657)\n"
        "25 v_A2 = 294.855 - 88.457 = 206.398\n"
        "v_A2 = 8.256\n"
        "v_B2 = 8.256 + 5.897 = 14.153\n"
        "T_1 = 0.5(15)(19.657)^2 = 2898\n"
        "T_2 = 0.5(15)(8.256)^2 + 0.5(10)(14.153)^2 = 1513\n"
        "2898 - 1513 = 1385\n"
    )
    found = lines("hibbeler-15-58-suitcases", work)
    assert found[1][:2] == ("wrong", "masses_swapped")
    assert found[2][0] == "correct"
    assert all(found[n][0] == "carried" for n in (3, 4, 5)), found
    assert found[6][:2] == ("wrong", "weight_as_mass")
    assert found[7] == ("wrong", "weight_as_mass", True), found
    assert found[8][0] == "carried", found


def test_a_sum_worked_wrongly_in_a_chain_stage_is_named_arithmetic() -> None:
    # OCR M2 2015 chain (thrown down at 5 m/s from 1.6 m, e = 0.7, g = 9.8): v_1^2 = 25 +
    # 31.36 = 56.36, written 65.36 (digits swapped): an arithmetic slip, named so; then
    # v_1 = sqrt(65.36) = 8.085 and v_2 = 0.7(8.08) = 5.66 are right given it.
    work = "v_1^2 = 5^2 + 2(9.8)(1.6) = 25 + 31.36 = 65.36\nv_1 = 8.08\nv_2 = 0.7(8.08) = 5.66\n"
    found = lines("chain-ocr-m2-2015-thrown-down-bounce", work)
    assert found[1][:2] == ("wrong", "arithmetic")
    assert found[2][0] == found[3][0] == "carried"


def test_sin_and_cos_swapped_on_one_body_only_carries_through_the_equations() -> None:
    # Notes 4.C.11 (20 kg at 5 m/s, 5 kg at 15 m/s, each at 37.6 deg to n, e = 0.6): A's
    # components swapped (5 sin 37.6 = 3.05 along n; the t one the same slip again), B's right
    # (-15 cos 37.6 = -11.9). Momentum 61.0 - 59.5 = 1.5 = 20 v_A2n + 5 v_B2n; restitution
    # v_B2n - v_A2n = 0.6(14.95) = 8.97; 25 v_A2n = 1.5 - 44.85, v_A2n = -1.734: all carried.
    work = (
        "v_A1n = 5 sin 37.6° = 3.05\n"
        "v_A1t = 5 cos 37.6° = 3.96\n"
        "v_B1n = -15 cos 37.6° = -11.9\n"
        "20(3.05) + 5(-11.9) = 20 v_A2n + 5 v_B2n\n"
        "v_B2n - v_A2n = 0.6(3.05 + 11.9) = 8.97\n"
        "25 v_A2n = 1.5 - 44.85\n"
        "v_A2n = -1.73\n"
    )
    found = lines("notes-4c11-two-spheres", work)
    assert found[1] == ("wrong", "sin_cos_swapped", False)
    assert found[2] == ("wrong", "sin_cos_swapped", True)
    assert found[3][0] == "correct"
    assert [found[n][0] for n in (4, 5, 6, 7)] == ["carried"] * 4


def test_sin_and_cos_swapped_about_a_line_of_impact_not_along_x() -> None:
    # A line of impact at phi = 20 deg to x with A
    # at 45 deg to x is at 25 deg to n: its n component is v cos 25 deg; swapped, v sin 25 deg
    # (not v sin 45 deg + ... about x). Fisicalab example 7 (80 m/s): 80 sin 25 = 33.81.
    found = lines("fisicalab-example-7-normal-at-20deg", "v_A1n = 80 sin 25° = 33.81\nv_B1n = 110 cos 100° = -19.10\n")
    assert found[1][:2] == ("wrong", "sin_cos_swapped")
    assert found[2][0] == "correct"


def test_a_common_velocity_worked_wrongly_is_both_velocities_in_the_carried_lines() -> None:
    # MSU bullet: 0.020 kg at 300 m/s lodges in 4.0 kg: 6 = 4.02 v', v' = 1.4925, written
    # 1.439 (an arithmetic slip). They move together, so KE after from the student's v' is
    # ½(4.02)(1.439²) = 2.01(2.0707) = 4.16 (not the true 4.48): carried, not a new mistake.
    work = "0.020(300) = (0.020 + 4.0) v'\n6 = 4.02 v'\nv' = 6/4.02 = 1.439\nKE after = 1/2 (4.02)(1.439)^2 = 4.16\n"
    found = lines("msu-lectureonline-bullet-lodges-in-block", work)
    assert found[1][0] == found[2][0] == "correct"
    assert found[3][:2] == ("wrong", "arithmetic")
    assert found[4][0] == "carried"


def test_a_value_in_letters_worked_wrongly_is_carried_where_it_is_written_again() -> None:
    # Edexcel M2 2010: P (2m) at 2u meets Q (m) at u: the reduced mass is 2m·m/3m = 2m/3,
    # written 3m/2; the approach speed is 3u, so the energy lost is ½(2m/3)(1 - e²)(9u²)
    # = 3mu²(1 - e²). With the student's 3m/2: ½(3m/2)(1 - e²)(9u²) = 27/4 mu²(1 - e²):
    # right given the slip, a carried error, not a new mistake.
    work = "μ = (2m × m)/(3m) = 3m/2\nKE lost = ½ (3m/2)(1 - e²)(3u)² = 27/4 mu²(1 - e²)\n"
    found = lines("edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u", work)
    assert found[1][:2] == ("wrong", "arithmetic")
    assert found[2][0] == "carried"


def test_sin_and_cos_swapped_on_a_then_again_on_b_carries_with_both_swapped() -> None:
    # Notes 4.C.11: A's n component 5 sin 37.6 = 3.05 (swapped), then B's the same wrong way,
    # -15 sin 37.6 = -9.15 (the same slip again). Momentum 61.0 - 45.75 = 15.25 = 20 v_A2n +
    # 5 v_B2n and v_B2n - v_A2n = 0.6(12.2) = 7.32 hold given both: carried.
    work = (
        "v_A1n = 5 sin 37.6° = 3.05\n"
        "v_B1n = -15 sin 37.6° = -9.15\n"
        "20(3.05) + 5(-9.15) = 20 v_A2n + 5 v_B2n\n"
        "v_B2n - v_A2n = 0.6(3.05 + 9.15) = 7.32\n"
    )
    found = lines("notes-4c11-two-spheres", work)
    assert found[1] == ("wrong", "sin_cos_swapped", False)
    assert found[2] == ("wrong", "sin_cos_swapped", True)
    assert found[3][0] == found[4][0] == "carried"


def test_a_chain_value_in_letters_got_wrong_carries_through_the_next_stage_and_the_solve() -> None:
    # Edexcel M2 three particles (equal masses, A at 7 m/s, C leaves at 4 m/s): B leaves the
    # first impact at u_B = 7(1 + e)/2. Written 9(1 + e)/2 (a wrong number), then by the same
    # working C leaves at u_B(1 + e)/2 = 9(1 + e)^2/4; = 4 gives (1 + e)^2 = 16/9, e = 1/3
    # (the true e is 4/sqrt(7) - 1 = 0.512): every line after the slip is right given it.
    work = "u_B = 9(1 + e)/2\nu_C = u_B(1 + e)/2 = 9(1 + e)^2/4\n9(1 + e)^2/4 = 4\n(1 + e)^2 = 16/9\ne = 1/3\n"
    found = lines("chain-edexcel-m2-three-particles", work)
    assert found[1][0] == "wrong"
    assert [found[n][0] for n in (2, 3, 4, 5)] == ["carried"] * 4


def test_a_chain_line_of_arithmetic_from_a_wrong_whole_number_is_carried() -> None:
    # OCR M2 2015 chain (5 m/s down from 1.6 m, g = 9.8): v_1^2 = 25 + 31.36 = 56.36, written
    # 65; then sqrt(65) = 8.06 is right as arithmetic but worked from the wrong 65: carried.
    work = "v_1^2 = 5^2 + 2(9.8)(1.6) = 65\nsqrt(65) = 8.06\n"
    found = lines("chain-ocr-m2-2015-thrown-down-bounce", work)
    assert found[1][0] == "wrong"
    assert found[2][0] == "carried"


def test_a_wrong_number_put_into_a_right_formula_and_worked_on_is_carried() -> None:
    # Hibbeler 15-58 (W_A = 15 lb at 19.657 ft/s, W_B = 10 lb at rest, e = 0.3): the centre of
    # mass moves at V = 15(19.657)/25 = 294.855/25 = 11.794 (written 11.97: a slip). In the
    # centre of mass frame v_A2 = (1 + e)V - e u: truly 1.3(11.794) - 0.3(19.657) = 15.332 -
    # 5.897 = 9.435 (the momentum and restitution give the same); with 11.97 it is 15.561 -
    # 5.897 = 9.664, right as arithmetic and worked from the wrong V: carried, not a new slip.
    # The same working with its own arithmetic wrong (10.66) is a further slip.
    head = "V = 15(19.657)/25 = 294.855/25 = 11.97 ft/s\nv_A2 = (1 + e)V - e u\n"
    found = lines("hibbeler-15-58-suitcases", head + "v_A2 = 1.3(11.97) - 0.3(19.657) = 9.664 ft/s\n")
    assert found[1][:2] == ("wrong", "arithmetic")
    assert found[2][0] == "correct"
    assert found[3][0] == "carried"
    found = lines("hibbeler-15-58-suitcases", head + "v_A2 = 1.3(11.97) - 0.3(19.657) = 10.66 ft/s\n")
    assert found[3][0] == "wrong"


def test_a_known_component_written_wrong_under_a_symbolic_mass_is_carried_into_the_momentum() -> None:
    # Gramoll's equal balls (masses m, kept symbolic): A at 4 m/s at 30° to the line of impact,
    # B at 3 m/s along it toward A, e = 1. A's component along it is 4 cos 30° = 3.4641
    # (written 3.564: a slip). Truly 3.4641 - 3 = 0.4641 = v_A2n + v_B2n and v_B2n - v_A2n =
    # 6.4641 (so v_B2n = 3.4641); worked from 3.564: 0.564 and 6.564, v_B2n = 7.128/2 = 3.564.
    # A value known before the impact (not an unknown) written wrong still carries on.
    work = (
        "v_A1n = 4 cos 30 = 3.564 m/s\n"
        "3.564 - 3 = v_A2n + v_B2n\n"
        "v_B2n - v_A2n = 3.564 + 3 = 6.564\n"
        "v_B2n = (0.564 + 6.564)/2 = 3.564 m/s\n"
    )
    found = lines("gramoll-ecourses-two-balls-elastic", work)
    assert found[1][:2] == ("wrong", "arithmetic")
    assert found[2][0] == found[3][0] == found[4][0] == "carried"


def test_a_law_in_names_after_a_given_copied_wrongly_is_correct_and_the_numbers_put_in_carried(tmp_path) -> None:
    # 2 kg at 5.25 m/s hits 3 kg at rest, e = 0.5 (by hand): 10.5 = 2v_A + 3v_B, v_B - v_A = 2.625,
    # v_B = 3.15, v_A = 0.525. Copied as 5.52: 11.04 = 2v_A + 3v_B, v_B - v_A = 2.76, v_B = 3.312.
    # The laws in names hold as the problem has them: correct; the lines with 5.52 put in carry
    # the slip, even "0.5 = (v_B2 - v_A2)/(5.52 - 0)" that 0.4755 happens to meet at one figure.
    problem = tmp_path / "copied.toml"
    problem.write_text(
        'title = "t"\nkind = "direct"\n[given]\nm_A = "2 kg"\nm_B = "3 kg"\nv_A1 = "5.25 m/s"\n'
        'v_B1 = "0 m/s"\ne = "0.5"\n'
    )
    work = (
        "v_A1 = 5.52 m/s\n"
        "m_A v_A1 + m_B v_B1 = m_A v_A2 + m_B v_B2\n"
        "2(5.52) + 0 = 2 v_A2 + 3 v_B2\n"
        "e = (v_B2 - v_A2)/(v_A1 - v_B1)\n"
        "0.5 = (v_B2 - v_A2)/(5.52 - 0)\n"
        "v_B2 = 3.312 m/s\n"
    )
    got = {n: s for n, (s, _, _) in lines(str(problem), work).items()}
    assert got == {1: "wrong", 2: "correct", 3: "carried", 4: "correct", 5: "carried", 6: "carried"}


def test_a_line_going_on_from_a_wrong_line_is_carried_whatever_markup_opens_it() -> None:
    # Edexcel M2 2010 Q2: 2m at 2u meets m at u. T_1 = ½(2m)(2u)² + ½m u² = 9/2 mu²; the
    # half left out, (2m)(2u)² + m u² = 8mu² + mu² = 9mu²: the second line is right as
    # algebra but goes on from the wrong one ("= ..."), however the line is opened.
    openers = ["$= {}$", "$$= {}$$", "\\[ = {} \\]", "  = {}", "> = {}", "- = {}", "* $= {}$"]
    for opener in openers:
        work = "KE before $= (2m)(2u)^2 + m u^2$\n" + opener.format("8mu^2 + mu^2 = 9mu^2") + "\n"
        found = lines("edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u", work)
        assert found[1][:2] == ("wrong", "ke_formula"), opener
        assert found[2][0] == "carried", opener
    work = "\\begin{align*}\nKE_1 &= (2m)(2u)^2 + m u^2 \\\\\n&= 8mu^2 + mu^2 = 9mu^2\n\\end{align*}\n"
    found = lines("edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u", work)
    assert (found[2][0], found[3][0]) == ("wrong", "carried")


def test_a_wrong_value_in_powers_of_ten_is_carried_where_written_as_a_decimal() -> None:
    # MSU bullet: 0.020 kg at 300 m/s lodges in 4.0 kg: V = 6/4.02 = 1.4925 m/s; the energy
    # after with the bullet alone, ½(0.020)(1.49²) = 0.0222 = 2.22 × 10⁻² J (for 4.46 J):
    # 0.0222/900 = 2.47 × 10⁻⁵ is right as arithmetic, but worked from the wrong value;
    # and the other way round, 0.0222 then 2.22 × 10⁻² again.
    problem = "msu-lectureonline-bullet-lodges-in-block"
    for wrong, again in (("2.22 \\times 10^{-2}", "0.0222"), ("0.0222", "2.22 \\times 10^{-2}")):
        work = f"$V = 6/4.02 = 1.49$\n$KE_f = \\frac12 (0.020)(1.49)^2 = {wrong}$\n$\\frac{{{again}}}{{900}} = 2.47 \\times 10^{{-5}}$\n"
        found = lines(problem, work)
        assert found[1][0] == "correct"
        assert found[2][0] == "wrong"
        assert found[3][0] == "carried", wrong
    # a line in names, right at its figures, that puts the wrong value in (ΔKE = -900 for -895.5)
    work = "$V = 6/4.02 = 1.49$\n$KE_f = \\frac12 (0.020)(1.49)^2 = 2.22 \\times 10^{-2}$\n$\\Delta KE = KE_f - 900 = 0.0222 - 900 = -899.98$\n"
    found = lines(problem, work)
    assert found[3][0] == "carried"


def test_a_given_velocity_copied_as_another_number_carries_through_the_find_e() -> None:
    # Beer & Johnston 13.13: 20 Mg at 0.5 m/s hits 35 Mg at rest, B leaves at 0.3 m/s: 10 = 20 v_A2
    # + 10.5, v_A2 = -0.025, e = 0.325/0.5 = 0.65. B's 0.3 copied as 0.2: 10 = 20 v_A2 + 7, v_A2 =
    # 0.15, e = (0.2 - 0.15)/0.5 = 0.1; as 0.4: 10 = 20 v_A2 + 14, v_A2 = -0.2, e = 0.6/0.5 = 1.2.
    # Every line after is right given the number as copied: carried, not a further slip.
    problem = "beer-johnston-13-13-railroad-cars-find-e"
    for c, rest in (
        ("0.2", "10 = 20 v_A2 + 7\nv_A2 = 3/20 = 0.15\ne = (0.2 - 0.15)/(0.5 - 0) = 0.1\n"),
        ("0.4", "10 = 20 v_A2 + 14\nv_A2 = -4/20 = -0.2\ne = (0.4 + 0.2)/(0.5 - 0) = 1.2\n"),
    ):
        found = lines(problem, f"20(0.5) + 35(0) = 20 v_A2 + 35({c})\n" + rest)
        assert found[1][:2] == ("wrong", "copied_wrong"), c
        assert [found[n][0] for n in (2, 3, 4)] == ["carried"] * 3, c


def test_an_unknown_found_from_the_condition_before_a_slip_stays_as_the_student_found_it() -> None:
    # CIE 2014 Q3: m at u hits 9m at rest and half the energy is lost: ½(9m/10)(1 - e²)u² =
    # ½(½mu²), so 1 - e² = 5/9 and e = 2/3 (found right, first). Then the masses exchanged in
    # the momentum: u = 9v_1 + v_2 with v_2 - v_1 = 2u/3 gives u = 10v_1 + 2u/3, v_1 = u/30,
    # v_2 = 7u/10: right given the slip with e kept at 2/3 (not e solved again from the
    # condition with the slip's velocities), so the restitution line is correct, the rest carried.
    work = (
        "1 - e^2 = 5/9, so e = 2/3\n"
        "m u + 0 = 9m v_1 + m v_2\n"
        "v_2 - v_1 = e u = 2u/3\n"
        "v_1 = u/30\n"
        "v_2 = u/30 + 2u/3 = 7u/10\n"
    )
    found = lines("cie-9231-p2-2014-june-q3-m-hits-9m-half-ke-lost", work)
    assert found[1][0] == "correct"
    assert found[2][:2] == ("wrong", "masses_swapped")
    assert found[3][0] == "correct"
    assert found[4][0] == found[5][0] == "carried"


def _inverse(tmp_path, name: str, given: str) -> str:
    problem = tmp_path / f"{name}.toml"
    problem.write_text(f'title = "t"\nkind = "direct"\n[given]\n{given}')
    return str(problem)


def test_a_given_misread_by_one_digit_in_a_find_the_mass_problem_is_the_slip_not_the_masses_swapped(tmp_path) -> None:
    # A 1500 kg van at 5 m/s runs into a parked car (mass M); they move on together at 3 m/s.
    # By hand: 1500(5) = 7500 = 3(1500 + M) -> M = 1000 kg. Read as 6 m/s: 9000 = 4500 + 3M,
    # M = 1500 kg, the van's own mass: M is still the mass solved for (not the 1500 kg given),
    # and the slip is the copy (every other number on the line is the problem's).
    problem = _inverse(
        tmp_path,
        "van",
        'm_A = "1500 kg"\nm_B = "? kg"\ne = "?"\nv_A1 = "5 m/s"\nv_B1 = 0\nv_A2 = "3 m/s"\nv_B2 = "3 m/s"\n',
    )
    work = "Let M be the mass of the parked car.\n1500 x 6 = (1500 + M) x 3\n9000 = 4500 + 3M\n3M = 4500\nM = 1500 kg\n"
    found = lines(problem, work)
    assert found[2][:2] == ("wrong", "copied_wrong")
    assert found[3][0] == found[4][0] == found[5][0] == "carried"


def test_a_given_velocity_after_misread_is_carried_into_the_restitution_worked_with_it(tmp_path) -> None:
    # 3 kg at 4 m/s hits 2 kg at rest; A goes on at 2 m/s; find e. By hand: 12 = 6 + 2v_B ->
    # v_B = 3, e = (3 - 2)/4 = 0.25. A's 2 m/s read as 1: 12 = 3 + 2v_B -> v_B = 4.5 and
    # e = (4.5 - 1)/4 = 0.875: the law in names is right, the numbers put in carry the copy.
    problem = _inverse(
        tmp_path, "finde", 'm_A = "3 kg"\nm_B = "2 kg"\ne = "?"\nv_A1 = "4 m/s"\nv_B1 = 0\nv_A2 = "2 m/s"\n'
    )
    work = (
        "3(4) + 2(0) = 3(1) + 2 v_B2\n"
        "12 = 3 + 2 v_B2\n"
        "v_B2 = 4.5 m/s\n"
        "e = (v_B2 - v_A2)/(v_A1 - v_B1)\n"
        "e = (4.5 - 1)/(4 - 0) = 0.875\n"
    )
    found = lines(problem, work)
    assert found[1][:2] == ("wrong", "copied_wrong")
    assert found[2][0] == found[3][0] == found[5][0] == "carried"
    assert found[4][0] == "correct"


def test_a_worked_number_with_two_digits_swapped_is_the_slip_though_the_line_holds_at_one_figure(tmp_path) -> None:
    # 0.2 kg at 35 m/s hits 0.27 kg at rest, elastic. By hand: 7 = 0.2a + 0.27b, b = a + 35,
    # 0.27 x 35 = 9.45: 7 = 0.47a + 9.45 -> a = -5.2128, b = 29.787. Written 9.54: at the one
    # figure of "7" the line still holds (0.47a + 9.54 = 7.09), but its digits are 9.45's
    # swapped: the slip (arithmetic), and a = -2.54/0.47 = -5.404 carries it.
    problem = _inverse(tmp_path, "swap", 'm_A = "0.2 kg"\nm_B = "0.27 kg"\nv_A1 = "35 m/s"\nv_B1 = "0 m/s"\ne = "1"\n')
    work = (
        "0.2(35) + 0.27(0) = 0.2a + 0.27b\n"
        "b - a = 35\n"
        "7 = 0.2a + 0.27(a + 35)\n"
        "7 = 0.47a + 9.54\n"
        "a = (7 - 9.54)/0.47 = -5.404 m/s\n"
    )
    found = lines(problem, work)
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3
    assert found[4][:2] == ("wrong", "arithmetic")
    assert found[5][0] == "carried"


def test_energies_worked_with_a_given_copied_wrongly_are_carried(tmp_path) -> None:
    # A 50 g pellet at 200 m/s lodges in a 2 kg block. By hand: V = 10/2.05 = 4.878, KE before
    # ½(0.05)(200²) = 1000 J. Copied as 0.5 kg: V = 100/2.5 = 40, KE before ½(0.5)(200²) = 10000,
    # after ½(2.5)(40²) = 2000, lost 8000: each energy is worked from the 0.5 kg, so carried
    # (the results of the problem are worked from the given as the student copied it).
    problem = _inverse(tmp_path, "pellet", 'm_A = "50 g"\nm_B = "2 kg"\nv_A1 = "200 m/s"\nv_B1 = "0 m/s"\ne = 0\n')
    work = (
        "m = 50 g = 0.5 kg, M = 2 kg, u = 200 m/s\n"
        "m u = (m + M) V\n"
        "V = 0.5 x 200 / 2.5 = 40 m/s\n"
        "KE before = 1/2 m u^2 = 0.5 x 0.5 x 200^2 = 10000 J\n"
        "KE after = 1/2 (m + M) V^2 = 0.5 x 2.5 x 40^2 = 2000 J\n"
        "KE lost = 10000 - 2000 = 8000 J\n"
    )
    found = lines(problem, work)
    assert found[1][:2] == ("wrong", "copied_wrong")
    assert found[2][0] == "correct"
    assert [found[n][0] for n in (3, 4, 5, 6)] == ["carried"] * 4


def test_a_chain_stage_slip_in_one_equation_is_carried_with_the_students_own_values() -> None:
    # AQA M3 2007 as a chain: A 0.3 kg at 3, B 0.2 kg at 2 toward it, e = 0.8, wall e = 0.7.
    # Momentum 0.9 - 0.4 = 0.5, written 0.6 (arithmetic); restitution y - x = 4 right. The
    # student's own: 0.3x + 0.2(x + 4) = 0.6 -> x = -0.4, y = 3.6; the wall: -0.7(3.6) = -2.52
    # (truly x = -0.6, y = 3.4, w_B = -2.38): each line after is carried, into the wall's stage.
    work = (
        "Let x and y be the velocities of A and B after the impact (A's direction positive).\n"
        "0.3(3) + 0.2(-2) = 0.3x + 0.2y\n"
        "0.3x + 0.2y = 0.6\n"
        "y - x = 0.8(3 + 2) = 4\n"
        "0.3x + 0.2(x + 4) = 0.6, so x = -0.4\n"
        "y = -0.4 + 4 = 3.6\n"
        "B rebounds from the wall: w_B = -0.7(3.6) = -2.52\n"
    )
    found = lines("chain-aqa-m3-2007-collide-again", work)
    assert found[2][0] == found[4][0] == "correct"
    assert found[3][:2] == ("wrong", "arithmetic")
    assert [found[i][0] for i in (5, 6, 7)] == ["carried"] * 3


def test_a_chain_stage_mistake_gives_the_declared_names_its_values() -> None:
    # The same chain, the masses swapped in the momentum: 0.2(3) + 0.3(-2) = 0 = 0.2x + 0.3y,
    # with y - x = 4: 0.5x + 1.2 = 0 -> x = -2.4, y = 1.6; the wall: -0.7(1.6) = -1.12.
    work = (
        "Let x and y be the velocities of A and B after the impact (A's direction positive).\n"
        "0.2(3) + 0.3(-2) = 0.2x + 0.3y\n"
        "y - x = 0.8(3 + 2) = 4\n"
        "0.2x + 0.3(x + 4) = 0\n"
        "0.5x = -1.2, x = -2.4\n"
        "y = -2.4 + 4 = 1.6\n"
        "B rebounds from the wall: w_B = -0.7(1.6) = -1.12\n"
    )
    found = lines("chain-aqa-m3-2007-collide-again", work)
    assert found[2][:2] == ("wrong", "masses_swapped") and found[3][0] == "correct"
    assert [found[i][0] for i in (4, 5, 6, 7)] == ["carried"] * 4


def test_a_sign_lost_moving_the_restitution_term_carries_into_the_other_velocity() -> None:
    # Edexcel M2 2004 Q5: P (2m) at 5u hits Q (3m) at rest, e: 10u = 2x + 3y, y - x = 5eu.
    # Substituting y = x + 5eu: 10u = 5x + 15eu, so 5x = 10u - 15eu, x = 2u - 3eu. With the
    # sign of 15eu kept when it moves across, x = 2u + 3eu (the value the restitution law
    # reversed would give, by coincidence); then y = x + 5eu = 2u + 8eu is the student's own
    # restitution with their own x: carried, not a further slip (corpus e10, zb07).
    work = (
        "10mu = 2mx + 3my\n"
        "y - x = 5eu\n"
        "10u = 2x + 3(x + 5eu) = 5x + 15eu\n"
        "5x = 10u + 15eu\n"
        "x = 2u + 3eu\n"
        "y = x + 5eu = 2u + 8eu\n"
    )
    found = lines("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", work)
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3
    assert found[4][0] == "wrong"
    assert found[5][0] == found[6][0] == "carried"


def test_the_other_velocity_from_the_momentum_with_the_own_value_is_carried() -> None:
    # The same slip (x = 2u + 3eu for 2u - 3eu), but y then found from the momentum, not the
    # restitution: y = (10u - 2x)/3 = (10u - 4u - 6eu)/3 = 2u - 2eu (true y = 2u + 2eu). The
    # slip stands for whichever equation the student did not go on with: carried.
    work = (
        "10mu = 2mx + 3my\n"
        "y = x + 5eu\n"
        "10u = 2x + 3x + 15eu\n"
        "5x = 10u + 15eu\n"
        "x = 2u + 3eu\n"
        "y = (10u - 2x)/3 = (10u - 4u - 6eu)/3 = 2u - 2eu\n"
    )
    found = lines("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", work)
    assert found[4][0] == "wrong"
    assert found[5][0] == found[6][0] == "carried"


def test_a_value_found_from_the_exact_carried_value_not_its_rounding_is_carried() -> None:
    # OCR M2 2006: 2 kg at 5 m/s meets 1 kg at 5 m/s head-on, e = 0.8: 5 = 2a + b, b - a = 8,
    # so a = -1, b = 7. B's sign lost: 15 = 2a + b, then 15 = 3b - 16, b = 31/3 = 10.33
    # (written 10.3) and a = b - 8 = 7/3 = 2.333 (written 2.33, from the exact 31/3; the
    # rounded 10.3 would give 2.3): carried (corpus zb08).
    work = (
        "2(5) + 1(5) = 2a + b\n"
        "b - a = 0.8(5 - (-5)) = 8\n"
        "15 = 2(b - 8) + b = 3b - 16\n"
        "b = 31/3 ≈ 10.3\n"
        "a = b - 8 ≈ 2.33\n"
    )
    found = lines("ocr-m2-2006-spheres-meet-at-5-ke-lost", work)
    assert found[1][:2] == ("wrong", "b_sign")
    assert [found[n][0] for n in (3, 4, 5)] == ["carried"] * 3


def test_an_energy_worked_with_a_wrong_formula_is_carried_when_worked_on_to_a_number() -> None:
    # OCR M2 2006 (2 kg at 5, 1 kg at -5, e = 0.8): a = -1, b = 7; T_1 = 25 + 12.5 = 37.5,
    # T_2 = 1 + 24.5 = 25.5, lost 12 J. ½m(u - v)² for each body instead: ½(2)(6²) +
    # ½(1)(12²) = 36 + 72 = 108; the line that works that expression to 108 carries it
    # (corpus i10).
    work = (
        "2(5) + 1(-5) = 2a + b\n"
        "b - a = 0.8(5 - (-5)) = 8\n"
        "a = -1, b = 7\n"
        "Delta T = 1/2(2)(5 - (-1))^2 + 1/2(1)(-5 - 7)^2\n"
        "Delta T = (6)^2 + 0.5(12)^2 = 36 + 72 = 108 J\n"
    )
    found = lines("ocr-m2-2006-spheres-meet-at-5-ke-lost", work)
    assert found[4][:2] == ("wrong", "ke_formula")
    assert found[5][0] == "carried"


def test_lines_after_two_slips_hold_with_the_values_as_the_student_stated_them() -> None:
    # Edexcel M2 2004 Q5 (2m at 5u hits 3m at rest, e): 10u = 2x + 3y, y - x = 5eu, so
    # 5y = 10u + 10eu, y = 2u + 2eu (right), x = y - 5eu = 2u - 3eu. The student writes
    # 2u + 7eu (a sign slip) and keeps their right y. Then the kinetic energy with the masses
    # exchanged, ½(3m)x² + ½(2m)y² (a second slip), worked with their own x and y:
    # 1.5m(2u + 7eu)² + m(2u + 2eu)², and the loss from T_1 = ½(2m)(5u)² = 25mu²: both
    # carried. (Solving the equations again with the slip would move y, which they kept.)
    work = (
        "10mu = 2mx + 3my\n"
        "y - x = 5eu\n"
        "5y = 10u + 10eu\n"
        "y = 2u + 2eu\n"
        "x = y - 5eu = 2u + 7eu\n"
        "KE after = 1/2(3m)x^2 + 1/2(2m)y^2\n"
        "= 1.5m(2u + 7eu)^2 + m(2u + 2eu)^2\n"
        "KE lost = 25mu^2 - 1.5m(2u + 7eu)^2 - m(2u + 2eu)^2\n"
    )
    found = lines("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", work)
    assert [found[n][0] for n in (1, 2, 3, 4)] == ["correct"] * 4
    assert found[5][0] == "wrong"
    assert found[6][:2] == ("wrong", "masses_swapped")
    assert found[7][0] == found[8][0] == "carried"


def test_a_result_said_right_then_worked_with_a_form_expanded_wrongly_is_carried() -> None:
    # Edexcel M2 2004 Q5: x = u(2 - 3e), y = 2u(1 + e); T_2 = ½(2m)x² + ½(3m)y²
    # = mu²[(2 - 3e)² + 6(1 + e)²] (right). Expanding, 6(1 + e)² = 6 + 12e + 6e², so the
    # bracket is 10 + 15e²; written 10 - 12e + 15e² (the 12e of the second square lost): the
    # slip. Then T_2 = mu²(10 - 12e + 15e²) and T_lost = 25mu² - T_2 = mu²(15 + 12e - 15e²),
    # right given that bracket: carried (corpus u12).
    work = (
        "x = u(2 - 3e), y = 2u(1 + e)\n"
        "KE after = 1/2(2m)x^2 + 1/2(3m)y^2 = mu^2[(2 - 3e)^2 + 6(1 + e)^2]\n"
        "(2 - 3e)^2 + 6(1 + e)^2 = 4 - 12e + 9e^2 + 6 + 6e^2 = 10 - 12e + 15e^2\n"
        "KE after = mu^2(10 - 12e + 15e^2)\n"
        "KE lost = 25mu^2 - mu^2(10 - 12e + 15e^2) = mu^2(15 + 12e - 15e^2)\n"
    )
    found = lines("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", work)
    assert found[1][0] == found[2][0] == "correct"
    assert found[3][0] == "wrong"
    assert found[4][0] == found[5][0] == "carried"


def test_a_wrong_number_said_again_rounded_as_a_size_is_carried() -> None:
    # OCR M2 2012: 0.8 kg at 4 m/s into a wall, e = 0.3: it rebounds at 1.2 m/s and the
    # impulse is 0.8(-1.2 - 4) = -4.16 N s (4.16 N s away from the wall). Worked as -0.416
    # (a decimal place lost), then "J = 0.42": the wrong number again, rounded, as a size:
    # carried, not a further slip (corpus z07).
    work = "v = -0.3(4) = -1.2\nI = 0.8(-1.2 - 4) = 0.8 x (-5.2)\n= -0.416\nso J = 0.42 N s, away from the wall\n"
    found = lines("ocr-m2-2012-particle-hits-wall", work)
    assert found[1][0] == found[2][0] == "correct"
    assert found[3][:2] == ("wrong", "arithmetic")
    assert found[4][0] == "carried"


def test_a_sign_lost_moving_a_number_carries_into_the_other_velocity_in_numbers() -> None:
    # OCR M2 2006 (2 kg at 5 m/s, 1 kg at -5 m/s, e = 0.8): 5 = 2a + b, b = a + 8, so
    # 5 = 3a + 8, 3a = -3, a = -1, b = 7. The 8 moved across with its sign kept: 3a = 13,
    # a = 4.33; then b = 4.33 + 8 = 12.33 from their own a: carried.
    work = (
        "2(5) + 1(-5) = 2a + b\n"
        "b - a = 0.8(5 + 5) = 8\n"
        "5 = 2a + a + 8\n"
        "3a = 5 + 8 = 13\n"
        "a = 4.33 m/s\n"
        "b = 4.33 + 8 = 12.33 m/s\n"
    )
    found = lines("ocr-m2-2006-spheres-meet-at-5-ke-lost", work)
    assert found[4][0] == "wrong"
    assert found[5][0] == found[6][0] == "carried"


def test_a_second_slip_substituting_the_first_slip_keeps_both_in_the_world() -> None:
    # AQA M3 2007 (0.3 kg at 3 m/s, 0.2 kg at 2 m/s toward it, e = 0.8), left positive: the
    # momentum 0.3(-3) + 0.2(2) = -0.5 = 0.3a + 0.2b; the impact rule is a - b = 0.8(5) = 4
    # (a = 0.6, b = -3.4, the mark scheme's -0.6 and 3.4 turned round). Written b - a = 4 (the
    # wrong way round), then b = a + 4 put into the momentum with 0.2 x 4 taken as 4: a further
    # slip, -0.5 = 0.5a + 4, a = -9; then b = a + 4 = -5 from the student's own two lines:
    # carried, not a new mistake.
    work = (
        "Taking left as positive, let a and b be the velocities of A and B after.\n"
        "Momentum: 0.3(-3) + 0.2(2) = 0.3a + 0.2b\n"
        "-0.5 = 0.3a + 0.2b\n"
        "Restitution: b - a = 0.8(2 + 3) = 4\n"
        "b = a + 4\n"
        "-0.5 = 0.3a + 0.2a + 4\n"
        "0.5a = -4.5\n"
        "a = -9\n"
        "b = -5\n"
    )
    found = lines("aqa-m3-2007-spheres-approach-head-on", work)
    assert found[2][0] == found[3][0] == "correct"
    assert found[4][0] == found[6][0] == "wrong"
    assert found[5][0] == found[7][0] == found[8][0] == "carried"
    assert found[9][0] == "carried"
