"""A name in brackets with its body and instant inside and its component glued after them, as
university courses type it without underscores: ``(vA1)n``, ``(vB2)t``, ``(v_A2)n`` are ``v_A1n``,
``v_B2t``, ``v_A2n`` (the n or t component of that body's velocity at that instant). A bare
``(v)t`` (no body inside) stays a product: a component is glued on only after a body's name.

Example 4.C.11 by hand (theta = 37.6 deg, cos 0.79229, sin 0.61015): v_A1n = 5 cos = 3.961,
v_A1t = 5 sin = 3.051; B at 15 from -n toward -t: v_B1n = -11.884, v_B1t = -9.152. The
t-momentum of each body keeps v_A2t = 3.051. Momentum along n: 20(3.961) + 5(-11.884) = 19.81;
restitution v_B2n - v_A2n = 0.6(3.961 + 11.884) = 9.507; so 25 v_A2n = 19.81 - 5(9.507),
v_A2n = -1.109, v_B2n = 8.398.
"""

from __future__ import annotations

import pytest

import derive
from derive.mathtext.bracketed import bracketed_names


def statuses(problem: str, work: str) -> list[str]:
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    return [i.status for i in report.items]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("(vA1)n = 4cos30", "v_A1n = 4cos30"),
        ("(v_A2)n + (uB1)t = 3", "v_A2n + u_B1t = 3"),
        ("2(vB2)n = 6", "2 v_B2n = 6"),
        ("(v)t = 3", "(v)t = 3"),  # no body inside: velocity times time, as written
    ],
)
def test_a_component_glued_after_a_bracketed_name_is_its_mark(text: str, expected: str) -> None:
    assert bracketed_names(text) == expected


@pytest.mark.parametrize(
    ("work", "expected"),
    [
        ("(vA1)n = 5cos37.6 = 3.961", ["correct"]),
        ("(vB1)n = -15cos37.6 = -11.884, (vB1)t = -15sin37.6 = -9.152", ["correct"]),
        ("(vA2)t = 3.051", ["correct"]),
        ("(v_B2)n - (v_A2)n = 0.6(3.961 + 11.884) = 9.507", ["correct"]),
        ("20(vA2)n + 5(vB2)n = 19.81\n(vA2)n = 1.109", ["correct", "wrong"]),  # the sign lost
    ],
)
def test_bracketed_components_are_judged_on_an_oblique_impact(work: str, expected: list[str]) -> None:
    assert statuses("notes-4c11-two-spheres", work) == expected
