"""A percentage worked as a fraction times 100 (``12/37.5 x 100 = 32%``): the ``%`` labels the number
worked, it is not a division by 100 (the side before it is already times 100).

Worked by hand (ocr-m2-2006-spheres-meet-at-5-ke-lost): A (2 kg) and B (1 kg) meet head-on at
5 m/s each, e = 0.8: KE before ½·2·25 + ½·1·25 = 37.5 J, after 25.5 J, lost 12 J; the share lost
12/37.5 = 0.32, that is 32 %.
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

SPHERES = "ocr-m2-2006-spheres-meet-at-5-ke-lost"


@pytest.mark.parametrize(
    "line",
    [
        "12/37.5 x 100 = 32% of the KE before is lost",
        "percentage lost = (12/37.5) * 100 = 32 %",
        "$\\frac{12}{37.5} \\times 100 = 32\\%$ of the initial kinetic energy",
        "fraction lost = 12/37.5 = 32%",
    ],
)
def test_a_percentage_of_the_energy_lost_is_right(line: str) -> None:
    assert statuses(SPHERES, line) == ["correct"]


def test_a_wrong_percentage_times_100_is_still_wrong() -> None:
    assert statuses(SPHERES, "fraction lost = 12/37.5 x 100 = 40%") == ["wrong"]
    assert statuses(SPHERES, "fraction lost = 12/37.5 x 100 = 0.32%") == ["wrong"]
