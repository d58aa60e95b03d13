"""An angle the problem asks for, resolved as if measured from the other axis: named
angle_other_axis where the relation in it is written, and the lines solved from it carried.
Worked by hand (Edexcel M4 2018: e = 3/4, 60% of the kinetic energy kept, α with the wall):
along the wall U cos α, into it U sin α, then (3/4) U sin α out, so cos²α + (9/16) sin²α = 3/5,
sin²α = 32/35 and α = 72.98°. Resolved from the normal: sin²α + (9/16) cos²α = 0.6, so
cos²α = 0.4/0.4375 = 32/35, cos α = 0.9562 and α = 17.02°."""

from __future__ import annotations

from support.checked import lines

PROBLEM = "edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke"


def test_the_asked_angle_resolved_from_the_other_axis_is_named_and_carried() -> None:
    work = (
        "(U sin(alpha))^2 + (0.75 U cos(alpha))^2 = 0.6 U^2\n"
        "sin(alpha)^2 + 0.5625 cos(alpha)^2 = 0.6\n"
        "0.4375 cos(alpha)^2 = 0.4\n"
        "cos(alpha) = 0.9562\n"
        "alpha = 17.0 deg\n"
    )
    found = lines(PROBLEM, work)
    assert found[1][:2] == ("wrong", "angle_other_axis")
    assert [found[n][0] for n in (2, 3, 4, 5)] == ["carried"] * 4


def test_the_asked_angle_resolved_right_is_correct() -> None:
    work = "(U cos(alpha))^2 + (0.75 U sin(alpha))^2 = 0.6 U^2\n0.4375 sin(alpha)^2 = 0.4\nalpha = 73.0 deg\n"
    found = lines(PROBLEM, work)
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3


def test_a_velocity_before_resolved_at_the_students_own_angle_with_sin_for_cos_then_again() -> None:
    # Fisicalab example 7: the line of centres at 20 deg to x, B at 110 m/s at 120 deg to x, so
    # 100 deg from n: v_B1n = 110 cos 100 = -19.10, v_B1t = 110 sin 100 = 108.3. Written with sin
    # for cos: the velocity resolved with sin and cos swapped (not an angle worked from the other
    # axis), and the t component the same mistake made again
    work = (
        "The line of centres is at 20 deg to x, so B moves at 120 - 20 = 100 deg to it.\n"
        "v_B1n = 110 sin(100 deg) = 108.3 m/s\nv_B1t = 110 cos(100 deg) = -19.10 m/s\n"
    )
    found = lines("fisicalab-example-7-normal-at-20deg", work)
    assert found[2] == ("wrong", "sin_cos_swapped", False)
    assert found[3] == ("wrong", "sin_cos_swapped", True)
