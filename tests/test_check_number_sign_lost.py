"""A line that works the relation before it out with its terms in the unknowns as they were and
the number they come to written with its sign lost (``20 v = 0.5`` from ``10 = 20 v + 10.5``:
10 − 10.5 = −0.5) is ``arithmetic``, as the corpus's teachers name it: every term treated
alike, a number worked wrongly. The same line with the numbers moved written out the wrong way
round (``3 v_A = 8 − 5``) is a step of its own, ``algebra``. Values by hand."""

from __future__ import annotations

from support.checked import worst_lines

#: OCR M2 2006: A (2 kg) at 5 m/s and B (1 kg) at 5 m/s meet head-on, e = 0.8; A's way +:
#: 2(5) + 1(-5) = 5 = 2 v_A + v_B and v_B - v_A = 0.8(10) = 8, so v_B = v_A + 8 and
#: 3 v_A + 8 = 5, 3 v_A = 5 - 8 = -3, v_A = -1 (not 3 v_A = 3, v_A = 1).
MEET = "ocr-m2-2006-spheres-meet-at-5-ke-lost"
#: Beer & Johnston 13.13 (masses in Mg): 20 Mg at 0.5 m/s hits 35 Mg at rest, which moves off at
#: 0.3 m/s: 20(0.5) = 20 v_A + 35(0.3), 10 = 20 v_A + 10.5, 20 v_A = -0.5, v_A = -0.025.
CARS = "beer-johnston-13-13-railroad-cars-find-e"

START = "2(5) + 1(-5) = 2 v_A + v_B\nv_B - v_A = 0.8(5 + 5) = 8\n2 v_A + v_A + 8 = 5\n"


def test_the_number_a_side_comes_to_written_with_its_sign_lost_is_arithmetic() -> None:
    found = worst_lines(MEET, START + "3 v_A + 8 = 5\n3 v_A = 3\nv_A = 1\n")
    assert [found[n][0] for n in (1, 2, 3, 4)] == ["correct"] * 4
    assert found[5] == ("wrong", "arithmetic")
    assert found[6][0] == "carried"


def test_in_another_layout_with_the_unknown_on_the_right_it_is_arithmetic_too() -> None:
    # 10 = 20 v_A + 10.5 turned round as 0.5 = 20 v_A (for -0.5), LaTeX-typed, primes for after
    work = "$20(0.5) + 35(0) = 20 v'_A + 35(0.3)$\n$10 = 20 v'_A + 10.5$\n$0.5 = 20 v'_A$\n"
    found = worst_lines(CARS, work)
    assert found[1][0] == found[2][0] == "correct"
    assert found[3] == ("wrong", "arithmetic")


def test_the_numbers_moved_across_written_out_the_wrong_way_round_stay_algebra() -> None:
    found = worst_lines(MEET, START + "3 v_A + 8 = 5\n3 v_A = 8 - 5 = 3\n")
    assert found[5] == ("wrong", "algebra")
