"""After a slip of rounding too early, the lines worked from the student's rounded values before the
impact are carried: the slip's world is the problem solved with the components as the student
stated them (``roundedworld.py``). And a first side of names the derivation works with on other
lines is judged, not dropped as a label before a working in numbers (``byvalue.worked_names``).
Every number is worked by hand from the problem files' givens (in the comments)."""

from __future__ import annotations

from support.checked import worst_lines

# M. Casco's disks: equal weights (47 lb), e = 0.8, A at 8 ft/s at 30° to the line of centres, B at
# rest. u_An = 8 cos 30° = 6.9282, u_At = 4; v_An + v_Bn = 6.9282, v_Bn - v_An = 0.8(6.9282) = 5.5426,
# so v_Bn = 6.2354, v_An = 0.6928. With u_An rounded to 6.9: v_Bn - v_An = 0.8(6.9) = 5.52 (5.54 at
# three figures: the rounding has moved it, rounded_too_early); v_Bn = (6.9 + 5.52)/2 = 6.21 (6.24 is
# the problem's), v_An = 6.9 - 6.21 = 0.69: both worked from the student's 6.9, carried.
DISKS = "mcasco-glancing-disks-us"


def test_velocities_solved_from_a_component_rounded_early_are_carried() -> None:
    work = (
        "n along the line of centres, A to B; t across\n"
        "uAn = 8 cos 30 = 6.928 = 6.9\n"
        "uAt = 8 sin 30 = 4\n"
        "vAn + vBn = 6.9\n"
        "vBn - vAn = 0.8 x 6.9 = 5.52\n"
        "2 vBn = 6.9 + 5.52 = 12.42 so vBn = 6.21\n"
        "vAn = 6.9 - 6.21 = 0.69\n"
    )
    found = worst_lines(DISKS, work)
    assert found[5] == ("wrong", "rounded_too_early")
    assert [found[n][0] for n in (6, 7)] == ["carried", "carried"]


def test_the_same_in_bracketed_names_in_markdown() -> None:
    work = (
        "**Along the line of centres** (A towards B positive)\n\n"
        "- $(v_A)_{1n} = 8\\cos 30^\\circ \\approx 6.9$ ft/s\n"
        "- momentum: $(v_A)_{2n} + (v_B)_{2n} = 6.9$\n"
        "- restitution: $(v_B)_{2n} - (v_A)_{2n} = 0.8(6.9 - 0) = 5.52$\n"
        "- adding: $2(v_B)_{2n} = 12.42$, $(v_B)_{2n} = 6.21$ ft/s\n"
        "- $(v_A)_{2n} = 6.9 - 6.21 = 0.69$ ft/s\n"
    )
    found = worst_lines(DISKS, work)
    assert found[5] == ("wrong", "rounded_too_early")
    assert [found[n][0] for n in (6, 7)] == ["carried", "carried"]


def test_names_worked_on_other_lines_are_judged_before_a_working_in_numbers() -> None:
    # Example 4.C.11: A (20 kg) at 5 m/s, B (5 kg) at 15 m/s, each at 37.6° to n, e = 0.6. A's n
    # component taken as 5 sin 37.6° = 3.05 (sin and cos swapped; 5 cos 37.6° = 3.96 is right);
    # B's -15 cos 37.6° = -11.9 right. In that slip's world the momentum 20(3.05) + 5(-11.9) =
    # 61.0 - 59.5 = 1.5 = 20a + 5b is carried, and the restitution is b - a = 0.6(3.05 + 11.9) =
    # 8.97: written a - b = 8.97 it is the rule the wrong way round, a new slip, though its
    # arithmetic 0.6(14.95) = 8.97 is right (a and b are placed by the momentum, not by this line).
    work = (
        "A_n = 5 sin 37.6 = 3.05\n"
        "B_n = -15cos37.6 = -11.9\n"
        "CLM: 20(3.05) + 5(-11.9) = 1.5 = 20a + 5b\n"
        "NEL: a - b = 0.6(3.05 + 11.9) = 8.97\n"
    )
    found = worst_lines("notes-4c11-two-spheres", work)
    assert found[1] == ("wrong", "sin_cos_swapped")
    assert found[3][0] == "carried"
    assert found[4] == ("wrong", "restitution_reversed")


def test_a_name_no_reading_places_keeps_its_working_judged() -> None:
    # OCR 2014: 2m at 4 m/s, 3m at -2 m/s, e = 0.4. The reduced mass is 2m·3m/5m = 6m/5 = 1.2m; the
    # student's 1.5m is a number worked wrongly. M, written on both lines, is no quantity a reading
    # by value places (the masses are 2m, 3m and 5m): its first line's working is judged, as for a
    # name written once, and the energy lost from it, ½(1.5m)(1 - 0.16)(6²) = 22.68m (18.144m for
    # the problem), is carried.
    work = "M = 2m x 3m / 5m = 1.5m\nKE lost = 1/2 M (1 - e^2)(6)^2 = 1/2 (1.5m)(0.84)(36) = 22.68m\n"
    found = worst_lines("ocr-m2-2014-particles-2m-3m-ke-lost", work)
    assert found[1] == ("wrong", "arithmetic")
    assert found[2][0] == "carried"
