"""Working that uses a number the student rounded to two figures: rounded too early, though the
number the line ends in is within a unit of its last place of the problem's value (the slack a
line is allowed for intermediates rounded to three figures, the notes' rule), and a decimal
typed without its leading zero (``.71``) is such a number as much as ``0.71`` is
(derive/checking/figures.py, :func:`worked_early`; derive/checking/rounding.py).

Every value is worked by hand from the problem's givens."""

from __future__ import annotations

from support.checked import lines

BULLET = "chain-msu-bullet-block-swings"  # 0.020 kg at 300 m/s into a 4.0 kg block, g = 9.81
TENNIS = "giancoli-7-18-tennis-ball-wall-45deg"  # 0.060 kg at 28 m/s, 45° to the normal, e = 1


def test_a_chain_stage_worked_from_a_speed_rounded_to_two_figures() -> None:
    # V = 6/4.02 = 1.49254: 1.5 is right at two figures as stated. The swing from it:
    # 1.5^2/19.62 = 0.11468, the problem's h = 1.49254^2/19.62 = 0.11354 (0.114): 1 % off,
    # more than three-figure working allows; 0.115 is near 0.1135 only at its own last place.
    work = "0.020 x 300 = 4.02 V\nV = 6/4.02 = 1.5 m/s\nh = V^2/(2 x 9.81) = 1.5^2/19.62 = 0.115 m\n"
    found = lines(BULLET, work)
    assert found[2][0] == "correct"
    assert found[3][:2] == ("wrong", "rounded_too_early")


def test_a_chain_stage_worked_from_three_figures_stays_correct() -> None:
    # The same with V at three figures: 1.49^2/19.62 = 0.11315 (0.113), the problem's 0.11354:
    # within the slack of three-figure working, correct.
    work = "0.020 x 300 = 4.02 V\nV = 6/4.02 = 1.49 m/s\nh = V^2/(2 x 9.81) = 1.49^2/19.62 = 0.113 m\n"
    found = lines(BULLET, work)
    assert [found[n][0] for n in (1, 2, 3)] == ["correct", "correct", "correct"]


def test_cos_45_typed_as_point_71_on_a_phone() -> None:
    # 28 cos 45 = 19.799; 28 x .71 = 19.88 (cos 45 = 0.7071 at two figures): rounded too early.
    # The impulse from it, 2(0.060)(19.88) = 2.3856 (2.39; the problem's 2.3759, 2.38): carried.
    work = "vn = 28cos45 = 28x.71 = 19.88\nJ = 2 x .060 x 19.88 = 2.39\n"
    found = lines(TENNIS, work)
    assert found[1][:2] == ("wrong", "rounded_too_early")
    assert found[2][0] == "carried"
