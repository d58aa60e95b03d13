"""A decimal set against working in the unknowns with no decimal in it (``2v = 6.8``), whose value
is a decimal of exactly the places written (2v is 6.9, from exact data), is that value or a slip:
the ±1 in its last digit is the slack of rounded intermediates, and exact arithmetic from exact
data has none; it let ``7 − 0.1 = 6.8`` pass. A number written to more places than its exact value
has (0.0499 for 0.05) was worked from rounded decimals, and a value that does not end (3.4/3 =
1.133…) is a rounding: both keep their slack."""

from __future__ import annotations

import pytest

import derive

# AQA M3 2007: A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward it, e = 0.8 (right positive). By hand:
# 0.3 v_A + 0.2 v_B = 0.9 - 0.4 = 0.5 and v_B - v_A = 0.8(3 + 2) = 4, so 0.5 v_A + 0.8 = 0.5:
# v_A = -0.6, v_B = 3.4 exactly. Then 2 v_B = 6.8, 4 v_B = 13.6, v_A + v_B = 2.8, 3 v_B = 10.2
# exactly, to the places written; 5 v_A = -3 has none, and v_B/3 = 1.1333… does not end.
PROBLEM = "aqa-m3-2007-spheres-approach-head-on"
FIRST = "Taking right as positive.\n0.3(3) + 0.2(-2) = 0.3 v_A + 0.2 v_B\nv_B - v_A = 0.8(3 + 2) = 4\n"


@pytest.mark.parametrize(
    ("line", "status"),
    [
        ("2 v_B = 6.9", "wrong"),
        ("4 v_B = 13.7", "wrong"),
        ("5 v_A = -3.1", "correct"),  # -3 has no tenths: a student who writes them was rounding
        ("v_A + v_B = 2.9", "wrong"),
        ("3 v_B = 10.3", "wrong"),
        ("2 v_B = 6.8", "correct"),
        ("v_A + v_B = 2.8", "correct"),
        ("v_B/3 = 1.13", "correct"),
        ("v_B/3 = 1.14", "correct"),  # 1.133… rounded: ±1 in the last digit as before
    ],
)
def test_a_decimal_against_exact_working(line: str, status: str) -> None:
    report = derive.check(derive.load(PROBLEM), derivation=FIRST + line + "\n")
    item = next(i for i in report.items if i.kind == "line" and i.name == "4")
    assert item.status == status, item.message
