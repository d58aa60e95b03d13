"""A mass the line names, put in as the body's weight (``m_B v_B2 = 3000(-0.6)`` with 3000 lb B's
weight), is ``weight_as_mass``, not a number worked wrongly. Values by hand."""

from __future__ import annotations

from support.checked import worst_lines

#: Two cars, 4500 lb at 3 ft/s and 3000 lb at 6 ft/s the other way, e = 0: 4500(3) - 3000(6)
#: = 7500 V, V = -4500/7500 = -0.6 ft/s. B's momentum after is (3000/32.2)(-0.6) = -55.9 slug ft/s,
#: not 3000(-0.6) = -1800.
CARS = "mcasco-two-cars-no-bounce"


def test_a_named_mass_worked_as_the_weight_is_weight_as_mass() -> None:
    found = worst_lines(CARS, "4500(3) - 3000(6) = 7500 V\nV = -0.6 ft/s\nm_B v_B2 = 3000(-0.6) = -1800\n")
    assert found[1][0] == found[2][0] == "correct"
    assert found[3] == ("wrong", "weight_as_mass")
