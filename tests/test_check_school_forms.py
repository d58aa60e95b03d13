"""Forms students type around their working that the checker reads as a teacher does: LaTeX's line
break after the words that follow a relation, a component labelled by a wall's axis in words, a
fraction with its arguments unbraced, a condition in brackets after a root, an impulse written as
the integral of the force (each value worked by hand from the problem's givens)."""

from __future__ import annotations

import pytest
from support.checked import line_statuses, lines

import derive

#: A ball at 4 m/s strikes a smooth wall, its path at 30° to the wall, e = 1/2 (kept apart from the
#: bundled problems). Along the wall 4 cos 30° = 3.464 (kept); into it 4 sin 30° = 2, out 1.
WALL30 = """title = "Ball at 30 degrees to a wall"
kind = "oblique"
find = ["v_A2"]

[given]
m_A = "0.5 kg"
e = 0.5
v_A1 = "4 m/s"
theta = "30 deg"

[A]
angle = "theta"
from = "+t"
toward = "+n"

[B]
fixed = true
name = "wall"
"""


def _wall(tmp_path, text: str) -> list[str]:
    path = tmp_path / "wall30.toml"
    path.write_text(WALL30, encoding="utf-8")
    report = derive.check(derive.solve(derive.load(str(path))), derivation=text)
    return [i.status for i in report.items if i.kind == "line"]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("along the wall: $4\\cos 30^\\circ = 3.46$ m/s (no change)", ["correct"]),
        ("along wall: 4 cos 30° = 3.46 (unchanged)", ["correct"]),
        ("parallel to the wall: 4cos30 = 3.46", ["correct"]),
        ("into the wall: 4 sin 30° = 2", ["correct"]),
        ("perpendicular to the wall: $4\\sin 30^\\circ = 2$", ["correct"]),
        # sin and cos swapped: along the wall the component is 4 cos 30°, not 4 sin 30°
        ("along the wall: 4 sin 30° = 2", ["wrong"]),
        ("into the wall: 4 cos 30° = 3.46", ["wrong"]),
    ],
)
def test_a_component_labelled_along_or_into_a_wall_is_that_axis(tmp_path, text: str, expected: list[str]) -> None:
    assert _wall(tmp_path, text) == expected


#: A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward it, e = 0.8: KE before 0.5(0.3)(9) + 0.5(0.2)(4) =
#: 1.35 + 0.4 = 1.75 J; after (v_A = -0.6, v_B = 3.4) 0.5(0.3)(0.36) + 0.5(0.2)(11.56) = 0.054 + 1.156 = 1.21 J.
HEAD_ON = "aqa-m3-2007-spheres-approach-head-on"


@pytest.mark.parametrize(
    "text",
    [
        "KE before $= \\tfrac12(0.3)(3^2) + \\tfrac12(0.2)(2^2) = 1.75$ J \\\\",
        "KE before $= \\tfrac12(0.3)(3^2) + \\tfrac12(0.2)(2^2) = 1.75$\\\\",
        "$T_1 = \\frac12(0.3)(9) + \\frac12(0.2)(4) = 1.75$ J\\\\[2pt]",
        "KE before $= 1.35 + 0.4 = 1.75$ J (both moving)\\\\",
        "KE before $= 1.35 + 0.4 = 1.75$ J \\newline",
    ],
)
def test_a_latex_line_break_after_the_words_is_layout(text: str) -> None:
    assert line_statuses(HEAD_ON, text) == ["correct"]


def test_a_latex_line_break_does_not_hide_a_slip() -> None:
    # 1/2 (0.3)(9) = 1.35, not 2.7: the line is still marked (wrong), not left unread
    assert line_statuses(HEAD_ON, "KE of A before $= \\tfrac12(0.3)(3^2) = 2.7$ J \\\\") == ["wrong"]


def test_lines_with_breaks_are_each_read() -> None:
    work = "KE before $= \\tfrac12(0.3)(3^2) + \\tfrac12(0.2)(2^2) = 1.75$ J \\\\\nKE after $= \\tfrac12(0.3)(0.6^2) + \\tfrac12(0.2)(3.4^2) = 1.21$ J \\\\\n"
    assert {n: s for n, (s, _slip, _again) in lines(HEAD_ON, work).items()} == {1: "correct", 2: "correct"}


#: m at u hits 9m at rest, half the kinetic energy lost: u = x + 9y, y - x = eu with e = 2/3, so
#: 10y = 5u/3, y = u/6 and x = u/6 - 2u/3 = -u/2 (x, y the velocities after, found by the relations).
NINE = "cie-9231-p2-2014-june-q3-m-hits-9m-half-ke-lost"
SETUP = "$u = x + 9y$\n$y - x = \\tfrac23 u$\n"


@pytest.mark.parametrize(
    ("row", "verdict"),
    [
        ("$y = \\frac u6$", "correct"),
        ("$y = \\dfrac u6$", "correct"),
        ("$y = \\frac{u}6$", "correct"),
        ("$y = \\tfrac u{6}$", "correct"),
        ("$x = -\\frac u2$", "correct"),
        ("$x = \\frac u6 - \\frac{2u}3 = -\\frac u2$", "correct"),
        ("$y = \\frac u3$", "wrong"),  # 10y = 5u/3: u/6, not u/3
        ("$x = \\frac u2$", "wrong"),
    ],
)
def test_a_fraction_with_unbraced_arguments_is_read_as_tex_sets_it(row: str, verdict: str) -> None:
    assert line_statuses(NINE, SETUP + row)[-1] == verdict


def test_a_full_stop_after_the_mathematics_ends_the_sentence() -> None:
    found = lines(NINE, SETUP + "So $y = \\frac{u}{6}$. Speed of B is $\\frac{u}{6}$ and A rebounds.\n")
    assert found[3][0] == "correct"


@pytest.mark.parametrize(
    "row",
    [
        "If $y = \\frac{u}{3}$ then $x = -\\frac{2u}{3}$, so A would pass through B. Reject.",
        "If $y = \\frac{u}{3}$ then $x = -\\frac{2u}{3}$. Impossible!",
        "Taking $y = \\frac{u}{3}$ gives $x = -\\frac{2u}{3}$. So not possible.",
    ],
)
def test_a_rejection_in_a_sentence_of_its_own_turns_down_the_case_before_it(row: str) -> None:
    # y = u/3 is not B's velocity (u/6): a case the student turns down, which a teacher does not mark
    found = lines(NINE, SETUP + row + "\n$y = \\frac{u}{6}$\n")
    assert 3 not in found or found[3][0] in ("correct", "not read")
    assert found[4][0] == "correct"


@pytest.mark.parametrize(
    "row",
    [
        "v_B - v_A = 0.8(3 + 2) = 4   (e < 1)",
        "$v_B - v_A = 4$ $(0 < e < 1)$",
        "v_B = 3.4 m/s (v_B > 0, so B moves on to the right)",
        "$v_A = -0.6 \\quad (v_A < 0 \\text{ so A rebounds})$",
        "v_A = -0.6 m/s (since v_A < 0, A turns back)",
        "$v_B = 3.4$ (v_B \\geq 0)",
    ],
)
def test_a_condition_in_brackets_after_a_value_is_no_part_of_it(row: str) -> None:
    # e = 0.8: v_B - v_A = 0.8(3 + 2) = 4, v_A = -0.6, v_B = 3.4 (worked above); the bracket says why
    assert line_statuses(HEAD_ON, "$0.3(3) - 0.2(2) = 0.3 v_A + 0.2 v_B$\n" + row)[-1] == "correct"


def test_a_condition_in_brackets_does_not_hide_a_wrong_value() -> None:
    assert line_statuses(HEAD_ON, "$0.3(3) - 0.2(2) = 0.3 v_A + 0.2 v_B$\nv_B = 3.8 (v_B > 0)")[-1] == "wrong"


@pytest.mark.parametrize(
    ("row", "verdict"),
    [
        # the impulse on B: 0.2(3.4 - (-2)) = 1.08 N s (B's velocity 2 m/s toward A before, 3.4 m/s after)
        ("$\\int F\\,dt = 0.2(3.4 - (-2)) = 1.08$ N s", "correct"),
        ("$\\int F dt = 1.08 \\text{ N s}$", "correct"),
        ("∫F dt = 1.08 Ns", "correct"),
        ("$\\int_0^{\\Delta t} F\\,dt = 0.2(5.4) = 1.08$", "correct"),
        ("$\\int F_B\\,dt = 1.08$ N s", "correct"),
        ("$\\int F dt = 0.2(3.4 - 2) = 0.28$ N s", "wrong"),  # B's velocity before taken the wrong way
    ],
)
def test_the_impulse_written_as_the_integral_of_the_force(row: str, verdict: str) -> None:
    assert line_statuses(HEAD_ON, row) == [verdict]


def test_a_markdown_table_row_is_read_cell_by_cell() -> None:
    work = (
        "| | KE (J) |\n|---|---|\n"
        "| before (both moving) | $\\tfrac12(0.3)(3^2) + \\tfrac12(0.2)(2^2) = 1.75$ |\n"
        "| after | $\\tfrac12(0.3)(0.6^2) + \\tfrac12(0.2)(3.4^2) = 1.21$ |\n"
        "| lost | 1.75 - 1.21 = 0.54 |\n"
    )
    found = {n: s for n, (s, _slip, _again) in lines(HEAD_ON, work).items()}
    assert found == {3: "correct", 4: "correct", 5: "correct"}


def test_a_table_row_with_a_slip_is_wrong() -> None:
    # 1/2 (0.3)(0.6^2) = 0.054, not 0.108
    work = "| A after | $\\tfrac12(0.3)(0.6^2) = 0.108$ |\n"
    assert line_statuses(HEAD_ON, work) == ["wrong"]


@pytest.mark.parametrize(
    "row",
    [
        "KE lost = 1.75 - 1.21 = 0.54 J  (31% of it), fine since e < 1",
        "KE lost = 1.75 - 1.21 = 0.54 J, which makes sense as e < 1",
        "$T_{lost} = 1.75 - 1.21 = 0.54$ J, OK since $0 < e < 1$",
    ],
)
def test_a_clause_that_checks_the_value_by_an_inequality_is_a_remark(row: str) -> None:
    assert line_statuses(HEAD_ON, row) == ["correct"]


@pytest.mark.parametrize(
    ("row", "verdict"),
    [
        # reduced mass 0.3(0.2)/(0.3 + 0.2) = 0.12 kg; approach 3 + 2 = 5 m/s, e = 0.8:
        # lost ½(0.12)(1 - 0.64)(25) = 0.54 J (= 1.75 - 1.21, the energies worked above)
        ("$\\mu = \\frac{0.3 \\times 0.2}{0.3 + 0.2} = 0.12$ kg", "correct"),
        ("mu = (0.3)(0.2)/(0.5) = 0.12 kg", "correct"),
        ("$\\Delta KE = \\tfrac12 \\mu (1 - e^2)(5)^2 = \\tfrac12(0.12)(0.36)(25) = 0.54$ J", "correct"),
        ("KE lost = ½ μ (1 − e²)(3 + 2)² = 0.54 J", "correct"),
        ("$\\mu = \\frac{0.3 \\times 0.2}{0.3 + 0.2} = 0.6$ kg", "wrong"),  # 0.06/0.5 = 0.12
        ("$\\Delta KE = \\tfrac12 \\mu (1 - e^2)(5)^2 = 0.9$ J", "wrong"),  # 0.54
    ],
)
def test_mu_is_the_reduced_mass_in_the_energy_lost(row: str, verdict: str) -> None:
    assert line_statuses(HEAD_ON, row) == [verdict]


def test_mu_in_letters_squared_stays_m_times_u() -> None:
    # m at u hits 9m at rest: KE before ½ m u² (the letters m, u), though μ is named on another line
    work = "$\\mu = \\frac{9m}{10}$\nKE before $= \\tfrac12 mu^2$, lost $= \\tfrac12 \\cdot \\tfrac12 mu^2 = \\tfrac14 mu^2$\n"
    assert lines(NINE, work)[2][0] == "correct"


#: Two 47 lb disks, A at 8 ft/s at 30° to the line of impact, B at rest, e = 0.8: along the line
#: a + b = 8 cos 30° = 6.928, b - a = 0.8(6.928) = 5.543, so b = 6.235, a = 0.693; A keeps 8 sin 30° = 4 across.
DISKS = "mcasco-glancing-disks-us"


@pytest.mark.parametrize(
    ("row", "verdict"),
    [
        ("vAy = 4 ft/s", "correct"),
        ("vBy = 0", "correct"),
        ("vAx + vBx = 6.928", "correct"),
        ("vBx - vAx = 0.8(6.928) = 5.542", "correct"),
        ("vBx = 6.235 ft/s", "correct"),
        ("uAx = 8 cos 30 = 6.928", "correct"),
        ("vAy' = 4", "correct"),
        ("vBx = 6.928 ft/s", "wrong"),  # all of A's 6.928 given to B: e = 1 worked, not 0.8
    ],
)
def test_a_component_glued_to_its_body_and_axis(row: str, verdict: str) -> None:
    assert line_statuses(DISKS, row) == [verdict]


@pytest.mark.parametrize(
    ("row", "verdicts"),
    [
        ("A before: $x$: $8\\cos30° = 6.93$ ft/s, $y$: $8\\sin30° = 4$ ft/s", ["correct"]),
        ("A before: x: 8 cos 30° = 6.93 ft/s, y: 8 sin 30° = 4 ft/s", ["correct"]),
        ("x: 8cos30 = 6.93, y: 8sin30 = 4", ["correct"]),
    ],
)
def test_an_axis_letter_leading_in_after_a_comma_labels_the_next_relation(row: str, verdicts: list[str]) -> None:
    assert line_statuses(DISKS, row) == verdicts


@pytest.mark.parametrize(
    "declaration",
    [
        "let p, q = velocities after the impact (A, B)",
        "let p, q = the velocities of the spheres afterwards (A, B resp.)",
        "Let p and q = final velocities (A then B)",
    ],
)
def test_names_let_be_quantities_in_words_are_a_declaration_not_a_relation(declaration: str) -> None:
    # 0.3(3) - 0.2(2) = 0.5 = 0.3p + 0.2q; q - p = 0.8(3 + 2) = 4: p = -0.6, q = 3.4
    work = f"{declaration}\n0.3(3) - 0.2(2) = 0.3p + 0.2q\nq - p = 0.8(5)\nq - p = 0.8(1)\n"
    found = {n: s for n, (s, _slip, _again) in lines(HEAD_ON, work).items()}
    assert found.get(1, "not read") in ("not read", "correct")
    assert (found[2], found[3], found[4]) == ("correct", "correct", "wrong")


@pytest.mark.parametrize("row", ["CLM: mu = mx + 9my", "mu = 9my + mx", "mu + 0 = mx + 9my"])
def test_mu_set_equal_to_a_momentum_stays_m_times_u(row: str) -> None:
    # m at u hits 9m at rest: m u = m x + 9 m y is the momentum, not the reduced mass 9m/10
    assert line_statuses(NINE, row + "\ny - x = \\tfrac23 u\n")[0] == "correct"


@pytest.mark.parametrize(
    ("row", "verdict"),
    [
        ("$v'_{Ax} + v'_{Bx} = 6.928$", "correct"),
        ("$v'_{Bx} - v'_{Ax} = 0.8(6.928) = 5.542$", "correct"),
        ("$v'_{Bx} = 6.235$ ft/s", "correct"),
        ("$v'_{Bx} = 6.928$ ft/s", "wrong"),  # 6.235
    ],
)
def test_a_prime_typed_before_a_braced_subscript(row: str, verdict: str) -> None:
    # after a line that names both (a lone v'_{Bx} is not read yet: its name is known from the relations)
    assert line_statuses(DISKS, "$v'_{Ax} + v'_{Bx} = 6.928$\n" + row)[-1] == verdict


@pytest.mark.parametrize(
    ("row", "verdict"),
    [
        ("v_B = 3.4. Reject v_B = -3.4.", "correct"),  # the value rejected is the one named after it
        ("v_B = 3.8. Reject the other root.", "wrong"),  # "the other": the value before is kept, and judged
        ("v_B = 3.4. Discard the negative value.", "correct"),
    ],
)
def test_a_rejection_that_names_what_it_turns_down_leaves_the_value_kept(row: str, verdict: str) -> None:
    # e = 0.8: v_B - v_A = 0.8(3 + 2) = 4 with 0.9 - 0.4 = 0.3 v_A + 0.2 v_B: v_A = -0.6, v_B = 3.4
    assert line_statuses(HEAD_ON, "$0.3(3) - 0.2(2) = 0.3 v_A + 0.2 v_B$\n" + row)[-1] == verdict
