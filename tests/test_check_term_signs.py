"""A sign lost collecting terms in letters is algebra, as teachers mark it: the working side
holds with exactly one of its typed terms given the other sign. A number of the collected
terms worked wrongly otherwise stays arithmetic. Every value is worked by hand."""

from __future__ import annotations

from support.checked import worst_lines

#: 2m at 4u meets m at 3u coming the other way (CIE 2014): 8u - 3u = 5u = 2v_A2 + v_B2 and
#: v_B2 - v_A2 = e(4u + 3u) = 7eu, so 3v_A2 = 5u - 7eu, v_A2 = 5u/3 - 7eu/3 and
#: v_B2 = v_A2 + 7eu = 5u/3 - 7eu/3 + 21eu/3 = 5u/3 + 14eu/3.
MEET = "cie-9231-p2-2014-november-q1-2m-at-4u-meets-m-at-3u-a-reverses"
START = (
    "2m(4u) - m(3u) = 2m v_A2 + m v_B2\n5u = 2v_A2 + v_B2\nv_B2 - v_A2 = 7eu\n3v_A2 = 5u - 7eu\nv_A2 = 5u/3 - 7eu/3\n"
)


def test_a_term_in_letters_collected_with_its_sign_lost_is_algebra() -> None:
    # the +7eu taken as -7eu: 5/3 - 7/3 - 7 = 5/3 - 28/3
    found = worst_lines(MEET, START + "v_B2 = 5u/3 - 7eu/3 + 7eu = 5u/3 - 28eu/3\n")
    assert all(found[n][0] == "correct" for n in range(1, 6))
    assert found[6] == ("wrong", "algebra")


def test_the_first_term_with_its_sign_lost_is_algebra() -> None:
    # written the other way round, 7eu - 7eu/3 + 5u/3, its first term's sign lost: -7 - 7/3 = -28/3
    found = worst_lines(MEET, START + "v_B2 = 7eu - 7eu/3 + 5u/3 = 5u/3 - 28eu/3\n")
    assert found[6] == ("wrong", "algebra")


def test_collected_terms_with_the_answers_sign_wrong_are_arithmetic() -> None:
    # -7/3 + 7 is +14/3, written -14/3: no one term's sign changed gives it (that gives -28/3)
    found = worst_lines(MEET, START + "v_B2 = 5u/3 - 7eu/3 + 7eu = 5u/3 - 14eu/3\n")
    assert found[6] == ("wrong", "arithmetic")


def test_a_sign_lost_in_a_bracket_over_a_number_is_arithmetic() -> None:
    # (5u - 7eu)/3 + 7eu is (5u + 14eu)/3; the -7eu inside the bracket taken as +7eu gives
    # (5u + 28eu)/3: not a term of the side as typed, a number of the working wrong
    found = worst_lines(MEET, START + "v_B2 = (5u - 7eu)/3 + 7eu = (5u + 28eu)/3\n")
    assert found[6] == ("wrong", "arithmetic")
