"""A percentage written after a side multiplied by 100 (``64/352 × 100 = 18.2 %``): the ``%`` is
the number's label, as a teacher reads it, not a factor 1/100 that makes a right line false; and
such a line worked from a wrong energy is carried, not a further slip.

The problem (BYJU'S, 4 kg ball at 12 m/s catches an 8 kg ball at 4 m/s, e = 0.5): after the impact
4 and 8 m/s; KE before ½(4)(12²) + ½(8)(4²) = 288 + 64 = 352 J, after ½(4)(4²) + ½(8)(8²) =
32 + 256 = 288 J; lost 64 J, 64/352 = 18.18 % of it.
"""

from __future__ import annotations

import pytest
from support.checked import lines

PROBLEM = "byjus-4kg-ball-catches-8kg-ball"
BEFORE = "KE before = 1/2(4)(12)^2 + 1/2(8)(4)^2 = 352 J\n"


@pytest.mark.parametrize(
    "work",
    [
        "KE after = 1/2(4)(4)^2 + 1/2(8)(8)^2 = 288 J\nKE lost = 352 - 288 = 64 J\npercentage lost = 100 x 64/352 = 18.2 %",
        "KE after = 1/2(4)(4)^2 + 1/2(8)(8)^2 = 288 J\nKE lost = 352 - 288 = 64 J\n"
        "percentage lost $= \\frac{64}{352} \\times 100 = 18.2\\%$",
        "KE after = 1/2(4)(4)^2 + 1/2(8)(8)^2 = 288 J\nkept: 288/352 = 0.818 = 81.8%",  # 0.818 is 81.8 %: as written
    ],
)
def test_a_percentage_after_a_side_times_100_is_read_as_that_number(work: str) -> None:
    found = lines(PROBLEM, BEFORE + work)
    assert {n: s[0] for n, s in found.items()} == dict.fromkeys(found, "correct"), found


def test_a_percentage_worked_from_a_wrong_energy_is_carried() -> None:
    # the squares of the speeds after forgotten: ½(4)(4) + ½(8)(8) = 8 + 32 = 40 J (not 288);
    # lost 352 - 40 = 312 J and 312/352 × 100 = 88.6 %: both carried
    work = BEFORE + "KE after = 1/2(4)(4) + 1/2(8)(8) = 40 J\nKE lost = 352 - 40 = 312 J\n"
    work += "percentage lost $= \\frac{312}{352} \\times 100 = 88.6\\%$"
    found = lines(PROBLEM, work)
    assert found[2][0] == "wrong", found
    assert (found[3][0], found[4][0]) == ("carried", "carried"), found
