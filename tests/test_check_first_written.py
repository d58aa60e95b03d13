"""The slip is where its wrong value is first written: a line right only as arithmetic, whose
quantity the checker cannot place (``k = 0.6 × 3.05 = 1.83``), that comes to the value of a
velocity after that the mistake found later gives (and the problem does not), is the slip; the
line the mistake was found on, worked from it, is carried. Values by hand."""

from __future__ import annotations

from support.checked import worst_lines

#: Example 4.C.11: A's t component 5 sin 37.6° = 3.053 is kept (v_A2t = 3.05); e applied to it
#: gives 0.6 × 3.053 = 1.832 (1.83), and A's speed sqrt(1.83² + 1.11²) = 2.14 for the true 3.24.
SPHERES = "notes-4c11-two-spheres"
#: A 2 kg ball at 4 m/s into a wall, e = 0.4: it rebounds at 0.4 × 4 = 1.6 m/s. Restitution
#: upside down: 4/0.4 = 10 m/s, and ½(2)(10²) = 100 J after (the true 2.56 J).
WALL = "edexcel-m2-ball-rebounds-from-wall"


def test_a_t_component_worked_with_e_under_a_name_of_its_own() -> None:
    found = worst_lines(SPHERES, "k = 0.6 × 3.05 = 1.83\nspeed of A after = sqrt(1.83^2 + 1.11^2) = 2.14 m/s\n")
    assert found[1] == ("wrong", "e_on_t")
    assert found[2][0] == "carried"


def test_a_rebound_speed_worked_upside_down_before_the_energy() -> None:
    work = "Ball into the wall, towards the wall positive.\nr = 4/0.4 = 10\nKE after = 1/2 (2)(10^2) = 100 J\n"
    found = worst_lines(WALL, work)
    assert found[2] == ("wrong", "restitution_reversed")
    assert found[3][0] == "carried"


def test_a_right_value_under_a_name_of_its_own_stays_correct() -> None:
    found = worst_lines(
        WALL, "Ball into the wall, towards the wall positive.\nr = 0.4 × 4 = 1.6\nKE after = 1/2 (2)(1.6^2) = 2.56 J\n"
    )
    assert found[2][0] == found[3][0] == "correct"


#: 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5: v_A = 4, v_B = 8. B's sign lost: 48 - 32 = 16 =
#: 4a + 8b, b - a = 0.5(16) = 8: a = -4, b = 4 (B's velocity after 4, the same number as its given 4).
CATCH = "byjus-4kg-ball-catches-8kg-ball"


def test_a_value_of_the_data_under_a_name_of_its_own_is_never_the_slip() -> None:
    found = worst_lines(CATCH, "k = 2 × 2 = 4\n4(12) + 8(-4) = 4 v_A + 8 v_B\n")
    assert found[1][0] == "correct"  # B's given 4, though B's sign lost makes its velocity after 4 too
    assert found[2] == ("wrong", "b_sign")
