"""A component's instant from the student's own marks: where a body's other component is primed for
after (``v2x'``), its unprimed components are before (``v2y``); ``u`` with a body's digit and an axis
(``u_1x``, ``u2n``, ``(u_1)_y``) is before, as ``u_A``, ``u_Ax`` are (docs/checking.md, "Names")."""

from __future__ import annotations

import pytest

import derive

#: McCasco's glancing disks: equal disks, B at rest, A at 8 ft/s at 30° to the line of centres, e = 0.8.
#: By hand: A before 8 cos 30° = 6.9282 along, 8 sin 30° = 4 across; B before 0, 0. Along after:
#: sum 6.9282, separation 0.8(6.9282) = 5.5426.
DISKS = "mcasco-glancing-disks-us"


def statuses(problem: str, work: str) -> dict[int, str]:
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    worst = ("wrong", "carried", "error", "not read", "not checked", "correct")
    out: dict[int, str] = {}
    for i in report.items:
        if i.kind == "line" and i.name.isdigit():
            n, old = int(i.name), out.get(int(i.name))
            out[n] = i.status if old is None or worst.index(i.status) < worst.index(old) else old
    return out


PRIMED = "v1x = 8 cos 30 = 6.928, v1y = 8 sin 30 = 4\nv2x = 0, v2y = {b}\nv1x' + v2x' = 6.928\n"


def test_a_component_beside_its_body_s_other_component_primed_is_before() -> None:
    assert statuses(DISKS, PRIMED.format(b=0)) == {1: "correct", 2: "correct", 3: "correct"}
    assert statuses(DISKS, PRIMED.format(b=4))[2] == "wrong"  # B is at rest: 4 is A's component across


@pytest.mark.parametrize(
    "work",
    [
        "$(u_1)_x = 6.928$, $(u_1)_y = 4$\n$(u_2)_y = 0$",
        "u1n = 8cos30 = 6.93\nu2t = 0",
        r"$u_{1x} = 8\cos 30^\circ = 6.928$" + "\n" + r"$u_{2y} = 0$",
    ],
)
def test_u_with_a_body_s_digit_and_an_axis_is_before(work: str) -> None:
    assert statuses(DISKS, work) == {1: "correct", 2: "correct"}


def test_u_with_a_body_s_digit_and_an_axis_is_judged() -> None:
    assert statuses(DISKS, "u_1n = 8 sin 30 = 4") == {1: "wrong"}  # along is 8 cos 30° = 6.93
    assert statuses(DISKS, "u2y = 4") == {1: "wrong"}  # B at rest


@pytest.mark.parametrize(
    ("work", "expected"),
    [
        ("along loc: A 8cos30=6.93\nperp: A 8sin30=4", {1: "correct", 2: "correct"}),
        ("across: A 8 sin 30 = 4.00 ft/s", {1: "correct"}),
        ("along: A 8sin30=4", {1: "wrong"}),  # along the line of centres is 8 cos 30° = 6.93
        ("perp: A 8cos30=6.93", {1: "wrong"}),  # across is 8 sin 30° = 4
    ],
)
def test_a_body_s_letter_before_its_value_under_an_axis_heading(work: str, expected: dict) -> None:
    # phone-typed: the colon after the body's letter left out; the axis said before the line's colon
    assert statuses(DISKS, work) == expected
