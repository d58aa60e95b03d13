"""A quantity labelled in words and worked in numbers (``KE after: ½(2)(2²) + ½(1)(5²) = …``) after
a slip: where its numbers are the student's own values (their v_B, carried from the slip), the
line is carried, not a new slip. Every number is worked by hand from the problem's givens."""

from __future__ import annotations

from support.checked import worst_lines


def test_an_energy_labelled_in_words_worked_from_a_carried_velocity_is_carried() -> None:
    # OCR M2 2006 Q8: A 2 kg at 5 m/s, B 1 kg at rest, A goes on at 2 m/s. True: 10 = 4 + v_B,
    # v_B = 6; KE after = ½(2)(4) + ½(1)(36) = 4 + 18 = 22 J. Slip: 10 − 4 worked as 5, so the
    # student's v_B = 5 and their KE after = 4 + 12.5 = 16.5 J: right with their own v_B.
    work = (
        "2(5) + 1(0) = 2(2) + 1 v_B\n"
        "10 = 4 + v_B\n"
        "v_B = 5 m/s\n"
        "KE after: 1/2 (2)(2^2) + 1/2 (1)(5^2) = 4 + 12.5 = 16.5 J\n"
    )
    found = worst_lines("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work)
    assert found[1][0] == found[2][0] == "correct"
    assert found[3][0] == "wrong"
    assert found[4][0] == "carried"
