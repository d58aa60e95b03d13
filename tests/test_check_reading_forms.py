"""Forms of writing a teacher reads and derive did not (issue #31, fourth session): a prime typed
inside a bracketed name (``(v_1')_n``, ``(v'_B)_t``), and a display whose relation goes on over
several lines with each new line starting ``=`` and no ``\\\\`` between them (each line is then
judged on its own, as a line ``  = …`` in plain text is).

Values worked by hand from each problem's givens (never from derive's output):

- ocr-m3-2006-oblique-a-across-centres: m_A = 5, m_B = 2 kg, e = 0.75; A at 4 m/s across the line
  of centres (n components 0), B at 4 m/s along it toward A (-4). Along n: 5(0) + 2(-4) = -8 =
  5a + 2b, b - a = 0.75(0 + 4) = 3, so 7a = -14: a = -2, b = 1; the t components stay 4 and 0.
- byjus-4kg-ball-catches-8kg-ball: m_A = 4, m_B = 8 kg, e = 0.5, A at 12 and B at 4 m/s. Momentum
  48 + 32 = 80 = 4 v_A + 8 v_B; v_B = v_A + 0.5(8) = v_A + 4; so 12 v_A = 80 - 32 = 48, v_A = 4.
"""

from __future__ import annotations

import functools

import pytest

import derive
from derive.mathtext.bracketed import bracketed_names
from derive.mathtext.reader import read_relations

ACROSS = "ocr-m3-2006-oblique-a-across-centres"
DIRECT = "byjus-4kg-ball-catches-8kg-ball"


@functools.cache
def _solution(problem: str):
    return derive.solve(derive.load(problem))


def statuses(problem: str, text: str) -> dict[int, str]:
    """line number -> derive's verdict on it."""
    items = derive.check(_solution(problem), derivation=text).items
    return {int(i.name): i.status for i in items if i.kind == "line" and str(i.name).isdigit()}


@pytest.mark.parametrize(
    ("written", "expected"),
    [
        ("(v_1')_n", "v_1n'"),
        ("(v'_1)_n", "v_1n'"),
        ("(v_{A}')_{t}", "v_At'"),
        (r"(v_A^{\prime})_n", "v_An'"),
        ("(vA')2", "v_A2'"),
        ("(v_A)_n'", "v_An'"),  # the prime outside, as before
        ("(v_A) - (v_B)", "(v_A) - (v_B)"),  # nothing after the brackets: left as written
    ],
)
def test_a_prime_inside_the_brackets_marks_the_name_after(written: str, expected: str) -> None:
    assert bracketed_names(written) == expected


@pytest.mark.parametrize(
    ("a", "b"),
    [
        ("(v_A')", "(v_B')"),
        ("(v'_A)", "(v'_B)"),
        ("(v_{A}^{\\prime})", "(v_{B}^{\\prime})"),
    ],
)
def test_primed_names_in_brackets_with_components_are_read(a: str, b: str) -> None:
    lines = [
        "Axes: $n$ along the line of centres from A to B, $t$ across it.",
        f"$5(0) + 2(-4) = 5{a}_n + 2{b}_n$",
        f"${b}_n - {a}_n = 0.75(0 + 4) = 3$",
        f"$7{a}_n = -8 - 6 = -14$, so ${a}_n = -2$",
        f"${b}_n = -2 + 3 = 1$",
        f"${a}_t = 4$, ${b}_t = 0$ (smooth: the $t$ parts do not change)",
    ]
    found = statuses(ACROSS, "\n".join(lines))
    assert all(found.get(n) == "correct" for n in range(2, 7)), found


def test_a_slip_in_primed_bracketed_names_is_still_a_slip() -> None:
    lines = [
        "$5(0) + 2(-4) = 5(v_A')_n + 2(v_B')_n$",
        "$(v_A')_n - (v_B')_n = 0.75(0 + 4) = 3$",  # restitution the wrong way round
    ]
    found = statuses(ACROSS, "\n".join(lines))
    assert found == {1: "correct", 2: "wrong"}, found


@pytest.mark.parametrize(
    "display",
    [
        ("\\[ v_A = \\frac{80 - 8(4)}{12}", " = \\frac{48}{12}", " = 4 \\]"),
        ("\\begin{align*}", "v_A &= \\frac{80 - 8(4)}{12}", "&= \\frac{48}{12}", "&= 4", "\\end{align*}"),
        ("$$v_A = \\frac{80 - 8(4)}{12}", "\\approx \\frac{48}{12}", "= 4.0$$"),
    ],
)
def test_each_line_of_a_display_that_goes_on_with_equals_is_judged(display: tuple[str, ...]) -> None:
    lines = ["$4(12) + 8(4) = 4v_A + 8v_B$, $v_B - v_A = 0.5(12 - 4)$", *display]
    found = statuses(DIRECT, "\n".join(lines))
    marked = [n for n, line in enumerate(lines, 1) if "=" in line or "approx" in line]
    assert [found.get(n) for n in marked] == ["correct"] * len(marked), found


def test_a_slip_on_a_later_line_of_such_a_display_is_marked_at_that_line() -> None:
    lines = [
        "$4(12) + 8(4) = 4v_A + 8v_B$, $v_B - v_A = 0.5(12 - 4)$",
        "\\[ v_A = \\frac{80 - 8(4)}{12}",
        " = \\frac{48}{12}",
        " = 3 \\]",  # 48/12 is 4
    ]
    found = statuses(DIRECT, "\n".join(lines))
    assert (found.get(2), found.get(3), found.get(4)) == ("correct", "correct", "wrong"), found


def test_a_display_whose_first_line_has_no_relation_stays_one_row() -> None:
    (r,) = read_relations("\\[ v_A\n = \\frac{48}{12} = 4 \\]")
    assert r.sides == ("v_A", "48/12", "4")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("v = 0.346 m/s (= 0.2 sqrt(3))", [("v", "0.346", "0.2 sqrt(3)")]),
        (r"$\sqrt{0.3^2 + 0.4^2} = 0.5$ m/s (= $\tfrac12$)", [("sqrt(0.3^2 + 0.4^2)", "0.5", "1/2")]),
        ("e = 0.837 (≈ sqrt(0.7))", [("e", "0.837", "sqrt(0.7)")]),
        ("x = 2(a + b) (= 6)", [("x", "2(a + b)", "6")]),
    ],
)
def test_a_value_said_again_in_brackets_opening_with_equals_is_one_more_side(text: str, expected: list) -> None:
    assert [r.sides for r in read_relations(text)] == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("T_lost = 500 - 320 = 180 J (≈ 36 %)", ("T_lost", "500 - 320", "180")),
        ("loss = 900 J (= 45%)", ("loss", "900")),
        ("E = 2400 J (= 2.4 kJ)", ("E", "2400")),
    ],
)
def test_a_share_or_another_unit_in_brackets_opening_with_equals_is_a_remark(text: str, expected: tuple) -> None:
    """A percentage of the energy before is another quantity than the energy: set aside, not a side."""
    assert [r.sides for r in read_relations(text)] == [expected]


@pytest.mark.parametrize(
    "line",
    [
        "Then momentum and restitution with $e = 0.5$ ($x$, $y$ velocities of $A$, $B$ after):",
        "with e = 0.5 (x, y the velocities after):",
        "$e = 0.5$ (given):",
        "e = 0.5 (x, y for A, B after);",
    ],
)
def test_a_bracketed_remark_before_a_colon_is_no_part_of_the_relation(line: str) -> None:
    assert [r.sides for r in read_relations(line)] == [("e", "0.5")]
    lines = [line, "$4(12) + 8(4) = 4x + 8y$", "$y - x = 0.5(12 - 4) = 4$", "$12x = 48$, $x = 4$, $y = 8$"]
    found = statuses(DIRECT, "\n".join(lines))
    assert all(found.get(n) == "correct" for n in (1, 2, 3, 4)), found


# mcasco-two-cars-no-bounce: W_A = 4500 lb at 3 ft/s, W_B = 3000 lb at -6 ft/s, e = 0; m = W/g, so
# W_A(3) + W_B(-6) = (W_A + W_B) v: v = (13500 - 18000)/7500 = -0.6 ft/s.
CARS = "mcasco-two-cars-no-bounce"


@pytest.mark.parametrize(
    ("problem", "lines"),
    [
        (CARS, ["3WA - 6WB = (WA + WB)v", "v = (3WA - 6WB)/(WA + WB) = -4500/7500 = -0.6 ft/s"]),
        (CARS, ["WA(3) + WB(-6) = (WA + WB)v", "v = 3WA/(WA + WB) - 6WB/(WA + WB) = -0.6"]),
        (DIRECT, ["12mA + 4mB = mA v_A + mB v_B", "v_B - v_A = 0.5(12 - 4)", "v_A = (12mA + 4mB - 4mB)/(mA + mB) = 4"]),
    ],
)
def test_a_number_before_a_glued_mass_or_weight_multiplies_it(problem: str, lines: list[str]) -> None:
    found = statuses(problem, "\n".join(lines))
    assert [found.get(n) for n in range(1, len(lines) + 1)] == ["correct"] * len(lines), found


def test_a_slip_with_glued_weights_is_still_a_slip() -> None:
    found = statuses(CARS, "\n".join(["3WA + 6WB = (WA + WB)v"]))  # B's velocity taken as +6
    assert found == {1: "wrong"}, found


@pytest.mark.parametrize(
    "givens",
    [
        "Before: $v_A = 12$ m/s, $v_B = 4$ m/s",
        "before: vA = 12 , vB = 4",
        "Initially vA = 12 m/s, vB = 4 m/s",
        "just before impact: v_A = 12, v_B = 4",
        "velocities before the collision: $v_A = 12$, $v_B = 4$",
    ],
)
def test_velocities_with_no_time_mark_on_a_line_that_says_before_are_before(givens: str) -> None:
    lines = [givens, "$4(12) + 8(4) = 4v_A + 8v_B$", "$v_B - v_A = 0.5(12 - 4)$", "After: $v_A = 4$, $v_B = 8$"]
    found = statuses(DIRECT, "\n".join(lines))
    assert [found.get(n) for n in (1, 2, 3, 4)] == ["correct"] * 4, found


def test_a_wrong_velocity_on_a_line_that_says_before_is_wrong() -> None:
    lines = ["Before: $v_A = 12$ m/s, $v_B = -4$ m/s", "$4(12) - 8(4) = 4v_A + 8v_B$"]
    found = statuses(DIRECT, "\n".join(lines))
    assert found.get(1) == "wrong", found


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("before: vA = 4j , vB = -4i", [("v_A1n", "0"), ("v_A1t", "4"), ("v_B1n", "-4"), ("v_B1t", "0")]),
        ("After: v_A = 2, v_B = 3", [("v_A", "2"), ("v_B", "3")]),
        ("so vA = 3 (before it was 4)", [("v_A", "3")]),
        ("u_A = 3 before", [("u_A", "3")]),
    ],
)
def test_only_a_line_that_says_before_gives_the_time_before(text: str, expected: list) -> None:
    assert [r.sides for r in read_relations(text)] == expected


@pytest.mark.parametrize(
    "said",
    [
        ", into (1):",
        " into (1)",
        ", sub into (1)",
        ", put this in (1)",
        ", then into CLM",
        ", substitute into the first",
    ],
)
def test_words_saying_where_a_relation_goes_next_are_no_part_of_it(said: str) -> None:
    (r,) = read_relations(f"v_B = v_A + 0.5u{said}")
    assert r.sides == ("v_B", "v_A + 0.5u")
    lines = ["$4v_A + 8v_B = 80$   (1)", "$v_B - v_A = 4$   (2)", f"(2): v_B = v_A + 4{said}", "12v_A + 32 = 80"]
    found = statuses(DIRECT, "\n".join(lines))
    assert [found.get(n) for n in (1, 2, 3, 4)] == ["correct"] * 4, found


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("v = 4 m/s in the direction of A", [("v", "4")]),
        ("x = 2u/3 in the same direction", [("x", "2u/3")]),
        ("v = 3t into 2", [("v", "3t into 2")]),  # no instruction, no equation: left as written
    ],
)
def test_only_words_that_send_a_relation_somewhere_are_cut(text: str, expected: list) -> None:
    assert [r.sides for r in read_relations(text)] == expected


# aqa-m3-2007-spheres-approach-head-on: 0.3 kg at 3 m/s, 0.2 kg at 2 m/s toward it, e = 0.8. The
# centre of mass moves at (0.9 - 0.4)/0.5 = 1 m/s; in its frame each velocity reverses and is
# multiplied by e: v_A = 1 - 0.8(3 - 1) = -0.6, v_B = 1 + 0.8(1 + 2) = 3.4 (momentum 0.5 = -0.18 + 0.68).
HEAD_ON = "aqa-m3-2007-spheres-approach-head-on"


@pytest.mark.parametrize(
    "said",
    [
        "Let $W$ be the velocity of the centre of mass: $W = 1$ m/s",
        "centre of mass velocity V = 1 m/s",
        "So the centre of mass moves at $V_0 = 1$ m/s, and in its frame each velocity is reversed and times e.",
        "In the zero-momentum frame ($U = 1$) each velocity is reversed and times e:",
        "the common velocity is w = 1 m/s",
    ],
)
def test_a_name_said_in_words_to_be_the_centre_of_mass_velocity(said: str) -> None:
    lines = [said, "$v_A = 1 - 0.8(3 - 1) = -0.6$", "$v_B = 1 + 0.8(1 + 2) = 3.4$"]
    found = statuses(HEAD_ON, "\n".join(lines))
    assert [found.get(n) for n in (1, 2, 3)] == ["correct"] * 3, found


def test_a_wrong_centre_of_mass_velocity_is_wrong() -> None:
    lines = [
        "The centre of mass moves at $V = 2.6$ m/s",
        "$v_A = 2.6 - 0.8(3 - 2.6)$",
    ]  # (0.9 + 0.4)/0.5: B's sign lost
    found = statuses(HEAD_ON, "\n".join(lines))
    assert found == {1: "wrong", 2: "carried"}, found


def test_a_bodys_velocity_in_the_centre_of_mass_frame_is_not_the_centre_of_mass_velocity() -> None:
    # In the centre of mass frame (moving at 1 m/s) B moves at -2 - 1 = -3 m/s; after, at
    # -0.8(-3) = 2.4 there, so v_B = 1 + 2.4 = 3.4 (the mark scheme's 3.4). "B moves at w" names
    # B's velocity in that frame, not the frame's own velocity (which is 1, not -3).
    lines = [
        "The centre of mass moves at $V = (0.3(3) - 0.2(2))/0.5 = 1$ m/s",
        "and in the CM frame B moves at $w = -2 - 1 = -3$ m/s",
        "$v_B = 1 - 0.8(-3) = 3.4$",
    ]
    found = statuses(HEAD_ON, "\n".join(lines))
    assert [found.get(n) for n in (1, 2, 3)] == ["correct"] * 3, found


# edexcel-fm1-2023-june-q7a-cushion-show-tan-beta: speed U at alpha to the cushion DC, smooth, e_1:
# along DC U cos(alpha) is kept, across it e_1 U sin(alpha): V cos(beta) = U cos(alpha),
# V sin(beta) = e_1 U sin(alpha). giancoli-7-18-tennis-ball-wall-45deg: 28 m/s at 45 deg to the
# normal, e = 1: the part along the wall 28 sin 45 is kept, the speed after is 28 m/s.
CUSHION = "edexcel-fm1-2023-june-q7a-cushion-show-tan-beta"
TENNIS = "giancoli-7-18-tennis-ball-wall-45deg"
AFTER_SPEED = [
    "After (speed $V$): along DC $V\\cos\\beta$, across it $V\\sin\\beta$.",
    "after the impact: speed V, angle beta with the cushion",
    "The ball rebounds with speed $V$ at $\\beta$ to DC.",
]


@pytest.mark.parametrize("said", AFTER_SPEED)
def test_the_speed_after_named_beside_after_is_the_speed_after(said: str) -> None:
    lines = [said, "$V\\cos\\beta = U\\cos\\alpha$", "$V\\sin\\beta = e_1 U\\sin\\alpha$"]
    assert statuses(CUSHION, "\n".join(lines)) == {2: "correct", 3: "correct"}


@pytest.mark.parametrize("said", AFTER_SPEED)
def test_with_the_speed_after_named_beside_after_a_slip_is_wrong(said: str) -> None:
    lines = [said, "$V\\cos\\beta = e_1 U\\cos\\alpha$"]  # e on the part along the cushion
    assert statuses(CUSHION, "\n".join(lines)) == {2: "wrong"}


def test_the_speed_after_named_on_a_wall_problem() -> None:
    lines = ["After the bounce (speed $V$), at 45° on the other side of the normal:", "$V\\sin 45° = 28\\sin 45°$"]
    assert statuses(TENNIS, "\n".join(lines) + "\n$V = 28$ m/s") == {2: "correct", 3: "correct"}


def test_mathematics_with_a_functions_name_that_cannot_be_read_is_not_read_not_prose() -> None:
    found = statuses(TENNIS, "$Q\\cos\\beta = 28\\cos 45°$")  # Q and beta: names never said
    assert found == {1: "not read"}


@pytest.mark.parametrize("after", [" … that is not 4?? I give up", " ... hmm, not what they want", "… so wrong?"])
def test_words_after_an_ellipsis_are_no_part_of_the_relation(after: str) -> None:
    assert [r.sides for r in read_relations(f"v_B/v_A = 22/13 = 1.69{after}")] == [("v_B/v_A", "22/13", "1.69")]
    assert [r.sides for r in read_relations(f"x = 2u{after}")] == [("x", "2u")]


@pytest.mark.parametrize(
    "givens",
    [
        "Knowns: $u_A = 3$ m/s →, $u_B = 2$ m/s ←. Taking → as positive, so $u_B = -2$.",
        "u_A = 3 m/s ->, u_B = 2 m/s <-. Right is positive.",
        "Given: $(v_A)_1 = 3$ m/s →, $(v_B)_1 = 2$ m/s ←.",
    ],
)
def test_an_arrow_after_a_speed_before_a_full_stop_is_its_direction(givens: str) -> None:
    lines = [givens, "$0.3(3) + 0.2(-2) = 0.3a + 0.2b$"]
    found = statuses(HEAD_ON, "\n".join(lines))
    assert found.get(1) in ("correct", None) and found.get(2) == "correct", found
    assert any(r.direction == -1 and r.sides[-1].strip() == "2" for r in read_relations(givens))


@pytest.mark.parametrize(
    "line",
    [
        "$v_A = -0.6$ \\quad (check: $0.3(-0.6) + 0.2(3.4) = 0.5$)",
        "$v_A = -0.6$ \\qquad (as a check: $0.3(-0.6) + 0.2(3.4) = 0.9 - 0.4$)",
        "$v_A = -0.6$ (check: $0.2(3.4) - 0.3(0.6) = 0.5$)",
    ],
)
def test_a_check_in_brackets_after_a_relation_is_a_relation_of_its_own(line: str) -> None:
    assert len(read_relations(line)) == 2
    assert statuses(HEAD_ON, line) == {1: "correct"}


def test_a_wrong_check_in_brackets_is_wrong() -> None:
    found = statuses(HEAD_ON, "$v_A = -0.6$ \\quad (check: $0.3(-0.6) + 0.2(3.4) = 0.6$)")  # 0.5
    assert found == {1: "wrong"}, found
