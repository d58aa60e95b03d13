"""A direct impact's names declared by how each body moves after, its way in words: "P moves back
with speed x and Q moves on with speed y after the impact", "Let $P$ move backwards with speed $v$":
x is P's speed backwards (minus its velocity along P's first way), y Q's velocity. And the
problem's one-letter names side by side on a left side (``eu = v + w``, ``3mu = …``) are their
product, not a name of the student's own.

Worked by hand (edexcel-m2-2015-january-q7-m-at-3u-hits-2m-p-reverses): P (m) at 3u hits Q (2m) at
rest. With P back at x and Q on at y: 3mu = -mx + 2my; restitution y + x = 3eu; so
3u = -x + 2(3eu - x), x = u(2e - 1), y = 3eu - u(2e - 1) = u(1 + e).
"""

from __future__ import annotations

from support.checked import worst_lines

REVERSES = "edexcel-m2-2015-january-q7-m-at-3u-hits-2m-p-reverses"
WORK = (
    "P moves back with speed x and Q moves on with speed y after the impact.\n"
    "3mu = -mx + 2my\n"
    "eu = (y + x)/3\n"
    "3u = -x + 2(3eu - x)\n"
    "x = u(2e - 1)\n"
    "y = 3eu - u(2e - 1) = u(1 + e)\n"
)


def test_speeds_declared_by_how_the_bodies_move_after() -> None:
    found = worst_lines(REVERSES, WORK)
    assert [found[n][0] for n in range(2, 7)] == ["correct"] * 5


def test_restitution_with_the_speed_back_taken_as_a_velocity_is_wrong() -> None:
    found = worst_lines(REVERSES, WORK.replace("eu = (y + x)/3", "eu = (y - x)/3"))
    assert found[3][0] == "wrong"


def test_in_latex_with_move_backwards() -> None:
    work = (
        "Let $P$ move backwards with speed $v$ and $Q$ move forwards with speed $w$.\n"
        "$$3mu = -mv + 2mw$$\n"
        "$$3eu = v + w$$\n"
    )
    found = worst_lines(REVERSES, work)
    assert [found[n][0] for n in (2, 3)] == ["correct", "correct"]
