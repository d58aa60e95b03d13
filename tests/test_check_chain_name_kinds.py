"""A chain's name read by its kind: a velocity's letter (``vB3``, ``w``) stands for one of the chain's
velocities where one makes its relations hold, never an impulse or a ratio that a slipped number
happens to round to (derive/checking/chainfit.py, ``of_kind``). Worked by hand from the problem file."""

from __future__ import annotations

from support.checked import lines


def test_a_slipped_velocity_after_the_wall_is_not_read_as_the_impulse() -> None:
    # chain-ocr-m2-2011-find-e-mass-then-wall: B (0.2 kg) reaches the wall at 2.9 m/s and gets 0.68 N s.
    # Toward the wall positive: 0.68 = 0.2(2.9) - 0.2 vB3 holds for vB3 = -0.5 (the chain's w_B).
    # The slip: 0.58 - 0.68 written -0.14 (it is -0.10), so vB3 = -0.7 and e = 0.7/2.9 = 0.241 (true
    # 0.5/2.9 = 0.172): carried. -0.7 is also the 0.68 N s impulse turned round at one decimal: a
    # velocity's name is not read as it.
    work = (
        "B hits the wall, towards wall +ve\n"
        "impulse on B: 0.68 = 0.2(2.9) - 0.2 vB3\n"
        "0.2 vB3 = 0.58 - 0.68 = -0.14\n"
        "vB3 = -0.7 m/s\n"
        "ewall = 0.7/2.9 = 0.241\n"
    )
    found = lines("chain-ocr-m2-2011-find-e-mass-then-wall", work)
    assert found[2][0] == "correct"
    assert found[3][:2] == ("wrong", "arithmetic")
    assert [found[n][0] for n in (4, 5)] == ["carried", "carried"]
