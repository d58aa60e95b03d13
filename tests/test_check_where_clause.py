"""A line ``= …`` under a line that ends with a where-clause (a name its formula uses, defined
after a comma and worked to numbers) goes on from the formula, not from the definition:
``KE lost = ½μ(1 − e²)(12 − 4)², μ = 4(8)/(4 + 8)`` then ``= ½ × 2.667 × 0.75 × 64 = 64``.

byjus by hand: 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5. Momentum 48 + 32 = 80 = 4 v_A2 +
8 v_B2, v_B2 - v_A2 = 0.5(8) = 4: v_A2 = 4, v_B2 = 8. KE before 288 + 64 = 352, after 32 + 256 =
288, lost 64; by the reduced mass μ = 32/12 = 2.667, ½ μ (1 - 0.25)(8)² = 64. B's impulse
8(8 - 4) = 32 N s.
"""

from __future__ import annotations

import pytest

import derive

BYJUS = "byjus-4kg-ball-catches-8kg-ball"


def statuses(work: str) -> list[str]:
    report = derive.check(derive.solve(derive.load(BYJUS)), derivation=work)
    return [i.status for i in report.items]


@pytest.mark.parametrize(
    ("work", "expected"),
    [
        ("KE lost = ½ μ (1 − e²)(12 − 4)², μ = 4(8)/(4 + 8)\n= ½ × 2.667 × 0.75 × 64 = 64 J", ["correct", "correct"]),
        ("KE lost = ½ μ (1 − e²)(12 − 4)², μ = 4(8)/(4 + 8)\n= ½ × 2.667 × 0.75 × 64 = 72 J", ["correct", "wrong"]),
        ("I = m_B (v_B2 - v_B1), m_B = 8\n= 8(8 - 4) = 32", ["correct", "correct"]),
        ("I = m_B (v_B2 - v_B1), m_B = 8\n= 8(8 - 4) = 40", ["correct", "wrong"]),
        ("v_B2 = v_A2 + 4, v_A2 = 4\n= 8", ["correct", "correct"]),
        ("v_B2 = v_A2 + 4, v_A2 = 4\n= 9", ["correct", "wrong"]),
        ("ΔKE = 0.5 mu (1 - e^2)(12 - 4)^2, where mu = 4*8/12\n= 0.5(2.667)(0.75)(64) = 64", ["correct", "correct"]),
    ],
)
def test_a_line_under_a_where_clause_goes_on_from_the_formula(work: str, expected: list[str]) -> None:
    assert statuses(work) == expected


def test_a_last_relation_no_formula_uses_is_gone_on_from() -> None:
    """``v_A2 = 4, v_B2 = 8`` then ``= 8``: v_B2 is not in v_A2's formula, the line goes on from it."""
    assert statuses("v_A2 = 80/20, v_B2 = 4 + 4\n= 8") == ["correct", "correct"]
