"""A line after a slip worked from the student's own wrong value is carried even where its
result, at the figures written, is also the problem's: a decimal typed without its leading
zero (``.696``, phone-typed or American) is the same number as ``0.696`` when the checker
asks whether a line uses a number the student got wrong; and an angle that rounds to the
slip's value at its figures and not to the problem's is the student's own. Every number
is worked by hand from the problem files' givens (in the comments)."""

from __future__ import annotations

from support.checked import lines


def test_a_decimal_typed_without_its_zero_is_seen_as_the_wrong_value_it_is() -> None:
    # OpenStax 8-5 goalie: 0.150 kg at 35.0 m/s caught by 70.0 kg: v = 5.25/70.15 = 0.074840,
    # KE after = ½(70.15)(0.074840²) = 0.19646 -> 0.20 J. The goalie's mass alone (70) gives
    # v = 5.25/70 = 0.075; ½(70.15)(0.075²) = 0.19730, also 0.20 J at two figures, but the
    # line is worked from the student's .075: carried, not correct.
    work = "0.150(35.0) = 70 v\nv = 5.25/70 = .075 m/s\nKE after = 1/2 (70.15)(.075)^2 = 0.20 J\n"
    found = lines("openstax-cp-8-5-goalie-catches-puck", work)
    assert found[1][0] == "wrong"
    assert found[3][0] == "carried"


def test_a_speed_worked_from_a_component_typed_without_its_zero_is_carried() -> None:
    # M. Casco disks: equal masses, u_An = 8 cos 30° = 6.9282, e = 0.8: v_An = 0.1(6.9282)
    # = 0.69282, |v_A| = sqrt(0.69282² + 4²) = 4.0596 -> 4.06. With cos 30 as .87: u_An = 6.96,
    # v_An = 0.696, sqrt(.696² + 16) = sqrt(16.4844) = 4.0601 -> 4.06 too: carried.
    work = (
        "n along the line of centres, A to B; t across\n"
        "uAn = 8 cos 30 = 8 x .87 = 6.96\n"
        "uAt = 8 sin 30 = 4\n"
        "vAn + vBn = 6.96\n"
        "vBn - vAn = .8 x 6.96 = 5.568\n"
        "vBn = 6.264, vAn = .696\n"
        "speed of A after = sqrt(.696^2 + 4^2) = 4.06 ft/s\n"
    )
    found = lines("mcasco-glancing-disks-us", work)
    assert found[2][0] == "wrong"
    assert [found[n][0] for n in (4, 5, 6, 7)] == ["carried"] * 4


def test_an_angle_at_the_slips_value_to_its_figures_is_carried() -> None:
    # The same disks: the problem's angle with n is tan⁻¹(4/0.69282) = 80.174° (80.2 to one
    # decimal); from the student's 0.696 it is tan⁻¹(4/0.696) = 80.129° (80.1): the slip's
    # value at the figures written, not the problem's: carried.
    work = (
        "n along the line of centres, A to B; t across\n"
        "uAn = 8 cos 30 = 8 x 0.87 = 6.96\n"
        "uAt = 8 sin 30 = 4\n"
        "vAn + vBn = 6.96\n"
        "vBn - vAn = 0.8 x 6.96 = 5.568\n"
        "vBn = 6.264, vAn = 0.696\n"
        "angle of A's path with n = tan^-1(4/0.696) = 80.1°\n"
    )
    found = lines("mcasco-glancing-disks-us", work)
    assert found[2][0] == "wrong"
    assert found[7][0] == "carried"


def test_an_angle_in_degrees_from_wrong_whole_numbers_that_are_also_givens_is_carried() -> None:
    # OCR M3 2006: A (5 kg) across the line at 4, B (2 kg) at -4 along it, e = 0.75:
    # 5a + 2b = -8, b - a = 3 -> a = -2, b = 1; A's angle with the line tan⁻¹(4/2) = 63.43°.
    # With the masses swapped, 2a + 5b = -20 -> 7a = -35, a = -5, b = -2: tan⁻¹(4/5) = 38.66°
    # (38.7), the slip's angle and none of the problem's, though 4 and 5 are both givens.
    work = (
        "x along the line of centres, A to B\n"
        "2(0) + 5(-4) = 2a + 5b\n"
        "b - a = 0.75(0 + 4) = 3\n"
        "-20 = 2a + 5(a + 3), 7a = -35\n"
        "a = -5, b = -2\n"
        "A keeps 4 across\n"
        "tan^-1(4/5) = 38.7 deg\n"
    )
    found = lines("ocr-m3-2006-oblique-a-across-centres", work)
    assert found[2][:2] == ("wrong", "masses_swapped")
    assert found[7][0] == "carried"
