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


def test_e_moved_off_the_rebound_is_the_same_mistake_again() -> None:
    # By hand (M4, e = 3/4): along the wall U cos α stays; the rebound is (3/4) U sin α. Writing
    # (3/4) U cos α along and U sin α for the rebound moves e from one to the other: one mistake,
    # made on the first line and again on the second.
    work = "v_{t1} = U cos(alpha)\nv_{n1} = U sin(alpha)\nv_{t2} = (3/4) U cos(alpha)\nv_{n2} = U sin(alpha)\n"
    got = _statuses(M4, work)
    assert got["3"] == ("wrong", "e_on_t"), got
    assert got["4"][0] == "wrong" and got["4"][1] in ("", "e_on_t"), got
    report = derive.check(derive.load(M4), derivation=work)
    assert next(i for i in report.items if i.name == "4").again


@pytest.mark.parametrize("rebound", ["e u sin(theta)", "-e u sin(theta)"])
def test_the_rebound_is_a_size_or_signed_into_the_wall(rebound: str) -> None:
    # Pre-U: the rebound away from the wall is e u sin θ; derive's n points into the wall, so a
    # student who signs it in that way writes -e u sin θ: both are right.
    work = f"v_{{t1}} = u cos(theta)\nv_{{n1}} = u sin(theta)\nv_{{t2}} = u cos(theta)\nv_{{n2}} = {rebound}\n"
    got = _statuses(PREU, work)
    assert all(s == "correct" for s, _ in got.values()), got
