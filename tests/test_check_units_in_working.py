"""A line that writes its units inside its working (``2(9.8 m/s^2)(1.6 m) = 31.36 m^2/s^2``), as
engineering students do: every unit after a number is taken off, the length ``m`` alone in a
bracket too (metres, not a mass m, in a line that writes a compound unit), and a speed squared
``m^2/s^2`` after the result. Numbers worked by hand from the problem files' givens."""

from __future__ import annotations

from support.checked import lines

from derive.mathtext.sides import units_inside


def test_units_inside_brackets_are_taken_off_and_a_lone_mass_letter_is_not() -> None:
    assert units_inside("2(32.2 ft/s^2)(6 ft)") == "2(32.2)(6)"
    assert units_inside("2(9.8 m/s²)(1.6 m)") == "2(9.8)(1.6)"
    assert units_inside("(0.5 m)(u) + (2 m)(v)") == "(0.5 m)(u) + (2 m)(v)"  # no unit beside: m a mass


def test_a_us_fall_with_units_in_every_line() -> None:
    # Hibbeler 15-58: a drop of 6 ft, g = 32.2 ft/s^2: v_1^2 = 2(32.2)(6) = 386.4, v_1 = 19.657.
    work = "v_1^2 = 2(32.2 ft/s^2)(6 ft) = 386.4 ft^2/s^2\nv_1 = 19.66 ft/s\n"
    found = lines("chain-hibbeler-15-58-suitcases", work)
    assert [found[n][0] for n in (1, 2)] == ["correct", "correct"]


def test_a_slip_in_a_line_with_units_is_found_and_carried() -> None:
    # OCR M2 2006: v_1^2 = 2(9.8)(2) = 39.2 (6.261); the rebound to 1.4 m: 2(9.8)(1.4) = 27.44,
    # written 24.74 (a slip): v_2 = sqrt(24.74) = 4.974, carried.
    work = (
        "v_1^2 = 2(9.8 m/s^2)(2 m) = 39.2 m^2/s^2\n"
        "v_2^2 = 2(9.8 m/s^2)(1.4 m) = 24.74 m^2/s^2\n"
        "v_2 = sqrt(24.74 m^2/s^2) = 4.97 m/s\n"
    )
    found = lines("chain-ocr-m2-2006-drop-rebound", work)
    assert found[1][0] == "correct"
    assert found[2][:2] == ("wrong", "arithmetic")
    assert found[3][0] == "carried"
