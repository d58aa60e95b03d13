"""A kinetic energy by a wrong formula after a given copied wrongly: the energy's line is named
``ke_formula`` (its side is then in the given as the student copied it, no longer the energy's
name), and the working of that formula with the copied given is carried. Values by hand."""

from __future__ import annotations

from support.checked import worst_lines

#: Edexcel M2: a 2 kg ball at 4 m/s into a wall, e = 0.4; the student copies 6 m/s:
#: speed after 0.4 x 6 = 2.4 (for 1.6), then ½m(u - v)² = ½ x 2 x (6 - 2.4)² = 3.6² = 12.96 J.
WALL = "edexcel-m2-ball-rebounds-from-wall"
#: OCR M2 2012: 0.8 kg at 4 m/s into a wall, e = 0.3; the student copies 5 m/s:
#: 0.3 x 5 = 1.5 (for 1.2), then 0.5 x 0.8 x (5 - 1.5)² = 0.4 x 12.25 = 4.9 J.
OCR = "ocr-m2-2012-particle-hits-wall"


def test_the_energy_lost_as_half_m_u_minus_v_squared_after_a_copied_speed() -> None:
    work = (
        "rebound speed = e u\n              = 0.4 x 6\n              = 2.4 m/s\n"
        "loss of KE = 1/2 m (u - v)^2\n           = 1/2 x 2 x (6 - 2.4)^2\n           = 12.96 J\n"
    )
    found = worst_lines(WALL, work)
    assert found[1][0] == "correct"
    assert found[2] == ("wrong", "copied_wrong")
    assert found[3][0] == "carried"
    assert found[4] == ("wrong", "ke_formula")
    assert found[5][0] == found[6][0] == "carried"


def test_the_formula_and_its_numbers_on_one_line_after_a_copied_speed() -> None:
    work = "rebound speed = e u = 0.3 x 5 = 1.5 m/s\nloss of KE = 1/2 m (u - v)^2 = 0.5 x 0.8 x (5 - 1.5)^2 = 4.9 J\n"
    found = worst_lines(OCR, work)
    assert found[1] == ("wrong", "copied_wrong")
    assert found[2] == ("wrong", "ke_formula")
