"""Which quantity a sign lost belongs to, decided from what the student wrote before.

A line that puts the numbers into the relation just written in names, a given velocity with
its sign lost, is ``b_sign`` (a velocity taken the wrong way), not a slip of rearranging, and
the relation's names written after mean the value as the student took it (carried); a line
that works out a relation of numbers in which the sign was written is ``arithmetic`` (the
sign lost in the working). Values by hand from the problems' givens."""

from __future__ import annotations

from support.checked import worst_lines

#: AQA FM specimen: A (0.8 kg) and B (0.4 kg) each at 6 m/s toward each other; A moves back at
#: 1.2 m/s. A's way +: 0.8(6) + 0.4(-6) = 2.4 = 0.8(-1.2) + 0.4 v_B, v_B = 3.36/0.4 = 8.4, e =
#: (8.4 + 1.2)/12 = 0.8. A's after taken as +1.2: 2.4 = 0.96 + 0.4 v_B, v_B = 1.44/0.4 = 3.6,
#: e = (3.6 - 1.2)/12 = 0.2.
DISCS = "aqa-fm-specimen-discs-show-e-0p8"
#: OCR M2 2006: A (2 kg) and B (1 kg) meet head-on at 5 m/s each, e = 0.8; A's way +:
#: 2(5) + 1(-5) = 5 = 2 v_A + v_B (B's sign lost: 10 + 5 = 15).
MEET = "ocr-m2-2006-spheres-meet-at-5-ke-lost"


def test_a_given_velocity_put_into_the_names_with_its_sign_lost_is_b_sign_and_its_name_after_carried() -> None:
    work = (
        "m_A u_A + m_B u_B = m_A v_A + m_B v_B\n"
        "0.8(6) + 0.4(-6) = 0.8(1.2) + 0.4 v_B\n"
        "2.4 = 0.96 + 0.4 v_B\n"
        "v_B = 3.6\n"
        "e = (v_B - v_A)/(u_A - u_B) = (3.6 - 1.2)/(6 + 6) = 0.2\n"
    )
    found = worst_lines(DISCS, work)
    assert found[1][0] == "correct"
    assert found[2] == ("wrong", "b_sign")
    assert [found[n][0] for n in (3, 4, 5)] == ["carried"] * 3


def test_phone_typed_with_stars_it_is_b_sign_too() -> None:
    work = "mA*uA + mB*uB = mA*vA + mB*vB\n0.8*6 + 0.4*(-6) = 0.8*1.2 + 0.4*vB\nvB = 3.6\n"
    found = worst_lines(DISCS, work)
    assert found[2] == ("wrong", "b_sign")
    assert found[3][0] == "carried"


def test_a_sign_written_on_the_line_before_and_lost_working_it_out_is_arithmetic() -> None:
    found = worst_lines(MEET, "2(5) + 1(-5) = 2 v_A + v_B\n15 = 2 v_A + v_B\n")
    assert found[1][0] == "correct"
    assert found[2] == ("wrong", "arithmetic")
    # taken the wrong way when first put in, it is the velocity's sign
    found = worst_lines(MEET, "2(5) + 1(5) = 2 v_A + v_B\n15 = 2 v_A + v_B\n")
    assert found[1] == ("wrong", "b_sign")


def test_a_given_velocity_moved_across_with_its_sign_kept_while_put_in_is_not_b_sign() -> None:
    # v_B - v_A = e(u_A - u_B) with A's -1.2 moved across: v_B = 12e - 1.2; written + 1.2 (the
    # move's sign, not the velocity's: the relation is not the one before with values put in),
    # so not b_sign (named as the step's slip, as before)
    found = worst_lines(DISCS, "v_B - v_A = e(u_A - u_B)\nv_B = e(6 + 6) + 1.2\n")
    assert found[1][0] == "correct"
    assert found[2][0] == "wrong" and found[2][1] in ("algebra", "arithmetic")
