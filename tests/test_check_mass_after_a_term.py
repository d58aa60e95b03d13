"""A lone ``m`` after the number of a term added to others (``1200(6) + 6 m``, ``0.002 +
0.150\\,m``) is a mass times that number, as a momentum's term, not metres: a unit stands after
a whole side or after every term of it (:func:`derive.mathtext.units.letter_in_sum`). The line
then holds or not as its momentum does, and the lines after a slip in it are carried. Values
worked by hand from the givens."""

from __future__ import annotations

from support.checked import lines

# web2.0calc: a 1200 kg car at 10 m/s runs into a parked car of mass m; they move on at 6 m/s.
# 12000 = 7200 + 6m, so m = 4800/6 = 800 kg. The slip: 1200(6) = 7800, so m = 4200/6 = 700 kg.
CARS = "web2calc-car-rear-ends-car-find-mass"


def test_a_mass_after_a_term_of_a_sum_is_read_as_the_mass_not_metres() -> None:
    found = lines(
        CARS,
        "m = mass of the parked car\n$1200(10) + 0 = 1200(6) + 6\\,m$\n$12000 = 7200 + 6\\,m$\n$m = 4800/6 = 800$ kg\n",
    )
    assert [found[n][0] for n in (2, 3, 4)] == ["correct"] * 3


def test_the_mass_found_after_an_arithmetic_slip_in_such_a_line_is_carried() -> None:
    found = lines(
        CARS,
        "m = mass of the parked car\n1200(10) + 0 = 1200(6) + 6 m\n12000 = 7800 + 6 m\nm = 4200/6 = 700 kg\n",
    )
    assert found[2][0] == "correct"
    assert found[3][:2] == ("wrong", "arithmetic")
    assert found[4][0] == "carried"


def test_a_length_after_a_whole_side_is_still_a_unit() -> None:
    from derive.mathtext.units import letter_in_sum

    assert not letter_in_sum("1.41 m")
    assert not letter_in_sum("2 m + 3 m")
    assert letter_in_sum("0.00020 + 0.150 m")
