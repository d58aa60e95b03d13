"""Relations joined by "but" or "whereas" are two relations, as with "and" or "so" (the reader's
split, :mod:`derive.mathtext.splitting`): ``KE lost = 0?? but e = 0.2`` is the energy lost and the
coefficient, each judged, never one relation with the word read as letters. A line after a slip
so joined is carried where its relations are. Values worked by hand from the givens."""

from __future__ import annotations

from support.checked import lines, worst_lines

# OCR M2 2012: 0.8 kg at 4 m/s hits a wall, e = 0.3: rebound 0.3 x 4 = 1.2 m/s; KE before
# 0.5(0.8)(16) = 6.4 J, after 0.5(0.8)(1.44) = 0.576 J, lost 5.824 J; 4 - 1.2 = 2.8 m/s.
WALL = "ocr-m2-2012-particle-hits-wall"


def test_two_right_relations_joined_by_but_or_whereas_are_each_correct() -> None:
    found = lines(
        WALL,
        "speed after = 0.3 x 4 = 1.2 m/s\n"
        "KE before = 0.5 x 0.8 x 4^2 = 6.4 J but KE after = 0.5 x 0.8 x 1.2^2 = 0.576 J\n"
        "KE lost = 6.4 - 0.576 = 5.824 J whereas speed lost = 4 - 1.2 = 2.8 m/s\n",
    )
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3


def test_a_result_carried_then_but_a_right_one_is_carried() -> None:
    # the slip: KE lost as 1/2 m (u - v)^2 = 0.4(2.8)^2 = 3.136; then KE after = 6.4 - 3.136 = 3.264
    found = worst_lines(
        WALL,
        "speed after = 0.3 x 4 = 1.2 m/s\n"
        "KE before = 0.5 x 0.8 x 4^2 = 6.4 J\n"
        "KE lost = 1/2 m (u - v)^2 = 0.5 x 0.8 x (4 - 1.2)^2 = 3.136 J\n"
        "so KE after = 6.4 - 3.136 = 3.264 J?? but speed after = 1.2 m/s\n",
    )
    assert found[3][:2] == ("wrong", "ke_formula")
    assert found[4][0] == "carried"
