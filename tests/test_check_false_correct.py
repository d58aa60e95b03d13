"""Slips a teacher marks wrong that the checker must not call correct (issue #31, fixG): an
impulse named by its letter and worked with a weight as the mass, after the velocities were
stated right. Every number here is worked by hand from the problem files' givens (in the
comments), never from derive's output."""

from __future__ import annotations

import pytest
from support.checked import WALL_30, solved_text

import derive


def lines(problem: str, work: str) -> dict[int, tuple[str, str]]:
    """line number -> (status, slip name) of ``derive check PROBLEM --derivation``."""
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    return {int(i.name): (i.status, i.slip) for i in report.items if i.kind == "line" and i.name.isdigit()}


# Two cars (M. Casco): 4500 lb at 3 ft/s, 3000 lb at 6 ft/s the other way, locked together.
# Masses 4500/32.2 = 139.75 and 3000/32.2 = 93.17 slug: 419.25 - 559.01 = 232.92 v, v = -0.6 ft/s.
# Impulse on B: 93.17(-0.6 + 6) = 503.1 lb s; with the weight as the mass 3000(5.4) = 16200.
CARS = "(4500/32.2)(3) + (3000/32.2)(-6) = (7500/32.2) v\nv = -0.6 ft/s\n"


@pytest.mark.parametrize(
    "said",
    [
        "Impulse on car B: $I = m\\,\\Delta v = 3000(-0.6 + 6) = 16200$ lb s",
        "Impulse on B: J = m_B Delta v = 3000(5.4) = 16200 lb s",
        "impulse on B = change in momentum = 3000(-0.6 - (-6)) = 16200",
        "$J = m \\Delta v = 3000 \\times 5.4 = 16200$",
    ],
)
def test_an_impulse_by_its_letter_worked_with_the_weight_as_the_mass_is_weight_as_mass(said: str) -> None:
    found = lines("mcasco-two-cars-no-bounce", CARS + said + "\n")
    assert found[1][0] == found[2][0] == "correct"
    assert found[3] == ("wrong", "weight_as_mass")


def test_an_impulse_by_its_letter_worked_with_the_mass_is_correct() -> None:
    # 3000/32.2 = 93.168 slug; 93.168 x 5.4 = 503.1 lb s
    found = lines(
        "mcasco-two-cars-no-bounce", CARS + "Impulse on B: $J = m\\,\\Delta v = (3000/32.2)(5.4) = 503.1$ lb s\n"
    )
    assert found[3][0] == "correct"


# OCR M2 2012: 0.8 kg at 4 m/s into a wall, e = 0.3. Toward the wall is derive's +n: the
# rebound is 0.3 x 4 = 1.2 m/s away from the wall (v = -1.2); KE 6.4 -> 0.576, lost 5.824 J.
WALL = "ocr-m2-2012-particle-hits-wall"


@pytest.mark.parametrize(
    "said",
    [
        "(towards the wall is +)",
        "(+ towards the wall)",
        "(toward wall = +)",
        "(+ = towards the wall)",
        "taking towards the wall as +",
    ],
)
def test_a_convention_said_with_a_bare_plus_grounds_the_frame(said: str) -> None:
    # toward the wall positive: the velocity after is -1.2; "v = 1.2" has the rebound's sign lost,
    # whatever frame would make it hold, and the impulse worked from it is carried
    work = f"u = 4 m/s {said}\nv = 0.3 u = 1.2\nI = 0.8(u - v) = 0.8(4 - 1.2) = 2.24\n"
    found = lines(WALL, work)
    assert found[2][0] == "wrong" and found[3][0] == "carried"
    right = lines(WALL, f"u = 4 m/s {said}\nv = -0.3 u = -1.2\nI = 0.8(v - u) = 0.8(-1.2 - 4) = -4.16\n")
    assert [right[k][0] for k in (1, 2, 3)] == ["correct"] * 3


@pytest.mark.parametrize("said", ["(away from the wall is +)", "(+ away from the wall)", "(+ve away from the wall)"])
def test_the_reversed_convention_said_with_a_bare_plus(said: str) -> None:
    # away from the wall positive: u = -4 and the velocity after +1.2
    assert lines(WALL, f"u = -4 m/s {said}\nv = 1.2\n")[2][0] == "correct"
    assert lines(WALL, f"u = -4 m/s {said}\nv = -1.2\n")[2][0] == "wrong"


# AQA M3 2007: 0.3 kg at 3 m/s meets 0.2 kg at 2 m/s head-on, e = 0.8 (right positive):
# 0.9 - 0.4 = 0.3a + 0.2b, b - a = 0.8(5) = 4 -> 0.5a = -0.3, a = -0.6 (0.6 m/s to the left), b = 3.4.
SPHERES_07 = "aqa-m3-2007-spheres-approach-head-on"


@pytest.mark.parametrize(
    "line",
    [
        "v_A = 0.3/0.5 = 0.6 m/s to the left",
        "v_A = (0.8 - 0.5)/0.5 = 0.6 m/s in the opposite direction",
        "v_A = (0.5 - 0.8)/0.5 = 0.6 m/s to the left",
        "v_A = -0.6 m/s, so 0.6 m/s to the left",
    ],
)
def test_a_size_worked_out_with_its_way_in_words_after_it(line: str) -> None:
    assert lines(SPHERES_07, line + "\n")[1][0] == "correct"


def test_a_size_worked_out_said_to_go_the_wrong_way_is_wrong() -> None:
    assert lines(SPHERES_07, "v_A = 0.3/0.5 = 0.6 m/s to the right\n")[1][0] == "wrong"


SPHERES = """title = "Spheres meet head-on: find the mass of A"
kind = "direct"
statement = "A meets B (0.1 kg) head-on; A goes on at 3 m/s and B comes back at 3.8 m/s."
question = "Find the mass of A and e."
find = ["e", "m_A"]

[given]
m_A = "? kg"
m_B = "0.1 kg"
e = "?"
v_A1 = "4 m/s"
v_B1 = "-2 m/s"
v_A2 = "3 m/s"
v_B2 = "3.8 m/s"
"""


def test_a_given_copied_with_a_digit_changed_is_no_rounding(tmp_path) -> None:
    # 4m - 0.1(2) = 3m + 0.1(3.8): m_A = 0.38 + 0.2 = 0.58 kg; e = (3.8 - 3)/(4 + 2) = 0.1333.
    # B's 3.8 copied as 3.3: at m_A = 0.58 the sides are 2.12 and 2.07, 2.4 % apart, within
    # 3.3's last figure (3 %) as a rounding would be; but 3.3 is no rounding of 3.8: copied_wrong.
    path = tmp_path / "spheres.toml"
    path.write_text(SPHERES)
    work = "4m_A - 0.1(2) = 3m_A + 0.1(3.3)\nm_A = 0.33 + 0.2 = 0.53 kg\n"
    report = derive.check(derive.solve(derive.load(str(path))), derivation=work)
    found = {int(i.name): (i.status, i.slip) for i in report.items if i.kind == "line"}
    assert found[1] == ("wrong", "copied_wrong")
    assert found[2][0] == "carried"
    right = derive.check(derive.solve(derive.load(str(path))), derivation="4m_A - 0.1(2) = 3m_A + 0.1(3.8)\n")
    assert right.items[0].status == "correct"


@pytest.mark.parametrize(
    ("par", "perp"), [("v_par", "v_perp"), ("v_parallel", "v_perpendicular"), ("v_along", "v_across")]
)
def test_components_after_named_parallel_and_perpendicular_to_a_wall(tmp_path, par: str, perp: str) -> None:
    # along the wall 10 cos 30 = 8.660 is kept; into it 10 sin 30 = 5 becomes 0.5 x 5 = 2.5 away
    sol = solved_text(tmp_path, "wall.toml", WALL_30)

    def judged(work: str) -> list[str]:
        return [i.status for i in derive.check(sol, derivation=work).items if i.kind == "line"]

    assert judged(f"after: {par} = 10 cos 30 = 8.660\nafter: {perp} = 0.5(10 sin 30) = 2.5\n") == ["correct"] * 2
    # e on the part along the wall: wrong, not a definition of the student's own name
    assert judged(f"after: {par} = 0.5(10 cos 30) = 4.330\n")[0] == "wrong"
    assert judged(f"after: {perp} = 10 sin 30 = 5\n")[0] == "wrong"


# BYJU'S (A 4 kg at 12 m/s catches B 8 kg at 4 m/s, e = 0.5), by hand: 80 = 4a + 8b, b - a = 4,
# so a = 4 and b = 8 m/s. KE after = ½(4)(4²) + ½(8)(8²) = 32 + 256 = 288 J; KE before =
# ½(4)(12²) + ½(8)(4²) = 288 + 64 = 352 J. Worked with 5 for A's velocity after the energy is
# ½(4)(5²) + ½(8)(8²) = 50 + 256 = 306 J: its arithmetic is right, the energy is not.
CATCH_WORK = "4(12) + 8(4) = 4a + 8b\nb - a = 0.5(12 - 4) = 4\na = 4 m/s, b = 8 m/s\n"


@pytest.mark.parametrize(
    "when",
    ["just after", "immediately after", "right after", "just after the collision", "after impact", "(after)"],
)
def test_an_energy_named_at_a_moment_said_closely_is_judged(when: str) -> None:
    name = "KE"
    right = lines("byjus-4kg-ball-catches-8kg-ball", CATCH_WORK + f"{name} {when} = ½(4)(4)² + ½(8)(8)² = 288 J\n")
    assert right[4][0] == "correct", right
    wrong = lines("byjus-4kg-ball-catches-8kg-ball", CATCH_WORK + f"{name} {when} = ½(4)(5)² + ½(8)(8)² = 306 J\n")
    assert wrong[4][0] == "wrong", wrong


def test_an_energy_before_named_closely_is_judged() -> None:
    found = lines("byjus-4kg-ball-catches-8kg-ball", "KE immediately before = ½(4)(12)² + ½(8)(4)² = 352 J\n")
    assert found[1][0] == "correct", found
    found = lines("byjus-4kg-ball-catches-8kg-ball", "KE just before = ½(4)(12)² + ½(8)(5)² = 388 J\n")
    assert found[1][0] == "wrong", found


# The same (BYJU'S): the momentum before is 4(12) + 8(4) = 80 kg m/s, and after 4(4) + 8(8) = 80.
# A's velocity after taken the other way: 4(-4) + 8(8) = 48, its arithmetic right, the momentum not.
@pytest.mark.parametrize("p", ["p ", "p_", "total p "])
def test_a_momentum_named_p_before_or_after_is_judged(p: str) -> None:
    work = f"{p}before = 4(12) + 8(4) = 80\n{p}after = 4(4) + 8(8) = 80\n"
    assert lines("byjus-4kg-ball-catches-8kg-ball", work) == {1: ("correct", ""), 2: ("correct", "")}
    work = f"{p}before = 4(12) + 8(4) = 80\n{p}after = 4(-4) + 8(8) = 48\n"
    assert lines("byjus-4kg-ball-catches-8kg-ball", work)[2][0] == "wrong"


# OCR FM 2023 (A 5 kg at 4 m/s at 60° to the line of centres, B 3 kg at 6 m/s toward A, e = 3/4),
# by hand: A's components 4 cos 60° = 2 along, 4 sin 60° = 3.46 across; 10 - 18 = -8 = 5a + 3b,
# b - a = 0.75(2 + 6) = 6, so 8a = -26: a = -3.25, b = 2.75. A keeps 3.46 across: speed
# √(3.25² + 3.46²) = 4.75. With e put on the component across too: 0.75 × 3.46 = 2.60 and
# √(3.25² + 2.60²) = 4.16, carried.
@pytest.mark.parametrize(("x", "y"), [("v_x", "v_y"), ("V_x", "V_y")])
def test_the_other_component_of_a_velocity_read_along_x_is_its_component_across(x: str, y: str) -> None:
    work = f"5(2) + 3(-6) = 5{x} + 3w\nw - {x} = 0.75(2 + 6) = 6\n-8 = 5{x} + 3({x} + 6), {x} = -3.25\n"
    slip = lines(
        "ocr-fm-2023-oblique-discs-60deg", work + f"{y} = 0.75 × 3.46 = 2.60\nspeed of A = √(3.25² + 2.60²) = 4.16\n"
    )
    assert [slip[k] for k in (4, 5)] == [("wrong", "e_on_t"), ("carried", "")], slip
    right = lines("ocr-fm-2023-oblique-discs-60deg", work + f"{y} = 3.46\nspeed of A = √(3.25² + 3.46²) = 4.75\n")
    assert {s for s, _ in right.values()} == {"correct"}, right
