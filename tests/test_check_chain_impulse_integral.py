"""The impulse as the integral of the force in a chain's line, typed in LaTeX (``\\int F\\,dt``), with
``∫`` or in words (``Int F dt``, ``integral of F dt``), inside a side: a name of the student's own,
the chain's impulse where its value makes the relation hold (derive/mathtext/reader.py ``_INTEGRAL``,
derive/checking/chainletters.py). Worked by hand from problems/chain-ocr-m2-2007-rebounds-to-start.toml:
0.2 kg hits the ground at 35 m/s (21² + 2(9.8)(40) = 1225) and leaves it at 28 m/s (it rises back
40 m: 2(9.8)(40) = 784); the impulse 0.2(28 + 35) = 12.6 N s, upwards."""

from __future__ import annotations

from support.checked import lines

PROBLEM = "chain-ocr-m2-2007-rebounds-to-start"


def test_int_f_dt_typed_in_words_inside_the_momentum_line() -> None:
    # Up positive: m(-v1) + impulse = m v2; 0.2(-35) + impulse = 0.2(28); impulse = 5.6 + 7 = 12.6.
    work = (
        "up positive: m(-v1) + Int F dt = m(v2)\n0.2(-35) + integral of F dt = 0.2(28)\nInt F dt = 5.6 + 7 = 12.6 N s\n"
    )
    assert [lines(PROBLEM, work)[n][0] for n in (1, 2, 3)] == ["correct"] * 3


def test_the_integral_in_latex_displays() -> None:
    work = "Taking up as positive,\n$$0.2(-35) + \\int F\\,dt = 0.2(28)$$\n$$\\int F\\,dt = 12.6 \\text{ N s}$$\n"
    found = lines(PROBLEM, work)
    assert [found[n][0] for n in (2, 3)] == ["correct", "correct"]


def test_the_speed_before_with_its_sign_lost_is_the_slip() -> None:
    # 0.2(35) + impulse = 0.2(28): the 35 m/s downwards put in upwards; impulse = 5.6 - 7 = -1.4, carried.
    work = "up positive\n0.2(35) + Int F dt = 0.2(28)\nInt F dt = 5.6 - 7 = -1.4 N s\n"
    found = lines(PROBLEM, work)
    assert found[2][0] == "wrong"
    assert found[3][0] == "carried"
