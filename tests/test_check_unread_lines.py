"""Lines a teacher marks that the checker used not to read, each family on problems and phrasings
other than the corpus's, its expected marks worked by hand from the problem's givens.

A root typed on a phone as ``rt3`` (``2rt3``, ``rt(3)``) is the root of 3, as ``sqrt3`` and
``root3`` are. AQA M3 June 2007 Q6(a): identical balls, A at u at 30 deg to the line of centres,
B at rest. A's velocity along the line of centres is u cos 30 = (rt3/2)u, across it u sin 30 = u/2;
B's after, (1 + e)(rt3/4)u (momentum x + y = (rt3/2)u, restitution y - x = e(rt3/2)u).
"""

from __future__ import annotations

import pytest
from support.checked import lines, solved_text, statuses_of, worst_lines

from derive.mathtext.notation import student

AQA = "aqa-m3-2007-june-q6a-b-at-rest-line-at-30deg-show-speed-of-b"


@pytest.mark.parametrize(
    ("typed", "plain"),
    [("rt3/2", "sqrt(3)/2"), ("2rt3", "2*sqrt(3)"), ("rt(3)u", "sqrt(3)*u"), ("u rt3", "u*sqrt(3)")],
)
def test_rt_glued_to_a_number_is_its_root(typed: str, plain: str) -> None:
    assert student(typed).replace(" ", "") == plain


def test_a_name_beginning_rt_is_not_a_root() -> None:
    assert "sqrt" not in student("rt + v_rt2")


@pytest.mark.parametrize(
    ("line", "status"),
    [
        ("A along l.o.c. before = u cos 30 = (rt3/2)u", "correct"),
        ("B's velocity after = (1 + e)(rt3/4)u", "correct"),
        ("B's velocity after = (1 + e) rt(3) u/2", "wrong"),
    ],
)
def test_rt3_lines_are_read_and_judged(line: str, status: str) -> None:
    assert worst_lines(AQA, line + "\n")[1][0] == status


# A letter the statement names an angle by ("the ball's path turns through an angle φ") where the
# file defines the asked quantity by its own name (deflection = beta_A2 - psi): the student's φ is
# that quantity, as the statement says. Worked by hand: u = 4 m/s at 30 deg to the line of
# centres, e = 0.5, B identical and at rest. Along n A has 4 cos 30 = 3.4641, across 2; after,
# v_A2n = 3.4641(1 - 0.5)/2 = 0.8660, so A moves at atan(2/0.8660) = 66.59 deg to the line of
# centres and turns through 66.59 - 30 = 36.59 deg (tan = sqrt3(1.5)/(5 - 1.5) = 0.7423).
TURNS = """\
title = "Equal discs, line of centres at 30 deg: the angle A turns through"
kind = "oblique"
statement = "A disc moving at 4 m/s strikes an identical disc at rest; the line of centres makes 30 deg with its path, e = 0.5. The impact turns the first disc's path through an angle φ."
question = "Find φ."
find = ["deflection"]

[given]
m_A = "1 kg"
m_B = "1 kg"
v_A1 = "4 m/s"
v_B1 = 0
e = 0.5
psi = "30 deg"

[define]
deflection = "beta_A2 - psi"

[A]
angle = "psi"
from = "+n"
toward = "+t"
"""


@pytest.mark.parametrize(
    ("work", "status"),
    [
        ("phi = 36.6°\n", "correct"),
        ("φ ≈ 36.6 deg\n", "correct"),
        ("tan phi = 0.742\n", "correct"),
        ("phi = 66.6°\n", "wrong"),
    ],
)
def test_the_statements_letter_names_a_defined_angle(tmp_path, work: str, status: str) -> None:
    solution = solved_text(tmp_path, "turns.toml", TURNS)
    assert statuses_of(solution, work)[1] == status


@pytest.mark.parametrize(
    ("last", "status"),
    [
        ("so the deflection phi = a - 30", "correct"),
        ("angle phi = a - 30", "correct"),
        ("deflection phi = a + 30", "wrong"),
    ],
)
def test_words_before_a_greek_name_lead_in(tmp_path, last: str, status: str) -> None:
    """``deflection θ = a − 30``: prose before a Greek letter typed as a word, as before ``V``; the
    bare 30 beside the angles is degrees."""
    solution = solved_text(tmp_path, "turns.toml", TURNS)
    work = f"A now moves at angle a to the line of centres\ntan a = 2/0.866\n{last}\n"
    assert statuses_of(solution, work)[3] == status


# A body's component said in words with its time, under a lead-in that names the axis ("Perp: Q's
# component after = ..."): derive's component of that body at that time on that axis. AQA M3 2007
# Q6(a) again (A at u, 30 deg to the line of centres; B identical, at rest): along the line of
# centres A has u cos 30 before, across it u sin 30 before and after (smooth: no impulse across);
# B has nothing across after; along it B has (1 + e)(sqrt3/4)u after.
@pytest.mark.parametrize(
    ("line", "status"),
    [
        ("Along l.o.c.: A's component before = u cos 30", "correct"),
        ("Perp: A's component after = u sin 30", "correct"),
        ("Across: B's final component = 0", "correct"),
        ("Along the line of centres: B's component after = (1 + e)(sqrt3/4)u", "correct"),
        ("perpendicular to l.o.c.: A's component after = e u sin 30", "wrong"),
        ("Along l.o.c.: A's component before = u sin 30", "wrong"),
    ],
)
def test_a_component_in_words_under_its_axis(line: str, status: str) -> None:
    assert worst_lines(AQA, line + "\n")[1][0] == status


# A law quoted in its textbook letters with the values of its letters stated with it ("v^2 = u^2 +
# 2as with u = 0, s = 2 m"): the formula and what its letters stand for, which a teacher leaves
# alone, not claims about the problem's own u or s. OCR M2 Jan 2007 Q3: thrown down at 21 m/s from
# 40 m: v^2 = 21^2 + 2(9.8)(40) = 441 + 784 = 1225, v = 35 m/s (the chain's u is the rebound's).
THROWN = "chain-ocr-m2-2007-rebounds-to-start"


@pytest.mark.parametrize(
    "first",
    [
        "Down: v^2 = u^2 + 2as, u = 21, a = 9.8, s = 40",
        "using v^2 = u^2 + 2as where u = 21 m/s, s = 40 m, a = 9.8",
        "v^2 = u^2 + 2gh with u = 21, h = 40",
        "fall: v^2 = u^2 + 2gh, where u = 21 m/s and h = 40 m",
    ],
)
def test_a_laws_letters_stated_with_it_are_not_marked(tmp_path, first: str) -> None:
    work = f"{first}\nv^2 = 441 + 784 = 1225\nv = 35 m/s\n"
    got = lines(THROWN, work)
    assert 1 not in got or got[1][0] not in ("wrong", "carried")
    assert got[2][0] == got[3][0] == "correct"


def test_a_result_after_the_laws_letters_is_marked() -> None:
    got = lines(THROWN, "v^2 = u^2 + 2as, u = 21, s = 40 so v^2 = 1255\n")
    assert got[1][0] == "wrong"


# A component named by its axis's sign alone (``∥ = U cos α``, ``⊥ = U sin α``, ``\perp = …``): at a
# wall the component along it (t) and across it (n). Pre-U 2013 Q12(i): the path makes θ with the
# wall, so along the wall the sphere has u cos θ and across it u sin θ before the impact.
PRE_U_WALL = "pre-u-9795-2-2013-june-q12i-wall-rebound-at-right-angles"


@pytest.mark.parametrize(
    ("line", "status"),
    [
        ("∥ = u cos θ", "correct"),
        ("before: ∥ = u cos θ, ⊥ = u sin θ", "correct"),
        ("$\\perp = u\\sin\\theta$", "correct"),
        ("∥ = u sin θ", "wrong"),
    ],
)
def test_an_axis_sign_alone_names_the_component(line: str, status: str) -> None:
    assert worst_lines(PRE_U_WALL, line + "\n")[1][0] == status


# A quantity after said to be a percentage of itself before (``KE after = 60% of before``): that
# fraction times it. Edexcel M4 2018 Q2: the ball keeps 60% of its kinetic energy, so T_2 = 0.6 T_1.
SIXTY = "edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke"


@pytest.mark.parametrize(
    ("line", "status"),
    [
        ("KE after = 60% of before", "correct"),
        ("KE after = 60 % of the original, find alpha", "correct"),
        ("KE_f = 60% of KE_i", "correct"),
    ],
)
def test_a_percentage_of_the_quantity_before(line: str, status: str) -> None:
    assert worst_lines(SIXTY, line + "\n")[1][0] == status
