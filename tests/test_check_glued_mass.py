"""A mass letter glued to a velocity's name, phone-typed: ``mvA``, ``2mvQ``, ``3mu1`` are the mass
times that velocity, as ``m v_A`` is, not a name derive does not know.

By hand. WJEC 2019 Q7 (equal spheres, A at u, B at rest, e): mu = mv_A + mv_B and v_B - v_A = eu.
Edexcel M2 2024 Q5: P (m) at u hits Q (2m) at rest; mu = mv_P + 2mv_Q, v_Q - v_P = eu, so
3v_P = u - 2eu, v_P = u(1 - 2e)/3.
"""

from __future__ import annotations

import pytest

import derive


def statuses(problem: str, work: str) -> list[str]:
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    return [i.status for i in report.items if i.kind == "line"]


WJEC = "wjec-further-unit3-2019-june-q7-equal-spheres-b-at-rest"
EDEXCEL = "edexcel-m2-2024-june-q5-m-hits-2m-speed-of-p"


@pytest.mark.parametrize(
    ("problem", "work", "expected"),
    [
        (WJEC, "clm mu=mvA+mvB so vA+vB=u\nnel vB-vA=eu", ["correct", "correct"]),
        (WJEC, "clm mu=mvA+2mvB", ["wrong"]),
        (EDEXCEL, "clm: m(u) = mvP + 2mvQ\nnel: vQ - vP = eu\nvP = u(1 - 2e)/3", ["correct"] * 3),
        (EDEXCEL, "nel: vQ - vP = eu\nclm: m(u) = 2mvP + mvQ", ["correct", "wrong"]),  # masses swapped
    ],
)
def test_a_mass_glued_to_a_velocity_is_a_product(problem: str, work: str, expected: list[str]) -> None:
    assert statuses(problem, work) == expected
