"""A momentum's unit typed with a product sign between its kilograms and its metres per second
(``kg*m/s``, ``kg×m/s``, ``kg⋅m/s``, the US engineers' ``kg-m/s``) inside a side: the sign is the
unit's, not an operator. The kilograms alone were taken off as a mass's unit, leaving ``*m/s``:
the line not read, or ``s`` read by its value as an impulse so that a wrong line held
(``m_A (1 m/s) = 0.58 kg*m/s - 0.3 kg*m/s``, a sign lost moving 0.3 across, passed as correct)."""

from __future__ import annotations

import pytest

import derive

# AQA M3 2007: A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward it (right positive). By hand the
# momentum before is 0.3(3) + 0.2(-2) = 0.9 - 0.4 = 0.5; 0.9 + 0.4 = 1.3 is B's sign lost.
PROBLEM = "aqa-m3-2007-spheres-approach-head-on"
FIRST = "Taking right as positive.\n0.3(3) + 0.2(-2) = 0.3 v_A + 0.2 v_B\n"


@pytest.mark.parametrize(
    ("line", "status"),
    [
        ("0.3 v_A + 0.2 v_B = 0.9 kg*m/s - 0.4 kg*m/s", "correct"),
        ("0.3 v_A + 0.2 v_B = 0.9 kg×m/s + 0.4 kg×m/s", "wrong"),
        ("0.3 v_A + 0.2 v_B = 0.5 kg-m/s", "correct"),
        ("0.3 v_A + 0.2 v_B = 1.3 kg⋅m/s", "wrong"),
    ],
)
def test_a_momentum_unit_with_a_product_sign(line: str, status: str) -> None:
    report = derive.check(derive.load(PROBLEM), derivation=FIRST + line + "\n")
    item = next(i for i in report.items if i.kind == "line" and i.name == "3")
    assert item.status == status, item.message
