"""A name set to a mass whose number is the given's copied wrongly (its point moved: 20 g written
0.2 kg; its digits in another order) still names that given mass, as a teacher reads it: the line
that sets it is the slip (a given copied wrongly) and the lines worked from it are carried. Before,
a mass's name was known by its value only, so the next lines were not read (the corpus's zg08:
"Bullet m = 20 g = 0.2 kg", then m u = (m + M) V).

Worked by hand.
openstax-cp-8-30 (puck 0.150 kg at 35.0 m/s, goalie 70.0 kg at rest, e = 1), the puck's mass
written 1.50 kg: m u = m v + M w holds whatever the numbers; the goalie's velocity after, by the
elastic formula 2 m u/(m + M), is 2(1.50)(35.0)/71.5 = 105/71.5 = 1.4685 = 1.47 m/s on the copy
(0.14968 m/s truly): carried.
uoguelph-8-34 (22 g at 3.5 m/s hits 27 g at rest, e = 1), the 27 g written 0.27 kg: the second
ball's velocity after is 2 m_s u/(m_s + M) = 2(0.022)(3.5)/0.292 = 0.154/0.292 = 0.527 m/s on the
copy (0.154/0.049 = 3.14 m/s truly): carried.
"""

from __future__ import annotations

from support.checked import lines

PUCK = "openstax-cp-8-30-puck-bounces-off-goalie"
BALLS = "uoguelph-8-34-superballs-grams"


def test_a_mass_with_its_point_moved_names_the_given_and_the_working_is_carried() -> None:
    work = "m = 1.50 kg (the puck), M = 70.0 kg, u = 35.0 m/s\nm u = m v + M w\nw = 2 m u/(m + M) = 2(1.50)(35.0)/71.5 = 1.47"
    found = lines(PUCK, work)
    assert found[1][:2] == ("wrong", "copied_wrong")
    assert found[2][0] == "correct"
    assert found[3][0] == "carried"


def test_grams_turned_into_kilograms_wrongly_name_the_given() -> None:
    work = (
        "m_s = 0.022 kg, M = 27 g = 0.27 kg, u = 3.5 m/s\nw = 2 m_s u/(m_s + M)\nw = 2(0.022)(3.5)/(0.292) = 0.527 m/s"
    )
    found = lines(BALLS, work)
    assert found[1][:2] == ("wrong", "copied_wrong")
    assert found[2][0] == "correct"
    assert found[3][0] == "carried"
