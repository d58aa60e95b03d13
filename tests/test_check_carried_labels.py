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


def test_a_mass_restated_wrongly_after_a_slip_is_carried_into_the_energy_worked_from_it() -> None:
    # OpenStax 8-5: a 0.150 kg puck at 35.0 m/s caught by a 70.0 kg goalie at rest. True:
    # 0.150(35.0) = 5.25 = 70.15 v, v = 0.07484 m/s. Slip 1: the puck left out after, 5.25 = 70.0 v,
    # v = 0.075. Slip 2: the puck's 150 g restated as 1.50 kg; the energy before worked with it,
    # ½(1.50)(35.0)² = 918.75 J (true ½(0.150)(35.0)² = 91.875 J): right with their own mass, carried.
    work = (
        "0.150(35.0) = 70.0 v\n"
        "v = 5.25/70.0 = 0.075 m/s\n"
        "m_p = 150 g = 1.50 kg\n"
        "KE before = 1/2 (1.50)(35.0)^2 = 918.75 J\n"
    )
    found = worst_lines("openstax-cp-8-5-goalie-catches-puck", work)
    assert found[1][0] == "wrong"
    assert found[3][0] == "wrong"
    assert found[4][0] == "carried"
