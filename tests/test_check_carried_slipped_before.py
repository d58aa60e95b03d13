"""Lines carried after a slip that changed the values before the impact, or the equations of a
world whose unknown is an angle. Every number is worked by hand from the problem files' givens
(in the comments), never taken from derive's output."""

from __future__ import annotations

from support.checked import lines, worst_lines

#: OCR FM 2023: A (5 kg) at 4 m/s at 60° to the line of centres, B (3 kg) at 6 m/s along it
#: toward A, e = 3/4. In radian mode 60 is 60 - 9(2π) = 3.4513 rad past a whole number of
#: turns: cos 60 = -0.95241, sin 60 = -0.30481 (the calculator's), so A's components come out
#: 4(-0.95241) = -3.8096 along and 4(-0.30481) = -1.2192 across (truly 2 and 3.464).
DISCS = "ocr-fm-2023-oblique-discs-60deg"
#: Edexcel M4 2018: a ball at U, its path at α to a smooth wall (e = 3/4), keeps 60 % of its
#: kinetic energy: U cos α along the wall, ¾ U sin α off it after.
WALL = "edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke"


def test_a_component_before_worked_from_the_radian_number_is_carried() -> None:
    # The slip is the calculator's line; the components that put its numbers in carry them:
    # 4(-0.9524) = -3.810 is u_An as the slip has it (4 cos 60 rad), not a slip of arithmetic.
    work = (
        "x along the line of centres from A to B\n"
        "calculator: cos 60 = -0.9524, sin 60 = -0.3048\n"
        "A: u_An = 4(-0.9524) = -3.810 m/s, u_At = 4(-0.3048) = -1.219 m/s\n"
        "5(-3.810) + 3(-6) = 5 v_An + 3 v_Bn\n"
    )
    found = worst_lines(DISCS, work)
    assert found[2] == ("wrong", "degrees_as_radians")
    assert found[3][0] == found[4][0] == "carried", found


def test_the_same_in_latex_one_component_a_line() -> None:
    # 5(-3.8096) + 3(-6) = -37.048: the momentum before with the calculator's component.
    work = (
        "Positive $x$ from A towards B along the line of centres.\n"
        "$$\\cos 60 = -0.95241, \\quad \\sin 60 = -0.30481$$\n"
        "$$u_{An} = 4 \\times (-0.95241) = -3.8096$$\n"
        "$$u_{At} = 4 \\times (-0.30481) = -1.2192$$\n"
        "$$5(-3.8096) + 3(-6) = -37.048$$\n"
    )
    found = worst_lines(DISCS, work)
    assert found[2] == ("wrong", "degrees_as_radians")
    assert [found[n][0] for n in (3, 4, 5)] == ["carried"] * 3, found


def test_a_component_resolved_afresh_the_same_wrong_way_is_the_mistake_again() -> None:
    # No number of the slip's in it: 4 cos 60 = -3.810 resolves A's velocity again in radians.
    work = (
        "x along the line of centres from A to B\n"
        "cos 60 = -0.9524 and sin 60 = -0.3048\n"
        "u_An = 4 cos 60 = -3.810\n"
        "u_At = 4 sin 60 = -1.219\n"
    )
    found = lines(DISCS, work)
    assert found[3] == ("wrong", "degrees_as_radians", True)
    assert found[4] == ("wrong", "degrees_as_radians", True)


def test_an_angle_found_after_a_slip_in_the_velocity_after_is_carried() -> None:
    # e times the speed for the component off the wall: ¾U for ¾U sin α (e_speeds). With U cos α
    # along the wall: cos²α + 9/16 = 0.6, cos²α = 0.0375, cos α = 0.19365, α = 78.83°: the
    # energy, the cosine and the angle all hold with the student's two components, none for the
    # problem (there (7/16) sin²α = 0.4, α = 72.98°).
    work = (
        "after: v_par = U cos(alpha),  v_perp = (3/4) U\n"
        "1/2 m (U^2 cos^2(alpha) + 9/16 U^2) = 0.6 x 1/2 m U^2\n"
        "cos^2(alpha) = 0.6 - 0.5625 = 0.0375\n"
        "alpha = 78.8 deg\n"
    )
    found = worst_lines(WALL, work)
    assert found[1][0] == "wrong"
    assert [found[n][0] for n in (2, 3, 4)] == ["carried"] * 3, found


def test_the_asked_angle_resolved_from_the_other_axis_is_named_so_where_its_world_is_solved() -> None:
    # U sin α along the wall and ¾U cos α off it (α taken from the normal): sin²α + (9/16)cos²α =
    # 0.6, the asked angle from the other axis (angle_other_axis), though the world of sin and cos
    # swapped in the velocity before makes it hold too.
    found = worst_lines(WALL, "(U sin(alpha))^2 + ((3/4) U cos(alpha))^2 = 0.6 U^2\n")
    assert found[1][0] == "wrong"
    assert "angle_other_axis" in found[1][1].split(","), found


#: Byju's: a 4 kg ball at 12 m/s catches an 8 kg ball at 4 m/s (e = 0.5). True energy before:
#: ½(4)(12²) + ½(8)(4²) = 288 + 64 = 352 J; with the masses swapped, ½(8)(12²) + ½(4)(4²) = 576 +
#: 32 = 608 J.
BALLS = "byjus-4kg-ball-catches-8kg-ball"


def test_the_energy_before_with_the_masses_swapped_as_in_the_momentum_is_carried() -> None:
    # The slip swaps the masses in the momentum; the energy before worked with them again is the
    # student's own (608 J), carried, whether labelled in words or under a heading.
    for energy in (
        "Kinetic energy before: 0.5 x 8 x 144 + 0.5 x 4 x 16 = 576 + 32 = 608 J\n",
        "\nKE check:\n- before: 1/2(8)(12)^2 + 1/2(4)(4)^2 = 608 J\n",
        "KE\n* before = 0.5(8)(144) + 0.5(4)(16) = 608\n",
    ):
        found = worst_lines(BALLS, "Momentum: 8 x 12 + 4 x 4 = 112 = 8 v_A + 4 v_B\n" + energy)
        assert found[1] == ("wrong", "masses_swapped")
        assert [s for n, (s, _) in found.items() if n > 1] == ["carried"], (energy, found)
