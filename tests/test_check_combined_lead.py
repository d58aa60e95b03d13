"""Equations combined, leading in, with a multiplier written after a reference (``(2)×(−1)``,
``(2) x 3``), then abandoned after an ellipsis for another way (``… easier: from (2) v_A = …``):
the lead-in and the words are not the relation's; the relation after them is judged.

byjus by hand: 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5: (1) 80 = 4 v_A2 + 8 v_B2,
(2) v_B2 - v_A2 = 0.5(12 - 4) = 4; so v_B2 = v_A2 + 4 (and v_A2 = 4, v_B2 = 8).
"""

from __future__ import annotations

import pytest

import derive
from derive.mathtext.reader import read_relations

BYJUS = "byjus-4kg-ball-catches-8kg-ball"
EQUATIONS = "4(12) + 8(4) = 4v_A2 + 8v_B2 …(1)\nv_B2 − v_A2 = 0.5(12 − 4) …(2)\n"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("(2) − (1)×(−3)… nicer: from (1) p = q − 2, into (2):", [("p", "q − 2")]),
        ("(1) + (2) x 3... quicker: x = 2y - 1", [("x", "2y - 1")]),
        ("(1) − (2)×(−1): v_A = 3", [("v_A", "3")]),
    ],
)
def test_a_combination_with_a_multiplier_after_a_reference_leads_in(text: str, expected: list) -> None:
    assert [r.sides for r in read_relations(text)] == expected


@pytest.mark.parametrize(
    ("line", "expected"),
    [
        ("(1) + (2)×(−1)… simpler: from (2) v_B2 = v_A2 + 4", "correct"),
        ("(1) − (2)×(−2)... easier: from (2) v_A2 = v_B2 − 4", "correct"),
        ("(1) + (2)×(−1)… simpler: from (2) v_B2 = v_A2 + 3", "wrong"),
    ],
)
def test_the_relation_after_an_abandoned_combination_is_judged(line: str, expected: str) -> None:
    report = derive.check(derive.solve(derive.load(BYJUS)), derivation=EQUATIONS + line)
    assert [i.status for i in report.items] == ["correct", "correct", expected]
