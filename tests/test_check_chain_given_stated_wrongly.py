"""A chain's given stated in the habit's names with another number (``(v_B)_2 = 2.5 m/s`` where
B moves back at 2.9 m/s): the line states data, nothing is worked out, so the slip is
``copied_wrong`` (not arithmetic), and the lines worked from the number as copied are carried,
not the same mistake again. Every number is worked by hand from the chain file's givens."""

from __future__ import annotations

from support.checked import worst_lines

#: OCR M2 2011: A at 3 m/s, B (0.2 kg) at 1.5 m/s toward it; after, A on at 2 m/s and B back
#: at 2.9 m/s. By hand: e = (2.9 − 2)/(3 + 1.5) = 0.2. With B's 2.9 copied as 2.5 (2.8 would be
#: within a unit of the last figure): e = 0.5/4.5 = 0.111; with A's 2 copied as 2.5: 0.4/4.5 = 0.0889.
CHAIN = "chain-ocr-m2-2011-find-e-mass-then-wall"


def test_bs_velocity_after_restated_with_another_number_is_copied_wrong() -> None:
    work = (
        "positive: A's way before\n"
        "(v_A)_1 = 3, (v_B)_1 = -1.5, (v_A)_2 = 2\n"
        "(v_B)_2 = 2.5 m/s\n"
        "e = (2.5 - 2)/(3 + 1.5) = 0.111\n"
    )
    found = worst_lines(CHAIN, work)
    assert found[3] == ("wrong", "copied_wrong"), found
    assert found[4][0] == "carried", found


def test_latex_as_velocity_after_restated_wrongly() -> None:
    work = (
        "Take $A$'s direction of motion as positive.\n"
        "$(v_A)_1 = 3$ m/s, $(v_B)_1 = -1.5$ m/s, $(v_B)_2 = 2.9$ m/s\n"
        "$(v_A)_2 = 2.5$ m/s\n"
        "$$e = \\frac{2.9 - 2.5}{3 - (-1.5)} = 0.0889$$\n"
    )
    found = worst_lines(CHAIN, work)
    assert found[3] == ("wrong", "copied_wrong"), found
    assert found[4][0] == "carried", found
