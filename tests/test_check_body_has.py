"""A body's letter said before a name is that name's body, as a lead-in ``B:`` is: ``so B has
u = -2``, ``for Q, v = 3``. The habit's ``u`` alone (the velocity before) is then B's, not A's.

OCR M2 2006 by hand: A (2 kg) at 5 m/s meets B (1 kg) at 5 m/s head-on, e = 0.8; rightwards
positive, u_A = 5, u_B = -5; 2(5) + 1(-5) = 5 = 2v_A + v_B, v_B - v_A = 0.8(10) = 8, so v_A = -1, v_B = 7.
"""

from __future__ import annotations

import pytest

import derive
from derive.mathtext.reader import read_relations

PROBLEM = "ocr-m2-2006-spheres-meet-at-5-ke-lost"
WORK = """right is +ve, so A has u = 5 and B has u = -5
2(5) + 1(-5) = 2v_A + v_B
v_B - v_A = 0.8(5 + 5)
v_A = -1, v_B = 7
"""


def statuses(work: str) -> list[str]:
    report = derive.check(derive.solve(derive.load(PROBLEM)), derivation=work)
    return [i.status for i in report.items if i.kind == "line"]


@pytest.mark.parametrize(
    ("work", "expected"),
    [
        (WORK, ["correct"] * 4),
        (WORK.replace("B has u = -5", "B has u = 5"), ["wrong", "correct", "correct", "correct"]),
        (WORK.replace("so A has u = 5 and B has u = -5", "(for A, u = 5; for B, u = -5)"), ["correct"] * 4),
    ],
)
def test_a_body_said_before_a_name_is_its_body(work: str, expected: list[str]) -> None:
    assert statuses(work) == expected


@pytest.mark.parametrize(
    ("text", "label"),
    [
        ("so B has u = -2", "B"),
        ("(for Q, v = 3)", "Q"),
        ("For Q, v = 3", "Q"),
        ("u = -2", ""),
        ("A has mass m = 2", ""),
    ],
)
def test_the_body_is_read_as_the_relations_lead_in(text: str, label: str) -> None:
    found = read_relations(text)
    assert [r.label for r in found] == ([label] if found else []), found
