"""Names read by the shape of the first relation they stand in: ``3p + 5(1) = 3(0) + 5q``, each name
beside its body's mass on its instant's side, is the conservation of momentum with p A's velocity
before and q B's after, and one relation is enough to read them so, though the next line's slip
leaves it the only one that holds (docs/checking.md, "Names")."""

from __future__ import annotations

import pytest

import derive

#: OCR MEI 2024: A (3 kg) along XY at an unknown speed, B (5 kg) at 2 m/s at 60° to XY, e = 0.8, A stops.
#: By hand: along XY B has 2 cos 60° = 1 before; 3p + 5(1) = 5q and q - 0 = 0.8(p - 1): p = 9, q = 6.4.
DISC = "ocr-mei-fmm-2024-disc-a-stops"


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
        # e upside down: separation e = approach (0.8 q for q - 0 = 0.8(p - 1))
        "$3p + 5(2\\cos 60^\\circ) = 3(0) + 5q$\n$p - 1 = 0.8\\,(q - 0)$",
        # B's component taken as toward A: x + 1 for x - 1
        "CLM: 3x + 5 = 5y\nNEL: y = 0.8(x + 1)",
    ],
)
def test_names_read_by_the_momentum_equation_they_first_stand_in(work: str) -> None:
    assert statuses(DISC, work) == {1: "correct", 2: "wrong"}


def test_the_lines_after_the_slip_are_carried() -> None:
    # y = 0.8(x + 1) and 3x + 5 = 5y: 3x + 5 = 4x + 4, x = 1, y = 1.6 (the slip's own values)
    work = "CLM: 3x + 5 = 5y\nNEL: y = 0.8(x + 1)\n3x + 5 = 4x + 4 so x = 1\ny = 1.6"
    assert statuses(DISC, work) == {1: "correct", 2: "wrong", 3: "carried", 4: "carried"}
