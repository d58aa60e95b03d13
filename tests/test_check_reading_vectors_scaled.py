"""Vectors as students write them with a factor outside a bracket (issue #31): ``4(cos 60° i +
sin 60° j)``, ``\\frac{u}{\\sqrt{10}}(\\mathbf{i} - 3\\mathbf{j})``, ``28\\,(-\\cos 45^\\circ\\,\\mathbf{i}
+ …)``, ``2(3, 4)``: the factor times each component; and axes placed in words with a pronoun
(``j perpendicular to the wall, away from it``), where "perpendicular to the wall" gives no sign.

Values worked by hand from each problem's givens (never from derive's output):

- ocr-fm-2023-oblique-discs-60deg: A at 4 m/s at 60° to the line of centres (n): u_An = 4 cos 60° = 2,
  u_At = 4 sin 60° = 2√3 = 3.46; B at 6 m/s toward A: u_Bn = -6.
- giancoli-7-18-tennis-ball-wall-45deg: 28 m/s at 45° to the normal, into the wall; e = 1. Along the
  wall 28 sin 45° = 19.8 before and after; into the wall 28 cos 45° = 19.8 before, 19.8 out after.
  With i along the wall and j away from it: u = 19.8 i - 19.8 j, v = 19.8 i + 19.8 j.
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

from derive.checking.frames import declared_axes
from derive.mathtext.reader import read_relations

DISCS = "ocr-fm-2023-oblique-discs-60deg"
WALL = "giancoli-7-18-tennis-ball-wall-45deg"
AXES = "Take i along the wall and j perpendicular to the wall, away from it.\n"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("u = 3(2i - j)", [("u_n", "(3)*(2)"), ("u_t", "(3)*(-1)")]),
        ("v = 2(3, 4)", [("v_n", "(2)*(3)"), ("v_t", "(2)*(4)")]),
        (r"$\mathbf{u} = \frac{u}{2}(\mathbf{i} - \mathbf{j})$", [("u_n", "((u/2))*(1)"), ("u_t", "((u/2))*(-1)")]),
        ("w = sqrt(i + j)", [("w", "sqrt(i + j)")]),  # a function of a bracket: no product
    ],
)
def test_a_factor_outside_a_bracketed_vector_multiplies_each_component(text: str, expected: list) -> None:
    assert [r.sides for r in read_relations(text)] == expected


@pytest.mark.parametrize(
    ("line", "expected"),
    [
        ("u_A = 4(cos 60° i + sin 60° j) = 2i + 3.46j", ["correct"]),
        (r"$\vec{u}_A = 4(\cos 60^\circ\,\hat{\imath} + \sin 60^\circ\,\hat{\jmath})$", ["correct"]),
        ("u_A = 2(1, sqrt(3))", ["correct"]),
        ("u_B = 6(-i)", ["correct"]),
    ],
)
def test_scaled_vectors_on_an_oblique_impact_are_checked(line: str, expected: list) -> None:
    assert statuses(DISCS, line) == expected


def test_a_scaled_vector_with_sine_and_cosine_swapped_is_not_correct() -> None:
    assert "correct" not in statuses(DISCS, "u_A = 4(sin 60° i + cos 60° j)")


def test_away_from_it_after_perpendicular_to_the_wall_turns_j_out_of_the_wall() -> None:
    assert declared_axes(AXES) == {"n": ("t", 1), "t": ("n", -1)}
    assert declared_axes("x along the wall, y perpendicular to the wall and into it") == {
        "n": ("t", 1),
        "t": ("n", 1),
    }


def test_wall_vectors_with_a_factor_and_axes_placed_with_a_pronoun() -> None:
    work = AXES + "u = 28(sin 45° i - cos 45° j)\nv = 28(sin 45° i + cos 45° j)\n"
    assert statuses(WALL, work) == ["correct", "correct"]
    wrong = AXES + "u = 28(sin 45° i - cos 45° j)\nv = 28(sin 45° i - cos 45° j)\n"  # still into the wall
    assert statuses(WALL, wrong) == ["correct", "wrong"]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # After: A's n velocity -3.25 and its t velocity 2√3 = 3.464 (speed 4.75 at 46.8° to the line
        # of centres, reversed along it). cos 46.8° = 0.6845, sin 46.8° = 0.7290: 3.251 and 3.463.
        ("v_A' = 4.75(-cos46.8 i + sin46.8 j)", ["correct"]),  # a function glued to a decimal angle
        ("v_At' = 4.75sin46.8", ["correct"]),
        ("v_An' = -4.75cos46.8°", ["correct"]),
        ("v_At' = 4.75sin56.8", ["wrong"]),  # 3.97: another angle
    ],
)
def test_a_function_glued_to_a_rounded_angle_keeps_the_angle_s_figures(text: str, expected: list) -> None:
    # 46.8 is an angle rounded to 3 figures: sin46.8 is read with its figures as sin 46.8 is.
    assert statuses(DISCS, text) == expected
