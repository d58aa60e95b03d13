"""A chain's first slip that no mistake explains, where a name stands in the working of a relation
whose sides are unequal (``(0.020)(300) = (4.0) V``): a term or factor lost setting it up, named
algebra (derive/checking/stageslips.py, ``named_arithmetic``); a side of numbers alone worked wrongly
stays arithmetic. Worked by hand from the problem files' givens."""

from __future__ import annotations

from support.checked import lines


def test_the_pan_left_out_of_the_mass_moving_after_is_algebra() -> None:
    # chain-block-onto-spring-pan: 30 kg falls 2 m onto a 10 kg pan at rest, g = 9.81: v² = 39.24,
    # v = 6.264. Momentum: 30(6.264) + 10(0) = 40 V (V = 4.698); written = 30 V, V = 6.264: carried.
    work = "v^2 = 2(9.81)(2) = 39.24, v = 6.264 m/s\n30(6.264) + 10(0) = 30 V\nV = 6.264 m/s\n"
    found = lines("chain-block-onto-spring-pan", work)
    assert found[2][:2] == ("wrong", "algebra")
    assert found[3][0] == "carried"


def test_the_mass_lost_from_one_term_at_the_wall_is_algebra() -> None:
    # chain-ocr-m2-2011-find-e-mass-then-wall: B (0.2 kg) reaches the wall at 2.9 m/s, impulse 0.68 N s;
    # toward A positive: 0.68 = 0.2 w + 0.2(2.9) = 0.2 w + 0.58 (w = 0.5). Written 0.68 = 0.2 w + 2.9:
    # the 0.2 lost from B's momentum before; w = (0.68 - 2.9)/0.2 = -11.1, carried.
    work = "towards A positive, B rebounds at w\n0.68 = 0.2 w + 2.9\nw = -11.1\n"
    found = lines("chain-ocr-m2-2011-find-e-mass-then-wall", work)
    assert found[2][:2] == ("wrong", "algebra")
    assert found[3][0] == "carried"
