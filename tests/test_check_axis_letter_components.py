"""A velocity's letter glued to an axis's letter (``vx``, ``vy``, ``vx'``) is that component, never
the product v·x where the student has also named a speed v; the same name under ``Before:`` and
``After:`` (a Markdown list's ``- after:`` too) is two quantities, before and after, as ``vx`` and
``vx'`` are. At a wall, the way out of it taken positive turns the normal round, not the wall's
own direction: the component along the wall keeps its sign.

Values worked by hand (support.checked.WALL_30): a 0.5 kg ball at 10 m/s, 30° to a smooth wall,
e = 0.5: along the wall 10 cos 30° = 8.660 before and after; into it 10 sin 30° = 5 before, and
0.5 × 5 = 2.5 out of it after. With x out of the wall: vx = −5 before, +2.5 after; vy = 8.66.
"""

from __future__ import annotations

from support.checked import wall_30_lines

from derive.checking.naming import rewrite


def test_vx_is_a_name_not_v_times_x() -> None:
    assert rewrite("m(vx_p - vx)", {"v", "m", "vx"}) == "m(vx_p - vx)"
    assert rewrite("16ux", {"u", "x"}) == "16 u x"  # x the student's velocity of P: u times x


def test_before_and_after_labels_with_x_out_of_the_wall(tmp_path) -> None:
    work = (
        "v = 10 m/s, x out of the wall, y along it\n"
        "- before: vx = -10 sin 30 = -5, vy = 10 cos 30 = 8.66\n"
        "- after: vx = +2.5, vy = 8.66\n"
    )
    assert wall_30_lines(tmp_path, work) == ["correct"] * 3


def test_e_forgotten_under_after_is_a_slip(tmp_path) -> None:
    work = "v = 10 m/s\nbefore: vx = 10 sin 30 = 5\nafter: vx = -5\n"  # the rebound is 2.5 out: e left out
    assert wall_30_lines(tmp_path, work) == ["correct", "correct", "wrong"]


def test_primed_twin_in_derive_s_way(tmp_path) -> None:
    work = "vx = 10 sin 30 = 5\nvx' = -0.5(5) = -2.5\nvy' = 8.66\n"
    assert wall_30_lines(tmp_path, work) == ["correct"] * 3
