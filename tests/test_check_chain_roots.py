"""A chain's name of the student's own that no value of the chain fits is what the relation it
is first met in solves it to be; where that relation was worked from a wrong number (carried),
the name is the student's wrong value, and a later line right with it is carried, not correct
(fixC, eighth session). Every number here is worked by hand from the problem file's givens."""

from __future__ import annotations

import derive

# MSU bullet and block: 0.020 kg at 300 m/s lodges in 4.0 kg, which swings up.
# V = 6/4.02 = 1.4925 (1.52 is an arithmetic slip); h_2 = V²/(2g) = 2.2277/19.62 = 0.1135 m.
# With the student's 1.52: y = 1.52²/19.62 = 2.3104/19.62 = 0.1178 m (0.118), no value of the chain.
BULLET = "chain-msu-bullet-block-swings"
SLIP = "0.020(300) = 4.02 V\nV = 6/4.02 = 1.52 m/s\n"


def lines(problem: str, work: str) -> dict[int, tuple[str, str]]:
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    return {int(i.name): (i.status, i.slip) for i in report.items if i.kind == "line" and i.name.isdigit()}


def test_a_name_solved_from_a_carried_energy_line_is_carried_after_it() -> None:
    found = lines(BULLET, SLIP + "1/2 (4.02)(1.52^2) = 4.02(9.81) y\ny = 0.118 m\n")
    assert found[1][0] == "correct"
    assert found[2] == ("wrong", "arithmetic")
    assert found[3][0] == found[4][0] == "carried"


def test_a_name_solved_from_a_carried_rule_of_motion_is_carried_after_it() -> None:
    found = lines(BULLET, SLIP + "(1.52)^2 = 2(9.81) y\ny = 0.1178\n")
    assert found[3][0] == found[4][0] == "carried"


def test_a_name_solved_from_a_right_line_is_still_correct() -> None:
    # 1.49² = 2.2201; 2.2201/19.62 = 0.11315 (0.113): the chain's h_2 at its figures
    found = lines(BULLET, "0.020(300) = 4.02 V\nV = 6/4.02 = 1.49 m/s\n(1.49)^2 = 2(9.81) y\ny = 0.113\n")
    assert [found[n][0] for n in (1, 2, 3, 4)] == ["correct"] * 4
