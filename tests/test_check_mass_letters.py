"""A lone ``m`` in a general formula where the bodies' masses differ, named by the number put in
its place on the same line (issue #31): ``impulse on B = m(v_B - u_B) = 8(8 - 4)`` is B's mass;
``KE lost = ½ m(u - V)² = ½(0.020)(…)²`` the bullet's. The line is then judged (before: not read).

Worked by hand (byjus-4kg-ball-catches-8kg-ball): 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5;
v_A = 4, v_B = 8 after (momentum 80 = 4 v_A + 8 v_B, v_B - v_A = 4). Impulse on B 8(8 - 4) = 32 N s,
on A 4(4 - 12) = -32 N s. Wrong: on A 4(12 - 4) = 32 (before minus after).
(ocr-m2-2006-sphere-hits-sphere-at-rest-find-e): A 2 kg at 5 m/s: KE before ½(2)(5²) = 25 J;
m u² = 2 × 25 = 50 is the half left out (ke_formula).
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses
from support.checked import lines

from derive.checking.massletters import _M

CATCH = "byjus-4kg-ball-catches-8kg-ball"
SOLVED = "4(12) + 8(4) = 4 v_A + 8 v_B\nv_B - v_A = 0.5(12 - 4) = 4\nv_A = 4, v_B = 8\n"
SPHERES = "ocr-m2-2006-sphere-hits-sphere-at-rest-find-e"


@pytest.mark.parametrize(
    "line", ["impulse on B = m(v_B - u_B) = 8(8 - 4) = 32", "impulse on A = m(v_A - u_A) = 4(4 - 12) = -32"]
)
def test_m_named_by_the_mass_put_in_for_it(line: str) -> None:
    assert statuses(CATCH, SOLVED + line)[-1] == "correct"


def test_a_formula_with_m_worked_wrongly_is_wrong() -> None:
    assert statuses(CATCH, SOLVED + "impulse on A = m(v_A - u_A) = 4(12 - 4) = 32")[-1] == "wrong"
    work = "CLM: 2(5) + 1(0) = 2(3) + 1v\nv = 4\nKE before = mu^2 = 2 x 25 = 50 J"
    assert lines(SPHERES, work)[3][:2] == ("wrong", "ke_formula")


@pytest.mark.parametrize(("text", "lone"), [("(1/2) m(u - V)^2", True), ("3 m/s", False), ("4 m s^-1", False)])
def test_a_unit_of_metres_is_no_mass(text: str, lone: bool) -> None:
    assert bool(_M.search(text)) is lone
