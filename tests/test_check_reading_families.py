"""Families of lines a teacher reads and derive did not (issue #31): a part's label after a
relation (``= 0.250 m/s   (a)``), the value said again in brackets as a speed with a direction
(``= -0.025 m/s (i.e. 0.025 m/s ←)``), a box around the mathematics in text (``\\fbox{$…$}``), a
quantity said in words on a wall problem (``velocity after``, ``speed after = e x speed before``),
a chain whose first sides are words (``impulse = change in momentum = …``), and an own quantity
worked out on one line and said again on a later one (``J = … = 1.76`` then ``so J ≈ 1.76``).

Values worked by hand from each problem's givens (never from derive's output):

- byjus-4kg-ball-catches-8kg-ball: m_A = 4, m_B = 8, e = 0.5, v_A1 = 12, v_B1 = 4 (m/s). Momentum
  48 + 32 = 80; v_B2 - v_A2 = 0.5(8) = 4; 12 v_A2 = 48: v_A2 = 4, v_B2 = 8. Impulse on B 8(8 - 4) = 32.
- edexcel-m2-ball-rebounds-from-wall: m = 2 kg, u = 4 m/s into the wall (+), e = 0.4: v = -1.6 m/s
  (1.6 m/s away from the wall); impulse 2(1.6 + 4) = 11.2 N s; KE lost 16 - 2.56 = 13.44 J.
- aqa-m3-2014-symbolic-2m-hits-m: 4u = 2 v_A + v_B, v_B - v_A = 4u/3: v_A = 8u/9, v_B = 20u/9.
"""

from __future__ import annotations

import functools

import pytest

import derive
from derive.mathtext.reader import read_relations

DIRECT = "byjus-4kg-ball-catches-8kg-ball"
WALL = "edexcel-m2-ball-rebounds-from-wall"
SYMBOLIC = "aqa-m3-2014-symbolic-2m-hits-m"


def sides(text: str) -> list[tuple[str, ...]]:
    return [r.sides for r in read_relations(text)]


@functools.cache
def _solution(problem: str):
    return derive.solve(derive.load(problem))


def statuses(problem: str, text: str) -> list[str]:
    return [i.status for i in derive.check(_solution(problem), derivation=text).items if i.kind == "line"]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("v_B2 = 0.200 + 0.050 = 0.250 m/s   (a)", [("v_B2", "0.200 + 0.050", "0.250")]),
        ("m_B = 0.00600/0.250 = 0.0240 kg   (b)", [("m_B", "0.00600/0.250", "0.0240")]),
        ("v_A2 = 4 m/s (a)(ii)", [("v_A2", "4")]),
        ("v_A2 = 4 ... (c)", [("v_A2", "4")]),
        ("v_A2 = 4 m/s -- part (b)", [("v_A2", "4")]),
        ("v_A2 = 4 m/s [b]", [("v_A2", "4")]),
        ("v = 2 (a)", [("v", "2 (a)")]),  # no gap, no unit: a product, as typed
    ],
)
def test_a_parts_label_after_a_relation_is_no_part_of_it(text: str, expected: list) -> None:
    assert sides(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "\\begin{align*}\n(v_A)_2 &= -0.025 \\text{ m/s} \\quad (\\text{i.e. } 0.025 \\text{ m/s} \\leftarrow)\n"
            "\\end{align*}",
            [("v_A2", "-0.025")],
        ),
        ("v = -0.025 m/s (so 0.025 m/s ←)", [("v", "-0.025")]),
        ("v = -1.6 (so 1.6 m/s away from the wall)", [("v", "-1.6")]),
        ("v_A2 = -3 (3 m/s to the left)", [("v_A2", "-3")]),
        ("v_B2 = 2.4 m/s (2.4 m/s in the original direction)", [("v_B2", "2.4")]),
        ("x = 0.2 (28)", [("x", "0.2 (28)")]),  # another number: a product
    ],
)
def test_the_value_said_again_in_brackets_is_a_remark(text: str, expected: list) -> None:
    assert sides(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (r"\fbox{$v_A = \frac{16u}{9},\ v_B = \frac{4u}{9}$}", [("v_A", "(16u)/9"), ("v_B", "(4u)/9")]),
        (r"\colorbox{yellow}{$v = 2$}", [("v", "2")]),
        (r"\fcolorbox{red}{white}{$v_A = 2$ m/s}", [("v_A", "2")]),
        (r"\textbf{$v = 2$}", [("v", "2")]),
        ("v_{A2} = 4", [("v_A2", "4")]),  # braces of plain text stay
    ],
)
def test_a_box_around_mathematics_in_text_is_layout(text: str, expected: list) -> None:
    assert sides(text) == expected


@pytest.mark.parametrize(
    ("problem", "text"),
    [
        (DIRECT, "v_A2 = 4 m/s   (a)\nv_B2 = 8 m/s   (b)"),
        (DIRECT, "v_A2 = 48/12 = 4 m/s (c)(ii)"),
        (WALL, "v_A2 = -1.6 m/s (i.e. 1.6 m/s away from the wall)"),
        (WALL, "v = -1.6 (so 1.6 m/s ←)"),
        (DIRECT, r"\fbox{$v_{A2} = 4,\ v_{B2} = 8$}"),
        (SYMBOLIC, r"\fbox{$v_A = \frac{8u}{9},\ v_B = \frac{20u}{9}$}"),
        (WALL, "impulse = change in momentum = 2(1.6) - 2(-4) = 11.2 N s"),
        (WALL, "velocity after = -1.6 m/s"),
        (WALL, "So velocity after $= -1.6$"),
        (WALL, "speed after = e x speed before\n            = 0.4 x 4\n            = 1.6 m/s"),
        (WALL, "rebound speed = e × speed before = 0.4 × 4 = 1.6 m/s"),
    ],
)
def test_the_family_is_judged_correct(problem: str, text: str) -> None:
    got = statuses(problem, text)
    assert got and all(s == "correct" for s in got), got


@pytest.mark.parametrize(
    ("problem", "text"),
    [
        (WALL, "velocity after = -1.2 m/s"),
        (WALL, "impulse = change in momentum = 2(1.6) - 2(-4) = 9.6 N s"),
        (DIRECT, "v_A2 = 5 m/s   (a)"),
        (WALL, "v_A2 = -1.2 m/s (i.e. 1.2 m/s away from the wall)"),
    ],
)
def test_a_slip_in_the_family_is_wrong(problem: str, text: str) -> None:
    assert "wrong" in statuses(problem, text)


def test_an_own_value_said_again_is_marked_as_the_line_that_worked_it() -> None:
    """``P`` is no name of derive's: its working is judged, and ``so P = …`` after it is that number
    again: right after right working, carried after a slip (48 + 32 is 80, not 78)."""
    assert statuses(DIRECT, "P = 4(12) + 8(4) = 80 kg m/s\nso P = 80") == ["correct", "correct"]
    assert statuses(DIRECT, "P = 4(12) + 8(4) = 78 kg m/s\nso P ≈ 78 kg m/s") == ["wrong", "carried"]
    assert statuses(WALL, "I = 2(1.6) + 2(4) = 11.2 N s\nSo $I \\approx 11.2$ N s, away from the wall.") == [
        "correct",
        "correct",
    ]
