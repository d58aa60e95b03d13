"""Correct lines a teacher marks right that the checker must not call wrong (issue #31): the
names a student uses as the course teaches them, a later stage's own coefficient, and the
precision a line is written to. Every value is worked by hand from the problem's givens (in
the comments), never from derive's output."""

from __future__ import annotations

import pytest
from support.checked import worst_lines

# OCR M2 June 2006: A (2 kg) at 5 m/s hits B (1 kg) at rest and carries on at 2 m/s:
# 2(5) + 1(0) = 2(2) + 1v -> v = 6 (B after); e = (6 - 2)/5 = 0.8.
AT_REST = "ocr-m2-2006-sphere-hits-sphere-at-rest-find-e"
# OCR MEI 2023 (backward): A (0.5 kg) at 6 catches B (2 kg) at 2 and moves back at 0.2:
# 3 + 4 = -0.1 + 2v -> v = 3.55 (B after); e = (3.55 + 0.2)/(6 - 2) = 0.9375.
BACKWARD = "ocr-mei-fmm-2023-a-speed-0p2-backward"


@pytest.mark.parametrize(
    ("problem", "work"),
    [
        (AT_REST, "u_A = 5, u_B = 0, v_A = 2\n2(5) + 1(0) = 2(2) + 1v\n10 = 4 + v\nv = 6\ne = (v - 2)/5 = 0.8\n"),
        (AT_REST, "u1 = 5 m/s, u2 = 0, v1 = 2 m/s\n2 × 5 = 2 × 2 + v\nv = 6 m/s\n"),
        (AT_REST, "Let u_A = 5, u_B = 0, v_A = 2, v_B = v.\n10 = 4 + v\nv = 6\n"),
        (BACKWARD, "u_A = 6, u_B = 2, v_A = -0.2\n0.5(6) + 2(2) = 0.5(-0.2) + 2v\n7 = -0.1 + 2v\nv = 3.55\n"),
    ],
)
def test_v_alone_beside_labelled_names_is_the_one_velocity_after_not_given(problem: str, work: str) -> None:
    # u_A, u_B (u1, u2) label the bodies, and A's velocity after is given: the v the student
    # solves for is B's velocity after (the habit "u before, v after" for one body does not
    # make it A's when A's is written beside it).
    found = worst_lines(problem, work)
    assert {n: s for n, (s, _) in found.items()} == dict.fromkeys(found, "correct")


def test_v_alone_for_the_velocity_not_given_and_worked_wrongly_is_wrong() -> None:
    # 10 = 4 + v worked as v = 14 (the 4 added): wrong, whatever v is read as.
    found = worst_lines(AT_REST, "u_A = 5, u_B = 0, v_A = 2\n10 = 4 + v\nv = 14\n")
    assert found[2][0] == "correct"
    assert found[3][0] == "wrong"


# OCR FM 2023: A (5 kg) at 4 m/s, 60° from the line of centres; B (3 kg) at 6 m/s along it
# toward A; e = 3/4. A's components 4 cos 60° = 2 along the line, 4 sin 60° = 3.464 across;
# along the line -8 = 5a + 3b and b - a = 0.75(2 + 6) = 6 -> a = -3.25, b = 2.75.
DISCS = "ocr-fm-2023-oblique-discs-60deg"
SIDE_BY_SIDE = (
    "\\begin{align*}\n"
    "u_{An} &= 4\\cos 60^\\circ = 2 & u_{At} &= 4\\sin 60^\\circ = 3.464 \\\\\n"
    "5(2) + 3(-6) &= 5v_{An} + 3v_{Bn} & v_{Bn} - v_{An} &= \\tfrac34(2 + 6) = 6 \\\\\n"
    "\\text{CLM:} & -8 = 5v_{An} + 3v_{Bn} & \\text{NEL:} & v_{Bn} - v_{An} = 6 \\\\\n"
    "v_{An} &= -3.25 & v_{Bn} &= 2.75\n"
    "\\end{align*}\n"
)


def test_two_relations_side_by_side_in_an_align_row_are_read_apart() -> None:
    found = worst_lines(DISCS, SIDE_BY_SIDE)
    assert [found[n][0] for n in (2, 3, 4, 5)] == ["correct"] * 4


def test_a_slip_in_one_of_two_relations_side_by_side_is_wrong() -> None:
    # the components resolved with sin and cos swapped: 4 sin 60° along the line
    work = "\\begin{align*}\nu_{An} &= 4\\sin 60^\\circ = 3.464 & u_{At} &= 4\\cos 60^\\circ = 2\n\\end{align*}\n"
    assert worst_lines(DISCS, work)[2] == ("wrong", "sin_cos_swapped")


# Edexcel M2: a 2 kg ball at 4 m/s hits a wall (e = 0.4) and comes back at 1.6 m/s: KE 16 J
# before, ½(2)(1.6²) = 2.56 J after, 13.44 J lost. OCR M2 2012: 0.8 kg at 4 m/s, e = 0.3, back
# at 1.2 m/s: ½(0.8)(16 - 1.44) = 5.824 J lost (½(0.8)(4 - 1.2)² = 3.136 squares the difference).
ONE_BODY = [
    (
        "edexcel-m2-ball-rebounds-from-wall",
        "(v)_1 = 4 m/s, (v)_2 = -1.6 m/s\nT_1 = 1/2 (2)(4)^2 = 16 J\nT_2 = 1/2 (2)(1.6)^2 = 2.56 J\n"
        "lost = 16 - 2.56 = 13.44 J\n",
        {1: "correct", 2: "correct", 3: "correct", 4: "correct"},
    ),
    (
        "edexcel-m2-ball-rebounds-from-wall",
        "$(v)_{1} = 4$ m/s and $(v)_{2} = -1.6$ m/s\n$T_2 = \\tfrac12 (2)(1.6)^2 = 2.56$ J\n",
        {1: "correct", 2: "correct"},
    ),
    (
        "ocr-m2-2012-particle-hits-wall",
        "v1 = 4 m/s, v2 = -1.2 m/s\nKE lost = 1/2 (0.8)(v1^2 - v2^2) = 0.4(16 - 1.44) = 5.824 J\n",
        {1: "correct", 2: "correct"},
    ),
    (
        "ocr-m2-2012-particle-hits-wall",
        "(v)1 = 4, (v)2 = -1.2\nKE lost = 1/2 (0.8)(4 - 1.2)^2 = 3.136 J\n",
        {1: "correct", 2: "wrong"},
    ),
]


@pytest.mark.parametrize(("problem", "work", "verdicts"), ONE_BODY)
def test_one_bodys_velocities_named_by_the_instant_before_and_after(problem: str, work: str, verdicts: dict) -> None:
    # One body against a wall: (v)_1, (v)_2 (engineering brackets) and v1, v2 (typed) are its
    # velocity before and after the impact, as v_1, v_2 are.
    found = worst_lines(problem, work)
    assert {n: s for n, (s, _) in found.items()} == verdicts


@pytest.mark.parametrize(
    "said",
    [
        "Before: (v_A)_1 = 3 m/s, (v_B)_1 = -2 m/s. After: (v_A)_2 = -0.6 m/s, (v_B)_2 = 3.4 m/s.",
        "$(v_A)_1 = 3$, $(v_B)_1 = -2$ (B toward A), $(v_A)_2 = -0.6$, $(v_B)_2 = 3.4$",
    ],
)
def test_a_whole_number_names_the_value_it_is_not_one_it_rounds_to(said: str) -> None:
    # AQA M3 2007 as a chain: A at 3 m/s, B at 2 m/s toward it; after the impact A at -0.6 and
    # B at 3.4 (0.5 = 0.3a + 0.2b, b - a = 0.8(5) = 4); B leaves the wall at -0.7(3.4) = -2.38.
    # "3" is 3 (A before), not 3.4 rounded; "-2" is B before, not the -2.38 after the wall:
    # e = (3.4 + 0.6)/(3 + 2) = 0.8, and 0.3(3) + 0.2(-2) = 0.5 = 0.3(-0.6) + 0.2(3.4).
    work = (
        f"{said}\n"
        "e = ((v_B)_2 - (v_A)_2)/((v_A)_1 - (v_B)_1) = (3.4 + 0.6)/(3 + 2) = 0.8\n"
        "0.3(v_A)_1 + 0.2(v_B)_1 = 0.3(v_A)_2 + 0.2(v_B)_2 = 0.5\n"
    )
    found = worst_lines("chain-aqa-m3-2007-collide-again", work)
    assert found[2][0] == found[3][0] == "correct"


@pytest.mark.parametrize(
    ("problem", "work"),
    [
        # MSU bullet: 0.020 kg at 300 m/s into a 4.0 kg block at rest; 6 = 4.02 v' -> v' = 1.49 m/s.
        (
            "msu-lectureonline-bullet-lodges-in-block",
            "Bullet: $m_1 = 2.0\\times10^{-2}$ kg, $v_1 = 300$ m/s\n"
            "Block: $m_2 = 4.0$ kg, at rest\n$m_1 v_1 = (m_1 + m_2) v'$\n$v' = 6/4.02 = 1.49$ m/s\n",
        ),
        # Byjus: 4 kg at 12 m/s behind 8 kg at 4 m/s, masses from weights (g = 9.8): 48 + 32 = 80.
        (
            "byjus-4kg-ball-catches-8kg-ball",
            "m_A = 39.2/9.8 = 4 kg, v_A = 12 m/s\nm_B = 78.4/9.8 = 8 kg, v_B = 4 m/s\n"
            "p = m_A v_A + m_B v_B = 48 + 32 = 80 kg m/s\n",
        ),
    ],
)
def test_velocities_stated_beside_masses_worked_out_are_the_givens(problem: str, work: str) -> None:
    # A line of givens whose masses are written in powers of ten or worked from weights still
    # states the velocities before the impact (v_1 = 300 is the bullet's speed, not a result).
    found = worst_lines(problem, work)
    assert {n: s for n, (s, _) in found.items() if s != "not read"} == dict.fromkeys(
        [n for n, (s, _) in found.items() if s != "not read"], "correct"
    )
    assert found[1][0] == "correct"


@pytest.mark.parametrize(
    ("work", "verdict"),
    [
        ("Newton's law: v = eu = 0.3 × 4 = 1.2 m/s back away from the wall\n", "correct"),
        ("NEL: $v = eu = 0.3 \\times 4 = 1.2$ m/s (away from the wall)\n", "correct"),
        ("v = e u = 0.3(4) = 1.2 m/s off the wall\n", "correct"),
        ("v = eu = 0.3 × 4 = 1.2 m/s (away from the wall)\n", "correct"),
        ("Rebound speed: $v = eu = 0.3 \\times 4 = 1.2$ m/s (away from the wall)\n", "correct"),
        ("Newton's law: v = eu = 0.4 × 4 = 1.6 m/s away from the wall\n", "wrong"),
    ],
)
def test_a_rebound_speed_said_away_from_the_wall(work: str, verdict: str) -> None:
    # OCR M2 2012: 0.8 kg at 4 m/s into a wall, e = 0.3: it comes back at 0.3 x 4 = 1.2 m/s.
    # "v = eu" is the size of the velocity after; "away from the wall" says its way (against the
    # way in), as "to the left" does (a name said to be the speed stays a size); 0.4 x 4 = 1.6
    # takes another e.
    assert worst_lines("ocr-m2-2012-particle-hits-wall", work)[1][0] == verdict
