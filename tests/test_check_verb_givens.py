"""Two givens on one line joined by a verb of what the body has (``$m_B = 1$ kg has $u_B = -5$
m/s``): two relations, each judged, not one chain ``m_B = 1 kg has u_B = -5`` that makes the
mass -5 (a given copied wrongly). Words of a condition after a value still belong to it."""

from __future__ import annotations

from support.checked import worst_lines

from derive.mathtext.reader import read_relations

#: OCR M2 2006: A (2 kg) and B (1 kg) meet head-on at 5 m/s each: 2(5) + 1(-5) = 2v_A + v_B.
MEET = "ocr-m2-2006-spheres-meet-at-5-ke-lost"


def test_a_mass_and_a_velocity_joined_by_has_are_two_givens() -> None:
    work = "Sphere B: $m_B = 1$ kg has $u_B = -5$ m/s.\n$2(5) + 1(-5) = 2v_A + v_B$\n"
    found = worst_lines(MEET, work)
    assert found[1][0] == found[2][0] == "correct"


def test_the_verb_and_its_words_are_dropped_but_a_condition_is_kept() -> None:
    sides = [r.sides for r in read_relations("the car: m = 1200 kg was travelling at speed u = 15 m/s")]
    assert ("m", "1200") in sides and ("u", "15") in sides
    assert [r.sides for r in read_relations("v = 2 when e = 1")] == [("v", "2 when e", "1")]
