"""A kinetic energy written without its half where B, at rest, is twice as heavy as A: the
half left out and the masses swapped give the same value (m_A u² = ½ m_B u²). A teacher names
what the line shows: A's own mass and no half is ``ke_formula``; the half and B's mass written
is ``masses_swapped``. Every number is worked by hand from the problem file's givens."""

from __future__ import annotations

import pytest
from support.checked import worst_lines

#: Edexcel M2 2015: P (m) at 3u hits Q (2m) at rest. By hand: the energy before is
#: ½ m (3u)² = 9mu²/2; without the half 9mu²; with the masses swapped ½(2m)(3u)² = 9mu².
P_REVERSES = "edexcel-m2-2015-january-q7-m-at-3u-hits-2m-p-reverses"


def test_the_half_left_out_with_as_own_mass_is_ke_formula() -> None:
    work = "P's way positive; x, y the velocities after.\nm(3u) = mx + 2my\nKE before = m(3u)^2 = 9mu^2\n"
    found = worst_lines(P_REVERSES, work)
    assert found[2][0] == "correct", found
    assert found[3] == ("wrong", "ke_formula"), found


def test_latex_energy_name_without_half() -> None:
    work = "Taking $P$'s direction as positive.\n$$T_1 = m(3u)^2 = 9mu^2$$\n"
    found = worst_lines(P_REVERSES, work)
    assert found[2] == ("wrong", "ke_formula"), found


def test_the_half_and_qs_mass_written_stays_masses_swapped() -> None:
    # ½(2m)(3u)² = 9mu²: the half is there, and the mass is Q's: the masses swapped.
    work = "P's way positive.\nKE before = 1/2 (2m)(3u)^2 = 9mu^2\n"
    found = worst_lines(P_REVERSES, work)
    assert found[2] == ("wrong", "masses_swapped"), found


@pytest.mark.parametrize(
    ("text", "half"),
    [
        ("3/2", False),
        ("\\frac{1}{25}", False),
        ("\\frac{12}{5}", False),
        ("0.50 m v^2", True),
        ("mv^2/2", True),
        ("½mv²", True),
    ],
)
def test_a_half_is_a_half(text: str, half: bool) -> None:
    from derive.checking.energyshown import HALF

    assert bool(HALF.search(text)) is half
