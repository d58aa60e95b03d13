"""A chain's derivation with names declared in words ("let x and y be the velocities of A and
B after the impact") and a given copied wrongly: the names known as the stage's velocities,
the copied given named as such, and the student's own values carried through the later lines
and stages, so that one slip is one mistake. Every number is worked by hand from the problem
files' givens (in the comments), never from derive's output."""

from __future__ import annotations

import pytest
from support.checked import worst_lines as lines

import derive

SAID = (
    "A and B collide. Let x and y be the velocities of A and B after the impact.",
    "x, y = velocities of A, B after",
    "Let the velocities of A and B after the impact be x and y.",
    "x = A after, y = B after",
    "x = velocity of A after the first impact; y = B's velocity after it",
    "A's velocity after = x, B's velocity after = y",
)


@pytest.mark.parametrize("said", SAID)
def test_names_in_words_and_a_given_copied_wrongly_carried_through_the_stages(said: str) -> None:
    # AQA M3 2007: A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward A, e = 0.8; then B hits a wall
    # (e = 0.7). A's 3 copied as 5: 1.5 - 0.4 = 1.1 = 0.3x + 0.2y, y - x = 0.8(7) = 5.6,
    # 0.5x + 1.12 = 1.1 -> x = -0.04, y = 5.56; the wall turns B back: -0.7(5.56) = -3.892.
    # (Truly 0.5 = 0.3x + 0.2y, y - x = 4: x = -0.6, y = 3.4, w_B = -2.38.)
    work = (
        f"{said}\n"
        "0.3(5) - 0.2(2) = 0.3x + 0.2y\n"
        "y - x = 0.8(5 + 2) = 5.6\n"
        "0.3x + 0.2(x + 5.6) = 1.1\n"
        "x = -0.04\n"
        "y = 5.56\n"
        "w_B = -0.7(5.56) = -3.892\n"
    )
    found = lines("chain-aqa-m3-2007-collide-again", work)
    assert found.get(1, ("not read", ""))[0] in ("not read", "correct")  # the declaration is not marked
    assert found[2] == ("wrong", "copied_wrong")
    assert [found[n][0] for n in (3, 4, 5, 6, 7)] == ["carried"] * 5


def test_names_in_words_right_are_correct_at_the_true_values() -> None:
    # The same impact worked rightly: 0.9 - 0.4 = 0.5 = 0.3x + 0.2y, y - x = 0.8(5) = 4,
    # 0.5x + 0.8 = 0.5 -> x = -0.6, y = 3.4.
    work = (
        "Let x and y be the velocities of A and B after the impact.\n"
        "0.3(3) - 0.2(2) = 0.3x + 0.2y\n"
        "y - x = 0.8(3 + 2)\n"
        "x = -0.6\n"
        "y = 3.4\n"
    )
    found = lines("chain-aqa-m3-2007-collide-again", work)
    assert [found[n][0] for n in (2, 3, 4, 5)] == ["correct"] * 4


def test_a_speed_declared_in_words_after_the_wall_and_a_given_copied_wrongly() -> None:
    # OCR M2 June 2011: B (0.2 kg) leaves the first impact at 2.9 m/s and the wall gives it an
    # impulse of 0.68 N s: 0.68 = 0.2(w + 2.9) -> w = 0.5, e_wall = 0.5/2.9 = 0.172. The
    # impulse copied as 0.86: w = 4.3 - 2.9 = 1.4, e_wall = 1.4/2.9 = 0.483 (carried).
    work = "Let w be the speed of B after it hits the wall.\n0.86 = 0.2(w + 2.9)\nw = 1.4\ne_wall = 1.4/2.9 = 0.483\n"
    found = lines("chain-ocr-m2-2011-find-e-mass-then-wall", work)
    assert found.get(1, ("not read", ""))[0] in ("not read", "correct")
    assert found[2] == ("wrong", "copied_wrong")
    assert found[3][0] == found[4][0] == "carried"


def test_a_speed_declared_in_words_after_the_wall_right() -> None:
    # 0.68 = 0.2(w + 2.9) -> w = 0.5; e_wall = 0.5/2.9 = 0.172.
    work = "Let w be the speed of B after it hits the wall.\n0.68 = 0.2(w + 2.9)\nw = 0.5\ne_wall = w/2.9 = 0.172\n"
    found = lines("chain-ocr-m2-2011-find-e-mass-then-wall", work)
    assert [found[n][0] for n in (2, 3, 4)] == ["correct"] * 3


def test_a_sum_of_numbers_worked_wrongly_in_a_chain_is_named_arithmetic() -> None:
    # OCR M2 June 2015 as a chain: 0.2 kg thrown down at 5 m/s from 1.6 m (g = 9.8):
    # v_1^2 = 25 + 31.36 = 56.36, added as 46.36; v_1 = sqrt(46.36) = 6.81 is carried.
    work = "v_1^2 = 5^2 + 2(9.8)(1.6) = 25 + 31.36 = 46.36\nv_1 = 6.81\n"
    found = lines("chain-ocr-m2-2015-thrown-down-bounce", work)
    assert found[1] == ("wrong", "arithmetic")
    assert found[2][0] == "carried"


def test_a_chain_value_alone_written_wrongly_is_not_named_arithmetic_of_a_sum() -> None:
    # v_1 = 7.2 where v_1 = sqrt(56.36) = 7.507: a value, no sum of numbers worked wrongly in it.
    found = lines("chain-ocr-m2-2015-thrown-down-bounce", "v_1 = 7.2\n")
    assert found[1][0] == "wrong" and found[1][1] != "copied_wrong"


@pytest.mark.parametrize(
    "said", ["Let w be the velocity of B after the second impact.", "w = B's velocity after it hits the wall"]
)
def test_a_name_declared_for_the_second_impact_is_its_velocity(said: str) -> None:
    # AQA M3 2007: B leaves the first impact at 3.4 m/s and the wall (e = 0.7) turns it back:
    # its velocity after the second impact is -0.7(3.4) = -2.38 (its speed 2.38).
    from derive.checking.chainnames import at, declared
    from derive.checking.context import Context

    solution = derive.solve(derive.load("chain-aqa-m3-2007-collide-again"))
    names, lines = declared(Context(solution, None), [(1, said)])
    (x,) = names.values()
    assert lines == {1}
    assert float(at(x, solution.values)) == pytest.approx(-2.38)


def test_a_slip_in_the_names_declared_in_words_carries_their_values_into_the_next_stage() -> None:
    # AQA M3 2007: momentum right, 0.9 - 0.4 = 0.5 = 0.3x + 0.2y; B's velocity -2 taken as +2 in
    # the restitution: y - x = 0.8(3 - 2) = 0.8 (truly 0.8(3 + 2) = 4). Then 0.5x + 0.16 = 0.5:
    # x = 0.68, y = 1.48, and the wall (e = 0.7) turns B back at -0.7(1.48) = -1.036.
    work = (
        "Let x and y be the velocities of A and B after the impact.\n"
        "0.3(3) - 0.2(2) = 0.3x + 0.2y\n"
        "y - x = 0.8(3 - 2)\n"
        "0.3x + 0.2(x + 0.8) = 0.5\n"
        "x = 0.68\n"
        "y = 1.48\n"
        "w_B = -0.7(1.48) = -1.036\n"
    )
    found = lines("chain-aqa-m3-2007-collide-again", work)
    assert found[2][0] == "correct"
    assert found[3] == ("wrong", "b_sign")
    assert [found[n][0] for n in (4, 5, 6, 7)] == ["carried"] * 4


def test_a_given_restated_wrongly_in_a_chain_is_copied_wrong_and_carried() -> None:
    # AQA M3 2007 with e written 0.6 (the problem gives 0.8): 0.5 = 0.3x + 0.2y (right),
    # y - x = 0.6(5) = 3, 0.5x + 0.6 = 0.5 -> x = -0.2, y = 2.8; the wall: -0.7(2.8) = -1.96.
    work = (
        "Let x and y be the velocities of A and B after the impact.\n"
        "e = 0.6\n"
        "0.3(3) - 0.2(2) = 0.3x + 0.2y\n"
        "y - x = 0.6(3 + 2) = 3\n"
        "0.3x + 0.2(x + 3) = 0.5\n"
        "x = -0.2\n"
        "y = 2.8\n"
        "w_B = -0.7(2.8) = -1.96\n"
    )
    found = lines("chain-aqa-m3-2007-collide-again", work)
    assert found[2] == ("wrong", "copied_wrong")
    assert found[3][0] == "correct"
    assert [found[n][0] for n in (4, 5, 6, 7, 8)] == ["carried"] * 5


def test_a_carried_product_with_x_for_times_is_carried() -> None:
    # The car (910 kg) into the SUV (2100 kg) at rest, locked; the skid 2.7 m, mu_k = 0.80,
    # g = 9.8. mu copied as 0.5: a = 0.5 x 9.8 = 4.9 (truly 7.84); V^2 = 2(4.9)(2.7) = 26.46,
    # V = 5.144; the crash v = 3010V/910 = 3.308V, so v = 3.308 x 5.144 = 17.02 (truly 21.52):
    # right given the slip, with x written for times.
    work = (
        "910v = (910 + 2100)V\n"
        "v = 3010V/910 = 3.308V\n"
        "a = mu g = 0.5 x 9.8 = 4.9\n"
        "V^2 = 2(4.9)(2.7) = 26.46\n"
        "V = 5.144\n"
        "v = 3.308 x 5.144 = 17.02\n"
    )
    found = lines("chain-car-rear-ends-suv-skid", work)
    assert found[3][0] == "wrong"
    assert [found[n][0] for n in (5, 6)] == ["carried"] * 2  # line 4 is another class (numbers for a)


@pytest.mark.parametrize(
    ("problem", "work", "lines_right"),
    [
        # OCR M2 2007 (0.2 kg thrown down at 21 m/s from 40 m): v_1^2 = 21^2 + 2(9.8)(40) = 441 + 784
        # = 1225, v_1 = 35 m/s. The chain's own u is the velocity after the bounce (28 m/s up).
        (
            "chain-ocr-m2-2007-rebounds-to-start",
            "Given: m = 0.2 kg, u = 21 m/s down, h = 40 m\nv_1^2 = 21^2 + 2(9.8)(40) = 1225\nv_1 = 35 m/s",
            (2, 3),
        ),
        # MSU bullet (0.020 kg at 300 m/s into a 4 kg block): V = 0.020(300)/4.020 = 1.4925 m/s.
        # The chain's own V is that common velocity, not the bullet's 300 m/s.
        ("chain-msu-bullet-block-swings", "V = 300 m/s, M = 4 kg\nv_1 = 0.020(300)/4.020 = 1.49 m/s", (2,)),
    ],
)
def test_a_given_restated_in_a_name_the_chain_has_for_another_quantity_is_not_marked(
    problem: str, work: str, lines_right: tuple
) -> None:
    got = lines(problem, work)
    assert got.get(1, ("not read", ""))[0] in ("not read", "correct")
    assert all(got[n][0] == "correct" for n in lines_right), got


@pytest.mark.parametrize(
    ("problem", "work"),
    [
        # OCR M2 2015 (0.2 kg thrown down at 5 m/s, e = 0.7): the speed at the ground is 7.51 m/s, not
        # the 5 m/s thrown; v_1 = 5 is the fall forgotten, the chain's own v_1 wrong
        ("chain-ocr-m2-2015-thrown-down-bounce", "v_1 = 5\nu = -0.7 x 5 = -3.5\nJ = 0.2(5 + 3.5) = 1.7"),
        # OCR M2 2007 (21 m/s down from 40 m): v_1 = 35 m/s (above), not 21
        ("chain-ocr-m2-2007-rebounds-to-start", "v_1 = 21"),
    ],
)
def test_a_chains_own_name_set_to_a_given_without_its_unit_or_words_is_judged(problem: str, work: str) -> None:
    assert lines(problem, work)[1][0] == "wrong"


def test_a_chain_name_set_to_a_given_after_the_working_is_still_judged() -> None:
    # OCR M2 2007: the chain's u (after the bounce) is 28 m/s up, not the 21 m/s thrown down.
    got = lines("chain-ocr-m2-2007-rebounds-to-start", "v_1^2 = 21^2 + 2(9.8)(40) = 1225\nu = 21")
    assert got[2][0] == "wrong"


def test_a_chains_answer_in_a_letter_of_the_students_own_is_judged_as_the_result() -> None:
    # MSU bullet and block swing: V = 6/4.02 = 1.4925 m/s, h_2 = V²/(2 × 9.81) = 0.1135 m.
    # "h = …" worked once at the end, the chain's one h: it is h_2, right or wrong; worked
    # with V²/g it is 0.2271, which a teacher marks wrong (not a name of the student's own).
    head = "0.020(300) = 4.02 V\nV = 1.4925\n"
    assert lines("chain-msu-bullet-block-swings", head + "h = 1.4925^2/(2 x 9.81) = 0.1135\n")[3][0] == "correct"
    assert lines("chain-msu-bullet-block-swings", head + "h = 1.4925^2/9.81 = 0.2271\n")[3][0] == "wrong"


def test_a_speed_from_its_square_worked_wrongly_is_carried() -> None:
    # Car and SUV skid (0.80, 2.7 m, g = 9.8; 910 kg into 2100 kg at rest). By hand: V² = 2(0.8)(9.8)(2.7)
    # = 42.336, V = 6.507. With g left out: V² = 2(0.80)(2.7) = 4.32 (the slip), V = √4.32 = 2.08 is
    # the student's own V (carried), and 910 v = 3010(2.08), v = 6.88 carry it on.
    work = "V^2 = 2 mu_k d = 2(0.80)(2.7) = 4.32\nV = 2.08 m/s\n910 v = 3010(2.08)\nv = 6.88 m/s\n"
    found = lines("chain-car-rear-ends-suv-skid", work)
    assert found[1][0] == "wrong"
    assert [found[n][0] for n in (2, 3, 4)] == ["carried"] * 3


def test_a_line_right_with_a_name_of_the_students_own_but_worked_from_a_wrong_number_is_carried() -> None:
    # As above (V = 2.08 from the slip): 910u = 3010 × 2.08 holds for the student's own u, but its
    # working is the wrong 2.08 (truly 3010 × 6.507): carried, not correct.
    work = "V^2 = 2 mu_k d = 2(0.80)(2.7) = 4.32\nV = 2.08 m/s\n910u = 3010 x 2.08\n"
    assert lines("chain-car-rear-ends-suv-skid", work)[3][0] == "carried"


@pytest.mark.parametrize(
    ("work", "verdict"),
    [
        ("B then hits the wall and comes back at 2.38 m/s.\ne = 2.38/3.4 = 0.7\n", "correct"),
        ("For the wall: e = v/u = 2.38/3.4 = 0.70\n", "correct"),
        ("B then hits the wall and comes back at 2.38 m/s.\ne = 2.38/3.4 = 0.8\n", "wrong"),
    ],
)
def test_e_for_a_later_stages_coefficient_with_working_and_an_answer(work: str, verdict: str) -> None:
    # AQA M3 2007 as a chain: e = 0.8 between the spheres, 0.7 for B and the wall. B leaves
    # the first impact at 3.4 m/s (0.5 = 0.3x + 0.2y, y - x = 4) and the wall sends it back at
    # 0.7(3.4) = 2.38, so e = 2.38/3.4 = 0.7 is the wall's e (a line of three sides, as the
    # student writes it), and 2.38/3.4 = 0.8 is false for either coefficient.
    found = lines("chain-aqa-m3-2007-collide-again", work)
    assert max(found.items())[1][0] == verdict
