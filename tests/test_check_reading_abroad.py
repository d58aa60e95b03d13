"""Reading work typed as students in Germany, France, Spain or Italy type it (issue #31): decimal
commas (``0,25``, LaTeX's ``0{,}25``), and the words between relations in their languages ("also",
"donc", "por lo tanto", ``\\Leftrightarrow``). A decimal comma is a point; a pair in brackets of its
own (``(3,4)``) and thousands (``20,000``) stay what they were.

Values worked by hand from each problem's givens (never from derive's output):

- byjus-4kg-ball-catches-8kg-ball: m_A = 4, m_B = 8, e = 0.5, v_A1 = 12, v_B1 = 4 (m/s). Momentum
  4(12) + 8(4) = 80 = 4 v_A2 + 8 v_B2; v_B2 - v_A2 = 0.5(12 - 4) = 4; 12 v_A2 = 48: v_A2 = 4,
  v_B2 = 8. KE before 288 + 64 = 352 J, after 32 + 256 = 288 J, lost 64 J.
- edexcel-m2-ball-rebounds-from-wall: m = 2 kg, u = 4 m/s into the wall, e = 0.4: v = -1.6 m/s;
  impulse 2(1.6 + 4) = 11.2 N s; KE 16 J before, 2.56 J after, 13.44 J lost.
"""

from __future__ import annotations

import functools

import pytest

import derive
from derive.mathtext.reader import read_relations

DIRECT = "byjus-4kg-ball-catches-8kg-ball"
WALL = "edexcel-m2-ball-rebounds-from-wall"


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
        ("u = 0,250 m/s", [("u", "0.250")]),
        ("v = 2(0,25)", [("v", "2(0.25)")]),
        ("a = 1,5, b = 2,5", [("a", "1.5"), ("b", "2.5")]),
        ("v = 3,46; w = 0", [("v", "3.46"), ("w", "0")]),
        (r"$v_{A2} = -0{,}4 \cdot 4 = -1{,}6$", [("v_A2", "-0.4 * 4", "-1.6")]),
        (r"$v = 3,46\ \text{m/s}$", [("v", "3.46")]),
        # not decimals: thousands, a pair in brackets of its own, a list of three
        ("p = 20,000", [("p", "20000")]),
        ("v = (3,4)", [("v_n", "3"), ("v_t", "4")]),
        ("x = 1,2,3", [("x", "1,2,3")]),
    ],
)
def test_a_decimal_comma_is_a_point(text: str, expected: list) -> None:
    assert sides(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Impulserhaltung: 4*12 + 8*4 = 80, also v_A2 = 4", [("4*12 + 8*4", "80"), ("v_A2", "4")]),
        ("v_B2 - v_A2 = 4 daher v_B2 = 8", [("v_B2 - v_A2", "4"), ("v_B2", "8")]),
        ("donc v_A2 = 4 m/s et v_B2 = 8 m/s", [("v_A2", "4"), ("v_B2", "8")]),
        ("12 v_A2 = 48 por lo tanto v_A2 = 4", [("12 v_A2", "48"), ("v_A2", "4")]),
        ("12 v_A2 = 48 quindi v_A2 = 4", [("12 v_A2", "48"), ("v_A2", "4")]),
        (r"$I_A = -I_B \;\Leftrightarrow\; m_A(2 - 3) = -0{,}88$", [("I_A", "-I_B"), ("m_A(2 - 3)", "-0.88")]),
        ("12 v_A2 = 48 ⇔ v_A2 = 4", [("12 v_A2", "48"), ("v_A2", "4")]),
    ],
)
def test_so_in_other_languages_parts_two_relations(text: str, expected: list) -> None:
    assert sides(text) == expected


@pytest.mark.parametrize(
    ("problem", "text"),
    [
        (DIRECT, "v_B2 - v_A2 = 0,5(12 - 4) = 4"),
        (DIRECT, r"$v_{B2} - v_{A2} = 0{,}5\,(12 - 4) = 4\ \mathrm{m/s}$"),
        (DIRECT, "e = 0,5"),
        (DIRECT, "Impulserhaltung: 4 · 12 + 8 · 4 = 4 v_A2 + 8 v_B2, also 80 = 4 v_A2 + 8 v_B2"),
        (DIRECT, "Conservation de la quantité de mouvement : 48 + 32 = 4 v_A2 + 8 v_B2, donc v_A2 = 4 m/s"),
        (DIRECT, "Energía cinética perdida = 352 - 288 = 64 J"),
        (WALL, "v_A2 = -0,4 · 4 = -1,6 m/s"),
        (WALL, r"$v = -0{,}4 \times 4 = -1{,}6\ \text{m/s}$"),
        (WALL, "KE lost = 16 - 2,56 = 13,44 J"),
    ],
)
def test_work_with_decimal_commas_is_judged_correct(problem: str, text: str) -> None:
    got = statuses(problem, text)
    assert got and all(s == "correct" for s in got), got


@pytest.mark.parametrize(
    ("problem", "text"),
    [
        (DIRECT, "v_B2 - v_A2 = 0,5(12 - 4) = 5"),
        (WALL, "v_A2 = -0,4 · 4 = -1,2 m/s"),
        (WALL, r"$\Delta E = 16 - 2{,}56 = 14{,}44\ \text{J}$"),
    ],
)
def test_a_slip_with_decimal_commas_is_wrong(problem: str, text: str) -> None:
    assert "wrong" in statuses(problem, text)
