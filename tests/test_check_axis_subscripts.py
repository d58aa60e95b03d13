"""A component named by its axis's sign as a subscript: ``v_\\perp``, ``v_{\\parallel}`` in LaTeX,
``u∥``, ``u⊥``, ``v_⊥`` typed in Unicode (on a phone, glued to the letter). It is the subscript
parallel or perpendicular; the line's lead-in (``After:``, ``A b4:``) or the habit's letter u
says the time, and the right side's given velocity the body. At a wall, parallel is along it
(t) and perpendicular into it (n); between two bodies parallel is along the line of centres (n).

Values worked by hand:
- a 0.5 kg ball at 10 m/s, 30° to a smooth wall, e = 0.5: along the wall 10 cos 30° = 8.660,
  into it 10 sin 30° = 5; after, along it 8.660 and out of it 0.5 × 5 = 2.5.
- Example 4.C.11 (A at 5 m/s, 37.6° to the line of impact): along it 5 cos 37.6° = 3.961,
  across it 5 sin 37.6° = 3.051.
"""

from __future__ import annotations

import pytest
from support.checked import wall_30_lines, worst_lines

from derive.mathtext.reader import read_relations
from derive.mathtext.subscripted import axis_subscripts


@pytest.mark.parametrize(
    ("typed", "name"),
    [
        (r"$v_\perp = 2.5$", "v_perpendicular"),
        (r"$v_{\parallel} = 8.66$", "v_parallel"),
        ("u∥ = 3.96", "u_parallel"),
        ("u⊥ = 3.05", "u_perpendicular"),
        ("v_⊥ = 2.5", "v_perpendicular"),
        ("v_A⊥ = 2.5", "v_Aperpendicular"),
    ],
)
def test_an_axis_sign_as_a_subscript_is_read(typed: str, name: str) -> None:
    assert [r.sides[0] for r in read_relations(typed)] == [name]


def test_a_sign_between_names_is_no_subscript() -> None:
    assert axis_subscripts(r"a \perp b") == r"a \perp b"
    assert axis_subscripts("AB⊥CD") == "AB⊥CD"
    assert [r.sides for r in read_relations("⊥ = 3.05")] == [("perpendicular", "3.05")]


def test_components_at_a_wall_in_latex_signs(tmp_path) -> None:
    work = (
        "Before: $u_\\parallel = 10\\cos 30^\\circ = 8.660$\n"
        "Before: $u_\\perp = 10\\sin 30^\\circ = 5$\n"
        "After: $v_\\parallel = 8.660$\n"
        "After: $v_\\perp = 0.5 \\times 5 = 2.5$\n"
    )
    assert wall_30_lines(tmp_path, work) == ["correct"] * 4


def test_components_at_a_wall_with_e_on_the_wrong_one(tmp_path) -> None:
    work = "Before: $u_\\perp = 10\\sin 30^\\circ = 5$\nAfter: $v_\\parallel = 0.5(10\\cos 30^\\circ) = 4.330$\n"
    assert wall_30_lines(tmp_path, work) == ["correct", "wrong"]


def test_phone_typed_components_of_two_bodies() -> None:
    right = worst_lines("notes-4c11-two-spheres", "A b4: u∥ = 5cos37.6 = 3.96, u⊥ = 5sin37.6 = 3.05\n")
    assert right[1][0] == "correct", right
    swapped = worst_lines("notes-4c11-two-spheres", "A b4: u∥ = 5sin37.6 = 3.05, u⊥ = 5cos37.6 = 3.96\n")
    assert swapped[1] == ("wrong", "sin_cos_swapped"), swapped
