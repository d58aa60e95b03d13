"""At a wall one body moves, so a velocity named by its axis and a time's digit with no body's
letter (``v_{t1}``, ``(u_t)_2``, ``v_{2t}``, ``v_{t,2}``) is that body's component: along the wall
(t) or into it (n), before (1) or after (2). Such names were "definitions" of the student's own,
so ``(v_t)_2 = e_1 U cos α`` (e put on the component along the cushion) passed as correct. The
component into the wall after (``v_n2``) is the rebound, written as a size or signed as the
student's words say: it is not read as derive's signed component (a size ``e u sin θ`` is right)."""

from __future__ import annotations

import pytest

import derive

# Edexcel M4 2018 Q2: a ball at speed U, its path at α to a smooth wall, e = 3/4. By hand: along
# the wall nothing acts, so the component along it is U cos α before and after; into the wall
# U sin α before, and it rebounds at (3/4) U sin α. So (3/4) U cos α along the wall after is the
# slip: e put on the component along the wall.
M4 = "edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke"
# Pre-U 2013 Q12(i): speed u at θ to the wall (tan θ = 3), e unknown: along the wall u cos θ before
# and after, into it u sin θ before and e u sin θ (a size, away from the wall) after.
PREU = "pre-u-9795-2-2013-june-q12i-wall-rebound-at-right-angles"


def _statuses(problem: str, work: str) -> dict[str, tuple[str, str]]:
    report = derive.check(derive.load(problem), derivation=work)
    return {i.name: (i.status, i.slip) for i in report.items if i.kind == "line"}


@pytest.mark.parametrize(
    ("work", "expected"),
    [
        ("v_{1t} = U cos(alpha)\nv_{2t} = (3/4) U cos(alpha)\n", {"1": "correct", "2": "wrong"}),
        (
            "v_{t,1} = U cos(alpha)\nv_{t,2} = U cos(alpha)\nv_{n,1} = U sin(alpha)\n",
            {"1": "correct", "2": "correct", "3": "correct"},
        ),
        ("vt1 = U cos α\nvt2 = 0.75 U cos α\n", {"1": "correct", "2": "wrong"}),
    ],
)
def test_a_wall_component_by_its_axis_and_time(work: str, expected: dict[str, str]) -> None:
    got = _statuses(M4, work)
    assert {k: got[k][0] for k in expected} == expected, got


def test_e_on_the_component_along_the_wall_is_named() -> None:
    got = _statuses(PREU, "(u_t)_1 = u cos(theta)\n(u_t)_2 = e u cos(theta)\n")
    assert got["1"][0] == "correct", got
    assert got["2"] == ("wrong", "e_on_t"), got


def test_the_rebound_named_by_its_axis_may_be_a_size() -> None:
    work = "(v_t)_1 = u cos(theta)\n(v_n)_1 = u sin(theta)\n(v_t)_2 = u cos(theta)\n(v_n)_2 = e u sin(theta)\n"
    got = _statuses(PREU, work)
    assert all(s == "correct" for s, _ in got.values()), got
