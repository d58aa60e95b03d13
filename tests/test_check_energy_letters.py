"""A kinetic energy's letter alone (K, E_k, Ek, T, E) and its marks for the instant: primed for
after, bare beside its primed twin for before (``K`` and ``K'``, as first-year physics writes
them); ``dK``, ``dKE``, ``dE_k`` the change typed without a Delta, and ``K_lost``, ``E_k loss``
the loss (docs/checking.md, "Names")."""

from __future__ import annotations

import pytest

import derive

#: 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5: 4 and 8 m/s after. By hand:
#: before 0.5(4)(144) + 0.5(8)(16) = 288 + 64 = 352 J; after 0.5(4)(16) + 0.5(8)(64) = 32 + 256 = 288 J.
CATCHES = "byjus-4kg-ball-catches-8kg-ball"
#: 0.8 kg at 4 m/s into a wall, e = 0.3: back at 1.2 m/s. By hand: before 0.5(0.8)(16) = 6.4 J,
#: after 0.5(0.8)(1.44) = 0.576 J, lost 5.824 J.
WALL = "ocr-m2-2012-particle-hits-wall"


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
        "K = 0.5(4)(12^2) + 0.5(8)(4^2) = 352 J\nK' = 0.5(4)(4^2) + 0.5(8)(8^2) = 288 J\ndK = K' - K = -64 J",
        "$E_k = 352$ J\n$E_k' = 288$ J\n$E_k - E_k' = 64$ J",
        "Ek = 352\nEk' = 288\nK_lost = Ek - Ek' = 64",
    ],
)
def test_an_energy_letter_and_its_primed_twin_are_before_and_after(work: str) -> None:
    found = statuses(CATCHES, work)
    assert found == {1: "correct", 2: "correct", 3: "correct"}, found


def test_the_letters_are_judged_not_only_read() -> None:
    assert statuses(CATCHES, "K = 352 J\nK' = 352 J") == {1: "correct", 2: "wrong"}  # after is 288
    assert statuses(CATCHES, "Ek = 288\nEk' = 288")[1] == "wrong"  # before is 352


@pytest.mark.parametrize(
    "work",
    [
        "K_loss = 5.82 J",
        r"$K_{\text{lost}} = \tfrac12(0.8)(16 - 1.44) = 5.824\ \text{J}$",
        "E_k loss = 5.824 J",
    ],
)
def test_a_loss_by_its_letter(work: str) -> None:
    assert statuses(WALL, work) == {1: "correct"}


@pytest.mark.parametrize("work", ["dK = 0.8(4^2 - 1.2^2) = 11.648 J", "dE_k = 11.6 J", "dKE = 6.4 + 0.576 = 6.98 J"])
def test_a_change_typed_without_delta_is_judged_as_the_loss(work: str) -> None:
    assert statuses(WALL, work) == {1: "wrong"}  # the loss is 5.824 J: twice it, and before plus after
