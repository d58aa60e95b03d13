"""A kinetic energy worked with a speed put in without its square (``T_1 = ½(2)(4) = 4`` for
½(2)(4²) = 16) is a number worked wrongly, ``arithmetic``, as teachers mark a speed left
unsquared anywhere (``v² = u² + 2gh = 5 + …``); a formula of its own that is wrong (m v² without
the half, ½ m (u − v)² for the energy lost) stays ``ke_formula``. Values by hand."""

from __future__ import annotations

from support.checked import worst_lines

#: Edexcel M2: a 2 kg ball at 4 m/s into a wall, e = 0.4, back at 1.6 m/s.
#: KE before ½(2)(4²) = 16 J, after ½(2)(1.6²) = 2.56 J, lost 13.44 J.
WALL = "edexcel-m2-ball-rebounds-from-wall"

#: OCR M2 2006: 2 kg at 5 m/s hits 1 kg at rest, A on at 2 m/s, so B at 6 m/s.
#: KE before ½(2)(5²) = 25 J; after ½(2)(2²) + ½(1)(6²) = 4 + 18 = 22 J; lost 3 J.
OCR_2006 = "ocr-m2-2006-sphere-hits-sphere-at-rest-find-e"


def test_one_body_speed_left_unsquared_is_arithmetic() -> None:
    found = worst_lines(WALL, "KE before = 1/2 * 2 * 4 = 4 J\n")
    assert found[1] == ("wrong", "arithmetic")


def test_two_bodies_speeds_left_unsquared_after_is_arithmetic() -> None:
    work = "v_B2 = 6\nT_2 = 0.5(2)(2) + 0.5(1)(6) = 5\n"
    found = worst_lines(OCR_2006, work)
    assert found[1][0] == "correct"
    assert found[2] == ("wrong", "arithmetic")


def test_the_half_left_out_stays_ke_formula() -> None:
    found = worst_lines(WALL, "KE before = 2(4)^2 = 32 J\n")
    assert found[1] == ("wrong", "ke_formula")
