"""A unit after each number inside a side, a mass's and a momentum's too, and the last factor's in
its brackets (derive/mathtext/sides.py: units_inside)."""

from __future__ import annotations

from support.checked import worst_lines

from derive.mathtext.sides import units_inside


def test_a_mass_unit_before_a_name_and_a_momentum_unit_are_units() -> None:
    # Cars couple: 150000(0.300) + 110000(-0.120) = 45000 - 13200 = 31800 = 260000 V, V = 0.1223 m/s.
    # 150 tonnes is 150000 kg.
    work = """(150000 kg)(0.300 m/s) + (110000 kg)(-0.120 m/s) = (260000 kg) V
45000 kg·m/s - 13200 kg·m/s = 260000 V
(150 tonnes)(0.300 m/s) + (110 tonnes)(-0.120 m/s) = 31800 kg·m/s
(150 tonnes)(0.300 m/s) + (110 tonnes)(-0.120 m/s) = 58200 kg·m/s
"""
    got = worst_lines("openstax-cp-8-train-cars-couple", work)
    assert [got[n][0] for n in (1, 2, 3)] == ["correct"] * 3
    assert got[4][0] == "wrong"  # 45000 + 13200: B's sign lost


def test_the_units_taken_off_and_a_thousand_kilograms_as_its_factor() -> None:
    assert units_inside("(20 Mg) v_A2 + (35 Mg)(0.3)") == "(20*1000) v_A2 + (35*1000)(0.3)"
    assert units_inside("7200 kg·m/s + (6 m/s) m_B") == "7200 + (6) m_B"
    assert units_inside("(2 g) h") == "(2 g) h"  # g is gravity's letter too
    assert units_inside("12 m/s") == "12 m/s"  # a side's own unit, read with the side
