"""A chain's impulse written I where the chain calls it J (OCR's and Edexcel's letter): the student's
own name of the impulse's letter, judged as the chain's impulse, not a quantity of their own that
its working defines (derive/checking/chainfit.py, ``of_the_letter``). Worked by hand from
problems/chain-ocr-m2-2007-rebounds-to-start.toml: 0.2 kg hits the ground at 35 m/s (21² + 2(9.8)(40)
= 1225) and rises back 40 m, so it leaves at 28 m/s; the impulse is 0.2(28 + 35) = 12.6 N s."""

from __future__ import annotations

from support.checked import lines

PROBLEM = "chain-ocr-m2-2007-rebounds-to-start"


def test_the_rebound_taken_the_same_way_in_i_is_a_slip_not_a_definition() -> None:
    # I = 0.2(35 - 28) = 1.4: the rebound's sign lost (the impulse is 0.2(35 + 28) = 12.6).
    work = "v1^2 = 21^2 + 2(9.8)(40) = 1225, v1 = 35 m/s\nv2 = 28 m/s (back up 40 m)\nI = 0.2(35 - 28) = 1.4 N s\n"
    found = lines(PROBLEM, work)
    assert found[3][:2] == ("wrong", "b_sign")


def test_i_worked_from_a_slip_in_the_fall_is_carried() -> None:
    # The slip: 441 + 784 written 1125, v1 = 33.5 (true 35); I = 0.2(28 j - (-33.5 j)) = 0.2(61.5) j
    # = 12.3 j: the slip's impulse (0.2(28 + 33.541) = 12.31; true 12.6), carried on both lines.
    work = (
        "j up positive\n"
        "v1^2 = 21^2 + 2(9.8)(40) = 441 + 784 = 1125, v1 = 33.5\n"
        "v2^2 = 2(9.8)(40) = 784, v2 = 28\n"
        "I = m(v_after - v_before) = 0.2(28 j - (-33.5 j))\n"
        "I = 0.2(61.5) j = 12.3 j N s\n"
    )
    found = lines(PROBLEM, work)
    assert found[2][0] == "wrong"
    assert [found[n][0] for n in (4, 5)] == ["carried", "carried"]
