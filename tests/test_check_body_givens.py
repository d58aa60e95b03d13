"""A given of one body (a weight W_A, W_B) under the student's mark for the body: ``W1``, ``W_2``,
``W_{1}``, ``W_b``, as the masses are ``m1``, ``m_2`` (docs/checking.md, "Names")."""

from __future__ import annotations

import pytest

import derive

#: Hibbeler 15-58: a 15 lb suitcase A at 19.657 ft/s into a 10 lb suitcase B at rest, e = 0.3, g = 32.2
#: ft/s². By hand: m_A = 15/32.2 = 0.46584 slug, m_B = 10/32.2 = 0.31056 slug; A's momentum before
#: 0.46584(19.657) = 9.1570 slug ft/s.
SUITCASES = "hibbeler-15-58-suitcases"


def statuses(problem: str, work: str) -> dict[int, str]:
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    worst = ("wrong", "carried", "error", "not read", "not checked", "correct")
    out: dict[int, str] = {}
    for i in report.items:
        if i.kind == "line" and i.name.isdigit():
            n, old = int(i.name), out.get(int(i.name))
            out[n] = i.status if old is None or worst.index(i.status) < worst.index(old) else old
    return out


@pytest.mark.parametrize(
    "work",
    [
        "m1 = W1/g = 15/32.2 = 0.4658 slug\nm2 = W2/g = 10/32.2 = 0.3106 slug",
        r"$m_{1} = \frac{W_{1}}{g} = \frac{15}{32.2} = 0.466$ slug" + "\n" + r"$m_{2} = W_{2}/g = 0.311$ slug",
        "m_a = W_a/32.2 = 0.46584\nm_b = W_b/32.2 = 0.31056",
    ],
)
def test_a_weight_under_the_student_s_mark_for_its_body(work: str) -> None:
    assert statuses(SUITCASES, work) == {1: "correct", 2: "correct"}


def test_a_weight_under_the_other_body_s_mark_is_wrong() -> None:
    assert statuses(SUITCASES, "m1 = W2/g = 10/32.2 = 0.3106 slug") == {1: "wrong"}  # A's mass is 0.4658
    assert statuses(SUITCASES, "p1 = (W1/g)(19.657) = 9.157 slug ft/s") == {1: "correct"}
