"""A name in brackets with its marks after them (``(v_B)_2``, ``(vA)1``, ``(v_{B})_{2}``) and then
a power typed as a superscript (``²``, ``³``): the name squared, as ``(v_B)_2^2`` is. The
superscript is no part of the name's marks (it was read as one more character of the name, and
the line was not read).

Values worked by hand (Beer & Johnston 13.13, railroad cars: m_A = 20 Mg at 0.5 m/s, m_B = 35 Mg
at rest, 0.3 m/s after): v_A2 = (20 000 × 0.5 − 35 000 × 0.3)/20 000 = −0.025 m/s; the energy
after ½(20 000)(0.025)² + ½(35 000)(0.3)² = 6.25 + 1575 = 1581.25 J.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

from derive.mathtext.reader import read_relations

CARS = "beer-johnston-13-13-railroad-cars-find-e"


@pytest.mark.parametrize(
    ("typed", "side"),
    [
        ("x = (v_B)_2² − 2 a d", "v_B2² − 2 a d"),
        ("x = (vA)1² + (v_{B})_{2}²", "v_A1² + v_B2²"),
        ("x = (v_A)_n³ + (v_A)_2x", "v_An³ + v_A2x"),
        ("x = ½ (2)(v_A)_1²", "½ (2) v_A1²"),
    ],
)
def test_a_superscript_power_after_a_bracketed_name(typed: str, side: str) -> None:
    assert read_relations(typed)[0].sides[1] == side


def test_energy_after_in_bracketed_names_squared() -> None:
    work = "(v_A)_2 = -0.025 m/s\nT_2 = ½(20000)(v_A)_2² + ½(35000)(v_B)_2² = 1581 J\n"
    assert [s for s, _ in worst_lines(CARS, work).values()] == ["correct", "correct"]


def test_energy_after_squared_wrongly_is_still_a_slip() -> None:
    work = "(v_A)_2 = -0.025 m/s\nT_2 = ½(20000)(v_A)_2² + ½(35000)(v_B)_2² = 1750 J\n"
    assert [s for s, _ in worst_lines(CARS, work).values()] == ["correct", "wrong"]


#: A mass in a multiple of the SI unit typed in LaTeX's text inside a side, `(20\text{ Mg})`:
#: 20 000 kg times what follows it, as the plain `(20 Mg)` is, never the product 20·M·g.
@pytest.mark.parametrize(
    "typed",
    [
        r"$(20\text{ Mg})(0.5\text{ m/s}) + 0 = (20\text{ Mg})(v_A)_2 + (35\text{ Mg})(0.3\text{ m/s})$",
        r"$(20\,\mathrm{Mg})(0.5) = (20\mathrm{Mg})\,v_{A2} + (35\ \text{Mg})(0.3)$",
    ],
)
def test_latex_megagrams_inside_a_side(typed: str) -> None:
    assert worst_lines(CARS, typed) == {1: ("correct", "")}


def test_latex_megagrams_with_a_slip_in_them() -> None:  # B's 35 Mg copied as 25: 10 000 ≠ −500 + 7500
    got = worst_lines(CARS, r"$(20\text{ Mg})(0.5) = (20\text{ Mg})(-0.025) + (25\text{ Mg})(0.3)$")
    assert got[1][0] == "wrong"
