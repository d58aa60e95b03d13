"""A negative number written wrong on a slip of arithmetic, then worked into a formula: put right
with its sign, the formula holds, and the line is carried. Every number is worked by hand from
the problem file's givens (in the comments), never taken from derive's output."""

from __future__ import annotations

from support.checked import worst_lines

#: OpenStax: satellites of 4.00e3 kg (at 0.250 m/s) and 7.50e3 kg (at rest) collide elastically.
#: m_A - m_B = -3500 kg; v_A2 = (-3500/11500)(0.250) = -0.07609 m/s. The slip: -3400 for -3500;
#: worked from it, (-3400/11500)(0.250) = -0.07391 = -0.0739, which holds once -3400 is put
#: back as -3500 (not as +3500: its sign is written with it).
SATELLITES = "openstax-cp-8-satellites-elastic"


def test_the_elastic_formula_worked_from_a_negative_number_written_wrong_is_carried() -> None:
    work = (
        "v_A2 = (m_A - m_B)/(m_A + m_B) v_A1\n"
        "m_A - m_B = 4000 - 7500 = -3400 kg\n"
        "m_A + m_B = 11500 kg\n"
        "v_A2 = (-3400/11500)(0.250) = -0.0739 m/s\n"
    )
    found = worst_lines(SATELLITES, work)
    assert found[2][0] == "wrong"
    assert found[3][0] == "correct" and found[4][0] == "carried", found


def test_the_same_with_the_formula_and_its_numbers_on_one_line() -> None:
    work = (
        "A is 1, B is 2.\n"
        "m1 - m2 = 4000 kg - 7500 kg = -3400 kg\n"
        "v1f = (m1 - m2)/(m1 + m2) * v1i = (-3400)(0.250)/11500 = -0.0739 m/s\n"
    )
    found = worst_lines(SATELLITES, work)
    assert found[2][0] == "wrong"
    assert found[3][0] == "carried", found
