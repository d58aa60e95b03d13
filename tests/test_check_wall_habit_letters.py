"""At a wall, a component named by its axis's sign and the letter v with no time said (``v_⊥``,
``v_\\perp``, ``v_perp``) is after the impact by the habit's letters (u before, v after), as a
teacher reads ``v_∥ = U cos α, v_⊥ = ¾ U sin α`` under "the perpendicular component becomes three
quarters of what it was". A name also written primed (``v_⊥'``) keeps its own marks. A way
declared positive by a bare plus after a verb of choosing (``Take $+$ = out of the wall``) is the
student's sign convention.

Values worked by hand. The cushion of Edexcel FM1 2023 Q7a (speed U at α to the cushion,
restitution e_1): along it U cos α before and after, across it U sin α before, e_1 U sin α after.
Support.checked.WALL_30: a 0.5 kg ball at 10 m/s, 30° to a smooth wall,
e = 0.5: along the wall 10 cos 30° = 8.660, into it 10 sin 30° = 5; after, along it 8.660 and out
of it 0.5 × 5 = 2.5.
"""

from __future__ import annotations

import pytest
from support.checked import wall_30_lines, worst_lines

from derive.checking.conventions import plus_said

CUSHION = "edexcel-fm1-2023-june-q7a-cushion-show-tan-beta"


def test_letters_only_components_after_by_the_habit() -> None:
    got = worst_lines(CUSHION, "$$v_{\\parallel} = U\\cos\\alpha, \\qquad v_{\\perp} = e_1 U\\sin\\alpha$$\n")
    assert got == {1: ("correct", "")}


def test_letters_only_rebound_with_e_left_out_is_a_slip() -> None:
    # u names the components before, so v's are after: v⊥ = U sin α has e_1 left out
    got = worst_lines(CUSHION, "u∥ = U cos α\nu⊥ = U sin α\nv∥ = U cos α\nv⊥ = U sin α\n")
    assert [got[n][0] for n in (1, 2, 3)] == ["correct"] * 3 and got[4][0] == "wrong"


def test_v_resolved_alone_with_no_u_is_the_velocity_before() -> None:
    # no u anywhere: "v⊥ = U sin α" resolves the velocity before (the student's v is the ball's
    # velocity), as a teacher reads it; the habit's v-after needs the habit's u-before
    got = worst_lines(CUSHION, "v∥ = U cos α\nv⊥ = U sin α\n")
    assert [got[n][0] for n in (1, 2)] == ["correct", "correct"]


def test_a_primed_twin_keeps_the_unprimed_name_before() -> None:
    got = worst_lines(CUSHION, "v_perp = U sin(alpha)\nv_perp' = e_1 U sin(alpha)\n")
    assert [got[n][0] for n in (1, 2)] == ["correct", "correct"]


def test_v_with_the_perpendicular_sign_and_no_time_is_after(tmp_path) -> None:
    work = "$u_\\perp = 10\\sin 30^\\circ = 5$\n$v_\\perp = 0.5 \\times 5 = 2.5$\n"
    assert wall_30_lines(tmp_path, work) == ["correct", "correct"]


def test_plain_typed_pair_on_one_line(tmp_path) -> None:
    work = "v_par = 10 cos 30 = 8.66,   v_perp = 0.5(10 sin 30) = 2.5\n"
    assert wall_30_lines(tmp_path, work) == ["correct"]


def test_e_forgotten_after_is_a_slip_not_a_line_not_read(tmp_path) -> None:
    work = "u⊥ = 10 sin 30 = 5\nv⊥ = 5\n"  # the rebound's size is 2.5: e left out
    assert wall_30_lines(tmp_path, work) == ["correct", "wrong"]


@pytest.mark.parametrize(
    ("line", "sign"),
    [
        ("Take $+$ = out of the wall. $m = 0.5$ kg", -1),
        ("taking + as away from the wall", -1),
        ("Take + = towards the wall", 1),
        ("take the 3 + 4 = 7", 0),
    ],
)
def test_a_bare_plus_after_a_verb_of_choosing_declares_the_way(line: str, sign: int) -> None:
    assert plus_said(line) == sign
