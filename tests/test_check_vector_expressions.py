"""A side written in vectors named before (``J = m(v - u) = 0.06(39.6 i)``): on each axis it is the
same expression in their components (``J_n = m(v_n - u_n)``), and a change in momentum written
out as ``m(v - u)`` names the impulse, whatever its sign, as ``m Δv`` does.

Values worked by hand:

- giancoli-7-18-tennis-ball-wall-45deg: m = 0.060 kg, 28 m/s at 45° to the normal, e = 1. With i out
  of the wall and j along it, u = -19.8 i + 19.8 j, v = 19.8 i + 19.8 j (28 cos 45° = 19.80), so
  m(v - u) = 0.060(39.6 i) = 2.376 i, and nothing along j.
- The impulse on the ball m(v - u) along the normal: 0.060(19.8 - (-19.8)) = 2.376 out of the wall,
  or -2.376 into it.
- aqa-m3-2007-spheres-approach-head-on: m_A = 0.3, m_B = 0.2, u_A = 3, u_B = -2, v_A = -0.6,
  v_B = 3.4 (worked in test_check_head_on_vectors). The impulse on B: 0.2(3.4 - (-2)) = 1.08;
  on A: 0.3(-0.6 - 3) = -1.08.
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

from derive.mathtext.reader import read_relations

WALL = "giancoli-7-18-tennis-ball-wall-45deg"
SPHERES = "aqa-m3-2007-spheres-approach-head-on"


def test_a_side_in_vectors_named_before_is_read_per_component() -> None:
    text = "u = 3i + 4j\nv = -3i + 4j\nP = 2(v - u) = -12 i"
    assert [r.sides for r in read_relations(text)][4:] == [("P_n", "2(v_n - u_n)", "-12"), ("P_t", "2(v_t - u_t)", "0")]


def test_a_line_going_on_from_a_vector_goes_on_from_the_vector_not_its_last_component() -> None:
    text = "u = 3i + 4j\nQ = 2u = 6i + 8j\n  = 10(0.6 i + 0.8 j)"
    assert [r.sides for r in read_relations(text)][-2:] == [("6", "(10)*(0.6)"), ("8", "(10)*(0.8)")]


@pytest.mark.parametrize(
    "impulse",
    [
        r"$\vec I = m(\vec v - \vec u) = 0.060\,(39.6\,\hat\imath) = 2.376\,\hat\imath$",
        "I = m(v - u) = 0.06(19.8 i + 19.8 j - (-19.8 i + 19.8 j)) = 2.38 i",
    ],
)
def test_an_impulse_as_a_vector_of_a_change_in_momentum_is_checked(impulse: str) -> None:
    work = f"i out of the wall, j along the wall.\nu = -19.8 i + 19.8 j\nv = 19.8 i + 19.8 j\n{impulse}\n"
    assert statuses(WALL, work)[-1] == "correct"


@pytest.mark.parametrize(
    ("problem", "line"),
    [
        (WALL, "J = m(v - u) = 0.06(19.8 + 19.8) = 2.38"),  # out of the wall positive
        (WALL, "J = m(v - u) = 0.060(-19.8 - 19.8) = -2.376"),  # into the wall positive
        (SPHERES, "J = m_A(v_A - u_A) = 0.3(-0.6 - 3) = -1.08"),
    ],
)
def test_a_change_in_momentum_written_out_names_the_impulse_whatever_its_sign(problem: str, line: str) -> None:
    assert statuses(problem, line) == ["correct"]


def test_a_wrong_impulse_written_out_is_not_correct() -> None:
    assert statuses(SPHERES, "J = m_B(v_B - u_B) = 0.2(3.4 - 2) = 0.28") != ["correct"]
