"""A value stored in the calculator's memory and recalled by its letter in a later line
(``= 352 J  (STO A)`` then ``A - B``): the note is no part of the value, and the letter alone is the
value stored, even where it is a body's letter too.

Values worked by hand: BYJU'S 4 kg ball at 12 m/s catches an 8 kg ball at 4 m/s, e = 0.5:
80 = 4 v_A + 8 v_B, v_B - v_A = 0.5(12 - 4) = 4, so v_A = 4, v_B = 8 (m/s). Kinetic energy
before 0.5(4)(144) + 0.5(8)(16) = 288 + 64 = 352 J; after 0.5(4)(16) + 0.5(8)(64) = 32 + 256 = 288 J;
lost 352 - 288 = 64 J.
"""

from __future__ import annotations

from support.checked import worst_lines

from derive.mathtext.memories import recalled, stored

PROBLEM = "byjus-4kg-ball-catches-8kg-ball"
WORK = """T1 = 0.5(4)(12^2) + 0.5(8)(4^2) = 352 J   (STO A)
T2 = 0.5(4)(4^2) + 0.5(8)(8^2) = 288 J  [stored in B]
T_lost = A - B = 64 J
"""


def test_the_note_is_taken_off_and_its_letter_kept() -> None:
    assert stored("T1 = 352 J   (STO A)") == ("T1 = 352 J", "A")
    assert stored("x = 3.5 → STO M") == ("x = 3.5", "M")
    assert stored("v = 3 (to the right) A") == ("v = 3 (to the right) A", "")  # no word of storing


def test_only_the_letter_alone_is_recalled() -> None:
    assert recalled(("v_A + A", "2A'"), {"A": "352"}) == ("v_A + (352)", "2A'")


def test_values_recalled_from_memory_are_judged() -> None:
    found = worst_lines(PROBLEM, WORK)
    assert {n: found[n][0] for n in (1, 2, 3)} == dict.fromkeys((1, 2, 3), "correct")


def test_a_recalled_value_worked_wrongly_is_wrong() -> None:
    found = worst_lines(PROBLEM, WORK.replace("A - B = 64", "A - B = 46"))
    assert found[3][0] == "wrong"
