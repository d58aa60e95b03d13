"""A decimal set against working in the unknowns with no decimal in it (``2v = 6.8``), where that
working's value is a decimal of no more places than written (2v is 6.9 exactly, from exact data):
the number is that value or a slip. The ±1 in its last digit is the slack of rounded intermediates,
and exact arithmetic from exact data has none; it let ``7 − 0.1 = 6.8`` pass. A value that does not
end at the places written (3.4/3 = 1.133…) is a rounding and keeps its slack."""

from __future__ import annotations

import pytest

import derive

# AQA M3 2007: A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward it, e = 0.8 (right positive). By hand:
# 0.3 v_A + 0.2 v_B = 0.9 - 0.4 = 0.5 and v_B - v_A = 0.8(3 + 2) = 4, so 0.5 v_A + 0.8 = 0.5:
# v_A = -0.6, v_B = 3.4 exactly. Then 2 v_B = 6.8, 5 v_A = -3.0, v_A + v_B = 2.8, 3 v_B = 10.2
# exactly, and v_B/3 = 1.1333…
PROBLEM = "aqa-m3-2007-spheres-approach-head-on"
FIRST = "Taking right as positive.\n0.3(3) + 0.2(-2) = 0.3 v_A + 0.2 v_B\nv_B - v_A = 0.8(3 + 2) = 4\n"


@pytest.mark.parametrize(
    ("line", "status"),
    [
        ("2 v_B = 6.9", "wrong"),
        ("5 v_A = -3.1", "wrong"),
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
