"""A chain's name that the student's line of data, before the working, sets to another value of the
same body is the student's own, read by the habit (``u`` before, ``v`` after) on every line after it
(derive/checking/chaindata.py, ``shadowed``). Every number is worked by hand from the problem files."""

from __future__ import annotations

from support.checked import lines


def test_u_before_v_after_where_the_chain_calls_the_velocities_after_u() -> None:
    # chain-aqa-m3-2007-collide-again: A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward it, e = 0.8; the
    # chain's u_A, u_B are the velocities after. Momentum 0.9 - 0.4 = 0.5 = 0.3 v_A + 0.2 v_B;
    # NEL v_B - v_A = 0.8(3 + 2) = 4; so 0.5 v_A + 0.8 = 0.5, v_A = -0.6, v_B = 3.4.
    work = (
        "Before: u_A = 3, u_B = -2 (right positive)\n"
        "0.3 u_A + 0.2 u_B = 0.3 v_A + 0.2 v_B\n"
        "0.5 = 0.3 v_A + 0.2 v_B\n"
        "v_B - v_A = 0.8(u_A - u_B) = 0.8(5) = 4\n"
        "0.5 v_A + 0.8 = 0.5, v_A = -0.6 m/s\n"
        "v_B = 3.4 m/s\n"
    )
    found = lines("chain-aqa-m3-2007-collide-again", work)
    assert [found[n][0] for n in (2, 3, 4, 5, 6)] == ["correct"] * 5


def test_initially_and_finally_in_words_where_the_chain_calls_the_speeds_before_v() -> None:
    # chain-ocr-m2-2011-find-e-mass-then-wall: A at 3 m/s, B (0.2 kg) at 1.5 m/s toward it; after,
    # A on at 2, B back at 2.9; the chain's v_A, v_B are the speeds before. e = (2.9 - 2)/(3 + 1.5)
    # = 0.9/4.5 = 0.2; m_A(3 - 2) = 0.2(2.9 + 1.5) = 0.88, m_A = 0.88 kg.
    work = (
        "Take A's way as positive.\n\n"
        "Initially u_A = 3 m/s, u_B = -1.5 m/s; finally v_A = 2 m/s, v_B = 2.9 m/s.\n\n"
        "e = (v_B - v_A)/(u_A - u_B) = 0.9/4.5 = 0.2\n\n"
        "m_A (u_A - v_A) = 0.2(v_B - u_B) = 0.2(2.9 + 1.5) = 0.88\n"
    )
    found = lines("chain-ocr-m2-2011-find-e-mass-then-wall", work)
    assert [found[n][0] for n in (5, 7)] == ["correct", "correct"]


def test_a_name_set_to_its_own_given_stays_the_chains() -> None:
    # The same chain, v_A and v_B written for the speeds before, as the chain has them (3 and 1.5):
    # e = (2.9 - 2)/(v_A + v_B) = 0.9/4.5 = 0.2 is right in the chain's own names.
    work = "v_A = 3 m/s, v_B = 1.5 m/s\ne = (2.9 - 2)/(v_A + v_B) = 0.9/4.5 = 0.2\n"
    found = lines("chain-ocr-m2-2011-find-e-mass-then-wall", work)
    assert found[2][0] == "correct"
