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

import pytest
from support.checked import line_statuses as statuses

import derive
from derive.mathtext.reader import read_relations

DIRECT = "byjus-4kg-ball-catches-8kg-ball"
WALL = "edexcel-m2-ball-rebounds-from-wall"
SYMBOLIC = "aqa-m3-2014-symbolic-2m-hits-m"


def sides(text: str) -> list[tuple[str, ...]]:
    return [r.sides for r in read_relations(text)]


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


@pytest.mark.parametrize(
    ("text", "verdict"),
    [
        ("e = [v_B2 - v_A2] / [v_A1 - v_B1]", "correct"),
        ("e = [(vB)2 - (vA)2] / [(vA)1 - (vB)1]", "correct"),
        ("v_B2 - v_A2 = 0.5 * [12 - 4] = 4", "correct"),
        ("e = [(vA)2 - (vB)2] / [(vA)1 - (vB)1]", "wrong"),  # separation the wrong way round
    ],
)
def test_square_brackets_after_an_operator_are_mathematics(text: str, verdict: str) -> None:
    assert statuses(DIRECT, text) == [verdict]


#: A bullet (0.02 kg, 400 m/s) lodges in a block at rest; they move off together at 2 m/s (both
#: velocities after given): 0.02(400) = 8 = (0.02 + m_B)(2), so m_B = (8 - 0.04)/2 = 3.98 kg.
LODGES = """title = "Bullet lodges in a block: find the block's mass (inverse)"
kind = "direct"
statement = "A bullet of mass {m_A} travelling at {v_A1} lodges in a block at rest; they move off at 2 m/s."
question = "Find the mass of the block."
digits = 3

[given]
m_A = "0.02 kg"
m_B = "? kg"
e = "?"
v_A1 = "400 m/s"
v_B1 = 0
v_A2 = "2 m/s"
v_B2 = "2 m/s"
"""


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("m_A u_A = (m_A + m_B) v'", ["correct"]),
        ("0.02(400) = (0.02 + m_B) v'", ["correct"]),
        (r"$m_A v_{A1} = (m_A + m_B)\,v'$", ["correct"]),
        ("m_A u_A = (m_A + m_B) V'", ["correct"]),
        ("0.02(400) = (0.02 + m_B) v'\nv' = 2\n8 = 0.04 + 2 m_B\nm_B = 3.98 kg", ["correct"] * 4),
        ("0.02(400) = (0.02 + m_B) v'\n8 = 0.04 + m_B", ["correct", "wrong"]),
    ],
)
def test_v_prime_is_the_velocity_both_move_off_with(tmp_path, text: str, expected: list[str]) -> None:
    path = tmp_path / "lodges.toml"
    path.write_text(LODGES, encoding="utf-8")
    report = derive.check(derive.solve(derive.load(str(path))), derivation=text)
    assert [i.status for i in report.items if i.kind == "line"] == expected


@pytest.mark.parametrize(
    ("problem", "text", "verdict"),
    [
        # mcasco-two-cars-no-bounce: A at 3 ft/s, B at 6 ft/s toward it (the other way)
        ("mcasco-two-cars-no-bounce", "(vB)1 = 6 ft/s left", "correct"),
        ("mcasco-two-cars-no-bounce", "Given: (vA)1 = 3 ft/s right, (vB)1 = 6 ft/s left", "correct"),
        ("mcasco-two-cars-no-bounce", "(vB)1 = 6 ft/s right", "wrong"),
        (DIRECT, "v_B1 = 4 m/s right", "correct"),  # B at 4 m/s the same way as A
        (DIRECT, "v_A2 = 4 m/s (right)", "correct"),
        (DIRECT, "v_B1 = 4 m/s left", "wrong"),
    ],
)
def test_left_or_right_alone_after_a_speed_is_its_direction(problem: str, text: str, verdict: str) -> None:
    assert statuses(problem, text) == [verdict]


#: msu-lectureonline-bullet-lodges-in-block: a 0.020 kg bullet at 300 m/s lodges in a 4.0 kg block at
#: rest (e = 0): v' = 0.020(300)/4.02 = 1.4925 m/s. "at" parts "m = 0.020 kg" from what follows; the
#: speed before the comma is no part of M's side; v and v' are the bullet's speed before and after.
BULLET = "msu-lectureonline-bullet-lodges-in-block"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "bullet m = 0.020 kg at 300 m/s, block M = 4.0 kg at rest\nv' = m v/(m + M) = 0.020(300)/4.02 = 1.49 m/s",
            ["correct", "correct"],
        ),
        ("m = 0.020 kg moving at 300 m/s, M = 4.0 kg\nm v = (m + M) v'\nv' = 6/4.02 = 1.49 m/s", ["correct"] * 3),
        (
            "bullet m = 0.020 kg at 300 m/s, block M = 4.0 kg at rest\nv' = m v/(m + M) = 0.020(300)/4.02 = 1.59 m/s",
            ["correct", "wrong"],
        ),
        ("bullet m = 0.020 kg at 300 m/s, block M = 4.0 kg at rest\nv' = M v/(m + M)", ["correct", "wrong"]),
    ],
)
def test_v_before_and_v_prime_after_with_masses_said_in_a_sentence(text: str, expected: list[str]) -> None:
    assert statuses(BULLET, text) == expected


def test_a_speed_before_a_comma_is_no_part_of_the_next_relation() -> None:
    assert sides("Puck m = 0.150 kg at 35.0 m/s, goalie M = 70.0 kg at rest.") == [("m", "0.150"), ("M", "70.0")]
    assert sides("x = 1, 2") == [("x", "1, 2")]


@pytest.mark.parametrize(
    "law",
    [
        "v^2 = u^2 + 2as",
        "v² = u² + 2as",
        "v = u + at",
        "s = ut + ½at²",
        "s = ut + (1/2)at^2",
        "F = ma",
        "s = (u + v)t/2",
    ],
)
def test_a_law_of_motion_quoted_in_its_letters_is_not_marked(law: str) -> None:
    """A teacher does not mark the formula a student writes before using it; the line after is marked."""
    assert sides(law) == []
    assert statuses(WALL, f"{law}\nv_A2 = -0.4(4) = -1.6") == ["correct"]


def test_a_law_with_its_numbers_is_still_read() -> None:
    assert sides("v^2 = u^2 + 2as = 21^2 + 2(9.8)(40) = 1225") == [("v^2", "u^2 + 2as", "21^2 + 2(9.8)(40)", "1225")]
    assert sides("v = 2 at t = 3") == [("v", "2"), ("t", "3")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("0.68 = 0.2(2.9 + v_B'')\nv_B'' = 0.5 m/s", ["correct", "correct"]),
        ("0.68 = 0.2(2.9 + v_B'')\nv_B'' = 0.6 m/s", ["correct", "wrong"]),
    ],
)
def test_two_primes_name_the_velocity_after_a_second_impact(text: str, expected: list[str]) -> None:
    """chain-ocr-m2-2011-find-e-mass-then-wall: B leaves A at 2.9 m/s toward the wall and gets an
    impulse of 0.68 N s from it: 0.68 = 0.2(2.9 + w), w = 3.4 - 2.9 = 0.5 m/s back (``v_B''``)."""
    assert statuses("chain-ocr-m2-2011-find-e-mass-then-wall", text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (
            "v_cm = (m_A v_A + m_B v_B)/(m_A + m_B) = 0.077/0.049 = 1.571 m/s\nv_i' = 2 v_cm - v_i\n"
            "v_A' = 2(1.571) - 3.5 = -0.357 m/s\nv_B' = 2(1.571) - 0 = 3.14 m/s",
            ["correct"] * 4,
        ),
        ("v_cm = 0.077/0.049 = 1.571 m/s\n$v_i' = 2v_{cm} - v_i$", ["correct", "correct"]),
        ("v_cm = 0.077/0.049 = 1.571 m/s\nv_i' = v_cm - v_i", ["correct", "wrong"]),
    ],
)
def test_a_rule_written_once_for_each_body_with_the_index_i(text: str, expected: list[str]) -> None:
    """uoguelph-8-34-superballs-grams (e = 1): 22 g at 3.5 m/s hits 27 g at rest; v_cm = 0.077/0.049
    = 1.5714; v_A' = 2(1.5714) - 3.5 = -0.357, v_B' = 3.143 (= 2(22)/49 × 3.5). ``v_f = 2v_cm - v_i``
    (i for initial) is one relation."""
    assert statuses("uoguelph-8-34-superballs-grams", text) == expected
    assert sides("v_f = 2v_cm - v_i") == [("v_f", "2v_cm - v_i")]


def test_masses_that_cancel_in_a_chain_need_no_values() -> None:
    """chain-msu-bullet-block-swings: V = 0.020(300)/4.02 = 1.4925 m/s; the block and bullet rise
    h = V²/(2g) = 2.2277/19.62 = 0.1135 m; ½(m1 + m2)V² = (m1 + m2) g h holds whatever the masses."""
    chain = "chain-msu-bullet-block-swings"
    work = "V = 0.020(300)/4.02 = 1.493 m/s\n(1/2)(m1 + m2)V^2 = (m1 + m2) g h\nh = 1.493^2/(2(9.81)) = 0.114 m"
    assert statuses(chain, work) == ["correct"] * 3
    assert "correct" not in statuses(chain, "(m1 + m2)V^2 = (m1 + m2) g h")  # the ½ lost: never right


@pytest.mark.parametrize(
    ("problem", "text", "verdict"),
    [
        (DIRECT, "KE lost = 64 J (18.2%)", "correct"),  # 64/352 = 18.2 %: an aside
        (DIRECT, r"$v_{A2} = 4$ \si{m/s}", "correct"),
        (DIRECT, r"$v_{B2} = 8$~\si{\metre\per\second}", "correct"),
        (DIRECT, "impulse = 32 N s", "correct"),  # on B: 8(8 - 4); on A: 4(4 - 12) = -32
        (WALL, "impulse = 11.2 Ns away from the wall", "correct"),
        (WALL, "impulse on the ball = 11.2 N s", "correct"),
        (DIRECT, "KE lost = 60 J (17%)", "wrong"),
    ],
)
def test_asides_and_units_in_text_and_the_impulse_in_words(problem: str, text: str, verdict: str) -> None:
    assert statuses(problem, text) == [verdict]


def test_a_share_in_brackets_is_an_aside_but_a_product_is_not() -> None:
    assert sides("KE lost = 64 J (18.2%)") == [("KE lost", "64")]
    assert sides("p = 2(30%)") == [("p", "2(30%)")]


@pytest.mark.parametrize(
    ("text", "verdict"),
    [
        ("The speed of B after the collision is 8 m/s.", "correct"),
        ("So B's speed after the collision is 8 m/s", "correct"),
        ("speed of B after the collision = 8 m/s", "correct"),
        ("the kinetic energy lost was about 64 J", "correct"),
        ("A's final velocity is 4 m/s", "correct"),
        ("The speed of B after the collision is 9 m/s.", "wrong"),
        ("the kinetic energy lost was 60 J", "wrong"),
    ],
)
def test_a_quantity_said_to_be_a_number_in_words(text: str, verdict: str) -> None:
    assert statuses(DIRECT, text) == [verdict]


@pytest.mark.parametrize("text", ["the ball is 2 m from the wall", "speed is important here", "A is 3 m from B"])
def test_other_sentences_with_is_stay_prose(text: str) -> None:
    assert sides(text) == []
